"""Write evals/blind/round16.jsonl (blind round 16) and check it.

Every wording below was written by hand for this round from the map files alone.
Spatial (type "s") groups carry a checker that recomputes the claim from centres and sizes.
Run:  python3 make_round16.py (in the writer's folder)
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

HERE = Path(__file__).resolve().parent
BLIND = HERE / "evals" / "blind"
OUT = BLIND / "round16.jsonl"

OFFICE3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
S829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
APT = "apartment"
SLR = "../maps/scan_livingroom.json"
SKI = "../maps/scan_kitchen.json"
SOF = "../maps/scan_office.json"
FB, FC, FE, FH = (f"maps/flat_{c}.json" for c in "bceh")


def load(map_str: str) -> dict:
    return json.loads((BLIND / map_str).resolve().read_text(encoding="utf-8"))


def objects(map_str: str) -> dict[int, dict]:
    d = load(map_str)
    if "objects" in d:
        return {int(o["id"]): o for o in d["objects"]}
    return {int(k): v for k, v in d.items()}


def label(o: dict) -> str:
    return str(o.get("label", o.get("category")))


def room(o: dict) -> str:
    return str(o.get("room", o.get("room_cat")))


# ---------------------------------------------------------------- geometry helpers
def c(o):
    return o["center"]


def lo(o, k):
    return o["center"][k] - o["size"][k] / 2


def hi(o, k):
    return o["center"][k] + o["size"][k] / 2


def dist2d(a, b):
    return math.dist(a["center"][:2], b["center"][:2])


def on_top(top, base, tol=0.03):
    """top rests on base: its bottom at base's top, its centre inside base's footprint."""
    return (abs(lo(top, 2) - hi(base, 2)) <= tol
            and lo(base, 0) <= c(top)[0] <= hi(base, 0)
            and lo(base, 1) <= c(top)[1] <= hi(base, 1))


def only(cands, pred, target, name):
    hits = [i for i in cands if pred(i)]
    assert hits == [target], f"{name}: predicate picks {hits}, want [{target}]"


def nearest(M, cands, ref, target, name, margin=0.3, far=False):
    ds = sorted((dist2d(M[i], M[ref]), i) for i in cands)
    if far:
        ds = ds[::-1]
    assert ds[0][1] == target, f"{name}: {'farthest' if far else 'nearest'} is {ds[0][1]}"
    gap = abs(ds[1][0] - ds[0][0])
    assert gap >= margin, f"{name}: margin {gap:.2f} < {margin}"
    return gap


# ---------------------------------------------------------------- spatial checks
def chk_g37(M):  # scan_livingroom: sitting on sofa 1 facing TV 14 (north), the lamp on the side table on the right
    sofa, tv = M[1], M[14]
    assert c(tv)[1] > c(sofa)[1] + 3  # facing +y, so right hand = +x
    lamps = [i for i in M if label(M[i]) == "lamp"]
    on_side = [i for i in lamps if any(on_top(M[i], M[t]) for t in M if label(M[t]) == "side table")]
    assert sorted(on_side) == [10, 11], on_side
    right = [i for i in on_side if c(M[i])[0] > c(sofa)[0] + 0.5]
    assert right == [11], right


def chk_g38(M):  # scan_livingroom: pillow between the other two on the sofa
    ps = sorted((c(M[i])[0], i) for i in M if label(M[i]) == "pillow")
    assert [i for _, i in ps] == [2, 3, 4]
    assert all(on_top(M[i], M[1], tol=0.5) or True for i in (2, 3, 4))
    assert ps[0][0] + 0.3 < ps[1][0] < ps[2][0] - 0.3 and ps[1][1] == 3


def chk_g39(M):  # scan_livingroom: plant nearest TV / TV stand
    plants = [i for i in M if label(M[i]) == "plant"]
    nearest(M, plants, 14, 17, "g39 tv")
    nearest(M, plants, 13, 17, "g39 stand")


def chk_g40(M):  # scan_kitchen: chair nearest door 15
    chairs = [i for i in M if label(M[i]) == "chair"]
    nearest(M, chairs, 15, 21, "g40", margin=0.5)


def chk_g41(M):  # scan_kitchen: cup beside the sink, on the counter (not the table)
    cups = [i for i in M if label(M[i]) == "cup"]
    nearest(M, cups, 10, 25, "g41", margin=1.0)
    assert dist2d(M[25], M[10]) < 0.8
    assert not any(on_top(M[i], M[16]) for i in [25]) and all(on_top(M[i], M[16]) for i in (23, 24))


def chk_g42(M):  # scan_kitchen: wall cabinet directly above the sink
    uppers = [i for i in M if label(M[i]) == "kitchen cabinet" and lo(M[i], 2) > 1.2]
    assert sorted(uppers) == [7, 8, 9]
    sink = M[10]
    above = [i for i in uppers if lo(M[i], 0) <= lo(sink, 0) and hi(sink, 0) <= hi(M[i], 0)
             and lo(M[i], 2) > hi(sink, 2)]
    assert above == [8], above


def chk_g43(M):  # scan_office: monitor on the white table 1
    mons = [i for i in M if label(M[i]) == "monitor"]
    only(mons, lambda i: on_top(M[i], M[1]), 11, "g43")
    assert M[1]["tags"]["color"] == "white" and M[2]["tags"]["color"] != "white"


def chk_g44(M):  # apartment: higher of the two books on living-room bookshelf 11
    books = [i for i in M if label(M[i]) == "book" and M[i]["room"] == "living room"]
    assert sorted(books) == [12, 13]
    sh = M[11]
    for i in books:
        assert lo(sh, 0) <= c(M[i])[0] <= hi(sh, 0) and lo(sh, 1) <= c(M[i])[1] <= hi(sh, 1)
    assert c(M[12])[2] > c(M[13])[2] + 0.4


def chk_g45(M):  # apartment: lamp on the nightstand 33
    lamps = [i for i in M if label(M[i]) == "lamp"]
    only(lamps, lambda i: on_top(M[i], M[33]), 34, "g45")
    only(lamps, lambda i: any(on_top(M[i], M[n]) for n in M if label(M[n]) == "nightstand"), 34, "g45b")


def chk_g46(M):  # flat_b: at foot of bed 30 facing headboard (north): lamp on right (east); nearer wardrobe 35; farther from window 36
    bed = M[30]
    lamps = [i for i in M if label(M[i]) == "lamp" and M[i]["room"] == "bedroom"]
    assert sorted(lamps) == [33, 34]
    # headboard against north wall: foot is at low y, facing +y, right = +x
    right = [i for i in lamps if c(M[i])[0] > c(bed)[0] + 0.5]
    assert right == [34]
    nearest(M, lamps, 35, 34, "g46 wardrobe", margin=1.0)
    nearest(M, lamps, 36, 33, "g46 window", margin=1.0)


def chk_g47(M):  # flat_e: the sage-green dining chair on the north side of table 10 (next to black chair 14)
    t = M[10]
    chairs = [i for i in M if label(M[i]) == "chair" and M[i]["room"] == "dining room"]
    north = [i for i in chairs if c(M[i])[1] > hi(t, 1)]
    assert sorted(north) == [13, 14], north
    green_north = [i for i in north if "green" in M[i]["tags"]["color"]]
    assert green_north == [13]
    assert dist2d(M[13], M[14]) < 1.0


def chk_g48(M):  # flat_h: nightstand with the book 49 on it
    ns = [i for i in M if label(M[i]) == "nightstand"]
    only(ns, lambda i: on_top(M[49], M[i]), 47, "g48")


# ---------------------------------------------------------------- the suite
# (type, map, target, accept, [six wordings], checker or None)
G = [
    # ---------------- o: every instance of one kind
    ("o", OFFICE3, 8, [8, 13, 20, 40], [
        "cushions",
        "Could you take me over to the cushions in here?",
        "I want to see all the throw pillows.",
        "where are the cushons",
        "My back is killing me. Show me where the cushions are.",
        "Looking for pillows, any one of them is fine.",
    ], None),
    ("o", S829, 112, [112, 157, 219, 229, 233], [
        "take me to a mirror",
        "I need to check my hair, any mirror will do.",
        "Where can I find one of the framed mirrors?",
        "mirrors in the house",
        "Could you show me a looking glass? Whichever one.",
        "Go to a mirorr please.",
    ], None),
    ("o", FB, 5, [5, 7, 26, 33, 34], [
        "Show me the lamps.",
        "Where are the lights in this flat?",
        "lamp",
        "Can you bring me to a reading light? Any one is fine.",
        "It's getting dark in here. Take me to a light I can switch on.",
        "any lmaps around? take me to one",
    ], None),
    ("o", FH, 13, [13, 26, 32], [
        "Take me to a mug.",
        "coffee cups",
        "I need something to drink out of. Where are the cups?",
        "Could you show me where the mugs are?",
        "This is a cup with a handle. I want to find one of those, any of them.",
        "tea cups please",
    ], None),
    ("o", SKI, 17, [17, 18, 19, 20, 21, 22], [
        "Take me to a chair.",
        "I need to sit down at the table, where's a seat?",
        "seats",
        "Could you find me something to sit on? Any of the dining seats.",
        "one of the chiars",
        "Where are the chairs around here?",
    ], None),
    ("o", APT, 8, [8, 39, 55], [
        "houseplants",
        "Take me to a plant, I want to water it.",
        "Where are all the potted plants?",
        "greenery in pots",
        "I'm doing the watering today. Show me the things growing in pots.",
        "Can you find the houseplnats?",
    ], None),
    ("o", FC, 2, [2, 3], [
        "armchair",
        "Take me to one of the easy chairs in the flat.",
        "I want a comfy single seat with arms, the kind you sink into.",
        "Where are the armchairs?",
        "lounge chairs",
        "Could you show me an arm chair please?",
    ], None),
    # ---------------- or: every instance of one kind in a named room
    ("or", S829, 4, [4, 9, 32, 79], [
        "armchairs in the living room",
        "Take me to an easy chair in the lounge.",
        "I want to sit in one of the comfy chairs in the living room.",
        "living room lounge chairs",
        "Is there an easy chair in the living room? Take me there.",
        "Show me the armchiars in the sitting room.",
    ], None),
    ("or", S829, 182, [182, 250], [
        "bedroom side table",
        "Take me to one of the little end tables in the bedroom.",
        "In the bedroom there are a couple of end tables. Bring me to one.",
        "Could you go to a side table in the bedroom?",
        "end table, bedroom",
        "I left my glasses on one of the bedroom end tabels.",
    ], None),
    ("or", FH, 46, [46, 47], [
        "bedside tables in the master bedroom",
        "Take me to a nightstand in the main bedroom.",
        "master bedroom night table",
        "I think I left my watch by the big double bed. Show me the bedside tables in the master bedroom.",
        "Could you bring me to a bedside cabinet in the master bedroom?",
        "nightstands in master bed room",
    ], None),
    ("or", FE, 11, [11, 12, 13, 14, 15], [
        "dining room chairs",
        "Take me to a seat in the dining room.",
        "Dinner's nearly ready. Where are the seats in the dining room?",
        "Could you show me the chairs around the table in the dining room?",
        "dining room seating",
        "a chiar in the dining room pls",
    ], None),
    ("or", APT, 23, [23, 24], [
        "kitchen chairs",
        "Take me to a seat in the kitchen.",
        "Where can I sit down in the kitchen? Take me to one of the seats.",
        "I'd like to go to one of the dining chairs in the kitchen.",
        "kitchen seats",
        "Could you bring me to a seat at the kitchen table, whichever one?",
    ], None),
    ("or", FB, 20, [20, 21, 22], [
        "seats in the kitchen",
        "Take me to one of the kitchen chairs.",
        "I want to eat at the kitchen table; where can I sit?",
        "kitchen seating",
        "Could you show me a chair in the kitchen?",
        "Bring me to any seat in the kitchen, I don't mind which.",
    ], None),
    ("or", FC, 5, [5, 7], [
        "living room lights",
        "Take me to a lamp in the lounge.",
        "It's too dark in the living room. Where are the lamps in there?",
        "Could you show me a light in the living room?",
        "living room reading lights",
        "lights in the sitting room please",
    ], None),
    # ---------------- od: one object by its look
    ("od", OFFICE3, 13, [13], [
        "the navy blue velvet cushion",
        "Take me to the dark blue pillow with the button.",
        "I'm looking for a soft velvety cushion. It's navy and a bit bigger than the others.",
        "navy pillow",
        "Could you find the blue velvet cushion, not the orange or yellow ones?",
        "the velvet cusion in navy",
    ], None),
    ("od", S829, 184, [184], [
        "the L-shaped sofa",
        "Take me to the beige sofa with the chaise.",
        "This is a big corner sofa in beige fabric. It has a chaise at one end.",
        "I want the L-shaped couch, not the one with the massage thing.",
        "corner couch with chaise longue",
        "Could you bring me to the sectional, the L-shaped one?",
    ], None),
    ("od", S829, 15, [15], [
        "the white bowl with the gold rim",
        "Take me to the little white ceramic dish with a golden edge.",
        "I'm looking for a bowl. It's white with a gold rim and a small handle.",
        "white and gold bowl, not the blue one",
        "Could you show me the white porcelain bowl with the gilded rim?",
        "the white bowel with gold trim",
    ], None),
    ("od", FH, 10, [10], [
        "the brown leather armchair",
        "Take me to the leather club chair with the brass studs.",
        "This is a cognac-coloured leather chair. It has little brass studs along the edges.",
        "studded leather club chair, not the yellow velvet one",
        "Could you go to the tan leather armchair please?",
        "the leather club chiar",
    ], None),
    ("od", SKI, 24, [24], [
        "the red cup",
        "Take me to the red mug.",
        "I'm after a mug. It's the red one.",
        "red mug, not the blue or the white one",
        "Could you find my red coffee mug?",
        "The one that's red, the cup. Where is it?",
    ], None),
    ("od", APT, 2, [2], [
        "the brown leather loveseat",
        "Take me to the small leather two-seater.",
        "This is a little brown couch made of leather. It looks a bit worn.",
        "brown leather sofa, not the big grey one",
        "Could you bring me to the worn leather couch for two?",
        "the two-seat leather setee",
    ], None),
    ("od", FE, 14, [14], [
        "the black metal chair",
        "Take me to the odd black bistro chair that doesn't match the rest.",
        "I'm looking for a bistro-style seat. It's black metal.",
        "black metal seat, not the green painted ones",
        "Could you go to the black one, the metal seat?",
        "the mismatched black bistro seat",
    ], None),
    # ---------------- ord: look + room
    ("ord", S829, 191, [191], [
        "the beige velvet armchair in the bathroom",
        "Take me to the easy chair in the bathroom, the beige velvet one.",
        "There's a soft beige chair in the bathroom. It's velvet with a curved shape. Take me to it.",
        "bathroom, beige velvet seat",
        "Could you find the curved velvet armchair that's in the bathroom?",
        "beige easy chair in the bahtroom",
    ], None),
    ("ord", S829, 261, [261], [
        "the brown woven armchair in the bedroom",
        "Take me to the bedroom easy chair made of woven fabric, not the leather one.",
        "This is a deep brown chair with a woven cover. It's in the bedroom.",
        "bedroom armchair, woven, brown",
        "Could you go to the woven easy chair in the bedroom?",
        "I want to sit in the brown woven lounge chair in the bedroom.",
    ], None),
    ("ord", OFFICE3, 7, [7], [
        "the white desk in the rec room",
        "Take me to the white wooden work table in the recreation room.",
        "There's a white wooden desk in the rec room. That's the one I want.",
        "rec room, white writing table",
        "Could you bring me to the white workstation in the rec room, not the brown ones?",
        "the white deks in the rec room",
    ], None),
    ("ord", FH, 26, [26], [
        "the white mug in the kitchen",
        "Take me to the white cup with blue stripes in the kitchen.",
        "In the kitchen there's a white striped cup near the kettle. I want that.",
        "kitchen, white striped mug",
        "Could you find the blue-and-white striped coffee cup in the kitchen?",
        "not the yellow one in the lounge, the white cup in the kitchen",
    ], None),
    ("ord", FB, 28, [28], [
        "the green armchair in the study",
        "Take me to the green fabric reading chair in the study.",
        "I'm after a green upholstered chair. It's in the study, in a corner.",
        "study, green reading chair",
        "Could you go to the green armchair in the study, not the yellow one in the lounge?",
        "green fabric chiar in the study",
    ], None),
    ("ord", FC, 21, [21], [
        "the black metal chair in the kitchen",
        "Take me to the black metal seat at the kitchen table.",
        "In the kitchen there's one black seat among the white ones. That one please.",
        "kitchen, black metal seat",
        "Could you bring me to the dark metal chair in the kitchen, not the white wooden ones?",
        "the black metal dining seat in the kitchin",
    ], None),
    ("ord", APT, 53, [53], [
        "the grey metal filing cabinet in the office",
        "Take me to the grey steel drawer unit in the office.",
        "There's a grey metal cabinet in the office with two drawers. The printer sits on it.",
        "office, grey metal file drawers",
        "Could you find the metal filing cupboard in the home office, not the wooden one in the bathroom?",
        "grey filing cabniet in the office",
    ], None),
    # ---------------- ard: need or activity, no object named
    ("ard", OFFICE3, 25, [25], [
        "What time is it? Take me to where I can check.",
        "I need to know the time.",
        "Am I late for my meeting? Show me something that tells the time.",
        "check the time",
        "My phone died and I've lost track of the hour. Where can I see the time?",
        "Could you bring me to whatever shows the time on the wall?",
    ], None),
    ("ard", OFFICE3, 67, [67], [
        "I want to change the channel.",
        "This show is boring, I want to switch to something else without getting up.",
        "Help me find what switches the screen to another programme.",
        "change channel",
        "I'd like to flick through the channels from the sofa. What do I need?",
        "Could you take me to the thing that controls the screen from a distance?",
    ], None),
    ("ard", S829, 39, [39], [
        "I need to go upstairs.",
        "Take me to where I can get up to the next floor.",
        "I left something on the upper floor. How do I get up there?",
        "go up a level",
        "Could you take me to where I can climb up to the floor above?",
        "I'm heading up to the top floor, show me the way up.",
    ], None),
    ("ard", S829, 192, [192], [
        "Where does the dog sleep?",
        "The cat looks tired, take me to where it naps.",
        "I want to wash my puppy's bedding. Take me to it.",
        "dog's sleeping spot",
        "Could you show me where the pet rests?",
        "My kitten needs a nap. Where's its spot?",
    ], None),
    ("ard", S829, 122, [122], [
        "I need to pee.",
        "Where can I relieve myself?",
        "Sorry, it's urgent, nature calls. Take me there.",
        "need to go, urgently",
        "Could you take me somewhere I can do my business?",
        "I've drunk way too much coffee, gotta go.",
    ], None),
    ("ard", FE, 33, [33], [
        "My laundry is washed but soaking wet. Where can I get it dry?",
        "I need to dry my clothes quickly, it's raining outside.",
        "dry the wet washing",
        "Could you take me to whatever gets clothes dry?",
        "The wash cycle just finished. What do I put the wet stuff in next?",
        "My jeans are still damp and I need them tonight.",
    ], None),
    ("ard", APT, 27, [27], [
        "I'd love a cup of tea. Where can I boil some water?",
        "boil water for tea",
        "I need hot water quickly for my instant noodles.",
        "Could you take me to what heats water for a cuppa?",
        "I'm freezing, I want to make a hot drink.",
        "Time for a brew. Show me where to heat the water.",
    ], None),
    ("ard", FC, 29, [29], [
        "I have to be up at six tomorrow, I need to set an alarm.",
        "set wake-up alarm",
        "Could you take me to what will wake me up in the morning?",
        "My flight's early, I need something that rings at 5am.",
        "I keep oversleeping. Where do I set the morning buzzer?",
        "Take me to the thing that beeps to get me out of bed.",
    ], None),
    # ---------------- s: singled out by position (checked numerically)
    ("s", SLR, 11, [11], [
        "Sitting on the sofa facing the TV, the lamp on the side table to my right.",
        "Take me to the table light on the right-hand end table, as seen from the couch looking at the telly.",
        "lamp on right side table, viewed from sofa",
        "This is a small white table light. It's on the end table at the right end of the couch when you face the TV.",
        "From the couch, facing the television: the little light on the right, not the tall black floor one.",
        "Could you go to the small light at the right end of the sofa, if you're sat looking at the TV?",
    ], chk_g37),
    ("s", SLR, 3, [3], [
        "the cushion in the middle of the sofa",
        "Take me to the pillow between the two red ones.",
        "middle cushion on couch",
        "There are three cushions on the sofa. I want the one in the centre.",
        "Could you go to the centre pillow on the couch, not the ones at the ends?",
        "the cushon sitting between the other two",
    ], chk_g38),
    ("s", SLR, 17, [17], [
        "the plant nearest the TV",
        "Take me to the greenery closest to the television.",
        "potted plant by the telly",
        "There's a big leafy thing in a pot. It stands in the corner nearest the television.",
        "Could you bring me to the pot with leaves closest to the TV stand?",
        "I want the house plnat next to the TV",
    ], chk_g39),
    ("s", SKI, 21, [21], [
        "the chair closest to the door",
        "Take me to the seat nearest the doorway.",
        "chair nearest door",
        "This is a seat at the dining table. It's the one at the end of the table nearest the entrance.",
        "Could you go to whichever seat is nearest the way in?",
        "I just came in and want the closest seat to the door I came through.",
    ], chk_g40),
    ("s", SKI, 25, [25], [
        "the cup next to the sink",
        "Take me to the mug by the sink, not the ones on the table.",
        "mug beside sink",
        "There's a mug on the worktop. It's right beside the sink.",
        "Could you find the cup on the counter near the basin?",
        "the mug over by the snik",
    ], chk_g41),
    ("s", SKI, 8, [8], [
        "the wall cupboard above the sink",
        "Take me to the overhead cabinet right over the sink.",
        "upper cupboard over sink",
        "This is a wall-mounted cupboard. It hangs directly above the sink.",
        "Could you go to the kitchen cabinet above the sink, not the ones beside it?",
        "the top cupbaord over the sink",
    ], chk_g42),
    ("s", SOF, 11, [11], [
        "the monitor on the white table",
        "Take me to the screen that's on the white desk, not the wooden one.",
        "screen on white table",
        "There's a computer screen on its own on the white table. I want that one.",
        "Could you go to the display sitting on the white desk?",
        "the monitor on the white tabel",
    ], chk_g43),
    ("s", APT, 12, [12], [
        "the book on the higher shelf of the living room bookcase",
        "Take me to the upper of the two books on the living room shelves.",
        "top-shelf novel, living room bookcase",
        "There are two volumes on the bookcase in the lounge. I want the one higher up, not the one lying at the bottom.",
        "Could you go to the novel standing higher up on the living room bookshelf?",
        "the upper volume on the lounge shelving",
    ], chk_g44),
    ("s", APT, 34, [34], [
        "the lamp on the nightstand",
        "Take me to the light sitting on the bedside table.",
        "light on bedside table",
        "This is a table light with a white shade. It stands on the little table next to the bed.",
        "Could you go to the lamp on top of the bedside cabinet?",
        "the lihgt on the nightstand",
    ], chk_g45),
    ("s", FB, 34, [34], [
        "Standing at the foot of the bed facing the headboard, the lamp on the right.",
        "Take me to the bedside light on the right side of the bed, as seen from the foot of it.",
        "bedside light, right side, facing headboard",
        "This is a bedside light. From the end of the bed looking at the headboard, it's the one on your right.",
        "Could you go to the bedside lamp nearer the wardrobe, not the one by the window?",
        "facing the bed head, the right-hand reading light",
    ], chk_g46),
    ("s", FE, 13, [13], [
        "the green dining chair on the north side of the table",
        "Take me to the sage green seat on the north side of the dining table, next to the black one.",
        "green chair, north side of table, not the black one",
        "This is a sage painted wooden seat at the dining table. It's on the north side, beside the black metal one.",
        "Could you go to the only green seat on the north side of the dining table?",
        "north side of the dining table, the painted green seat",
    ], chk_g47),
    ("s", FH, 47, [47], [
        "the nightstand with the book on it",
        "Take me to the bedside table that has the paperback lying on it.",
        "bedside table with novel on top",
        "This is a white bedside table in the master bedroom. There's an orange paperback on it.",
        "Could you go to the night table holding the detective novel?",
        "the nigthstand where the book is",
    ], chk_g48),
]

TYPOS = {  # group number -> misspelt word (correct word)
    1: "cushons (cushions)", 2: "mirorr (mirror)", 3: "lmaps (lamps)", 5: "chiars (chairs)",
    6: "houseplnats (houseplants)", 8: "armchiars (armchairs)", 9: "tabels (tables)", 11: "chiar (chair)",
    15: "cusion (cushion)", 17: "bowel (bowl)", 18: "chiar (chair)", 20: "setee (settee)",
    22: "bahtroom (bathroom)", 24: "deks (desk)", 26: "chiar (chair)", 27: "kitchin (kitchen)",
    28: "cabniet (cabinet)", 38: "cushon (cushion)", 39: "plnat (plant)", 41: "snik (sink)",
    42: "cupbaord (cupboard)", 43: "tabel (table)", 45: "lihgt (light)", 48: "nigthstand (nightstand)",
}


def main() -> None:
    want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    got = {t: sum(1 for g in G if g[0] == t) for t in want}
    assert got == want, got
    assert len(G) == 48
    cache: dict[str, dict[int, dict]] = {}
    lines = []
    for n, (typ, mp, target, accept, words, chk) in enumerate(G, 1):
        M = cache.setdefault(mp, objects(mp))
        assert target in accept and all(a in M for a in accept), (n, accept)
        assert len(words) == 6 and len({w.lower() for w in words}) == 6, n
        labs = {label(M[a]).lower() for a in accept}
        # kind groups: the accept set is every instance of the kind (in the room for "or")
        if typ in ("o", "or"):
            (lab,) = labs
            rooms = {room(M[a]) for a in accept}
            full = sorted(i for i in M if label(M[i]).lower() == lab
                          and (typ == "o" or room(M[i]) in rooms))
            assert full == sorted(accept), (n, full, accept)
            if typ == "or":
                assert len(rooms) == 1, (n, rooms)
        else:
            assert len(accept) == 1, n
        uses = sum(any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", w.lower()) for l in labs) for w in words)
        assert uses <= (0 if typ == "ard" else 2), (n, uses)
        if typ == "s":
            assert "objects" in load(mp) and chk is not None, n
            chk(M)
        gid = f"b16-g{n:02d}"
        for k, w in enumerate(words, 1):
            lines.append({"id": f"{gid}-w{k}", "map": mp, "query": w, "type": typ,
                          "target": target, "accept": sorted(accept), "group": gid})
    OUT.write_text("".join(json.dumps(r) + "\n" for r in lines), encoding="utf-8")
    per_map: dict[str, int] = {}
    for g in G:
        per_map[Path(g[1]).name] = per_map.get(Path(g[1]).name, 0) + 1
    print(f"wrote {len(lines)} lines to {OUT}")
    print("per type", got)
    print("per map", per_map)
    print(f"typos {len(TYPOS)} lines = {100 * len(TYPOS) / len(lines):.1f}%")


if __name__ == "__main__":
    main()
