"""Hand-written blind suite round 31: 48 groups x 6 wordings. Writes ../evals/blind/round31.jsonl.

Each group: (map key, type, target, accept, [w1..w6]).  SPATIAL holds the numeric claims that
check.py verifies for the spatial groups (and the contrasts named in their w4 wordings)."""
import json
from pathlib import Path

MAPS = {
    "s829": "../../../shared/data/iesm_maps/scene_00829_caption.json",
    "off3": "../../../shared/data/iesm_maps/scene_office3_caption.json",
    "fc": "maps/flat_c.json", "fd": "maps/flat_d.json", "ff": "maps/flat_f.json", "fh": "maps/flat_h.json",
    "apt": "apartment",
    "sb": "../maps/scan_bedroom.json", "sk": "../maps/scan_kitchen.json",
    "sl": "../maps/scan_livingroom.json", "so": "../maps/scan_office.json",
}

GROUPS = [
    # ---------------- caption map scene_00829 / office3 ----------------
    ("s829", "o", 78, [78, 234], [
        "Go to a wall tv.",
        "Could you take me to one of the televisions mounted on a wall?",
        "wall-mounted television",
        "I want to catch the news, so find me a TV hung on the wall, any of them will do.",
        "This is a flat television fixed to a wall. It is used for watching shows.",
        "take me to a wall televsion, whichever one"]),
    ("s829", "o", 249, [249], [
        "Go to the keyboard.",
        "Could you bring me over to where the computer keyboard is?",
        "typing keys",
        "I need to type a long email, so find something with keys to type on, the computer kind, not a piano.",
        "This is a flat input device with rows of keys. It is used for typing into a computer.",
        "where's the thing i type on, the computer keybaord?"]),
    ("off3", "o", 10, [10, 14, 16, 24], [
        "Go to a window.",
        "Could you guide me to any of the windows?",
        "glass pane to outside",
        "I'd like to see what the weather is doing, so take me to any glazed opening in the wall, I don't care which.",
        "This is a glazed opening in the wall. It lets daylight into the room.",
        "i need to look outside, take me to one of the windos"]),
    ("s829", "or", 261, [261, 263], [
        "Go to an easy chair in the bedroom.",
        "Could you take me to one of the lounge armchairs in the bedroom?",
        "bedroom lounge armchair",
        "I want to sit back comfortably where I sleep, so any of the padded armchairs in the bedroom, not the plain armless one.",
        "This is a deep, comfy armchair for relaxing. It stands in the bedroom.",
        "take me to a comfy armchiar in the bedroom"]),
    ("off3", "or", 8, [8, 13, 20, 40], [
        "Go to a pillow in the rec room.",
        "Could you bring me to one of the cushions in the recreation room?",
        "rec room cushion",
        "My back hurts, so find me any throw cushion in the rec room, I don't mind which colour.",
        "This is a soft cushion to lean against. It is in the rec room.",
        "any cusion in the rec room will do"]),
    ("s829", "od", 86, [86], [
        "Go to the black metal gadget with a round little display.",
        "Could you show me the black metal device that has a circular screen and a small knob-like handle?",
        "black metal thing, round screen",
        "I want to figure out what that odd appliance is, the dark metal one with the circular display, not the wall TV.",
        "This is an unidentified black metal item. It has a round screen and a small round grip.",
        "where's that black meatl gizmo with the round screen"]),
    ("off3", "od", 13, [13], [
        "Go to the navy velvet cushion.",
        "Could you find the dark blue velvety pillow for me?",
        "navy velvet pillow",
        "I want the plushest-looking one: the navy blue velvet cushion, not the orange or yellow ones.",
        "This is a dark blue cushion with a velvety cover. It is a bit bigger than the other cushions.",
        "grab me the navy blue velvet pilow"]),
    ("s829", "ord", 184, [184], [
        "Go to the L-shaped couch in the bedroom.",
        "Could you take me to the corner sofa with the chaise in the bedroom?",
        "bedroom L-shaped sofa",
        "I want to lie down with my legs up, so the beige sectional in the bedroom, not the plush sofa in the living room.",
        "This is a beige fabric sofa shaped like an L. It is in the bedroom.",
        "take me to the l-shaped sofa in the bedrom"]),
    ("off3", "ord", 7, [7], [
        "Go to the white desk in the rec room.",
        "Could you take me to the white wooden writing table in the rec room?",
        "white work table, rec room",
        "I need the light-coloured one to work at: the white desk in the rec room, not the brown wooden ones.",
        "This is a work table made of white wood. It is in the rec room and has a USB port.",
        "go to the whte work table in the rec room"]),
    ("s829", "ard", 192, [192], [
        "Go to where the dog can curl up and sleep.",
        "Could you take me to the spot where my pet can nap?",
        "somewhere for pet to sleep",
        "The cat is tired and keeps sleeping on the couch, so show me the place meant for her instead.",
        "This is a thing a small animal can sleep in. It is soft and padded.",
        "my puppy needs a comfy spot to slep, where should she go"]),
    ("off3", "ard", 25, [25], [
        "Go to whatever will tell me the time.",
        "Could you take me to something that shows what time it is?",
        "time check",
        "I'm worried I'm late for a meeting, so take me to what shows the hour on the wall, not my phone.",
        "This is the thing I need to see how late it is. It hangs on the wall.",
        "what tme is it? take me to something that shows it"]),
    ("off3", "ard", 3, [3], [
        "Take me somewhere I can stretch out and nap.",
        "Could you take me to a spot where I can lie down for a bit?",
        "somewhere to lie down",
        "I'm exhausted and want to put my feet up: somewhere soft to lie on, not a hard bench or an office seat.",
        "This is where I want to lounge. It is long, soft and gray, big enough to lie on.",
        "i need a npa, where can i lie down"]),
    # ---------------- flat_c ----------------
    ("fc", "o", 5, [5, 7, 28, 36], [
        "Go to a lamp.",
        "Could you take me to any light I can switch on?",
        "any lamp",
        "It's getting dark and I want to read, so find me any light fitting to switch on: floor, table or desk, I don't mind.",
        "This is a light source with a shade. It gives light when switched on.",
        "find me a lammp, any one"]),
    ("fc", "s", 27, [27], [
        "Go to the nightstand closest to the wardrobe.",
        "Could you take me to the bedside table nearer the tall oak closet?",
        "bedside table nearest wardrobe",
        "I want to put my watch down on the way to get dressed, so the bedside table on the wardrobe side, not the one far from it.",
        "This is a white bedside table. It is the one closer to the wardrobe.",
        "go to the bedside tabel next to the wardrobe"]),
    ("fc", "ord", 21, [21], [
        "Go to the black metal chair in the kitchen.",
        "Could you take me to the dark metal seat at the kitchen table?",
        "kitchen black metal seat",
        "I want the metal one, not the white wooden dining chairs: the black seat in the kitchen.",
        "This is a black seat made of metal. It is at the dining table in the kitchen.",
        "the blak metal seat in the kitchen please"]),
    ("fc", "ard", 17, [17], [
        "Take me to something I can boil water in for tea.",
        "Could you show me what I'd use to heat water quickly for a cuppa?",
        "boil water fast",
        "I want a quick cup of tea without firing up the cooker, so what do I heat the water with?",
        "This is what I need to get hot water for coffee. It plugs in and sits on the worktop.",
        "need hot watr for tea, what do i boil it in"]),
    # ---------------- flat_d ----------------
    ("fd", "or", 4, [4, 5, 7], [
        "Go to a chair in the studio.",
        "Could you take me to any seat in the studio that isn't the sofa bed?",
        "studio chair",
        "I just need to sit for a minute: any of the single seats in the studio, not the little one in the kids room.",
        "This is a seat for one person. It is in the studio.",
        "any saet in the studio, i want to sit"]),
    ("fd", "od", 20, [20], [
        "Go to the red toaster.",
        "Could you take me to the red appliance that browns bread?",
        "red two-slot toaster",
        "I'm making breakfast and want the red thing for crisping bread, not the white kettle.",
        "This is a small red metal appliance. It has two slots for slices of bread.",
        "where's the red toastr"]),
    ("fd", "s", 21, [21], [
        "Go to the stool nearest the bin.",
        "Could you take me to the bar stool closer to the pedal bin?",
        "seat nearest trash",
        "I'm going to throw something away, so the high seat on the bin side, not the one nearer the fridge.",
        "This is a black metal bar seat. It is the one closer to the trash can.",
        "the stoool closest to the rubbish bin"]),
    ("fd", "ard", 25, [25], [
        "Take me to what I can use to dry my wet laundry.",
        "Could you take me to where I can get my freshly washed clothes dry?",
        "dry wet clothes",
        "The wash just finished and it's raining outside, so I can't hang the clothes out. Where do I get them dry?",
        "This is where damp clothes go after washing. It tumbles them with warm air.",
        "my clothes are soaking wet, where do i dry them qiuckly"]),
    ("fd", "ord", 34, [34], [
        "Go to the pink moon lamp in the kids room.",
        "Could you take me to the little pink night light in the children's room?",
        "pink moon light, kids room",
        "My daughter is scared of the dark: the pink moon-shaped light on her desk in the kids room, not the desk lamp in the studio.",
        "This is a small pink plastic light in the form of the moon. It is on the children's desk in the kids room.",
        "the pnik moon light in the kids room"]),
    # ---------------- flat_f ----------------
    ("ff", "s", 15, [15], [
        "Go to the chair closest to the fridge.",
        "Could you take me to the dining chair nearest the refrigerator?",
        "seat nearest fridge",
        "I'll be getting milk out, so the seat at the table next to the fridge, not the yellow one.",
        "This is a blue painted wooden seat at the dining table. It is the one nearest to the fridge.",
        "take me to the dinning seat closest to the fridge"]),
    ("ff", "ard", 25, [25], [
        "Take me to what I can use to look at the stars.",
        "Could you take me to something for watching the night sky?",
        "stargazing",
        "There's a meteor shower tonight and my eyes aren't good enough, so what can I look at the planets through?",
        "This is what I want for seeing distant things in the sky. It stands on three legs on the porch.",
        "i want to see the moon up close, what's there for stargazng"]),
    ("ff", "or", 12, [12, 13, 14, 15], [
        "Go to one of the kitchen chairs.",
        "Could you take me to any of the dining chairs in the kitchen?",
        "kitchen seat",
        "I'm going to eat, so any seat at the kitchen table will do, not the rocking one on the porch.",
        "This is a wooden seat at the dining table. It is in the kitchen.",
        "any kitchen saet is fine"]),
    ("ff", "od", 3, [3], [
        "Go to the cream leather armchair.",
        "Could you take me to the pale leather easy chair with rounded arms?",
        "cream leather armchair",
        "I want to read somewhere comfy, but not in the red tartan wingback: the cream leather one.",
        "This is a light, creamy leather chair for lounging. Its arms are rounded.",
        "the cream lether easy chair pls"]),
    ("ff", "ord", 14, [14], [
        "Go to the yellow chair in the kitchen.",
        "Could you take me to the mustard-coloured seat at the kitchen table?",
        "yellow kitchen seat",
        "I always sit in the odd one: the yellow seat in the kitchen, not any of the blue ladder-backs.",
        "This is a mustard painted wooden seat. It is at the dining table in the kitchen, unlike the blue ones.",
        "the yelow seat in the kitchen"]),
    # ---------------- flat_h ----------------
    ("fh", "o", 13, [13, 26, 32], [
        "Go to a mug.",
        "Could you take me to any coffee cup in the flat?",
        "any mug",
        "I want a hot drink, so any cup will do: the one on the coffee table, the desk or the worktop.",
        "This is a drinking cup with a handle. It holds tea or coffee.",
        "find me a coffe cup, i don't care which"]),
    ("fh", "or", 46, [46, 47], [
        "Go to a nightstand in the master bedroom.",
        "Could you take me to one of the bedside tables in the main bedroom?",
        "master bedroom bedside table",
        "I need to set my glasses down: either bedside table in the master bedroom, not the pine one in the guest room.",
        "This is a white bedside table with a drawer. It is in the master bedroom.",
        "either bedside tabel in the master bedroom"]),
    ("fh", "s", 47, [47], [
        "Go to the nightstand with the book on it.",
        "Could you take me to the bedside table that has a paperback on top?",
        "bedside table under novel",
        "I left my novel somewhere, so go to the bedside table holding the paperback, not the one with the lamp.",
        "This is a white bedside table in the master bedroom. It has an orange novel lying on it.",
        "the bedside tabel with the paperback on it"]),
    ("fh", "ord", 6, [6], [
        "Go to the cream sofa in the living room.",
        "Could you take me to the small linen loveseat in the living room?",
        "living room cream two-seater",
        "I want the little one by the window: the cream settee in the living room, not the green velvet one.",
        "This is a small pale linen couch for two. It is in the living room under a window.",
        "the cream setee in the living room"]),
    ("fh", "ard", 4, [4], [
        "Take me to where I should leave my house keys.",
        "Could you take me to the place where we put our keys when we come in?",
        "drop keys",
        "I keep losing my keys, so where do they go when I get home? Not on the coat rack.",
        "This is the spot where keys are left. It is on the narrow table in the hall.",
        "where do the keys go when i come hoem"]),
    ("fh", "s", 17, [17], [
        "Go to the black chair nearer the window in the dining room.",
        "Could you take me to the black bistro chair closest to the window?",
        "black bistro seat nearest window",
        "I want some daylight while I eat: the black metal seat on the window side, not the other black one.",
        "This is a black metal seat at the dining table. Of the two black ones, it is nearer the tall east window.",
        "the blak seat closest to the dining room window"]),
    # ---------------- apartment ----------------
    ("apt", "o", 12, [12, 13, 52], [
        "Go to a book.",
        "Could you take me to any book in the apartment?",
        "something to read, any volume",
        "I'm bored and want to read, so any volume will do, whether in the living room or the office.",
        "This is a bound volume of printed pages. It is something to read.",
        "find me a bok to read, any one"]),
    ("apt", "or", 23, [23, 24], [
        "Go to one of the kitchen chairs.",
        "Could you take me to a dining chair in the kitchen?",
        "kitchen seat",
        "I want to eat at the table, so any kitchen seat, not the red office one.",
        "This is a wooden seat by the dining table. It is in the kitchen.",
        "any kichen seat is ok"]),
    ("apt", "od", 31, [31], [
        "Go to the black-and-white lighthouse photo.",
        "Could you take me to the small monochrome photograph of a lighthouse?",
        "lighthouse photo",
        "I want to look at the little lighthouse snapshot, not the big blue abstract painting.",
        "This is a small photo in black and white. It shows a lighthouse and has a thin dark frame.",
        "the litle lighthouse photo"]),
    ("apt", "od", 42, [42], [
        "Go to the gray wooden vanity.",
        "Could you take me to the grey wooden cupboard below the washbasin?",
        "gray vanity unit",
        "I need a fresh towel: the gray vanity cupboard under the basin, not the kitchen cupboards.",
        "This is a gray wooden cupboard under a washbasin. It holds towels and toiletries.",
        "the grey cupbaord under the sink"]),
    ("apt", "ord", 52, [52], [
        "Go to the green book in the office.",
        "Could you take me to the thick green textbook in the office?",
        "office green textbook",
        "I need to look up some code: the green programming book in the office, not the novels in the living room.",
        "This is a thick green volume about programming. It sits on the shelves in the office.",
        "the green progamming textbook in the office"]),
    ("apt", "ard", 54, [54], [
        "Take me to where I can print out a document.",
        "Could you take me to what I'd use to get a paper copy of my file?",
        "print document",
        "My boarding pass is on my laptop and I need it on paper, so where can I get it printed?",
        "This is what I need to put my file onto paper. It stands on the gray metal drawers in the office.",
        "i need to prnt my tickets, where do i go"]),
    ("apt", "s", 12, [12], [
        "Go to the book on the higher shelf in the living room.",
        "Could you take me to the living room volume that's higher up on the shelves?",
        "upper-shelf hardback, living room",
        "I want the one up high: the living room volume on the upper shelf, not the one lying on the bottom shelf.",
        "This is a red hardcover standing in the living room bookcase. Of the two there, it is the higher one.",
        "the higher novle on the living room shelf"]),
    ("apt", "s", 1, [1], [
        "Go to the sofa farther from the TV.",
        "Could you take me to the couch that is farther away from the television?",
        "couch farthest from TV",
        "The screen hurts my eyes up close, so the settee farther from the telly, not the little leather loveseat.",
        "This is a large gray fabric couch in the living room. Of the two couches, it is farther from the TV.",
        "the cuoch furthest from the tv"]),
    # ---------------- scans ----------------
    ("so", "o", 11, [11, 12, 13], [
        "Go to a monitor.",
        "Could you take me to any of the computer screens?",
        "computer display",
        "I need to check something on a computer, so any screen on the tables will do.",
        "This is a flat computer display on a table. It is black.",
        "take me to any computr screen"]),
    ("sk", "or", 23, [23, 24, 25], [
        "Go to a cup in the kitchen.",
        "Could you take me to any mug in the kitchen?",
        "kitchen mug",
        "I'm thirsty, so any drinking cup in the kitchen, on the table or by the sink.",
        "This is a small drinking vessel. It is in the kitchen.",
        "any mugg in the kitchen"]),
    ("sl", "od", 3, [3], [
        "Go to the yellow pillow.",
        "Could you take me to the yellow cushion?",
        "yellow cushion",
        "I want the yellow throw cushion, not either of the red ones.",
        "This is a yellow cushion. It sits on the gray sofa.",
        "the yelow cushion on the couch"]),
    ("sk", "s", 25, [25], [
        "Go to the cup next to the sink.",
        "Could you take me to the mug closest to the sink?",
        "mug nearest sink",
        "I want the one by the sink, not the ones on the dining table.",
        "This is a white cup on the counter. It is the one nearest the sink.",
        "the mug next to the snik"]),
    ("sk", "s", 21, [21], [
        "Go to the chair at the end of the table nearest the door.",
        "Could you take me to the seat at the door end of the table?",
        "seat at table end by door",
        "I want to slip out quickly after eating, so the seat at the head of the table closest to the door, not the one at the far end.",
        "This is a red seat at a short end of the table. It is at the end closer to the door.",
        "the seat at the end of the tabel near the door"]),
    ("so", "s", 3, [3], [
        "Go to the office chair farthest from the door.",
        "Could you take me to the desk chair that's the greatest distance from the door?",
        "swivel chair farthest from door",
        "I want to be as far from the corridor noise as possible: the work seat farthest from the door.",
        "This is a black office chair at the white table. It is the one farthest from the door.",
        "the desk chiar farthest from the door"]),
    ("so", "s", 15, [15], [
        "Go to the bookshelf in the middle of the three.",
        "Could you take me to the bookcase between the other two?",
        "middle bookcase",
        "I need the one in the middle: the bookcase between the other two, not either end one.",
        "This is a tall brown wooden bookcase against the wall. It stands between the other two.",
        "the midle bookcase of the three"]),
    ("sb", "s", 8, [8], [
        "Go to the lamp nearest the window.",
        "Could you take me to the bedside light closest to the window?",
        "light by window",
        "I want the light on the window side of the bed, not the one by the door.",
        "This is a white lamp on a nightstand. It is the one closer to the window.",
        "the bedside lihgt closest to the window"]),
]

# Spatial claims per group number (1-based): (kind, args).  check.py evaluates them.
#   nearest/farthest: (ref id, candidate ids, expected id)   -- 2-D centre distance, margin >= 0.2 m
#   higher: (candidate ids, expected id)                     -- centre height, margin >= 0.2 m
#   on: (top id, support id)                                 -- top's centre inside support footprint, bottoms/tops meet
#   between: (id, a, b)                                      -- id lies between a and b along the a-b line
#   endof: (id, table id)                                    -- id beyond a short end of the table, within its width
SPATIAL = {
    14: [("nearest", (30, [26, 27], 27))],
    19: [("nearest", (23, [21, 22], 21)), ("nearest", (15, [21, 22], 22))],
    22: [("nearest", (20, [12, 13, 14, 15, 21, 33, 39], 15))],
    29: [("on", (49, 47)), ("on", (48, 46))],
    32: [("nearest", (20, [16, 17], 17)), ("nearest", (20, [16, 17, 18], 17))],
    39: [("higher", ([12, 13], 12))],
    40: [("farthest", (4, [1, 2], 1))],
    44: [("nearest", (10, [23, 24, 25], 25))],
    45: [("nearest", (15, [17, 18, 19, 20, 21, 22], 21)), ("endof", (21, 16))],
    46: [("farthest", (20, [3, 4, 5, 6, 7, 8, 9, 10], 3))],
    47: [("between", (15, 14, 16))],
    48: [("nearest", (14, [8, 9], 8)), ("nearest", (15, [8, 9], 9))],
}


def rows():
    out = []
    for g, (mk, typ, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, g
        for k, q in enumerate(words, 1):
            out.append({"id": f"b31-g{g:02d}-w{k}", "map": MAPS[mk], "query": q, "type": typ,
                        "target": target, "accept": sorted(accept), "group": f"b31-g{g:02d}"})
    return out


if __name__ == "__main__":
    dest = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round31.jsonl"
    rs = rows()
    dest.write_text("".join(json.dumps(r, ensure_ascii=False) + "\n" for r in rs), encoding="utf-8")
    print(f"wrote {len(rs)} lines, {len(GROUPS)} groups to {dest}")
