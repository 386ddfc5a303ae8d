"""Hand-written groups of blind round 33; writes evals/blind/round33.jsonl.

Each group: (type, map, target, accept, spec, [w1..w6]).
spec is used by check.py: for o {"label"}, for or {"label","room"},
for s a relation (see check.py); for od/ord/ard {"label"} of the target only.
"""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

G = [
 # ---------------- caption map scene_00829 ----------------
 ("o", C829, 122, [122], {"label": "toilet"}, [
  "Go to the toilet.",
  "Could you show me where the loo is?",
  "WC location",
  "I really need to pee, so take me to the lavatory.",
  "This is a white porcelain fixture for relieving yourself. It is flushed with water after use.",
  "where's the toliet"]),
 ("o", C829, 153, [153], {"label": "backpack"}, [
  "Go to the backpack.",
  "Could you find my rucksack for me?",
  "rucksack location",
  "I'm packing for a hike and need the knapsack, not the toiletry bag.",
  "This is a bag you carry on your back. It is black with a padded shoulder strap.",
  "hey where did i leave my bakcpack"]),
 ("or", C829, 261, [261, 263], {"label": "easy chair", "room": "bedroom"}, [
  "Go to an easy chair in the bedroom.",
  "Could you take me to one of the armchairs in the bedroom?",
  "bedroom lounge chair",
  "I want to read somewhere comfy in the bedroom, so an armchair there, not one in the living room.",
  "This is a cushioned seat with arms for relaxing. It is in the bedroom.",
  "can u go to a comfy armchiar in the bedroom"]),
 ("or", C829, 34, [34, 74], {"label": "side table", "room": "living room"}, [
  "Go to a side table in the living room.",
  "Could you head over to one of the end tables in the living room?",
  "living room end table",
  "I want to set my drink down next to the seating, so an end table in the lounge, not the ones in the bedroom.",
  "This is a small table that sits beside a seat. It is in the living room.",
  "go to one of the littel side tables in the living room"]),
 ("od", C829, 211, [211], {"label": "decorative bowl"}, [
  "Go to the deep blue bowl with gold patterns.",
  "Could you find the blue ceramic bowl decorated in gold?",
  "blue gilded bowl",
  "I'm after the glossy blue ornamental dish, not the white sweets bowl with the golden rim.",
  "This is an ornamental ceramic dish. It is deep blue and glazed, with gold detailing.",
  "where's that blue bowl with the gold pattrens on it"]),
 ("od", C829, 184, [184], {"label": "couch"}, [
  "Go to the L-shaped beige couch.",
  "Could you take me to the corner sofa with the chaise?",
  "L-shaped fabric sofa",
  "I want the sectional with the built-in lounger end, not the beige couch that has a massage system.",
  "This is a large sofa bent into an L. It is covered in light beige fabric and has storage inside.",
  "go to the l-shaped sectionnal with the chaise end"]),
 ("ord", C829, 110, [110], {"label": "stand/small table", "room": "bathroom"}, [
  "Go to the honey-coloured little table in the bathroom.",
  "Could you go to the small wooden table with the X-shaped metal legs in the bathroom?",
  "bathroom honey wood side stand",
  "Take me to the warm-toned small table in the bathroom, not the dark wooden ones elsewhere; I want to charge my phone there.",
  "This is a small light wooden table on a crossed metal base. It is in the bathroom.",
  "go to the small honey colored tabel in the bathroom"]),
 ("ord", C829, 197, [197], {"label": "book", "room": "bathroom"}, [
  "Go to the red book in the bathroom.",
  "Could you fetch the red leather-bound volume from the bathroom?",
  "red book bathroom",
  "I left my red volume in the bathroom, not the dark brown one in the bedroom; take me to it.",
  "This is a volume bound in red leather, with gilt lettering on the cover. It is in the bathroom.",
  "pls go get the red novle from the bathroom"]),
 ("ard", C829, 192, [192], {"label": "bed for pet"}, [
  "Go to where the dog sleeps.",
  "Could you show me where our cat curls up to sleep?",
  "pet sleeping spot",
  "The puppy is tired; take me to his own sleeping place, not the one the people use.",
  "This is where the household animal sleeps. It is soft and made just for pets.",
  "where does the cat sleeep"]),
 # ---------------- caption map scene_office3 ----------------
 ("o", OF3, 8, [8, 13, 20, 40], {"label": "pillow"}, [
  "Go to a pillow.",
  "Could you bring me to one of the cushions?",
  "any cushion",
  "My back hurts on this chair, so find me a cushion, any one will do.",
  "This is a soft stuffed cushion. It is one of several in the rec room, and any colour will do.",
  "can u find me a cusion"]),
 ("or", OF3, 7, [7, 55, 64], {"label": "desk", "room": "rec room"}, [
  "Go to a desk in the rec room.",
  "Could you take me to one of the computer workstations in the rec room?",
  "rec room workstation",
  "I need to sit and write a letter, so any desk in the recreation room will do.",
  "This is a piece of furniture you sit at to work, with a flat top for a computer. It stands in the rec room.",
  "go to a workstaton in the rec room"]),
 ("od", OF3, 13, [13], {"label": "pillow"}, [
  "Go to the navy blue velvet cushion.",
  "Could you find the dark blue velvety pillow?",
  "navy cushion",
  "Bring me to the navy one, not the orange or yellow cushions.",
  "This is a cushion with a button in the middle. It is velvety and navy blue.",
  "where's the navy blue pilow"]),
 ("ord", OF3, 7, [7], {"label": "desk", "room": "rec room"}, [
  "Go to the white desk in the rec room.",
  "Could you take me to the white wooden workstation in the rec room?",
  "white desk rec room",
  "In the rec room, I want the white one, not the brown wooden ones.",
  "This is a wooden work surface painted white. It is in the rec room and has a USB port.",
  "go to the whiet workstation in the rec room"]),
 ("ard", OF3, 3, [3], {"label": "sofa"}, [
  "Take me somewhere I can lie down for a nap.",
  "Could you find me a place to stretch out and doze?",
  "spot to lie down",
  "I'm exhausted and want to put my feet up and snooze, not sit upright on an office chair.",
  "This is somewhere soft to lie flat and doze. It is long enough to stretch out on.",
  "need somwhere to take a nap"]),
 # ---------------- flats ----------------
 ("o", FC, 2, [2, 3], {"label": "armchair"}, [
  "Go to an armchair.",
  "Could you take me to one of the easy chairs?",
  "lounge chair",
  "I want to sit on my own with a book, so any single upholstered seat with arms, not the sofa.",
  "This is a padded seat for one person with arms on both sides. It is one of the two in the living room, either will do.",
  "go to an armcahir pls"]),
 ("o", FF, 7, [7, 32], {"label": "rug"}, [
  "Go to a rug.",
  "Could you take me to one of the carpets?",
  "floor rug",
  "I want to do some stretches on something soft on the floor, like a carpet, either one.",
  "This is a woven covering lying on the floor. It is either the one in the lounge or the one in the bedroom.",
  "go to one of the carpts"]),
 ("or", FH, 16, [16, 17, 18], {"label": "chair", "room": "dining room"}, [
  "Go to a chair in the dining room.",
  "Could you take me to one of the dining room seats?",
  "dining room seat",
  "I want to sit down to eat, so any seat at the table in the dining room, not the office chair in the study.",
  "This is a seat for eating at a table. It is in the dining room.",
  "go to a seat in the dinning room"]),
 ("or", FD, 4, [4, 5, 7], {"label": "chair", "room": "studio"}, [
  "Go to a chair in the studio.",
  "Could you take me to one of the single chairs in the studio?",
  "studio single seat",
  "I need to sit for a minute, any one-person seat in the studio, not the little one in the kids room.",
  "This is something for one person to sit on, with a backrest. It is in the studio.",
  "go to a chiar in the studio"]),
 ("od", FH, 10, [10], {"label": "armchair"}, [
  "Go to the cognac leather armchair.",
  "Could you take me to the brown leather club chair with the brass studs?",
  "studded leather armchair",
  "I want the leather one by the bookcase, not the mustard velvet one in the corner.",
  "This is a tan leather club-style seat. It is decorated with brass studs.",
  "go to the brown lether club chair"]),
 ("od", FF, 14, [14], {"label": "chair"}, [
  "Go to the mustard-yellow chair.",
  "Could you take me to the yellow painted wooden chair?",
  "yellow dining seat",
  "I want the yellow one at the table, not the blue ladder-back seats.",
  "This is a painted wooden dining seat. It is mustard yellow, unlike the others around the table.",
  "go to the yelow seat at the dining table"]),
 ("ord", FC, 21, [21], {"label": "chair", "room": "kitchen"}, [
  "Go to the black metal chair in the kitchen.",
  "Could you take me to the dark metal seat at the kitchen table?",
  "black metal kitchen seat",
  "In the kitchen I want the black metal one, not the white wooden chairs.",
  "This is a metal seat at the dining table. It is black and stands in the kitchen.",
  "go to the blakc metal seat in the kitchen"]),
 ("ord", FH, 48, [48], {"label": "lamp", "room": "master bedroom"}, [
  "Go to the white ceramic lamp in the master bedroom.",
  "Could you take me to the white bedside light in the master bedroom?",
  "master bedroom white bedside light",
  "In the master bedroom, the white ceramic light with the pleated shade, not the red one in the guest room.",
  "This is a bedside light with a white ceramic base and a pleated shade. It is in the master bedroom.",
  "go to the white bedside lmap in the main bedroom"]),
 ("ard", FD, 25, [25], {"label": "dryer"}, [
  "Take me to where I can dry my wet laundry.",
  "Could you show me the machine that dries clothes?",
  "drying clothes",
  "The wash just finished and I need to dry it, not wash it again.",
  "This is the appliance that gets damp laundry dry. It is in the laundry room and tumbles clothes in warm air.",
  "where can i dry my cloths"]),
 ("ard", FF, 25, [25], {"label": "telescope"}, [
  "Take me to something I can use to look at the stars.",
  "Could you show me what I'd use to watch the night sky?",
  "stargazing gear",
  "I want to see the moon up close tonight, not just look out the window.",
  "This is something for observing planets and stars. It is out on the porch and magnifies distant things in the sky.",
  "i wanna look at the plannets tonight"]),
 ("ard", FH, 4, [4], {"label": "bowl"}, [
  "Take me to where I should leave my keys when I come home.",
  "Could you show me where we drop our keys in the hallway?",
  "key drop spot",
  "I just got home and want to put my keys down where they always go, not on the kitchen counter.",
  "This is the place to drop my keys as I come in. It is on the table in the hall.",
  "where do i leave my kyes"]),
 ("s", FC, 7, [7], {"label": "lamp", "rel": "on", "ref": 6}, [
  "Go to the lamp on the side table.",
  "Could you take me to the light standing on the small black table beside the sofa?",
  "light on side table",
  "Not the tall brass floor lamp, the small one sitting on the black metal side table.",
  "This is a small light with a white base. It stands on top of the black side table at the sofa's end.",
  "go to the litle light on the side table"]),
 ("s", FH, 47, [47], {"label": "nightstand", "room": "master bedroom", "rel": "nearest", "ref": 50}, [
  "Go to the nightstand in the master bedroom that is closest to the wardrobe.",
  "Could you take me to the master bedroom bedside table nearer the tall white wardrobe?",
  "master bedroom bedside table by wardrobe",
  "In the master bedroom, the bedside table next to the wardrobe, not the one on the far side of the bed.",
  "This is a bedside table in the master bedroom. It is the one nearer to the glossy white wardrobe.",
  "go to the bedsde table closest to the wardrobe in the master bedroom"]),
 ("s", FF, 13, [13], {"label": "chair", "room": "kitchen", "rel": "farthest", "ref": 17}, [
  "Go to the kitchen chair that is farthest from the stove.",
  "Could you take me to the dining seat in the kitchen furthest away from the range cooker?",
  "kitchen seat farthest from cooker",
  "It gets too hot by the range, so take me to the kitchen table seat farthest from it.",
  "This is a blue wooden seat at the kitchen table. It is the one farthest from the cream range cooker.",
  "go to the kitchen seat furthest from the stvoe"]),
 ("s", FD, 22, [22], {"label": "stool", "rel": "nearest", "ref": 15, "also": {"rel": "nearest", "ref": 23, "expect": 21}}, [
  "Go to the stool nearest the fridge.",
  "Could you take me to the bar seat closer to the refrigerator?",
  "stool by fridge",
  "Of the two bar seats, I want the one closer to the fridge, not the one nearer the bin.",
  "This is a backless seat in the kitchenette. It is the one closer to the refrigerator.",
  "go to the stoool closest to the fridge"]),
 ("s", FH, 13, [13], {"label": "mug", "rel": "lowest"}, [
  "Go to the mug that sits lowest.",
  "Could you take me to the cup that is closest to the floor?",
  "lowest mug",
  "Not the ones up on the desk or the worktop, I want the cup at the lowest height.",
  "This is a drinking cup. It is the one resting at the lowest height of all of them in the flat.",
  "go to the cup that's sitting lowset"]),
 # ---------------- apartment ----------------
 ("o", APT, 1, [1, 2], {"label": "sofa"}, [
  "Go to a sofa.",
  "Could you take me to a couch?",
  "any settee",
  "I want to sit down with my feet up, so any couch, it doesn't matter which.",
  "This is an upholstered seat for two or more people. It is one of the two in the living room.",
  "take me to a cocuh pls"]),
 ("or", APT, 12, [12, 13], {"label": "book", "room": "living room"}, [
  "Go to a book in the living room.",
  "Could you find one of the volumes in the living room?",
  "living room book",
  "I want something to read on the sofa, any volume in the living room, not the textbook in the office.",
  "This is a bound volume with pages. It is kept on the shelves in the living room.",
  "go to a bok in the living room"]),
 ("od", APT, 48, [48], {"label": "chair"}, [
  "Go to the red leather office chair.",
  "Could you take me to the red swivel seat with wheels?",
  "red leather swivel seat",
  "Not a dining chair, I mean the red leather one that rolls.",
  "This is a swivel seat upholstered in red leather. It has armrests and castors.",
  "go to the red leathr desk seat"]),
 ("ord", APT, 42, [42], {"label": "cabinet", "room": "bathroom"}, [
  "Go to the gray vanity cabinet in the bathroom.",
  "Could you take me to the gray wooden cupboard under the basin in the bathroom?",
  "gray vanity bathroom",
  "In the bathroom, the gray unit below the washbasin where towels are stored, not the filing cabinet.",
  "This is a gray wooden unit for storing toiletries. It stands under the sink in the bathroom.",
  "go to the grey vanity unit in the bathrom"]),
 ("ord", APT, 36, [36], {"label": "pillow", "room": "bedroom"}, [
  "Go to the white pillow in the bedroom.",
  "Could you take me to the fluffy white pillow on the bed in the bedroom?",
  "bedroom white cushion",
  "In the bedroom, the white one where you rest your head in bed, not the yellow cushion on the sofa.",
  "This is a soft white cushion for sleeping on. It lies at the top of the bed in the bedroom.",
  "go to the fluffy white cushon in the bedroom"]),
 ("ard", APT, 20, [20], {"label": "microwave"}, [
  "Take me to something I can use to reheat my leftovers in a minute or two.",
  "Could you show me what I can use to warm up leftover pasta quickly?",
  "zap food fast",
  "I want to heat my lunch fast, without turning on the oven.",
  "This is the quickest way to warm a plate of food. It is the compact box on the counter, not the stove.",
  "need to reheat my leftovres fast"]),
 ("ard", APT, 54, [54], {"label": "printer"}, [
  "Take me to something that can put my document on paper.",
  "Could you show me where I can print out my boarding pass?",
  "print document",
  "I need a hard copy of this contract, the screen isn't enough.",
  "This is what turns a file from my laptop into a paper copy. It is in the office, sitting on the gray filing cabinet.",
  "where can i prnit this"]),
 ("s", APT, 12, [12], {"label": "book", "room": "living room", "rel": "highest"}, [
  "Go to the higher book in the living room.",
  "Could you take me to the novel standing higher up in the living room?",
  "upper living room volume",
  "On the living room bookshelf, the one higher up, not the photo album lying on the bottom shelf.",
  "This is a volume on the living room bookshelf. It is the higher of the two there.",
  "go to the novle higher up in the living room"]),
 ("s", APT, 30, [30], {"label": "mirror", "rel": "nearest", "ref": 29}, [
  "Go to the mirror closest to the coat stand.",
  "Could you take me to the looking glass nearest the coat rack by the front door?",
  "mirror near coat stand",
  "I want to check my outfit before leaving, so the glass nearest the coat stand, not the one in the bathroom.",
  "This is a wall-hung reflective glass. It is the one nearer to the coat stand.",
  "go to the miror closest to the coat rack"]),
 # ---------------- scans ----------------
 ("o", SO, 11, [11, 12, 13], {"label": "monitor"}, [
  "Go to a monitor.",
  "Could you take me to one of the computer screens?",
  "computer display",
  "I need to look at a spreadsheet, any of the screens on the desks will do.",
  "This is a flat computer display. It stands on one of the tables.",
  "go to a computr screen"]),
 ("or", SL, 2, [2, 3, 4], {"label": "pillow", "room": "living room"}, [
  "Go to a pillow in the living room.",
  "Could you take me to one of the cushions in the living room?",
  "living room cushion",
  "I want something to prop my back, any of the cushions in the living room, red or yellow.",
  "This is a small soft cushion. It is one of those lined up on the sofa in the living room.",
  "go to a cushin in the living room"]),
 ("od", SB, 4, [4], {"label": "pillow"}, [
  "Go to the red pillow.",
  "Could you take me to the red cushion?",
  "red cushion",
  "I mean the red one, not the white or blue pillows.",
  "This is a small decorative cushion. It is red.",
  "go to the rde cushion"]),
 ("ard", SK, 12, [12], {"label": "coffee maker"}, [
  "Take me to where I can brew a coffee.",
  "Could you show me what I'd use to make an espresso?",
  "brew coffee",
  "I need caffeine badly this morning; take me to what makes it, not the fridge.",
  "This is what I'd use for a fresh cup of coffee. It is the machine on the counter that brews it.",
  "i need my morning cofee"]),
 ("s", SK, 25, [25], {"label": "cup", "rel": "nearest", "ref": 10}, [
  "Go to the cup nearest the sink.",
  "Could you take me to the mug closest to the sink?",
  "cup by sink",
  "Not the ones on the table, the mug sitting by the sink.",
  "This is a small drinking vessel on the counter. It is the one closest to the sink.",
  "go to the mug closest to the snik"]),
 ("s", SO, 7, [7], {"label": "office chair", "color": "blue", "rel": "left", "facing": "north"}, [
  "Go to the blue office chair on the left as seen from the windows looking into the room.",
  "With your back to the windows, could you take me to the blue desk chair on your left?",
  "blue seat, left side, windows behind",
  "Facing away from the windows, I want the blue seat on the left, not the blue one on the right.",
  "This is a blue desk chair. It is the left one of the two blue ones, seen from the windows looking into the room.",
  "back to the windows, go to the blue chiar on the left"]),
 ("s", SB, 7, [7], {"label": "nightstand", "rel": "nearest", "ref": 15, "also": {"rel": "nearest", "ref": 14, "expect": 6}}, [
  "Go to the nightstand closest to the door.",
  "Could you take me to the bedside table nearest the door?",
  "bedside table by door",
  "Not the one by the window, the bedside table on the door side.",
  "This is a wooden bedside table. It is the one nearer the door of the bedroom.",
  "go to the nighstand closest to the door"]),
 ("s", SL, 2, [2], {"label": "pillow", "color": "red", "rel": "left", "facing": "north"}, [
  "Go to the red pillow on the left as seen from the sofa facing the TV.",
  "Could you take me to the red cushion on the left, as seen by someone seated on the sofa looking at the TV?",
  "red cushion, left, facing tv",
  "From the sofa looking at the television, the red cushion at the left end, not the red one on the right.",
  "This is a red cushion on the sofa. It is on the left side for someone seated there facing the TV.",
  "sitting on the couch looking at the tv, the red cusion on the left"]),
 ("s", SO, 15, [15], {"label": "bookshelf", "rel": "between", "also": {"rel": "nearest", "ref": 27, "expect": 14}}, [
  "Go to the bookshelf between the other two.",
  "Could you take me to the middle bookcase of the three along the wall?",
  "middle bookcase",
  "Not the white one or the one by the floor lamp, the bookcase in between them.",
  "This is a tall brown wooden bookcase. It stands between the other two.",
  "go to the middel bookcase"]),
]


def rows():
    out = []
    for n, (typ, mp, target, accept, spec, ws) in enumerate(G, 1):
        assert len(ws) == 6, n
        for k, q in enumerate(ws, 1):
            out.append({"id": f"b33-g{n:02d}-w{k}", "map": mp, "query": q, "type": typ,
                        "target": target, "accept": sorted(accept), "group": f"b33-g{n:02d}"})
    return out


if __name__ == "__main__":
    path = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round33.jsonl"
    path.write_text("".join(json.dumps(r) + "\n" for r in rows()), encoding="utf-8")
    print(f"wrote {len(G)} groups, {len(rows())} lines to {path}")
