#!/usr/bin/env python3
"""Generate evals/blind/round24.jsonl. Every wording below was written by hand for this round,
after reading only the map files named in BRIEF.md."""
import json, os, random

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
COFF = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SB, SK, SL = "../maps/scan_bedroom.json", "../maps/scan_kitchen.json", "../maps/scan_livingroom.json"
FC, FD, FE, FH, FI = ("maps/flat_%s.json" % c for c in "cdehi")

# (type, map, target, accept, [six wordings])
G = [
# ---------------- o ----------------
("o", C829, 4, [4, 9, 32, 79, 191, 261, 263], [
 "Take me to an armchair.",
 "Could you bring me over to one of the easy chairs, please?",
 "comfy armchair, any",
 "My back hurts from sitting at the desk and I want to sink into something soft. Where's a lounge chair?",
 "There are a few big padded chairs with arms around the place. Go to any one of them.",
 "find me an armchiar"]),
("o", C829, 112, [112, 157, 219, 229, 233], [
 "Go to a mirror.",
 "I want to check there's nothing stuck in my teeth. Take me to a looking glass.",
 "reflection glass in a frame, whichever is closest",
 "Could you show me where the framed mirrors are?",
 "This is a glass in a wooden frame that shows your reflection. Any of them will do.",
 "looking glass pls"]),
("o", COFF, 8, [8, 13, 20, 40], [
 "Find a cushion.",
 "Could you take me to one of the cushions, please?",
 "throw cushion, any colour",
 "My lower back is killing me in this seat, so I need something soft to stuff behind it. Go to a pillow.",
 "What I want is a soft cushion from the couch. Any of them works.",
 "go to a cuhsion"]),
("o", FH, 13, [13, 26, 32], [
 "Go to a mug.",
 "Can you find me a coffee cup somewhere in the flat?",
 "cup, any",
 "I'm gathering the dirty dishes before I run the dishwasher. Show me where the cups are.",
 "I want a tea cup. It doesn't matter which one.",
 "take me to a mgu"]),
("o", APT, 12, [12, 13, 52], [
 "Take me to a book.",
 "Would you bring me to any of the books, please?",
 "something to read, a hardback or whatever",
 "I'm bored and fancy reading for a bit. Where's a novel or any volume at all?",
 "There are hardcovers lying around the place. Go to one of them.",
 "go to any boook"]),
("o", SK, 23, [23, 24, 25], [
 "Go to a cup.",
 "Could you find me a mug, please?",
 "mug, any colour",
 "I'm thirsty and need something to drink out of. Take me to a mug.",
 "There are some drinking mugs about, on the table and on the counter. Any of them.",
 "find a muug"]),
("o", FD, 21, [21, 22], [
 "Take me to a bar stool.",
 "Could you go to one of the high seats with no backrest?",
 "high seat without a back",
 "I just want to perch for a minute while the toast is going. Go to a stool.",
 "The thing I want is a tall seat with no back. Either of the two will do.",
 "find a stoool"]),
# ---------------- or ----------------
("or", C829, 160, [160, 162, 164], [
 "Go to the towels in the living room.",
 "Could you take me to the folded towels in the living room?",
 "towels, living room",
 "I've just come out of the shower dripping wet. Take me to the stack of towels in the living room.",
 "I'm after the fluffy white towels. They're somewhere in the living room.",
 "go to a towle in the living room"]),
("or", C829, 259, [259], [
 "Take me to the book in the bedroom.",
 "Could you find the hardback lying in the bedroom?",
 "bedroom novel",
 "I want to read before I go to sleep. Go to the volume that's in the bedroom.",
 "There's a leather-bound volume I'm after. I mean the one in the bedroom, not elsewhere.",
 "bedroom reading book"]),
("or", FE, 11, [11, 12, 13, 14, 15], [
 "Take me to a chair in the dining room.",
 "Could you find me a seat at the table in the dining room?",
 "dining room seat",
 "Guests are coming and I'm counting places to sit. Show me the seats in the dining room.",
 "I need somewhere to sit down. It should be in the dining room, any one there.",
 "go to a chiar in the dining room"]),
("or", FH, 46, [46, 47], [
 "Go to the bedside table in the master bedroom.",
 "Could you take me to a nightstand in the master bedroom, please?",
 "master bedroom bedside cabinet",
 "I left my glasses by the bed last night. Take me to a bedside table in the master bedroom.",
 "I'm looking for the little tables next to the big double bed. They're in the master bedroom.",
 "bedside tabel, master bedroom"]),
("or", FI, 45, [45, 46], [
 "Take me to a lamp in the bedroom.",
 "Would you go to one of the bedside lights in the bedroom?",
 "bedroom light",
 "It's getting dark and I want to read in bed. Go to a reading light in the bedroom.",
 "There are two little lights by the bed. Either of those in the bedroom is fine.",
 "bedroom lmap"]),
("or", FC, 19, [19, 20, 21], [
 "Go to a chair in the kitchen.",
 "Can you find me a seat at the table in the kitchen?",
 "kitchen seat",
 "My feet are sore from cooking. Take me to somewhere to sit in the kitchen.",
 "The one I want is a dining seat. It's in the kitchen, any of them.",
 "any seat at the kitchen table"]),
("or", APT, 55, [55], [
 "Take me to the plant in the office.",
 "Could you go to the greenery in the office, please?",
 "office plant",
 "The leaves are drooping, so I need to water it. Take me to the potted greenery in the office.",
 "I mean the green thing in a pot. It's in the office.",
 "office houseplnat"]),
# ---------------- od ----------------
("od", C829, 211, [211], [
 "Go to the blue bowl with gold patterns.",
 "Could you find the deep blue ceramic dish decorated in gold, please?",
 "dark blue decorative dish",
 "I want to show a friend that pretty piece of pottery. Take me to the blue one with the gold trim.",
 "It's a glossy blue ceramic dish. It has golden patterns painted on it.",
 "blue and gold bowl, not the white one"]),
("od", C829, 184, [184], [
 "Take me to the L-shaped couch.",
 "Could you go to the corner sofa with the chaise, please?",
 "beige L-shaped sofa",
 "I want to stretch my legs out while watching something. Go to the sectional sofa with the chaise end.",
 "There's a beige fabric settee shaped like an L. Go there.",
 "the L sofa, not the one with the massager"]),
("od", COFF, 13, [13], [
 "Go to the navy blue pillow.",
 "Could you find the dark blue velvet cushion?",
 "navy velvet cushion",
 "I dropped an earring between the cushions. Take me to the navy velvet one.",
 "It's a soft cushion. The navy velvet one with a button.",
 "the blue cushoin, not the orange or yellow ones"]),
("od", FD, 5, [5], [
 "Take me to the yellow chair.",
 "Could you go to the wooden seat that's painted yellow?",
 "yellow wooden seat",
 "I spilled juice on the yellow seat. Take me to it so I can wipe it off.",
 "I'm looking for a seat painted bright yellow. It's made of wood.",
 "the yellow one, not the white plastic chair"]),
("od", APT, 48, [48], [
 "Go to the red leather office chair.",
 "Could you take me to the red swivel seat with wheels?",
 "red leather swivel seat",
 "I need to adjust the height of my work seat. Take me to the red one on wheels.",
 "It's a seat covered in red leather. It has armrests and castors.",
 "the red chari with wheels"]),
("od", FI, 23, [23], [
 "Take me to the blue mug full of pencils.",
 "Could you find the cobalt blue cup that holds the pencils?",
 "blue pencil cup",
 "I need to sketch something. Go to the blue cup with the pencils in it.",
 "It's a dark blue ceramic cup. Someone uses it to hold pencils.",
 "blue muug with pencils, not the yellow one"]),
("od", FE, 14, [14], [
 "Go to the black metal chair.",
 "Could you take me to the odd one out at the dining table, the black metal seat?",
 "black bistro seat",
 "I want to swap out the seat that doesn't match. Take me to the black metal one.",
 "It's a metal cafe-style seat, black. It doesn't go with the green ones.",
 "the black seat, not the green ones"]),
# ---------------- ord ----------------
("ord", C829, 110, [110], [
 "Take me to the honey-coloured small table in the bathroom.",
 "Could you go to the light wood table with the X-shaped legs in the bathroom?",
 "bathroom, honey wood side table",
 "I need to put my book down somewhere while I soak. Go to the honey-coloured stand in the bathroom.",
 "It's a little table in warm honey-coloured wood. It stands in the bathroom.",
 "the honey wood one in the bathroom, not a dark one"]),
("ord", C829, 190, [190], [
 "Go to the marble counter in the bathroom.",
 "Could you take me to the dark wood and white marble vanity with the gold frame in the bathroom?",
 "bathroom vanity top, marble and gold",
 "I left my watch by the basin. Take me to the marble-topped worktop in the bathroom.",
 "This is a slab of white marble on dark wood. It's in the bathroom.",
 "bathroom countr, the marble one"]),
("ord", COFF, 7, [7], [
 "Take me to the white desk in the rec room.",
 "Could you go to the white wooden work table in the rec room?",
 "rec room white work table",
 "My charger is plugged in at the white table. Take me to that one in the rec room.",
 "It's a white wooden writing table. It's in the rec room, not one of the brown ones.",
 "white dsek in the rec room"]),
("ord", FH, 50, [50], [
 "Go to the white wardrobe in the master bedroom.",
 "Could you take me to the glossy white closet in the master bedroom?",
 "master bedroom white closet",
 "I need a clean shirt. Take me to the tall white cupboard in the master bedroom.",
 "It's a glossy white closet with three doors. It's in the master bedroom.",
 "white wardobe in the master bedroom, not the pine one"]),
("ord", FC, 36, [36], [
 "Take me to the green lamp in the study.",
 "Could you go to the green banker's light in the study?",
 "study, green desk light",
 "It's too dim to read these papers. Go to the green light in the study.",
 "I mean a green metal desk light. It's in the study.",
 "green lamp, study"]),
("ord", FI, 15, [15], [
 "Go to the black leather chair in the studio.",
 "Could you take me to the black high-backed swivel seat in the studio?",
 "studio, black leather desk seat",
 "I want to sit at my workstation. Go to the black leather swivel seat in the studio.",
 "It's a high-backed swivel seat in black leather. It's in the studio, at the white desk.",
 "the black one in the studio, not the blue mesh seat"]),
("ord", APT, 42, [42], [
 "Take me to the gray cabinet in the bathroom.",
 "Could you go to the gray vanity unit in the bathroom?",
 "bathroom gray vanity",
 "We're out of toilet roll. Take me to the gray cupboard in the bathroom.",
 "I'm looking for a gray wooden cupboard under the basin. It's in the bathroom.",
 "gray cabnet in the bathroom, not the metal one in the office"]),
# ---------------- ard ----------------
("ard", C829, 192, [192], [
 "My dog needs somewhere to sleep.",
 "Where can the puppy curl up for a nap?",
 "somewhere for the cat to doze",
 "The dog has been running around all day and is exhausted. Take me to where he can lie down.",
 "Could you show me where our dog sleeps?",
 "spot for the kitten to snooze"]),
("ard", COFF, 25, [25], [
 "What time is it?",
 "I need to check the time, could you take me to something that shows it?",
 "check the time",
 "My phone died and I don't know if I'm late for the meeting. Take me to where I can see the time.",
 "Where can I see how many minutes are left before lunch?",
 "need to know the hour"]),
("ard", APT, 27, [27], [
 "I want to boil water for tea.",
 "Could you take me to where I can heat water quickly for a cuppa?",
 "boil water",
 "I'm cold and fancy a hot cup of tea. Where do I boil the water?",
 "Where can I get hot water fast for my instant noodles?",
 "need hot water for coffee"]),
("ard", FD, 27, [27], [
 "I need to iron my shirt.",
 "Could you take me to where I can press my trousers?",
 "get creases out of a shirt",
 "I have a job interview in an hour and my blouse is crumpled. Where do I smooth it out?",
 "Where can I press my wrinkled clothes?",
 "press a shirt"]),
("ard", FH, 4, [4], [
 "Where do I drop my keys?",
 "Could you take me to the place where the house keys are kept?",
 "house keys",
 "I'm about to head out and can't find my keys. Take me to where they usually get left.",
 "Where do we put our keys when we come home?",
 "find my keys"]),
("ard", FE, 33, [33], [
 "I need to dry the washing.",
 "Could you take me to where I can dry these wet clothes?",
 "dry wet laundry",
 "It's raining outside, so I can't hang the laundry out. Where do I dry it?",
 "The wash has finished and the clothes are soaked. Where should they go to dry?",
 "tumble the towels dry"]),
("ard", SB, 21, [21], [
 "I need to know the time.",
 "Could you show me what can tell me the time in here?",
 "time check",
 "I think I overslept. Take me to where I can see what time it is.",
 "How late is it? Show me something that tells the time.",
 "set my wake-up alarm"]),
("ard", FI, 20, [20], [
 "I need to print the plans.",
 "Could you take me to where I can print an A3 drawing?",
 "print a document",
 "The client wants a paper copy of the drawings. Where can I run them off?",
 "Where do I scan this contract?",
 "make a hard copy"]),
# ---------------- s ----------------
("s", SK, 3, [3], [
 "Go to the cabinet under the sink.",
 "Could you take me to the cupboard directly below the sink?",
 "cupboard under sink",
 "We're out of dish soap and the spare is kept below the sink. Take me to that cupboard.",
 "There's a row of white cupboards along the wall. I mean the one right under the sink.",
 "the cupbaord beneath the sink, not the ones above it"]),
("s", SK, 22, [22], [
 "Take me to the chair farthest from the door.",
 "Could you go to the seat at the table that's furthest from the doorway?",
 "seat farthest from door",
 "I want to sit away from the draught. Take me to the seat farthest from the door.",
 "There are several seats around the table. Go to the one at the far end, away from the door.",
 "the chair furthest from the dorr"]),
("s", SL, 3, [3], [
 "Go to the middle pillow on the sofa.",
 "Could you take me to the cushion between the other two on the couch?",
 "middle cushion on sofa",
 "My remote fell behind the cushions. Take me to the one in the middle of the couch.",
 "There are three cushions on the couch. I mean the centre one, between the other two.",
 "facing the sofa, the cushion in between, not the ones at either end"]),
("s", SB, 9, [9], [
 "Take me to the lamp closest to the door.",
 "Could you go to the bedside light nearest the bedroom door?",
 "bedside light nearest door",
 "I want to switch on a light as soon as I come in. Take me to the bedside light on the door side.",
 "There are two lights on the bedside tables. Go to the one closer to the door.",
 "lamp nearest the door, not the one by the window"]),
("s", SB, 2, [2], [
 "Standing at the foot of the bed facing the headboard, take me to the white pillow on the left.",
 "Could you go to the left one of the two white ones at the head of the bed, as seen from the foot?",
 "from foot of bed: left white one at the head",
 "Facing the headboard from the end of the bed, my side is the left. Go to the white one there.",
 "The bed has two white pillows at its head. Looking from the foot, go to the left one.",
 "the white pilow on the left as you look up the bed, not the red one"]),
("s", APT, 39, [39], [
 "Go to the plant on top of the dresser.",
 "Could you take me to the little pot sitting on the chest of drawers?",
 "potted thing on the chest of drawers",
 "The succulent needs a drop of water. Take me to the one sitting on top of the drawers in the bedroom.",
 "There's a small potted green thing. It's sitting on top of the dresser.",
 "plnat on the dresser"]),
("s", APT, 13, [13], [
 "Take me to the lower of the two books on the living room bookshelf.",
 "Could you go to the book lying on the bottom shelf in the living room?",
 "bottom-shelf volume, living room bookcase",
 "I want to flip through some photos. Go to the volume on the lowest shelf of the living room bookcase.",
 "There are two volumes on the living room bookcase. I mean the one lower down.",
 "the volume on the bottom shelf, not the one higher up"]),
("s", FE, 13, [13], [
 "Go to the green chair next to the black one.",
 "Could you take me to the sage green seat that's right beside the black metal one?",
 "green seat beside black seat",
 "I want to sit by my friend, who's on the black metal seat. Take me to the green seat closest to it.",
 "At the dining table there's one black metal seat. Go to the green seat right next to it.",
 "the green one nearest the black chair, not the black one itself"]),
("s", FH, 6, [6], [
 "Take me to the smaller sofa.",
 "Could you go to the little two-seater couch, not the long one?",
 "smaller couch",
 "I only need a short rest. Go to the smaller of the two couches in the living room.",
 "There are two couches in the living room. I mean the smaller one.",
 "the smaller sofa, not the long green one"]),
("s", FC, 7, [7], [
 "Go to the lamp on the side table.",
 "Could you take me to the small light sitting on the little black table by the sofa?",
 "light on the side table",
 "I want a soft light while I read on the couch. Take me to the little light sitting on the black table.",
 "There are two lights by the sofa. I mean the small one standing on the table, not the tall one on the floor.",
 "small lamp on the side table"]),
("s", FI, 9, [9], [
 "Take me to the chair closest to the screen in the meeting room.",
 "Could you go to the meeting room seat nearest the wall display?",
 "meeting room seat nearest screen",
 "I need to plug my laptop into the display. Take me to the seat right by it in the meeting room.",
 "In the meeting room there's a big screen on the wall. Go to the seat nearest to it.",
 "facing the wall screen in the meeting room, the seat closest to it"]),
("s", FD, 22, [22], [
 "Go to the stool nearest the fridge.",
 "Could you take me to whichever bar seat is closer to the refrigerator?",
 "seat closest to fridge, kitchenette",
 "I want to grab a cold drink and sit down. Take me to the seat closest to the fridge.",
 "There are two stools in the kitchenette. Go to the one nearer the fridge.",
 "the seat by the frige, not the black metal one"]),
]

TYPOS = ["armchiar", "cuhsion", "mgu", "boook", "muug", "stoool", "towle", "chiar", "tabel", "lmap",
         "houseplnat", "cushoin", "chari", "dsek", "wardobe", "cabnet", "countr", "cupbaord", "dorr", "pilow",
         "plnat", "frige"]

def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "evals", "blind", "round24.jsonl")
    assert len(G) == 48, len(G)
    lines = []
    rng = random.Random(24)  # shuffle wording order so styles/typos are not always in the same slot
    for gi, (t, m, tgt, acc, qs) in enumerate(G, 1):
        assert len(qs) == 6 and tgt in acc
        qs = list(qs); rng.shuffle(qs)
        for wi, q in enumerate(qs, 1):
            lines.append({"id": "b24-g%02d-w%d" % (gi, wi), "map": m, "query": q, "type": t,
                          "target": tgt, "accept": acc, "group": "b24-g%02d" % gi})
    with open(out, "w") as f:
        for l in lines:
            f.write(json.dumps(l) + "\n")
    print("wrote", len(lines), "lines to", os.path.normpath(out))

if __name__ == "__main__":
    main()
