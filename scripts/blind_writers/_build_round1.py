# Builds round1.jsonl from the hand-written groups below. A leading "~" marks a line
# that contains a deliberate typo/misspelling (stripped before writing; counted for the notes).
import json

H829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "../../map_store/apartment.json"
SK = "../maps/scan_kitchen.json"
SB = "../maps/scan_bedroom.json"
SO = "../maps/scan_office.json"
SL = "../maps/scan_livingroom.json"
FB = "maps/flat_b.json"

G = [
# ---------------- type o ----------------
("o", H829, 122, [122], [
 "Take me to the loo, please.",
 "where's the toilet",
 "Can you guide me to the WC?",
 "I need the john, head there now",
 "~navigate to the nearest toliet",
 "Hey robot, could you show me where the lavatory is? I really need to go.",
]),
("o", H829, 263, [4, 9, 32, 79, 191, 261, 263], [
 "Go to an armchair.",
 "find me a comfy easy chair to sit in",
 "Could you take me to one of the armchairs? Any of them is fine.",
 "lounge chair, whichever's closest",
 "~Bring me over to an armchiar, I want to read for a bit.",
 "Where's the nearest easy chair?",
]),
("o", OFF3, 7, [7, 55, 64], [
 "Take me to a desk.",
 "Could you find me a workstation? Any one will do.",
 "I've got emails to answer, go to one of the work stations",
 "Where's the closest desk?",
 "head to a computer workstation pls",
 "Hi! Can you bring me over to somewhere people sit and work, like an office workstation?",
]),
("o", APT, 1, [1, 2], [
 "Go to the couch.",
 "take me to a sofa",
 "Where's the settee?",
 "I wanna lie down for a bit, bring me to a couch, whichever",
 "Navigate to the nearest sofa please.",
 "Could you head over to whichever couch is closest?",
]),
("o", APT, 7, [7, 34, 56], [
 "Go to a lamp.",
 "Can you take me to one of the lights?",
 "head to the nearest reading light",
 "~where's a lampp",
 "Take me to a light: floor, desk or bedside, I don't mind which.",
 "I'm after a table lamp or a floor lamp, any of them, please navigate there.",
]),
("o", SK, 13, [13], [
 "Go to the fridge.",
 "take me to the refrigerator",
 "Where's the icebox?",
 "~navigate to the frige",
 "~Could you please head over to the refridgerator?",
 "fridge",
]),
("o", SL, 14, [14], [
 "Go to the TV.",
 "take me to the telly",
 "Where's the television?",
 "I want to watch something, walk over to the box",
 "~head over to the telivision please",
 "could u bring me to the tv set",
]),
("o", FB, 10, [10, 27], [
 "Go to a bookcase.",
 "take me to one of the bookshelves",
 "Where can I find some shelves with books on them?",
 "Could you head over to the nearest bookcase?",
 "book shelf pls",
 "~I want something to read, navigate to a bookcsae",
]),
# ---------------- type or ----------------
("or", H829, 184, [184], [
 "Go to the couch in the bedroom.",
 "take me to the sofa in the bedroom",
 "Could you head over to the settee in the bedroom, please?",
 "bedroom sofa",
 "I want to sit on the couch that's in the room with the bed, go there",
 "Navigate to the sectional in the bedroom.",
]),
("or", H829, 14, [14, 33], [
 "Go to the curtains in the living room.",
 "take me to the drapes in the lounge",
 "Head over to the living-room curtain.",
 "Could you go to the sheers in the sitting room?",
 "front room drapes pls",
 "I'd like to close the window drapes in the family room, bring me there.",
]),
("or", H829, 219, [219], [
 "Go to the mirror in the bedroom.",
 "take me to the bedroom mirror",
 "Where's the looking glass in the bedroom?",
 "~I want to check my outfit, head to the mirror in the bedrom",
 "Could you navigate to the bedroom's mirror, please?",
 "mirror, bedroom",
]),
("or", H829, 78, [6, 78], [
 "Go to the TV in the living room.",
 "take me to the telly in the lounge",
 "Where's the television in the front room?",
 "Could you navigate over to the living room TV please",
 "I want to catch the game, head to the tellie in the sitting room",
 "living room flatscreen",
]),
("or", APT, 41, [41], [
 "Go to the sink in the bathroom.",
 "take me to the bathroom washbasin",
 "Could you head to the basin in the loo?",
 "I need to rinse something, where's the wash basin in the washroom?",
 "navigate to the bathroom sink pls",
 "the hand basin in the bathroom",
]),
("or", APT, 51, [51], [
 "Go to the bookshelf in the office.",
 "take me to the bookcase in the study",
 "Where are the shelves in the home office?",
 "Could you head over to the office bookcase, please?",
 "swing by the book shelf in the office",
 "~office bookshlef",
]),
("or", APT, 39, [39], [
 "Go to the plant in the bedroom.",
 "take me to the houseplant in the bedroom",
 "Can you head over to the potted plant where I sleep?",
 "bedroom greenery",
 "I need to water the little succulent in the bedroom, bring me there",
 "navigate to the flowerpot in the bedroom",
]),
("or", FB, 28, [28], [
 "Go to the armchair in the study.",
 "take me to the reading chair in the study",
 "Could you head over to the easy chair in the home office?",
 "study armchair pls",
 "I'd like to curl up with a book, bring me to the comfy chair in the study room",
 "~navigate to the lounge chair in the stuyd",
]),
# ---------------- type od ----------------
("od", H829, 197, [197, 212], [
 "Go to the red book.",
 "take me to the red volume with the gold on the cover",
 "Where's the crimson tome with the gold embossing?",
 "find the red hardback pls",
 "Could you bring me over to the red-covered volume?",
 "red book pls",
]),
("od", H829, 78, [78], [
 "Go to the TV that has the soundbar built in.",
 "take me to the telly with the built-in sound bar",
 "Which screen has the integrated soundbar? Head there.",
 "the glossy black television with the soundbar",
 "Could you navigate to the wall-mounted TV, the black one with a soundbar?",
 "~I want to crank up the volume, find the TV with the soundbr",
]),
("od", H829, 211, [211], [
 "Go to the blue bowl.",
 "take me to the deep blue ceramic bowl with the gold pattern",
 "Where's the ornamental bowl that's blue?",
 "Could you find the navy bowl with gold detailing?",
 "blue and gold dish",
 "Head over to the decorative bowl, the blue one, not the white one with the sweets.",
]),
("od", OFF3, 7, [7], [
 "Go to the white desk.",
 "take me to the white workstation",
 "Which desk is the white wooden one? Go there.",
 "Head over to the white work table.",
 "navigate to the white-topped workstation please",
 "~i need the whtie workspace",
]),
("od", OFF3, 20, [20], [
 "Go to the yellow pillow.",
 "take me to the yellow cushion",
 "Where's the yellow throw cushion with the pattern on it?",
 "Could you find the patterned yellow cushion for me?",
 "the yellow pillow please",
 "head over to the cushion that's yellow, not the orange ones or the navy one",
]),
("od", APT, 2, [2], [
 "Go to the leather sofa.",
 "take me to the brown loveseat",
 "Where's the little two-seater couch, the brown leather one?",
 "Could you head to the small brown settee?",
 "the worn leather couch please",
 "~navigate to the brwon leather sofa",
]),
("od", SK, 4, [4], [
 "Go to the gray kitchen cabinet.",
 "take me to the grey cupboard",
 "Which cabinet is the grey one? Head there.",
 "Could you navigate to the grey lower cupboard?",
 "the only grey kitchen unit, please",
 "find the grey cupboard",
]),
("od", FB, 26, [26], [
 "Go to the green lamp.",
 "take me to the green desk light",
 "Where's the green banker's lamp?",
 "Could you head over to the light with the green glass shade?",
 "green reading light pls",
 "~i need the grean light",
]),
# ---------------- type ord ----------------
("ord", H829, 263, [263], [
 "Go to the leather armchair in the bedroom.",
 "take me to the brown leather easy chair in the bedroom",
 "In the bedroom there's a leather lounge chair, head over to it.",
 "Could you navigate to the bedroom armchair? The leather one, not the woven one.",
 "~bedroom leather armchiar",
 "I want the comfy leather armchair where we sleep, take me there please",
]),
("ord", H829, 197, [197], [
 "Go to the red book in the bathroom.",
 "take me to the red volume in the bathroom",
 "There's a red leather-bound book in the washroom, head there.",
 "Could you find the crimson tome in the bathroom?",
 "bathroom red hardcover",
 "navigate to the red leather reading material in the bathroom",
]),
("ord", H829, 267, [267], [
 "Go to the sideboard with the LED light strip in the bedroom.",
 "take me to the bedroom credenza that has the LED strip",
 "There are two sideboards in the bedroom; go to the one with the LED lighting.",
 "Could you head over to the glass-topped credenza in the bedroom?",
 "bedroom credenza w/ the LED lights",
 "~navigate to the sideboad in the bedroom that lights up",
]),
("ord", OFF3, 40, [40], [
 "Go to the orange striped pillow in the rec room.",
 "take me to the orange cushion with white and yellow stripes in the recreation room",
 "In the games room, which cushion is the stripy orange one? Head there.",
 "Could you find the orange-and-white striped cushion in the rec area?",
 "rec room, the stripey orange pillow pls",
 "~navigate to the orange cusion with stripes in the rec room",
]),
("ord", APT, 12, [12], [
 "Go to the red book in the living room.",
 "take me to the red novel in the lounge",
 "Could you find the red hardback on the living room shelf?",
 "In the sitting room there's a red book, head over to it.",
 "front room red hardcover",
 "navigate to the red novel in the livingroom",
]),
("ord", APT, 24, [24], [
 "Go to the white chair in the kitchen.",
 "take me to the white spindle-back seat in the kitchen",
 "Could you head over to the white-painted wooden seat at the kitchen table?",
 "kitchen, white chair",
 "I'd like to sit down in the kitchen, bring me to the white one of the dining seats.",
 "~navigate to the whte seat in the kitchn",
]),
("ord", FB, 3, [3], [
 "Go to the brown leather armchair in the living room.",
 "take me to the leather easy chair in the lounge",
 "Could you head to the brown armchair in the front room?",
 "In the sitting room, find the brown leather lounge chair.",
 "living room, the leather one of the two arm chairs",
 "~navigate to the brown lether easy chair in the livng room",
]),
("ord", FB, 34, [34], [
 "Go to the brass lamp in the bedroom.",
 "take me to the gold-coloured bedside light in the bedroom",
 "Could you find the brass reading light in the bedroom?",
 "In the bedroom, head to the lamp with the brass base.",
 "bedroom, brass bedside light",
 "~navigate to the brasss light in the bedroom",
]),
# ---------------- type ard ----------------
("ard", H829, 249, [249], [
 "Take me to the thing I type on in the bedroom.",
 "Where's the bit of computer kit with all the keys, in the bedroom?",
 "I need to type up a note, go to whatever I can type with in the bedroom.",
 "bedroom, the input device for typing",
 "Could you navigate to the white typing thing in the bedroom?",
 "~head to the gadget for typing in the bedrom",
]),
("ard", H829, 192, [192], [
 "Go to where the pet sleeps in the bathroom.",
 "take me to the pet's sleeping spot in the bathroom",
 "Where does our pet curl up to sleep? It's in the bathroom somewhere.",
 "the white-and-brown thing the pet naps on, bathroom",
 "Could you head to the animal's bed in the bathroom?",
 "navigate to the pet snooze spot in the bathroom",
]),
("ard", OFF3, 25, [25], [
 "Take me to the thing on the wall that tells the time.",
 "Where can I check what time it is? Go to that thing on the wall.",
 "I need to see the time, bring me to whatever shows the hours on the wall.",
 "the black thing on the wall with the red second hand",
 "Could you navigate to the wall-mounted thing that ticks?",
 "~go to wat tells the time in the rec room",
]),
("ard", APT, 16, [16], [
 "Take me to the thing that keeps food cold in the kitchen.",
 "Where do we keep the milk chilled? Go there.",
 "I'm thirsty, go to the thing in the kitchen with the water dispenser in the door.",
 "the big silver appliance in the kitchen that keeps stuff cool",
 "Could you navigate to where the cold food is stored in the kitchen?",
 "kitchen, the tall stainless one that keeps leftovers cold",
]),
("ard", APT, 45, [45], [
 "Take me to the thing that washes clothes in the bathroom.",
 "Where do I put my dirty laundry to get it cleaned? It's in the bathroom.",
 "Go to the appliance in the bathroom that does the laundry.",
 "I need to do a load of washing, head to where that happens in the bathroom.",
 "Could you bring me to whatever cleans clothes, in the bathroom?",
 "laundry appliance in the bathroom",
]),
("ard", SO, 17, [17], [
 "Take me to the thing on the wall I can write on with markers.",
 "Where can I sketch out some ideas with a dry-erase pen? Go there.",
 "head to the white writing surface mounted on the wall",
 "I want to draw a diagram for the team, bring me to what we scribble on with markers.",
 "Could you navigate to the wipeable board on the wall?",
 "~go to the wall thing for marker notes, the whit one",
]),
("ard", FB, 18, [18], [
 "Take me to the thing that boils water, the one on the kitchen counter.",
 "I fancy a cuppa, go to whatever heats water on the worktop.",
 "Where's the electric thing on the counter for boiling water? Go there.",
 "head to the cream-coloured appliance on the counter that I use to make tea",
 "Could you navigate to what I use to boil water for coffee, on the kitchen counter?",
 "~the water boiler on the worktop in the kichen",
]),
("ard", FB, 29, [29], [
 "Take me to where I can hang my coat in the hallway.",
 "Where do I hang up my jacket out in the hall?",
 "I'm heading out, go to the thing in the hallway with the jackets on it.",
 "head to the spot in the corridor for hanging up coats",
 "Could you navigate to the hallway stand where jackets go?",
 "~hallway, where the coats get hung, plese",
]),
# ---------------- type s ----------------
("s", APT, 7, [7], [
 "Go to the lamp next to the sofa.",
 "take me to the light standing beside the grey couch",
 "Which lamp is in the corner by the big sofa? Head there.",
 "Could you navigate to the floor light next to the three-seater?",
 "the light right by the gray settee in the living room",
 "~go stand next to the lite beside the gray sofa",
]),
("s", APT, 42, [42], [
 "Go to the cabinet under the bathroom sink.",
 "take me to the cupboard beneath the washbasin",
 "Which cupboard sits right below the basin in the bathroom? Head there.",
 "Could you navigate to the unit underneath the bathroom sink?",
 "the cabinet below the bathroom basin",
 "~go to the cubbard under the sink in the bathroom",
]),
("s", SK, 21, [21], [
 "Go to the chair closest to the door.",
 "take me to the seat nearest the door",
 "Which chair is nearest the doorway? Go there.",
 "Could you head to the dining seat that's closest to the kitchen door?",
 "the seat at the end of the table nearest the door",
 "~navigate to the chiar nearest to the door",
]),
("s", SK, 25, [25], [
 "Go to the cup next to the sink.",
 "take me to the mug beside the sink",
 "Which cup is on the counter by the sink, not on the table? Go there.",
 "Could you navigate to the mug sitting near the kitchen sink?",
 "the mug between the coffee maker and the sink",
 "head to the little mug by the sink",
]),
("s", SB, 8, [8], [
 "Go to the lamp on the nightstand closest to the window.",
 "take me to the bedside light on the window side of the bed",
 "Which lamp is on the bedside table by the window? Head there.",
 "Could you navigate to the light on the night table nearer the window?",
 "window-side bedside light",
 "~navigate to the lite on the nighstand near the windw",
]),
("s", SO, 21, [21], [
 "Go to the trash can by the door.",
 "take me to the bin next to the door",
 "Which wastebasket is closest to the exit? Head there.",
 "Could you navigate to the rubbish bin near the office door?",
 "the garbage can beside the door, not the one across the room",
 "head to the trash can near the door",
]),
("s", SL, 6, [6], [
 "Go to the armchair next to the window.",
 "take me to the easy chair by the window",
 "Which armchair sits right beside the window? Go there.",
 "Could you navigate to the lounge chair that's nearest the window?",
 "the comfy chair by the window",
 "head to the arm chair closest to the window",
]),
("s", FB, 7, [7], [
 "Go to the lamp on the side table in the living room.",
 "take me to the little light sitting on the end table next to the couch",
 "Which lamp is on the small table beside the sofa? Head there.",
 "Could you navigate to the light on top of the end table in the lounge?",
 "the light on the side table by the sofa, not the tall floor one",
 "~go to the lite on top of the sidetable in the livingroom",
]),
]

out = []
ntypo = 0
counters = {}
for gi, (typ, mp, tgt, acc, qs) in enumerate(G, 1):
    assert len(qs) == 6, (gi, len(qs))
    g = f"b1-g{gi:02d}"
    for wi, q in enumerate(qs, 1):
        if q.startswith("~"):
            ntypo += 1
            q = q[1:]
        out.append({"id": f"{g}-w{wi}", "map": mp, "query": q, "type": typ,
                    "target": tgt, "accept": sorted(acc), "group": g})
with open("/work/main/evals/blind/round1.jsonl", "w") as f:
    for r in out:
        f.write(json.dumps(r, ensure_ascii=False) + "\n")
print(len(G), "groups,", len(out), "lines,", ntypo, "lines with a deliberate typo")
