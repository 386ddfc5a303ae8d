"""Hand-written blind suite round 39: 48 groups x 6 wordings. Writes evals/blind/round39.jsonl."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
CO3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
AP = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

# (type, map, target, accept, [w1 plain, w2 polite, w3 telegraphic, w4 context, w5 two sentences, w6 casual+typo])
GROUPS = [
    # ---- caption maps ----
    ("o", CO3, 4, [4, 11, 12, 27], [
        "Go to the curtains.",
        "Could you take me to one of the drapes, please?",
        "window drapes",
        "I want to shut out the light, so head over to where the curtains hang.",
        "This is a fabric panel hanging from a rod beside a window. It can be drawn closed for privacy.",
        "can u go find the drpes by the window"]),
    ("o", C829, 112, [112, 157, 219, 229, 233], [
        "Go to a mirror frame.",
        "Could you find me a framed mirror?",
        "framed looking glass",
        "I want to check my hair, so bring me to any mirror with a border around it.",
        "This is a mirror set inside a decorative surround. It hangs so you can see yourself.",
        "where's a mirorr with a frame around it"]),
    ("o", CO3, 8, [8, 13, 20, 40], [
        "Go to a pillow.",
        "Could you show me where a cushion is?",
        "soft cushion",
        "My back hurts on this hard seat, so find me a throw pillow to lean on.",
        "This is a small soft stuffed object for resting against. It usually sits on a couch.",
        "need a cusion for my back"]),
    ("or", C829, 261, [261, 263], [
        "Go to the easy chair in the bedroom.",
        "Could you take me to one of the lounge chairs in the bedroom?",
        "bedroom armchair",
        "I want a comfy seat to read in, but only the ones in the bedroom, not the living room.",
        "This is a cushioned armchair for relaxing. It is in the bedroom.",
        "go to the comfy armchair in the bedrom"]),
    ("or", C829, 34, [34, 74], [
        "Go to a side table in the living room.",
        "Could you bring me over to an end table in the living room?",
        "living room end table",
        "I need somewhere to set my drink down, a side table in the living room, not the bedroom ones.",
        "This is an occasional table placed at the side of a seat. It is in the living room.",
        "take me to the little end tabel in the living room"]),
    ("or", C829, 195, [195, 216, 228], [
        "Go to a cabinet in the bathroom.",
        "Could you take me to one of the bathroom cupboards?",
        "bathroom cupboard",
        "I'm looking for storage, specifically the wooden cupboards in the bathroom, not the one in the kitchen or bedroom.",
        "This is a dark wooden storage cupboard. It is in the bathroom.",
        "wheres a cupbaord in the bathroom"]),
    ("od", CO3, 7, [7], [
        "Go to the white desk.",
        "Could you take me to the white wooden desk?",
        "white wood workstation",
        "I need the white writing table, not either of the brown wooden ones.",
        "This is a work table painted white and made of wood. It has a USB port built in.",
        "go to the whtie writing table"]),
    ("od", C829, 197, [197], [
        "Go to the red leather book.",
        "Could you find the red volume bound in leather?",
        "red leather-bound volume",
        "I want the red one with the leather binding, not the red paper one.",
        "This is a red hardbound volume with a leather cover. It has gold lettering pressed into the front.",
        "grab me the red lether book"]),
    ("od", CO3, 13, [13], [
        "Go to the navy blue pillow.",
        "Could you take me to the dark blue velvet cushion?",
        "navy velvet cushion",
        "I want the velvety navy one, not the orange or yellow cushions.",
        "This is a dark blue cushion with a velvet feel. It has a button in the middle.",
        "find the navy pilow pls"]),
    ("ord", C829, 184, [184], [
        "Go to the L-shaped couch in the bedroom.",
        "Could you take me to the corner sofa with the chaise in the bedroom?",
        "L-shaped sofa, bedroom",
        "Not the beige one in the living room; I mean the L-shaped settee in the bedroom.",
        "This is a beige fabric sofa shaped like an L. It stands in the bedroom.",
        "go to the l shaped sofa in the bedrooom"]),
    ("ord", CO3, 37, [37], [
        "Go to the black plastic chair with the speaker in the rec room.",
        "Could you take me to the seat in the rec room that has a built-in speaker?",
        "rec room seat with speaker",
        "I want to sit and listen to music, so find the rec room seat with a speaker, not one of the mesh ones.",
        "This is a black plastic seat with a speaker and a massage function. It is in the rec room.",
        "which chiar in the rec room has the speaker"]),
    ("ard", C829, 122, [122], [
        "Take me somewhere I can relieve myself.",
        "Could you show me where I can empty my bladder?",
        "need to pee",
        "Nature calls and I can't wait, so guide me to where I can do my business.",
        "This is the ceramic fixture you sit on to relieve yourself. It is in one of the bathrooms.",
        "really need to pee rn, take me to the rigth spot"]),
    ("ard", CO3, 67, [67], [
        "Bring me to the thing I can use to control the devices from my seat.",
        "Could you help me find something to switch channels without standing up?",
        "change channel from couch",
        "The buttons on the device are too far away, so take me to whatever lets me operate it from across the room.",
        "This is the handheld thing with buttons for operating a screen from a distance. It lets you change settings without getting up.",
        "wanna flip chanels without getting up"]),
    # ---- flats ----
    ("o", FC, 5, [5, 7, 28, 36], [
        "Go to a lamp.",
        "Could you take me to a light fixture?",
        "any light",
        "It's getting dark, so take me to any lamp, I don't mind which room.",
        "This is a device that gives off light. It has a shade or bulb on a base.",
        "go to a lmap"]),
    ("o", FH, 13, [13, 26, 32], [
        "Go to a mug.",
        "Could you find me a cup to drink from?",
        "coffee cup",
        "I want my tea, so take me to any of the mugs, whichever room it's in.",
        "This is a drinking vessel with a handle. It holds hot drinks.",
        "where is a coffe cup"]),
    ("or", FF, 12, [12, 13, 14, 15], [
        "Go to a chair in the kitchen.",
        "Could you take me to one of the kitchen chairs?",
        "kitchen seat",
        "Take me to a seat in the kitchen; I don't mean the rocker on the porch.",
        "This is a painted wooden seat by the dining table. It is in the kitchen.",
        "find a seat in the kitchn"]),
    ("or", FH, 46, [46, 47], [
        "Go to a nightstand in the master bedroom.",
        "Could you take me to a bedside table in the master bedroom?",
        "master bedroom bedside table",
        "Not the one in the guest room; I mean a bedside table in the main bedroom.",
        "This is a small table next to the double bed. It is in the main bedroom.",
        "go to one of the night tables in the big bedrom"]),
    ("od", FD, 5, [5], [
        "Go to the yellow chair.",
        "Could you take me to the yellow painted wooden seat?",
        "yellow wooden seat",
        "I don't want the white plastic one; take me to the yellow wooden seat at the table.",
        "This is a wooden seat painted yellow. It stands at a round table.",
        "go to the yelow chair pls"]),
    ("od", FH, 6, [6], [
        "Go to the cream sofa.",
        "Could you take me to the small cream linen couch?",
        "cream two-seater",
        "I want the small cream one, not the long green velvet sofa.",
        "This is a small couch covered in cream linen. It seats two people.",
        "go sit on the little crem loveseat"]),
    ("ord", FC, 36, [36], [
        "Go to the green lamp in the study.",
        "Could you take me to the green metal desk light in the study?",
        "study green desk light",
        "I need light to read papers in the study, so the green banker's-style one, not a bedroom lamp.",
        "This is a small green metal light on a desk. It is in the study.",
        "go to the grean desk light in the study"]),
    ("ord", FH, 48, [48], [
        "Go to the white lamp in the master bedroom.",
        "Could you take me to the white ceramic bedside light in the master bedroom?",
        "master bedroom white bedside light",
        "Not the red one in the guest room; I want the white bedside light in the master bedroom.",
        "This is a bedside light with a white ceramic base. It is in the main bedroom.",
        "go to the whte reading light in the master bedroom"]),
    ("ord", FD, 33, [33], [
        "Go to the green chair in the kids room.",
        "Could you take me to the little green plastic seat in the children's room?",
        "kids room small green seat",
        "My daughter wants her own seat, the green one in the kids room, not a grown-up chair.",
        "This is a small green plastic seat for a child. It is in the kids' room by the yellow desk.",
        "go to the tiny gren seat in the kids room"]),
    ("ard", FD, 24, [24], [
        "Take me to where I can wash my dirty clothes.",
        "Could you show me where I can do a load of laundry?",
        "wash dirty clothes",
        "My jeans are muddy and need a proper wash, not just drying; take me to what cleans them.",
        "This is the appliance that cleans dirty clothes with water and soap. It is in the laundry room.",
        "need to wash my sheeets, where do i go"]),
    ("ard", FF, 4, [4], [
        "Take me to where I can light a log fire.",
        "Could you show me where I can burn some firewood to warm up?",
        "log fire",
        "I'm freezing and want a crackling wood fire, not the cooker in the kitchen.",
        "This is the spot where you can burn logs to heat the room. It is built of stone in the living room.",
        "wanna light a fier with the logs"]),
    ("ard", FH, 4, [4], [
        "Take me to where I can drop my house keys.",
        "Could you show me where the keys usually get left when someone comes home?",
        "keys drop spot",
        "I just came in and don't want to lose my keys again, so take me to the place they normally go.",
        "This is where the house keys are left on the way in. It sits on the narrow table in the hallway.",
        "where do i leave my kyes"]),
    ("s", FC, 20, [20], [
        "Go to the chair nearest the fridge.",
        "Could you take me to the seat closest to the refrigerator?",
        "chair closest fridge",
        "I want to grab a drink and sit right away, so the seat nearest the fridge, not the ones further from it.",
        "This is a dining seat at the table. It is the one closest to the fridge-freezer.",
        "go to the seat closest to the frigde"]),
    ("s", FH, 17, [17], [
        "Go to the dining chair nearest the window.",
        "Could you bring me to the seat at the dining table that's closest to the window?",
        "dining seat closest window",
        "I want some daylight while I eat, so the seat at the table closest to the window, not the others.",
        "This is a black metal seat at the dining table. Of all the table's seats, it is nearest the window.",
        "go to the dining seat closest to the windo"]),
    ("s", FD, 22, [22], [
        "Go to the stool nearest the fridge.",
        "Could you take me to the high seat closest to the refrigerator?",
        "counter seat nearest fridge",
        "Of the two high seats in the kitchenette, I want the one nearer the fridge.",
        "This is a backless seat in the kitchenette. It is the one closer to the fridge.",
        "go to the stool nearest the frdge"]),
    ("s", FF, 2, [2], [
        "Go to the armchair nearest the fireplace.",
        "Could you take me to the easy chair closest to the fireplace?",
        "armchair by fireplace",
        "I want to warm up, so the upholstered seat closest to the hearth, not the one across the room.",
        "This is a cushioned seat with arms in the living room. It is the one nearest the stone hearth.",
        "sit me in the comfy chair closest to the firplace"]),
    # ---- apartment ----
    ("o", AP, 12, [12, 13, 52], [
        "Go to a book.",
        "Could you take me to any of the books?",
        "reading volume",
        "I'm bored and want something printed to read; any volume in the flat is fine.",
        "This is a bound set of printed pages. You read it.",
        "find me a bok"]),
    ("or", AP, 23, [23, 24], [
        "Go to a kitchen chair.",
        "Could you find me a seat in the kitchen?",
        "seat, kitchen",
        "I want to eat at the table, so a seat in the kitchen, not the office one.",
        "This is a wooden seat at the dining table. It is in the kitchen.",
        "take me to a chiar in the kitchen"]),
    ("od", AP, 2, [2], [
        "Go to the brown leather loveseat.",
        "Could you take me to the small brown leather couch?",
        "brown leather two-seater",
        "Not the big gray one; I want the brown leather sofa.",
        "This is a small two-seat couch in brown leather. It stands against the west wall of the living room.",
        "go to the brwon leather couch"]),
    ("ord", AP, 53, [53], [
        "Go to the filing cabinet in the office.",
        "Could you take me to the gray metal drawer unit in the office?",
        "office metal file drawers",
        "I need to put away some paperwork, so the metal filing cabinet in the office, not the kitchen cupboards.",
        "This is a gray metal unit with two drawers for papers. It is in the office, under the printer.",
        "go to the gray file cabnet in the office"]),
    ("ard", AP, 27, [27], [
        "Take me to what I can use to boil water.",
        "Could you take me to something that heats water for tea?",
        "boil water for tea",
        "I'd like a hot cup of tea and I need hot water fast, not the stove.",
        "This is the appliance that boils water for a cuppa. It sits on the kitchen counter.",
        "need hot watter for tea"]),
    ("ard", AP, 54, [54], [
        "Take me to where I can get a paper copy of my document.",
        "Could you show me where I can print out my boarding pass?",
        "print document",
        "The screen is hard on my eyes, so I want this report on paper; take me to the machine for that.",
        "This is the machine that turns documents into paper copies. It is in the office.",
        "gotta print my resumee"]),
    ("s", AP, 12, [12], [
        "Go to the higher of the two books on the living room bookshelf.",
        "Could you take me to the volume on the upper shelf in the living room?",
        "upper-shelf volume, living room",
        "Not the one lying on the bottom shelf; I want the volume standing higher up on the living room shelves.",
        "This is a volume on the living room bookcase. It sits higher up than the other one there.",
        "go to the book up hihg on the living room shelf"]),
    ("s", AP, 39, [39], [
        "Go to the plant on top of the dresser.",
        "Could you take me to the little potted greenery sitting on the chest of drawers?",
        "greenery on dresser",
        "I want to water the potted one up on the chest of drawers, not the ones standing on the floor.",
        "This is a small houseplant. It rests on top of the chest of drawers in the bedroom.",
        "go to the plnat on the dresser"]),
    ("s", AP, 23, [23], [
        "Go to the chair closest to the stove.",
        "Could you take me to the dining seat nearest the cooker?",
        "seat nearest stove",
        "I want to keep an eye on the pot while sitting, so the seat closest to the stove, not the one on the far side.",
        "This is a wooden seat at the dining table. It is the one nearest the cooker.",
        "go to the chair closest to the stvoe"]),
    # ---- scans ----
    ("o", SB, 2, [2, 3, 4, 5], [
        "Go to a pillow.",
        "Could you take me to a cushion?",
        "any cushion",
        "My neck is sore, so any pillow will do, whichever color.",
        "This is a soft padded item you rest your head on. Several are on the bed.",
        "take me to a cushon"]),
    ("or", SK, 26, [26, 27], [
        "Go to a trash can in the kitchen.",
        "Could you take me to a bin in the kitchen?",
        "kitchen bin",
        "I have peelings to throw out, so any rubbish bin in the kitchen will do.",
        "This is a container for waste. It is in the kitchen.",
        "where's a garbage bin in the kitchn"]),
    ("od", SK, 21, [21], [
        "Go to the red chair.",
        "Could you take me to the red seat?",
        "red seat",
        "Not one of the black ones or the white one; I want the red chair.",
        "This is a seat at the table. It is red.",
        "go sit on the red chiar"]),
    ("ord", SO, 30, [30], [
        "Go to the white keyboard in the office.",
        "Could you take me to the white thing I type on in the office?",
        "office white keyboard",
        "The black one is taken, so take me to the white one for typing in the office.",
        "This is a white input device for typing. It sits on a table in the office.",
        "go to the white keybord in the office"]),
    ("ard", SK, 12, [12], [
        "Take me to where I can brew a coffee.",
        "Could you show me what I can use to make an espresso?",
        "brew coffee",
        "I need caffeine before work; take me to what makes it, not the microwave.",
        "This is the machine that brews hot coffee. It stands on the counter in the kitchen.",
        "need my morning cofee"]),
    ("s", SO, 10, [10], [
        "Go to the office chair nearest the door.",
        "Could you take me to the desk seat closest to the door?",
        "seat nearest door",
        "I may need to leave quickly, so the desk seat closest to the door, not one deep in the room.",
        "This is a swivel seat at one of the tables. It is the one closest to the door.",
        "go to the swivel chair closest to the dor"]),
    ("s", SO, 16, [16], [
        "Go to the lowest bookshelf.",
        "Could you take me to the lowest of the bookcases?",
        "lowest bookcase",
        "I can't reach high, so the low bookcase, not the two tall ones.",
        "This is a set of shelves along the north wall. It is the lowest of the three.",
        "go to the short bookcsae"]),
    ("s", SB, 8, [8], [
        "Go to the lamp on the left when you stand at the foot of the bed facing the headboard.",
        "Could you take me to the bedside light on the left side, as seen from the foot of the bed?",
        "left bedside light, facing headboard",
        "I sleep on the left side when looking at the bed from its foot, so that side's lamp, not the right one.",
        "This is a bedside light on a nightstand. Standing at the foot of the bed and looking at the headboard, it is on your left.",
        "go to the left bedside light when ur facing the headbord"]),
    ("s", SK, 3, [3], [
        "Go to the cabinet under the sink.",
        "Could you take me to the cupboard beneath the sink?",
        "cupboard under sink",
        "I need the dish soap refill, which is in the cupboard below the sink, not the wall ones.",
        "This is a base cupboard in the kitchen. The sink sits directly on top of it.",
        "go to the cupbord under the sink"]),
    ("s", SL, 3, [3], [
        "Go to the pillow between the other two on the sofa.",
        "Could you take me to the cushion in the middle of the couch?",
        "middle cushion on sofa",
        "Not the ones at either end; I want the cushion between them on the sofa.",
        "This is a cushion on the sofa. It sits between the two others.",
        "go to the midle cushion on the couch"]),
]


def rows():
    out = []
    for g, (typ, mp, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, g
        for k, q in enumerate(words, 1):
            out.append({"id": f"b39-g{g:02d}-w{k}", "map": mp, "query": q, "type": typ,
                        "target": target, "accept": sorted(accept), "group": f"b39-g{g:02d}"})
    return out


if __name__ == "__main__":
    path = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round39.jsonl"
    path.write_text("".join(json.dumps(r) + "\n" for r in rows()), encoding="utf-8")
    print(f"wrote {len(GROUPS)} groups, {len(rows())} lines to {path}")
