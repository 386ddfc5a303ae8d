"""Emit /work/blind28/evals/blind/round28.jsonl from the hand-written groups below."""
import json
from pathlib import Path

C1 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
C2 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
AP = "apartment"
SB, SK, SL, SO = ("../maps/scan_%s.json" % r for r in ("bedroom", "kitchen", "livingroom", "office"))
FB, FE, FG, FI = ("maps/flat_%s.json" % f for f in "begi")

# (type, map, target, accept, [six wordings])
G = [
 # ---------------- o ----------------
 ("o", C1, 42, [42, 197, 212, 259], [
  "Go to a book.",
  "Could you head over to any bound volume you can find?",
  "any book pls",
  "I want to read for a bit, so take me to one of the leather or paper-covered volumes lying around; any of them is fine.",
  "This is a bound volume with pages and a cover. Any one of them in the house will do.",
  "need sumthing to read, a novel or whatever, whichever one's closest"]),
 ("o", C2, 8, [8, 13, 20, 40], [
  "Go to a pillow.",
  "Would you mind going to one of the cushions?",
  "cushion, any",
  "My back hurts on this seat, so go to any of the throw cushions; the colour doesn't matter.",
  "This is a soft cushion, the kind you prop behind you. Any of them is fine.",
  "find a pilow for me"]),
 ("o", FB, 2, [2, 3, 28], [
  "Go to an armchair.",
  "Could you go to one of the single upholstered easy chairs?",
  "armchair",
  "I just want somewhere comfy for one person: any of the padded seats with arms, not the sofa and not the desk chair.",
  "This is a one-person upholstered seat with arms. Any of them in the flat.",
  "find me a comfy armchiar, any room"]),
 ("o", FG, 2, [2, 3], [
  "Go to a bicycle.",
  "Could you go over to one of the bikes?",
  "bike",
  "I'm going for a ride later; head to either of the bikes, the kid's one or the grown-up one.",
  "This is a two-wheeled pedal cycle. Either of them is fine.",
  "where's a bicyle"]),
 ("o", AP, 7, [7, 34, 56], [
  "Go to a lamp.",
  "Would you go to one of the lights, floor, bedside or desk, any kind?",
  "a lamp",
  "I need some light to read by, so just go to any of the freestanding light fittings, whichever is closest.",
  "This is a light you switch on, standing on the floor or on a piece of furniture. Any of them.",
  "any reading light in the flat is fine, go"]),
 ("o", SK, 23, [23, 24, 25], [
  "Go to a cup.",
  "Could you go to one of the mugs?",
  "cup",
  "I want a drink, so go to any of the drinking vessels: blue, red or white, whichever.",
  "This is a small drinking vessel. Any of them in the kitchen.",
  "mug pls any"]),
 ("o", SO, 14, [14, 15, 16], [
  "Go to a bookshelf.",
  "Could you head to one of the bookcases?",
  "bookcase",
  "I need a reference book, so go to any of the shelving units along the north wall.",
  "This is a set of shelves for books. Any of them.",
  "book shelf, whichever"]),
 # ---------------- or ----------------
 ("or", C1, 261, [261, 263], [
  "Go to an easy chair in the bedroom.",
  "Could you go to one of the armchairs in the bedroom?",
  "bedroom armchair",
  "I want to sit and read in the bedroom, so head to one of the comfy armchairs in there, not the ones in the living room.",
  "This is an upholstered armchair for relaxing. It is in the bedroom.",
  "bedroom - either of the two big cosy armchairs"]),
 ("or", C1, 14, [14, 33], [
  "Go to a curtain in the living room.",
  "Could you head over to one of the drapes in the lounge?",
  "living room drapes",
  "It's too bright in the living room; go to one of the curtains there so we can close it, not the ones in the bedroom.",
  "This is a light white window drape. It hangs in the living room.",
  "the curtians in the living room, whichever"]),
 ("or", C2, 10, [10, 14, 16, 24], [
  "Go to a window in the rec room.",
  "Could you move over to one of the panes of glass looking outside in the recreation room?",
  "rec room window",
  "I want some fresh air in the rec room, so head to any of the glazed openings there; any will do.",
  "This is an opening in the wall of the rec room with glass in it. Any of them counts.",
  "go to whichever windw, rec room"]),
 ("or", FI, 6, [6, 7, 8, 9], [
  "Go to a chair in the meeting room.",
  "Could you go to one of the seats in the conference room?",
  "meeting room seat",
  "Find me somewhere to sit in the meeting room; any of the seats there is fine, red or gray.",
  "This is a seat at the glass table. It is in the meeting room.",
  "a chiar in the meetng room, any one"]),
 ("or", FG, 34, [34, 35], [
  "Go to a lamp in the bedroom.",
  "Would you go to one of the bedside lights in the bedroom?",
  "bedroom light",
  "I want to read in bed, so go to either of the lights by the bed, not the one in the kids' room.",
  "This is a small reading light on a bedside table. It is in the bedroom.",
  "lamp bedroom either side"]),
 ("or", AP, 12, [12, 13], [
  "Go to a book in the living room.",
  "Could you find one of the volumes on the living room shelves?",
  "living room book",
  "I left something to read in the living room; go to anything readable on the shelves there, not the textbook in the office.",
  "This is a volume kept on the shelf unit in the living room.",
  "one of the living rm reads, whichever"]),
 ("or", AP, 23, [23, 24], [
  "Go to a chair in the kitchen.",
  "Could you go to one of the dining seats in the kitchen?",
  "kitchen seat",
  "I'm about to eat in the kitchen; go to either of the seats at the table there, not the desk one in the office.",
  "This is a wooden seat by the dining table. It is in the kitchen.",
  "chair, kitchen, any"]),
 # ---------------- od ----------------
 ("od", C1, 184, [184], [
  "Go to the L-shaped couch.",
  "Could you go to the corner sofa with the chaise?",
  "L sofa with chaise",
  "I want to stretch my legs out, so go to the settee with the chaise end, not the one with the massage system.",
  "This is a beige fabric sofa in an L shape. It has a chaise section and storage.",
  "that big L-shaped couch w/ the storage bit"]),
 ("od", C1, 211, [211], [
  "Go to the deep blue bowl.",
  "Could you go to the dark blue ornamental dish with gold patterns?",
  "blue bowl gold pattern",
  "I want to show my guest the pretty blue dish, not the white one holding sweets.",
  "This is a glossy blue ceramic dish. It has fine gold patterns on it.",
  "the blue one w/ gold bits on it, the dish"]),
 ("od", C2, 7, [7], [
  "Go to the white desk.",
  "Would you go to the white wooden writing table?",
  "white work table",
  "My notes are on the white work surface, not on either of the brown wooden ones.",
  "This is a white wooden work desk. It has a USB port built in.",
  "the whte work table, not the brown ones"]),
 ("od", FI, 46, [46], [
  "Go to the lamp with the rattan shade.",
  "Could you go to the light that has a woven wicker shade?",
  "rattan-shade light",
  "I like the patterned light it throws on the wall: the bedside one with the woven shade, not the ceramic one.",
  "This is a bedside light with a beige woven rattan shade. It stands on the white bedside table.",
  "the lamp w/ woven shade thing"]),
 ("od", FE, 14, [14], [
  "Go to the black metal chair.",
  "Could you go to the dark metal bistro-style seat that doesn't match the rest?",
  "black bistro seat",
  "The odd one out at the dining table: the black metal one, not the green painted ones.",
  "This is a black metal bistro chair. It does not match the sage green seats around it.",
  "that mismatched black metal seat"]),
 ("od", AP, 2, [2], [
  "Go to the brown leather loveseat.",
  "Could you go to the little two-seater couch in brown leather?",
  "brown leather loveseat",
  "Not the big gray three-seater; I mean the small brown leather one for two.",
  "This is a small two-seat settee made of brown leather. It looks a bit worn.",
  "the worn leather 2 seater"]),
 ("od", SK, 4, [4], [
  "Go to the gray kitchen cabinet.",
  "Could you go to the grey cupboard?",
  "gray cupboard",
  "The one cupboard that's gray rather than white: go there.",
  "This is a lower cupboard unit painted gray. All the others are white.",
  "grey cabnet pls"]),
 # ---------------- ord ----------------
 ("ord", C2, 20, [20], [
  "Go to the yellow pillow in the rec room.",
  "Could you go to the yellow cushion in the recreation room?",
  "yellow cushion rec room",
  "In the rec room, I want the lumpy yellow cushion with the pattern, not the orange ones or the navy one.",
  "This is a soft yellow patterned cushion. It is in the rec room.",
  "rec room, yelow pillow"]),
 ("ord", C1, 110, [110], [
  "Go to the honey-coloured small table in the bathroom.",
  "Could you go to the little wooden stand with the X-shaped metal base in the bathroom?",
  "bathroom small table, X legs",
  "In the bathroom there's a little warm-toned wooden table with a crossed metal base; go there, not the dark one in the living room.",
  "This is a little honey-toned wooden table on an X-shaped metal base. It is in the bathroom.",
  "the lil honey wood table, bathroom one"]),
 ("ord", FB, 34, [34], [
  "Go to the brass lamp in the bedroom.",
  "Could you go to the bedside light with the gold-coloured base in the bedroom?",
  "brass bedside light, bedroom",
  "In the bedroom, head to the bedside light with the brass base, not the plain white one.",
  "This is a reading light whose base is polished brass, topped by a pale shade. You will find it in the bedroom.",
  "bedroom, the goldy brass lamp"]),
 ("ord", FG, 19, [19], [
  "Go to the wooden chair with the red checked cushion in the kitchen.",
  "Could you go to the kitchen seat that has a red gingham cushion?",
  "kitchen, red check cushion seat",
  "I'm after the wooden kitchen seat with the checked pad, not the white plastic one.",
  "This is a wooden chair whose seat pad has a red check pattern. It is in the kitchen.",
  "the red checkered seat in kitchen"]),
 ("ord", AP, 42, [42], [
  "Go to the gray cabinet in the bathroom.",
  "Could you go to the grey vanity unit in the bathroom?",
  "bathroom vanity, gray",
  "I need a fresh towel from the gray wooden cupboard under the basin in the bathroom, not the gray filing one in the office.",
  "This is a gray wooden vanity unit. It is in the bathroom and stores towels and toiletries.",
  "gray cabinet bathroom"]),
 ("ord", SL, 5, [5], [
  "Go to the green armchair in the living room.",
  "Could you go to the green easy chair in the lounge?",
  "green armchair living room",
  "In the living room there are two big single seats; I want the green one, not the brown leather one.",
  "This is a green upholstered chair with arms. It is in the living room.",
  "living room, the grene comfy chair"]),
 ("ord", SO, 30, [30], [
  "Go to the white keyboard in the office.",
  "Could you go to the white set of computer keys in the office?",
  "white kbd office",
  "In the office, go to the white keyboard, not the black one.",
  "This is a white input device you type on. It is in the office.",
  "office white keybaord"]),
 # ---------------- ard ----------------
 ("ard", C1, 192, [192], [
  "Take me to where the dog sleeps.",
  "Could you go to the spot where my puppy curls up to nap?",
  "dog's sleeping spot",
  "The cat needs a rest and I don't want it on the couch; go to its own place to sleep.",
  "This is where the family pet sleeps. It is soft and plush, in white and brown.",
  "where does the doggo nap? go there"]),
 ("ard", C2, 25, [25], [
  "Go to the thing on the wall that tells the time.",
  "Could you take me to whatever shows the time on the wall of the rec room?",
  "wall time thing",
  "I don't want to dig my phone out; just go to what I can glance at on the wall to see the time.",
  "This is the object that shows the hours with a second hand. It is mounted on the wall.",
  "wat time is it? go to the thing on the wall that shows it"]),
 ("ard", C2, 67, [67], [
  "Go to the thing I can use to change the channel.",
  "Could you find what I'd use to switch programmes from the sofa?",
  "channel changer",
  "I want to turn the volume down from across the room without getting up; go to whatever lets me do that.",
  "This is the handheld thing used to control a screen from a distance.",
  "need to flip channels, go get whatever does it"]),
 ("ard", FG, 11, [11], [
  "Go to where I can iron my shirt.",
  "Could you go to the place set up for pressing clothes?",
  "press shirt",
  "My shirt's wrinkled and I have a meeting; go to wherever I can smooth out the creases, the thing with the steam iron resting on it.",
  "This is what you lay clothes on to press out wrinkles. It has a blue floral cover.",
  "creased trousers, where do i sort that"]),
 ("ard", FE, 33, [33], [
  "Go to what I can use to dry the wet laundry.",
  "Could you go to the machine that dries clothes?",
  "dry clothes",
  "The washing is done and the clothes are damp; go to what will dry them, not the washer.",
  "This is the appliance that dries laundry with warm air. It stands next to the washer.",
  "wet towels need drying, go"]),
 ("ard", FI, 20, [20], [
  "Go to where I can print an A3 plan.",
  "Could you go to the machine that puts drawings on paper?",
  "print plans",
  "I have to get a hard copy of this floor plan for the client; go to whatever can do that.",
  "This is the machine that copies files onto paper and can also scan. It sits on a steel drawer unit.",
  "need 2 print smth, go there"]),
 ("ard", AP, 54, [54], [
  "Go to where I can print a document.",
  "Could you go to what I'd use to get a paper copy of my report?",
  "hard copy",
  "I have to bring a printed contract to the meeting; go to what produces it, not the laptop.",
  "This is the machine that puts text onto paper. It sits on top of a filing cabinet.",
  "gotta print my boarding pass, go"]),
 ("ard", SK, 11, [11], [
  "Go to what I can use to heat up leftovers.",
  "Could you go to the thing I'd use to warm up my lunch quickly?",
  "reheat food",
  "My soup's gone cold; go to whatever can warm it up in a couple of minutes.",
  "This is the black appliance that zaps food hot in a minute or two.",
  "heat my leftovers?? where"]),
 # ---------------- s ----------------
 ("s", FB, 33, [33], [
  "Go to the bedside lamp nearest the bedroom window.",
  "Could you go to the light beside the bed on the window side?",
  "bedside light by window",
  "I'm reading by the window; go to the bedside light on that side of the bed, not the one near the wardrobe.",
  "This is a bedside light. It is on the nightstand closer to the bedroom window.",
  "bed lamp, the window side one"]),
 ("s", FB, 7, [7], [
  "Go to the lamp on the side table.",
  "Could you go to the little light standing on top of the small round table by the sofa?",
  "light on side table",
  "Not the tall one on the floor: the small light that sits on the little table by the east end of the couch.",
  "This is a small light. It stands on top of the side table next to the sofa.",
  "lamp thats on the lil table next to the couch"]),
 ("s", FE, 15, [15], [
  "Go to the chair at the dining table that is nearest the kitchen.",
  "Could you go to the seat at the end of the dining table, on the kitchen side?",
  "dining seat closest to kitchen",
  "Go to the seat at the head of the dining table by the kitchen, not any of the ones along the sides.",
  "This is the seat at the dining table's east end. Of all the seats around it, it is closest to the kitchen.",
  "kitchen-side end of the dining table, that chair"]),
 ("s", FG, 34, [34], [
  "Go to the bedside lamp closest to the wardrobe.",
  "Could you go to the bedside light on the same side of the bed as the wardrobe?",
  "bedside light, wardrobe side",
  "Go to the light on the west side of the bed, the side nearer the wardrobe, not the one nearer the laundry hamper.",
  "This is a bedside light. It stands on the nightstand on the wardrobe's side of the bed.",
  "lamp by the bed - the one nearer the wardrobe"]),
 ("s", FG, 2, [2], [
  "Go to the bicycle closest to the workbench.",
  "Could you go to the bike parked nearest the tool bench?",
  "bike nearest workbench",
  "Go to the bike near where the tools are, not the one in the corner by the west wall.",
  "This is a bicycle parked along the garage's north wall. Of the two, it is the one closer to the workbench.",
  "the bike by the workbench"]),
 ("s", FI, 36, [36], [
  "Go to the mug on the coffee table.",
  "Could you go to the cup sitting on the low table in front of the sofa?",
  "cup on coffee table",
  "Clear the cold tea off the low table by the sofa: that cup, not the ones in the kitchen or the studio.",
  "This is a cup. It is on top of the coffee table in the living room.",
  "the mugg on the coffee table"]),
 ("s", AP, 12, [12], [
  "Go to the higher of the two books on the living room bookshelf.",
  "Could you go to the volume sitting higher up on the living room bookcase?",
  "upper-shelf read, living room",
  "On the living room shelves, go to the one placed up high, not the one lying on the bottom shelf.",
  "This is a book on the living room bookshelf. It is the higher of the two there.",
  "living rm shelf - the upper one, not the bottom"]),
 ("s", AP, 39, [39], [
  "Go to the plant on top of the dresser.",
  "Could you go to the little potted succulent sitting on the chest of drawers?",
  "pot on dresser",
  "Water the one on the chest of drawers in the bedroom, not the big one on the floor in the living room.",
  "This is a small potted plant. It sits on top of the dresser in the bedroom.",
  "the lil pot on top of the drawers"]),
 ("s", SB, 5, [5], [
  "Go to the pillow farthest from the headboard.",
  "Could you go to the cushion lying down toward the foot of the bed?",
  "cushion near foot of bed",
  "Not the ones at the head of the bed; go to the one lying further down toward the foot.",
  "This is a pillow on the bed. It is the one closest to the foot end, away from the headboard.",
  "the cushion down by the feet end of bed"]),
 ("s", SK, 21, [21], [
  "Go to the chair at the end of the table nearest the door.",
  "Could you go to the seat at the table end closest to the entrance?",
  "table-end seat by door",
  "Go to the seat at the head of the table on the door side, not the one at the window end.",
  "This is a chair at the west end of the table. It is the one closest to the door.",
  "the seat at the door end of the tabel"]),
 ("s", SK, 25, [25], [
  "Go to the cup next to the sink.",
  "Could you go to the mug sitting on the counter beside the sink?",
  "mug by sink",
  "Not the ones on the table: the one up on the counter by the sink.",
  "This is a cup on the counter. It is between the coffee maker and the sink.",
  "the counter mug, next to the sink"]),
 ("s", SL, 2, [2], [
  "Go to the red pillow on the left when you sit on the sofa facing the TV.",
  "Could you go to the red cushion at the left-hand end of the couch, as seen by someone sitting on it facing the television?",
  "red cushion, left end of sofa (sitting)",
  "There are two red cushions on the sofa; I want the one nearer the green armchair, not the one by the brown leather armchair.",
  "This is a red pillow on the sofa. It is on the west side of the yellow one.",
  "red pilow on the left side of the couch if ur sitting on it"]),
]

out = Path("/work/blind28/evals/blind/round28.jsonl")
lines = []
for gi, (t, m, tgt, acc, ws) in enumerate(G, 1):
    assert len(ws) == 6, gi
    for wi, q in enumerate(ws, 1):
        lines.append(json.dumps({"id": f"b28-g{gi:02d}-w{wi}", "map": m, "query": q, "type": t,
                                 "target": tgt, "accept": sorted(acc), "group": f"b28-g{gi:02d}"}))
out.write_text("\n".join(lines) + "\n", encoding="utf-8")
print(len(G), "groups", len(lines), "lines")
