"""Generate evals/blind/round13.jsonl (blind round 13) and check spatial groups numerically.

All wordings below were written by hand for this round. A wording that ends in " ~" carries a deliberate
typo in a noun; the marker is stripped and the line is listed in the typo report.

    python3 make_round13.py        # writes the suite, prints the spatial checks and the typo list
"""

from __future__ import annotations

import json
import math
import re
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "evals" / "blind" / "round13.jsonl"

C1 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
C2 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
AP = "apartment"
SL = "../maps/scan_livingroom.json"
SK = "../maps/scan_kitchen.json"
FB = "maps/flat_b.json"
FC = "maps/flat_c.json"

# (type, map, target, accept, [six wordings])
G = [
    # ---------------- o: every instance of a kind ----------------
    ("o", C2, 8, [8, 13, 20, 40], [
        "take me to the cushions",
        "Could you show me where the throw cushions are?",
        "cushions - any of them",
        "My back hurts on these chairs, so I'd like a pilow. Where are they? ~",
        "I'm looking for the soft cushions people lean on. There should be a few of them on the sofa.",
        "go to any of the pillows",
    ]),
    ("o", C1, 160, [160, 162, 164], [
        "take me to the folded towels",
        "Where are the stacks of bath towels kept?",
        "towel piles, folded",
        "I just got out of the shower and I'm dripping. Please bring me to a pile of towels.",
        "I need the fluffy white towels. They're folded up in neat stacks somewhere in the house.",
        "any of the folded towl stacks please ~",
    ]),
    ("o", C1, 42, [42, 197, 212, 259], [
        "take me to a book",
        "Can you find me one of the books? Any of them is fine.",
        "reading material - any volume",
        "I'm after one of the hardbacks lying around the house.",
        "Show me where the bound volumes are, whichever is nearest.",
        "I fancy a novel. Could be any of them, just bring me to one.",
    ]),
    ("o", FB, 5, [5, 7, 26, 33, 34], [
        "take me to the lihgts ~",
        "Where are the lamps in this flat?",
        "any light fixture, standing or table",
        "It's getting dark in here. Take me to one of the lamps.",
        "I want a light I can switch on. It doesn't matter which room it's in.",
        "Go to a light, whichever is closest.",
    ]),
    ("o", FC, 26, [26, 27], [
        "go to the bedside tables",
        "Could you take me to one of the bedside cabinets?",
        "nightstand, either side",
        "I put my glasses down somewhere before sleeping. Take me to the little tables beside the bed.",
        "There are two small white tables in the bedroom. They flank the bed, one on each side.",
        "either of the nighstands ~",
    ]),
    ("o", SK, 26, [26, 27], [
        "take me to the bin",
        "Where are the rubbish bins in here?",
        "garbage can - any",
        "I've got peelings in my hand. Which way to a waste bin?",
        "I need a bin. There are a couple in this kitchen, either one is fine.",
        "nearest trash can please",
    ]),
    ("o", AP, 12, [12, 13, 52], [
        "take me to the books",
        "Could you show me where there's a book?",
        "any hardcover or textbook",
        "I want something to read. Show me a volume, any of them.",
        "There are a few novels and textbooks on the shelves. Bring me to one of those.",
        "go to a bok ~",
    ]),
    ("o", SL, 2, [2, 3, 4], [
        "bring me over to the cushions",
        "Could you point me to the sofa cushions?",
        "throw cushion, any colour",
        "My neck is stiff. I'd like one of the cushions from the couch.",
        "There are three little cushions lined up on the grey sofa. Any of them will do.",
        "a pillow please",
    ]),
    # ---------------- or: a kind in a named room ----------------
    ("or", FB, 33, [33, 34], [
        "take me to a bedside light",
        "Could you show me the lamps in the bedroom?",
        "bedroom lamp",
        "I want to read in bed tonight, where are the lights in the bedroom?",
        "One of the reading lights in the bedrom. They sit on the tables either side of the bed. ~",
        "a light in the bedroom, not the living room one",
    ]),
    ("or", FC, 37, [37], [
        "take me to the plant in the study",
        "Is there a houseplant in the study? Take me there please.",
        "study - plant",
        "I want to water the greenery in the study.",
        "The potted one in the home office, not the one in the lounge.",
        "green thing in a pot, study room",
    ]),
    ("or", FC, 19, [19, 20, 21], [
        "take me to a kitchen chair",
        "Could you bring me to one of the seats around the kitchen table?",
        "seat, kitchen",
        "My feet are sore from cooking. Any chair in the kitchen will do.",
        "I want to sit down in the kitchen. Any of the dining seats, not the one in the bedroom.",
        "a dining chiar in the kitchen ~",
    ]),
    ("or", AP, 42, [42], [
        "take me to the bathroom cupboard",
        "Could you show me the cabinet in the bathroom?",
        "bathroom storage",
        "I need a fresh towel. Where's the cupboard in the bathroom?",
        "The cupboard in the bathroom, please. Not the kitchen ones.",
        "bathroom cabnet ~",
    ]),
    ("or", AP, 55, [55], [
        "take me to the plant in the office",
        "Could you bring me to the houseplant in the home office?",
        "office greenery",
        "I want to check if the office plant needs water.",
        "There's something green in a pot in the office. Take me to it.",
        "the potted one in the workroom, not the one on the bedroom dresser",
    ]),
    ("or", C1, 261, [261, 263], [
        "take me to an armchair in the bedroom",
        "Could you show me the lounge chairs in the bedroom?",
        "bedroom, comfy chair",
        "I want to sit and read in the bedroom. Any of the big cushy chairs there.",
        "The easy chairs in the bedroom. Either of the two brown ones.",
        "armchiar in the bedroom, any ~",
    ]),
    ("or", C1, 112, [112, 233], [
        "take me to the bathroom mirror",
        "Could you show me the mirrors in the bathroom?",
        "mirrror, bathroom ~",
        "I want to check my hair. Any mirror in the bathroom is fine.",
        "There's a wood-framed looking glass in the bathroom. Take me there.",
        "bathroom mirror",
    ]),
    ("or", C1, 182, [182, 250], [
        "take me to a side table in the bedroom",
        "Could you bring me to one of the little tabels in the bedroom? ~",
        "bedroom end table",
        "I need to set my mug down. Any of the small side tables in the bedroom.",
        "The low glass-topped occasional tables in the bedroom, either one.",
        "bedroom, small table",
    ]),
    # ---------------- od: one object by its look ----------------
    ("od", C2, 40, [40], [
        "take me to the striped orange cushion",
        "Could you find the orange cushion with white and yellow stripes?",
        "orange cushin, stripy one ~",
        "I like the stripy one. It's the orange pillow with white and yellow bands.",
        "the orange one with stripes, not the plain orange one with a button",
        "stripy orange cushion",
    ]),
    ("od", C2, 13, [13], [
        "take me to the navy velvet cushion",
        "Can you show me the dark blue velvety pillow?",
        "navy cushion, velvet",
        "I want the softest one. The velvet cushion in navy blue, with buttons.",
        "The blue one, a bit bigger than the others, velvet with buttons on it.",
        "not the orange or yellow ones - the navy blue one",
    ]),
    ("od", C1, 184, [184], [
        "take me to the L-shaped sofa",
        "Could you take me to the corner sofa with the chaise?",
        "L shaped couch",
        "I want to stretch out. Bring me to the sectional with the lounger end.",
        "This is a beige fabric couch. It's L-shaped with a chaise on one side.",
        "the corner settee, not the straight beige one with massage",
    ]),
    ("od", C1, 211, [211], [
        "take me to the blue bowl with gold patterns",
        "Where's the deep blue ceramic dish with gold detailing?",
        "blue and gold ornamental bowl",
        "I want to show my friend that pretty bowl. The glossy blue one with gold swirls.",
        "The decorative bowl, not the white one with the sweets.",
        "blue ceramic bowel with gold ~",
    ]),
    ("od", FB, 2, [2], [
        "take me to the yellow armchair",
        "Could you show me the mustard velvet chair?",
        "mustard armchair",
        "I want the comfy yellow seat, the velvet one.",
        "It's a yellow velvet chair. Not the brown leather one or the green one.",
        "the mustard-coloured velvet seat please",
    ]),
    ("od", FB, 22, [22], [
        "take me to the white plastic chair",
        "Could you show me the white moulded seat?",
        "white plastic seat",
        "The one that isn't wooden. It's a white moulded chair.",
        "I'm looking for a plastic seat. It's white, the odd one out at the table.",
        "the white plastic chari ~",
    ]),
    ("od", FC, 21, [21], [
        "take me to the black metal chair",
        "Could you bring me to the black metal saet? ~",
        "metal chair, black",
        "I want the sturdy seat. It's the black metal one, not the white wooden ones.",
        "This is a black metal dining seat. The others are white and wooden.",
        "the black metal one please",
    ]),
    ("od", AP, 48, [48], [
        "take me to the red leather chair",
        "Could you find the red leather swivel seat?",
        "red office chair w/ armrests",
        "I like spinning around. Take me to the red swivel seat with wheeels. ~",
        "The red one with wheels and armrests. Not the wooden dining seats.",
        "red leather office seat",
    ]),
    # ---------------- ord: look + room ----------------
    ("ord", C1, 91, [91], [
        "take me to the white sink in the bathroom",
        "Could you show me the white ceramic basin in the bathroom?",
        "bathroom basin, white ceramic",
        "I want to brush my teeth. The white ceramic washbasin in the bathroom with the touchless tap.",
        "It's a white ceramic basin with a touchless faucet. It's in the bathroom.",
        "bathroom sink, the ceramic one with the sensor tap",
    ]),
    ("ord", C1, 254, [254], [
        "take me to the pale blue-grey curtain in the bedroom",
        "Could you show me the silky blue-grey drape in the bedroom?",
        "bedroom drapes, pale blue silky",
        "I want to block out the light in the bedroom. The shimmery pale blue-grey curtain.",
        "This is a silky, pale greyish-blue drape. It hangs in the bedroom.",
        "the blue-grey curtian in the bedroom, not the one round the bed ~",
    ]),
    ("ord", C1, 191, [191], [
        "take me to the beige velvet armchair in the bathroom",
        "Could you find the cream velvet lounge chair in the bathroom?",
        "bathroom, beige velvet seat",
        "Odd place for it, but there's a beige velvety easy chair in the bathroom. Take me there.",
        "The soft beige chair with curves. It's in the bathroom, not the living room.",
        "beige velvet armcahir, bathroom ~",
    ]),
    ("ord", C2, 37, [37], [
        "take me to the black plastic chair in the rec room",
        "Could you find the black plastic seat in the rec room, the one with a speaker?",
        "rec room: black plastic chair w/ speaker",
        "I want a massage. The black plastic seat in the rec room with the built-in speaker.",
        "This is a black plastic seat, not a mesh one. It's in the rec room.",
        "black plastic seet in the games room ~",
    ]),
    ("ord", FB, 38, [38], [
        "take me to the white basin in the bathroom",
        "Could you show me the ceramic washbasin in the bathroom?",
        "bathroom sink, white",
        "I need to wash my face. The white ceramic basin in the bathroom, not the steel one in the kitchen.",
        "It's a white ceramic washbasin. It's on the west wall of the bathroom.",
        "white bathroom snik ~",
    ]),
    ("ord", FC, 31, [31], [
        "take me to the rattan chair in the bedroom",
        "Could you bring me to the wicker seat in the bedroom?",
        "bedroom, beige rattan seat",
        "I left my jumper on the rattan seat in the bedroom. Take me there.",
        "This is a beige wicker chair with clothes on it. It sits in the bedroom.",
        "beige ratan chiar in the bedroom ~",
    ]),
    ("ord", AP, 53, [53], [
        "take me to the grey metal filing cabinet in the office",
        "Could you show me the metal file drawers in the office?",
        "office: gray filing cabinet",
        "I need an old contract. The grey metal drawer unit in the office.",
        "This is a grey metal drawer unit for paperwork. It's in the office.",
        "the metal file cabnet in the study, the gray one ~",
    ]),
    ("ord", FB, 3, [3], [
        "take me to the brown leather armchair in the living room",
        "Could you show me the leather easy chair in the lounge?",
        "living room, brown leather seat",
        "I want to sit somewhere cool. The brown leather chair in the sitting room with wooden legs.",
        "This is a brown leather chair with wooden legs. It's in the living room.",
        "lounge armchar, brown leather, not the mustard one ~",
    ]),
    # ---------------- ard: need / activity, no object named ----------------
    ("ard", FB, 18, [18], [
        "I'd like to make a cup of tea.",
        "Could you take me to where I can boil some water?",
        "boil water",
        "I'm freezing, something hot to drink would help. Where can I heat water for tea?",
        "I want a cuppa. Take me to the thing that heats water quickly.",
        "need hot water for an instant coffee, fast",
    ]),
    ("ard", FC, 23, [23], [
        "I need to throw this away.",
        "Where can I get rid of some rubbish?",
        "dispose of wrapper",
        "My hands are full of orange peel. Where do I chuck it?",
        "I've got an empty can to dump. Take me somewhere I can drop it.",
        "take me where the waste goes",
    ]),
    ("ard", AP, 54, [54], [
        "I need to print my boarding pass.",
        "Could you take me to where I can get a hard copy of a document?",
        "print document",
        "My meeting notes need to be on paper. Where can I print them out?",
        "I have to sign a form, so I need a paper version of it first.",
        "take me where I can make a printout",
    ]),
    ("ard", AP, 20, [20], [
        "I want to heat up my leftovers.",
        "Could you take me somewhere to warm up this soup quickly?",
        "reheat food, quick",
        "My coffee has gone cold. Where can I zap it for a minute?",
        "I'd like to defrost some bread. Take me to something that does it in a few minutes.",
        "warm up my lunch in 2 minutes",
    ]),
    ("ard", SK, 12, [12], [
        "I need a coffee.",
        "Could you take me to where I can brew a fresh pot?",
        "brew coffee",
        "I'm half asleep. Where can I make myself something with caffeine?",
        "I want a filter coffee before work. Take me to the machine for that.",
        "take me where i can get a morning brew",
    ]),
    ("ard", C1, 177, [177], [
        "I want to lie down and sleep.",
        "Could you take me somewhere I can have a proper night's sleep?",
        "need to sleep",
        "I'm exhausted after the flight. Where can I crash for the night?",
        "I want to take a nap. Somewhere soft where I can stretch out under a duvet.",
        "take me where I can sleep tonight",
    ]),
    ("ard", C2, 25, [25], [
        "What time is it? Take me where I can check.",
        "Could you bring me to something that shows the time?",
        "check time",
        "I think I'm late for my meeting. Where can I see the time on the wall?",
        "I want to see how long until lunch. Take me to something telling the hour.",
        "show me what tells the time around here",
    ]),
    ("ard", C2, 68, [68], [
        "I need to make a call.",
        "Could you take me to something I can ring my mum with?",
        "call someone quick",
        "I have to tell the office I'm running late. Where can I dial them?",
        "I want to text a friend. Take me to the handset.",
        "take me to where I can ring a number",
    ]),
    # ---------------- s: singled out by position ----------------
    ("s", FB, 7, [7], [
        "take me to the lamp on the side table",
        "Could you show me the light sitting on the little round table by the sofa?",
        "light on white side table",
        "This is a small table lamp. It stands on the round side table at the end of the sofa.",
        "the light on top of the small table, not the tall floor one",
        "the one on the side table next to the couch",
    ]),
    ("s", FB, 31, [31], [
        "Standing at the foot of the bed, facing the headboard, take me to the nightstand on the left.",
        "Could you bring me to the bedside table on the left as you look at the bed from its foot?",
        "bedside table, left side when facing headboard",
        "Facing the bed from the end, I want the little table on my left.",
        "It's a white bedside cabinet. From the foot of the bed looking toward the pillows, it's the left one.",
        "the nightstand nearer the window",
    ]),
    ("s", FC, 20, [20], [
        "take me to the chair closest to the fridge",
        "Could you show me which dining seat is nearest the refrigerator?",
        "seat nearest fridge",
        "I want to sit close to the fridge so I can grab drinks. The chair next to it at the table.",
        "The dining seat on the fridge side of the table.",
        "the kitchen seat nearest the fridge, not the black metal one",
    ]),
    ("s", SK, 25, [25], [
        "take me to the cup on the counter",
        "Could you find the mug that's sitting next to the sink?",
        "mug by sink",
        "This is a white cup. It's on the worktop beside the sink, not on the table.",
        "the mug that isn't on the dining table",
        "the one on the kitchen counter, near the sink",
    ]),
    ("s", SK, 21, [21], [
        "take me to the chair nearest the door",
        "Which seat at the table is closest to the door? Take me there.",
        "chair closest to door",
        "I'm in a hurry to leave, so I'll sit nearest the exit. Which seat is that?",
        "The seat at the end of the table on the door side.",
        "the seat at the head of the table by the doorway, not the ones along the sides",
    ]),
    ("s", SL, 3, [3], [
        "take me to the middle cushion on the sofa",
        "Could you show me the cushion in between the two red ones?",
        "centre cushion, sofa",
        "It's a small cushon on the couch. It sits between the other two. ~",
        "the pillow in the middle of the three",
        "the cushion in the centre of the grey sofa",
    ]),
    ("s", SL, 10, [10], [
        "take me to the bigger of the two lamps on the side tables",
        "Could you show me the larger table light by the sofa?",
        "larger side-table lamp",
        "There are two small lights on the end tables by the couch. I want the bigger one.",
        "the light on the end table nearer the green armchair",
        "not the smaller one - the bigger light beside the sofa, on a side table",
    ]),
    ("s", AP, 13, [13], [
        "take me to the book on the bottom shelf",
        "Could you find the volume lying on the lowest shelf of the living room bookcase?",
        "lowest book on the lounge shelves",
        "There are two volumes on the living room bookshelf. I want the lower one.",
        "It's lying flat on the bottom shelf of the living room bookcase, below the red one.",
        "the bottom-shelf one in the living room, not the hardback higher up",
    ]),
]


def objects(map_str: str) -> dict[int, dict]:
    data = json.loads((OUT.parent / map_str).resolve().read_text())
    return {int(o["id"]): o for o in data["objects"]}


def d2(a: dict, b: dict) -> float:
    return math.dist(a["center"][:2], b["center"][:2])


def on_top(top: dict, base: dict, tol: float = 0.05) -> bool:
    (tx, ty, tz), (sx, sy, sz) = top["center"], top["size"]
    (bx, by, bz), (bsx, bsy, bsz) = base["center"], base["size"]
    inside = abs(tx - bx) <= bsx / 2 and abs(ty - by) <= bsy / 2
    return inside and abs((tz - sz / 2) - (bz + bsz / 2)) <= tol


def spatial_checks() -> list[str]:
    """Each s group re-derived from centres and sizes with a margin; returns failures."""
    fail: list[str] = []
    fb, fc, sk, sl, ap = objects(FB), objects(FC), objects(SK), objects(SL), objects(AP)
    lamps = [i for i, o in fb.items() if o["label"] == "lamp"]
    hits = [i for i in lamps if any(on_top(fb[i], o) for o in fb.values() if o["label"] == "side table")]
    if hits != [7]:
        fail.append(f"FB lamp on side table {hits}")
    # foot of bed 30 (headboard north): viewer looks +y, left = smaller x; 31 and 32 by the bed
    bed = fb[30]
    if not (fb[31]["center"][0] < bed["center"][0] - 0.5 < fb[32]["center"][0]):
        fail.append("FB left nightstand")
    if not d2(fb[31], fb[36]) + 1.0 < d2(fb[32], fb[36]):
        fail.append("FB nightstand nearer window")
    chairs = sorted((d2(o, fc[13]), i) for i, o in fc.items() if o["label"] == "chair")
    if chairs[0][1] != 20 or chairs[1][0] - chairs[0][0] < 0.5:
        fail.append(f"FC chair nearest fridge {chairs}")
    cups = [i for i, o in sk.items() if o["label"] == "cup" and not on_top(o, sk[16])]
    if cups != [25] or d2(sk[25], sk[10]) > 0.8:
        fail.append(f"SK cup off table {cups}")
    chairs = sorted((d2(o, sk[15]), i) for i, o in sk.items() if o["label"] == "chair")
    if chairs[0][1] != 21 or chairs[1][0] - chairs[0][0] < 0.5:
        fail.append(f"SK chair nearest door {chairs}")
    p = {i: sl[i]["center"] for i in (2, 3, 4)}
    if not (p[2][0] + 0.3 < p[3][0] < p[4][0] - 0.3 and abs(p[2][1] - p[3][1]) < 0.1):
        fail.append("SL middle pillow")
    vol = {i: math.prod(sl[i]["size"]) for i in (10, 11)}
    if not vol[10] > 1.3 * vol[11] or not (on_top(sl[10], sl[8]) and on_top(sl[11], sl[9])):
        fail.append(f"SL bigger lamp {vol}")
    if not d2(sl[10], sl[5]) + 1.0 < d2(sl[11], sl[5]):
        fail.append("SL lamp nearer green armchair")
    shelf = ap[11]
    inside = [i for i, o in ap.items() if o["label"] == "book"
              and abs(o["center"][0] - shelf["center"][0]) <= shelf["size"][0] / 2
              and abs(o["center"][1] - shelf["center"][1]) <= shelf["size"][1] / 2]
    if sorted(inside) != [12, 13] or not ap[13]["center"][2] + 0.4 < ap[12]["center"][2]:
        fail.append(f"AP lower book {inside}")
    return fail


def labels(map_str: str) -> dict[int, str]:
    data = json.loads((OUT.parent / map_str).resolve().read_text())
    if isinstance(data, dict) and "objects" in data:
        return {int(o["id"]): o["label"] for o in data["objects"]}
    return {int(k): v["category"] for k, v in data.items()}


def main() -> None:
    assert len(G) == 48
    rows, typos, problems = [], [], []
    for n, (typ, mp, target, accept, words) in enumerate(G, 1):
        assert len(words) == 6 and target in accept
        names = {labels(mp)[a].lower() for a in accept}
        uses = 0
        for k, w in enumerate(words, 1):
            typo = w.endswith(" ~")
            q = w[:-2] if typo else w
            rid = f"b13-g{n:02d}-w{k}"
            if typo:
                typos.append(f"{rid}: {q}")
            if any(re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", q.lower()) for lab in names):
                uses += 1
            rows.append({"id": rid, "map": mp, "query": q, "type": typ, "target": target,
                         "accept": accept, "group": f"b13-g{n:02d}"})
        if uses > (0 if typ == "ard" else 2):
            problems.append(f"b13-g{n:02d} label used {uses}x")
    OUT.write_text("".join(json.dumps(r) + "\n" for r in rows))
    print("wrote", OUT, len(rows))
    print("types", Counter(g[0] for g in G))
    print("maps", Counter(g[1] for g in G))
    print("label problems", problems)
    print("spatial failures", spatial_checks())
    print(f"typos {len(typos)} ({100 * len(typos) / len(rows):.1f}%)")
    for t in typos:
        print("  ", t)


if __name__ == "__main__":
    main()
