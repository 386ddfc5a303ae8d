"""Hand-written blind query suite, round 46. Writes evals/blind/round46.jsonl.
Each group: (map key, type, target, accept, [w1..w6]).  Run: python3 scripts/emit.py"""
import json
from pathlib import Path

C1 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
C2 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

GROUPS = [
    # ---------------- caption map scene_00829 ----------------
    (C1, "o", 78, [78, 234], [
        "Go to the wall TV.",
        "Could you take me to a television that's mounted on a wall?",
        "wall-mounted telly",
        "I'd like to watch the news, so find me one of the wall TVs, not the other display screens.",
        "This is a flat television fixed to a wall. It is a thin panel for watching shows.",
        "where's the tv thats hung on the wal",
    ]),
    (C1, "o", 42, [42, 197, 212, 259], [
        "Go to a book.",
        "Could you show me where a book is?",
        "bound volume, any",
        "I'm bored and want to read, so take me to any bound volume at all, not a loose sheet of paper.",
        "This is a bound volume with pages. It is something you read.",
        "can u find me a bok to read",
    ]),
    (C1, "or", 261, [261, 263], [
        "Go to the easy chair in the bedroom.",
        "Could you take me to a comfy armchair in the bedroom?",
        "bedroom lounge chair",
        "I want to sit and read before bed, so find an easy chair in the bedroom, not one in the living room.",
        "This is a deep, comfortable lounging seat. It is in the bedroom.",
        "comfy armchair in the bedrom",
    ]),
    (C1, "or", 190, [190, 196, 207], [
        "Go to the counter desk in the bathroom.",
        "Could you bring me to a countertop workspace in the bathroom?",
        "bathroom counter desk",
        "I need to set down my things, so take me to a counter-style desk in the bathroom, not the washbasin counter.",
        "This is a desk-height counter surface. It is located in the bathroom.",
        "take me to the counter-top desk in the bathrom",
    ]),
    (C1, "od", 211, [211], [
        "Go to the deep blue decorative bowl.",
        "Could you find the navy ceramic bowl with gold patterns on it?",
        "blue gold-patterned bowl",
        "I want to admire the ornamental piece, the dark blue bowl with gold detailing, not the white sweets bowl.",
        "This is a glossy dark blue ceramic dish. It is ornamented with golden patterns.",
        "wheres that blue bowl with the gold desings",
    ]),
    (C1, "od", 105, [105], [
        "Go to the folded chair made of leather and woven material.",
        "Could you take me to the brown folding chair with the foldable armrests?",
        "folding chair, woven and leather, fold-down arms",
        "I need an extra seat with arms, so the fold-up chair combining leather with weaving, not the one with a table attachment.",
        "This is a rich brown foldable seat. It mixes leather with a woven material and its armrests can fold.",
        "the brown folding chiar with the woven bits and bendy armrests",
    ]),
    (C1, "ord", 145, [145], [
        "Go to the bedroom doorway with the small metal sliding lock.",
        "Could you take me to the door in the bedroom that has a little sliding bolt?",
        "bedroom door, sliding lock",
        "I want to lock myself in, so the bedroom entrance with the slide lock, not the one with the round white handle.",
        "This is a dark wood-look doorway. It is in the bedroom and has a small sliding metal latch.",
        "bedroom dorway with the slidey lock pls",
    ]),
    (C1, "ard", 192, [192], [
        "Go to the place where my dog can curl up and sleep.",
        "Could you show me where my pet is supposed to sleep?",
        "spot for pet to sleep",
        "The puppy is tired, so take me to its own sleeping spot, not my bed.",
        "This is where the animal rests. It is a soft plush cushion made for a pet.",
        "where does the dog go to slepe",
    ]),
    # ---------------- caption map scene_office3 ----------------
    (C2, "o", 8, [8, 13, 20, 40], [
        "Go to a pillow.",
        "Could you take me to one of the cushions?",
        "throw cushion",
        "My back hurts on this chair, so find me any cushion to lean on, I don't care which colour.",
        "This is a soft stuffed cushion. It is the kind you rest your head or back on.",
        "wheres a pilow i can grab",
    ]),
    (C2, "or", 7, [7, 55, 64], [
        "Go to a desk in the rec room.",
        "Could you guide me to a work station in the rec room?",
        "rec room workstation",
        "I need to write something, so find a desk in the recreation room, not the golden-brown table.",
        "This is a work surface for a computer or paperwork. It is in the rec room.",
        "any deks in the rec room?",
    ]),
    (C2, "od", 13, [13], [
        "Go to the navy blue velvet pillow.",
        "Could you take me to the dark blue velvety cushion with buttons?",
        "navy velvet cushion",
        "I want the biggest, softest one: the navy velvet cushion, not the orange or yellow ones.",
        "This is a deep blue cushion with a velvet feel. It has a buttoned design and is a bit bigger than the rest.",
        "the navy velvit cushion please",
    ]),
    (C2, "ord", 7, [7], [
        "Go to the white desk in the rec room.",
        "Could you take me to the white wooden writing table in the rec room?",
        "white wood desk, rec room",
        "I need the light one, the white workstation in the rec room, not the brown wooden ones.",
        "This is a white wooden work surface. It is in the rec room and has a USB port built in.",
        "take me to the whte workdesk in the rec room",
    ]),
    # ---------------- flat_b ----------------
    (FB, "or", 2, [2, 3], [
        "Go to an armchair in the living room.",
        "Could you take me to one of the living room easy chairs?",
        "lounge armchair living room",
        "I want to sit down with a coffee, so any single padded seat in the living room, not the green reading chair in the study.",
        "This is a padded seat for one person with arms. It is in the living room.",
        "comfy one-seater in the livng room",
    ]),
    (FB, "s", 7, [7], [
        "Go to the lamp on the side table.",
        "Could you take me to the light sitting on top of the little side table?",
        "light on side table",
        "I want to switch on a small light, the one standing on the side table, not the tall floor one.",
        "This is a small table light with a ceramic base. It stands on top of the small round side table at the end of the sofa.",
        "the litle lamp on top of the side table",
    ]),
    (FB, "ard", 39, [39], [
        "Take me somewhere I can rinse off standing up.",
        "Could you take me where I can wash my whole body after my run?",
        "wash whole body, standing",
        "I'm sweaty from the gym and need to clean up head to toe; just washing hands at a basin won't do.",
        "This is where a person washes their whole body under falling water. It is behind a glass screen in the bathroom.",
        "i need to rinse off after football, where can i stnad under running water",
    ]),
    (FB, "od", 26, [26], [
        "Go to the lamp with the green glass shade.",
        "Could you take me to the banker's style light with the brass base?",
        "green-shaded brass desk light",
        "I need good light for paperwork, so the green glass banker's light, not the white bedside ones.",
        "This is a classic reading light with a green glass shade. It has a brass base and stands on a desk.",
        "the grene bankers lamp",
    ]),
    # ---------------- flat_e ----------------
    (FE, "o", 7, [7, 29], [
        "Go to a mirror.",
        "Could you take me to something I can see my reflection in?",
        "looking glass",
        "I want to check my hair before I leave, so any mirror, not the TV screen.",
        "This is a reflective glass surface on a wall. It is for checking how you look.",
        "wheres a miror so i can fix my makeup",
    ]),
    (FE, "ord", 14, [14], [
        "Go to the black metal chair in the dining room.",
        "Could you take me to the odd one out among the dining room seats, the black metal one?",
        "black bistro seat, dining room",
        "I want the one that doesn't match, the black metal seat in the dining room, not the sage green wooden ones.",
        "This is a black metal bistro-style seat. It is in the dining room and looks different from the others around the table.",
        "the blak metal chair in the dining room",
    ]),
    (FE, "s", 13, [13], [
        "Go to the chair at the north-west corner of the dining table.",
        "Could you take me to the seat at the table's north-west corner in the dining room?",
        "dining seat, north-west corner of table",
        "I want my usual place, the seat at the north-west corner of the dining table, not the black one at the north-east corner.",
        "This is a sage green wooden dining seat. It is at the north-west corner of the dining table.",
        "the chair at the nortwest corner of the dinner table",
    ]),
    (FE, "ard", 33, [33], [
        "Take me to something that will dry my wet laundry.",
        "Could you show me where I can get my washed clothes dry?",
        "dry wet clothes",
        "The wash has finished and the clothes are soaking, so I need to dry them by machine, not put them back in the washer.",
        "This is where damp clothes go after washing. It tumbles them with warm air until they are dry.",
        "my clothes are still soakng wet, where can i dry them",
    ]),
    # ---------------- flat_g ----------------
    (FG, "o", 2, [2, 3], [
        "Go to a bicycle.",
        "Could you take me to one of the bikes?",
        "bike",
        "I want to go for a ride, so any of the bikes, I don't mind which size.",
        "This is a two-wheeled pedal vehicle. It is kept in the garage.",
        "where r the bikse",
    ]),
    (FG, "or", 34, [34, 35], [
        "Go to a lamp in the bedroom.",
        "Could you take me to one of the bedroom bedside lights?",
        "bedroom reading light",
        "I want to read in bed, so any light in the bedroom, not the floor lamp in the living room.",
        "This is a small light with a shade. It is in the bedroom on a bedside table.",
        "a bedside ligth in the bedroom",
    ]),
    (FG, "s", 34, [34], [
        "Standing at the foot of the bed facing the headboard, go to the lamp on your left.",
        "Could you take me to the left bedside light, as seen from the foot of the bed looking at the headboard?",
        "bedside light, left, from foot of bed",
        "I sleep on the left side when looking at the bed from its foot, so that side's light, not the one on the right.",
        "This is a bedside light on a white nightstand. Seen from the foot of the bed facing the headboard, it is the one on the left.",
        "from the end of the bed lookin at the headboard, the lamp on the left",
    ]),
    (FG, "ard", 11, [11], [
        "Take me somewhere I can press the creases out of my shirt.",
        "Could you show me where I can iron my clothes?",
        "press shirt creases",
        "I have an interview and my trousers are wrinkled, so I need to smooth them with heat, not just wash them.",
        "This is where you flatten wrinkled clothes with a hot iron. It has a padded cover to lay the fabric on.",
        "my shirt is all crumpld, where do i iron it",
    ]),
    # ---------------- flat_i ----------------
    (FI, "od", 31, [31], [
        "Go to the white mug with red stripes.",
        "Could you take me to the striped cup that's upside down?",
        "red-striped white cup",
        "I want the stripy one, the white cup with red lines that's turned over, not the blue pencil mug.",
        "This is a white drinking cup decorated with red stripes. It is placed upside down on the kitchen worktop.",
        "the white cup with red strips, flipped over",
    ]),
    (FI, "ord", 46, [46], [
        "Go to the bedside lamp with the woven rattan shade in the bedroom.",
        "Could you take me to the bedroom light whose shade is woven from rattan?",
        "rattan-shade light, bedroom",
        "I like the patterned glow, so the rattan shaded light in the bedroom, not the one with the ceramic base.",
        "This is a bedside light with a woven rattan shade. It is in the bedroom on the white nightstand and casts patterned light.",
        "the rattan lamp in the bedrom",
    ]),
    (FI, "ord", 14, [14], [
        "Go to the blue mesh chair in the studio.",
        "Could you take me to the blue mesh task seat in the studio?",
        "blue mesh seat, studio",
        "I'm working at the oak drafting desk today, so the blue mesh seat in the studio, not the black leather one.",
        "This is a blue mesh office seat on castors. It is in the studio, pushed under the oak desk.",
        "the blue mesh chiar in the studio",
    ]),
    (FI, "s", 7, [7], [
        "Go to the red chair closest to the wall screen in the meeting room.",
        "Could you take me to whichever red seat in the meeting room is nearer the big display?",
        "red seat nearest display, meeting room",
        "I'm presenting, so I want the red seat near the screen, not the red one farther from it.",
        "This is a red plastic shell seat in the meeting room. Of the two red ones it is the closer to the display on the east wall.",
        "red chair closest to the tv in the meetng room",
    ]),
    # ---------------- apartment ----------------
    (APT, "o", 8, [8, 39, 55], [
        "Go to a plant.",
        "Could you take me to one of the houseplants?",
        "potted greenery",
        "I want to water something green, so any plant in a pot, I don't mind which room.",
        "This is a living green thing growing in a pot. It is kept indoors as decoration.",
        "wheres a house plnat",
    ]),
    (APT, "or", 23, [23, 24], [
        "Go to a chair in the kitchen.",
        "Could you take me to one of the dining seats in the kitchen?",
        "kitchen dining seat",
        "I want to eat at the table, so any kitchen seat, not the office swivel chair.",
        "This is a wooden seat that goes with the dining table. It is in the kitchen.",
        "a seat in the kitchn",
    ]),
    (APT, "or", 12, [12, 13], [
        "Go to a book in the living room.",
        "Could you take me to one of the volumes on the living room shelves?",
        "living room book",
        "I want something to flip through on the sofa, so any volume from the living room bookcase, not the office textbook.",
        "This is a bound volume with paper pages. It is on the living room bookshelf.",
        "any volumne in the living room",
    ]),
    (APT, "od", 31, [31], [
        "Go to the black-and-white photo of a lighthouse.",
        "Could you take me to the small monochrome picture showing a lighthouse?",
        "lighthouse photo, thin black frame",
        "I want to see the seaside print, the lighthouse shot, not the big blue and orange abstract painting.",
        "This is a little monochrome photograph hanging in the hallway. It shows a lighthouse and has a slim dark frame.",
        "the lighthose photo in the hallway",
    ]),
    (APT, "ord", 14, [14], [
        "Go to the mustard yellow pillow in the living room.",
        "Could you take me to the yellow tasselled cushion in the living room?",
        "yellow cushion, living room sofa",
        "I want the colourful one, the yellow cushion in the living room, not the white one on the bed.",
        "This is a yellow throw cushion with tassels. It rests on the gray couch in the living room.",
        "the yelow cushion in the living room",
    ]),
    (APT, "ord", 51, [51], [
        "Go to the black metal bookshelf in the office.",
        "Could you take me to the industrial metal shelving in the office?",
        "black metal shelves, office",
        "I need a manual, so the metal shelving unit in the office, not the walnut bookcase in the living room.",
        "This is a black metal shelving unit full of binders. It stands in the office.",
        "the blak metal bookshelf in the office",
    ]),
    (APT, "ard", 54, [54], [
        "Take me to where I can print out a document.",
        "Could you show me where I can get a paper copy of my boarding pass?",
        "print document",
        "I need a hard copy of this contract; reading it on the laptop isn't enough.",
        "This is where a file on the computer becomes ink on paper. It sits above the gray filing cabinet in the office.",
        "i need to pritn my ticket",
    ]),
    (APT, "ard", 29, [29], [
        "Take me to where I can hang my coat when I come in.",
        "Could you show me where to hang up my wet jacket by the entrance?",
        "hang coat by front door",
        "I just got in from the rain and want to hang my raincoat near the door, not put it away in the bedroom wardrobe.",
        "This is where outdoor jackets are hung up. It is by the front door in the hallway.",
        "where do i hang my jakcet when i get home",
    ]),
    (APT, "s", 39, [39], [
        "Go to the plant on top of the dresser.",
        "Could you take me to the little potted succulent sitting on the chest of drawers?",
        "succulent on top of drawers",
        "I want to water the tiny one, the pot sitting on the bedroom chest of drawers, not the floor plants.",
        "This is a tiny succulent in a clay pot. It is on top of the dark chest of drawers in the bedroom.",
        "the little succulant on top of the dresser",
    ]),
    (APT, "s", 23, [23], [
        "Go to the dining chair closest to the stove.",
        "Could you take me to whichever kitchen seat is nearer the cooker?",
        "dining seat nearest cooker",
        "I want to keep an eye on the pot, so the kitchen seat nearest the stove, not the white one across the table from it.",
        "This is a wooden dining seat with a green cushion. Of the kitchen seats, it is the one closest to the stove.",
        "kitchen chiar nearest the oven",
    ]),
    # ---------------- scans ----------------
    (SL, "o", 2, [2, 3, 4], [
        "Go to a pillow.",
        "Could you find me a cushion?",
        "sofa cushion",
        "I need something to hug while watching TV, any cushion, red or yellow is fine.",
        "This is a soft square cushion. It sits on the sofa.",
        "wheres a cusion",
    ]),
    (SL, "ard", 24, [24], [
        "Take me to what I can use to change the channel.",
        "Could you show me what I'd use to turn the volume down from the sofa?",
        "change channel",
        "I want to switch shows without getting up, so the handheld thing, not the TV itself.",
        "This is a small handheld device with buttons. It lies on the coffee table and controls the television.",
        "i wanna flip chanels without standing up",
    ]),
    (SL, "s", 2, [2], [
        "Sitting on the sofa facing the TV, go to the red pillow on your left.",
        "Could you take me to the red cushion on the left, as seen by someone sitting on the sofa facing the TV?",
        "red cushion, left side, sitting facing TV",
        "When I sit on the couch looking at the TV, I want the red cushion to my left, not the red one on my right.",
        "This is a red cushion on the gray sofa. For someone seated facing the TV, it is the one at the left end.",
        "sitting on the couch looking at the tv, the red pilow on the left",
    ]),
    (SL, "s", 10, [10], [
        "Go to the table lamp nearest the green armchair.",
        "Could you take me to the light on whichever side table is closer to the green armchair?",
        "light nearest green armchair",
        "I'm going to read in the green armchair, so take me to the side-table light nearest it, not the one at the other end of the sofa.",
        "This is a small white light on a side table. It is the one nearest the green armchair.",
        "the lamp closest to the grean armchair",
    ]),
    (SK, "s", 3, [3], [
        "Go to the kitchen cabinet directly under the sink.",
        "Could you take me to the cupboard beneath the sink?",
        "cupboard under sink",
        "I need the dish soap refill, so the base cupboard right below the sink, not the one under the coffee maker.",
        "This is a white lower cupboard. It sits directly beneath the sink.",
        "the cubpoard under the sink",
    ]),
    (SK, "od", 4, [4], [
        "Go to the gray kitchen cabinet.",
        "Could you take me to the one gray cupboard among the white ones?",
        "gray cupboard",
        "I want the odd-coloured cupboard, the gray one, not any of the white ones.",
        "This is a lower cupboard in gray. It is the only one that is not white.",
        "the grey cuboard",
    ]),
    (SO, "s", 15, [15], [
        "Go to the middle bookshelf of the three.",
        "Could you take me to the bookcase between the other two?",
        "middle bookcase",
        "The book I want is in the centre one, so the bookcase between the other two, not either end.",
        "This is a tall wooden bookcase along the north wall. It stands between the other two bookcases.",
        "the bookshelf in the midle",
    ]),
    (SO, "s", 10, [10], [
        "Go to the office chair nearest the door.",
        "Could you take me to whichever desk chair is closest to the door?",
        "swivel seat nearest door",
        "I'll be in and out all day, so give me the seat closest to the door, not one of the ones by the windows.",
        "This is a blue swivel desk chair. Of all the desk chairs, it is the one closest to the door.",
        "the ofice chair closest to the door",
    ]),
    (SB, "s", 7, [7], [
        "Standing at the foot of the bed and facing the headboard, go to the nightstand on your right.",
        "Could you take me to the bedside table on the right, as seen from the foot of the bed looking toward the pillows?",
        "bedside table, right, from foot of bed",
        "My glasses are on my side, which is the right when you look at the bed from its foot, so not the other bedside table.",
        "This is a wooden bedside table. Seen from the foot of the bed facing the headboard, it is the one on the right.",
        "from the foot of the bed, the nightstnad on the right",
    ]),
    (SB, "ard", 21, [21], [
        "Take me to something that tells me what time it is.",
        "Could you show me where I can check the time in the bedroom?",
        "check time",
        "I'm worried I'm late, so I need to see the hour, and I don't want to open my laptop.",
        "This is a small black device that shows the hour. It sits on the nightstand by the bed.",
        "what tiem is it, take me to whatever shows it",
    ]),
]


def main():
    out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round46.jsonl"
    assert len(GROUPS) == 48, len(GROUPS)
    lines = []
    for g, (mp, typ, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6 and target in accept
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b46-g{g:02d}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": sorted(accept), "group": f"b46-g{g:02d}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {out}")


if __name__ == "__main__":
    main()
