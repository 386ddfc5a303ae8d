"""Write evals/blind/round12.jsonl: 48 groups x 6 hand-written wordings (blind round 12).

Every wording below was written by hand for this round, reading only the map files named in BRIEF.md.
Run:  python3 /work/blind12/make_round12.py   (then check_round12_spatial.py and validate.py)
"""

import json
from pathlib import Path

OUT = Path(__file__).parent / "evals" / "blind" / "round12.jsonl"

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
FB, FC, FD, FE, FG = (f"maps/flat_{x}.json" for x in "bcdeg")
SLR, SKI, SBE, SOF = (f"../maps/scan_{x}.json" for x in ("livingroom", "kitchen", "bedroom", "office"))

# (map, type, target, accept, [6 wordings])
G = [
    # ---------------- scene_00829 (caption map, no geometry) ----------------
    (C829, "o", 160, [160, 162, 164, 125], [
        "Where do you keep the towels?",
        "I just showered and I'm dripping wet, could you take me to some towels?",
        "towles pls",
        "Take me to a towel, please.",
        "Could you show me where the fluffy white towels are? Any of them is fine.",
        "These are soft white cotton things you dry your hands or body with. Take me to any of them.",
    ]),
    (C829, "or", 261, [261, 263], [
        "Take me to an easy chair in the bedroom.",
        "Is there a comfy armchair in the bedroom I could sit in?",
        "bedroom armchair",
        "I want to read for a bit. Which of the big brown lounge chairs are in the bedroom? Take me to one.",
        "Could you bring me to one of the recliner-type seats in the bedroom, not the ones in the living room?",
        "Bedroom, easy chiar, whichever is closer.",
    ]),
    (C829, "od", 211, [211], [
        "Take me to the deep blue ceramic bowl with the gold patterns.",
        "the blue and gold ornamental dish",
        "Where's that glossy blue bowl, the decorative one? Not the white one with the sweets.",
        "It's a bowl. It is dark blue with gold-tinged decorations and looks like it's just for show.",
        "Could you show me the cobalt blue ceramic piece with the gold trim?",
        "blue decorative bowl, the fancy one",
    ]),
    (C829, "ord", 259, [259], [
        "Take me to the dark brown leather book in the bedroom.",
        "In the bedroom there's a leather-bound volume with gold lettering on the cover. Where is it?",
        "bedroom, brown leather bok",
        "I left my leather notebook-looking volume in the bedroom, the dark one with the embossed cover. Can you find it?",
        "This is a dark leather hardback with a gold-embossed cover. It's in the bedroom, not the living room.",
        "Could you lead me to the brown leather-bound book that's in the bedroom?",
    ]),
    (C829, "ard", 122, [122], [
        "I really need to pee.",
        "Sorry, where can I relieve myself?",
        "I've been drinking coffee all morning and I urgently need to go. Where should I go?",
        "need to go number two",
        "My kid needs to do a wee, quick, take us there.",
        "Where can I flush something away and do my business?",
    ]),
    (C829, "ard", 192, [192], [
        "Where does the dog sleep?",
        "My puppy is tired and needs somewhere cosy to curl up. Take me there.",
        "the cat wants a nap, where's its spot",
        "Can you show me where our pet usually snoozes?",
        "I brought the dog's blanket back. Where does he lie down at night?",
        "spot for the dog to rest",
    ]),
    (C829, "od", 265, [265], [
        "Take me to the black leather briefcase.",
        "Where's the black leather case with the metal lock? Not the backpack.",
        "the leather work case with the lock",
        "It's a black leather bag, the stiff businesslike one with a metal clasp that locks. Where is it?",
        "Could you find my black leather attache case?",
        "black breifcase with lock",
    ]),
    # ---------------- scene_office3 (caption map, no geometry) ----------------
    (OFF3, "o", 8, [8, 13, 20, 40], [
        "Take me to a cushion.",
        "Where are the pillows?",
        "Could you show me the throw cushions? Any colour will do.",
        "My back hurts from sitting. I'd like something soft to put behind me; take me to one of the cushions.",
        "pilows",
        "I'm looking for the soft puffy things on the couch, any of them, orange, yellow or blue.",
    ]),
    (OFF3, "or", 7, [7, 55, 64], [
        "Take me to a desk in the rec room.",
        "Where are the work desks in the rec room?",
        "rec room workstation",
        "I need to fill in a form sitting down. Could you bring me to one of the workstations in the rec room?",
        "Is there a work surface in the recreation room I can use? Any of them.",
        "Rec room: the workstations with USB ports, any one is fine.",
    ]),
    (OFF3, "od", 13, [13], [
        "Take me to the navy blue velvet pillow.",
        "the dark blue velvety cushion with the button",
        "Where's the navy cushion? Not the orange or yellow ones.",
        "It's a cushion. It's soft navy velvet, buttoned, and a bit bigger than the others.",
        "Could you show me the big velvet cushion in dark blue?",
        "navy blue cusion",
    ]),
    (OFF3, "ord", 42, [42], [
        "Take me to the brown leather chair in the rec room.",
        "In the rec room there is one seat that's dark brown leather instead of black mesh. Where is it?",
        "rec room, brown leather seat",
        "I don't like mesh. Can you find me the brown leather armless seat in the rec room?",
        "This is a chair. It's the only brown leather one and it stands in the rec room.",
        "Could you bring me to the dark brown leather chiar in the recreation room?",
    ]),
    (OFF3, "ard", 25, [25], [
        "What time is it? I need to check.",
        "I've lost track of time; take me to something that shows the time on the wall.",
        "need to see the time",
        "Is there anything in here that tells the hour? My phone is dead.",
        "Before my meeting I want to check how late it is. Where can I look?",
        "I keep missing the bus; show me where I can see the time.",
    ]),
    # ---------------- flat_b ----------------
    (FB, "o", 5, [5, 7, 26, 33, 34], [
        "Take me to a lamp.",
        "Where are the lights in this flat? Any one will do.",
        "lmap",
        "It's dark over here; I'd like to switch on a light. Bring me to the nearest one, any kind.",
        "Could you show me one of the lamps? Floor, desk or bedside, doesn't matter.",
        "Any of the lights you can switch on by hand: reading light, floor light, bedside light.",
    ]),
    (FB, "or", 33, [33, 34], [
        "Take me to a lamp in the bedroom.",
        "Which bedside lights are there? Either one is fine.",
        "bedroom reading light",
        "I want to read in bed. Could you take me to one of the bedroom lights?",
        "Is there a light next to the bed? Either side.",
        "bedroom lights, any",
    ]),
    (FB, "od", 2, [2], [
        "Take me to the mustard yellow velvet armchair.",
        "the yellow velvet chair",
        "Where's the yellow armchair? Not the brown leather one or the green one.",
        "It's a single seat with arms. It's upholstered in mustard velvet and sits by a window.",
        "Could you bring me to the velvety yellow seat?",
        "yellow velvet armchiar",
    ]),
    (FB, "s", 7, [7], [
        "Take me to the lamp that stands on the side table.",
        "the light on the little round table by the sofa",
        "Which light is sitting on top of the white table at the sofa's east end? Not the tall floor one.",
        "This is a small ceramic light. It stands on the side table next to the sofa.",
        "Could you bring me to the little light that rests on the side table in the living room?",
        "lamp on top of the side table",
    ]),
    (FB, "s", 21, [21], [
        "Take me to the kitchen chair farthest from the stove.",
        "Which dining seat is the furthest away from the cooker?",
        "chair farthest from cooker",
        "I don't want to sit near the hot oven. Bring me to the seat at the table that is as far as possible from it.",
        "This is one of the wooden dining seats. It's the one furthest from the cooker.",
        "Of the seats round the kitchen table, the one most distant from the hob, please.",
    ]),
    # ---------------- flat_c ----------------
    (FC, "o", 10, [10, 37], [
        "Take me to a plant.",
        "Where are the houseplants? Any one of them.",
        "I want to water the greenery. Could you show me where the pots with leaves are?",
        "potted plnat",
        "Is there anything green growing in a pot around here?",
        "The monstera or the snake plant, whichever, take me to one of the plants.",
    ]),
    (FC, "or", 19, [19, 20, 21], [
        "Take me to a chair in the kitchen.",
        "Where can I sit down in the kitchen? Any of the seats at the table.",
        "kitchen seat",
        "I'm going to eat. Could you take me to one of the seats round the kitchen table?",
        "Any kitchen chiar, I don't mind which.",
        "Is there a free seat at the dining table in the kitchen? Any one.",
    ]),
    (FC, "ord", 28, [28], [
        "Take me to the pink lamp in the bedroom.",
        "the bedside light with the pink shade",
        "In the bedroom there's a lamp with a pink fabric shade. Where is it?",
        "I'd like to read in bed. Could you take me to the pink bedside light?",
        "It's a reading light. It has a pink cloth shade and stands by the bed.",
        "bedroom, pink lampshade",
    ]),
    (FC, "s", 27, [27], [
        "Take me to the nightstand with the alarm clock on it.",
        "Which bedside table has the red clock on top?",
        "nightstand under alarm clock",
        "My alarm keeps going off. Bring me to the bedside table it's sitting on.",
        "This is a white bedside table. The red alarm clock is standing on it.",
        "Lying in bed, it's the bedside table on my left, the one the clock sits on, not the one with the lamp.",
    ]),
    # ---------------- flat_d ----------------
    (FD, "or", 4, [4, 5, 7], [
        "Take me to a chair in the studio.",
        "Is there a seat in the studio? Any of them.",
        "studio seat",
        "I need to sit for a minute. Could you bring me to any of the chairs in the studio, not the kids' one?",
        "Where can I sit in the main studio room? The desk seat or a dining seat, whichever.",
        "any seat in the studio",
    ]),
    (FD, "od", 22, [22], [
        "Take me to the wooden stool.",
        "the wooden bar seat with the round top",
        "Where's the wooden stool? Not the black metal one.",
        "It's a backless seat. It's made of wood and has a round top.",
        "Could you show me the round wooden perch in the kitchenette?",
        "wooden stol",
    ]),
    (FD, "ord", 33, [33], [
        "Take me to the green plastic chair in the kids room.",
        "the little green kid's seat in the children's room",
        "In the kids' room there's a small green plastic seat at the desk. Where is it?",
        "My daughter left her book on her little seat. Could you take me to the small green one in her room?",
        "This is a tiny plastic chair. It's green and it's in the kids room at the yellow desk.",
        "kids room, green plastic chiar",
    ]),
    (FD, "ard", 27, [27], [
        "My shirt is all creased, I need to press it.",
        "Where can I get the wrinkles out of my trousers?",
        "need to do some ironing",
        "I have an interview in an hour and my blouse is crumpled. Take me to where I can smooth it out.",
        "Could you take me to where I can press my clothes flat?",
        "press shirt before work",
    ]),
    (FD, "s", 21, [21], [
        "Take me to the stool that's nearer the hob.",
        "which bar seat is closest to the cooktop",
        "stool nearest stove",
        "I want to sit where I can keep an eye on the pan. Bring me to the high seat closest to the cooking rings.",
        "This is a high seat in the kitchenette. It's the one closer to the induction hob, not the one on the fridge side.",
        "The kitchenette perch on the cooker side, please, not the other one.",
    ]),
    # ---------------- flat_e ----------------
    (FE, "o", 7, [7, 29], [
        "Take me to a mirror.",
        "Where can I check my reflection? Any mirror will do.",
        "mirorr",
        "I have something on my face, I think. Could you bring me to a looking glass?",
        "Is there a looking glass in this flat? The round one or the bathroom one, whichever.",
        "I want to fix my hair; show me where I can see myself.",
    ]),
    (FE, "od", 14, [14], [
        "Take me to the black metal chair.",
        "the bistro-style seat that doesn't match the green ones",
        "Where's the odd one out at the dining table, the black metal one?",
        "It's a chair. It's black metal, café style, and unlike the painted wooden ones.",
        "Could you show me the dark metal seat, not one of the sage green ones?",
        "black metal chiar",
    ]),
    (FE, "ord", 36, [36], [
        "Take me to the red plastic chair in the kids bedroom.",
        "the small red kid's seat in the children's room",
        "In the kids' bedroom there's a little red plastic seat by the desk. Where is it?",
        "My son wants to do homework; could you take me to his little red seat in his room?",
        "This is a small kid-sized seat. It's red plastic and it's in the kids' bedroom.",
        "kids bedroom, red plastic seat",
    ]),
    (FE, "ard", 15, [15], [
        "The baby's hungry, where do I sit her to feed her?",
        "I need somewhere to put my toddler for lunch.",
        "somewhere to seat the baby at meals",
        "My one-year-old is too small for a normal seat. Where can she sit at the dining table?",
        "Could you show me where the little one eats?",
        "feeding time for the baby, where does she go",
    ]),
    (FE, "s", 13, [13], [
        "Take me to the green chair on the north side of the dining table.",
        "the green dining seat right next to the black metal one",
        "Of the sage green seats, which one is on the far side of the table, beside the black one?",
        "This is a sage green painted seat at the dining table. It's on the north side, next to the black bistro one.",
        "Looking at the dining table from the south, I want the green seat on the far side, next to the mismatched black one.",
        "green seat north side of table",
    ]),
    # ---------------- flat_g ----------------
    (FG, "or", 42, [42], [
        "Take me to the bed in the kids room.",
        "Where does the children's bunk bed stand?",
        "kids room bunk",
        "The kids are going to sleep. Could you bring me to their bunks?",
        "Is there a place to sleep in the kids' room? Take me there.",
        "the childrens bunks, kids room",
    ]),
    (FG, "ord", 34, [34], [
        "Take me to the teal glass lamp in the bedroom.",
        "the bedside light with the teal base",
        "In the bedroom, the light with the turquoise glass base, not the beige ceramic one. Where is it?",
        "I want to turn on the teal light by the bed. Could you take me there?",
        "This is a bedside lamp. It has a teal glass base with a white shade and it's in the bedroom.",
        "bedroom teal lmap",
    ]),
    (FG, "ard", 5, [5], [
        "I need a screwdriver and a spanner to fix the bike.",
        "Where are the tools kept?",
        "need a hammer",
        "The shelf came loose and I have to tighten a few screws. Take me to where the tools are.",
        "Could you show me where I can find a wrench?",
        "fixing something, need pliers",
    ]),
    (FG, "s", 41, [41], [
        "Take me to the mirror above the washbasin.",
        "the looking glass over the bathroom sink",
        "Which one hangs directly over the sink? Not the tall full-length one in the hall.",
        "This is a round looking glass. It hangs on the wall right above the washbasin.",
        "I want to brush my teeth and look at myself. Bring me to the glass over the basin.",
        "mirror above sink",
    ]),
    # ---------------- scan maps ----------------
    (SLR, "od", 3, [3], [
        "Take me to the yellow pillow.",
        "the yellow cushion on the sofa",
        "Where's the yellow cushion? Not one of the red ones.",
        "It's a cushion. It's yellow and sits in the middle of the sofa.",
        "Could you show me the yellow throw cushion?",
        "yellow scatter cushion",
    ]),
    (SKI, "ord", 21, [21], [
        "Take me to the red chair in the kitchen.",
        "the red seat in the kitchen",
        "In the kitchen there's one red seat among the black ones. Where is it?",
        "I always sit on the red one. Can you take me to it in the kitchen?",
        "This is a seat at the kitchen table. It's the red one, not the black or the white ones.",
        "kitchen, red chiar",
    ]),
    (SKI, "s", 3, [3], [
        "Take me to the cabinet under the sink.",
        "the cupboard below the sink",
        "Which kitchen cupboard is right beneath the sink? I need a sponge.",
        "This is a white base cupboard. It's the one directly under the sink.",
        "Could you bring me to the cupboard underneath the sink?",
        "cupbaord under sink",
    ]),
    (SBE, "o", 2, [2, 3, 4, 5], [
        "Take me to a pillow.",
        "Where are the cushions on the bed? Any of them.",
        "pilow",
        "My neck hurts; I'd like something soft to prop it up. Take me to one of the cushions.",
        "Could you show me any of the pillows, white, red or blue?",
        "Any of the soft things on the bed you put your head on.",
    ]),
    (SOF, "o", 21, [21, 22], [
        "Take me to a trash can.",
        "Where's a bin?",
        "waste basket",
        "I have an empty coffee cup to throw away. Could you take me to a rubbish bin?",
        "Is there a garbage can in the office? Either one is fine.",
        "trash cna",
    ]),
    (SOF, "ard", 25, [25], [
        "I need a hard copy of this document.",
        "Where can I get my slides on paper?",
        "need to print",
        "My boss wants a paper version of the report. Where can I get it out?",
        "Could you take me to where I can print out my boarding pass?",
        "I sent a file to print; where do I pick it up?",
    ]),
    # ---------------- apartment ----------------
    (APT, "o", 12, [12, 13, 52], [
        "Take me to a book.",
        "Where are the books? Any of them.",
        "I'd like something to read. Could you take me to anything I could read?",
        "bok",
        "Is there a novel or textbook around? Any one will do.",
        "Red, yellow or green hardback, I don't mind which; show me one.",
    ]),
    (APT, "or", 42, [42], [
        "Take me to the cabinet in the bathroom.",
        "Where's the cupboard in the bathroom?",
        "bathroom cupboard",
        "I need a fresh towel. Could you bring me to the bathroom storage unit under the basin?",
        "Is there a cabinet in the bathroom? Take me there.",
        "bathroom vanity unit",
    ]),
    (APT, "or", 23, [23, 24], [
        "Take me to a chair in the kitchen.",
        "Where can I sit in the kitchen? Either dining seat.",
        "kitchen seat",
        "I'd like to have breakfast at the table. Bring me to one of the seats in the kitchen.",
        "Any of the kitchen chairs, please.",
        "kitchen dining seat, either",
    ]),
    (APT, "od", 2, [2], [
        "Take me to the brown leather loveseat.",
        "the small brown leather couch",
        "Where's the two-seater in leather? Not the big gray one.",
        "It's a small couch. It's brown leather and a little worn.",
        "Could you show me the leather two-seat settee?",
        "brown leather sofaa",
    ]),
    (APT, "ord", 53, [53], [
        "Take me to the gray metal filing cabinet in the office.",
        "the office drawer unit for paperwork",
        "In the office there's a gray metal unit with two drawers for papers. Where is it?",
        "I need to file my tax papers. Could you take me to the metal filing drawers in the office?",
        "This is a filing cabinet. It's gray metal, and it's in the office under the printer.",
        "office, grey metal file cabnet",
    ]),
    (APT, "ard", 27, [27], [
        "I'd love a cup of tea.",
        "I want to boil some water for my coffee.",
        "need hot water for tea",
        "I'm freezing; I want to make myself a hot drink. Where should I go?",
        "Could you take me to where I can heat water quickly?",
        "tea time, where do I boil water",
    ]),
    (APT, "s", 12, [12], [
        "Take me to the book on the upper shelf of the living room bookshelf.",
        "the higher of the two volumes on the living room shelves",
        "Which novel sits higher up on the bookcase in the living room? Not the one lying flat at the bottom.",
        "This is a red hardback. It's standing on an upper shelf of the bookcase, above the photo album.",
        "Could you bring me to the book that's on a high shelf in the living room, not the low one?",
        "living room bookcase, the volume up high",
    ]),
]


def main() -> None:
    lines = []
    for g, (mp, typ, target, accept, words) in enumerate(G, 1):
        assert len(words) == 6, (g, len(words))
        assert target in accept
        for k, q in enumerate(words, 1):
            lines.append({"id": f"b12-g{g:02d}-w{k}", "map": mp, "query": q, "type": typ,
                          "target": target, "accept": accept, "group": f"b12-g{g:02d}"})
    OUT.write_text("".join(json.dumps(x, ensure_ascii=False) + "\n" for x in lines), encoding="utf-8")
    print(f"{len(G)} groups, {len(lines)} lines -> {OUT}")


if __name__ == "__main__":
    main()
