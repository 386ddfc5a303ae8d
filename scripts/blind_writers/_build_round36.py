"""Hand-written groups of blind suite round 36; writes evals/blind/round36.jsonl.

Each group: (map key, type, target, accept, check spec, six wordings w1..w6).
The check spec is read by check.py (it is not written to the suite).
"""
import json
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE.parent / "evals" / "blind" / "round36.jsonl"

MAPS = {
    "c829": "../../../shared/data/iesm_maps/scene_00829_caption.json",
    "off3": "../../../shared/data/iesm_maps/scene_office3_caption.json",
    "fb": "maps/flat_b.json", "fe": "maps/flat_e.json", "fg": "maps/flat_g.json", "fi": "maps/flat_i.json",
    "apt": "apartment",
    "sbed": "../maps/scan_bedroom.json", "skit": "../maps/scan_kitchen.json",
    "sliv": "../maps/scan_livingroom.json", "soff": "../maps/scan_office.json",
}

# check spec keys: label (o), label+room (or), unique=filter dict (od/ord: exactly one object matches),
# spatial claims list (s).
GROUPS = [
    # ---------------- scene_00829 (caption map) ----------------
    ("c829", "o", 4, [4, 9, 32, 79, 191, 261, 263], {"label": "easy chair"}, [
        "Go to an easy chair.",
        "Could you take me to one of the cushioned lounging armchairs?",
        "comfy lounge armchair",
        "I just want to sink into something soft for a while, so an easy chair, not the folding kind.",
        "This is an upholstered armchair made for lounging. It is one of several such seats around the home.",
        "take me to a comfy lounging armchiar pls",
    ]),
    ("c829", "o", 42, [42, 197, 212, 259], {"label": "book"}, [
        "Go to a book.",
        "Could you find me a bound volume I could read?",
        "hardcover volume",
        "I fancy some reading, so take me to a book, any one will do, not the rack they are kept in.",
        "This is a bound volume with a cover and printed pages. It could be any of the ones lying around the home.",
        "where's a novle or some volume i can read",
    ]),
    ("c829", "or", 34, [34, 74], {"label": "side table", "room": "living room"}, [
        "Go to a side table in the living room.",
        "Could you show me an end table in the lounge?",
        "end table, living room",
        "I need to set my drink down while sitting in the living room, so a side table there, not the ones in the bedroom.",
        "This is a small occasional table placed next to seating. It stands in the living room.",
        "which little end tabel is in the living room",
    ]),
    ("c829", "or", 195, [195, 216, 228], {"label": "cabinet kitchen", "room": "bathroom"}, [
        "Go to a cupboard in the bathroom.",
        "Could you take me to one of the wooden cabinets in the bathroom?",
        "bathroom cupboard",
        "I'm looking for spare storage space in the bathroom, so a cupboard in there, not the ones in the kitchen or bedroom.",
        "This is a dark wooden storage cabinet with doors. It is found in the bathroom.",
        "need a cuboard in the bathroom",
    ]),
    ("c829", "od", 211, [211], {"unique": {"label": "decorative bowl"}}, [
        "Go to the blue decorative bowl with gold patterns.",
        "Could you bring me to the deep blue ceramic dish with gold detailing?",
        "blue glazed bowl, gold pattern",
        "I want to show a guest the ornamental blue bowl, not the white one that holds sweets.",
        "This is a shiny ceramic bowl in a deep blue. It is decorated with fine golden motifs.",
        "where's the blue bowl with the gold patern on it",
    ]),
    ("c829", "od", 164, [164], {"unique": {"label": "set of towels", "caption_has": "'H'"}}, [
        "Go to the folded towels embroidered with the letter H.",
        "Could you take me to the pile of white towels that have an H stitched on them?",
        "towels with H monogram",
        "I want the monogrammed towels with the letter H, not the plain stacks.",
        "This is a stack of folded white cotton towels. They carry a letter H sewn into the fabric.",
        "the towles with the h on them, where are they",
    ]),
    ("c829", "ord", 191, [191], {"unique": {"label": "easy chair", "room": "bathroom"}}, [
        "Go to the beige velvet easy chair in the bathroom.",
        "Could you lead me to the cream velvet armchair that's in the bathroom?",
        "beige velvet armchair, bathroom",
        "Take me to the soft beige velvet lounge chair in the bathroom, not the ones in the living room.",
        "This is a curved armchair upholstered in beige velvet. It sits in the bathroom.",
        "that beige velvet armchiar in the bathroom pls",
    ]),
    ("c829", "ard", 192, [192], {"unique": {"label": "bed for pet"}}, [
        "Go to where my cat can curl up and sleep.",
        "Could you show me where the dog is supposed to sleep?",
        "spot for pet to sleep",
        "The puppy is tired and needs its own place to nap, not my bed.",
        "What I need is a soft spot where my kitten can doze. It should be sized for a small animal, not a person.",
        "my kiten needs somewhere cosy to nap",
    ]),
    # ---------------- scene_office3 (caption map) ----------------
    ("off3", "o", 8, [8, 13, 20, 40], {"label": "pillow"}, [
        "Go to a pillow.",
        "Could you take me to one of the cushions?",
        "throw cushion",
        "My back hurts on this hard seat, so take me to a pillow, any colour is fine.",
        "This is a soft stuffed cushion. It is one of several scattered around the room.",
        "where is a cusion i can lean on",
    ]),
    ("off3", "od", 37, [37], {"unique": {"label": "chair", "caption_has": "speaker"}}, [
        "Go to the black plastic chair with a built-in speaker.",
        "Could you take me to the seat that has a speaker built into it?",
        "chair with speaker",
        "I want to listen to music while sitting, so the seat with the integrated speaker, not the mesh ones.",
        "This is a black plastic seat that can give you a massage. It also has a speaker inside it.",
        "the black seat with a speker in it",
    ]),
    ("off3", "od", 45, [45], {"unique": {"label": "table"}}, [
        "Go to the golden brown wooden table with power outlets.",
        "Could you take me to the golden-brown wooden surface that has plug sockets built in?",
        "golden wood top, built-in outlets",
        "My laptop is dying, so take me to the wooden table with outlets, not one of the desks.",
        "This is a piece of furniture with a flat golden brown wooden top. It has power outlets built into it.",
        "the wood one with plugs built in, golden brwon colour",
    ]),
    ("off3", "ord", 7, [7], {"unique": {"label": "desk", "room": "rec room", "color": "white"}}, [
        "Go to the white wooden desk in the rec room.",
        "Could you take me to the white workstation in the recreation room?",
        "white desk, rec room",
        "I'd like to work at the white writing table in the rec room, not the brown ones.",
        "This is a white wooden work surface with a USB port. It is in the rec room.",
        "the wite workstation in the rec room",
    ]),
    ("off3", "ard", 25, [25], {"unique": {"label": "clock"}}, [
        "Go to something on the wall that tells the time.",
        "Could you take me to where I can read the time on the wall?",
        "wall time check",
        "I'm running late and need a glance at the hour on the wall, without digging out a phone.",
        "I need to know the current hour. Take me to whatever on the wall shows it.",
        "what hour is it, take me to whatever on the wall shows the tmie",
    ]),
    # ---------------- flat_b ----------------
    ("fb", "s", 33, [33], {"spatial": [("nearest", 36, {"label": "lamp"})]}, [
        "Go to the lamp closest to the bedroom window.",
        "Could you take me to the light that is nearest the window in the bedroom?",
        "lamp nearest bedroom window",
        "I want to read by the window in the bedroom, so take me to the bedside light closest to it, not the one on the far side of the bed.",
        "This is a bedside light in the bedroom. It is the one nearest to the window.",
        "the bedside light closest to the bedroom windw",
    ]),
    ("fb", "s", 32, [32], {"spatial": [("side", "+y", "right", {"label": "nightstand"})]}, [
        "Stand at the foot of the bed facing the headboard and go to the nightstand on your right.",
        "Could you go to the bedside table on the right-hand side when you face the headboard from the foot of the bed?",
        "bedside table, right side, facing headboard from foot of bed",
        "Facing the headboard from the foot of the bed, I want the bedside table on the right, not the left one.",
        "This is a white bedside table next to the double bed. Facing the headboard from the bed's foot, it is on the right.",
        "from the foot of the bed looking at the headboard, the bedside tabel on the right",
    ]),
    ("fb", "or", 2, [2, 3], {"label": "armchair", "room": "living room"}, [
        "Go to an armchair in the living room.",
        "Could you take me to one of the easy chairs in the lounge?",
        "lounge armchair",
        "I want a comfy single seat in the living room, not the reading chair in the study.",
        "This is an upholstered single-seat chair with arms. It is in the living room.",
        "any comfy chiar in the living room",
    ]),
    ("fb", "ord", 26, [26], {"unique": {"label": "lamp", "room": "study"}}, [
        "Go to the green glass lamp in the study.",
        "Could you take me to the banker's-style light with the green shade in the study?",
        "green shade desk light, study",
        "I need focused light for paperwork, so the green-shaded lamp on the study desk, not the bedside ones.",
        "This is a desk light whose shade is green glass on a brass stand. It sits in the study.",
        "the green banker's lihgt in the study",
    ]),
    ("fb", "ard", 40, [40], {"unique": {"label": "towel"}}, [
        "Take me to something I can dry myself with after a shower.",
        "Could you find me something to dry off with in the bathroom?",
        "dry off after bath",
        "I've just washed my face and it's dripping, so I need something to pat it dry with, not a hairdryer.",
        "I have just stepped out of the shower and I'm wet. Take me to what I can dry my body with.",
        "i'm soaking wet, need something to drry myself off",
    ]),
    # ---------------- flat_e ----------------
    ("fe", "o", 6, [6, 37], {"label": "plant"}, [
        "Go to a plant.",
        "Could you take me to some greenery in a pot?",
        "potted greenery",
        "I want to check if anything needs watering, so take me to a potted plant, either one.",
        "This is something living and green growing in a pot. It could be indoors or out on the balcony.",
        "where's some potted greenry",
    ]),
    ("fe", "or", 11, [11, 12, 13, 14, 15], {"label": "chair", "room": "dining room"}, [
        "Go to a chair in the dining room.",
        "Could you take me to a seat in the dining room?",
        "dining room seat",
        "I want to sit down for dinner, so any chair in the dining room, not the one on the balcony.",
        "This is a seat in the room where meals are eaten. Any of the ones around the dining table will do.",
        "a seat in the dinning room pls",
    ]),
    ("fe", "ord", 14, [14], {"unique": {"label": "chair", "room": "dining room", "color": "black"}}, [
        "Go to the black metal chair in the dining room.",
        "Could you take me to the mismatched black bistro seat in the dining room?",
        "black metal seat, dining room",
        "Take me to the black metal seat in the dining room, not the sage green ones.",
        "This is a dark metal seat in a bistro style. It is in the dining room and is the odd one out.",
        "the blak metal seat in the dining room",
    ]),
    ("fe", "ard", 33, [33], {"unique": {"label": "dryer"}}, [
        "Take me to something that will dry my wet laundry.",
        "Could you show me where I can dry a load of washing?",
        "dry wet clothes",
        "The wash just finished and the clothes are soaking, so I need to get them dry, not wash them again.",
        "I have a basket of damp clothes. Take me to the appliance that will get them dry.",
        "my clothes are still wet, where can i tumble them dyr",
    ]),
    ("fe", "s", 39, [39], {"spatial": [("nearest", 1, {"label": "chair"}), ("nearest", 1, {"label_in": ["chair", "armchair"]})]}, [
        "Go to the chair nearest the sofa.",
        "Could you take me to the seat that's closest to the couch?",
        "seat closest to couch",
        "I want somewhere to sit right by the sofa, so the nearest seat to it, not one at the dining table.",
        "This is a seat. Of every chair in the flat, it is the one closest to the teal couch.",
        "whichever seat is nearest the teal cuoch",
    ]),
    # ---------------- flat_g ----------------
    ("fg", "od", 37, [37], {"unique": {"label": "basket", "material": "wicker"}}, [
        "Go to the lidded wicker hamper.",
        "Could you take me to the woven laundry hamper with a lid?",
        "wicker hamper with lid",
        "I have dirty socks to throw in, so the wicker hamper, not the plastic basket of clean clothes.",
        "This is a brown woven container with a lid on top. It is meant for clothes that need washing.",
        "the wicker hampr for dirty laundry",
    ]),
    ("fg", "s", 2, [2], {"spatial": [("nearest", 4, {"label": "bicycle"})]}, [
        "Go to the bicycle closer to the workbench.",
        "Could you take me to the bike that stands nearer the workbench?",
        "bike nearest workbench",
        "I need to fix a puncture at the bench, so take me to the bike closest to it, not the farther one.",
        "This is one of the two bikes in the garage. It is the one nearer the wooden workbench.",
        "the bike closest to the wrokbench",
    ]),
    ("fg", "or", 34, [34, 35], {"label": "lamp", "room": "bedroom"}, [
        "Go to a lamp in the bedroom.",
        "Could you take me to one of the bedside lights in the bedroom?",
        "bedroom bedside light",
        "I want to switch on a light in the bedroom, not the one in the kids room.",
        "This is a small light that sits on a bedside table. It is in the bedroom.",
        "a bedside lamp in the bedrom",
    ]),
    ("fg", "ord", 20, [20], {"unique": {"label": "trash can", "room": "kitchen"}}, [
        "Go to the stainless steel trash can in the kitchen.",
        "Could you take me to the steel pedal bin in the kitchen?",
        "kitchen pedal bin",
        "I've got food scraps to throw out, so the steel bin in the kitchen, not the green wheelie bin in the garage.",
        "This is a stainless steel rubbish bin with a foot pedal. It stands in a corner of the kitchen.",
        "the stainless garbage bin in the kichen",
    ]),
    ("fg", "ard", 11, [11], {"unique": {"label": "ironing board"}}, [
        "Take me to where I can press my shirt.",
        "Could you show me where I can get the creases out of my trousers?",
        "iron wrinkled shirt",
        "My shirt is all creased for the interview, so I need to iron it, not wash it.",
        "I have a crumpled blouse. Take me to where I can smooth out the wrinkles with a hot iron.",
        "my shirt is so wrinkly, where can i iorn it",
    ]),
    # ---------------- flat_i ----------------
    ("fi", "o", 23, [23, 31, 36], {"label": "mug"}, [
        "Go to a mug.",
        "Could you take me to a coffee cup?",
        "handled cup",
        "I want a hot drink, so take me to a mug, any of them, not the kettle.",
        "This is a ceramic drinking vessel with a handle. There are a few around the flat.",
        "where's a cofee cup",
    ]),
    ("fi", "or", 6, [6, 7, 8, 9], {"label": "chair", "room": "meeting room"}, [
        "Go to a chair in the meeting room.",
        "Could you take me to a seat in the conference room?",
        "meeting room seat",
        "I'm joining the client meeting, so any seat in the meeting room, not the ones in the studio.",
        "This is a seat around the glass table. It is in the meeting room.",
        "a seat in the meting room",
    ]),
    ("fi", "ord", 46, [46], {"unique": {"label": "lamp", "room": "bedroom", "material": "rattan"}}, [
        "Go to the rattan lamp in the bedroom.",
        "Could you take me to the bedside light with a woven shade in the bedroom?",
        "woven-shade bedside light, bedroom",
        "I want that patterned glow, so the rattan-shaded light in the bedroom, not the ceramic one.",
        "This is a bedside light topped by a woven rattan shade. It is in the bedroom.",
        "the rattan bedsdie light in the bedroom",
    ]),
    ("fi", "ard", 20, [20], {"unique": {"label": "printer"}}, [
        "Take me to where I can print out a drawing.",
        "Could you show me where I can get a paper copy of these plans?",
        "print A3 plans",
        "I need a hard copy of the floor plan for the client, so somewhere to print it, not just a screen.",
        "I have a document on my laptop that must go on paper. Take me to what can print it.",
        "need to prnt some drawings",
    ]),
    ("fi", "s", 7, [7], {"spatial": [("nearest", 10, {"label": "chair", "color": "red"})]}, [
        "Go to the red chair closer to the wall screen in the meeting room.",
        "Could you take me to the red seat nearest the big wall display in the meeting room?",
        "red chair nearest meeting room wall screen",
        "I'm presenting, so I want the red seat right by the wall-mounted display, not the other red one.",
        "This is one of two red plastic seats at the meeting table. It is the one nearer the display hung on the wall.",
        "the red seat closest to the big wall scren",
    ]),
    # ---------------- apartment ----------------
    ("apt", "o", 6, [6, 31], {"label": "picture"}, [
        "Go to a picture.",
        "Could you take me to a framed artwork on the wall?",
        "framed wall art",
        "I want to look at some art, so take me to a picture on the wall, not the mirror.",
        "This is a framed image hanging on a wall. There is more than one around the flat.",
        "take me to some framed artwrok",
    ]),
    ("apt", "or", 23, [23, 24], {"label": "chair", "room": "kitchen"}, [
        "Go to a chair in the kitchen.",
        "Could you take me to a dining seat in the kitchen?",
        "kitchen dining seat",
        "I want to sit down to eat, so a chair in the kitchen, not the office one.",
        "This is a wooden seat placed at the dining table. It is in the kitchen.",
        "any seat in the kitchn",
    ]),
    ("apt", "ord", 42, [42], {"unique": {"label": "cabinet", "room": "bathroom"}}, [
        "Go to the gray vanity cabinet in the bathroom.",
        "Could you take me to the grey wooden vanity unit under the basin in the bathroom?",
        "gray vanity, bathroom",
        "I need fresh towels and toiletries, so the bathroom cabinet under the sink, not the kitchen cupboards.",
        "This is a gray wooden storage unit beneath the washbasin. It is in the bathroom.",
        "the grey vanity unit in the bathrom",
    ]),
    ("apt", "od", 31, [31], {"unique": {"label": "picture", "caption_has": "lighthouse"}}, [
        "Go to the black-and-white photo of a lighthouse.",
        "Could you take me to the small framed photograph showing a lighthouse?",
        "lighthouse photo",
        "I want to see the lighthouse print, not the big blue painting over the sofa.",
        "This is a small monochrome photograph with a thin dark frame. It shows a lighthouse.",
        "the lighthouse phtoo in the black frame",
    ]),
    ("apt", "ard", 20, [20], {"unique": {"label": "microwave"}}, [
        "Take me to something that can reheat my leftovers in a couple of minutes.",
        "Could you show me where I can quickly warm up last night's curry?",
        "zap leftovers quickly",
        "I'm in a hurry and just want to reheat this plate fast, not cook on the hob.",
        "I have cold leftovers on a plate. Take me to the appliance that warms them up in a minute or two.",
        "need to nuke my lefovers real quick",
    ]),
    ("apt", "s", 12, [12], {"spatial": [("higher", {"label": "book", "room": "living room"})]}, [
        "Go to the higher of the two books on the living room bookshelf.",
        "Could you take me to the book that sits higher up in the living room bookcase?",
        "upper volume, living room bookcase",
        "Take me to the volume standing up high on the living room shelves, not the one lying at the bottom.",
        "This is a novel on the living room bookcase. It sits higher up than the other volume there.",
        "the volume higher up on the living room shelvs",
    ]),
    ("apt", "s", 39, [39], {"spatial": [("on", 38, {"label": "plant"})]}, [
        "Go to the plant on top of the dresser.",
        "Could you take me to the little potted plant sitting on the chest of drawers?",
        "potted greenery atop chest of drawers",
        "I want to water the small one on the dresser, not the big fig in the living room.",
        "This is a small potted thing growing on top of the dresser. It is in the bedroom.",
        "the tiny houseplant on top of the dreser",
    ]),
    # ---------------- scans ----------------
    ("skit", "s", 8, [8], {"spatial": [("above", 10, {"label": "kitchen cabinet"})]}, [
        "Go to the wall cabinet directly above the sink.",
        "Could you take me to the upper cupboard over the sink?",
        "cupboard above sink",
        "I need something from the top cupboard over the sink, not the base unit under it.",
        "This is an upper wall cupboard. It hangs directly above the sink.",
        "the cupbaord right above the sink",
    ]),
    ("skit", "s", 20, [20], {"spatial": [("nearest", 13, {"label": "chair", "color": "black"})]}, [
        "Go to the black chair nearest the fridge.",
        "Could you take me to the black seat that's closest to the refrigerator?",
        "black chair closest to fridge",
        "I want to sit near the fridge to grab drinks, so the nearest black seat to it, not the red or white ones.",
        "This is one of the black dining seats at the table. It is the one closest to the refrigerator.",
        "the black seat nearest the frige",
    ]),
    ("skit", "o", 23, [23, 24, 25], {"label": "cup"}, [
        "Go to a cup.",
        "Could you take me to one of the drinking mugs?",
        "any drinking mug",
        "I'm thirsty, so take me to a cup, any colour, not the bowl.",
        "This is a small vessel you drink from. There are several around the kitchen.",
        "wheres a coffe mug",
    ]),
    ("sbed", "s", 7, [7], {"spatial": [("nearest", 15, {"label": "nightstand"})]}, [
        "Go to the nightstand nearest the door.",
        "Could you take me to the bedside table closest to the doorway?",
        "bedside table by door",
        "I want to drop my keys as I walk in, so the bedside table closest to the door, not the one by the window.",
        "This is a wooden bedside table beside the bed. It is the one closer to the entrance door.",
        "the bedside tabel closest to the door",
    ]),
    ("sliv", "s", 2, [2], {"spatial": [("side", "+y", "left", {"label": "pillow", "color": "red"})]}, [
        "Sit on the sofa facing the TV and go to the red pillow on your left.",
        "Could you take me to the red cushion on the left end of the couch, as seen by someone sitting on it facing the TV?",
        "left red cushion, seated on sofa facing tv",
        "Sitting on the couch looking at the TV, I want the red cushion on my left, not the one on my right.",
        "This is a red cushion on the gray sofa. For a person seated there facing the TV, it is on the left side.",
        "sitting on the couch facing the tv, the red cusion on the left",
    ]),
    ("soff", "s", 10, [10], {"spatial": [("nearest", 20, {"label": "office chair"})]}, [
        "Go to the office chair nearest the door.",
        "Could you take me to the desk chair that is closest to the exit?",
        "swivel chair nearest door",
        "I'm leaving soon, so give me the seat closest to the door, not one by the whiteboard.",
        "This is a swivel chair at one of the two tables. It is the one closest to the door.",
        "the desk chair nearest the dooor",
    ]),
    ("sliv", "od", 5, [5], {"unique": {"label": "armchair", "color": "green"}}, [
        "Go to the green armchair.",
        "Could you take me to the green easy chair?",
        "green easy chair",
        "I want the green armchair, not the brown leather one.",
        "This is an upholstered single seat with arms. It is green.",
        "the gren easy chair",
    ]),
    ("soff", "ard", 17, [17], {"unique": {"label": "whiteboard"}}, [
        "Take me to something I can sketch ideas on for the whole team.",
        "Could you show me where I can write up notes with a marker for everyone to see?",
        "write on wall with marker",
        "I want to brainstorm with the team using dry-erase pens, not on paper.",
        "I need to draw a diagram large enough for a group to see. Take me to where I can write it with a marker.",
        "where can i scribble notes with a markr for the team",
    ]),
]


def rows():
    out = []
    for n, (mk, typ, target, accept, _spec, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, n
        g = f"b36-g{n:02d}"
        for k, q in enumerate(words, 1):
            out.append({"id": f"{g}-w{k}", "map": MAPS[mk], "query": q, "type": typ,
                        "target": target, "accept": sorted(accept), "group": g})
    return out


if __name__ == "__main__":
    r = rows()
    OUT.write_text("".join(json.dumps(x) + "\n" for x in r), encoding="utf-8")
    print(f"wrote {len(r)} lines, {len(GROUPS)} groups to {OUT}")
