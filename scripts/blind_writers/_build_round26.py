"""Writes evals/blind/round26.jsonl (blind round 26). All wordings hand-written below.
Only the map files named in BRIEF.md were read to choose targets and accept sets."""
import json
from pathlib import Path

OUT = Path(__file__).resolve().parents[2] / "evals/blind/round26.jsonl"
C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
FC, FE, FI, FB = "maps/flat_c.json", "maps/flat_e.json", "maps/flat_i.json", "maps/flat_b.json"
SB, SK, SO = "../maps/scan_bedroom.json", "../maps/scan_kitchen.json", "../maps/scan_office.json"

# (map, type, target, accept, [6 wordings])
G = [
# ---------------- o: every instance of a kind ----------------
(C829, "o", 79, [4, 9, 32, 79, 191, 261, 263], [
  "Take me to an armchair.",
  "Could you bring me over to one of the easy chairs?",
  "armchair, any",
  "My legs are tired and I'd like to sink into something padded. Can you show me a lounge chair, whichever?",
  "I'm looking for one of those big comfy single-seat chairs with thick upholstery.",
  "go to an armchiar"]),
(OFF3, "o", 13, [8, 13, 20, 40], [
  "Find me a cushion.",
  "Where can I grab a throw pillow?",
  "cushion pls",
  "My back hurts on these chairs. Could you take me to one of the cushions?",
  "I need something soft to lean against, like one of those sofa cushions. Which way?",
  "take me to a pilow"]),
(FI, "o", 31, [23, 31, 36], [
  "Take me to a cup.",
  "Could you show me where there's a coffee cup?",
  "any cup",
  "I've got to take my pills and need something to drink out of. Where's a cup?",
  "Looking for a mug, doesn't matter which one.",
  "Lead me to a ceramic cup, any of them will do."]),
(FC, "o", 26, [26, 27], [
  "Take me to a bedside table.",
  "Can you bring me to one of the bedside tables, please?",
  "bedside cabinet",
  "I left my glasses by the bed somewhere. Show me a night table.",
  "Go to the little table next to the bed, either side is fine.",
  "nightstand"]),
(SO, "o", 22, [21, 22], [
  "Take me to the bin.",
  "Where's a wastebasket I can use?",
  "rubbish bin",
  "I've got an empty coffee cup to throw away. Could you lead me to a trash can?",
  "Find a waste paper basket, any one in the room.",
  "go to the garbge bin"]),
(APT, "o", 7, [7, 34, 56], [
  "Take me to a lamp.",
  "Could you guide me to one of the lights I can switch on?",
  "light, any",
  "It's getting dark in here and I can barely see. Where's a lamp?",
  "I'm after a reading light of some sort, floor or desk, I don't mind.",
  "show me a lmap"]),
(SK, "o", 23, [23, 24, 25], [
  "Take me to a mug.",
  "Would you show me where a mug is?",
  "mug",
  "I'm thirsty. Take me to a cup I can drink from.",
  "Find me any of the mugs in here.",
  "teacup, whichever"]),
# ---------------- or: a kind in a named room ----------------
(C829, "or", 233, [112, 233], [
  "Take me to the mirror in the bathroom.",
  "Could you show me a mirror in the bathroom? I want to check my hair.",
  "bathroom mirror",
  "I've got something in my eye. Where's the looking glass in the washroom?",
  "There's a framed mirror somewhere in the bathroom. Go to it, please.",
  "mirrror in the bathroom"]),
(C829, "or", 263, [261, 263], [
  "Take me to an armchair in the bedroom.",
  "Is there an easy chair in the bedroom? Take me there.",
  "bedroom armchair",
  "I want to read for a bit before bed. Show me a big comfy lounge seat in the bedroom.",
  "Go to one of the lounge chairs in the bedroom, not the ones in the living room.",
  "In the bedroom there are some deep padded armchairs. Bring me to one."]),
(FI, "or", 45, [45, 46], [
  "Take me to a lamp in the bedroom.",
  "Could you go to one of the bedside lights in the bedroom?",
  "bedroom light",
  "I want to read in bed. Where's a reading light in the bedroom?",
  "Find a light on either bedside table in the bedroom.",
  "bedroom lamp, either one"]),
(FE, "or", 12, [11, 12, 13, 14, 15], [
  "Take me to a chair in the dining room.",
  "Can you find me a seat in the dining room?",
  "dining room seat",
  "Dinner's nearly ready. Show me a place to sit at the dining room table.",
  "Go to any of the chairs around the table in the dining room.",
  "chiar in the dining room"]),
(FB, "or", 5, [5, 7], [
  "Take me to a lamp in the living room.",
  "Would you show me a light in the lounge?",
  "living room light",
  "It's too dark to read on the sofa. Go to one of the lights in the living room.",
  "Find a lamp in the sitting room, floor or table, whichever.",
  "Any light in the living room, please."]),
(APT, "or", 13, [12, 13], [
  "Take me to a book in the living room.",
  "Is there something to read in the living room? Show me.",
  "living room books",
  "I'm bored. Go to one of the volumes on the living room shelves.",
  "Find a hardback or a photo album in the lounge, either one.",
  "a boook in the living room"]),
(OFF3, "or", 11, [4, 11, 12, 27], [
  "Take me to the curtains in the rec room.",
  "Could you go over to the drapes in the rec room?",
  "rec room drappes",
  "The sun's in my eyes. Where are the curtains in the games room?",
  "Bring me to any of the window drapes in the recreation room.",
  "I need to draw the drapes. Which way in the rec room?"]),
# ---------------- od: one object by its look ----------------
(C829, "od", 211, [211], [
  "Take me to the deep blue bowl with the gold pattern.",
  "Could you show me the blue ceramic bowl, the ornamental one?",
  "blue and gold bowl",
  "There's a glossy blue dish with gold-tinged designs on it. Go there.",
  "Not the white bowl with sweets, the dark blue decorative one.",
  "I want to look at that ornamental blue dish again. Where is it?"]),
(C829, "od", 184, [184], [
  "Take me to the L-shaped sofa.",
  "Where's the sectional with the chaise? Can you take me there?",
  "L-shaped couch with chaise",
  "I want the corner sofa, the beige one that has a chaise lounge built in.",
  "This is a beige fabric sofa. It's L-shaped and has a storage compartment.",
  "The sofa, not the plush massaging one, the L-shaped one."]),
(OFF3, "od", 13, [13], [
  "Take me to the navy blue cushion.",
  "Can you find the dark blue velvet pillow for me?",
  "navy velvet cushion",
  "Not the orange or the yellow ones. I want the navy one with the button.",
  "This is a soft velvety cushion. It's dark blue and a bit bigger than the others.",
  "the navy cushoin"]),
(OFF3, "od", 42, [42], [
  "Take me to the brown chair.",
  "Could you show me the dark brown leather seat without arms?",
  "brown leather chair",
  "I'd like the only brown seat, the one with wireless charging.",
  "Go to the armless seat in brown, not one of the black mesh ones.",
  "The one I mean is brown leather. It has built-in phone charging."]),
(FC, "od", 2, [2], [
  "Take me to the mustard yellow armchair.",
  "Could you bring me to the yellow easy chair?",
  "yellow fabric armchair",
  "Not the grey one, the mustard coloured lounge chair.",
  "This is a big fabric seat. It's mustard yellow.",
  "the yellow easy chiar"]),
(FI, "od", 15, [15], [
  "Take me to the black leather office chair.",
  "Could you find the high-backed black leather swivel seat?",
  "black leather swivel chair",
  "I want the executive-style seat, black leather, tall back.",
  "Not the blue mesh one. The black leather desk seat with the high back.",
  "This is a swivel seat in black leather. Its back is very high."]),
(SK, "od", 4, [4], [
  "Take me to the grey cupboard.",
  "Could you show me the gray kitchen cabinet?",
  "grey base unit",
  "All the cupboards are white except one gray one. Go there.",
  "This is a lower kitchen unit. It's the grey one, not white like the rest.",
  "gray cupbaord"]),
# ---------------- ord: look + room ----------------
(C829, "ord", 197, [197], [
  "Take me to the red book in the bathroom.",
  "Could you find the red leather-bound volume in the bathroom?",
  "red leather book bathroom",
  "I left a red volume with a gold embossed cover in the bathroom. Go there.",
  "Not the one in the bedroom: the red leather-bound tome in the bathroom.",
  "This is a red leather hardback. It's in the bathroom."]),
(C829, "ord", 191, [191], [
  "Take me to the beige velvet armchair in the bathroom.",
  "Is there a soft beige lounge chair in the bathroom? Take me to it.",
  "beige velvet chair, bathroom",
  "I want the curved beige easy chair in the bathroom, the velvet one.",
  "This is a velvet armchair in a neutral beige. It's in the bathroom.",
  "bathroom, beige velvet armchiar"]),
(OFF3, "ord", 40, [40], [
  "Take me to the striped orange cushion in the rec room.",
  "Could you find the orange pillow with white and yellow stripes in the rec room?",
  "orange striped cushion rec room",
  "Not the plain orange one, the stripy one, in the games room.",
  "This is an orange cushion with stripes. It's in the rec room.",
  "rec room, stripy orange cusion"]),
(FE, "ord", 26, [26], [
  "Take me to the white ceramic lamp in the main bedroom.",
  "Could you go to the bedside light with the white ceramic base in the master bedroom?",
  "white ceramic bedside light, main bedroom",
  "I want to read in bed. Go to the white table lamp in the main bedroom, not the brass floor one in the lounge.",
  "This is a small light with a white ceramic base. It sits by the bed in the master bedroom.",
  "master bedroom, white bedside lmap"]),
(FI, "ord", 36, [36], [
  "Take me to the yellow mug in the living room.",
  "Could you find the mustard yellow cup in the lounge?",
  "yellow cup living room",
  "I left my tea in the living room. It's in the yellow cup.",
  "Not the blue one with pencils; the mustard coloured cup in the living room.",
  "This is a mustard-yellow cup of cold tea. It's somewhere in the living room."]),
(FB, "ord", 28, [28], [
  "Take me to the green armchair in the study.",
  "Could you show me the green reading chair in the study?",
  "green chiar study",
  "I want to read in peace. Go to the green fabric seat in the study.",
  "Not the yellow or leather ones in the living room, the green one in the study.",
  "This is a green fabric reading seat. It's in the study."]),
(APT, "ord", 53, [53], [
  "Take me to the grey filing cabinet in the office.",
  "Could you go to the gray metal drawers in the office?",
  "gray metal file drawers, office",
  "Not the grey vanity in the bathroom. The metal one in the office, for paperwork.",
  "This is a grey metal drawer unit for documents. It's in the office.",
  "office, grey filing cabniet"]),
# ---------------- ard: a need, no object named ----------------
(C829, "ard", 122, [122], [
  "I really need to pee.",
  "Excuse me, where can I relieve myself?",
  "need to go number two",
  "I've had way too much coffee and my bladder's full. Help.",
  "Take me where I can do my business, please, quickly.",
  "urgent, need to empty my bladder"]),
(C829, "ard", 192, [192], [
  "Where can the dog have a nap?",
  "My puppy is tired. Could you take me to where he sleeps?",
  "somewhere for the cat to curl up",
  "The dog needs a rest; take me to his spot.",
  "Where does the pet sleep?",
  "I want to put the kitten down for a nap. Where should she go?"]),
(OFF3, "ard", 25, [25], [
  "What time is it?",
  "Could you take me to where I can check the time?",
  "need to know the time",
  "My phone's dead and I've no idea how late it is. Help me find out.",
  "I might be late for a meeting. Show me where I can see what hour it is.",
  "check the tiem"]),
(FE, "ard", 33, [33], [
  "My laundry is wet. Where can I dry it?",
  "Could you take me to somewhere I can dry my clothes quickly?",
  "dry washing fast",
  "The wash cycle just finished and it's raining outside. I need to get these clothes dry.",
  "I need my towels bone dry in under an hour.",
  "Where do I put damp clothes to dry them by machine?"]),
(FI, "ard", 20, [20], [
  "I need to print out a floor plan.",
  "Could you take me to where I can print some drawings?",
  "print A3 plans",
  "The client wants paper copies of the plans. Where do I make them?",
  "I have to scan a signed contract. Where do I go?",
  "need hard copies of these drawings"]),
(FC, "ard", 29, [29], [
  "I need to wake up at six tomorrow.",
  "Could you take me where I can set something to wake me up in the morning?",
  "set wake-up time",
  "I've got an early flight, so I must not oversleep. Where do I set that up?",
  "What can ring to get me up in the morning?",
  "early start tomorrow, need something to get me up"]),
(APT, "ard", 27, [27], [
  "I'd like to make a cup of tea.",
  "Could you take me to where I can boil some water?",
  "boil water for tea",
  "I'm cold and fancy a hot drink. Where do I heat the water?",
  "I want to make instant coffee and need hot water fast.",
  "tea time, need hot watre"]),
(SO, "ard", 17, [17], [
  "I need to sketch out an idea for the team.",
  "Could you take me to where I can draw a diagram with markers so everyone can see?",
  "brainstorm with markers",
  "We're planning the sprint and I want to write the tasks up on the wall. Where?",
  "I need somewhere to jot down notes big enough for the whole room to read.",
  "want to write the agenda up for the meeting"]),
# ---------------- s: singled out by position ----------------
(SB, "s", 8, [8], [
  "Take me to the lamp nearest the window.",
  "Could you go to the bedside light closest to the window?",
  "lamp nearest window",
  "Standing at the foot of the bed looking at the headboard, the light on the left.",
  "There are two bedside lights. I want the one on the window side, not the one by the door.",
  "the light on the nightstand next to the windo"]),
(SB, "s", 6, [6], [
  "Take me to the nightstand with the clock on it.",
  "Could you find the bedside table that has the alarm clock on top?",
  "bedside table with clock",
  "Of the two bedside tables, I want the one by the window, where the clock is.",
  "This is a small wooden bedside table. There's a black clock sitting on it.",
  "Not the one with the book on it: the other bedside cabinet."]),
(SK, "s", 3, [3], [
  "Take me to the cupboard under the sink.",
  "Could you show me the cabinet right below the sink?",
  "cupboard under sink",
  "I need a new sponge. It's in the unit beneath the sink, I think.",
  "This is a white base cupboard. The sink sits right on top of it.",
  "the cabinet underneath the sikn"]),
(SK, "s", 25, [25], [
  "Take me to the mug between the coffee maker and the sink.",
  "Could you find the cup standing between the coffee machine and the sink?",
  "mug between coffee machine and sink",
  "Not the ones on the table. The white mug on the counter, next to the coffee maker.",
  "This is a white mug. It's on the worktop, between the coffee machine and the sink.",
  "the mug on the counter, not on the dining table"]),
(SO, "s", 8, [8], [
  "Take me to the black office chair at the wooden table that's closest to the windows.",
  "Could you go to the black chair at the brown table, the one nearest the window?",
  "black seat, wood table, window side",
  "At the wooden desk there are two black seats. I want the one nearer the windows.",
  "This is a black swivel seat. It's at the wooden table, on the window side, next to a blue one.",
  "the black seat at the brown table, not the one by the bookshelves"]),
(SO, "s", 15, [15], [
  "Take me to the tallest bookshelf.",
  "Could you take me to the tallest of the bookcases?",
  "tallest bookcase",
  "There are three shelving units along the back wall. I want the highest one, in the middle.",
  "This is a brown wooden bookcase. It's the tallest one, taller than its brown neighbour.",
  "the biggest bookcsae"]),
(APT, "s", 12, [12], [
  "Take me to the book on the upper shelf of the living room bookcase.",
  "Could you find the higher of the two volumes on the living room shelves?",
  "top-shelf book, living room",
  "On the living room bookcase, not the one on the bottom shelf: the one standing higher up.",
  "This is a red hardcover. It stands on an upper shelf of the bookcase in the living room.",
  "the novel up high on the lounge bookshelf, not the photo album lower down"]),
(APT, "s", 39, [39], [
  "Take me to the plant on top of the dresser.",
  "Could you show me the little cactus-like thing sitting on the chest of drawers?",
  "succulent on dresser",
  "I want to water the succulent standing on the chest of drawers in the bedroom.",
  "This is a small potted succulent. It sits on top of the dark brown chest of drawers.",
  "the potted greenery on the drawers, not the big fig in the living room"]),
(FE, "s", 13, [13], [
  "Take me to the green chair right next to the black metal one.",
  "Could you go to the sage green dining chair beside the black bistro chair?",
  "green seat next to black metal one",
  "Looking at the dining table from the living room, the green seat on the left side.",
  "This is a sage green wooden seat. It's on the same side of the table as the odd black metal one.",
  "green seat beside the mismatched black one"]),
(FC, "s", 19, [19], [
  "Take me to the white chair closest to the stove.",
  "Could you go to the white dining chair nearest the cooker?",
  "white seat nearest cooker",
  "Not the black metal one. Of the two white seats at the table, the one on the cooker side.",
  "This is a white wooden seat at the dining table. It's the one nearer to the oven.",
  "the white chiar on the west side of the table"]),
(FI, "s", 7, [7], [
  "Take me to the red chair closest to the screen.",
  "Could you find the red plastic seat nearest the wall display in the meeting room?",
  "red seat nearest display",
  "In the meeting room, of the two red shell chairs, I want the one nearer the big screen.",
  "Not the grey ones. The red seat on the east side of the table, near the screen.",
  "This is a red moulded seat. It's at the meeting table, the one closer to the TV on the wall."]),
(FB, "s", 31, [31], [
  "Take me to the bedside table next to the window.",
  "Could you go to the nightstand closest to the bedroom window?",
  "nightstand nearest window",
  "Standing at the foot of the bed facing the headboard, the bedside table on the left.",
  "This is a white wooden bedside table. It's the one near the window, with the fabric-shaded lamp on it.",
  "Not the one with the brass lamp; the other bedsde table."]),
]

assert len(G) == 48
rows = []
for n, (m, t, tgt, acc, ws) in enumerate(G, 1):
    assert len(ws) == 6 and tgt in acc
    for k, q in enumerate(ws, 1):
        rows.append({"id": f"b26-g{n:02d}-w{k}", "map": m, "query": q, "type": t, "target": tgt,
                     "accept": sorted(acc), "group": f"b26-g{n:02d}"})
OUT.write_text("".join(json.dumps(r, ensure_ascii=False) + "\n" for r in rows), encoding="utf-8")
print(len(rows), "lines ->", OUT)
