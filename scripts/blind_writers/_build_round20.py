"""Writes evals/blind/round20.jsonl: 48 hand-written groups x 6 wordings (blind round 20).

Every wording below was written by hand for this round from the map contents only.
Run: python3 /work/blind20/make_round20.py
"""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FF, FH = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_f.json", "maps/flat_h.json"
SLR, SBR = "../maps/scan_livingroom.json", "../maps/scan_bedroom.json"
APT = "apartment"

# (map, type, target, accept, [6 wordings])
G = [
    # ---------------- scene_00829 (caption map) ----------------
    (C829, "o", 4, [4, 9, 32, 79, 191, 261, 263], [
        "take me to an armchair",
        "Could you bring me over to one of the big comfy armchairs?",
        "any lounge chair",
        "My back hurts from standing. Is there a cushy armchair somewhere I can sink into?",
        "I'm looking for an easy chair, any of them will do.",
        "armchiar please, whichever is closest",
    ]),
    (C829, "or", 261, [261, 263], [
        "go to an armchair in the bedroom",
        "Is there an easy chair in the bedroom? Take me to one.",
        "bedroom armchair",
        "I want to read quietly away from everyone, so one of the armchairs in the bedroom please.",
        "There are padded armchairs in the bedroom. Bring me to either of them.",
        "Which way to the bedroom lounge chairs?",
    ]),
    (C829, "od", 192, [192], [
        "take me to the pet bed",
        "Where does the dog sleep? I mean the little white and brown cushion bed for the animal.",
        "white/brown plush animal cushion",
        "This is a soft pet basket, white with brown. I need to find it to wash the cover.",
        "Could you show me the cat's bed, the fluffy two-tone one?",
        "the plush bed for the pet, not the one for people",
    ]),
    (C829, "od", 15, [15], [
        "the white bowl with the gold rim",
        "Could you take me to the dish full of sweets?",
        "candy bowl, ceramic, gold edge",
        "I've got a sweet tooth right now. Where's that white bowl with the little handle that holds the candies?",
        "Find the ceramic sweets dish for me. It's white with a golden trim.",
        "the one with sweets in it, the white china one",
    ]),
    (C829, "ord", 100, [100], [
        "the dark blue cushion in the living room",
        "Can you take me to the deep blue pillow in the lounge?",
        "living room - blue embroidered cushion",
        "My neck is stiff. I'd like that soft royal blue cushion from the living room.",
        "There is an embroidered cushion in the living room. It's a vivid deep blue. Go there.",
        "blue cusion in the sitting room",
    ]),
    (C829, "ard", 122, [122], [
        "I really need to pee",
        "Sorry, where can I relieve myself around here?",
        "need the loo, urgent",
        "I've had three coffees this morning. Please show me where I can go to the bathroom.",
        "Where's the WC?",
        "nature calls, take me to the right spot",
    ]),
    (C829, "ard", 177, [177], [
        "I'm exhausted and want to sleep for the night",
        "Where can I lie down and get a proper night's rest?",
        "somewhere to sleep tonight",
        "I've been travelling for twelve hours. Can you take me somewhere I can crash under the covers?",
        "I need a nap under a duvet, please guide me.",
        "where do I sleep?",
    ]),
    # ---------------- scene_office3 (caption map) ----------------
    (OFF3, "o", 8, [8, 13, 20, 40], [
        "take me to a pillow",
        "Could you find me a cushion? Any one is fine.",
        "cushions",
        "My lower back is aching in this seat, so bring me to one of the throw cushions please.",
        "I'd like a pillow, whichever colour.",
        "go to the nearest cushoin",
    ]),
    (OFF3, "o", 4, [4, 11, 12, 27], [
        "go to the curtains",
        "Can you take me to where the drapes hang?",
        "drapes",
        "The sun is in my eyes. Take me to the curtains so I can pull them shut.",
        "I'm after any of the window drapes, red or white.",
        "one of the curtians by the window",
    ]),
    (OFF3, "or", 7, [7, 55, 64], [
        "a desk in the rec room",
        "Could you take me to one of the desks in the recreation room?",
        "rec room work tabel",
        "I have to fill out some forms. Bring me to a writing table in the rec room.",
        "In the rec room there are a few workstations. Any of them, please.",
        "which way to a rec-room workspace?",
    ]),
    (OFF3, "od", 25, [25], [
        "the clock",
        "Where is the black wall clock with the red dot?",
        "black timepiece on the wall",
        "I've lost track of time. Take me to the black plastic thing on the wall with the red second hand that tells the time.",
        "There's a black timepiece mounted on the wall. Show me that.",
        "the wall clok, black and red",
    ]),
    (OFF3, "od", 13, [13], [
        "the navy velvet pillow",
        "Could you take me to the dark blue velvety cushion, the buttoned one?",
        "navy cushion, velvet, button in the middle",
        "I want the soft navy blue cushion. It's a bit bigger than the others and has a button.",
        "the one that's navy, not the orange or yellow ones",
        "Bring me to the velvet cushion in dark blue.",
    ]),
    (OFF3, "ord", 40, [40], [
        "the orange striped pillow in the rec room",
        "In the rec room, which cushion is orange with white and yellow stripes? Take me there.",
        "rec room: stripey orange cushion",
        "There's an orange cushion in the rec room. It's the one with stripes, not the plain one with the button.",
        "Could you go to the orange and white striped pillow in the recreation room?",
        "striped orange cushon, rec room",
    ]),
    (OFF3, "ard", 68, [68], [
        "I need to call my mother",
        "Is there anything here I can ring someone with?",
        "need to make a call",
        "My battery died and I have to let my boss know I'm late. What can I dial out on?",
        "I want to text a friend, help me find something to do that with.",
        "where can I make a quick call?",
    ]),
    # ---------------- flat_b ----------------
    (FB, "o", 5, [5, 7, 26, 33, 34], [
        "take me to a lamp",
        "Can you bring me to one of the lights? Any of them.",
        "light fixture, any",
        "It's getting dark in here. Take me to whichever lamp is closest so I can switch it on.",
        "I'm looking for a reading light, doesn't matter which room.",
        "any lmap in the flat",
    ]),
    (FB, "or", 2, [2, 3], [
        "an armchair in the living room",
        "Could you take me to one of the easy chairs in the lounge?",
        "living room single seat",
        "I want to sit on my own for a bit. One of the living room armchairs, please.",
        "There are two comfy chairs in the sitting room. Either will do.",
        "take me to a lounge recliner-type chair in the living room",
    ]),
    (FB, "ord", 34, [34], [
        "the brass lamp in the bedroom",
        "In the bedroom, could you take me to the bedside light with the brass base?",
        "bedroom, gold-base bedside light",
        "I want to read before sleeping. It's the brass bedside light in the bedroom, not the one with the fabric shade.",
        "Go to the bedroom. The light I mean has a shiny brass stand and a white shade.",
        "bedroom bedside lamp, the brass one",
    ]),
    (FB, "s", 7, [7], [
        "the lamp on the side table",
        "Could you take me to the little light sitting on top of the small side table by the sofa?",
        "table light on the white side table",
        "I want to turn on a light. It's the small one standing on the round side table, not the tall floor one.",
        "There's a small ceramic light. It sits on the side table at the east end of the sofa.",
        "the light that stands on the round side tabel",
    ]),
    (FB, "s", 21, [21], [
        "the brown dining chair farthest from the cooker",
        "Which of the two brown wooden dining chairs is further away from the stove? Take me to that one.",
        "brown seat, far side from oven",
        "I'd rather not sit near the heat. Bring me to the brown dining seat that is farther from the cooker.",
        "This is a brown wooden dining seat. It's the one away from the stove, on the east side of the table.",
        "not the white plastic one and not the brown one near the hob, the other brown one",
    ]),
    (FB, "ard", 18, [18], [
        "I'd like to boil some water for tea",
        "Where can I heat up water quickly for a cuppa?",
        "hot water for coffee",
        "I'm making instant noodles and need boiling water. Take me to what does that.",
        "I want to make a pot of tea, guide me to what I need.",
        "need to boil water fast",
    ]),
    # ---------------- flat_e ----------------
    (FE, "o", 11, [11, 12, 13, 14, 15, 28, 36, 39], [
        "take me to a chair",
        "Could you bring me to a seat? Any one in the flat.",
        "somewhere to sit, any seat",
        "My feet are killing me. Show me the nearest seat, I don't care which.",
        "I need one of the chairs, whichever you find first.",
        "any chiar",
    ]),
    (FE, "or", 11, [11, 12, 13, 14, 15], [
        "a chair in the dining room",
        "Can you take me to one of the seats around the dining table in the dining room?",
        "dining room seat",
        "Dinner's nearly ready. Bring me to any chair in the dining room.",
        "In the dining room there are several seats. Any of them is fine.",
        "dinning room, any seat",
    ]),
    (FE, "od", 14, [14], [
        "the black metal bistro chair",
        "Could you take me to the black metal seat, the one that doesn't match the others?",
        "black iron cafe-style saet",
        "I want the odd one out. It's a black metal bistro seat, not one of the green painted wooden ones.",
        "This seat is black and made of metal. It doesn't go with the rest of the set.",
        "the mismatched black chair",
    ]),
    (FE, "ord", 36, [36], [
        "the red plastic chair in the kids bedroom",
        "In the children's room, where is the little red seat?",
        "kids room - small red seat",
        "My daughter wants to do her homework. Take me to the small red plastic seat in the kids' bedroom.",
        "There's a tiny red seat in the kids bedroom. It's plastic and pulled up to the desk.",
        "red plastic stool thing in the childrens room",
    ]),
    (FE, "s", 13, [13], [
        "the green dining chair next to the black metal one",
        "Which sage green seat is right beside the black metal bistro chair? Take me to it.",
        "sage seat beside black one, north side",
        "I'd like to sit next to my son on the black seat. So the green one directly beside it, on the same side of the table.",
        "This is a sage green wooden dining seat. It's next to the black metal one on the north side of the table.",
        "green seat neighbouring the mismatched black one",
    ]),
    (FE, "ard", 33, [33], [
        "I need to dry my washing",
        "The laundry is wet. Where can I get it dry quickly?",
        "dry clothes, fast",
        "It's raining so I can't hang the sheets outside. Take me to what will dry them.",
        "My towels are damp, where can I tumble them?",
        "somewhere to dry the wet laudnry",
    ]),
    # ---------------- flat_f ----------------
    (FF, "or", 12, [12, 13, 14, 15], [
        "a chair in the kitchen",
        "Could you take me to one of the kitchen seats?",
        "kitchen seat, any",
        "I want to sit down and have my toast. Any seat in the kitchen please.",
        "There are four seats at the table in the kitchen. Take me to one.",
        "kitchen chiar",
    ]),
    (FF, "ord", 14, [14], [
        "the yellow chair in the kitchen",
        "In the kitchen, which is the mustard yellow seat? Bring me there.",
        "kitchen, mustard seat",
        "Everyone else gets the blue ones. In the kitchen I want the mustard yellow painted seat.",
        "There's a seat in the kitchen painted yellow. It's the odd one out at the table.",
        "kitchen - not the blue ones, the yellow one",
    ]),
    (FF, "od", 3, [3], [
        "the cream leather armchair",
        "Could you take me to the pale leather easy chair with rounded arms?",
        "cream leather seat, rounded arms",
        "I don't want the tartan one by the fire. Take me to the cream leather armchair instead.",
        "This is a light cream leather chair. It has soft rounded arms.",
        "the cream leather lounge chaair",
    ]),
    (FF, "s", 15, [15], [
        "the blue chair nearest the stove",
        "Of the blue ladder-back chairs, which one is closest to the range cooker? Take me there.",
        "blue seat closest to cooker",
        "I want to stay warm while I eat. Bring me to the blue dining seat nearest the range.",
        "This is a blue painted seat at the kitchen table. Of the blue ones, it's the one closest to the cooker.",
        "nearest blue seat to the oven, not the yellow one",
    ]),
    (FF, "s", 40, [40], [
        "the lamp on the writing desk",
        "Could you take me to the light that's sitting on the walnut desk in the study?",
        "light on top of study deks",
        "I'm about to write letters. Bring me to the green glass light on the desk.",
        "There's a banker's light. It stands on the old writing desk under the study window.",
        "the one on the desk, not the bedside one or the floor one",
    ]),
    (FF, "ard", 25, [25], [
        "I want to look at the stars tonight",
        "Is there anything here I could use to watch the moon up close?",
        "stargazing",
        "The sky is clear tonight and I'd love to see Saturn's rings. What should I use?",
        "I want to spot some planets, where do I go?",
        "something to see the night sky up close",
    ]),
    # ---------------- flat_h ----------------
    (FH, "o", 13, [13, 26, 32], [
        "take me to a mug",
        "Can you bring me to any cup in the flat?",
        "cups",
        "I'm thirsty. Show me where I can grab one of the cups, any of them.",
        "I need a coffee cup, whichever.",
        "any coffee cupp",
    ]),
    (FH, "or", 46, [46, 47], [
        "a nightstand in the master bedroom",
        "Could you take me to one of the bedside tables in the main bedroom?",
        "master bedroom bedside table",
        "I left my glasses by the bed. Bring me to a bedside table in the master bedroom.",
        "There are two bedside tables in the master bedroom, either is fine.",
        "bedisde table, master bedroom",
    ]),
    (FH, "od", 10, [10], [
        "the brown leather armchair",
        "Could you take me to the cognac leather club chair with the brass studs?",
        "studded leather club chair",
        "I don't want the yellow velvet one. It's the tan leather chair with the brass studs.",
        "This is a cognac-coloured leather club chair. It has little brass studs.",
        "the leather club chari",
    ]),
    (FH, "ord", 32, [32], [
        "the black mug in the study",
        "In the study, could you take me to the matte black cup with the chipped handle?",
        "study, black cup",
        "I left my coffee in the study. It's the black cup with the chip on the handle.",
        "There's a matte black cup in the study. Go to that.",
        "the chipped black cup in the office room",
    ]),
    (FH, "s", 47, [47], [
        "the nightstand with the book on it",
        "Which bedside table in the master bedroom has the paperback lying on top? Take me there.",
        "bedside table under the detective novel",
        "I want to keep reading. It's the bedside table on the east side of the double bed, where the orange novel is.",
        "This is a white bedside table. The orange paperback lies on top of it.",
        "not the one with the lamp, the one with the novel",
    ]),
    (FH, "ard", 4, [4], [
        "where do I put my house keys?",
        "I just got home. Where should I drop my keys?",
        "leave kyes",
        "I keep losing my keys. Take me to the place where everyone drops them at the door.",
        "Somewhere to toss my keyring please.",
        "where do keys go in this house?",
    ]),
    # ---------------- scan_livingroom ----------------
    (SLR, "s", 18, [18], [
        "the plant nearest the door",
        "Which houseplant is closest to the door? Take me there.",
        "greenery by the door",
        "I want to water the pot by the entrance. It's the small one near the door, not the tall one in the far corner.",
        "There's a small potted green. It stands in the corner closest to the door.",
        "the plnat closest to the door",
    ]),
    (SLR, "s", 21, [21], [
        "the window next to the door",
        "Could you take me to the window right beside the door?",
        "pane by the door, east wall",
        "It's stuffy, I want to open the one on the same wall as the door, not the one on the TV wall.",
        "This one lets the light in. It's in the east wall just next to the door.",
        "glazing beside the doorway",
    ]),
    (SLR, "s", 3, [3], [
        "the middle pillow on the sofa",
        "Could you take me to the cushion in the centre of the couch?",
        "centre cushion, sofa",
        "There are three cushions on the couch. I want the one between the two red ones.",
        "This is a yellow cushion. It sits in the middle of the couch.",
        "the cushion between the red ones",
    ]),
    # ---------------- scan_bedroom ----------------
    (SBR, "o", 2, [2, 3, 4, 5], [
        "take me to a pillow",
        "Could you bring me to one of the cushions?",
        "cushions",
        "My head hurts and I want something soft. Any of the pillows will do.",
        "I'm looking for a cushion, whichever colour.",
        "any pilow",
    ]),
    (SBR, "s", 8, [8], [
        "the lamp nearest the window",
        "Which bedside light is closest to the window? Take me to it.",
        "light closest to windw",
        "I want to read by the window. Bring me to the bedside light on that side of the bed.",
        "This is a white bedside light. It stands on the bedside table nearest the window.",
        "the light by the window, not the one by the door",
    ]),
    (SBR, "s", 5, [5], [
        "the pillow at the foot of the bed",
        "Could you take me to the cushion lying down toward the foot of the bed, away from the headboard?",
        "cushion at bottom of bed",
        "I need the cushion that slid to the end of the bed, the blue one, not the ones by the headboard.",
        "This is a small blue cushion. It's lying near the foot of the bed.",
        "the one far from the headboard",
    ]),
    # ---------------- apartment ----------------
    (APT, "or", 1, [1, 2], [
        "a sofa in the living room",
        "Could you take me to one of the couches in the living room?",
        "living room couch",
        "I want to put my feet up and watch TV. Any couch in the living room.",
        "In the lounge there's a big grey one and a small leather one. Either is fine.",
        "living room setee please",
    ]),
    (APT, "ord", 24, [24], [
        "the white chair in the kitchen",
        "In the kitchen, could you take me to the white painted dining seat with the spindle back?",
        "kitchen, white spindle-back seat",
        "I don't want the one with the green cushion. In the kitchen, bring me to the white wooden seat.",
        "There's a white painted dining seat in the kitchen. It's on the far side of the table.",
        "kitchen white chair not the brown one",
    ]),
    (APT, "s", 13, [13], [
        "the book on the bottom shelf",
        "Could you take me to the volume lying flat on the lowest shelf of the living room bookcase?",
        "lower shelf photo album",
        "I want to show the guests our holiday photos. It's the big volume lying on the bottom shelf, not the one higher up.",
        "This is a yellow photo album. It's on the lower shelf of the walnut bookcase.",
        "the lower of the two books on the living room shelves",
    ]),
    (APT, "ard", 30, [30], [
        "I want to check how I look before I go out",
        "Where can I see my whole outfit before leaving the house?",
        "last look before leaving",
        "I have a job interview in an hour. Take me somewhere to check my tie and hair on the way out.",
        "I want to fix my hair by the front door.",
        "check my reflection before heading out",
    ]),
]

TYPOS = ["armchiar", "cusion", "cushoin", "curtians", "clok", "cushon", "lmap", "tabel", "chiar", "dinning",
         "chaair", "cupp", "bedisde", "chari", "plnat", "pilow", "laudnry", "deks", "kyes", "setee", "windw",
         "saet"]


def main() -> None:
    out = Path(__file__).parent / "evals/blind/round20.jsonl"
    lines = []
    for n, (mp, typ, target, accept, words) in enumerate(G, 1):
        assert len(words) == 6 and target in accept, n
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b20-g{n:02d}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": accept, "group": f"b20-g{n:02d}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(len(G), "groups,", len(lines), "lines ->", out)


if __name__ == "__main__":
    main()
