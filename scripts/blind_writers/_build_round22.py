"""Generate evals/blind/round22.jsonl (48 groups x 6 wordings), written by hand below."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SB, SK = "../maps/scan_bedroom.json", "../maps/scan_kitchen.json"
FC, FE, FG, FH = "maps/flat_c.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_h.json"

G = [
# ---- o: every instance of a kind
("o", OFF3, 8, [8, 13, 20, 40], [
 "Take me to a cushion.",
 "Could you show me where the throw cushions are?",
 "cushions, any of them",
 "My back hurts on this seat. I need a pillow, whichever is closest.",
 "I'm looking for one of the pillows. Any one is fine.",
 "go to a cusion"]),
("o", C829, 78, [78, 234], [
 "Take me to the television.",
 "Where's a TV in this place?",
 "tv screen on the wall",
 "The match starts soon. Bring me to a telly, please.",
 "Can you find me one of the flat screens mounted on the wall?",
 "I want to watch something, any television will do."]),
("o", C829, 160, [160, 162, 164], [
 "Take me to the stacked towels.",
 "Where are the piles of folded towels kept?",
 "towel stack",
 "I just got out of the shower and I'm dripping. I need a fresh towel from one of the piles.",
 "Could you guide me to one of the folded sets of bath linen?",
 "towel pile, any"]),
("o", FH, 13, [13, 26, 32], [
 "Take me to a mug.",
 "Where can I find a coffee cup?",
 "any cup",
 "I want to make tea, so I need something to drink from. Show me a mug.",
 "Can you point me to one of the cups in the flat?",
 "find me a mugg"]),
("o", SK, 26, [26, 27], [
 "Take me to the bin.",
 "Where's a rubish bin?",
 "garbage can",
 "I have some peelings to throw away. Which way to a trash can?",
 "Could you lead me to a waste bin, either one?",
 "nearest trash can pls"]),
("o", APT, 1, [1, 2], [
 "Take me to the couch.",
 "Where can I sit on a sofa?",
 "settee",
 "I'm exhausted and want to lie down for a bit. Any couch will do.",
 "Could you show me one of the sofas?",
 "go to the settee please"]),
("o", FG, 2, [2, 3], [
 "Take me to a bike.",
 "Where do we keep the bicycles?",
 "bikes",
 "I want to go for a ride this afternoon. Show me a bike.",
 "Could you bring me to one of the cycles? Either is fine.",
 "find a bicyle"]),
# ---- or: every instance of a kind in a named room
("or", OFF3, 7, [7, 55, 64], [
 "Take me to a desk in the rec room.",
 "Which way to one of the workstations in the recreation room?",
 "rec room desk",
 "I need to write something down. Is there a writing surface for computers in the rec room?",
 "In the rec room there are a few computer work spots. Take me to any of them.",
 "workstation in the rec room, any"]),
("or", C829, 261, [261, 263], [
 "Take me to an armchair in the bedroom.",
 "Is there a comfy lounge chair in the bedroom? Bring me there.",
 "bedroom armchair",
 "I want to read somewhere cosy near the bed. Which armchairs are in the bedroom?",
 "Go to one of the easy chairs in the bedroom.",
 "bedroom armcahir, either one"]),
("or", FE, 11, [11, 12, 13, 14, 15], [
 "Take me to a chair in the dining room.",
 "Where can I sit in the dining room?",
 "dining room seat",
 "We have guests coming for dinner. Show me a seat at the table in the dining room.",
 "Could you go to any of the dining-room chairs?",
 "a chiar in the dinning room"]),
("or", FH, 46, [46, 47], [
 "Take me to a bedside table in the master bedroom.",
 "Where are the night tables in the main bedroom?",
 "master bedroom nightstand",
 "I left my glasses by the bed in the master bedroom. Go to one of the bedside tables there.",
 "One of the nightstands in the big bedroom, please.",
 "bedside cabnet in master bedroom"]),
("or", FG, 34, [34, 35], [
 "Take me to a lamp in the bedroom.",
 "Could you show me the bedside lights in the bedroom?",
 "bedroom light",
 "It's dark in the bedroom and I need to switch on a reading light.",
 "Any of the lamps in the bedroom, please.",
 "go to the bedroom lmap"]),
("or", APT, 12, [12, 13], [
 "Take me to a book in the living room.",
 "Where can I find something to read in the lounge?",
 "living room reading matter",
 "I'm bored and want something to read in the living room. Show me one of the volumes on the shelf there.",
 "Any of the books in the living room is fine.",
 "Could you bring me to a hardcover or photo album in the sitting room?"]),
("or", FC, 19, [19, 20, 21], [
 "Take me to a chair in the kitchen.",
 "Where can I sit down in the kitchen?",
 "kitchen seat",
 "My feet hurt after cooking. Find me somewhere to sit in the kitchen.",
 "Any of the kitchen chairs will do.",
 "anywhere to sit in the kitchen"]),
# ---- od: one object by its look
("od", OFF3, 25, [25], [
 "Take me to the black and red clock.",
 "Where's the wall clock with the red second hand?",
 "black timepiece w/ red hand",
 "I want to check the time. Go to the black timepiece on the wall with the red dot.",
 "The one with the red second hand and the black plastic case, please.",
 "black and red wall clokc"]),
("od", C829, 211, [211], [
 "Take me to the blue bowl with gold patterns.",
 "Could you find the glossy deep blue ceramic dish decorated in gold?",
 "blue+gold bowl",
 "I want to show my friend that pretty ornamental bowl, the blue one with the gold pattern.",
 "It's a ceramic bowl, deep blue. It has gold-tinged designs on it.",
 "not the white sweets bowl, the blue one with gold"]),
("od", FC, 17, [17], [
 "Take me to the green kettle.",
 "Where's the green metal electric kettle?",
 "green water boiler",
 "This is a green electric jug for boiling water. Take me there.",
 "The green one you boil water in, please.",
 "green ketle"]),
("od", FH, 24, [24], [
 "Take me to the mint green fridge.",
 "Where's the retro fridge with rounded corners?",
 "pastel green fridge w/ postcards",
 "It's a retro-style fridge, pale green. Postcards and magnets cover the door.",
 "the old-fashioned mint icebox, please",
 "mint green frigde"]),
("od", APT, 31, [31], [
 "Take me to the black-and-white photo of the lighthouse.",
 "Where's the little lighthouse photograph in the thin black frame?",
 "lighthouse pic",
 "I want to look at that small monochrome print. It shows a lighthouse.",
 "Not the big colourful painting, the small black and white picture.",
 "lighthouse photgraph"]),
("od", FE, 15, [15], [
 "Take me to the high chair.",
 "Where's the baby's feeding seat with the clip-on tray?",
 "white plastic highchair",
 "The baby is hungry. Bring me to her white plastic seat with a tray.",
 "It's a white plastic seat for the baby. It has a tray clipped on.",
 "the kid's hihg chair"]),
("od", FG, 3, [3], [
 "Take me to the small blue bike.",
 "Where's the children's bicycle with training wheels?",
 "blue kids bike",
 "My son wants to ride. Show me his little blue bike with the stabilisers.",
 "Not the black mountain bike, the little blue one.",
 "small blue bike with stabilisers"]),
# ---- ord: look + room
("ord", C829, 184, [184], [
 "Take me to the L-shaped beige couch in the bedroom.",
 "In the bedroom, where's the corner sofa with the chaise?",
 "bedroom L-sofa, beige",
 "I want to put my feet up. Go to the beige sectional with the chaise in the bedroom.",
 "It's a beige fabric settee with a built-in chaise. It's in the bedroom, not the living room.",
 "beige L-shaped cuoch in the bedroom"]),
("ord", C829, 197, [197], [
 "Take me to the red leather book in the bathroom.",
 "Is there a red leather-bound volume in the bathroom? Where is it?",
 "bathroom red leather-bound volume",
 "Someone left a red book with gold embossing in the bathroom. Bring me to it.",
 "It's a leather-bound volume, red with gold lettering. It's lying in the bathroom.",
 "the red leather tome in the bathroom"]),
("ord", FH, 43, [43], [
 "Take me to the red lamp in the guest bedroom.",
 "Where's the red ceramic bedside light in the spare room?",
 "guest room red light",
 "My guest says it's dark. Go to the red-based bedside lamp in the guest bedroom.",
 "It's a red ceramic light with a cream shade. It's in the guest room by the single bed.",
 "red bedside lmap, guest bedroom"]),
("ord", FG, 34, [34], [
 "Take me to the teal lamp in the bedroom.",
 "Where's the bedside light with the teal glass base in the bedroom?",
 "bedroom lamp, teal glass",
 "I want to read in bed. Take me to the teal bedside light in the bedroom, not the beige one.",
 "It's a reading light with a turquoise glass base. It's in the bedroom next to the bed.",
 "teal glass light in bedroom"]),
("ord", FE, 36, [36], [
 "Take me to the red chair in the kids' room.",
 "Where's the little red plastic seat at the children's desk?",
 "kids bedroom red seat",
 "My daughter needs to do homework. Go to her small red chair in the kids bedroom.",
 "It's a small red plastic seat. It's pulled up to the desk in the kids' bedroom.",
 "red plastic chiar, kids room"]),
("ord", APT, 30, [30], [
 "Take me to the gold-framed mirror in the hallway.",
 "Where's the tall looking glass with the ornate golden frame in the entrance hall?",
 "hall looking glass, gold frame",
 "I want to check my outfit before I leave. Go to the tall gilded looking glass in the hall.",
 "It's a tall rectangular glass with a fancy gold frame. It hangs in the hallway, not the bathroom.",
 "gold framed mirorr in the hallway"]),
("ord", OFF3, 13, [13], [
 "Take me to the navy blue pillow in the rec room.",
 "Where's the velvet navy cushion in the rec room?",
 "rec room navy cushion",
 "I want the soft one. Go to the dark blue velvet cushion in the rec room, not the orange or yellow ones.",
 "It's a velvety navy blue pillow with a button. It's in the rec room.",
 "navy blue cushon in rec room"]),
# ---- ard: a need, no object named
("ard", OFF3, 67, [67], [
 "I want to change the channel.",
 "Could you take me to whatever lets me control the screen from the sofa?",
 "change channel / volume",
 "The volume is way too loud and I can't reach the screen. Take me to what controls it.",
 "I'd like to flip through the channels from my seat.",
 "turn the sound down from across the room"]),
("ard", C829, 122, [122], [
 "I need to pee.",
 "Excuse me, where can I relieve myself?",
 "need the loo",
 "I've drunk way too much coffee. Take me where I can go.",
 "Nature calls, please hurry.",
 "I have to use the WC urgently."]),
("ard", C829, 192, [192], [
 "Where does the dog sleep?",
 "The cat needs a nap spot. Take me to its sleeping place.",
 "dog's sleeping spot",
 "I'm bringing our puppy home. Show me where he'll curl up at night.",
 "Could you take me to where our pet rests?",
 "kitty naptime spot"]),
("ard", FG, 11, [11], [
 "My shirt is all creased.",
 "I need to press my trousers before the interview. Where can I do that?",
 "de-wrinkle shirt",
 "Could you take me where I can get the creases out of this dress?",
 "There's a job interview tomorrow and my blouse is wrinkled. Help.",
 "iron my clothes"]),
("ard", FH, 4, [4], [
 "Where do I drop my keys when I get home?",
 "I just came in. Take me to where the house keys go.",
 "put keys down",
 "I'm heading out and can't find my keys. Where do they usually get left?",
 "Could you show me the spot by the entrance for keys?",
 "leave my keyss somewhere"]),
("ard", APT, 27, [27], [
 "I'd love a cup of tea.",
 "Can you take me to where I can boil some water?",
 "boil water",
 "I'm freezing and want a hot drink. Where do I heat water for tea?",
 "Fancy a cuppa. What do I use to boil the water?",
 "make tea quick"]),
("ard", FE, 33, [33], [
 "The laundry is wet and I need it dry by tonight.",
 "Where can I dry these clothes quickly?",
 "dry laundry",
 "It's raining so I can't hang the washing outside. Take me to something that dries it.",
 "Could you show me where to tumble my wet towels?",
 "get clothes dry fast"]),
("ard", SK, 12, [12], [
 "I need coffee.",
 "Could you take me to where I can brew an espresso?",
 "brew coffee",
 "I barely slept last night. Where can I make myself a strong cup?",
 "Morning! Where do I make a fresh pot?",
 "need caffeine asap"]),
# ---- s: singled out by position (checked in check_spatial.py)
("s", FC, 7, [7], [
 "Take me to the lamp standing on the small black table.",
 "Where's the light sitting on the side table by the sofa?",
 "lamp on side table",
 "There's a little table at the end of the couch. The light on top of it, please.",
 "the one on the black end table, at the west end of the couch",
 "small light on top of the end table"]),
("s", FC, 27, [27], [
 "Take me to the bedside table with the alarm clock on it.",
 "Which nightstand has the clock? Go there.",
 "bedside table under clock",
 "There's a red alarm clock in the bedroom. Take me to the little table it sits on.",
 "Not the one with the pink lamp, the bedside table holding the alarm clock.",
 "nightstand with the alrm clock"]),
("s", FE, 16, [16], [
 "Take me to the light hanging over the dining table.",
 "Which lamp is above the table in the dining room?",
 "light above dining table",
 "We're eating soon. The light that dangles above the table, go there.",
 "It's a pendant. It hangs right over the dining table.",
 "the lamp over the table, not the floor one"]),
("s", FG, 33, [33], [
 "Standing at the foot of the bed facing the headboard, take me to the bedside table on your right.",
 "Facing the bed's headboard from the foot end, which nightstand is on the right?",
 "bed foot -> headboard, right nightstand",
 "Look at the bed from its foot. The little table on the right side of the headboard, please.",
 "From the end of the bed looking toward the pillows, go to the right-hand bedside cabinet.",
 "the one on the right when you face the head of the bed from its foot"]),
("s", FH, 26, [26], [
 "Take me to the mug next to the kettle.",
 "Which cup is sitting beside the kettle on the worktop?",
 "cup by kettle",
 "I'll make a hot drink. Go to the cup right next to the copper kettle.",
 "The one beside the kettle, not the one on the coffee table.",
 "mug right next to the kettle"]),
("s", FH, 17, [17], [
 "Of the two black seats on the south side of the dining table, take me to the one nearer the window.",
 "Which metal bistro seat is closer to the east window?",
 "black dining chair nearest window",
 "There are two black chairs at the table. I want the one by the window.",
 "Not the black seat farther from the window, the one closest to it.",
 "bistro seat, window side"]),
("s", SB, 5, [5], [
 "Take me to the pillow at the foot of the bed.",
 "Which cushion lies near the bottom end of the bed?",
 "pillow, foot of bed",
 "Most cushions are up by the headboard. I want the one down at the other end.",
 "It's a cushion on the bed. It's near the foot, away from the headboard.",
 "the pilow lying at the foot end"]),
("s", SB, 8, [8], [
 "Take me to the lamp closest to the window.",
 "Which bedside light is nearer the window?",
 "light nearest window",
 "I want to read by natural light later. Go to the bedside lamp on the window side.",
 "the one on the nightstand by the window, not the one by the door",
 "light on the window side"]),
("s", SK, 3, [3], [
 "Take me to the cupboard under the sink.",
 "Which base unit is right below the sink?",
 "cabinet below sink",
 "I need the dish soap, it's kept under the sink. Go to that cupboard.",
 "The lower cupboard directly beneath the sink, please.",
 "undersink cuboard"]),
("s", SK, 21, [21], [
 "Take me to the chair nearest the door.",
 "Which seat at the table is closest to the door?",
 "table seat by the door",
 "I'm coming in with shopping bags and want to sit straight away. Go to the chair closest to the entrance.",
 "the red one at the end of the table, next to the door",
 "seat nearest the dorr"]),
("s", APT, 12, [12], [
 "Take me to the book on the upper shelf of the living room bookcase.",
 "Which book is higher up on the living-room shelves?",
 "top-shelf novel, living room",
 "There are two on the living room bookshelf. Bring me to the higher one.",
 "It's a hardcover on the bookcase in the living room. It stands above the other one.",
 "not the one on the bottom shelf, the higher volume"]),
("s", APT, 39, [39], [
 "Take me to the plant on top of the dresser.",
 "Which potted plant is sitting on the chest of drawers?",
 "succulent on dresser",
 "There's a chest of drawers in the bedroom. Go to the little green thing on top of it.",
 "the tiny pot on the drawers, not the fig in the living room",
 "small plnat on the chest of drawers"]),
]

out = Path(__file__).parent / "evals/blind/round22.jsonl"
with out.open("w", encoding="utf-8") as f:
    for n, (t, m, target, acc, ws) in enumerate(G, 1):
        assert len(ws) == 6, n
        for k, q in enumerate(ws, 1):
            f.write(json.dumps({"id": f"b22-g{n:02d}-w{k}", "map": m, "query": q, "type": t,
                                "target": target, "accept": acc, "group": f"b22-g{n:02d}"}) + "\n")
print(len(G), "groups written to", out)
