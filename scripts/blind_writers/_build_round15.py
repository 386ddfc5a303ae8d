"""Generate evals/blind/round15.jsonl: 48 groups x 6 hand-written wordings.

Written blind for round 15: the only inputs read were the map files named in BRIEF.md
(the two *_caption.json maps, evals/blind/apartment, evals/maps/scan_*.json, evals/blind/maps/flat_*.json).
Every wording below was typed by hand for this round. Run from anywhere:

    python3 make_round15.py (in the writer's folder)
"""

from __future__ import annotations

import json
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "evals" / "blind" / "round15.jsonl"

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SOFF = "../maps/scan_office.json"
SBED = "../maps/scan_bedroom.json"


def flat(x: str) -> str:
    return f"maps/flat_{x}.json"


# (type, map, target, accept, [six wordings])
GROUPS = [
    # ---------------- o: every instance of a kind ----------------
    ("o", OFF3, 8, [8, 13, 20, 40], [
        "take me to a cushion",
        "Could you show me where the throw cushions are?",
        "pillows rec room",
        "My back hurts on this seat, I need something soft to lean on. Bring me to one of the cushions.",
        "Any cushion will do, just find me one.",
        "where's a pilow",
    ]),
    ("o", C829, 122, [122], [
        "take me to the loo",
        "Where is the WC, please?",
        "toilet",
        "Could you guide me to the lavatory?",
        "Show me the way to the toliet.",
        "Where's the john in this place?",
    ]),
    ("o", flat("d"), 21, [21, 22], [
        "go to a bar stool",
        "Is there a high seat without a back anywhere? Take me there.",
        "backless seat, any",
        "Can you find me one of the stools?",
        "I want to perch on one of those tall little seats with no backrest.",
        "either of the little backless seats",
    ]),
    ("o", flat("h"), 13, [13, 26, 32], [
        "find a mug",
        "Where can I find a coffee cup?",
        "take me to a cup, doesn't matter which one",
        "I'd like to go to any of the tea cups in the flat.",
        "mugs?",
        "Please bring me to one of the drinking cups lying around.",
    ]),
    ("o", flat("g"), 2, [2, 3], [
        "take me to a bike",
        "Where are the bikes kept?",
        "I want to go for a ride. Show me a bike.",
        "bicycle please",
        "Could you show me one of the bycicles?",
        "any of the cycles, big or small",
    ]),
    ("o", flat("e"), 7, [7, 29], [
        "take me to a mirror",
        "I want to check my hair. Where's a looking glass?",
        "Is there a mirror somewhere in the house?",
        "looking glass, any room",
        "Bring me to one of the wall mirors.",
        "Find me a reflecting glass on a wall, whichever is closest.",
    ]),
    ("o", SOFF, 11, [11, 12, 13], [
        "go to a computer screen",
        "Can you take me to one of the displays?",
        "screen, any desk",
        "I need to look at a monitor, whichever is free.",
        "Where are the PC screens?",
        "take me to one of the monitors",
    ]),
    # ---------------- or: a kind in a named room ----------------
    ("or", C829, 261, [261, 263], [
        "take me to an armchair in the bedroom",
        "Is there a comfy lounge chair in the bedroom? Take me there.",
        "bedroom armchair",
        "I'd like to sit down in the bedroom, in one of the big padded armchairs.",
        "Which easy chairs are in the bedroom? Go to one.",
        "Take me to a cushy armchiar in the bed room.",
    ]),
    ("or", C829, 112, [112, 233], [
        "go to the bathroom mirror",
        "Could you show me a mirror in the bathroom?",
        "mirror, bathroom",
        "I want to fix my makeup in the bathroom. Find me a mirror there.",
        "Where's the mirror in the washroom?",
        "The framed looking glass in the bathroom, please.",
    ]),
    ("or", flat("e"), 11, [11, 12, 13, 14, 15], [
        "take me to a seat in the dining room",
        "Could you find me somewhere to sit in the dining room?",
        "dining room chair",
        "Any of the dining room chairs is fine, I'm just tired.",
        "I'm about to eat. Bring me to a seat at the dining room table.",
        "a sitting place in the dinning room",
    ]),
    ("or", flat("h"), 46, [46, 47], [
        "bedside table in the master bedroom",
        "Take me to one of the bedside tables in the main bedroom.",
        "Could you go to a night table in the master bedroom, please?",
        "master bedroom nightstand",
        "I left my glasses by the bed in the master bedroom. Go to one of the little tables next to it.",
        "Show me the nighstands in the big bedroom.",
    ]),
    ("or", flat("i"), 6, [6, 7, 8, 9], [
        "take me to a seat in the meeting room",
        "Is there a free chair in the meeting room?",
        "meeting room seat",
        "Our client is coming. Bring me to any seat in the conference room.",
        "Find me somewhere to sit in the meeting room, any place at the table.",
        "Go to one of the chiars in the boardroom.",
    ]),
    ("or", APT, 12, [12, 13], [
        "a book in the living room",
        "Take me to any of the books in the lounge.",
        "something to read, living room, any title",
        "Is there a paperback or hardback in the living room? Take me to it.",
        "I'm bored. Show me a volume from the living room shelf.",
        "lounge boks",
    ]),
    ("or", flat("g"), 34, [34, 35], [
        "bedside light in the bedroom",
        "Take me to a lamp in the bedroom.",
        "Could you show me the reading lights in the bedroom?",
        "It's dark in the bedroom. Go to one of the lights there.",
        "bedroom lamps, either one",
        "Find a lmap by the bed in the bedroom.",
    ]),
    # ---------------- od: one object by its look ----------------
    ("od", OFF3, 13, [13], [
        "the navy velvet cushion",
        "Could you take me to the dark blue velvety pillow with the button?",
        "navy cushion, buttoned",
        "It's a cushion in deep navy velvet. It has a button in the middle.",
        "The blue pillow, not the orange or yellow ones.",
        "Go to the plush dark-blue cushion that's a bit bigger than the rest.",
    ]),
    ("od", C829, 211, [211], [
        "the blue bowl with gold patterns",
        "Could you find the deep blue ceramic dish with the gilded pattern?",
        "blue+gold bowl",
        "This is a glossy blue ceramic bowl. It's decorated with golden patterns.",
        "Take me to the ornamental bowl in blue, not the white one with sweets.",
        "blue glazed bwol with gold",
    ]),
    ("od", C829, 184, [184], [
        "the L-shaped sofa",
        "Take me to the corner sofa with the chaise longue, please.",
        "beige L sofa w/ chaise",
        "I'm looking for a beige fabric settee. It's L-shaped and has a storage compartment.",
        "the L-shaped couch, not the plush one with the massage thing",
        "Where's the sectional sofa with the chaise end?",
    ]),
    ("od", flat("f"), 2, [2], [
        "the tartan chair",
        "Could you take me to the red plaid wingback?",
        "red tartan wing chair",
        "It's a wingback armchair covered in red tartan wool.",
        "The red armchair, not the cream leather one.",
        "Go to the checked red woollen wingback seat.",
    ]),
    ("od", flat("i"), 24, [24], [
        "the green door",
        "Take me to the bottle-green entrance with the round brass knob.",
        "green front entrance, brass knob",
        "This is a wooden front door painted bottle green. It has a round brass knob.",
        "Bring me to the green entryway, not the black steel one on the street side.",
        "the wooden green entrance dor",
    ]),
    ("od", flat("h"), 11, [11], [
        "the mustard velvet chair",
        "Could you take me to the yellow velvet armchair?",
        "yellow armchair",
        "The one in mustard velvet, not the brown leather club chair.",
        "It's an easy chair upholstered in mustard-yellow velvet.",
        "go to the ochre velvet seat",
    ]),
    ("od", SOFF, 30, [30], [
        "the white keyboard",
        "Can you find the white keybaord for me?",
        "Take me to the white computer keypad.",
        "This is a white typing board for the computer. Take me to it.",
        "the light-coloured keyboard, not the black one",
        "white keys, PC",
    ]),
    # ---------------- ord: look + room ----------------
    ("ord", C829, 110, [110], [
        "the honey-coloured side table in the bathroom",
        "Could you take me to the little wooden table with the X-shaped metal legs in the bathroom?",
        "bathroom, small honey wood table, X base",
        "It's a small table of warm honey wood on a metal X base. It's in the bathroom.",
        "The small stand in the bathroom with the crossed metal base.",
        "In the bathroom there's a light wooden tabel with a USB port. Go there.",
    ]),
    ("ord", C829, 164, [164], [
        "the towels with the embroidered H in the living room",
        "Could you show me the folded towel stack monogrammed with an H in the living room?",
        "living room towels, letter H",
        "These are fluffy white cotton towels with an H stitched on them. They sit on a rack in the living room.",
        "the stack of towls with the H on it, living room one",
        "The H-embroidered bath towels in the lounge, not the plain ones.",
    ]),
    ("ord", flat("e"), 14, [14], [
        "the black metal chair in the dining room",
        "Take me to the black bistro seat in the dining room.",
        "dining room, black metal seat",
        "It's the chair that doesn't match the others in the dining room, the black metal one.",
        "The dark metal seat in the dining room, not one of the sage green wooden ones.",
        "In the dining room there's a black bistro-style chiar. Go to it.",
    ]),
    ("ord", flat("g"), 34, [34], [
        "the teal lamp in the bedroom",
        "Could you bring me to the bedside light with the teal glass base in the bedroom?",
        "bedroom, teal glass light",
        "In the bedroom there are two bedside lights. I want the one with the teal glass base, not the beige ceramic one.",
        "Go to the turquoise glass bedside lamp in the bedroom.",
        "bedroom reading light, the blue-green glass one",
    ]),
    ("ord", flat("i"), 17, [17], [
        "the white screen in the studio",
        "Take me to the white computer display in the studio, please.",
        "studio, white-framed monitor",
        "It's a computer screen with a white frame, turned for portrait. It's in the studio.",
        "The white monitor in the studio, not the wide black one.",
        "In the studio, find the white-rimmed scren.",
    ]),
    ("ord", flat("d"), 5, [5], [
        "the yellow chair in the studio",
        "Could you take me to the yellow wooden seat in the studio?",
        "studio yellow seat",
        "This is a yellow painted wooden chair. It's in the studio.",
        "In the studio, the yellow painted seat, not the white plastic one.",
        "Bring me to the sunny yellow wooden seat in the studio area.",
    ]),
    ("ord", APT, 48, [48], [
        "the red leather chair in the office",
        "Could you take me to the red swivel seat in the office?",
        "office, red leather swivel seat",
        "It's a red leather desk chair on wheels. It's in the office.",
        "Take me to the red seat with armrests in the office.",
        "In the home office, the red leather one on casters.",
    ]),
    # ---------------- ard: a need, no object named ----------------
    ("ard", OFF3, 25, [25], [
        "I need to know what time it is",
        "What's the time? Take me to where I can check it.",
        "check the time",
        "I have a meeting soon and lost track of the hour. Where can I see the time?",
        "Could you take me to something on the wall that tells the time?",
        "My watch died. Where can I check the hour?",
    ]),
    ("ard", OFF3, 67, [67], [
        "I want to change the channel",
        "Could you take me to whatever I use to switch what's on the screen without getting up?",
        "switch channels",
        "The volume is way too loud and I'm sitting across the room. What do I use to turn it down?",
        "I need to flip through the channels from my seat.",
        "How do I turn the TV off from across the room?",
    ]),
    ("ard", C829, 192, [192], [
        "my dog needs somewhere to nap",
        "Where does the cat usually curl up to sleep?",
        "pupy sleeping spot",
        "We just got a kitten and it's exhausted. Where can it lie down?",
        "Could you take me to where the dog sleeps?",
        "Our pup keeps lying on the tiles, I want to show him his own place to rest.",
    ]),
    ("ard", flat("d"), 27, [27], [
        "my shirt is creased",
        "I need to press my trousers before the interview. Where should I go?",
        "get wrinkles out of a shirt",
        "Could you take me where I can smooth out my crumpled clothes?",
        "My dress is all wrinkled, help",
        "I want to iron my blouse.",
    ]),
    ("ard", flat("f"), 25, [25], [
        "I want to look at the stars tonight",
        "Is there anything here for stargazing?",
        "see the moon up close",
        "It's a clear night. Take me where I can get a good view of the planets.",
        "Could you take me to whatever lets me watch the night sky properly?",
        "I'd love to spot Saturn's rings.",
    ]),
    ("ard", flat("g"), 5, [5], [
        "I need a screwdriver",
        "The shelf is wobbly, I need a spanner to tighten it. Where would I find one?",
        "need hammer + pliers",
        "Could you take me to where the tools are kept?",
        "My bike chain is loose and I need a wrench.",
        "I want to hang a picture, so I need a hammer and some nails.",
    ]),
    ("ard", flat("h"), 4, [4], [
        "where do I leave my keys",
        "I just got home. Where should I drop my house keys?",
        "key drop spot",
        "Could you take me to where the keys usually get put down by the entrance?",
        "I can't find my kyes, where do they normally end up?",
        "I'm heading out and need my keys, where are they usually kept?",
    ]),
    ("ard", APT, 54, [54], [
        "I need to print my boarding pass",
        "Could you take me to where I can get a hard copy of this document?",
        "print a docment",
        "My report is due in an hour and I need paper copies. Where do I go?",
        "I want to print some photos on paper.",
        "Where can I print out a form?",
    ]),
    # ---------------- s: singled out by position ----------------
    ("s", SOFF, 15, [15], [
        "the middle bookshelf",
        "Could you take me to the bookcase in the middle of the three?",
        "centre shelf unit of the three",
        "There are three bookcases along the wall. I want the one between the other two.",
        "The tall brown bookcase between the other brown one and the short white one.",
        "the bookshelf sitting between its two neighbours",
    ]),
    ("s", SOFF, 21, [21], [
        "the bin by the door",
        "Could you take me to the wastebasket closest to the exit?",
        "trash can nearest door",
        "There are two rubbish bins. I want the one next to the door, not the one in the far corner.",
        "The wastepaper basket right beside the doorway.",
        "bin near the dorr",
    ]),
    ("s", SOFF, 11, [11], [
        "the screen on the white table",
        "Take me to the monitor sitting on the white desk.",
        "display, white table",
        "It's a black computer screen. It stands on the white table, not the wooden one.",
        "the only screen on the white table",
        "Could you find the monitor on the white desk with the black keyboard in front of it?",
    ]),
    ("s", SOFF, 23, [23], [
        "the plant in the corner by the window",
        "Could you take me to the big potted greenery near the windows?",
        "greenery, window corner",
        "There are two plants. I want the tall one in the corner next to the window, not the small one by the shelves.",
        "the houseplant closest to the window",
        "the leafy pot furthest from the bookcases",
    ]),
    ("s", SBED, 7, [7], [
        "standing at the foot of the bed facing the headboard, the bedside table on the right",
        "Facing the bed from its foot end, take me to the nightstand on my right.",
        "right nightstand (from foot of bed)",
        "The bedside table with the blue book on it.",
        "The bedside table nearer the door, please.",
        "It's a small wooden bedside table. It's the one with the book on it, not the one with the clock.",
    ]),
    ("s", SBED, 4, [4], [
        "the pillow between the two white ones",
        "Take me to the cushion sitting in the middle of the two white pillows.",
        "middle cushion, headboard",
        "There are two big white ones at the head of the bed. I want the small cushion between them.",
        "the cushion in between the white ones, not the one lying further down the bed",
        "the little cushion flanked by the big white ones",
    ]),
    ("s", flat("h"), 47, [47], [
        "the bedside table with the book on it",
        "Could you take me to the nightstand that has a paperback lying on top?",
        "bedside table + novel on top",
        "There are two bedside tables in the master bedroom. Take me to the one with the orange book on it.",
        "The bedside table on the east side of the double bed.",
        "Standing at the foot of the double bed looking at the headboard, the night stand on the right.",
    ]),
    ("s", flat("e"), 13, [13], [
        "the green chair on the north side nearest the living room",
        "Could you take me to the sage green seat next to the black metal chair?",
        "dining seat, north-west corner of table",
        "It's one of the green wooden dining seats. It sits on the north side of the table, at the west end.",
        "At the dining table, the seat diagonally opposite the south-east one.",
        "the sage seat in the table's north-west corner, not the black one beside it",
    ]),
    ("s", flat("g"), 35, [35], [
        "facing the bed from its foot, the lamp on the right-hand bedside table",
        "Standing at the foot of the bed, take me to the light on my right.",
        "bedside light, right side (from foot of bed)",
        "The reading light on the side of the bed closest to the wicker hamper.",
        "the bedside lamp farthest from the wardrobe",
        "the bedside lihgt on the east side of the bed",
    ]),
    ("s", flat("i"), 36, [36], [
        "the mug on the coffee table",
        "Could you take me to the cup sitting on the low table in front of the sofa?",
        "cup on cofee table",
        "There's a cup of cold tea. It's on the low table in the living room.",
        "the cup closest to the sofa",
        "Take me to the mug on the teak table, not the ones on the desk or the worktop.",
    ]),
    ("s", flat("d"), 22, [22], [
        "the stool nearer the fridge",
        "Could you take me to the bar seat closest to the refrigerator?",
        "kitchenette seat closest to the fridge",
        "There are two stools in the kitchenette. I want the one closer to the fridge, not the one near the bin.",
        "the backless seat further east",
        "Facing the worktop, the left-hand one of the two bar seats.",
    ]),
    ("s", APT, 39, [39], [
        "the plant on top of the dresser",
        "Could you take me to the little potted succulent sitting on the chest of drawers?",
        "pot on dresser",
        "There's a tiny plant in a terracotta pot. It's on the chest of drawers in the bedroom.",
        "the greenery sitting on the bedroom drawers",
        "The houseplant that's up on furniture, not on the floor.",
    ]),
]

# (group number, wording number, typed word, intended word) -- every deliberate typo
TYPOS = [
    (1, 6, "pilow", "pillow"), (2, 5, "toliet", "toilet"), (5, 5, "bycicles", "bicycles"),
    (6, 5, "mirors", "mirrors"), (8, 6, "armchiar", "armchair"), (10, 6, "dinning", "dining"),
    (11, 6, "nighstands", "nightstands"), (12, 6, "chiars", "chairs"), (13, 6, "boks", "books"),
    (14, 6, "lmap", "lamp"), (16, 6, "bwol", "bowl"), (19, 6, "dor", "door"),
    (21, 2, "keybaord", "keyboard"), (22, 6, "tabel", "table"), (23, 5, "towls", "towels"),
    (24, 6, "chiar", "chair"), (26, 6, "scren", "screen"), (31, 3, "pupy", "puppy"),
    (35, 5, "kyes", "keys"), (36, 3, "docment", "document"), (38, 6, "dorr", "door"),
    (45, 6, "lihgt", "light"), (46, 3, "cofee", "coffee"),
]


def main() -> None:
    counts = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    assert len(GROUPS) == 48
    for t, n in counts.items():
        assert sum(g[0] == t for g in GROUPS) == n, t
    for g, w, typo, word in TYPOS:
        assert typo in GROUPS[g - 1][4][w - 1], (g, w, typo)
    lines = []
    for gi, (t, m, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6 and target in accept
        for wi, q in enumerate(words, 1):
            lines.append(json.dumps({
                "id": f"b15-g{gi:02d}-w{wi}", "map": m, "query": q, "type": t,
                "target": target, "accept": sorted(accept), "group": f"b15-g{gi:02d}",
            }))
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {OUT}")


if __name__ == "__main__":
    main()
