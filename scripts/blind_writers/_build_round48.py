"""Hand-written blind suite round 48: 48 groups x 6 wordings. Writes evals/blind/round48.jsonl
and scripts/specs.json (the derivation spec per group, read by check.py)."""
import json
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
S829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SBED, SKIT, SLIV, SOFF = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                          "../maps/scan_livingroom.json", "../maps/scan_office.json")

# (map, type, target, accept, spec, [w1..w6])
# spec: o -> {"label"}; or -> {"label","room"}; od/ord/ard -> {"why"}; s -> {"claims": [...]}
G = [
# ---------------- scene_office3 (caption map) ----------------
(OFF3, "o", 4, [4, 11, 12, 27], {"label": "curtain"}, [
 "Go to the curtains.",
 "Could you take me to where the window drapes are hanging?",
 "window drapes",
 "I want to let some light in, so take me to the drapes by the windows, any of them will do.",
 "This is a long piece of cloth hanging beside a window. It can be drawn open or shut.",
 "can u find me a curtian pls"]),
(OFF3, "or", 7, [7, 55, 64], {"label": "desk", "room": "rec room"}, [
 "Go to a desk in the rec room.",
 "Could you bring me to one of the workstations in the rec room?",
 "desk, rec room",
 "I have emails to write, so take me to any workstation in the rec room, not the golden brown table.",
 "This is a piece of furniture in the rec room where someone sits to work. It has a flat wooden top and there are several like it.",
 "take me to a deks in the rec room"]),
(OFF3, "od", 13, [13], {"why": "only navy/velvet pillow; others orange (8, 40) and yellow (20)"}, [
 "Go to the navy blue velvet pillow.",
 "Could you find the dark blue cushion with the button for me?",
 "navy velvet cushion",
 "I want the soft blue one for my back, not the orange or yellow pillows.",
 "This is a plush cushion covered in velvet. It is deep navy and a bit bigger than the rest.",
 "where's the navy cushon"]),
(OFF3, "od", 7, [7], {"why": "only white desk; 55 and 64 are brown"}, [
 "Go to the white wooden desk.",
 "Could you take me to the white work table made of wood?",
 "white wood workstation",
 "I'm looking for the pale desk, not the brown wooden ones.",
 "This is a writing surface painted white. It is made of wood and has a USB socket in it.",
 "take me to the white workstaton pls"]),
(OFF3, "ord", 40, [40], {"why": "only striped pillow; 8 is orange with a button, not striped"}, [
 "Go to the striped orange pillow in the rec room.",
 "Could you take me to the orange cushion with stripes in the recreation room?",
 "striped orange cushion rec room",
 "In the rec room I want the orange cushion that has stripes, not the plain one with a button.",
 "This is an orange cushion in the rec room. It is striped in white and yellow.",
 "go to the stripy orange pilow in the rec room"]),
(OFF3, "ard", 25, [25], {"why": "the clock is the only wall-mounted time display"}, [
 "Go to whatever on the wall tells the time.",
 "Could you show me where on the wall I can check what time it is?",
 "wall time check",
 "I think I'm late for a meeting, take me to the thing on the wall that shows the hour, not my phone.",
 "This is the thing I need to see how late it is. It hangs on the wall and has a second hand.",
 "take me somewhere i can see the tiem on the wall"]),
# ---------------- scene_00829 (caption map) ----------------
(S829, "o", 112, [112, 157, 219, 229, 233], {"label": "mirror frame"}, [
 "Go to a mirror frame.",
 "Could you take me to one of the framed mirrors?",
 "framed looking glass",
 "I want to check my hair, so any mirror with a frame will do, it doesn't matter which room.",
 "This is a reflective glass set in a decorative wooden surround. It hangs on a wall.",
 "take me to a miror with a frame"]),
(S829, "o", 160, [160, 162, 164], {"label": "set of towels"}, [
 "Go to a set of towels.",
 "Could you take me to a pile of folded towels?",
 "folded towel stack",
 "I just showered and need a fresh one from the folded stacks, not the hand towel on the holder.",
 "This is a neat stack of folded white cotton bath linen. There are a few of these in the house.",
 "where r the folded towles"]),
(S829, "or", 261, [261, 263], {"label": "easy chair", "room": "bedroom"}, [
 "Go to an easy chair in the bedroom.",
 "Could you take me to one of the brown lounge chairs in the bedroom?",
 "bedroom armchair",
 "I want to read in the bedroom, so any of the cosy armchairs there, not the armless leather one.",
 "This is a deep brown upholstered armchair in the bedroom. There are two of these there.",
 "go to a comfy armchiar in the bedroom"]),
(S829, "or", 195, [195, 216, 228], {"label": "cabinet kitchen", "room": "bathroom"}, [
 "Go to a cabinet in the bathroom.",
 "Could you take me to one of the wooden cupboards in the bathroom?",
 "bathroom cupboard",
 "I'm after storage in the bathroom, any of the dark wood cupboards there, not the counters with the sink.",
 "This is a dark brown wooden storage cupboard in the bathroom. There are a few of them there.",
 "take me to a bathroom cabnet"]),
(S829, "od", 110, [110], {"why": "only honey-coloured small table with an X base; 22 and 224 are dark"}, [
 "Go to the honey-coloured small table with the X-shaped base.",
 "Could you take me to the little table in light honey wood on crossed metal legs?",
 "honey wood table, X base",
 "I need the light wooden stand, not the dark wood ones.",
 "This is a small stand made of warm, golden wood. Its metal legs cross in an X shape.",
 "go to the honey colord little table"]),
(S829, "ord", 259, [259], {"why": "only book in a bedroom; 42 (living room) is also dark leather"}, [
 "Go to the leather-bound book in the bedroom.",
 "Could you find me the brown leather volume in the bedroom?",
 "bedroom leather book",
 "I want to read the one in the bedroom, not the dark volume in the living room.",
 "This is a hardbound volume with a dark brown leather cover. It is in the bedroom and has gold lettering on the front.",
 "where's the leathr volume in the bedroom"]),
# ---------------- flat_b ----------------
(FB, "o", 5, [5, 7, 26, 33, 34], {"label": "lamp"}, [
 "Go to a lamp.",
 "Could you take me to any of the lights?",
 "any light fixture",
 "It's getting dark and I want to switch something on, any lamp in the flat will do.",
 "This is a light you switch on to brighten a room. There are several of them around the flat.",
 "find me a lmap"]),
# ---------------- flat_g ----------------
(FG, "o", 10, [10, 37, 45], {"label": "basket"}, [
 "Go to a basket.",
 "Could you take me to one of the baskets in the house?",
 "any hamper",
 "I just need something to toss stuff into, so any of them will do, laundry or toys, it doesn't matter.",
 "This is an open or lidded container for holding loose things like clothes or toys. There are a few of them around the home.",
 "where is a baskit"]),
# ---------------- flat_e ----------------
(FE, "or", 11, [11, 12, 13, 14, 15], {"label": "chair", "room": "dining room"}, [
 "Go to a chair in the dining room.",
 "Could you take me to one of the seats at the dining table?",
 "dining room seat",
 "Any seat in the dining room is fine, I just don't want the little one in the kids bedroom.",
 "This is something to sit on in the dining room. Several of them are set around the big oak table.",
 "take me to a chiar in the dining room"]),
# ---------------- flat_i ----------------
(FI, "or", 6, [6, 7, 8, 9], {"label": "chair", "room": "meeting room"}, [
 "Go to a chair in the meeting room.",
 "Could you take me to a seat in the meeting room?",
 "meeting room seat",
 "I have a client call, so any seat around the glass table in the meeting room, not the studio ones.",
 "This is a seat in the meeting room. Four of them stand around the oval glass table.",
 "go to a seet in the meeting room"]),
(FG, "od", 34, [34], {"why": "only teal lamp; others white arched, beige ceramic, yellow bendy"}, [
 "Go to the lamp with the teal glass base.",
 "Could you take me to the bedside light that has a blue-green glass base?",
 "teal glass bedside light",
 "I want the teal one, not the beige ceramic lamp on the other side of the bed.",
 "This is a small bedside light. Its base is teal glass and its shade is white.",
 "go to the teel bedside light"]),
(FI, "od", 23, [23], {"why": "only blue mug; 31 white striped, 36 mustard yellow"}, [
 "Go to the cobalt blue mug.",
 "Could you find the blue cup that holds the pencils?",
 "blue pencil cup",
 "I need a pencil, take me to the blue mug on the oak desk, not the yellow or striped ones.",
 "This is a deep blue ceramic cup. It is stuffed with pencils.",
 "wheres the blue pencil mugg"]),
(FB, "ord", 3, [3], {"why": "living room armchairs: 2 yellow velvet, 3 brown leather; 28 green is in the study"}, [
 "Go to the brown leather armchair in the living room.",
 "Could you take me to the leather easy chair in the living room?",
 "living room leather chair",
 "In the living room I want the brown leather seat, not the yellow velvet one by the window.",
 "This is a brown leather armchair in the living room. It stands on wooden legs.",
 "go to the brwon leather chair in the living room"]),
(FE, "ord", 30, [30], {"why": "sinks: 21 kitchen (also white ceramic), 30 bathroom"}, [
 "Go to the sink in the bathroom.",
 "Could you take me to the washbasin in the bathroom?",
 "bathroom basin",
 "I want to brush my teeth, so the little basin in the bathroom, not the farmhouse one in the kitchen.",
 "This is a small white ceramic basin in the bathroom. A mirror cabinet hangs above it.",
 "go to the bathroom wash basn"]),
(FI, "ord", 44, [44], {"why": "bedroom nightstands: 43 oak, 44 white"}, [
 "Go to the white nightstand in the bedroom.",
 "Could you take me to the white bedside table in the bedroom?",
 "white bedside table, bedroom",
 "In the bedroom I want the white bedside table with a drawer, not the oak one.",
 "This is a white bedside cabinet in the bedroom. It has one drawer and a rattan lamp on top.",
 "go to the whtie bedside table in the bedroom"]),
(FE, "ard", 33, [33], {"why": "the tumble dryer is the only drying appliance"}, [
 "Take me somewhere I can dry my wet laundry.",
 "Could you show me where to get my washed clothes dry?",
 "dry clothes",
 "The wash just finished, so I need the machine that dries clothes, not the one that washes them.",
 "This is where I want to put my damp clothes. It tumbles them with warm air until they are dry.",
 "my clothes r still wet, where can i drie them"]),
(FG, "ard", 11, [11], {"why": "the ironing board (with the steam iron) is the only place to iron"}, [
 "Take me to where I can iron a shirt.",
 "Could you bring me to where I can press my creased trousers?",
 "iron shirt",
 "My shirt is all wrinkled for the interview, take me where I can smooth it out with a hot iron, not the washer.",
 "This is what I need to get the creases out of my clothes. It should have a steam iron with it.",
 "my shirt is so wrinkly, where can i iorn it"]),
(FI, "ard", 20, [20], {"why": "the printer (also scans) is the only printing device"}, [
 "Take me to where I can print out a drawing.",
 "Could you show me where I can get a paper copy of my plans?",
 "print A3 plans",
 "The client wants a hard copy of the floor plan, so take me to what can put it on paper, not a screen.",
 "This is what I need to turn a file into a sheet of paper. It should also be able to scan.",
 "need to prnt something, where do i go"]),
(FB, "ard", 39, [39], {"why": "flat_b has a shower and no bathtub"}, [
 "Take me where I can rinse off after my run.",
 "Could you show me where I can wash myself standing up?",
 "wash off, standing",
 "I'm covered in mud, take me where I can get clean under running water, not just the sink.",
 "This is where I want to wash my whole body. Water falls from above behind a glass screen.",
 "im all sweaty, where can i showr"]),
(FB, "s", 7, [7], {"claims": [["on", 7, 6, "lamp"], ["east_of", 6, 1]]}, [
 "Go to the lamp on the side table.",
 "Could you take me to the light sitting on top of the little round table in the living room?",
 "light on side table",
 "I mean the small light on top of the side table by the sofa, not the tall floor lamp at the other end.",
 "This is a small light standing on a round white table. The table sits at the sofa's east end.",
 "go to the light on the side tabel"]),
(FG, "s", 32, [32], {"claims": [["nearest", 32, 36, "nightstand"], ["west_of", 32, 31]]}, [
 "Go to the nightstand nearest the wardrobe.",
 "Could you take me to the bedside table that is closer to the wardrobe?",
 "bedside table nearest wardrobe",
 "I want the bedside table on the wardrobe side of the bed, not the one farther away.",
 "This is a white bedside table in the bedroom. It is the one closest to the tall oak wardrobe.",
 "take me to the bedside table closest to the wardrobbe"]),
(FI, "s", 6, [6], {"claims": [["farthest", 6, 10, "chair", "meeting room"], ["east_wall", 10]]}, [
 "Go to the chair in the meeting room that is farthest from the TV.",
 "Could you take me to the meeting room seat farthest from the wall screen?",
 "meeting chair farthest from screen",
 "I don't want to sit near the display, so the seat in the meeting room that is farthest from it, not the one next to it.",
 "This is a seat at the meeting table. Of the four, it is the one farthest from the display on the east wall.",
 "go to the meeting room seat furthest from the scren"]),
# ---------------- apartment ----------------
(APT, "o", 8, [8, 39, 55], {"label": "plant"}, [
 "Go to a plant.",
 "Could you take me to any of the potted greenery?",
 "houseplant",
 "I want to water something green, any of the potted plants will do, fig, succulent or the snake plant.",
 "This is something living and green growing in a pot. There are a few of them in the flat.",
 "take me to some greenry"]),
(APT, "or", 12, [12, 13], {"label": "book", "room": "living room"}, [
 "Go to a book in the living room.",
 "Could you take me to one of the novels or photo albums in the living room?",
 "living room reading material",
 "I want something to read on the couch, any volume from the living room shelf, not the programming one in the office.",
 "This is a printed volume in the living room. It is kept on the tall walnut bookcase.",
 "go to a bok in the living room"]),
(APT, "od", 48, [48], {"why": "only red/leather chair; 23 and 24 are wooden dining chairs"}, [
 "Go to the red leather office chair.",
 "Could you take me to the red swivel seat with wheels?",
 "red leather swivel seat",
 "I want the red one with armrests, not the wooden dining chairs.",
 "This is a red leather seat with armrests. It spins and rolls on wheels.",
 "go to the red swivl seat"]),
(APT, "ord", 42, [42], {"why": "gray cabinets: 42 bathroom vanity, 53 office filing cabinet; 21 kitchen is white"}, [
 "Go to the gray cabinet in the bathroom.",
 "Could you take me to the gray vanity unit in the bathroom?",
 "bathroom vanity",
 "I need a fresh towel from the grey cupboard under the basin in the bathroom, not the metal filing one in the office.",
 "This is a gray wooden cupboard in the bathroom. The washbasin sits on top of it.",
 "go to the grey vanty in the bathroom"]),
(APT, "ard", 29, [29], {"why": "the coat rack by the front door is the place to hang a coat"}, [
 "Take me somewhere by the front door to hang my coat.",
 "Could you show me where I can hang up my jacket when I come in?",
 "hang jacket by door",
 "I'm soaked from the rain and need somewhere to hang my raincoat by the door, not in the wardrobe.",
 "This is where I want to put my coat when I come in. It stands by the front door.",
 "where do i hnag my coat when i get home"]),
(APT, "ard", 45, [45], {"why": "the washing machine is the only laundry appliance"}, [
 "Take me to where I can wash my dirty clothes.",
 "Could you show me where I can do a load of laundry?",
 "wash clothes",
 "My gym kit stinks, so take me to where I can launder it, not the bathtub.",
 "This is what I need to get my clothes clean. It uses water and detergent and spins them.",
 "where can i wash my clohtes"]),
(APT, "s", 13, [13], {"claims": [["lowest", 13, "book"]]}, [
 "Go to the lowest book.",
 "Could you take me to the book that sits lowest down?",
 "bottom-shelf volume",
 "Not the red novel up high, I want the one resting flat down on the lowest shelf.",
 "This is a volume placed nearer the floor than any other. It lies on its side at the base of a bookcase.",
 "go to the lowest boook"]),
(APT, "s", 23, [23], {"claims": [["nearest", 23, 19, "chair"]]}, [
 "Go to the dining chair closest to the stove.",
 "Could you take me to the kitchen seat nearest the cooker?",
 "seat nearest cooker",
 "I want the dining seat near the stove, not the white one across the table.",
 "This is a wooden seat at the dining table. It is the one closest to the oven.",
 "go to the chiar nearest the cooker"]),
# ---------------- scans ----------------
(SOFF, "o", 14, [14, 15, 16], {"label": "bookshelf"}, [
 "Go to a bookshelf.",
 "Could you take me to any of the bookcases?",
 "bookcase",
 "I need a reference book, so any of the shelving units along the wall will do.",
 "This is a piece of furniture with shelves for books. There are three of them against one wall.",
 "go to a bookshelff"]),
(SKIT, "or", 23, [23, 24, 25], {"label": "cup", "room": "kitchen"}, [
 "Go to a cup in the kitchen.",
 "Could you take me to a mug in the kitchen?",
 "kitchen mug",
 "I'm thirsty, any drinking vessel in the kitchen will do, colour doesn't matter.",
 "This is a small drinking vessel in the kitchen. There are several, in different colours.",
 "go to a kitchen cupp"]),
(SKIT, "od", 21, [21], {"why": "only red chair; 17-20 black, 22 white"}, [
 "Go to the red chair.",
 "Could you take me to the red seat?",
 "red seat",
 "I want the red seat, not any of the black ones or the white one.",
 "This is a seat painted red. It is the only one of that colour.",
 "take me to the red chiar"]),
(SLIV, "ord", 3, [3], {"why": "pillows: 2 and 4 red, 3 yellow"}, [
 "Go to the yellow pillow in the living room.",
 "Could you take me to the yellow cushion in the living room?",
 "yellow cushion living room",
 "In the living room I want the yellow cushion, not the red ones.",
 "This is a yellow cushion in the living room. It rests on the gray sofa between two red ones.",
 "go to the yelow cushion in the living room"]),
(SBED, "ard", 22, [22], {"why": "the only trash can in the scan", "claims": [["near", 22, 11, 1.0]]}, [
 "Take me somewhere I can throw away this tissue.",
 "Could you show me where to dispose of my rubbish?",
 "throw away wrapper",
 "I've got an empty wrapper to get rid of, take me to where rubbish goes, not the drawer.",
 "This is where I want to put my garbage. It is a small container near the desk.",
 "where can i thorw this away"]),
(SOFF, "s", 15, [15], {"claims": [["between", 15, 14, 16, "bookshelf"], ["east_end_short", 16, 14, 15]]}, [
 "Go to the bookshelf between the other two.",
 "Could you take me to the middle one of the three bookcases?",
 "middle bookcase",
 "Not the short white one on the east end or the one on the west end, I want the bookcase in between.",
 "This is a wooden bookcase standing between two others. It is brown wood and sits in the middle of the row along the back wall.",
 "go to the midle bookshelf"]),
(SOFF, "s", 21, [21], {"claims": [["nearest", 21, 20, "trash can"]]}, [
 "Go to the trash can nearest the door.",
 "Could you take me to the bin next to the door?",
 "bin by door",
 "I want the wastebasket by the exit, not the one in the far corner near the windows.",
 "This is a black waste bin in the office. It is the one right beside the door.",
 "go to the bin closest to the dorr"]),
(SKIT, "s", 3, [3], {"claims": [["under", 3, 10, "kitchen cabinet"], ["on", 12, 1, "coffee maker"]]}, [
 "Go to the kitchen cabinet under the sink.",
 "Could you take me to the cupboard right below the sink?",
 "cupboard under sink",
 "I need the dish soap, so the base cupboard under the sink, not the one with the coffee maker on it.",
 "This is a white lower cupboard in the kitchen. The sink is set directly above it.",
 "go to the cupbaord under the sink"]),
(SKIT, "s", 25, [25], {"claims": [["on_any", 25, [1, 2, 3, 4, 5, 6], "cup"], ["nearest", 25, 10, "cup"]]}, [
 "Go to the cup sitting on the base cabinets.",
 "Could you take me to the mug on the countertop next to the sink?",
 "mug on countertop",
 "Not the ones on the dining table, I mean the mug standing on the counter by the sink.",
 "This is a white drinking vessel on top of the lower kitchen cupboards. It stands just beside the sink.",
 "go to the cupp on the counter"]),
(SBED, "s", 6, [6], {"claims": [["left_from_foot", 6, 1, "nightstand"], ["on", 21, 6, "clock"], ["on", 20, 7, "book"]]}, [
 "Go to the nightstand on the left when you stand at the foot of the bed facing the headboard.",
 "Could you take me to the bedside table on the left, as seen from the foot of the bed looking at the pillows?",
 "left bedside table from bed foot",
 "Standing at the end of the bed and looking toward the pillows, I want the bedside table on the left, not the one on the right with the book.",
 "This is a wooden bedside table next to the bed. Seen from the foot of the bed it is on the left, and it has a clock on it.",
 "go to the nightstand on the lefft, looking at the bed from its foot"]),
(SBED, "s", 5, [5], {"claims": [["nearest_foot", 5, 1, "pillow"]]}, [
 "Go to the pillow nearest the foot of the bed.",
 "Could you take me to the cushion lying closest to the end of the bed?",
 "cushion at foot of bed",
 "Not the ones up by the headboard, I want the pillow down near the foot of the bed.",
 "This is a small blue cushion on the bed. It lies farther from the headboard than any other.",
 "go to the cushin near the foot of the bed"]),
(SLIV, "s", 15, [15], {"claims": [["above", 15, 1, "picture"]]}, [
 "Go to the picture above the sofa.",
 "Could you take me to the painting hanging over the couch?",
 "painting over couch",
 "I mean the artwork on the wall behind the sofa, not the one on the side wall.",
 "This is a framed picture on the wall. It hangs right above the sofa.",
 "go to the paintng above the couch"]),
]


def main():
    assert len(G) == 48, len(G)
    rows, specs = [], {}
    for n, (mp, typ, target, accept, spec, words) in enumerate(G, 1):
        assert len(words) == 6, n
        gid = f"b48-g{n:02d}"
        specs[gid] = {"map": mp, "type": typ, "target": target, "accept": accept, **spec}
        for k, q in enumerate(words, 1):
            rows.append({"id": f"{gid}-w{k}", "map": mp, "query": q, "type": typ, "target": target,
                         "accept": accept, "group": gid})
    out = ROOT / "evals/blind/round48.jsonl"
    out.write_text("".join(json.dumps(r, ensure_ascii=False) + "\n" for r in rows), encoding="utf-8")
    (ROOT / "scripts/blind_writers/_specs_round48.json").write_text(json.dumps(specs, indent=1), encoding="utf-8")
    print(f"wrote {len(rows)} lines, {len(specs)} groups to {out}")


if __name__ == "__main__":
    main()
