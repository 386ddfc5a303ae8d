"""Write evals/blind/round19.jsonl: 48 groups x 6 hand-written wordings.

Every wording below was written by hand for this round after reading only the map files named in
BRIEF.md. Accept sets were chosen by reading the maps (see round19_NOTES.md); spatial groups are
checked numerically by check_spatial19.py.

    python3 /work/blind19/make_round19.py
"""

import json
from pathlib import Path

OUT = Path(__file__).resolve().parent / "evals" / "blind" / "round19.jsonl"

M829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
MOFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
FC, FD, FG, FI = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_g.json", "maps/flat_i.json"
SOFF, SKIT = "../maps/scan_office.json", "../maps/scan_kitchen.json"

# (map, type, target, accept, [6 wordings])
GROUPS = [
    # ---------------- scene_00829 (caption map, no geometry) ----------------
    (M829, "o", 112, [112, 157, 219, 229, 233], [
        "take me to a mirror",
        "Could you bring me to one of the mirrors in the house?",
        "mirror frame, any",
        "I want to check my hair. Any looking glass will do, just get me to one.",
        "Somewhere I can see my reflection - one of the framed mirrors, whichever is closest.",
        "need a mirorr",
    ]),
    (M829, "or", 261, [261, 263], [
        "Take me to an easy chair in the bedroom.",
        "Which armchairs are in the bedroom? Go to one of them.",
        "bedroom lounge chair, any of them",
        "I'd like to sit comfortably in the bedroom. Show me one of the big cushy chairs in there.",
        "There are some comfy armchairs in the bedroom. Bring me to one, doesn't matter which.",
        "bedrom armchair please",
    ]),
    (M829, "od", 211, [211], [
        "Go to the deep blue bowl with the gold patterns.",
        "Could you find the dark blue ceramic bowl, the ornamental one with gold detailing?",
        "blue & gold ornamental bolw",
        "There's a glossy blue ceramic dish with gold swirls on it. Take me there.",
        "Not the white sweets bowl - the blue one with gold on it.",
        "the navy decorative bowl please",
    ]),
    (M829, "od", 184, [184], [
        "take me to the L-shaped couch",
        "Where's the beige sectional with the chaise end?",
        "L shaped sofa w/ chaise",
        "I'm looking for the corner sofa. It's beige fabric and has a built-in chaise longue.",
        "The sectional, please - not the plush one with the massage feature.",
        "Could you guide me to the big L-shaped settee that has storage in it?",
    ]),
    (M829, "ord", 263, [263], [
        "the big brown leather armchair in the bedroom",
        "In the bedroom there are two comfy lounge chairs; I want the leather one, not the woven fabric one.",
        "bedroom, leather easy chair w/ lumbar support",
        "Could you take me to the deep brown leather easy chair in the bedroom?",
        "I'm after a recliner-style seat. The leather one with the lumbar support, in the bedroom.",
        "brown leather armchiar in bedroom",
    ]),
    (M829, "ord", 34, [34], [
        "Take me to the side table with the glass top in the living room.",
        "In the living room, the little end table that has a glass top and a metal base.",
        "living rm end table, glass top, metal legs",
        "There's a small end table with a metal base and glass on top. It sits in the living room.",
        "Living room: the glass-topped side table, not the one with the USB port.",
        "Could you show me the glass-top end tabel with the metal base in the lounge?",
    ]),
    (M829, "ard", 192, [192], [
        "My dog needs somewhere to sleep - where should I take him?",
        "Where can the cat curl up for a nap?",
        "spot for the puppy to rest",
        "I just got a kitten and she looks tired. Take me to her sleeping spot.",
        "Could you show me where the animal sleeps?",
        "Our pup is exhausted, take me to his snooze place",
    ]),
    # ---------------- scene_office3 (caption map, no geometry) ----------------
    (MOFF3, "o", 8, [8, 13, 20, 40], [
        "take me to a pillow",
        "Can you find me a cushion?",
        "any cushoin",
        "My back hurts in this chair. Bring me to one of the throw cushions.",
        "I need something soft to lean on - one of the cushions, whichever.",
        "Where are the pillows? Take me to one.",
    ]),
    (MOFF3, "or", 7, [7, 55, 64], [
        "Take me to a desk in the rec room.",
        "Which workstations are in the recreation room? Any one is fine.",
        "rec room - any place to work at a computer",
        "I need to set my laptop down in the rec room; take me to one of the desks there.",
        "In the recreation room, find me any of the workstations, white or wooden.",
        "Could you bring me to one of the rec room deks?",
    ]),
    (MOFF3, "od", 7, [7], [
        "the white desk",
        "Take me to the desk that's white, not one of the brown wooden ones.",
        "white wooden workstation",
        "I'm looking for a workstation. It's painted white and has a USB port built in.",
        "Could you go to the pale work surface with the USB port please?",
        "the one white workstation, not the brown wood ones",
    ]),
    (MOFF3, "ord", 40, [40], [
        "In the rec room, the orange pillow with white and yellow stripes.",
        "Take me to the striped orange cushion in the recreation room.",
        "rec room: orange striped cushion",
        "There's an orange cushion with white and yellow stripes. It's in the rec room.",
        "Not the plain orange one with the button - the striped orange pillow in the rec room.",
        "Could you find the stripy orange cusion in the rec room?",
    ]),
    (MOFF3, "ard", 68, [68], [
        "I need to call my mum.",
        "I think someone's been trying to reach me. Take me to where I can ring them back.",
        "need to make a call",
        "I have to text my boss that I'm running late. Where can I do that?",
        "Could you take me to what I'd use to dial a number?",
        "gotta ring the office real quick",
    ]),
    # ---------------- apartment ----------------
    (APT, "or", 23, [23, 24], [
        "take me to a chair in the kitchen",
        "Could you bring me to one of the kitchen seats? Either is fine.",
        "kitchen dining seat, any",
        "I want to sit down while I eat. Any of the seats at the kitchen table, please.",
        "There are a couple of dining chairs in the kitchen. Go to one of them.",
        "kitchen chiar",
    ]),
    (APT, "or", 12, [12, 13], [
        "Take me to a book in the living room.",
        "Any of the books in the living room, please.",
        "living room reading material, the novel or the photo album",
        "I'd like something to flip through in the lounge. Take me to one of the volumes there.",
        "Could you locate one of the living room boks?",
        "sitting room - any printed volume will do",
    ]),
    (APT, "od", 30, [30], [
        "the mirror with the gold frame",
        "Take me to the tall looking glass with the ornate golden frame.",
        "gold frame mirror",
        "There's a big rectangular glass with a fancy gold border that you check yourself in. Please go there.",
        "Not the oval one above the basin - the one with the gilt frame.",
        "Could you find the gold-framed miror?",
    ]),
    (APT, "ord", 2, [2], [
        "the brown leather sofa in the living room",
        "In the living room, take me to the small leather loveseat, not the big gray one.",
        "living room - brown leather couch",
        "There's a little two-seater in brown leather. It's against the wall in the living room.",
        "Could you go to the worn leather settee in the lounge?",
        "brown leather sfoa, living room",
    ]),
    (APT, "ard", 27, [27], [
        "I'd like a cup of tea.",
        "I need to boil some water.",
        "boil water for tea",
        "It's freezing and I want something hot to drink. Where can I heat water quickly?",
        "Could you take me to where I can make a cuppa?",
        "need hot water for my instant noodles",
    ]),
    (APT, "s", 34, [34], [
        "the lamp on the nightstand",
        "Take me to the light that sits on the bedside table.",
        "light on bedside table",
        "I want to read in bed. The little light on top of the night table, please.",
        "There's a small light with a white fabric shade. It stands on the cabinet beside the bed.",
        "Not the floor light or the desk one - the one resting on the nightsatnd.",
    ]),
    (APT, "s", 14, [14], [
        "the pillow on the sofa",
        "Take me to the cushion sitting on the couch.",
        "cushion on couch",
        "I want to lie back on the sofa. Go to the cushion that's on it.",
        "There's a yellow cushion. It's resting on the gray couch in the living room.",
        "Not the one on the bed - the pillow on the settee.",
    ]),
    # ---------------- flat_c ----------------
    (FC, "o", 2, [2, 3], [
        "take me to an armchair",
        "Could you bring me to one of the easy chairs?",
        "any lounge chair",
        "I want to sit somewhere comfy with arms to rest on - any of the single-seat upholstered chairs.",
        "There are two padded chairs with armrests in the lounge. Either one.",
        "armchair pls",
    ]),
    (FC, "or", 5, [5, 7], [
        "Take me to a lamp in the living room.",
        "Could you go to one of the living room lights? Either the floor one or the table one.",
        "living room light, any",
        "It's too dark in the lounge. Take me to any of the lamps in there.",
        "There are a couple of lights in the living room. Bring me to one.",
        "any lmap in the living room",
    ]),
    (FC, "od", 2, [2], [
        "the mustard yellow armchair",
        "Take me to the yellow easy chair.",
        "mustard fabric chair",
        "I'm after a chair with arms. It's mustard-colored fabric.",
        "Not the gray one - the yellow armchair.",
        "Could you find the ochre upholstered seat please?",
    ]),
    (FC, "ard", 29, [29], [
        "I need to be woken up at six tomorrow.",
        "What time is it? Take me to something that shows it.",
        "wake me at 6am tomorrow",
        "I've got an early train and can't oversleep. Where can I set a wake-up beep?",
        "Could you take me to whatever tells the time in here?",
        "need to check the time",
    ]),
    (FC, "s", 27, [27], [
        "the nightstand with the alarm clock on it",
        "Take me to the bedside table that has the red clock on top.",
        "bedside table w/ clock",
        "I left my glasses by the clock. Go to the bedside table it sits on.",
        "There are two bedside tables. I want the one holding the alarm clock, not the one with the pink lamp.",
        "Could you take me to the night table where the clock is?",
    ]),
    (FC, "s", 20, [20], [
        "the chair closest to the fridge",
        "Which dining seat is nearest the refrigerator? Take me to it.",
        "seat nearest fridge",
        "I want to sit close to the frdige while I cook. The seat nearest to it, please.",
        "Standing at the fridge, go to the closest seat.",
        "There's a fridge in the kitchen corner. Take me to the dining chair nearest to it.",
    ]),
    # ---------------- flat_d ----------------
    (FD, "o", 21, [21, 22], [
        "take me to a stool",
        "Could you find me a bar seat? Either one.",
        "any backless seat",
        "My legs are tired. Take me to one of the high seats in the kitchenette.",
        "There are two stools. Go to whichever.",
        "any stoool",
    ]),
    (FD, "or", 8, [8, 9], [
        "Take me to a lamp in the studio.",
        "Any of the lights in the main studio room, please.",
        "studio lamp, whichever",
        "I need more light in the studio. Go to one of the lights there.",
        "There's a floor light and a desk light in the studio. Either is fine.",
        "Could you bring me to a studio lampp?",
    ]),
    (FD, "ord", 5, [5], [
        "the yellow chair in the studio",
        "In the studio, take me to the painted yellow wooden seat by the round table.",
        "studio - yellow wooden chair",
        "I'd like the yellow seat. It's the wooden one in the studio, not the white plastic one.",
        "Could you go to the yellow dining seat in the studio?",
        "the yellow wooden chari in the studio",
    ]),
    (FD, "ard", 27, [27], [
        "My shirt is all wrinkled.",
        "I need to press my trousers before the interview.",
        "get creases out of a shirt",
        "I have a meeting in an hour and my blouse is crumpled. Where can I fix that?",
        "Could you take me to where I can iron my clothes?",
        "need to smooth out my dress",
    ]),
    (FD, "s", 22, [22], [
        "the stool nearest the fridge",
        "Which of the bar stools is closer to the refrigerator? Take me there.",
        "bar seat nearest fridge",
        "I'll be grabbing drinks from the fridge. Go to the bar seat closest to it.",
        "Standing at the fridge, the nearest of the two high seats.",
        "There are two bar seats in the kitchenette. I mean the one on the fridge side.",
    ]),
    # ---------------- flat_g ----------------
    (FG, "od", 3, [3], [
        "the small blue bike",
        "Take me to the kids' bicycle, the blue one with stabilisers.",
        "blue child bike w/ training wheels",
        "I'm looking for a children's bike. It's blue and has stabilisers.",
        "Not the black mountain bike - the little blue one.",
        "Could you find the blue bicylce?",
    ]),
    (FG, "ord", 34, [34], [
        "the teal lamp in the bedroom",
        "In the bedroom, go to the bedside light with the teal glass base.",
        "bedroom - teal glass light",
        "There's a bedside lamp with a blue-green glass base. It's in the main bedroom.",
        "Not the beige ceramic one - the teal bedside light in the bedroom.",
        "Could you take me to the turquoise-ish glass light in the bedroom?",
    ]),
    (FG, "ard", 23, [23], [
        "I want to see my whole outfit before I leave.",
        "Where can I check how I look from head to toe?",
        "check full outfit",
        "I've got a wedding today and want to see if the suit fits right top to bottom. Take me somewhere I can do that.",
        "Could you take me where I can see my entire reflection?",
        "need to see if these shoes go with the dress",
    ]),
    (FG, "s", 29, [29], [
        "the lamp next to the sofa",
        "Take me to the light standing beside the couch.",
        "floor light by sofa",
        "I want to read on the couch. Go to the lamp right beside it.",
        "There's a navy sofa in the living room. Take me to the light standing in the corner beside it.",
        "Which light is closest to the couch? That one.",
    ]),
    # ---------------- flat_i ----------------
    (FI, "o", 23, [23, 31, 36], [
        "take me to a mug",
        "Could you find me a coffee cup? Any of them.",
        "any cup",
        "I'm thirsty and need something to drink from. Any of the cups will do.",
        "There are a few mugs around the place. Go to whichever.",
        "whichever coffee cup is nearest",
    ]),
    (FI, "or", 6, [6, 7, 8, 9], [
        "Take me to a chair in the meeting room.",
        "Any seat at the conference table, please.",
        "meeting room seat, any",
        "I'm early for the client meeting. Take me to one of the seats in the meeting room.",
        "There are four chairs in the meeting room. Go to any of them.",
        "boardroom seat, whichever one",
    ]),
    (FI, "od", 18, [18], [
        "the banker's lamp with the green glass shade",
        "Take me to the green-shaded desk light.",
        "green glass lamp",
        "There's a classic library-style light with a green glass shade. Please go to it.",
        "Not the rattan or ceramic ones - the green glass desk light.",
        "Could you find the green bankers' light?",
    ]),
    (FI, "ord", 13, [13], [
        "the white desk in the studio",
        "In the studio, take me to the plain white desk with the cable tray, not the oak one.",
        "studio - white work table",
        "I'm after a work table in the studio. It's plain white and sits next to the oak one.",
        "Could you go to the white workstation in the design studio?",
        "studio, the white dsek",
    ]),
    (FI, "ard", 40, [40], [
        "I want to listen to some vinyl.",
        "Let's put on a record.",
        "play an LP",
        "I'm in the mood for some old jazz on vinyl. Take me to where I can spin a record.",
        "Could you take me to where I can play records?",
        "wanna hear my old albums",
    ]),
    (FI, "s", 36, [36], [
        "the mug on the coffee table",
        "Take me to the cup sitting on the low table in front of the sofa.",
        "cup on coffee table",
        "I left my tea somewhere. It's the cup on the coffee table in the living room.",
        "There's a low teak table in front of the sofa. Take me to the cup on top of it.",
        "Not the one on the worktop or the desk - the mug on the coffee table.",
    ]),
    # ---------------- scan_office ----------------
    (SOFF, "o", 21, [21, 22], [
        "take me to a trash can",
        "Could you find me a bin?",
        "any wastebasket",
        "I've got a wrapper to throw away. Take me to one of the rubbish bins.",
        "There are two waste bins in here. Either one.",
        "nearest garbage cna",
    ]),
    (SOFF, "ard", 17, [17], [
        "I need to sketch a diagram for the team.",
        "Where can I write something up so everyone can see it?",
        "brainstorm with markers",
        "We're planning the next sprint and need to draw it out big. Take me to where we can do that.",
        "Could you take me somewhere I can jot notes with a dry-erase marker?",
        "need to draw a flowchart for the meeting",
    ]),
    (SOFF, "s", 15, [15], [
        "the middle bookshelf",
        "Facing the shelves, take me to the one in the middle.",
        "center shelf unit of the three",
        "There are three bookcases against the back wall. I want the one between the other two.",
        "Could you go to the bookcase sandwiched between the short white one and the other brown one?",
        "the tall one in the middle of the row of bookcases",
    ]),
    (SOFF, "s", 23, [23], [
        "the plant by the window",
        "Take me to the houseplant closest to the windows.",
        "greenery nearest window",
        "I want to check whether the leafy thing in the sun needs watering. Go to the one near the window.",
        "There are two plants. Go to the one next to the window, not the one by the shelves.",
        "Could you take me to the pot of greenery near the windwo?",
    ]),
    (SOFF, "s", 11, [11], [
        "the monitor on the white table",
        "Take me to the screen sitting on the white desk.",
        "screen on white table",
        "I need the computer display that's on the white table, not the wooden one.",
        "There are two tables. Go to the screen on the white one.",
        "Could you find the montior on the white table?",
    ]),
    # ---------------- scan_kitchen ----------------
    (SKIT, "o", 23, [23, 24, 25], [
        "take me to a cup",
        "Could you find me a mug? Any one.",
        "any mug",
        "I'd like some water. Take me to any of the mugs.",
        "There are a few cups around the kitchen. Whichever is closest.",
        "a mug please",
    ]),
    (SKIT, "s", 25, [25], [
        "the cup on the counter",
        "Take me to the mug sitting on the countertop, not the ones on the table.",
        "mug on counter near sink",
        "I left my coffee by the sink. Go to the mug on the counter there.",
        "There's a white cup. It's on the kitchen counter, next to the sink.",
        "Not the ones on the dining table - the mug up on the worktop.",
    ]),
    (SKIT, "s", 3, [3], [
        "the cabinet under the sink",
        "Take me to the cupboard right below the sink.",
        "under-sink cupboard",
        "I need a new sponge; they're kept under the sink. Take me to that cupboard.",
        "There's a metal sink in the counter. Go to the base cabinet directly beneath it.",
        "Could you take me to the cupbaord beneath the sink?",
    ]),
]

# (group number, wording number, typo, intended word)
TYPOS = [
    (1, 6, "mirorr", "mirror"), (2, 6, "bedrom", "bedroom"), (3, 3, "bolw", "bowl"),
    (5, 6, "armchiar", "armchair"), (6, 6, "tabel", "table"), (8, 3, "cushoin", "cushion"),
    (9, 6, "deks", "desks"), (11, 6, "cusion", "cushion"), (13, 6, "chiar", "chair"),
    (14, 5, "boks", "books"), (15, 6, "miror", "mirror"), (16, 6, "sfoa", "sofa"),
    (18, 6, "nightsatnd", "nightstand"), (21, 6, "lmap", "lamp"), (25, 4, "frdige", "fridge"),
    (26, 6, "stoool", "stool"), (27, 6, "lampp", "lamp"), (28, 6, "chari", "chair"),
    (31, 6, "bicylce", "bicycle"), (38, 6, "dsek", "desk"), (41, 6, "cna", "can"),
    (44, 6, "windwo", "window"), (45, 6, "montior", "monitor"), (48, 6, "cupbaord", "cupboard"),
]


def main() -> None:
    assert len(GROUPS) == 48, len(GROUPS)
    lines = []
    for g, (mp, typ, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6 and target in accept
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b19-g{g:02d}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": accept, "group": f"b19-g{g:02d}"}))
    for g, k, typo, _ in TYPOS:
        assert typo in GROUPS[g - 1][4][k - 1], (g, k, typo)
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {OUT}")


if __name__ == "__main__":
    main()
