"""Write evals/blind/round18.jsonl (48 groups x 6 wordings) and check the spatial groups numerically.

All wordings were written by hand for this round; the only inputs read are the map files listed in
/work/blind18/BRIEF.md.  Run:  python3 /work/blind18/make_round18.py
"""

import json
import math
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "evals" / "blind" / "round18.jsonl"

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SLR = "../maps/scan_livingroom.json"
SK = "../maps/scan_kitchen.json"
FB, FC, FE, FH = (f"maps/flat_{x}.json" for x in "bceh")

OFF3_CHAIRS = [32, 35, 36, 37, 42, 44, 48, 59, 60, 65, 66, 69, 70, 71, 74, 82, 86, 87]

# (map, type, target, accept, [six wordings])
GROUPS = [
    # ---------------- scene_00829 (caption map) ----------------
    (C829, "o", 4, [4, 9, 32, 79, 191, 261, 263], [
        "Take me to an easy chair.",
        "Could you show me where the armchairs are?",
        "comfy lounge chair, any of them",
        "I want to sink into a big padded chair with arms. Where are those?",
        "Find me one of the big cushioned armchairs, whichever.",
        "take me to a lounge chiar please",
    ]),
    (C829, "or", 261, [261, 263], [
        "Go to the easy chair in the bedroom.",
        "Is there an armchair in the bedroom? Take me there.",
        "bedroom armchair",
        "I'd like to sit and read in the bedroom. Bring me to one of the comfy chairs with arms in there.",
        "The big brown lounge chairs, the ones in the bedroom, not the living room.",
        "Could you guide me to a padded seat with armrests in the bedroom?",
    ]),
    (C829, "od", 211, [211], [
        "Take me to the deep blue bowl with the gold patterns.",
        "Where's that glossy blue ceramic dish with gold detailing?",
        "blue+gold ornamental bowl",
        "There's a decorative bowl, dark blue. It has gold-tinged patterns on it.",
        "Not the white one with sweets in it, the blue ceramic bowl, please.",
        "Can you find the blue bwol with the golden design?",
    ]),
    (C829, "ord", 191, [191], [
        "Take me to the beige velvet armchair in the bathroom.",
        "There's an oddly placed easy chair in the bathroom, the soft beige one. Go there.",
        "bathroom: beige velvet lounge chair",
        "Could you bring me to the cream-coloured velvety seat that's in the bathroom?",
        "I'm looking for a seat in the bathroom. It's beige velvet with a curved shape.",
        "the beige curvy armchiar in the bathroom",
    ]),
    (C829, "ard", 122, [122], [
        "I really need to pee, where do I go?",
        "Nature calls. Take me to where I can relieve myself.",
        "need the loo, urgent",
        "Excuse me, where can I do my business? I just need to go.",
        "My kid needs to go potty right now, quick!",
        "I've had way too much coffee and I have to go, you know, go.",
    ]),
    (C829, "od", 265, [265], [
        "Take me to the black leather briefcase.",
        "Where did I leave my black work bag, the leather one with a metal lock?",
        "black leather attache case w/ lock",
        "I need my document case. It's black leather and locks with a metal clasp.",
        "Could you find the black leather breifcase?",
        "The one made of black leather that you carry papers in, not the backpack.",
    ]),
    (C829, "o", 42, [42, 197, 212, 259], [
        "Take me to a book.",
        "Where can I find something to read? Any of the books is fine.",
        "hardcover volume, any",
        "Could you show me where the hardback volumes are?",
        "I'd like one of the novels lying around, whichever is closest.",
        "any bok will do, just bring me to one",
    ]),
    # ---------------- scene_office3 (caption map) ----------------
    (OFF3, "o", 8, [8, 13, 20, 40], [
        "Take me to a pillow.",
        "Where are the cushions?",
        "cushion, any colour",
        "I want something soft to put behind my back. Find me one of the throw cushions.",
        "Could you show me one of the sofa pillows, doesn't matter which?",
        "any of the cusions on the couch",
    ]),
    (OFF3, "od", 13, [13], [
        "Take me to the navy blue pillow.",
        "Which cushion is the dark blue velvet one? Go there.",
        "navy velvet cushion",
        "It's a cushion. Dark blue, velvety, with buttons, a bit bigger than the rest.",
        "Not the orange or yellow ones, the navy cushion, please.",
        "Could you find the velvet pillow in deep navy?",
    ]),
    (OFF3, "ord", 45, [45], [
        "Take me to the golden brown wooden table in the rec room.",
        "In the rec room there's a warm honey-toned wood surface with power outlets built in. Bring me to it.",
        "rec room, golden-brown wood table",
        "Could you show me the light-brown wooden tabletop in the recreation room? Not one of the desks.",
        "I'm after the wooden surface with charging sockets, the golden-brown one in the games room.",
        "That golden brown wood tabel in the rec room, please.",
    ]),
    (OFF3, "ard", 25, [25], [
        "What time is it? Take me to where I can check.",
        "I've lost track of the time and my phone is dead.",
        "need to see the time",
        "Show me something on the wall that tells me the hour.",
        "Am I late for my meeting? I need to check what time it is.",
        "How long until lunch? Bring me to whatever shows the time.",
    ]),
    (OFF3, "or", 35, OFF3_CHAIRS, [
        "Take me to a chair in the rec room.",
        "Could you bring me to one of the desk chairs in the recreation room?",
        "rec room, any office seat",
        "I need to sit down in the rec room, but not on the sofa or the bench. One of the individual seats.",
        "Which of the office-style seats in the games room is free? Take me to one.",
        "a chiar in the rec room, any of them",
    ]),
    # ---------------- flat_b ----------------
    (FB, "s", 34, [34], [
        "Standing at the foot of the bed looking at the headboard, take me to the light on the right-hand nightstand.",
        "bedside ligth, east side of the bed",
        "Which lamp sits on the right nightstand if I face the headboard? Go there.",
        "There's a reading light on each side of the double bed. I want the one on the east side.",
        "Facing the bed from its foot, the right bedside light please, not the left one.",
        "lamp on the bedside table to the right, seen from the foot of the bed",
    ]),
    (FB, "od", 26, [26], [
        "Take me to the green glass banker's lamp.",
        "Where's the desk light with the green shade and brass base?",
        "green-shaded desk light",
        "It's a classic library-style light with a green glass shade. Take me to it.",
        "Not the white bedside ones, the green glass lamp, please.",
        "Could you find the banker's light with the green glass?",
    ]),
    (FB, "or", 20, [20, 21, 22], [
        "Take me to a chair in the kitchen.",
        "Could you show me one of the dining seats in the kitchen?",
        "kitchen chair, any",
        "I want to sit at the kitchen table. Bring me to one of the seats around it.",
        "Any of the seats at the round table in the kitchen, not the swivel one in the study.",
        "a kitchen cahir, whichever",
    ]),
    (FB, "ard", 29, [29], [
        "Where can I hang my jacket?",
        "I just came in soaking wet, where does my coat go?",
        "hang up coat",
        "I've got my scarf and jacket in my hands. Where should I put them?",
        "Could you take me somewhere to hang my coat so it's not on the floor?",
        "Guests are arriving; show me where they can hang their coats.",
    ]),
    (FB, "ord", 2, [2], [
        "Take me to the yellow velvet armchair in the living room.",
        "In the living room, the mustard-coloured seat by the window, please.",
        "living room: mustard velvet seat",
        "There's a yellow velvet easy chair. It's in the living room beside the window.",
        "Not the brown leather one, the yellow armchair in the lounge.",
        "Could you guide me to the mustard velvet seat in the living room?",
    ]),
    # ---------------- flat_c ----------------
    (FC, "ord", 21, [21], [
        "Take me to the black metal chair in the kitchen.",
        "In the kitchen, which seat is the black metal one? Go there.",
        "kitchen - black metal seat",
        "There's a chair that doesn't match the white ones. It's black metal and sits at the kitchen table.",
        "Not the white wooden ones, the black metal seat by the kitchen table.",
        "Could you take me to the dark metal kitchen seat?",
    ]),
    (FC, "s", 7, [7], [
        "Take me to the lamp sitting on the side table.",
        "the small light on top of the little black table by the sofa",
        "Which light stands on the side table at the end of the couch? Not the tall floor one.",
        "There's a little table at the west end of the sofa. Bring me to the light on it.",
        "lamp on top of the side table",
        "Could you go to the table light resting on the small metal table next to the sofa?",
    ]),
    (FC, "o", 5, [5, 7, 28, 36], [
        "Take me to a lamp.",
        "Where are the lights? Any one of them.",
        "any lamp",
        "Could you show me one of the light fittings, floor or table, doesn't matter?",
        "Bring me to one of the lampshades, any room.",
        "Go to whichever lmap is nearest.",
    ]),
    (FC, "ard", 17, [17], [
        "I want to make a cup of tea.",
        "Could you take me to where I can boil some water?",
        "boil water for cofee",
        "I'm cold and want a hot cup of tea. Take me to what I need to boil the water.",
        "Fancy a cuppa? Show me what heats water quickest.",
        "hot water for my instant noodles, fast",
    ]),
    # ---------------- flat_e ----------------
    (FE, "s", 13, [13], [
        "Take me to the green dining chair right next to the black metal one.",
        "Which sage chair sits beside the black bistro one? Go there.",
        "green seat next to the black one at the table",
        "At the dining table, one seat is black metal. I want the green seat right beside it, on the same side.",
        "the painted green seat that neighbours the odd black one",
        "Of the three green dining seats, the one closest to the black metal seat.",
    ]),
    (FE, "ard", 15, [15], [
        "My baby is hungry, where can I sit her to feed her?",
        "Time for the toddler's lunch. Take me to where he eats.",
        "feed the baby",
        "We're about to eat and the little one needs a seat with a tray. Where is it?",
        "Where does the baby sit at mealtimes?",
        "I need to strap my one-year-old in for dinner.",
    ]),
    (FE, "or", 11, [11, 12, 13, 14, 15], [
        "Take me to a chair in the dining room.",
        "any dining room seat",
        "Could you show me one of the seats in the dining room?",
        "I want to sit down in the dining room. Any seat there.",
        "One of the chairs around the dining room table, please, any of them.",
        "a seat in the dinning room",
    ]),
    (FE, "ord", 28, [28], [
        "Take me to the rattan chair in the main bedroom.",
        "In the main bedroom there's a natural wicker armchair with a cream cushion. Go there.",
        "master bedroom rattan seat",
        "Could you bring me to the woven seat in the corner of the main bedroom?",
        "The cane armchair, the one in the big bedroom, not the one at the kid's desk.",
        "rattan chiar in the main bedroom",
    ]),
    # ---------------- flat_h ----------------
    (FH, "od", 32, [32], [
        "Take me to the black mug with the chipped handle.",
        "Where's the matte black cup that's a bit chipped?",
        "black chipped mug",
        "I'm looking for a coffee cup. It's matte black and the handle is damaged.",
        "Not the yellow camping one or the striped one, the dark cup.",
        "Could you find my black coffe cup, the chipped one?",
    ]),
    (FH, "ord", 11, [11], [
        "Go to the mustard armchair in the living room.",
        "living room, yellow velvet chair in the corner",
        "Could you find the mustard-coloured velvet seat in the lounge?",
        "There's a velvet easy chair in the living room. It's mustard yellow, not the leather one.",
        "Not the cognac leather one by the bookshelf, the yellow armchair in the living room.",
        "I'd like to sit in the yellow velvet seat in the sitting room.",
    ]),
    (FH, "s", 46, [46], [
        "Take me to the bedside table that has the lamp on it.",
        "In the master bedroom, which nightstand holds the lamp? Go there.",
        "nightstand under the white lamp",
        "There are two bedside tables by the double bed. I want the one with the ceramic light standing on it.",
        "Not the one with the book, the bedside cabinet with the light on it.",
        "bedside tabel topped by the light, main bedroom",
    ]),
    (FH, "o", 5, [5, 6], [
        "Take me to a sofa.",
        "Where's the couch?",
        "couch, either",
        "I want to stretch out for a bit. Bring me to one of the settees.",
        "Could you show me any of the sofas in the flat?",
        "Go to the nearest cuoch.",
    ]),
    (FH, "ard", 4, [4], [
        "Where should I drop my keys when I get home?",
        "I just walked in, where do the house keys go?",
        "somewhere to leave keys",
        "I keep losing my keys. Show me where they're supposed to go.",
        "Could you take me to where everyone puts their keys?",
        "Coming through the front door with my keys in hand. Where do they belong?",
    ]),
    (FH, "s", 16, [16], [
        "Standing south of the dining table and facing it, take me to the left of the two black chairs.",
        "the black bistro seat on the west, on the near side of the dining table",
        "Facing the dining table from the living room side, which black seat is on the left? Go there.",
        "There are two black metal seats on the south side of the table. I want the west one.",
        "Not the one on the right: with your back to the living room, the left black chair.",
        "left-hand black seat when you face the table from the south",
    ]),
    # ---------------- apartment ----------------
    (APT, "s", 12, [12], [
        "Take me to the book on the upper shelf of the living room bookcase.",
        "Of the two books on the living room shelves, the higher one.",
        "top-shelf novel in the lounge bookcase",
        "There's a bookcase in the living room with two volumes on it. I want the one that's higher up, not the one lying at the bottom.",
        "Go to the living room bookcase's upper volume, not the flat one at the bottom.",
        "highest boook on the living room shelves",
    ]),
    (APT, "or", 12, [12, 13], [
        "Take me to a book in the living room.",
        "any of the books in the lounge",
        "Something to read in the living room: where are the novels kept?",
        "I want to grab a read from the living room shelves. Show me one.",
        "Could you show me a volume from the living-room bookcase?",
        "living room reading material on the shelf",
    ]),
    (APT, "or", 23, [23, 24], [
        "Take me to a chair in the kitchen.",
        "kitchen seat, either one",
        "Could you bring me to one of the seats at the kitchen table?",
        "I'd like to sit down in the kitchen. Any of the dining chairs there.",
        "Where can I sit in the kitchen? One of the wooden seats by the table.",
        "One of the kitchen table seats, the green-cushioned or the white one, I don't mind.",
    ]),
    (APT, "ard", 45, [45], [
        "I need to do a load of laundry.",
        "My clothes are dirty, where can I wash them?",
        "wash clothes",
        "I spilled wine all over my shirt and need to get it properly clean. Where do I go?",
        "Where can I run a wash cycle for the bedsheets?",
        "The laundry basket is full. Take me to where it gets done.",
    ]),
    (APT, "ord", 2, [2], [
        "Take me to the brown leather sofa in the living room.",
        "the small leather two-seater in the living room",
        "living room leather loveseat",
        "In the living room there are two couches. I want the brown leather one against the west wall, not the big grey one.",
        "Could you guide me to the worn brown leather couch in the lounge?",
        "brown leather settee, living room, the small one",
    ]),
    (APT, "od", 48, [48], [
        "Take me to the red leather office chair.",
        "Where is the red swivel seat with wheels?",
        "red leather desk chair",
        "It's a seat on wheels. Red leather, with armrests.",
        "Not the blue velvet one, the red leather seat with castors.",
        "Could you find the red rolling seat?",
    ]),
    (APT, "o", 17, [17, 41], [
        "Take me to a sink.",
        "Where's the nearest basin?",
        "any sink",
        "Could you show me one of the washbasins, kitchen or bathroom?",
        "Bring me to a basin with a tap, any room.",
        "take me to a snik",
    ]),
    # ---------------- scan_livingroom ----------------
    (SLR, "s", 3, [3], [
        "Take me to the pillow between the two red ones.",
        "the middle cushion on the sofa",
        "Which cushion sits between the red pair? Go there.",
        "There are three cushions on the couch. I want the one in the middle.",
        "Not either end, the centre sofa cushion.",
        "cushion in between the red ones",
    ]),
    (SLR, "s", 10, [10], [
        "Sitting on the sofa facing the TV, take me to the lamp on my left.",
        "the table light on the left-hand side table, seen from the couch",
        "From the couch looking at the television, which light is on the left end table? Go there.",
        "There's a side table at each end of the sofa. I want the light on the west one.",
        "Not the right one: with my back on the sofa facing the TV, the left table lamp.",
        "left end-table light when seated on the sofa",
    ]),
    (SLR, "s", 18, [18], [
        "Take me to the plant nearest the door.",
        "which houseplant is closest to the doorway?",
        "plant closest to door",
        "There are two potted greens in this room. I want the one nearer the door, not the one by the bookshelf.",
        "Go to the leafy pot nearer the way out.",
        "Could you find the potted plnat nearest the exit?",
    ]),
    (SLR, "o", 15, [15, 16], [
        "Take me to a picture.",
        "Where are the paintings on the wall?",
        "framed art, any",
        "Could you show me one of the framed pictures hanging up?",
        "I want to look at some of the artwork. Any piece.",
        "go to a pitcure on the wall",
    ]),
    (SLR, "od", 5, [5], [
        "Take me to the green armchair.",
        "Where's the green easy chair?",
        "green armchair, not the leather one",
        "I'm after an upholstered seat. It's the green one.",
        "Not the brown leather seat, the green one with arms.",
        "Could you find the green lounge chair?",
    ]),
    # ---------------- scan_kitchen ----------------
    (SK, "s", 3, [3], [
        "Take me to the cabinet under the sink.",
        "the cupboard directly below the sink",
        "Which base cupboard is under the basin? Go there.",
        "There's a row of lower cupboards. I want the one with the sink above it.",
        "Where do I find the under-sink cupboard? Not the upper wall ones.",
        "cupbaord under the sink",
    ]),
    (SK, "s", 25, [25], [
        "Take me to the cup on the counter.",
        "the mug sitting on the worktop, not on the table",
        "Which cup is on the kitchen counter? Go there.",
        "Two mugs are on the dining table and one on the counter. I want the counter one.",
        "the mug next to the sink on the worktop",
        "mug standing on the countertop",
    ]),
    (SK, "s", 27, [27], [
        "Take me to the bin nearest the fridge.",
        "which rubbish bin is closest to the refrigerator?",
        "trash can by the fridge",
        "There are two bins in the kitchen. I want the one beside the fridge, not the one by the door.",
        "Could you go to the garbage can next to the fridge?",
        "bin closest to the frdige",
    ]),
    (SK, "or", 17, [17, 18, 19, 20, 21, 22], [
        "Take me to a chair in the kitchen.",
        "any seat in the kitchen",
        "Could you show me one of the kitchen chairs?",
        "I want to sit in the kitchen. Any seat at the table.",
        "One of the seats round the kitchen table please, colour doesn't matter.",
        "a kitchen seat, whichever is free",
    ]),
    (SK, "ard", 11, [11], [
        "I need to heat up my leftovers quickly.",
        "My soup went cold. Where can I warm it up in a minute or two?",
        "reheat food fast",
        "I want to make popcorn the quick way. Take me to what I need.",
        "Where can I defrost this frozen bread?",
        "Could you take me to the thing that warms up a plate of food in a couple of minutes?",
    ]),
]

# (group number, typo word, correct word)
TYPOS = [
    (1, "chiar", "chair"), (3, "bwol", "bowl"), (4, "armchiar", "armchair"), (6, "breifcase", "briefcase"),
    (7, "bok", "book"), (8, "cusions", "cushions"), (10, "tabel", "table"), (12, "chiar", "chair"),
    (13, "ligth", "light"), (15, "cahir", "chair"), (20, "lmap", "lamp"), (21, "cofee", "coffee"),
    (24, "dinning", "dining"), (25, "chiar", "chair"), (26, "coffe", "coffee"), (28, "tabel", "table"),
    (29, "cuoch", "couch"), (32, "boook", "book"), (38, "snik", "sink"), (41, "plnat", "plant"),
    (42, "pitcure", "picture"), (44, "cupbaord", "cupboard"), (46, "frdige", "fridge"),
]


# ---------------- numerical checks of the spatial groups ----------------
def objects(map_string):
    data = json.loads((OUT.parent / map_string).read_text())
    return {o["id"]: o for o in data["objects"]}


def rests_on(top, base, tol=0.05):
    """top's bottom face at base's top face and top's centre inside base's footprint."""
    tz = top["center"][2] - top["size"][2] / 2
    bz = base["center"][2] + base["size"][2] / 2
    inside = all(abs(top["center"][i] - base["center"][i]) <= base["size"][i] / 2 + 1e-9 for i in (0, 1))
    return abs(tz - bz) <= tol and inside


def dist(a, b):
    return math.dist(a["center"][:2], b["center"][:2])


def checks():
    B, C, E, H = objects(FB), objects(FC), objects(FE), objects(FH)
    A, L, K = objects(APT), objects(SLR), objects(SK)
    out = []
    # g13 flat_b: facing headboard (north, +y) from the foot, right = +x; lamp 34 on nightstand 32.
    bed = B[30]
    out.append(("g13", B[30]["center"][1] - bed["size"][1] / 2 < B[34]["center"][1]
                and B[34]["center"][0] - bed["center"][0] > 0.5 and B[33]["center"][0] - bed["center"][0] < -0.5
                and rests_on(B[34], B[32])))
    # g19 flat_c: lamp 7 on side table 6; floor lamp 5 on nothing of that kind.
    out.append(("g19", rests_on(C[7], C[6]) and not rests_on(C[5], C[6])))
    # g22 flat_e: green chair nearest black chair 14 is 13, with a margin of > 0.3 m.
    d = sorted((dist(E[14], E[i]), i) for i in (11, 12, 13))
    out.append(("g22", d[0][1] == 13 and d[1][0] - d[0][0] > 0.3))
    # g28 flat_h: lamp 48 stands on nightstand 46, book 49 on 47.
    out.append(("g28", rests_on(H[48], H[46]) and not rests_on(H[48], H[47]) and rests_on(H[49], H[47])))
    # g31 flat_h: chairs 16/17 south of table 15; facing north, left = smaller x.
    out.append(("g31", H[16]["center"][1] < H[15]["center"][1] and H[17]["center"][1] < H[15]["center"][1]
                and H[17]["center"][0] - H[16]["center"][0] > 0.5
                and H[5]["center"][1] < H[15]["center"][1]))  # living room (sofa) is south
    # g32 apartment: of the living room books, 12 is higher than 13 by > 0.3 m.
    lr_books = [o for o in A.values() if o["label"] == "book" and o["room"] == "living room"]
    out.append(("g32", {o["id"] for o in lr_books} == {12, 13}
                and A[12]["center"][2] - A[13]["center"][2] > 0.3))
    # g39 scan_livingroom: pillow 3 between the red pillows 2 and 4 in x.
    out.append(("g39", L[2]["center"][0] < L[3]["center"][0] < L[4]["center"][0]
                and L[2]["tags"]["color"] == L[4]["tags"]["color"] == "red"))
    # g40 scan_livingroom: sofa faces the TV (+y); left = smaller x; lamp 10 on side table 8 (west).
    out.append(("g40", L[14]["center"][1] > L[1]["center"][1] and rests_on(L[10], L[8])
                and L[8]["center"][0] < L[1]["center"][0] - 1 and L[9]["center"][0] > L[1]["center"][0] + 1))
    # g41 scan_livingroom: plant nearest door 22 is 18 with a margin of > 1 m.
    d = sorted((dist(L[22], L[i]), i) for i in (17, 18))
    out.append(("g41", d[0][1] == 18 and d[1][0] - d[0][0] > 1.0))
    # g44 scan_kitchen: sink 10 rests on lower cabinet 3 only.
    lower = [i for i in range(1, 7) if rests_on(K[10], K[i])]
    out.append(("g44", lower == [3]))
    # g45 scan_kitchen: cup 25 rests on a counter cabinet, cups 23/24 on table 16; 25 nearest the sink.
    out.append(("g45", rests_on(K[25], K[2]) and rests_on(K[23], K[16], 0.06) and rests_on(K[24], K[16], 0.06)
                and dist(K[25], K[10]) < 0.7))
    # g46 scan_kitchen: bin nearest the fridge 13 is 27 with a margin.
    d = sorted((dist(K[13], K[i]), i) for i in (26, 27))
    out.append(("g46", d[0][1] == 27 and d[1][0] - d[0][0] > 1.0))
    return out


def main():
    assert len(GROUPS) == 48
    lines = []
    for n, (m, t, target, accept, qs) in enumerate(GROUPS, 1):
        assert len(qs) == 6 and target in accept, n
        for k, q in enumerate(qs, 1):
            lines.append(json.dumps({"id": f"b18-g{n:02d}-w{k}", "map": m, "query": q, "type": t,
                                     "target": target, "accept": accept, "group": f"b18-g{n:02d}"}))
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    for n, word, _ in TYPOS:
        assert any(word in q for q in GROUPS[n - 1][4]), (n, word)
    # ard wordings must not name the map label of the target at all
    import re
    for n, (m, t, target, accept, qs) in enumerate(GROUPS, 1):
        if t == "ard" and not m.startswith("../../../shared"):
            lab = objects(m)[target]["label"].lower()
            assert not any(re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", q.lower()) for q in qs), n
        elif t == "ard":
            lab = json.loads((OUT.parent / m).read_text())[str(target)]["category"].lower()
            assert not any(re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", q.lower()) for q in qs), n
    results = checks()
    for name, ok in results:
        print(name, "OK" if ok else "FAILED")
    print(f"wrote {len(lines)} lines to {OUT}; typos {len(TYPOS)}")
    return 0 if all(ok for _, ok in results) else 1


if __name__ == "__main__":
    raise SystemExit(main())
