"""Hand-written blind query suite, round 47 (48 groups x 6 wordings).

Each group: (group number, map key, type, target, accept, room or None, claim or None, [w1..w6]).
`room` is the named room for or/ord groups (check.py re-derives the accept set / checks the target's room);
`claim` is the spatial claim of an s group, checked numerically by check.py.
Run: python3 scripts/emit.py  -> writes evals/blind/round47.jsonl
"""
import json
from pathlib import Path

MAPS = {
    "c829": "../../../shared/data/iesm_maps/scene_00829_caption.json",
    "off3": "../../../shared/data/iesm_maps/scene_office3_caption.json",
    "fc": "maps/flat_c.json",
    "fd": "maps/flat_d.json",
    "ff": "maps/flat_f.json",
    "fh": "maps/flat_h.json",
    "apt": "apartment",
    "sb": "../maps/scan_bedroom.json",
    "sk": "../maps/scan_kitchen.json",
    "sl": "../maps/scan_livingroom.json",
    "so": "../maps/scan_office.json",
}

GROUPS = [
    # ---------------- scene_00829 (caption map) ----------------
    (1, "c829", "o", 42, [42, 197, 212, 259], None, None, [
        "Go to a book.",
        "Could you take me to any of the books lying around?",
        "any volume to read",
        "I fancy something to read tonight, so bring me to a bound volume; any one will do.",
        "This is a bound volume with a cover and pages. It is the kind of thing you sit down and read.",
        "hey can u find me something to raed, any hardback is fine",
    ]),
    (2, "c829", "o", 4, [4, 9, 32, 79, 191, 261, 263], None, None, [
        "Go to an armchair.",
        "Could you show me where there's an easy chair?",
        "comfy lounge chair",
        "My back hurts from the folding seats; take me to a proper padded lounge chair instead.",
        "This is a cushioned armchair meant for relaxing. It is a deep, comfortable seat with arms.",
        "wheres a comfy armchiar i can sink into",
    ]),
    (3, "c829", "or", 182, [182, 250], "bedroom", None, [
        "Go to a side table in the bedroom.",
        "Could you take me to one of the end tables in the bedroom?",
        "bedroom end table",
        "I left my glasses on a small end table in the bedroom, not on one of those in the living room.",
        "This is a small occasional table. It is located in the bedroom.",
        "go to the little ocasional table in the bedroom pls",
    ]),
    (4, "c829", "or", 195, [195, 216, 228], "bathroom", None, [
        "Go to a cabinet in the bathroom.",
        "Could you bring me to one of the bathroom cupboards?",
        "bathroom cupboard",
        "I need to put away spare toiletries, so find a storage cupboard in the bathroom rather than the one in the bedroom.",
        "This is a wooden storage cupboard with doors. It stands in the bathroom.",
        "take me to a cupbaord in the bathroom",
    ]),
    (5, "c829", "od", 184, [184], None, None, [
        "Go to the L-shaped beige couch.",
        "Could you take me to the corner sofa with the chaise section?",
        "L-shaped sofa with chaise",
        "I want to stretch my legs out, so the sectional with the chaise end, not the plain beige sofa with the massager.",
        "This is a large corner sofa covered in light beige fabric. It has an extended chaise section and hidden storage.",
        "find me the big l shaped setee with the chaise",
    ]),
    (6, "c829", "od", 110, [110], None, None, [
        "Go to the honey-coloured wooden stand with the metal X base.",
        "Could you lead me to the small light-wood table that sits on crossed metal legs?",
        "honey wood stand, X-shaped legs",
        "I'm looking for the warm light-wood side stand with the crossed metal base, not the dark wooden one with storage.",
        "This is a little stand with a warm golden wooden top. Its base is a metal frame shaped like an X.",
        "where's the small honey colored tabel with the x legs",
    ]),
    (7, "c829", "ord", 261, [261], "bedroom", None, [
        "Go to the brown woven-fabric easy chair in the bedroom.",
        "Could you take me to the bedroom armchair upholstered in woven material?",
        "bedroom armchair, woven fabric",
        "In the bedroom, I want the brown armchair covered in woven cloth, not the leather one.",
        "This is a deep brown lounge chair with a woven textile cover. It is in the bedroom.",
        "go to the woven brown armchar in the bedroom",
    ]),
    (8, "c829", "ard", 192, [192], None, None, [
        "Go to the spot where my dog can curl up and sleep.",
        "Could you show me where the dog is supposed to sleep?",
        "dog sleeping spot",
        "The puppy is tired; take me to its own cushioned bed, not a bed for people.",
        "This is where the family pet naps. It is a soft padded spot made for an animal.",
        "where does the dgo sleep, i wanna put him down for a nap",
    ]),
    # ---------------- scene_office3 (caption map) ----------------
    (9, "off3", "o", 8, [8, 13, 20, 40], None, None, [
        "Go to a pillow.",
        "Could you take me to one of the cushions?",
        "throw cushion",
        "I need something soft to prop behind my back; any cushion will do.",
        "This is a soft stuffed cushion. It is the kind you lean against on a sofa.",
        "grab me a cusion from somewhere",
    ]),
    (10, "off3", "or", 7, [7, 55, 64], "rec room", None, [
        "Go to a desk in the rec room.",
        "Could you take me to one of the desks in the rec room?",
        "rec room writing table",
        "I need to sit down and work on my laptop, so find a work table in the rec room, not the sofa.",
        "This is a flat work surface for writing or computing. It is in the rec room.",
        "take me to a workdesk in the rec roon",
    ]),
    (11, "off3", "od", 7, [7], None, None, [
        "Go to the white desk.",
        "Could you bring me to the white-painted wooden work table?",
        "white writing table",
        "Not one of the brown wooden ones; I want the white work table.",
        "This is a work table made of wood painted white. It is the only pale one among the work surfaces.",
        "go to the whte desk plz",
    ]),
    (12, "off3", "ord", 40, [40], "rec room", None, [
        "Go to the orange striped pillow in the rec room.",
        "Could you find the orange cushion with white and yellow stripes in the rec room?",
        "striped orange cushion, rec room",
        "In the rec room I want the orange cushion with stripes, not the plain puffy one with the button.",
        "This is an orange fabric cushion decorated with stripes. It is in the rec room.",
        "take me to the stripy orange cushoin in the rec room",
    ]),
    # ---------------- flat_c ----------------
    (13, "fc", "o", 5, [5, 7, 28, 36], None, None, [
        "Go to a lamp.",
        "Could you take me to any light I can switch on?",
        "any reading light",
        "It's getting dark and I want to turn on a light; any lamp in the flat is fine.",
        "This is a light fixture with a shade or head. It is something you switch on to brighten a room.",
        "find me a ligth i can turn on",
    ]),
    (14, "fc", "or", 19, [19, 20, 21], "kitchen", None, [
        "Go to a chair in the kitchen.",
        "Could you take me to one of the kitchen seats?",
        "kitchen dining seat",
        "I want to sit at the table while I eat, so a seat in the kitchen, not the rattan one in the bedroom.",
        "This is a seat for eating meals. It is in the kitchen, around the dining table.",
        "bring me to a kitchn chair",
    ]),
    (15, "fc", "s", 3, [3], None, ("nearest", 12, [2, 3]), [
        "Go to the armchair closest to the bookcase.",
        "Could you take me to the easy chair that sits nearest the bookshelf?",
        "armchair nearest bookcase",
        "I want to grab a book and read right away, so the lounge chair next to the bookcase, not the one over on the west side.",
        "This is a single upholstered seat in the living room. It is the one placed closest to the shelves of books.",
        "take me to the comfy chiar right by the bookcase",
    ]),
    (16, "fc", "ard", 24, [24], None, None, [
        "Take me to where I can hang my coat when I come in.",
        "Could you show me where to hang up my jacket by the front door?",
        "hang jacket, front door",
        "I'm dripping wet from the rain and want to hang my coat up near the entrance, not stuff it in the bedroom wardrobe.",
        "This is the place for hanging outdoor clothes. It stands just inside the entrance.",
        "where do i hang my jakcet when i get home",
    ]),
    # ---------------- flat_d ----------------
    (17, "fd", "od", 3, [3], None, None, [
        "Go to the round pine table.",
        "Could you take me to the little round table made of pine?",
        "round pine dinette",
        "I want to eat breakfast, so the circular wooden one where two can sit, not the low black metal one by the sofa bed.",
        "This is a circular eating surface made of light wood. It has room for two people.",
        "take me to the roud pine dinette",
    ]),
    (18, "fd", "ord", 7, [7], "studio", None, [
        "Go to the black mesh office chair in the studio.",
        "Could you take me to the swivel seat on wheels in the studio?",
        "studio mesh desk seat",
        "I need to answer emails, so the black mesh seat at the writing desk in the studio, not the plastic or yellow ones at the dining table.",
        "This is a black swivel seat with a mesh back and castors. It is in the studio at the desk.",
        "take me to the blak mesh chair in the studio",
    ]),
    (19, "fd", "s", 22, [22], None, ("nearest", 15, [21, 22]), [
        "Go to the stool nearest the fridge.",
        "Could you take me to whichever bar stool is closer to the refrigerator?",
        "high seat closest to fridge",
        "I want to sit where I can reach the fridge easily, so the seat nearer to it, not the other high seat.",
        "This is one of two high seats in the kitchenette. It is the one closer to the fridge.",
        "go to the high seat next to the frigde",
    ]),
    (20, "fd", "ard", 25, [25], None, None, [
        "Take me to where I can dry my washed clothes.",
        "Could you show me the machine that dries laundry?",
        "tumble dry clothes",
        "The wash just finished and the clothes are soaking, so I need the drying machine, not the washer.",
        "This is the appliance that dries wet laundry. It is in the laundry room.",
        "where can i dry my wet clohtes",
    ]),
    # ---------------- flat_f ----------------
    (21, "ff", "or", 12, [12, 13, 14, 15], "kitchen", None, [
        "Go to a chair in the kitchen.",
        "Could you bring me to any seat at the kitchen table?",
        "kitchen seat",
        "Dinner is ready; I need any seat in the kitchen, not the rocking chair out on the porch.",
        "This is a wooden seat for meals. It is in the kitchen.",
        "find me somewhere to sit in the kitchn",
    ]),
    (22, "ff", "od", 2, [2], None, None, [
        "Go to the red tartan armchair.",
        "Could you take me to the wingback chair in red plaid wool?",
        "red plaid wingback",
        "I want the checked red wingback by the fire, not the cream leather one.",
        "This is a high-backed seat with wings upholstered in red tartan. It is made of wool.",
        "go to the red tartn wingback",
    ]),
    (23, "ff", "ord", 37, [37], "bathroom", None, [
        "Go to the medicine cabinet in the bathroom.",
        "Could you take me to the mirrored wall cupboard in the bathroom?",
        "bathroom mirrored wall cupboard",
        "I need a plaster, so the little white wall cupboard in the bathroom, not the green dresser in the kitchen.",
        "This is a small white cupboard with a mirror on its door. It hangs on the bathroom wall.",
        "take me to the medicne cupboard in the bathroom",
    ]),
    (24, "ff", "s", 15, [15], None, ("nearest", 20, [12, 13, 14, 15]), [
        "Go to the dining chair nearest the fridge.",
        "Could you take me to the kitchen seat closest to the refrigerator?",
        "dining seat closest fridge",
        "I'll be getting drinks out all evening, so put me on the table seat nearest the fridge, not one by the cooker.",
        "This is one of the chairs around the dining table. It is the one nearest to the fridge.",
        "which seat at the table is closest to the frdige",
    ]),
    (25, "ff", "ard", 25, [25], None, None, [
        "Take me to something I can use to look at the stars.",
        "Could you show me where I can do some stargazing?",
        "stargazing gear",
        "The sky is clear tonight and I want to see the planets up close, not just through the window.",
        "This is an optical instrument on three legs. It is used to look at the night sky.",
        "i wanna look at the moon up clsoe, where's the thing for that",
    ]),
    # ---------------- flat_h ----------------
    (26, "fh", "o", 13, [13, 26, 32], None, None, [
        "Go to a mug.",
        "Could you take me to any of the cups around the flat?",
        "any coffee cup",
        "I want to make tea and need something to drink from; any mug will do.",
        "This is a drinking vessel with a handle. It holds hot drinks like tea or coffee.",
        "where's a cupp i can use",
    ]),
    (27, "fh", "ord", 6, [6], "living room", None, [
        "Go to the cream linen sofa in the living room.",
        "Could you take me to the small cream two-seater in the living room?",
        "living room cream loveseat",
        "In the living room I want the little pale linen loveseat, not the long green velvet one.",
        "This is a compact settee covered in cream linen. It is in the living room by the east window.",
        "go to the cream coloured lovesaet in the lounge",
    ]),
    (28, "fh", "s", 17, [17], None, ("side", "+x", [16, 17]), [
        "Go to the black chair on the right when you face the dining table from its south side.",
        "Could you take me to the metal bistro seat on your right as you face the dining table from the south?",
        "right black bistro seat, facing table from south",
        "Standing south of the dining table and looking at it, I want the black seat on the right, not the one on the left.",
        "This is a black metal seat along the southern edge of the dining table. It is the right one when you face the table from the south.",
        "facing the dining table from the south, take me to the black seat on the rihgt",
    ]),
    # ---------------- apartment ----------------
    (29, "apt", "o", 8, [8, 39, 55], None, None, [
        "Go to a plant.",
        "Could you take me to one of the houseplants?",
        "any potted greenery",
        "I need to water something green today; any potted plant in the flat will do.",
        "This is a living green thing in a pot. It needs watering now and then.",
        "take me to a housplant",
    ]),
    (30, "apt", "or", 12, [12, 13], "living room", None, [
        "Go to a book in the living room.",
        "Could you take me to one of the books in the living room?",
        "living room reading material",
        "I want something to read on the sofa, so a volume from the living room, not the textbook in the office.",
        "This is a bound volume with pages. It is on the shelves in the living room.",
        "find me a volum to flick through in the living room",
    ]),
    (31, "apt", "or", 23, [23, 24], "kitchen", None, [
        "Go to a kitchen chair.",
        "Could you take me to one of the seats at the kitchen table?",
        "seat, kitchen",
        "I want to eat at the table, so any seat in the kitchen, not the red swivel one in the office.",
        "This is a wooden dining seat. It is in the kitchen by the table.",
        "take me to a kitchen chiar",
    ]),
    (32, "apt", "od", 2, [2], None, None, [
        "Go to the brown leather loveseat.",
        "Could you take me to the small leather couch that's a bit worn?",
        "worn brown leather two-seater",
        "I don't want the big gray fabric one; take me to the little brown leather sofa.",
        "This is a compact two-person couch in brown leather. It is slightly worn and sits against a wall.",
        "go to the brwon leather couch",
    ]),
    (33, "apt", "ord", 53, [53], "office", None, [
        "Go to the gray filing cabinet in the office.",
        "Could you take me to the metal drawer unit for paperwork in the office?",
        "office metal filing drawers",
        "I need to file this invoice, so the gray metal drawers in the office, not the vanity in the bathroom.",
        "This is a gray metal unit with two drawers for documents. It is in the office with a printer on top.",
        "take me to the filling cabinet in the office",
    ]),
    (34, "apt", "ard", 54, [54], None, None, [
        "Take me to where I can print a document.",
        "Could you show me where I can get a paper copy of my boarding pass?",
        "print document",
        "I have to hand in a signed form on paper, so I need whatever prints, not a screen.",
        "This is the device that puts documents on paper. It sits in the office.",
        "i need to prnit my tickets, where do i go",
    ]),
    (35, "apt", "s", 34, [34], None, ("on", 33, [7, 34, 56]), [
        "Go to the lamp on the nightstand.",
        "Could you take me to the light standing on the bedside table?",
        "light on bedside table",
        "I want to read in bed, so the light on top of the bedside table, not the floor lamp in the living room.",
        "This is a small light with a fabric shade. It rests on top of the bedside table.",
        "go to the ligth on the nightstand",
    ]),
    (36, "apt", "s", 23, [23], None, ("nearest", 16, [23, 24]), [
        "Go to the dining chair nearest the fridge.",
        "Could you take me to whichever seat at the dining table is closest to the fridge?",
        "table seat nearest fridge",
        "I keep getting up for milk, so the dining seat nearest the fridge, not the one across the table.",
        "This is a wooden seat tucked in at the dining table. It is the closest of those seats to the fridge.",
        "which dinner seat is closest to the fride",
    ]),
    # ---------------- scan_bedroom ----------------
    (37, "sb", "od", 4, [4], None, None, [
        "Go to the red pillow.",
        "Could you take me to the red cushion on the bed?",
        "red cushion",
        "Not the white ones or the blue one; I want the red cushion.",
        "This is a small red cushion. It is on the bed.",
        "go to the red cusion",
    ]),
    (38, "sb", "s", 8, [8], None, ("side", "-x", [8, 9]), [
        "Go to the lamp on the left nightstand when you look at the headboard from the foot of the bed.",
        "Could you take me to the bedside light on the left, standing at the foot of the bed facing the headboard?",
        "left bedside light, from foot of bed",
        "Standing at the foot of the bed facing the pillows, I want the light on the left side, not the right.",
        "This is a white light on a bedside table. It is the left one when you face the head of the bed from its foot.",
        "from the end of the bed, the lamp on the lfet nightstand",
    ]),
    (39, "sb", "ard", 17, [17], None, None, [
        "Take me to where I can check how I look.",
        "Could you show me where I can see my reflection?",
        "check outfit reflection",
        "Before my interview I want to fix my hair, so somewhere I can see myself, not the window.",
        "This is a reflective surface on the wall. It is where you check your appearance.",
        "where can i see my refelction to fix my hair",
    ]),
    # ---------------- scan_kitchen ----------------
    (40, "sk", "s", 3, [3], None, ("under", 10, list(range(1, 10))), [
        "Go to the cabinet under the sink.",
        "Could you take me to the cupboard right below the sink?",
        "cupboard beneath sink",
        "I need the dish soap refill kept below the sink, so that base cupboard, not the ones under the microwave or coffee maker.",
        "This is a white lower kitchen cupboard. It is the one the sink sits right on top of.",
        "take me to the cupbord under the sink",
    ]),
    (41, "sk", "s", 24, [24], None, ("nearest", 13, [23, 24, 25]), [
        "Go to the cup closest to the fridge.",
        "Could you take me to the mug that's nearest the refrigerator?",
        "mug nearest fridge",
        "I'll pour milk in it, so the mug closest to the fridge, not the one by the sink or the other one on the table.",
        "This is a small drinking cup on the table. It is nearer to the refrigerator than any other cup.",
        "grab the mug closest to the frigde",
    ]),
    (42, "sk", "ard", 12, [12], None, None, [
        "Take me to where I can brew a coffee.",
        "Could you show me where I can make a fresh pot of coffee?",
        "brew coffee",
        "I'm half asleep and need caffeine, so whatever brews coffee, not the microwave.",
        "This is the appliance that brews hot coffee. It sits on the counter.",
        "need coffe badly, where's the machine",
    ]),
    # ---------------- scan_livingroom ----------------
    (43, "sl", "o", 10, [10, 11, 12], None, None, [
        "Go to any lamp.",
        "Could you take me to one of the lights in here?",
        "any light",
        "I want to brighten the room a bit; any lamp works, small or standing.",
        "This is a light with a shade. It is switched on to light the room.",
        "find me a lihgt to switch on",
    ]),
    (44, "sl", "s", 2, [2], None, ("side", "-x", [2, 4]), [
        "Go to the red pillow on your left when sitting on the sofa.",
        "Could you take me to the red cushion that's on my left as I sit on the couch facing the TV?",
        "left red cushion, seated on couch",
        "Sitting on the couch looking at the TV, I want the red cushion on the left, not the one on the right.",
        "This is a red cushion on the sofa. It is the left one for someone sitting there facing the TV.",
        "the red cushon on my left when im on the sofa",
    ]),
    (45, "sl", "ard", 24, [24], None, None, [
        "Take me to what I need to change the TV channel.",
        "Could you show me where I can switch channels from the couch?",
        "change channel",
        "I want to turn the volume down without getting up, not walk over to the TV itself.",
        "This is a small handheld device with buttons. It controls the television.",
        "where's the thing to chnage the channel",
    ]),
    # ---------------- scan_office ----------------
    (46, "so", "s", 16, [16], None, ("lowest_top", None, [14, 15, 16]), [
        "Go to the shortest bookshelf.",
        "Could you take me to the lowest of the bookcases?",
        "shortest bookcase",
        "I can't reach high shelves, so the short bookcase, not the tall wooden ones.",
        "This is a set of shelves against the north wall. It is the shortest of the three.",
        "go to the small bookshlef",
    ]),
    (47, "so", "s", 7, [7], None, ("nearest", [18, 19], [7, 10]), [
        "Go to the blue office chair closest to the windows.",
        "Could you take me to whichever blue swivel seat is nearer the windows?",
        "blue desk seat nearest window",
        "I'd like some daylight while I work, so the blue seat by the windows, not the blue one on the far side of the table.",
        "This is a blue swivel seat at the wooden table. It is the blue one nearer the windows.",
        "take me to the blue chair by the windos",
    ]),
    (48, "so", "ord", 30, [30], "office", None, [
        "Go to the white keyboard in the office.",
        "Could you take me to the pale keyboard in the office?",
        "office white typing pad",
        "Not the black one; in the office I need the white keys to type on.",
        "This is a white typing device on the wooden table. It is in the office.",
        "go to the white keybaord in the office",
    ]),
]


def rows():
    for num, key, typ, target, accept, _room, _claim, words in GROUPS:
        assert len(words) == 6, num
        for k, q in enumerate(words, 1):
            yield {"id": f"b47-g{num:02d}-w{k}", "map": MAPS[key], "query": q, "type": typ,
                   "target": target, "accept": sorted(accept), "group": f"b47-g{num:02d}"}


def main():
    out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round47.jsonl"
    with out.open("w", encoding="utf-8") as fh:
        for r in rows():
            fh.write(json.dumps(r, ensure_ascii=False) + "\n")
    print(f"wrote {out} ({len(GROUPS)} groups)")


if __name__ == "__main__":
    main()
