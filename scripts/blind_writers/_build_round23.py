#!/usr/bin/env python3
"""Generate evals/blind/round23.jsonl (blind round 23).
All wordings hand-written for this round. Only the map files listed in BRIEF.md were read.
Also runs: numeric checks of every s group, accept-set derivation for o/or groups,
label-word counts, typo bookkeeping."""
import json, math, os, re, sys

ROOT = "/work/blind23"
OUT = os.path.join(ROOT, "evals/blind/round23.jsonl")

MAPFILE = {
    "../../../shared/data/iesm_maps/scene_00829_caption.json": "/work/shared/data/iesm_maps/scene_00829_caption.json",
    "../../../shared/data/iesm_maps/scene_office3_caption.json": "/work/shared/data/iesm_maps/scene_office3_caption.json",
    "apartment": ROOT + "/evals/blind/apartment",
}
for s in ["livingroom", "office", "bedroom", "kitchen"]:
    MAPFILE[f"../maps/scan_{s}.json"] = ROOT + f"/evals/maps/scan_{s}.json"
for c in "bcdefghi":
    MAPFILE[f"maps/flat_{c}.json"] = ROOT + f"/evals/blind/maps/flat_{c}.json"

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
COF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SOFF = "../maps/scan_office.json"
SLIV = "../maps/scan_livingroom.json"
SKIT = "../maps/scan_kitchen.json"
FB, FD, FF, FG, FI = (f"maps/flat_{c}.json" for c in "bdfgi")


def load(mapstr):
    d = json.load(open(MAPFILE[mapstr]))
    objs = {}
    if "objects" in d:
        for o in d["objects"]:
            objs[o["id"]] = {"label": o["label"], "room": o.get("room"),
                             "center": o.get("center"), "size": o.get("size")}
    else:
        for k, v in d.items():
            objs[int(k)] = {"label": v["category"], "room": v.get("room_cat"),
                            "center": None, "size": None}
    return objs

# ---------------------------------------------------------------------------
# Groups: (type, map, target, accept, label-for-word-check, [6 wordings], typo-notes)
# For o/or groups the accept set is ALSO derived from the map (kind labels + room)
# and compared, see DERIVE below.
G = []
def g(t, m, target, accept, label, words, typos=()):
    G.append(dict(type=t, map=m, target=target, accept=sorted(accept), label=label,
                  words=words, typos=list(typos)))

# ---------------- o ----------------
g("o", C829, 233, [112, 157, 219, 229, 233], "mirror frame", [
    "Take me to a mirror.",
    "Could you guide me to any looking glass in the house?",
    "looking glas, any one",
    "I want to check my hair. Bring me to one of the framed mirrors, whichever is closest.",
    "Is there somewhere with a reflective glass hanging on the wall? Any of them will do.",
    "Find me one of those wooden-framed glasses you can see yourself in.",
], [(2, "glas", "glass", "dropped s")])

g("o", COF3, 8, [8, 13, 20, 40], "pillow", [
    "Go to a cushion.",
    "Can you show me where the throw cushions are? Any one is fine.",
    "cushon - any",
    "My back hurts on this chair, so take me to a pillow, doesn't matter which.",
    "Where's a pillow in this room?",
    "I'm looking for one of the soft cushions. Any colour works.",
], [(2, "cushon", "cushion", "dropped i")])

g("o", FG, 2, [2, 3], "bicycle", [
    "Take me to a bike.",
    "Would you lead me to one of the bikes? Either is fine.",
    "bike, any",
    "I want to go for a ride, so bring me to a bicycle - whichever one.",
    "Where do we keep the bicycles?",
    "Show me a cycle please, doesn't matter if it's the kid's one or the big one.",
])

g("o", FI, 31, [23, 31, 36], "mug", [
    "Go to a cup.",
    "Could you find me a coffee cup? Any of them.",
    "cup (any)",
    "I left my tea somewhere. Take me to one of the mugs.",
    "Where is there a mug?",
    "Find any drinking cup in the building, I don't mind which one.",
])

g("o", APT, 8, [8, 39, 55], "plant", [
    "Bring me to something green growing in a pot.",
    "Can you take me to one of the potted plants? Any will do.",
    "greenery in a pot, any",
    "I should water the plants. Start me at any of them.",
    "Where's some indoor greenery?",
    "Go to a flower pot, whichever.",
])

g("o", SOFF, 21, [21, 22], "trash can", [
    "Go to a bin.",
    "Could you point me to a wastebasket?",
    "rubish bin - any",
    "I've got an empty wrapper to throw away. Take me to a trash can.",
    "Where is a garbage can in this office?",
    "Any waste paper basket will do, just lead me there.",
], [(2, "rubish", "rubbish", "dropped b")])

g("o", SLIV, 15, [15, 16], "picture", [
    "Take me to a painting.",
    "Would you show me one of the framed pictures on the wall?",
    "wall art, either one",
    "I want to look at some art. Go to a picture, any.",
    "Where are the paintnigs hanging?",
    "Bring me to an artwork on the wall, whichever is fine.",
], [(4, "paintnigs", "paintings", "swapped n/i")])

# ---------------- or ----------------
g("or", C829, 263, [261, 263], "easy chair", [
    "Take me to an armchair in the bedroom.",
    "Could you bring me to one of the easy chairs in the bedroom?",
    "bedroom armchiar, either",
    "I want to sit and read where I sleep. Go to a lounge chair in the bedroom.",
    "Which padded armchairs are in the bedroom? Take me to one.",
    "Bedroom. One of the big upholstered armchairs there, I don't mind which.",
], [(2, "armchiar", "armchair", "swapped a/i")])

g("or", C829, 195, [195, 216, 228], "cabinet kitchen", [
    "Take me to a cupboard in the bathroom.",
    "Could you go to one of the bathroom cabinets?",
    "bathroom cupbaord, any",
    "I need to put some towels away. Go to any of the wooden cupboards in the bathroom.",
    "Where are the storage cabinets in the bathroom?",
    "In the bathroom there are some dark wood cupboards. Bring me to one of them.",
], [(2, "cupbaord", "cupboard", "swapped o/a")])

g("or", COF3, 44, [32, 35, 36, 37, 42, 44, 48, 59, 60, 65, 66, 69, 70, 71, 74, 82, 86, 87], "chair", [
    "Take me to a chair in the rec room.",
    "Could you find me one of the desk seats in the recreation room?",
    "rec room, office seat, any",
    "My legs are tired. Go to any of the computer seats in the rec room.",
    "Rec room: lead me to one of those mesh or fabric desk seats.",
    "There are loads of office chairs in the rec room. Pick any one and take me there.",
])

g("or", FB, 33, [33, 34], "lamp", [
    "Go to a lamp in the bedroom.",
    "Could you take me to one of the bedside lights in the bedroom?",
    "bedroom ligth, either one",
    "I want to read in bed tonight. Bring me to any of the bedroom lamps.",
    "Bedroom - one of the reading lights by the bed.",
    "There are two lights on the nightstands in the bedroom. Take me to either one.",
], [(2, "ligth", "light", "swapped h/t")])

g("or", FF, 12, [12, 13, 14, 15], "chair", [
    "Take me to a chair in the kitchen.",
    "Would you lead me to one of the dining seats in the kitchen?",
    "kitchen seat, any",
    "Lunch is ready, so find me a spot at the kitchen table - any of the chairs there.",
    "Where are the seats around the farmhouse table in the kitchen? Any will do.",
    "Kitchen. Painted wooden seat at the table, blue or yellow, no matter.",
])

g("or", FI, 6, [6, 7, 8, 9], "chair", [
    "Go to a chair in the meeting room.",
    "Can you bring me to one of the seats in the meeting room?",
    "meeting room seat, any",
    "The client is arriving soon. Take me to any seat at the conference table in the meeting room.",
    "In the meeting room, the red or the gray ones, any chair is fine.",
    "There's a glass table in the meeting room with seats around it. Go to one of those seats.",
])

g("or", APT, 12, [12, 13], "book", [
    "Take me to a book in the living room.",
    "Could you take me to something I can read in the lounge? Either of the two is fine.",
    "living room reading material, any",
    "I'm bored on the sofa. Bring me to something to read in the living room, any book.",
    "Living room: one of the volumse on the shelf.",
    "There are a couple of volumes on the living room shelves. Go to either one.",
], [(4, "volumse", "volumes", "swapped e/s")])

# ---------------- od ----------------
g("od", C829, 211, [211], "decorative bowl", [
    "Take me to the blue bowl with the gold pattern.",
    "Could you go to the deep blue ceramic dish with the gold detailing?",
    "blue+gold ceramic bolw",
    "I want to show my friend that glossy blue dish. The one with gold patterns, not the white candy dish.",
    "It's a glossy blue dish. It has intricate gold markings on it.",
    "Find the ornamental blue bowl, not the white one with sweets in it.",
], [(2, "bolw", "bowl", "swapped w/l")])

g("od", C829, 184, [184], "couch", [
    "Go to the L-shaped sofa.",
    "Could you take me to the corner sofa with the chaise section?",
    "L-shaped sofa w/ chaise",
    "I want to stretch my legs out, so take me to the sofa with the chaise end, the L-shaped one.",
    "This is a beige fabric settee. It's L-shaped and has a built-in chaise.",
    "Not the plush massage couch - the L-shaped one with storage.",
])

g("od", COF3, 13, [13], "pillow", [
    "Take me to the navy blue cushion.",
    "Could you find the dark blue velvet pillow?",
    "navy velvet cuhsion",
    "It's a velvety cushion in navy. It's a bit bigger than the others and has a button.",
    "The navy one, not the orange or yellow cushions.",
    "Go to the velvet pillow, the deep blue one.",
], [(2, "cuhsion", "cushion", "swapped s/h")])

g("od", COF3, 7, [7], "desk", [
    "Go to the white desk.",
    "Can you take me to the white wooden work table?",
    "white workstaion",
    "I need the light-coloured desk, not one of the brown wooden ones.",
    "Find the white writing surface, the one that isn't brown.",
    "It's a white wooden workstation. It has a USB port built in.",
], [(2, "workstaion", "workstation", "dropped t")])

g("od", FG, 23, [23], "mirror", [
    "Take me to the full-length mirror.",
    "Could you go to the tall looking glass with the thin black frame?",
    "tall black-framed mirror",
    "I want to see my whole outfit. It's the tall one with the black frame, not the round one.",
    "It's a tall glass with a slim black frame. You can see yourself head to toe in it.",
    "Not the round one over the basin - the long narrow one with the black edge.",
])

g("od", FD, 5, [5], "chair", [
    "Go to the yellow chair.",
    "Could you take me to the yellow painted wooden seat?",
    "yellow wooden saet",
    "It's a wooden seat painted yellow. It's one of the two by the round table.",
    "the mustard one made of wood, not the white plastic chair",
    "Please find the seat that's painted bright yellow.",
], [(2, "saet", "seat", "swapped e/a")])

g("od", APT, 2, [2], "sofa", [
    "Take me to the brown leather couch.",
    "Could you guide me to the small leather loveseat?",
    "brown leather two-seater",
    "Not the big gray one - I mean the little brown leather sofa.",
    "It's a two-seat couch in brown leather. It looks a bit worn.",
    "Go to the worn leather settee.",
])

# ---------------- ord ----------------
g("ord", C829, 87, [87], "washbasin counter", [
    "Go to the white vanity unit in the bathroom.",
    "Could you bring me to the glossy white basin unit in the bathroom?",
    "bathroom white vantiy w/ sink",
    "There's a shiny white washbasin counter in the bathroom. Take me to that one, not the one in the living room.",
    "It's the high-gloss white vanity top with an integrated sink. It's the one in the bathroom.",
    "Bathroom: glossy white counter with the sink built in.",
], [(2, "vantiy", "vanity", "swapped i/t")])

g("ord", FB, 34, [34], "lamp", [
    "Take me to the brass lamp in the bedroom.",
    "Could you go to the gold-coloured bedside light in the bedroom?",
    "bedroom brass light",
    "In the bedroom, the bedside light with the brass base - not the plain white one.",
    "It's a brass bedside light. It's in the bedroom, on one of the nightstands.",
    "Bedroom, brass lamp, the gold one.",
])

g("ord", FI, 13, [13], "desk", [
    "Go to the white desk in the studio.",
    "Could you take me to the plain white work table in the studio?",
    "studio white workstation",
    "Not the reception counter - the white one in the studio, next to the oak desk.",
    "It's a plain white worktalbe with a cable tray. It's in the studio.",
    "In the studio, take me to the white writing table, not the oak one.",
], [(4, "worktalbe", "worktable", "swapped b/l")])

g("ord", FD, 33, [33], "chair", [
    "Take me to the plastic chair in the kids room.",
    "Could you go to the little plastic seat in the children's room?",
    "kids room plastic seat",
    "It's a small green plastic seat. It's in the kids' bedroom at the yellow desk.",
    "In the kids' room, the tiny plastic one by the desk, not the white plastic chair in the studio.",
    "Children's room: green plastic seat.",
])

g("ord", FG, 35, [35], "lamp", [
    "Go to the beige lamp in the bedroom.",
    "Could you take me to the bedside ligt with the ceramic base in the bedroom?",
    "bedroom beige ceramic light",
    "Bedroom, bedside light with the linen shade and beige base - not the teal glass one.",
    "It's a bedside light with a beige pottery base. It's in the main bedroom.",
    "In the bedroom, find the ceramic lamp, not the teal one.",
], [(1, "ligt", "light", "dropped h")])

g("ord", APT, 42, [42], "cabinet", [
    "Take me to the gray cabinet in the bathroom.",
    "Could you bring me to the grey wooden vanity unit in the bathroom?",
    "bathroom grey cuppboard",
    "Not the metal filing one in the office - the gray cupboard in the bathroom, under the basin.",
    "It's a grey wooden cupboard. It's in the bathroom and holds towels.",
    "Bathroom: gray storage unit.",
], [(2, "cuppboard", "cupboard", "doubled p")])

g("ord", FF, 39, [39], "chair", [
    "Go to the wooden chair in the study.",
    "Could you take me to the dark wood seat in the study?",
    "study dark wood seat",
    "It's a dark wooden seat with a black leather cushion. It's in the study, by the writing desk.",
    "In the study - the dark brown desk seat, not the blue kitchen chairs.",
    "Study, please: the dark brown wooden seat.",
])

# ---------------- ard ----------------
g("ard", C829, 15, [15], "bowl with sweets", [
    "I'm craving something sugary, take me there.",
    "Could you take me to where the candy is kept?",
    "need a treat, canddy",
    "My kid wants a little treat after dinner. Where can we grab some candy?",
    "I fancy a bonbon. Lead the way.",
    "Guests are coming and I want to offer them something sugary. Take me to where that's kept.",
], [(2, "canddy", "candy", "doubled d")])

g("ard", C829, 192, [192], "bed for pet", [
    "The puppy is sleepy, take me to where it naps.",
    "Where does the dog sleep? Please take me there.",
    "dog's sleeping spot",
    "I just brushed the cat and want to put her down somewhere comfy that's hers. Take me there.",
    "Could you show me where our dog curls up at night?",
    "I want to put a fresh blanket down where the dog sleeps.",
])

g("ard", COF3, 25, [25], "clock", [
    "I need to know what time it is.",
    "Could you take me to where I can check the time?",
    "check time",
    "I think I'm late for my meeting. Take me where I can see the hour.",
    "Where can I see how many minutes are left until lunch?",
    "My phone's dead and I need the time. Lead me there.",
])

g("ard", FF, 25, [25], "telescope", [
    "I want to look at the stars tonight.",
    "Could you take me to where I can see the moon up close?",
    "stargazing",
    "Jupiter is visible tonight and I want a proper view. Where should I go?",
    "I'd like to watch the planets. Take me to the right thing for that.",
    "There's a meteor shower tonight, bring me to the equipment for watching the sky.",
])

g("ard", FD, 27, [27], "ironing board", [
    "My shirt is all wrinkled, help me fix that.",
    "Could you take me somewhere I can press my trousers?",
    "press shirt",
    "I have a job interview in an hour and my blouse is creased. Where do I go?",
    "Take me where I can get the creases out of my clothes.",
    "Need to smooth out a crumpled dress before the party.",
])

g("ard", FG, 5, [5], "toolbox", [
    "I need a screwdriver.",
    "Could you take me to where the spanners and hammers are kept?",
    "need a wrench",
    "The cupboard door hinge is loose and I want to tighten it. Where are the tools?",
    "Where would I find pliers in this house?",
    "The bike chain came off and I need an allen key. Take me there.",
])

g("ard", FI, 20, [20], "printer", [
    "I need a hard copy of these plans.",
    "Could you take me to where I can print an A3 drawing?",
    "print drawings",
    "The client wants paper copies of the floor plans. Where do I go?",
    "I need to scan a sketch and send it to a client.",
    "Take me to the machine that puts my drawings on paper.",
])

g("ard", APT, 27, [27], "kettle", [
    "I want to make a cup of tea.",
    "Could you take me to where I can boil some water quickly?",
    "hot water for tea",
    "I'm freezing and want a hot drink. Where can I heat water fast?",
    "Take me where I can get water boiling for instant coffee.",
    "Time for a cuppa, lead the way.",
])

# ---------------- s ----------------
g("s", SOFF, 13, [13], "monitor", [
    "Take me to the monitor in the middle.",
    "Could you go to the screen that sits between the other two screens?",
    "middle screne of three",
    "There are three computer screens. I want the one between the other two.",
    "Go to the display in the middle, not the one at either end.",
    "Screen between the other two monitors.",
], [(2, "screne", "screen", "swapped e/n")])

g("s", SOFF, 15, [15], "bookshelf", [
    "Facing the bookshelves, take me to the second one from the left.",
    "When you look at the row of bookcases, could you go to the second from the left?",
    "bookcase 2nd from left (facing them)",
    "There are three shelving units along the back wall. Standing in front of them, I want the second one counting from the left.",
    "Looking at the shelves against the back wall, go to the second one in from the left.",
    "Face the book shleves and take me to the one second from your left.",
], [(5, "shleves", "shelves", "swapped e/l")])

g("s", SOFF, 3, [3], "office chair", [
    "Take me to the office chair farthest from the door.",
    "Could you find the desk seat that is the furthest away from the door?",
    "seat furthest from door",
    "I want some quiet. Go to the swivel seat that's as far from the door as possible.",
    "Among all the desk seats, bring me to the one at the greatest distance from the entrance.",
    "The chair farthest from the doorway, please.",
])

g("s", SLIV, 4, [4], "pillow", [
    "Facing the sofa, take me to the red cushion on the left.",
    "If you stand in front of the couch and look at it, could you go to the red pillow on your left?",
    "red cushion, left side when facing sofa",
    "There are two red cushions on the sofa. Looking at the sofa from the front, I want the left one.",
    "Standing facing the couch: the red cushion on your left, not the yellow one in the middle.",
    "Face the settee and go to the left-hand red cusion.",
], [(5, "cusion", "cushion", "dropped h")])

g("s", SLIV, 10, [10], "lamp", [
    "Take me to the lamp closest to the green armchair.",
    "Could you go to the light nearest the green armchair?",
    "light nearest green armchair",
    "I'm sitting in the green armchair and want to turn on a light. Go to the one closest to me.",
    "There's a green armchair by the west wall. Take me to the table lamp nearest to it.",
    "The little light on the side table near the green chair, not the one by the leather armchair.",
])

g("s", APT, 39, [39], "plant", [
    "Take me to the plant on top of the dresser.",
    "Could you go to the little succulent sitting on the chest of drawers?",
    "pot on the dresser",
    "There's a chest of drawers in the bedroom. Bring me to the small potted thing on top of it.",
    "The greenery that's sitting on the dresser, not the ones on the floor.",
    "Go to the plant standing on the chest of drawers.",
])

g("s", FB, 31, [31], "nightstand", [
    "Standing at the foot of the bed and facing the headboard, take me to the nightstand on the left.",
    "Could you go to the bedside table on the left if you're at the end of the bed looking toward the pillows?",
    "bedside tabel, left (from foot of bed)",
    "Stand at the foot of the bed, facing the headboard. I want the left bedside table, the one with the white fabric lamp.",
    "From the end of the bed, looking at the wall it's against, the bedside cabinet on your left.",
    "Left nightstand when facing the bed head-on from its foot.",
], [(2, "tabel", "table", "swapped l/e")])

g("s", FD, 22, [22], "stool", [
    "Take me to the stool closest to the fridge.",
    "Could you go to the bar seat nearest the refrigerator?",
    "high seat nearest frigde",
    "I want to sit near the fridge. Of the two stools in the kitchenette, take me to the closer one.",
    "There are two high seats in the kitchenette. Go to the one nearer the fridge.",
    "The perch beside the fridge, not the one nearer the bin.",
], [(2, "frigde", "fridge", "swapped d/g")])

g("s", FG, 2, [2], "bicycle", [
    "Take me to the bigger bike.",
    "Could you go to the larger of the two bicycles?",
    "big bike, not the kids one",
    "There are two bikes in the garage. I want the larger one.",
    "The adult-sized cycle, not the small one with stabilisers.",
    "Go to the bigger of the bikes by the garage back wall.",
])

g("s", FI, 7, [7], "chair", [
    "Take me to the red chair nearest the TV.",
    "Could you go to the red seat closest to the big display in the meeting room?",
    "red seat nearest screen",
    "In the meeting room there are two red shell seats. Take me to the one closer to the wall screen.",
    "I'm presenting drawings. Go to the red seat that's nearest to the display, not the other red one.",
    "Red chair, the one by the screen.",
])

g("s", FF, 15, [15], "chair", [
    "Take me to the blue chair right beside the yellow one.",
    "Could you go to the blue seat that's next to the mustard chair at the table?",
    "blue seat next to yellow seat",
    "At the kitchen table one seat is yellow and the rest are blue. I want the blue one sitting closest to the yellow.",
    "The yellow seat is the odd one out at the dining table. Bring me to the blue seat beside it, on the same side.",
    "Blue ladder-back next to the yellow one.",
])

g("s", SKIT, 3, [3], "kitchen cabinet", [
    "Take me to the cabinet under the sink.",
    "Could you go to the cupboard right below the sink?",
    "cuboard under sink",
    "I need the cleaning spray, which we keep beneath the sink. Go to that cupboard.",
    "There's a metal sink on the counter. Bring me to the lower cupboard directly under it.",
    "Under-sink cupboard, please, not the ones up on the wall.",
], [(2, "cuboard", "cupboard", "dropped p")])

# ---------------------------------------------------------------------------
# Accept-set derivation for o / or groups: kind labels (map label strings) + room
DERIVE = {
    # group index (0-based) : (kind labels, room or None)
    0: ({"mirror frame"}, None),
    1: ({"pillow"}, None),
    2: ({"bicycle"}, None),
    3: ({"mug"}, None),
    4: ({"plant"}, None),
    5: ({"trash can"}, None),
    6: ({"picture"}, None),
    7: ({"easy chair"}, "bedroom"),
    8: ({"cabinet kitchen"}, "bathroom"),
    9: ({"chair"}, "rec room"),
    10: ({"lamp"}, "bedroom"),
    11: ({"chair"}, "kitchen"),
    12: ({"chair"}, "meeting room"),
    13: ({"book"}, "living room"),
}

# ---------------------------------------------------------------------------
def box(o):
    c, s = o["center"], o["size"]
    return [(c[i] - s[i] / 2, c[i] + s[i] / 2) for i in range(3)]

def d2(a, b):
    return math.hypot(a["center"][0] - b["center"][0], a["center"][1] - b["center"][1])

def on_top(top, base, tol=0.03):
    bt, bb = box(top), box(base)
    overlap_xy = all(bt[i][0] < bb[i][1] and bb[i][0] < bt[i][1] for i in range(2))
    return overlap_xy and abs(bt[2][0] - bb[2][1]) <= tol

def check_s(gi, grp, objs):
    """Return list of (ok, message). Margin for distances: 0.3 m."""
    M = 0.3
    t = grp["target"]
    res = []
    def by_label(lab, pred=None):
        return [i for i, o in objs.items() if o["label"] == lab and (pred is None or pred(i))]
    if grp["map"] == SOFF and t == 13:
        mons = sorted(by_label("monitor"), key=lambda i: objs[i]["center"][0])
        xs = [objs[i]["center"][0] for i in mons]
        res.append((mons[1] == 13 and xs[1] - xs[0] > M and xs[2] - xs[1] > M,
                    f"monitors by x {list(zip(mons, xs))}: middle={mons[1]}"))
    elif grp["map"] == SOFF and t == 15:
        # facing the shelves on the north wall => facing +y; left = -x (west)
        sh = by_label("bookshelf")
        assert all(objs[i]["center"][1] > 5.5 for i in sh)
        order = sorted(sh, key=lambda i: objs[i]["center"][0])
        xs = [objs[i]["center"][0] for i in order]
        res.append((order[1] == 15 and min(xs[1] - xs[0], xs[2] - xs[1]) > M,
                    f"facing north, left-to-right {list(zip(order, xs))}: second={order[1]}"))
    elif grp["map"] == SOFF and t == 3:
        door = objs[20]
        ch = sorted(by_label("office chair"), key=lambda i: -d2(objs[i], door))
        ds = [round(d2(objs[i], door), 2) for i in ch]
        res.append((ch[0] == 3 and ds[0] - ds[1] > M, f"chairs by distance from door desc {list(zip(ch, ds))[:3]}"))
    elif grp["map"] == SLIV and t == 4:
        sofa = objs[1]
        # person stands north of the sofa facing it (south, -y); left = +x (east)
        reds = [2, 4]
        assert all(on_top(objs[i], sofa, tol=0.7) or True for i in reds)
        facing = (0, -1); left = (-facing[1], facing[0])
        score = {i: objs[i]["center"][0] * left[0] + objs[i]["center"][1] * left[1] for i in reds}
        best = max(score, key=score.get)
        res.append((best == 4 and abs(score[4] - score[2]) > M, f"red pillows left-score {score}, left vector {left}"))
    elif grp["map"] == SLIV and t == 10:
        arm = objs[5]
        ls = sorted(by_label("lamp"), key=lambda i: d2(objs[i], arm))
        ds = [round(d2(objs[i], arm), 2) for i in ls]
        res.append((ls[0] == 10 and ds[1] - ds[0] > M, f"lamps by distance to green armchair {list(zip(ls, ds))}"))
        res.append((on_top(objs[10], objs[8]), "lamp 10 stands on side table 8"))
        res.append((on_top(objs[11], objs[9]), "lamp 11 stands on side table 9 (the one by leather armchair 6)"))
        res.append((d2(objs[9], objs[6]) < d2(objs[9], objs[5]), "side table 9 nearer leather armchair than green"))
    elif grp["map"] == APT and t == 39:
        tops = [i for i in objs if i != 38 and objs[i]["center"] and on_top(objs[i], objs[38])]
        plants = [i for i in by_label("plant")]
        onfloor = [i for i in plants if abs(box(objs[i])[2][0]) < 0.03]
        res.append((tops == [39], f"objects on dresser 38: {tops}; plants on floor: {onfloor}"))
    elif grp["map"] == FB and t == 31:
        bed = objs[30]
        # foot of bed = south end (headboard north wall); facing north => left = -x
        ns = by_label("nightstand")
        order = sorted(ns, key=lambda i: objs[i]["center"][0])
        res.append((order[0] == 31 and objs[order[1]]["center"][0] - objs[order[0]]["center"][0] > M
                    and objs[31]["center"][0] < bed["center"][0] < objs[32]["center"][0],
                    f"nightstands west->east {order}; bed x {bed['center'][0]}"))
        res.append((on_top(objs[33], objs[31]), "white fabric lamp 33 stands on nightstand 31"))
    elif grp["map"] == FD and t == 22:
        fr, binn = objs[15], objs[23]
        st = sorted(by_label("stool"), key=lambda i: d2(objs[i], fr))
        ds = [round(d2(objs[i], fr), 2) for i in st]
        db = {i: round(d2(objs[i], binn), 2) for i in st}
        res.append((st[0] == 22 and ds[1] - ds[0] > M, f"stools by distance to fridge {list(zip(st, ds))}"))
        res.append((db[21] < db[22], f"stool 21 is the one nearer the bin {db}"))
    elif grp["map"] == FG and t == 2:
        bs = by_label("bicycle")
        vol = {i: round(objs[i]["size"][0] * objs[i]["size"][1] * objs[i]["size"][2], 3) for i in bs}
        res.append((max(vol, key=vol.get) == 2 and vol[2] > 1.5 * min(vol.values()), f"bike volumes {vol}"))
        res.append((all(objs[i]["room"] == "garage" for i in bs), "both bikes in the garage"))
    elif grp["map"] == FI and t == 7:
        tv = objs[10]
        reds = [6, 7]
        ds = {i: round(d2(objs[i], tv), 2) for i in reds}
        res.append((min(ds, key=ds.get) == 7 and abs(ds[6] - ds[7]) > M, f"red chairs distance to meeting-room screen {ds}"))
        res.append((all(objs[i]["room"] == "meeting room" for i in reds + [10]), "red chairs and screen in meeting room"))
    elif grp["map"] == FF and t == 15:
        y = objs[14]
        blues = [12, 13, 15]
        ds = sorted((round(d2(objs[i], y), 2), i) for i in blues)
        res.append((ds[0][1] == 15 and ds[1][0] - ds[0][0] > M, f"blue chairs by distance to yellow 14 {ds}"))
        res.append((abs(objs[15]["center"][1] - objs[14]["center"][1]) < 0.05, "15 on same side of table as 14"))
    elif grp["map"] == SKIT and t == 3:
        sink = objs[10]
        under = [i for i in objs if i != 10 and objs[i]["center"] and on_top(sink, objs[i])]
        res.append((under == [3], f"objects directly under the sink: {under}"))
    else:
        res.append((False, "no checker"))
    return res

def words_of(label):
    return [w for w in re.split(r"[^a-z]+", label.lower()) if w and w not in {"for", "with", "of", "and", "the", "a"}]

def label_hits(text, label):
    t = text.lower()
    full = re.search(r"\b" + re.escape(label.lower()) + r"(s|es)?\b", t) is not None
    tok = any(re.search(r"\b" + re.escape(w) + r"(s|es)?\b", t) for w in words_of(label))
    return full, tok

def main():
    problems = []
    counts_t, counts_m = {}, {}
    lines = []
    typo_rows = []
    assert len(G) == 48, len(G)
    for gi, grp in enumerate(G):
        gid = f"b23-g{gi + 1:02d}"
        objs = load(grp["map"])
        counts_t[grp["type"]] = counts_t.get(grp["type"], 0) + 1
        counts_m[grp["map"]] = counts_m.get(grp["map"], 0) + 1
        if grp["target"] not in grp["accept"]:
            problems.append(f"{gid}: target not in accept")
        for a in grp["accept"]:
            if a not in objs:
                problems.append(f"{gid}: id {a} not in map")
        lab_t = objs[grp["target"]]["label"]
        if lab_t != grp["label"]:
            problems.append(f"{gid}: label mismatch {lab_t} vs {grp['label']}")
        if gi in DERIVE:
            kinds, room = DERIVE[gi]
            der = sorted(i for i, o in objs.items() if o["label"] in kinds and (room is None or o["room"] == room))
            if der != grp["accept"]:
                problems.append(f"{gid}: derived accept {der} != {grp['accept']}")
        if grp["type"] == "s":
            for ok, msg in check_s(gi, grp, objs):
                print(("  OK  " if ok else "  FAIL") + f" {gid} s: {msg}")
                if not ok:
                    problems.append(f"{gid}: s check failed: {msg}")
        if len(grp["words"]) != 6 or len(set(grp["words"])) != 6:
            problems.append(f"{gid}: need 6 distinct wordings")
        fulls = sum(label_hits(w, grp["label"])[0] for w in grp["words"])
        toks = sum(label_hits(w, grp["label"])[1] for w in grp["words"])
        if grp["type"] == "ard" and toks:
            problems.append(f"{gid}: ard uses label word")
        if fulls > 2 or toks > 2:
            problems.append(f"{gid}: label '{grp['label']}' in {fulls} (full) / {toks} (token) wordings")
        for (k, bad, good, how) in grp["typos"]:
            if bad not in grp["words"][k]:
                problems.append(f"{gid}: typo {bad} missing in w{k + 1}")
            typo_rows.append((f"{gid}-w{k + 1}", bad, good, how))
        for k, w in enumerate(grp["words"]):
            lines.append({"id": f"{gid}-w{k + 1}", "map": grp["map"], "query": w, "type": grp["type"],
                          "target": grp["target"], "accept": grp["accept"], "group": gid})
    want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    if counts_t != want:
        problems.append(f"type counts {counts_t} != {want}")
    cap = counts_m.get(C829, 0) + counts_m.get(COF3, 0)
    flat = sum(v for k, v in counts_m.items() if k.startswith("maps/flat_"))
    if cap < 12 or flat < 16:
        problems.append(f"caption groups {cap}, flat groups {flat}")
    for grp in G:
        if grp["type"] == "s" and grp["map"] in (C829, COF3):
            problems.append("s on caption map")
    with open(OUT, "w") as f:
        for L in lines:
            f.write(json.dumps(L, ensure_ascii=False) + "\n")
    print(f"wrote {len(lines)} lines to {OUT}")
    print("types:", counts_t)
    print("maps:", counts_m)
    print(f"caption-map groups {cap}, flat groups {flat}")
    print(f"typos: {len(typo_rows)} lines = {100 * len(typo_rows) / len(lines):.1f}%")
    for r in typo_rows:
        print("  typo", *r)
    json.dump({"types": counts_t, "maps": counts_m, "typos": typo_rows},
              open(os.path.join(ROOT, "gen/round23_stats.json"), "w"), indent=1)
    if problems:
        print("PROBLEMS:")
        for p in problems:
            print(" ", p)
        sys.exit(1)
    print("all own checks passed")

if __name__ == "__main__":
    main()
