"""Hand-written blind suite round 42: 48 groups x 6 wordings. Run: python3 emit.py (writes evals/blind/round42.jsonl).

Each group: (map key, type, target, accept, [w1..w6], spatial spec or None).
Spatial specs are checked numerically by check.py.
"""
import json
from pathlib import Path

MAPS = {
    "o3": "../../../shared/data/iesm_maps/scene_office3_caption.json",
    "829": "../../../shared/data/iesm_maps/scene_00829_caption.json",
    "fb": "maps/flat_b.json",
    "fe": "maps/flat_e.json",
    "fg": "maps/flat_g.json",
    "fi": "maps/flat_i.json",
    "apt": "apartment",
    "sb": "../maps/scan_bedroom.json",
    "sk": "../maps/scan_kitchen.json",
    "sl": "../maps/scan_livingroom.json",
    "so": "../maps/scan_office.json",
}

# spatial specs: ("nearest"|"farthest", candidates, ref ids) ; ("max"|"min", candidates, axis, measure)
#   measure: "c" centre, "top" top face, "bottom" bottom face ; ("on", candidates, support) ; ("under", candidates, above)
# or/o specs: ("label", label) or ("label_room", label, room)
G = [
 # ---------------- caption maps (12) ----------------
 ("o3", "o", 8, [8, 13, 20, 40], [
  "Go to a pillow.",
  "Could you find me one of the pillows?",
  "cushion, any",
  "I want something soft to lean my back on, so bring me to any of the cushions; colour does not matter.",
  "This is a soft cushion. It can be any one of the cushions lying around in the room.",
  "hey where's a cushon, any one is fine",
 ], ("label", "pillow")),
 ("829", "o", 42, [42, 197, 212, 259], [
  "Go to a book.",
  "Could you show me where there's a book?",
  "any volume",
  "I feel like reading something, so any volume will do, whichever room it is in.",
  "This is a bound volume. It could be any of the ones in the house.",
  "i wanna read, find me a bok somewhere",
 ], ("label", "book")),
 ("o3", "or", 7, [7, 55, 64], [
  "Go to a desk in the rec room.",
  "Could you take me to one of the desks in the rec room?",
  "rec room writing table",
  "I need a flat surface to sign some forms on, so any work table in the rec room, not the golden brown wooden table.",
  "This is a work surface for a computer. It stands in the recreation room, any one of them.",
  "need a wrting table in the rec room pls",
 ], ("label_room", "desk", "rec room")),
 ("829", "or", 182, [182, 250], [
  "Go to a side table in the bedroom.",
  "Could you bring me to one of the small side tables in the bedroom?",
  "bedroom end table",
  "I want somewhere to set my glass of water down, so one of the occasional tables in the bedroom, not those in the living room.",
  "This is a little end table with a glass top. It is located in the bedroom.",
  "which small tabel is in the bedroom? either works",
 ], ("label_room", "side table", "bedroom")),
 ("o3", "od", 13, [13], [
  "Go to the navy blue velvet pillow.",
  "Could you find the dark blue velvety cushion?",
  "navy velvet cushion",
  "I want the blue cushion with the buttons, not the orange or the yellow ones.",
  "This is a deep blue cushion. It has a velvet feel and is a bit bigger than the rest.",
  "where's the dark blue cushoin, the velvet one",
 ], None),
 ("o3", "od", 42, [42], [
  "Go to the dark brown leather armless chair.",
  "Could you take me to the brown leather seat with no armrests?",
  "brown leather armless seat",
  "My phone is nearly dead, so I want the brown leather seat that charges phones wirelessly, not one of the black mesh ones.",
  "This is a seat covered in dark brown leather. It has no arms and can charge a phone without a cable.",
  "take me to the brown lether seat without arms",
 ], None),
 ("829", "od", 164, [164], [
  "Go to the set of towels embroidered with an H.",
  "Could you find the white towels that have the letter H stitched on them?",
  "towels with letter H",
  "I want the monogrammed towels, the ones with an H on them, not the plain folded stacks.",
  "These are fluffy white cotton towels. They carry an embroidered letter H and sit on a rack.",
  "where r the towels with the h embroidary on them",
 ], None),
 ("829", "ord", 191, [191], [
  "Go to the beige velvet easy chair in the bathroom.",
  "Could you take me to the cream velvet armchair that is in the bathroom?",
  "beige velvet lounge seat, bathroom",
  "I want the pale velvet lounge seat in the bathroom, not the brown ones in the bedroom.",
  "This is a neutral beige lounge seat made of velvet. It stands in the bathroom and has a curved shape.",
  "the beige velvt armchair in the bathroom please",
 ], None),
 ("o3", "ord", 40, [40], [
  "Go to the striped orange pillow in the rec room.",
  "Could you find the orange cushion with white and yellow stripes in the rec room?",
  "striped orange cushion rec room",
  "In the rec room I want the orange cushion that has stripes, not the plain orange one with a button.",
  "This is an orange fabric cushion in the recreation room. It is patterned with white and yellow stripes.",
  "rec room, the orange cushion with strpes",
 ], None),
 ("829", "ard", 122, [122], [
  "Take me somewhere I can relieve myself.",
  "Could you show me where I can do my business?",
  "need to pee",
  "It's urgent, I need to relieve myself, and I don't mean washing my hands.",
  "This is the fixture you use when you need to relieve yourself. It is in one of the bathrooms.",
  "i need to peee really bad, where do i go",
 ], None),
 ("o3", "ard", 25, [25], [
  "Show me something that tells the time.",
  "Could you take me to where I can see what time it is?",
  "check time",
  "My phone is dead, so I need something on the wall to read the current time from, not the laptop.",
  "This is the thing on the wall that shows the hour. It hangs in the rec room.",
  "what time is it? take me to whatever shows the tiem",
 ], None),
 ("829", "ard", 192, [192], [
  "Take me to where the dog can sleep.",
  "Could you show me where our pet curls up for a nap?",
  "pet sleeping spot",
  "The puppy is tired and needs its own place to sleep, not our bed or the couch.",
  "This is where the pet sleeps. It is soft, white and brown, and made for animals rather than people.",
  "where does the dog sleeep?",
 ], None),
 # ---------------- flat_b (4) ----------------
 ("fb", "o", 5, [5, 7, 26, 33, 34], [
  "Go to a lamp.",
  "Could you take me to any of the lamps?",
  "any light",
  "It's getting dark and I want to switch on a light, any one in the flat, it doesn't matter which.",
  "This is a light fitting you can switch on. It can be any of them in the home.",
  "take me to a lmap, any will do",
 ], ("label", "lamp")),
 ("fb", "or", 20, [20, 21, 22], [
  "Go to a chair in the kitchen.",
  "Could you bring me to one of the seats in the kitchen?",
  "kitchen dining seat",
  "I want to sit down while I eat breakfast, so any seat at the table in the kitchen, not the swivel one in the study.",
  "This is a seat for dining. It stands around the round table in the kitchen.",
  "need a seet in the kitchen, any",
 ], ("label_room", "chair", "kitchen")),
 ("fb", "ord", 2, [2], [
  "Go to the yellow velvet armchair in the living room.",
  "Could you take me to the mustard velvet armchair in the lounge?",
  "yellow velvet seat living room",
  "In the living room I want the mustard coloured velvet seat by the window, not the brown leather one.",
  "This is a single seat upholstered in yellow velvet. It stands in the living room near the window.",
  "the yelow velvet seat in the lounge",
 ], None),
 ("fb", "s", 32, [32], [
  "Go to the nightstand nearest the wardrobe.",
  "Could you take me to the bedside table that is closest to the wardrobe?",
  "bedside table by wardrobe",
  "I want the bedside table on the wardrobe side of the bed, not the one by the window.",
  "This is a bedside table. Of the two, it is the one closer to the tall clothes cupboard.",
  "bedside tabel next to the wardrobe side",
 ], ("nearest", [31, 32], [35])),
 # ---------------- flat_e (4) ----------------
 ("fe", "o", 11, [11, 12, 13, 14, 15, 28, 36, 39], [
  "Go to a chair.",
  "Could you take me to any chair in the flat?",
  "any seat, not velvet armchair",
  "I need a simple seat to stand on to reach a shelf, any of them, but not the sofa or the velvet armchair.",
  "This is an ordinary seat for one person, not the sofa or the velvet armchair. It can be any of them in the home.",
  "i need to sit, find me a chiar",
 ], ("label", "chair")),
 ("fe", "od", 14, [14], [
  "Go to the black metal bistro chair.",
  "Could you find the black metal cafe-style seat that is different from the others?",
  "odd black metal seat",
  "I want the one seat at the dining table that isn't painted sage green, the black metal bistro one.",
  "This is a black seat made of metal in a bistro style. It is the odd one out at the dining table.",
  "the black metl bistro chair, the mismatched one",
 ], None),
 ("fe", "ard", 33, [33], [
  "Take me to where I can dry my wet laundry.",
  "Could you show me where I can get my clothes dry after washing?",
  "dry clothes",
  "The wash has just finished and I need to get the clothes dry, not wash them again.",
  "This is the machine that gets wet clothes dry. It stands next to the one that washes them.",
  "where can i dry my washng?",
 ], None),
 ("fe", "s", 12, [12], [
  "Go to the green dining chair nearest the kitchen.",
  "Could you take me to the sage green seat at the dining table closest to the kitchen?",
  "green seat, kitchen side",
  "I want the green seat straight across the table from the black metal one, not the two on the living room side.",
  "This is a sage green dining seat. Of the green ones it is the one farthest east, toward the kitchen.",
  "the green dinning chair nearest the kitchen",
 ], ("max", [11, 12, 13], 0, "c")),
 # ---------------- flat_g (4) ----------------
 ("fg", "or", 34, [34, 35], [
  "Go to a lamp in the bedroom.",
  "Could you take me to one of the lamps in the bedroom?",
  "bedroom bedside light",
  "I want to read in bed, so either bedside light in the bedroom, not the yellow one in the kids room.",
  "This is a small light on a bedside table. It is in the main bedroom, either side.",
  "a ligth in the bedroom, either one",
 ], ("label_room", "lamp", "bedroom")),
 ("fg", "od", 19, [19], [
  "Go to the wooden chair with the red checked cushion.",
  "Could you find the wooden seat that has a red gingham pad on it?",
  "wooden seat red checks",
  "I want the wooden one with the red checked pad, not the white plastic one.",
  "This is a wooden seat at the kitchen table. A red check-pattern cushion lies on it.",
  "wooden seat with the red chcked cushion",
 ], None),
 ("fg", "ard", 11, [11], [
  "Take me to where I can iron a shirt.",
  "Could you show me where I can press my trousers?",
  "press clothes",
  "My shirt is all creased for the interview, so I need to get the wrinkles out, not wash it.",
  "This is what you use to smooth creases out of clothes. It is set up in the laundry room with an iron resting on it.",
  "need to iorn my shirt, where?",
 ], None),
 ("fg", "s", 3, [3], [
  "Go to the bike on the left as you face the garage's rear wall.",
  "Could you take me to the bicycle on the left-hand side when looking at the garage's back wall?",
  "left bike, garage back wall",
  "I want the bike farther from the workbench, the one on the west side, not the one nearer the bench.",
  "This is a bike parked by the garage's rear wall. It is the one farther west, away from the workbench.",
  "the bike on the left by the back wal",
 ], ("min", [2, 3], 0, "c")),
 # ---------------- flat_i (4) ----------------
 ("fi", "o", 23, [23, 31, 36], [
  "Go to a mug.",
  "Could you find any mug for me?",
  "any cup",
  "I want a cup to drink my tea out of, any one will do, whatever room it's in.",
  "This is a ceramic cup with a handle. It can be any of them in the flat.",
  "find me a cup to drinkk from, any",
 ], ("label", "mug")),
 ("fi", "or", 12, [12, 13], [
  "Go to a desk in the studio.",
  "Could you take me to one of the desks in the studio?",
  "studio work table",
  "I need to sketch something, so any work table in the studio, not the reception counter.",
  "This is a work table against the north wall. It is in the studio, either of the two.",
  "a work tabel in the studio please",
 ], ("label_room", "desk", "studio")),
 ("fi", "ord", 15, [15], [
  "Go to the black leather chair in the studio.",
  "Could you take me to the black leather swivel seat in the studio?",
  "studio black leather seat",
  "In the studio I want the high-backed leather seat at the white desk, not the blue mesh one.",
  "This is a swivel seat in the studio. It is made of black leather with a tall back.",
  "the black lether swivel seat in the studio",
 ], None),
 ("fi", "s", 16, [16], [
  "Go to the monitor nearest the green banker's lamp.",
  "Could you take me to the computer screen closest to the green glass lamp?",
  "screen by green lamp",
  "I want the screen next to the green lamp, not the white-framed one farther east.",
  "This is a computer screen on a desk. It is the one closest to the lamp with the green shade.",
  "the scren closest to the green lamp",
 ], ("nearest", [16, 17], [18])),
 # ---------------- apartment (8) ----------------
 ("apt", "o", 12, [12, 13, 52], [
  "Go to a book.",
  "Could you show me where there's a book?",
  "any volume",
  "I'm bored and want to read, so any volume on any shelf, I don't mind which.",
  "This is something to read with pages and a cover. It can be any of them in the flat.",
  "find me something to read, a bok",
 ], ("label", "book")),
 ("apt", "or", 1, [1, 2], [
  "Go to a sofa in the living room.",
  "Could you take me to one of the sofas in the living room?",
  "living room couch",
  "I want to lie down for a bit, either couch in the living room, not the bed.",
  "This is a couch for sitting on. It is in the living room, either one.",
  "a couch in the livng room, any",
 ], ("label_room", "sofa", "living room")),
 ("apt", "ord", 13, [13], [
  "Go to the yellow book in the living room.",
  "Could you find the yellow photo album in the living room?",
  "yellow photo album living room",
  "In the living room I want the yellow album with the photos, not the red novel.",
  "This is a big yellow volume of photographs. It lies flat in the living room.",
  "the yelow photo album in the living room",
 ], None),
 ("apt", "ord", 42, [42], [
  "Go to the gray cabinet in the bathroom.",
  "Could you take me to the gray vanity unit in the bathroom?",
  "bathroom gray vanity",
  "I need a fresh towel from the gray wooden vanity in the bathroom, not the metal filing one in the office.",
  "This is a gray wooden cupboard in the bathroom. It holds towels and toiletries.",
  "the grey vanity cupbaord in the bathroom",
 ], None),
 ("apt", "ard", 54, [54], [
  "Take me to where I can print a document.",
  "Could you show me where I can get a paper copy of my boarding pass?",
  "print page",
  "I need a hard copy of my ticket, not just on the laptop screen.",
  "This is the machine that puts documents on paper. It rests on the gray drawer unit in the office.",
  "where can i prnt this?",
 ], None),
 ("apt", "ard", 29, [29], [
  "Take me to where I can hang up my coat.",
  "Could you show me where I can put my jacket when I come in?",
  "hang jacket",
  "I just came in from the rain and want to hang my wet jacket up, not put it in the wardrobe.",
  "This is where coats and jackets get hung up. It stands by the front door in the hallway.",
  "where do i hang my jackett?",
 ], None),
 ("apt", "s", 12, [12], [
  "Go to the higher of the two books on the living room bookshelf.",
  "Could you take me to the volume sitting higher up in the living room bookcase?",
  "upper novel, living room shelves",
  "On the living room shelves I want the hardback up high, not the album on the bottom shelf.",
  "This is a volume on the living room shelves. It sits higher up than the other one there.",
  "the novle higher up on the living room shelf",
 ], ("max", [12, 13], 2, "c")),
 ("apt", "s", 39, [39], [
  "Go to the plant on top of the dresser.",
  "Could you take me to the little plant standing on the chest of drawers?",
  "succulent on drawers",
  "I want the tiny potted succulent on the chest of drawers in the bedroom, not the big fig in the living room.",
  "This is a small potted succulent. It sits on top of the chest of drawers.",
  "the litle pot on top of the dresser",
 ], ("on", [8, 39, 55], 38)),
 # ---------------- scans (12) ----------------
 ("sk", "o", 23, [23, 24, 25], [
  "Go to a cup.",
  "Could you bring me to any of the cups?",
  "any mug",
  "I'm thirsty, so any mug at all, the colour doesn't matter.",
  "This is a small drinking vessel. It can be any one of them in the kitchen.",
  "find me a mugg, any one",
 ], ("label", "cup")),
 ("so", "or", 23, [23, 24], [
  "Go to a plant in the office.",
  "Could you take me to one of the plants in the office?",
  "office greenery",
  "I want to water the greenery in the office, either pot will do.",
  "This is a green potted thing that grows. It is in the office, either of the two.",
  "a houseplnt in the office, any",
 ], ("label_room", "plant", "office")),
 ("sk", "od", 4, [4], [
  "Go to the gray kitchen cabinet.",
  "Could you find the grey cupboard among the kitchen units?",
  "grey cupboard",
  "I want the one grey base unit, not any of the white cupboards.",
  "This is a low cupboard along the north wall. It is the only one coloured gray.",
  "the grey cupbord please",
 ], None),
 ("sl", "od", 3, [3], [
  "Go to the yellow pillow.",
  "Could you find the yellow cushion?",
  "yellow cushion",
  "I want the yellow cushion, not one of the red ones.",
  "This is a cushion on the couch. It is yellow.",
  "where's the yelow cushion",
 ], None),
 ("sb", "ord", 4, [4], [
  "Go to the red pillow in the bedroom.",
  "Could you find the red cushion in the bedroom?",
  "red bedroom cushion",
  "In the bedroom I want the red cushion on the bed, not the white or blue ones.",
  "This is a red cushion in the bedroom. It lies on the bed.",
  "the red cusion in the bedroom",
 ], None),
 ("sk", "ard", 26, [26, 27], [
  "Take me to where I can throw away this wrapper.",
  "Could you show me where I can get rid of some rubbish?",
  "throw away rubbish",
  "I have vegetable peelings to get rid of, not to wash down the sink; either place for waste is fine.",
  "This is where rubbish goes. It can be either of the two in the kitchen.",
  "where can i chuck this garbge",
 ], None),
 ("so", "s", 7, [7], [
  "Go to the blue office chair closest to the windows.",
  "Could you take me to the blue office chair that is nearest the windows?",
  "blue swivel seat near windows",
  "I want the blue seat on the window side, not the other blue one farther back toward the bookshelves.",
  "This is a blue desk seat. Of the two blue ones it is nearer the windows.",
  "the blue seat closer to the windws",
 ], ("nearest", [7, 10], [18, 19])),
 ("so", "s", 16, [16], [
  "Go to the shortest bookshelf.",
  "Could you take me to the lowest of the bookshelves?",
  "lowest bookcase",
  "I want the short bookcase I can reach the top of, not the tall brown ones.",
  "This is a set of shelves against the north wall. It is lower than the other two.",
  "the shortest bookcace",
 ], ("min", [14, 15, 16], 2, "top")),
 ("sk", "s", 21, [21], [
  "Go to the chair at the end of the table nearest the door.",
  "Could you take me to the seat at the door end of the table?",
  "seat at door end of table",
  "I want the seat at the end of the table by the door, not the one at the fridge end.",
  "This is a seat at the dining table. It is at the end closest to the door.",
  "the seat at the end of the tabel near the door",
 ], ("nearest", [17, 18, 19, 20, 21, 22], [15])),
 ("sk", "s", 3, [3], [
  "Go to the kitchen cabinet under the sink.",
  "Could you take me to the cupboard right below the sink?",
  "cupboard below sink",
  "I need the bin bags from the cupboard under the sink, not the ones up on the wall.",
  "This is a low cupboard. It is directly beneath the sink.",
  "the cuboard under the sink",
 ], ("under", [1, 2, 3, 4, 5, 6], 10)),
 ("sl", "s", 10, [10], [
  "Go to the lamp on your left when you sit on the sofa.",
  "Could you take me to the light on the left of the couch, seen from someone sitting on it?",
  "left light by couch",
  "Sitting on the couch facing the TV, I want the light at my left hand, not the one on the right.",
  "This is a small light on a side table next to the couch. It is on the left for someone sitting there facing the TV.",
  "the light on the lefft of the couch when i sit",
 ], ("min", [10, 11, 12], 0, "c")),
 ("sb", "s", 8, [8], [
  "Go to the lamp nearest the desk.",
  "Could you take me to the bedside light closest to the desk?",
  "light nearest desk",
  "I want the bedside light on the desk side, not the one by the door.",
  "This is a light on a bedside table. It is the one closer to the desk.",
  "the lamp closest to the dsk",
 ], ("nearest", [8, 9], [11])),
]

STYLES = 6


def main():
    out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round42.jsonl"
    lines = []
    assert len(G) == 48, len(G)
    for gi, (mk, typ, target, accept, words, _spec) in enumerate(G, 1):
        assert len(words) == STYLES, (gi, len(words))
        for wi, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b42-g{gi:02d}-w{wi}", "map": MAPS[mk], "query": q, "type": typ,
                                     "target": target, "accept": accept, "group": f"b42-g{gi:02d}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {out}")


if __name__ == "__main__":
    main()
