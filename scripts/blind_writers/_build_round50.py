"""Hand-written source of blind suite round 50: 48 groups x 6 wordings.
Each group: (group number, map, type, target, accept, [w1..w6], typo word in w6).
build.py turns this into evals/blind/round50.jsonl."""

B = "maps/flat_b.json"
E = "maps/flat_e.json"
G = "maps/flat_g.json"
I = "maps/flat_i.json"
A = "apartment"
SB = "../maps/scan_bedroom.json"
SK = "../maps/scan_kitchen.json"
SL = "../maps/scan_livingroom.json"
SO = "../maps/scan_office.json"
C8 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
C3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"

GROUPS = [
 # ---------------- scene_00829 (caption map) ----------------
 (1, C8, "o", 42, [42, 197, 212, 259], [
  "Take me to a book, any one at all.",
  "Could you guide me to wherever there's a volume I could leaf through?",
  "Any bound volume, please.",
  "I want something to read tonight, so any hardback will do, not the loose papers.",
  "This is a bit of a random request. Bring me to one of the books in this place.",
  "hey can you walk me over to a novle or some other hardcover, whichever is closest",
 ], "novle"),
 (2, C8, "or", 14, [14, 33], [
  "Go to one of the curtains in the living room.",
  "Could you take me to the drapes hanging in the living room?",
  "Living room window drapes, please.",
  "I want to pull the drapes in the lounge because the sun is glaring, not the ones in the bedroom.",
  "This is about the white fabric at the living room windows. Head over to either of those drapes.",
  "just get me to a curtian in the living room, either one is fine",
 ], "curtian"),
 (3, C8, "or", 112, [112, 233], [
  "Take me to a mirror in the bathroom.",
  "Could you bring me to one of the bathroom mirrors?",
  "Bathroom mirror, please.",
  "I need to check my hair in the washroom, so any mirror in there works, not the one in the bedroom.",
  "This is a quick grooming stop. Guide me to a wood-framed looking glass in the bathroom.",
  "can you take me to any mirorr in the bathroom",
 ], "mirorr"),
 (4, C8, "od", 184, [184], [
  "Go to the L-shaped sofa with the chaise end.",
  "Could you take me to the corner sofa that has a chaise lounge built in?",
  "L-shaped beige sofa with chaise",
  "I want to stretch my legs out on a chaise, so take me to the L-shaped settee, not the plush beige one that massages.",
  "This is the big beige sectional I mean. Bring me to it, the one shaped like an L.",
  "take me to the l-shaped sofa with the chaise and the hidden storgae",
 ], "storgae"),
 (5, C8, "ord", 197, [197], [
  "Take me to the red leather-bound book in the bathroom.",
  "Could you go to the bathroom and find the red leather volume with the gold-stamped cover?",
  "Red leather volume, bathroom",
  "I left my reading in the bathroom, so I want the red leather one in there, not the dark brown book in the bedroom.",
  "This is a red volume bound in leather. It's in the bathroom; take me to it.",
  "take me to the red lether hardback in the bathroom",
 ], "lether"),
 (6, C8, "ard", 192, [192], [
  "Take me to where the dog sleeps in the bathroom.",
  "Could you show me the spot where our pet curls up for naps, the soft white and brown one?",
  "Dog's sleeping spot, bathroom",
  "The puppy needs a rest, so go to its cushy napping spot in the bathroom, not the beige easy chair in there.",
  "This is for the dog. Lead me to the plush place where it naps in the bathroom.",
  "take me to where the dog snoozes, the comfy spot in the bathrom",
 ], "bathrom"),
 (7, C8, "ard", 265, [265], [
  "Take me to the black leather thing with a lock that I carry my work papers in, in the bedroom.",
  "Could you lead me to what I use for hauling documents to the office, the lockable black leather one in the bedroom?",
  "Lockable leather document carrier, bedroom",
  "I have a meeting, so I need my lockable leather document holder from the bedroom, not the black backpack.",
  "This is for carrying contracts to work. Go to the black leather one with the metal lock in the bedroom.",
  "need my work docments, take me to the black leather thing with the lock in the bedroom",
 ], "docments"),
 # ---------------- scene_office3 (caption map) ----------------
 (8, C3, "o", 8, [8, 13, 20, 40], [
  "Go to any pillow in here.",
  "Could you take me to one of the cushions?",
  "Any cushion, whichever's nearest",
  "My back hurts from sitting, so I want a cushion, any of them, not a chair.",
  "This is a simple one. Bring me to whatever throw pillow is closest.",
  "find me a cushon, any colour is fine",
 ], "cushon"),
 (9, C3, "or", 4, [4, 11, 12, 27], [
  "Head to a curtain in the rec room.",
  "Could you take me to one of the drapes in the rec room?",
  "Rec room drapes",
  "It's too bright in the rec room, so go to any of the drapes there, not the blinds.",
  "This is about shutting out daylight. Take me to the window drapes in the recreation room, any of them.",
  "go to whichever drpae is closest in the rec room",
 ], "drpae"),
 (10, C3, "od", 10, [10], [
  "Go to the window that has the clock mounted above it.",
  "Could you bring me to the red-tinted pane that has a pale blind, with a clock hanging over it?",
  "Red pane under clock",
  "I want to check the time and look outside at once, so the pane below the clock, not the frosted red one.",
  "This is the red glass pane with a pale blind. There's a clock just over it; take me there.",
  "take me to the windw with the clock right above it",
 ], "windw"),
 (11, C3, "ord", 13, [13], [
  "Take me to the navy blue velvet cushion in the rec room.",
  "Could you go to the rec room and find the buttoned dark blue velvet pillow?",
  "Navy velvet cushion, rec room",
  "I want the soft navy one in the rec room, not the orange striped pillow.",
  "This is the biggish dark blue cushion with a button. It's in the rec room, please head there.",
  "go to the navy velvit cushion in the rec room",
 ], "velvit"),
 (12, C3, "ard", 3, [3], [
  "Take me somewhere in the rec room where I can lie down for a nap, the soft gray one.",
  "Could you find me a spot in the rec room to stretch out and rest on light gray fabric?",
  "Nap spot, rec room, gray",
  "I'm exhausted, so I need somewhere soft to lie flat in the rec room, not the hard blue bench.",
  "This is for a quick snooze. Head to the padded gray place in the rec room where I can lie down.",
  "take me to somewhere comfy to lie down for a nap in the rec room, the light grey fabrik one",
 ], "fabrik"),
 # ---------------- flat_b ----------------
 (13, B, "or", 20, [20, 21, 22], [
  "Take me to a chair in the kitchen.",
  "Could you lead me to any seat at the kitchen table?",
  "Kitchen seat, any",
  "I want to sit down while the kettle boils, so any kitchen chair, not the armchairs in the living room.",
  "This is just so I can sit and eat. Bring me to one of the seats around the kitchen's dining table.",
  "get me to a seat in the kitchn, any of them",
 ], "kitchn"),
 (14, B, "od", 26, [26], [
  "Go to the lamp with the green glass shade.",
  "Could you take me to the old-fashioned banker's light with the brass base?",
  "Green-shaded banker's light",
  "I want the green-glass banker's light, not the white ceramic one by the sofa.",
  "This is the classic library-style light with green glass. Take me to it.",
  "take me to the green glass desk lmap with the brass base",
 ], "lmap"),
 (15, B, "ard", 29, [29], [
  "Take me to where I can hang up my jacket in the hallway.",
  "Could you show me where coats get hung in the hallway?",
  "Hallway, somewhere to hang jacket",
  "I'm dripping wet from outside, so I need to hang my coat up in the hall, not put it in the bedroom wardrobe.",
  "This is my raincoat and it needs a place to go. Guide me to the spot in the hallway for hanging it.",
  "where do i hang my jaket in the hallway? take me there",
 ], "jaket"),
 (16, B, "s", 2, [2], [
  "Go to the armchair right next to the window.",
  "Could you take me to the easy chair that sits beside the window?",
  "Armchair beside window",
  "I want to read in daylight, so the seat closest to the window, not the leather one on the far side of the room.",
  "This is the comfy chair by the window. Take me over to it.",
  "take me to the cosy chair next to the windoe",
 ], "windoe"),
 # ---------------- flat_e ----------------
 (17, E, "o", 6, [6, 37], [
  "Take me to a plant.",
  "Could you bring me to any of the potted greenery?",
  "Any greenery, whichever's closest",
  "I want to water something green, so any potted plant will do, indoors or out on the balcony.",
  "This is for watering day. Lead me to something leafy growing in a pot.",
  "take me to a potted plnat, whichever one",
 ], "plnat"),
 (18, E, "or", 11, [11, 12, 13, 14, 15], [
  "Go to a chair in the dining room.",
  "Could you take me to any seat in the dining room?",
  "Dining room seat, any",
  "Dinner's ready, so take me to any seat in the dining room, not the sofa in the living room.",
  "This is so I can sit down to eat. Bring me to one of the dining room chairs.",
  "get me to a seat in the dinning room",
 ], "dinning"),
 (19, E, "ord", 28, [28], [
  "Take me to the rattan armchair in the main bedroom.",
  "Could you go to the main bedroom and find the wicker seat with the cream cushion?",
  "Main bedroom rattan seat",
  "I want to sit and put my shoes on in the master bedroom, so the rattan one, not the wooden folding chair on the balcony.",
  "This is the woven cane chair with a cream cushion. It's in the main bedroom; take me there.",
  "go to the ratan armchair in the big bedroom",
 ], "ratan"),
 (20, E, "s", 16, [16], [
  "Go to the lamp hanging above the dining table.",
  "Could you take me to the light that dangles over the dining table?",
  "Light over dining table",
  "I need to change a bulb, so the light suspended over the table where we eat, not the floor lamp by the sofa.",
  "This is the one hanging from the ceiling. Bring me to the light directly over the dining table.",
  "take me to the light hangng over the dining table",
 ], "hangng"),
 # ---------------- flat_g ----------------
 (21, G, "od", 3, [3], [
  "Take me to the little blue bike with training wheels.",
  "Could you lead me to the child's bicycle that has stabilisers?",
  "Small blue kids' bike",
  "My daughter wants to ride, so the small blue one with training wheels, not the black mountain bike.",
  "This is the kid's bicycle, the blue one. Take me to it.",
  "take me to the littel blue bike with the training wheels",
 ], "littel"),
 (22, G, "ard", 11, [11], [
  "Take me to where I can iron my shirt in the laundry room.",
  "Could you guide me to the place in the laundry room for pressing clothes?",
  "Laundry room, ironing spot",
  "My trousers are creased, so I need to press them, not wash them; take me to the spot in the laundry room.",
  "This is for getting wrinkles out of a shirt. Head to where I do that in the laundry room.",
  "i need to iron a blouse, take me to the spot for that in the laundry rom",
 ], "rom"),
 (23, G, "or", 34, [34, 35], [
  "Head to a lamp in the bedroom.",
  "Could you take me to one of the bedside lights in the bedroom?",
  "Bedroom reading light, either",
  "I'd like to read before sleep, so any light in the bedroom, not the yellow one in the kids' room.",
  "This is just about a bedroom lamp. Either of the two by the bed is fine, so go there.",
  "take me to a bedside lihgt in the bedroom, either side",
 ], "lihgt"),
 (24, G, "s", 18, [18], [
  "Go to the kitchen chair closest to the sink.",
  "Could you take me to whichever seat at the kitchen table is nearer the sink?",
  "Kitchen seat nearest sink",
  "I want to keep an eye on the dishes, so the seat on the sink side of the table, not the one with the checked cushion.",
  "This is one of the two seats at the kitchen table. Take me to the one nearer the sink.",
  "go to the kitchen chiar closest to the sink",
 ], "chiar"),
 # ---------------- flat_i ----------------
 (25, I, "o", 23, [23, 31, 36], [
  "Take me to a mug.",
  "Could you bring me to any coffee cup around here?",
  "Nearest cup, any kind",
  "I want a hot drink, so find me a cup, any of them, whichever is closest.",
  "This is for my tea. Lead me to one of the mugs, whichever is handiest.",
  "take me to a coffe cup, any one",
 ], "coffe"),
 (26, I, "od", 24, [24], [
  "Go to the bottle-green door with the brass knob.",
  "Could you take me to the dark green entrance that has a round brass handle?",
  "Green front door",
  "I need to let a guest in, so the green one with the round knob, not the black steel studio entrance.",
  "This is the green painted entrance to the flat. Take me there, please.",
  "take me to the grean entrance with the brass knob",
 ], "grean"),
 (27, I, "ord", 43, [43], [
  "Take me to the oak bedside table in the bedroom.",
  "Could you go to the bedroom and find the wooden nightstand with the open shelf?",
  "Bedroom oak bedside table",
  "I left my glasses on the natural wood one in the bedroom, not the white one with the drawer.",
  "This is the light oak table beside the bed. It's in the bedroom, so head there.",
  "go to the oak nighstand in the bedroom",
 ], "nighstand"),
 (28, I, "s", 16, [16], [
  "Go to the left-hand computer screen when you face the two desks in the studio.",
  "Could you take me to the monitor on the left as you look at the studio desks?",
  "Left screen, facing studio desks",
  "I want to use the left screen when facing the desks, not the right one tilted for portrait work.",
  "This is in the studio, facing the pair of desks. Take me to the display on the left.",
  "facing the studio desks, take me to the left scren",
 ], "scren"),
 # ---------------- apartment ----------------
 (29, A, "o", 9, [9, 37], [
  "Take me to a rug.",
  "Could you bring me to any of the carpets on the floor?",
  "Nearest floor rug",
  "The vacuum needs a job, so take me to any carpet, whichever is closest.",
  "This is for shaking out some dust. Lead me to one of the carpets lying on the floor.",
  "get me to a carpte, either room is fine",
 ], "carpte"),
 (30, A, "or", 1, [1, 2], [
  "Go to a sofa in the living room.",
  "Could you take me to one of the couches in the living room?",
  "Living room couch, any",
  "I want to lie down and watch something, so any couch in the lounge works, not the armchair.",
  "This is just about sitting down. Bring me to either settee in the living room.",
  "take me to a sofa in the livng room",
 ], "livng"),
 (31, A, "od", 31, [31], [
  "Go to the black-and-white photo of a lighthouse.",
  "Could you take me to the small framed lighthouse picture?",
  "Lighthouse photograph, thin black frame",
  "I want to look at the lighthouse snapshot, not the big abstract painting over the sofa.",
  "This is a small monochrome print showing a lighthouse. Head over to it.",
  "take me to the litle lighthouse photo",
 ], "litle"),
 (32, A, "ord", 30, [30], [
  "Take me to the gold-framed mirror in the hallway.",
  "Could you lead me to the ornate gilded looking glass in the hall?",
  "Hallway gold mirror",
  "I want a last look at my outfit before heading out, so the one in the hallway with the fancy gilt frame, not the oval one in the bathroom.",
  "This is the tall one with the fancy golden frame. It hangs in the hallway; take me there.",
  "go to the gold framed mirorr in the hall",
 ], "mirorr"),
 (33, A, "ord", 24, [24], [
  "Go to the white painted chair in the kitchen.",
  "Could you take me to the kitchen seat with the spindle back?",
  "White spindle-back kitchen seat",
  "I prefer the white one in the kitchen, not the wooden seat with the green cushion.",
  "This is the white wooden dining seat with spindles. It's in the kitchen, so head there.",
  "take me to the whte chair in the kitchen",
 ], "whte"),
 (34, A, "ard", 45, [45], [
  "Take me to where I can wash a load of clothes in the bathroom.",
  "Could you show me where the laundry gets done in the bathroom?",
  "Bathroom, clothes washing spot",
  "My sheets are dirty, so I need to run a wash, not take a bath; it's in the bathroom.",
  "This is a pile of dirty laundry. Lead me to the thing in the bathroom that cleans it.",
  "i need to do laundery, take me to where that happens in the bathroom",
 ], "laundery"),
 (35, A, "s", 12, [12], [
  "Go to the book on the higher shelf of the living room bookcase.",
  "Could you take me to whichever volume sits higher up on the living room bookshelf?",
  "Upper-shelf novel, living room",
  "I want the one I can reach standing up, higher on the living room shelf, not the one lying flat down low.",
  "This is one of two books on the living room shelf. Take me to the one placed higher.",
  "go to the hihger of the two volumes on the living room shelf",
 ], "hihger"),
 (36, A, "s", 39, [39], [
  "Take me to the plant sitting on top of the chest of drawers.",
  "Could you bring me to the little potted succulent on the dresser?",
  "Greenery on top of dresser",
  "I want to water the one perched on the dresser, not the fig by the TV or the one in the office.",
  "This is the tiny green thing on the dresser in the bedroom. Take me there.",
  "take me to the smal plant on top of the dresser",
 ], "smal"),
 # ---------------- scan_bedroom ----------------
 (37, SB, "o", 2, [2, 3, 4, 5], [
  "Go to one of the pillows.",
  "Could you take me to any cushion on the bed?",
  "Any pillow, please",
  "I want something soft to prop my head on, so any cushion will do, whatever the colour.",
  "This is a simple request. Bring me to whichever cushion is closest.",
  "take me to a pilow, any of them",
 ], "pilow"),
 (38, SB, "ard", 17, [17], [
  "Take me somewhere I can check how my outfit looks.",
  "Could you bring me to where I can see my reflection in the bedroom?",
  "Somewhere to see my reflection",
  "I'm getting dressed and want to see myself, not look out the window.",
  "This is about fixing my hair. Head to the spot where I can see myself.",
  "take me where i can see my reflecton",
 ], "reflecton"),
 (39, SB, "s", 5, [5], [
  "Go to the pillow down at the foot of the bed.",
  "Could you take me to the cushion lying near the bottom end of the bed, away from the headboard?",
  "Cushion at bed's foot",
  "I want the one near the foot end, not the ones stacked up by the headboard.",
  "This is the pillow that's not up by the headboard. Take me to the one near the bed's foot.",
  "take me to the cushion at the foot of the bedd",
 ], "bedd"),
 # ---------------- scan_kitchen ----------------
 (40, SK, "ord", 21, [21], [
  "Take me to the red chair in the kitchen.",
  "Could you go over to the kitchen and find the seat that's red?",
  "Red kitchen seat",
  "I want the red one in the kitchen, not any of the black seats.",
  "This is the only red seat in the kitchen. Bring me to it.",
  "go to the red chiar in the kitchen",
 ], "chiar"),
 (41, SK, "s", 20, [20], [
  "Go to the chair closest to the window.",
  "Could you bring me to whichever seat is nearest the window?",
  "Seat nearest window",
  "I'd like some daylight while I eat, so the seat closest to the window, not the white one at the table's end.",
  "This is a black seat at the table. Take me to the one nearest the window.",
  "take me to the seat clossest to the window",
 ], "clossest"),
 (42, SK, "s", 3, [3], [
  "Go to the cupboard right under the sink.",
  "Could you take me to the base cabinet directly beneath the sink?",
  "Cupboard under sink",
  "I need the dish soap, which is kept below the sink, so that cupboard, not the ones up on the wall.",
  "This is the low cupboard with the sink set on top of it. Take me there.",
  "take me to the cuboard under the sink",
 ], "cuboard"),
 # ---------------- scan_livingroom ----------------
 (43, SL, "ard", 27, [27], [
  "Take me to something low and padded in the living room where I can put my feet up.",
  "Could you find me a small gray spot to rest my feet on in the living room?",
  "Somewhere to prop feet up",
  "My legs are aching, so I want to prop my feet on the small gray padded thing, not the coffee table.",
  "This is for resting my feet after a long day. Head to the little gray padded spot in the middle of the living room.",
  "take me somewhere low to put my feet up, the little gray paded one",
 ], "paded"),
 (44, SL, "s", 2, [2], [
  "Go to the red cushion on the left end of the sofa, as seen from someone sitting on it facing the TV.",
  "Could you take me to the red pillow on the left when you're seated on the couch facing the TV?",
  "Left red cushion, facing TV",
  "I want the red one on my left-hand side while I sit watching TV, not the other red one on the right.",
  "This is one of the two red cushions on the couch. From the seat facing the TV, take me to the left one.",
  "sat on the sofa looking at the tv, take me to the red cusion on the left",
 ], "cusion"),
 (45, SL, "s", 12, [12], [
  "Go to the lamp nearest the door.",
  "Could you take me to whichever light stands closest to the doorway?",
  "Light closest to door",
  "I want to switch on the one right as I come in, so the light by the door, not the ones beside the sofa.",
  "This is the light you pass when you walk in. Bring me to the one nearest the door.",
  "take me to the light nearest the dore",
 ], "dore"),
 # ---------------- scan_office ----------------
 (46, SO, "o", 11, [11, 12, 13], [
  "Take me to a monitor.",
  "Could you bring me to any of the computer screens?",
  "Any computer screen",
  "I need to check my email, so any screen on the tables works, not the whiteboard.",
  "This is for a quick look at something online. Head over to one of the displays.",
  "take me to a computr screen, whichever",
 ], "computr"),
 (47, SO, "od", 30, [30], [
  "Go to the white computer keyboard.",
  "Could you find the white keypad for me and take me there?",
  "White typing keypad",
  "I type better on the white one, not the black keyboard.",
  "This is the white keypad I use for typing. Bring me to it.",
  "take me to the white keybord",
 ], "keybord"),
 (48, SO, "s", 15, [15], [
  "Go to the bookshelf in the middle of the three.",
  "Could you take me to the bookcase between the other two?",
  "Middle bookcase of three",
  "I want the middle one, not either of the bookcases at the ends.",
  "This is the bookcase with one on each side of it. Lead me to that middle one.",
  "take me to the midle bookcase, the one between the other two",
 ], "midle"),
]


if __name__ == "__main__":
    import json
    from pathlib import Path
    out = Path(__file__).resolve().parents[2] / "evals/blind/round50.jsonl"
    lines = []
    for n, mp, typ, target, accept, ws, _typo in GROUPS:
        g = f"b50-g{n:02d}"
        for k, q in enumerate(ws, 1):
            lines.append(json.dumps({"id": f"{g}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": sorted(accept), "group": g}, ensure_ascii=False))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(len(lines), "lines written to", out)
