"""What things are for, as English phrases that follow "for" in an abstract (a,r,d) query:
"something for sitting on", "the thing used for heating up leftovers".

Written for query generation in everyday words, independent of the affordance cues the readers
(lexicon, offline model) match, so a synthetic abstract query does not simply quote what the
reader knows. Keys are canonical lexicon categories; a category without an entry borrows those of
its nearest more general category ("folding chair" -> chair), else it gets no abstract query.
"""

from __future__ import annotations

from typing import Iterable

PURPOSES: dict[str, tuple[str, ...]] = {
    "chair": ("sitting on", "taking a seat"),
    "armchair": ("sitting back in", "curling up with a book"),
    "sofa": ("lounging on", "stretching out on", "sitting on with guests"),
    "bench": ("sitting on", "sitting on while putting shoes on"),
    "stool": ("perching on", "reaching the top shelves"),
    "bed": ("sleeping in", "lying down on"),
    "table": ("putting things down on", "eating a meal at"),
    "desk": ("working at", "doing paperwork at"),
    "coffee table": ("putting drinks down on", "resting a mug on"),
    "side table": ("setting a glass down on", "putting a drink down next to a seat"),
    "nightstand": ("putting a glass of water down at night", "keeping my glasses within reach at night"),
    "counter": ("chopping vegetables on", "preparing food on"),
    "kitchen island": ("chopping vegetables on", "preparing food on"),
    "shelf": ("putting things up on", "displaying ornaments on"),
    "bookshelf": ("keeping my novels", "lining up books"),
    "cabinet": ("keeping things out of sight", "storing supplies"),
    "kitchen cabinet": ("keeping dishes and dry food", "storing pots and pans"),
    "bathroom cabinet": ("keeping medicine", "storing toiletries"),
    "wardrobe": ("hanging up clothes", "keeping my clothes"),
    "dresser": ("keeping folded clothes", "storing socks and shirts"),
    "sideboard": ("keeping plates and glasses", "storing tableware"),
    "coat rack": ("hanging up coats", "hanging hats and jackets"),
    "shoe rack": ("keeping shoes tidy", "lining up shoes"),
    "rack": ("hanging things on", "keeping shoes tidy"),
    "sink": ("washing hands", "rinsing dishes"),
    "vanity": ("washing up in the morning", "brushing teeth"),
    "toilet": ("a bathroom break", "when nature calls"),
    "bathtub": ("taking a long bath", "a relaxing soak"),
    "shower": ("rinsing off", "washing up after a run"),
    "towel": ("drying off", "drying wet hands"),
    "mirror": ("checking how I look", "fixing my hair"),
    "refrigerator": ("keeping food cold", "chilling drinks"),
    "microwave": ("heating up leftovers", "warming up a meal"),
    "oven": ("baking bread", "roasting vegetables"),
    "stove": ("cooking dinner", "frying eggs"),
    "kettle": ("boiling water", "making tea"),
    "coffee machine": ("making coffee", "a morning espresso"),
    "toaster": ("toasting bread",),
    "dishwasher": ("cleaning dirty dishes",),
    "washing machine": ("washing dirty clothes", "doing the laundry"),
    "cup": ("drinking tea", "a hot drink"),
    "bottle": ("carrying water", "a drink of water"),
    "bowl": ("serving soup", "holding snacks"),
    "plate": ("serving food on",),
    "trash can": ("throwing rubbish away", "getting rid of wrappers"),
    "lamp": ("lighting up the room", "reading at night"),
    "tv": ("watching a film", "watching the news"),
    "monitor": ("looking at a second screen", "working on a computer"),
    "screen": ("watching videos", "looking at slides"),
    "computer": ("checking email", "writing documents"),
    "laptop": ("checking email", "working on the go"),
    "keyboard": ("typing",),
    "printer": ("printing documents", "making a paper copy"),
    "phone": ("making a call", "calling someone"),
    "remote control": ("changing the channel", "turning up the volume"),
    "book": ("reading before bed", "a bit of reading"),
    "paper": ("writing a note", "jotting something down"),
    "picture": ("decorating the wall", "brightening up a wall"),
    "plant": ("adding some greenery", "a bit of nature indoors"),
    "vase": ("holding fresh flowers",),
    "clock": ("telling the time", "checking the time"),
    "rug": ("walking on barefoot", "keeping feet warm on a cold floor"),
    "pillow": ("resting my head on", "leaning back against"),
    "blanket": ("keeping warm at night", "snuggling under"),
    "curtain": ("shutting out the light", "blocking the morning sun"),
    "blinds": ("shutting out the light", "darkening the room"),
    "window": ("letting in fresh air", "looking outside"),
    "door": ("leaving the room", "going out"),
    "stairs": ("getting to the next floor", "going up a level"),
    "backpack": ("carrying my things", "packing for a hike"),
    "bag": ("carrying my things",),
    "suitcase": ("packing for a trip",),
    "fan": ("cooling down", "a bit of a breeze"),
    "heater": ("warming up the room",),
    "radiator": ("warming up the room",),
    "fireplace": ("a cosy fire",),
    "toy": ("playing with",),
    "speaker": ("playing music",),
    "piano": ("playing music",),
}


def purposes_of(categories: Iterable[str]) -> list[str]:
    """Purposes of the first of `categories` (a category, then its more general ones) that has an
    entry; [] when none has."""
    return next((list(PURPOSES[c]) for c in categories if c in PURPOSES), [])
