#!/usr/bin/env python3
"""Hand-written blind query suite round 37. Emits evals/blind/round37.jsonl.
Each group: (map, type, target, accept, meta, [w1..w6]). `meta` is read by check.py."""
import json, os

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
APT = "apartment"
SB, SK, SL, SO = "../maps/scan_bedroom.json", "../maps/scan_kitchen.json", "../maps/scan_livingroom.json", "../maps/scan_office.json"

G = [
# ---------------- caption maps (12) ----------------
(OF3, "o", 8, [8, 13, 20, 40], {"label": "pillow"}, [
 "Go to a pillow.",
 "Could you take me to one of the cushions?",
 "any cushion",
 "I want something soft to prop behind my back, so find me a throw cushion; any colour will do.",
 "This is a soft cushion. It is one of several lying around the rec room.",
 "can you find me a cushoin, whichever one"]),
(C829, "o", 160, [160, 162, 164], {"label": "set of towels"}, [
 "Go to the folded towels.",
 "Could you show me where the stacks of towels are?",
 "towel pile",
 "I just got out of the shower and need to dry off, so take me to a set of towels, not the toiletry bag.",
 "These are clean white towels folded into a pile. They are kept together in one spot.",
 "where are the clean towles"]),
(C829, "or", 261, [261, 263], {"label": "easy chair", "room": "bedroom"}, [
 "Go to an easy chair in the bedroom.",
 "Could you take me to one of the armchairs in the bedroom?",
 "bedroom armchair",
 "I want to sit and read in the bedroom, so any lounge chair in there, not the ones in the living room.",
 "This is a comfy brown armchair. It stands in the bedroom.",
 "take me to a comfy chair in the bedrom"]),
(C829, "or", 182, [182, 250], {"label": "side table", "room": "bedroom"}, [
 "Go to a side table in the bedroom.",
 "Could you bring me to one of the little end tables in the bedroom?",
 "bedroom end table",
 "I need to set my glass down next to me in the bedroom; any side table in there works, not the ones in the living room.",
 "This is a small occasional table with a glass top. It is located in the bedroom.",
 "find an end tabel in the bedroom"]),
(OF3, "od", 13, [13], {"label": "pillow"}, [
 "Go to the navy blue velvet pillow.",
 "Could you find the dark blue velvety cushion for me?",
 "navy velvet cushion",
 "I want the deep blue soft one, not the orange or yellow cushions.",
 "This is a cushion covered in navy velvet. It has a plush, velvety feel.",
 "go to the navy blue cusion"]),
(OF3, "od", 7, [7], {"label": "desk"}, [
 "Go to the white desk.",
 "Could you take me to the white wooden writing table?",
 "white work table",
 "I need the white one to work at, not either of the brown wooden desks.",
 "This is a white wooden workstation. It is the only light-coloured one in the room.",
 "take me to the whte writing table"]),
(C829, "od", 211, [211], {"label": "decorative bowl"}, [
 "Go to the deep blue bowl with gold patterns.",
 "Could you show me the blue ceramic dish with golden decoration?",
 "blue gold ornamental bowl",
 "I mean the blue ornamental one with gold detailing, not the white bowl of sweets.",
 "This is a glossy blue ceramic bowl. It is decorated with gold patterns.",
 "where's the blue bwol with the gold pattern"]),
(C829, "ord", 219, [219], {"label": "mirror frame", "room": "bedroom"}, [
 "Go to the mirror in the bedroom.",
 "Could you take me to the dark wooden mirror in the bedroom?",
 "bedroom mirror dark wood",
 "I want to check my outfit in the bedroom mirror, not one of the bathroom mirrors.",
 "This is an ornate mirror with a dark wooden frame. It hangs in the bedroom.",
 "go to the fancy mirorr in the bedroom"]),
(C829, "ord", 87, [87], {"label": "washbasin counter", "room": "bathroom"}, [
 "Go to the white washbasin counter in the bathroom.",
 "Could you take me to the glossy white vanity with the sink in the bathroom?",
 "bathroom white vanity",
 "I want to wash my face at the white vanity in the bathroom, not the one in the living room with the mirror.",
 "This is a shiny white vanity unit with an integrated basin. It is in the bathroom.",
 "take me to the white vanty in the bathroom"]),
(OF3, "ard", 25, [25], {}, [
 "Go to something that tells the time.",
 "Could you take me somewhere I can check the time?",
 "check time",
 "My phone battery is flat and I need to know the time, so take me to whatever on the wall shows it.",
 "This is the thing you look at to know the hour. It hangs on the wall of the rec room.",
 "i need to knw the time"]),
(C829, "ard", 122, [122], {}, [
 "Go to where I can relieve myself.",
 "Could you take me somewhere I can pee?",
 "need to pee",
 "I really need to go, and a sink won't do, so take me to where I can do my business.",
 "This is where you go when nature calls. It is in the bathroom and it flushes.",
 "gotta go numbr two, take me there"]),
(C829, "ard", 192, [192], {}, [
 "Go to where my dog can sleep.",
 "Could you show me where the dog naps?",
 "dog sleeping spot",
 "The puppy is tired; take me to its own sleeping place, not our bed.",
 "This is a soft place for an animal to curl up. It is meant for a cat or dog to rest on.",
 "where does the kitty slepe"]),
# ---------------- flats (17) ----------------
(FC, "o", 5, [5, 7, 28, 36], {"label": "lamp"}, [
 "Go to a lamp.",
 "Could you take me to one of the lights?",
 "any light",
 "It's getting dark and I want to read, so go to any lamp; it doesn't matter which.",
 "This is a source of light you switch on. It may stand on the floor, a table or a desk.",
 "go to a lmap, any of them"]),
(FC, "s", 7, [7], {"claims": [["on", 7, 6], ["taller", 5, 7]]}, [
 "Go to the lamp that stands on the side table.",
 "Could you take me to the light sitting on the small table at the end of the sofa?",
 "light on little table by sofa",
 "I want the lamp on top of the small black table, not the tall floor-standing one.",
 "This is a small light. It is placed on top of the little metal table beside the couch.",
 "the lihgt on the side table pls"]),
(FC, "ord", 21, [21], {"label": "chair", "room": "kitchen", "tags": {"color": "black", "material": "metal"}}, [
 "Go to the black metal chair in the kitchen.",
 "Could you take me to the dark metal seat at the kitchen table?",
 "black metal kitchen seat",
 "I'll sit on the black metal one in the kitchen, not the white wooden ones.",
 "This is a black metal seat. It is at the dining table in the kitchen.",
 "go to the blak metal chair in the kitchen"]),
(FC, "ard", 17, [17], {}, [
 "Go to something I can boil water in.",
 "Could you take me to where I can heat water for tea?",
 "boil water",
 "I want to make a cup of tea; take me to whatever heats the water quickly, not the stove.",
 "This is an electric appliance for boiling water. It sits on the kitchen counter.",
 "i wanna make some tea, need hot watr"]),
(FD, "or", 4, [4, 5, 7], {"label": "chair", "room": "studio"}, [
 "Go to a chair in the studio.",
 "Could you take me to a single seat in the studio?",
 "chair, studio",
 "I need to sit down for a minute in the studio; any of the one-person seats there will do, not the little one in the kids' room.",
 "This is a seat for one person with a backrest. It stands in the studio.",
 "take me to a seat for one in the stuido"]),
(FD, "od", 5, [5], {"label": "chair", "tags": {"color": "yellow"}}, [
 "Go to the yellow wooden chair.",
 "Could you take me to the yellow painted seat?",
 "yellow wooden seat",
 "Not the white plastic one: I want the yellow painted one at the round table.",
 "This is a wooden seat painted yellow. It is pulled up to the round dining table.",
 "go to the yelow chair"]),
(FD, "s", 22, [22], {"claims": [["nearest", 22, [21, 22], 15], ["nearest", 21, [21, 22], 18]]}, [
 "Go to the stool nearest the fridge.",
 "Could you take me to the backless seat closest to the refrigerator?",
 "high seat closest fridge",
 "I want the bar perch next to the fridge, not the one nearer the hob.",
 "This is a high seat without a back. Of the two in the kitchenette, it is the one closer to the fridge-freezer.",
 "the stol by the fridge"]),
(FD, "ard", 25, [25], {}, [
 "Go to the machine that dries clothes.",
 "Could you take me to where I can dry my wet laundry?",
 "dry wet clothes",
 "The wash just finished and I need to get the clothes dry; not the washer, the other machine.",
 "This is an appliance that tumbles clothes with warm air until they are dry. It stands next to the washer.",
 "my clothes are still wet, need to dyr them"]),
(FF, "o", 7, [7, 32], {"label": "rug"}, [
 "Go to a rug.",
 "Could you take me to one of the floor rugs?",
 "carpet, any",
 "I dropped an earring on some carpet; take me to any of the mats on the floor, it doesn't matter which.",
 "This is a woven covering lying on the floor. It could be any of the ones in the house.",
 "go to a carpt"]),
(FF, "or", 12, [12, 13, 14, 15], {"label": "chair", "room": "kitchen"}, [
 "Go to a chair in the kitchen.",
 "Could you take me to one of the seats at the kitchen table?",
 "kitchen dining seat",
 "I want to sit down in the kitchen; any of the dining seats there is fine, not the rocking one on the porch.",
 "This is a painted wooden dining chair. It is at the table in the kitchen.",
 "take me to a seat in the kitchn"]),
(FF, "od", 2, [2], {"label": "armchair", "tags": {"color": "red"}}, [
 "Go to the red tartan armchair.",
 "Could you take me to the plaid wingback chair?",
 "red tartan wingback",
 "I want the red checked wool one, not the cream leather armchair.",
 "This is a wingback seat upholstered in red tartan wool. It is near the fireplace.",
 "go to the red tartn chair"]),
(FF, "s", 14, [14], {"claims": [["nearest", 14, [12, 13, 14, 15], 17]]}, [
 "Go to the dining chair nearest the stove.",
 "Could you take me to the seat at the dining table closest to the range cooker?",
 "table seat nearest cooker",
 "I want to sit where it's warm, so the dining seat next to the range cooker, not one of the ones further away.",
 "This is a chair at the farmhouse dining table. It is the one nearest to the cream range cooker.",
 "the chiar closest to the cooker"]),
(FH, "o", 13, [13, 26, 32], {"label": "mug"}, [
 "Go to a mug.",
 "Could you take me to any coffee cup?",
 "any cup",
 "I want a hot drink; take me to any of the mugs, I'm not fussy.",
 "This is a drinking vessel with a handle. There are several of them around the flat.",
 "find me a coffe cup"]),
(FH, "ord", 50, [50], {"label": "wardrobe", "room": "master bedroom", "tags": {"color": "white"}}, [
 "Go to the white wardrobe in the master bedroom.",
 "Could you take me to the glossy white closet in the main bedroom?",
 "master bedroom white closet",
 "I need a clean shirt from the big white wardrobe in the master bedroom, not the pine one in the guest room.",
 "This is a tall, shiny white clothes cupboard with three doors. It stands in the master bedroom.",
 "take me to the white closset in the master bedroom"]),
(FH, "od", 6, [6], {"label": "sofa", "tags": {"color": "cream"}}, [
 "Go to the cream linen sofa.",
 "Could you take me to the small cream two-seater?",
 "cream loveseat",
 "I mean the little cream one under the window, not the long green velvet sofa.",
 "This is a small two-seat couch covered in cream linen. It sits under a window in the living room.",
 "the litle cream couch"]),
(FH, "s", 47, [47], {"claims": [["on", 49, 47], ["on", 48, 46]]}, [
 "Go to the nightstand with the book on it.",
 "Could you take me to the bedside table with a paperback resting on it?",
 "bedside table with novel",
 "My detective novel is on one of the bedside tables; take me to that one, not the one with the lamp.",
 "This is a white bedside table in the master bedroom. An orange paperback rests on top of it.",
 "go to the night stand with the bok on it"]),
(FH, "s", 16, [16], {"claims": [["farthest", 16, [16, 17, 18], 20], ["farthest", 16, [18, 16], 20]]}, [
 "Go to the dining chair farthest from the window.",
 "Could you take me to the seat at the dining table that is furthest from the window?",
 "dining seat farthest from window",
 "The sun is in my eyes; take me to the dining seat farthest from the window, not the rattan one.",
 "This is a black metal bistro chair at the walnut dining table. Of all the chairs there, it is the one farthest from the tall window.",
 "the dining seat furthest from the windw"]),
# ---------------- apartment (9) ----------------
(APT, "o", 30, [30, 43], {"label": "mirror"}, [
 "Go to a mirror.",
 "Could you take me to somewhere I can see my reflection?",
 "looking glass",
 "I want to check my hair before I leave; any mirror will do, hallway or bathroom.",
 "This is a reflective glass panel on a wall. There is more than one in the apartment.",
 "go to a mirorr"]),
(APT, "or", 12, [12, 13], {"label": "book", "room": "living room"}, [
 "Go to a book in the living room.",
 "Could you take me to one of the books in the living room?",
 "living room reading material",
 "I want something to read from the lounge shelves, not the textbook in the office.",
 "This is something to read. It is on the bookshelf in the living room.",
 "take me to a bok in the living room"]),
(APT, "or", 23, [23, 24], {"label": "chair", "room": "kitchen"}, [
 "Go to a chair in the kitchen.",
 "Could you take me to one of the kitchen dining seats?",
 "kitchen seat",
 "I'd like to sit at the kitchen table; either seat there is fine, not the office one.",
 "This is a wooden dining chair. It is pulled up to the table in the kitchen.",
 "take me to a dinning seat in the kitchen"]),
(APT, "ord", 53, [53], {"label": "cabinet", "room": "office", "tags": {"color": "gray", "material": "metal"}}, [
 "Go to the gray metal filing cabinet in the office.",
 "Could you take me to the metal file drawers in the office?",
 "office filing drawers",
 "I need to put away some paperwork in the office's metal filing unit, not the bathroom vanity.",
 "This is a gray metal unit with two drawers for documents. It is in the office, with the printer on top.",
 "go to the filng cabinet in the office"]),
(APT, "ard", 29, [29], {}, [
 "Go to where I can hang my coat.",
 "Could you take me somewhere to hang up my jacket?",
 "hang jacket",
 "I just came in from the rain and want to hang my wet coat, not put it in the wardrobe.",
 "This is where outdoor jackets are hung. It stands by the front door.",
 "where can i hang my jakcet"]),
(APT, "ard", 54, [54], {}, [
 "Go to something that can print my boarding pass.",
 "Could you take me to where I can print out a document?",
 "print document",
 "I need a paper copy of this contract, so take me to whatever makes printouts, not the laptop.",
 "This is the device that puts documents onto paper. It is in the office.",
 "i need to prnt my tickets"]),
(APT, "s", 12, [12], {"claims": [["higher", 12, 13]]}, [
 "Go to the higher of the two books on the living room bookshelf.",
 "Could you take me to the volume sitting higher up on the living room shelves?",
 "upper volume, lounge shelf",
 "Not the one laid down at the very bottom: I want the one standing higher up on the living room bookcase.",
 "This is a volume on the living room shelving. Of the two there, it sits higher.",
 "the higher bok on the living room shelf"]),
(APT, "s", 39, [39], {"claims": [["on", 39, 38]]}, [
 "Go to the plant on top of the dresser.",
 "Could you take me to the potted plant sitting on the chest of drawers?",
 "pot on chest of drawers",
 "Not the big fig in the living room: the little potted one on top of the bedroom dresser.",
 "This is a small potted succulent. It sits on top of the chest of drawers in the bedroom.",
 "the tiny succlent on top of the dresser"]),
(APT, "od", 2, [2], {"label": "sofa", "tags": {"color": "brown", "material": "leather"}}, [
 "Go to the brown leather loveseat.",
 "Could you take me to the small brown leather couch?",
 "brown leather two-seater",
 "I want the worn brown leather one against the wall, not the big gray sofa.",
 "This is a compact two-seat couch in brown leather. It looks a little worn.",
 "go to the brwon leather couch"]),
# ---------------- scans (10) ----------------
(SO, "o", 11, [11, 12, 13], {"label": "monitor"}, [
 "Go to a monitor.",
 "Could you take me to one of the computer screens?",
 "any screen",
 "I need to look at a display; any of the computer screens will do.",
 "This is a black computer display on a table. There are a few of them in the office.",
 "take me to a computr screen"]),
(SL, "or", 2, [2, 3, 4], {"label": "pillow", "room": "living room"}, [
 "Go to a pillow in the living room.",
 "Could you take me to one of the cushions in the living room?",
 "living room cushion",
 "My back hurts; bring me to any throw cushion in the living room, whatever colour.",
 "This is a small cushion. It rests on the sofa in the living room.",
 "go to a cushon in the living room"]),
(SO, "ord", 1, [1], {"label": "table", "room": "office", "tags": {"color": "white"}}, [
 "Go to the white table in the office.",
 "Could you take me to the white work table in the office?",
 "white office desk",
 "Not the brown wooden one: I mean the white worktop in the office.",
 "This is a large white work surface. It is in the office, with black chairs around it.",
 "go to the wite desk in the office"]),
(SK, "ord", 4, [4], {"label": "kitchen cabinet", "room": "kitchen", "tags": {"color": "gray"}}, [
 "Go to the gray cabinet in the kitchen.",
 "Could you take me to the grey cupboard in the kitchen?",
 "grey kitchen cupboard",
 "I need the gray cupboard in the kitchen, not any of the white ones.",
 "This is a low cupboard with a gray front. It is among the base units in the kitchen.",
 "take me to the gray cuboard in the kitchen"]),
(SK, "ard", 11, [11], {}, [
 "Go to something that can reheat my leftovers quickly.",
 "Could you take me to where I can warm up my soup in a minute?",
 "reheat leftovers fast",
 "I want to warm up last night's pizza quickly, not in an oven or on a stove.",
 "This is the appliance that heats food with waves in a couple of minutes. It sits on the counter.",
 "need to heat up my lunh fast"]),
(SB, "s", 8, [8], {"claims": [["nearest", 8, [8, 9], 14], ["nearest", 9, [8, 9], 15]]}, [
 "Go to the lamp closest to the window.",
 "Could you take me to the bedside light nearest the window?",
 "lamp nearest window",
 "I want the bedside light on the window side, not the one by the door.",
 "This is a white bedside light on a nightstand. Of the two, it is the one nearer the window.",
 "the ligth closest to the window"]),
(SO, "s", 10, [10], {"claims": [["nearest", 10, [3, 4, 5, 6, 7, 8, 9, 10], 20]]}, [
 "Go to the office chair nearest the door.",
 "Could you take me to the desk chair closest to the door?",
 "seat closest to door",
 "I just walked in and want to sit right away; the seat nearest the door, not one by the windows.",
 "This is a blue office chair. Of all the swivel seats in the room, it is the one closest to the door.",
 "the swivle seat nearest the door"]),
(SL, "s", 9, [9], {"claims": [["left_from", 9, 8, 14, 1]]}, [
 "Standing at the TV and facing the sofa, go to the side table on your left.",
 "Could you take me to the end table that is on the left when you look at the sofa from the TV?",
 "end table, left of sofa seen from TV",
 "Looking from the TV toward the couch, I want the little table on the left, not the one on the right.",
 "This is a small white table beside the sofa. Seen from the television, it is the one on the left.",
 "from the tv looking at the couch, the end tabel on the left"]),
(SK, "s", 27, [27], {"claims": [["farthest", 27, [26, 27], 15], ["nearest", 27, [26, 27], 13]]}, [
 "Go to the trash can farthest from the door.",
 "Could you take me to the bin furthest from the door?",
 "bin farthest from door",
 "Not the gray bin by the entrance: the other one, far from the door by the fridge.",
 "This is a small black rubbish bin. It is the one farthest from the kitchen door.",
 "the garbge bin far from the door"]),
(SO, "s", 16, [16], {"claims": [["lowest_top", 16, [14, 15, 16]]]}, [
 "Go to the lowest bookshelf.",
 "Could you take me to the shortest of the bookcases?",
 "shortest bookcase",
 "I want the short white one, not either of the tall brown wooden bookshelves.",
 "This is a low white shelving unit against the back wall. It is the shortest of the three shelves there.",
 "the shortst bookcase"]),
]

def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "evals", "blind", "round37.jsonl")
    assert len(G) == 48, len(G)
    with open(out, "w") as f:
        for gi, (mp, typ, tgt, acc, meta, ws) in enumerate(G, 1):
            assert len(ws) == 6
            for wi, q in enumerate(ws, 1):
                f.write(json.dumps({"id": f"b37-g{gi:02d}-w{wi}", "map": mp, "query": q, "type": typ,
                                    "target": tgt, "accept": sorted(acc), "group": f"b37-g{gi:02d}"}) + "\n")
    print("wrote", out)

if __name__ == "__main__":
    main()
