"""Write evals/blind/round14.jsonl: 48 groups x 6 hand-written wordings (blind round 14).

Every wording below was written by hand for this round from the map files only.
TYPOS lists the deliberately misspelt nouns (group, wording index, typo, intended word).
Run: python3 make_round14.py  (then check_spatial_round14.py and validate.py)
"""
import json
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "evals/blind/round14.jsonl"

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
COF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
SOFF = "../maps/scan_office.json"
SBED = "../maps/scan_bedroom.json"
FD, FE, FF, FG, FH, FI = (f"maps/flat_{c}.json" for c in "defghi")

# (map, type, target, accept, [6 wordings])
GROUPS = [
    # ---------------- scene_00829 (caption map) ----------------
    (C829, "o", 4, [4, 9, 32, 79, 191, 261, 263], [
        "Go to an easy chair.",
        "armchair, any of them",
        "I want to sink into one of the big comfy armchairs, doesn't matter which.",
        "Could you bring me over to a lounge chair? Any one will do.",
        "Looking for a recliner-type seat. The cushy upholstered kind with arms.",
        "nearest armcahir pls",
    ]),
    (C829, "o", 42, [42, 197, 212, 259], [
        "take me to a book",
        "Where are the books in this place? Any one is fine.",
        "I feel like reading. There should be some volumes lying around, show me one.",
        "any hardback or novel",
        "Could you guide me to something to read, like one of the leather-bound volumes?",
        "a bok, whichever is closest",
    ]),
    (C829, "or", 112, [112, 233], [
        "Take me to the mirror in the bathroom.",
        "bathroom looking glass",
        "I need to check my hair. Is there a mirror in one of the bathrooms? Either is fine.",
        "Could you find me a wall mirror, but only the ones in a bathroom please.",
        "There's a framed mirror hanging somewhere. I mean one of the bathroom ones, not the bedroom or the other rooms.",
        "bathrom mirror",
    ]),
    (C829, "or", 261, [261, 263], [
        "take me to an easy chair in the bedroom",
        "Is there an armchair in the bedroom? Bring me to it.",
        "bedroom armchair, either one",
        "I'd like to sit down somewhere quiet. One of the padded chairs in the bedroom would be perfect.",
        "Could you lead me to a lounge seat? It has to be the ones in the bedroom, not the living room.",
        "Any of the brown recliners that are in the sleeping room, please.",
    ]),
    (C829, "od", 211, [211], [
        "Where is the deep blue bowl with the gold patterns?",
        "blue ceramic bowl, gold detail",
        "I want to look at that glossy dark blue dish. It has golden patterns painted on it.",
        "Could you show me the decorative bowl, the blue one, not the white bowl with sweets?",
        "the ornamental blue bwol",
        "There's a shiny cobalt-coloured bowl with gold swirls. That one please.",
    ]),
    (C829, "ord", 263, [263], [
        "Please take me to the brown leather easy chair in the bedroom.",
        "bedroom armchair - the leather one",
        "In the bedroom there are two brown armchairs. I want the leather one, not the woven fabric one.",
        "Could you bring me to the leather recliner that's in the bedroom?",
        "I'd like the dark brown leather lounge seat with lumbar support. It's in the bedroom.",
        "leather armchiar in bedroom",
    ]),
    (C829, "ard", 192, [192], [
        "My dog needs somewhere soft to nap. Where should I put him?",
        "where does the puppy sleep",
        "I've brought my cat along and she wants to curl up somewhere cosy. Take me there.",
        "Could you show me the spot meant for the pet to rest?",
        "The dog is tired and keeps looking for his own place to lie down.",
        "somewhere for my kitten to snooze",
    ]),
    # ---------------- scene_office3 (caption map) ----------------
    (COF3, "o", 8, [8, 13, 20, 40], [
        "take me to a pillow",
        "Any cushion will do, I just need one.",
        "My back hurts. Where's a cushion I can grab, whichever colour?",
        "Could you find me one of the throw cushions?",
        "cushoin",
        "I'm after something soft to lean on, one of the pillows. Any of them.",
    ]),
    (COF3, "or", 7, [7, 55, 64], [
        "Navigate to a desk in the rec room.",
        "Could you bring me to one of the workstations in the rec room? Any of them.",
        "rec room workstation, any",
        "I have to write something up. Is there a writing table in the recreation room? Whichever one.",
        "a dekss in the rec room",
        "Any desk over in the rec room, white or brown, it doesn't matter.",
    ]),
    (COF3, "od", 13, [13], [
        "Show me the navy blue pillow.",
        "velvet cushion, dark blue",
        "I want the soft navy cushion with the button. It's a bit bigger than the others.",
        "Could you show me the dark blue velvety cushion? Not the orange or the yellow one.",
        "the navy cushion, please",
        "There's a plush pillow in deep navy. It has a buttoned design. Go there please.",
    ]),
    (COF3, "od", 7, [7], [
        "Bring me to the white desk.",
        "white wooden work table",
        "I'm looking for the writing table that's white, not the brown ones.",
        "Could you guide me to the white-painted wooden workstation with the USB port?",
        "the pale one of the desks, not a brown one",
        "There's a white wooden writing table somewhere. Bring me to it.",
    ]),
    (COF3, "ord", 20, [20], [
        "take me to the yellow pillow in the rec room",
        "the yellow cushion in the rec room",
        "In the rec room there's a lumpy patterned cushion. It's yellow. Take me there.",
        "Could you find the soft yellow cushion in the recreation room for me?",
        "rec room - yellow cushion",
        "I want the one in the rec room that's yellow, not the orange or navy pillows.",
    ]),
    (COF3, "ard", 25, [25], [
        "What time is it? Take me to where I can check.",
        "I need to see the time",
        "My phone's dead and I have a call at three. Where can I see the hour?",
        "Could you show me something that tells the time?",
        "I keep losing track of the minutes. Is there anything on the wall to read the time from?",
        "need to check time, no watch",
    ]),
    # ---------------- scan_office ----------------
    (SOFF, "o", 3, [3, 4, 5, 6, 7, 8, 9, 10], [
        "Find an office chair for me.",
        "any desk seat",
        "I need to sit down and work. Bring me to one of the swivel seats at the tables.",
        "Could you find me a rolling chair? Any colour is fine.",
        "computer seat, whichever",
        "I just want one of the task chairs, black or blue, doesn't matter.",
    ]),
    (SOFF, "od", 30, [30], [
        "take me to the white keyboard",
        "Could you bring me to the white keybaord?",
        "I'm after the light-coloured keys, not the black set.",
        "white computer keys",
        "There's a keyboard that's white. That's the one I need.",
        "the pale typing board please",
    ]),
    (SOFF, "ard", 17, [17], [
        "I want to sketch out a plan for the team where everyone can see it.",
        "need to write on something big with a marker",
        "We're brainstorming and I need a surface to draw diagrams on. Take me there.",
        "Could you take me to where I can jot ideas in marker for the meeting?",
        "I have to explain a flowchart to my colleagues standing up.",
        "where can I doodle with a dry-erase pen",
    ]),
    (SOFF, "s", 21, [21], [
        "Go to the trash can by the door.",
        "bin nearest the door",
        "I need to throw something away on my way out. Which bin is right next to the exit?",
        "Could you lead me to the wastebasket near the doorway, not the one in the far corner?",
        "There are two rubbish bins. I want the one beside the door.",
        "the garbage bin closest to the dor",
    ]),
    # ---------------- scan_bedroom ----------------
    (SBED, "o", 2, [2, 3, 4, 5], [
        "Take me to a pillow.",
        "any cushion on the bed",
        "I need something to prop my head up. Any cushion will do.",
        "Could you bring me to one of the pillows? Colour doesn't matter.",
        "pilow",
        "Find me a cushion, whichever is nearest. White, red or blue are all fine.",
    ]),
    (SBED, "od", 4, [4], [
        "take me to the red pillow",
        "red cushion",
        "I want the red cushion. Not the white ones or the blue one.",
        "Could you point me to the crimson throw cushion?",
        "There's one cushion that's red. That's what I'm after.",
        "the red cusion please",
    ]),
    (SBED, "s", 9, [9], [
        "Take me to the lamp nearest the door.",
        "bedside light closest to the door",
        "I just walked in and want to switch on the light. Which one is right by the entrance?",
        "Could you bring me to the reading light next to the doorway side of the bed, not the one by the window?",
        "Facing the headboard from the foot of the bed, I mean the light on the right, by the door.",
        "lmap nearest door",
    ]),
    # ---------------- flat_d ----------------
    (FD, "ord", 9, [9], [
        "I need the silver lamp in the studio.",
        "silver desk light, studio",
        "In the studio there's a little metal reading light with a bendy arm. It's silver. Take me to it.",
        "Could you find the small silver light in the studio? Not the tall white floor one.",
        "the silver light on the writing desk in the studo",
        "I'd like the compact silver desk lamp that's in the main studio room.",
    ]),
    (FD, "od", 4, [4], [
        "Take me to the white plastic chair.",
        "white moulded seat",
        "I want the white plastic seat. Not the yellow one, not the mesh one.",
        "Could you bring me over to the white moulded plastic chair?",
        "This is a plain white plastic seat. It's at the round dining table.",
        "the white plastic seat by the round table",
    ]),
    (FD, "s", 21, [21], [
        "Head to the stool nearest the trash can.",
        "stool closest to the bin",
        "There are two bar seats in the kitchenette. I want the one nearer the pedal bin.",
        "Could you bring me to whichever of the high seats is closer to the rubbish bin?",
        "Facing the worktop, it's the seat on the right, the one by the bin.",
        "the stol next to the bin",
    ]),
    (FD, "or", 2, [2, 3], [
        "Take me to a table in the studio.",
        "studio - a tabletop, any",
        "I need to put my bag down. In the studio, either the round dining one or the low glass-topped one.",
        "Could you guide me to one of the tables in the studio?",
        "anywhere in the studio to set a plate down, the round one or the coffee one",
        "I want something flat to lean on in the studio, any of the two.",
    ]),
    # ---------------- flat_e ----------------
    (FE, "or", 11, [11, 12, 13, 14, 15], [
        "Where can I find a chair in the dining room?",
        "dining room seat, any",
        "I'd like to sit down for a bit. Any seat in the dining room is fine.",
        "Could you find me somewhere to sit at the dining table? Whichever one.",
        "any of the dining room chiars",
        "The dining room has several seats around the table. Take me to one, I don't mind which.",
    ]),
    (FE, "ord", 14, [14], [
        "Go to the black metal chair in the dining room, please.",
        "dining room, black bistro seat",
        "In the dining room most of the seats are sage green. I want the black metal one that doesn't match.",
        "Could you bring me to the dark metal bistro-style seat in the dining room?",
        "I mean the odd one out at the dining table, the black one, not a green one.",
        "black metal chair dining room",
    ]),
    (FE, "ard", 32, [32], [
        "My clothes are dirty and I need to get a load going.",
        "need to do laundry",
        "I spilled coffee all over my shirt. Where can I put it in for a wash?",
        "Could you take me to where I can wash my clothes?",
        "The kids' sports kit is muddy, I have to run a wash cycle.",
        "somewhere to wash my jeans",
    ]),
    (FE, "s", 29, [29], [
        "Navigate to the mirror above the washbasin.",
        "looking glass over the sink",
        "I want to shave. Which glass hangs right above the basin?",
        "Could you bring me to the mirrored cabinet over the bathroom sink, not the round one in the lounge?",
        "There's a medicine cabinet with a mirror front. It hangs directly over the washbasin.",
        "the mirorr above the basin",
    ]),
    (FE, "o", 4, [4, 16, 26], [
        "Take me to a lamp.",
        "any light",
        "It's getting dark in here. Take me to any of the lights, I'll switch it on.",
        "Could you find me a lamp? Any of them, floor, pendant or bedside.",
        "light fitting, whichever",
        "Whichever light fixture is nearest, please.",
    ]),
    # ---------------- flat_f ----------------
    (FF, "ord", 14, [14], [
        "Bring me to the yellow chair in the kitchen.",
        "kitchen - mustard seat",
        "At the kitchen table most seats are blue. I want the mustard-yellow one.",
        "Could you guide me to the yellow painted seat in the kitchen, not a blue one?",
        "This is a yellow wooden seat. It's in the kitchen, at the dining table.",
        "yellow chiar in kitchen",
    ]),
    (FF, "or", 2, [2, 3], [
        "I'd like to go to an armchair in the living room.",
        "living room armchair",
        "I want to sit by the fire in the lounge. Any of the single easy chairs in the living room.",
        "Could you bring me to one of the upholstered single seats in the living room? Either is fine.",
        "any of the comfy chairs in the lounge",
        "Living room, one of the wingback-type seats, doesn't matter which.",
    ]),
    (FF, "ard", 25, [25], [
        "I want to look at the stars tonight.",
        "stargazing",
        "There's supposed to be a meteor shower later. Where can I get a close look at the sky?",
        "Could you take me to what I'd use to see the planets?",
        "I'd like to look at the moon up close.",
        "where can I watch the night sky properly",
    ]),
    (FF, "s", 13, [13], [
        "Take me to the chair at the dining table that is closest to the dresser.",
        "kitchen seat nearest the tall dresser",
        "At the dining table, I want the seat that's nearest the sage-green dresser with the plates.",
        "Could you bring me to whichever dining chair is closest to the kitchen dresser?",
        "This is a blue ladder-back seat. It's the one right next to the tall green dresser.",
        "dining seat nearest the plate dresser",
    ]),
    # ---------------- flat_g ----------------
    (FG, "o", 2, [2, 3], [
        "Where's a bicycle?",
        "any bike",
        "I want to go for a ride. Take me to one of the bikes, any of them.",
        "Could you bring me to one of the bikes in the garage?",
        "bikes - either",
        "I need to pump up a tyre on one of the bikes, whichever.",
    ]),
    (FG, "od", 34, [34], [
        "Go to the teal lamp.",
        "teal glass bedside light",
        "I want the bedside light with the teal glass base. Not the beige one.",
        "Could you show me the lamp with a blue-green glass base and white shade?",
        "This is a little reading light. Its base is teal glass.",
        "the teal lampp",
    ]),
    (FG, "ord", 37, [37], [
        "Take me to the wicker basket in the bedroom.",
        "bedroom wicker hamper",
        "I have dirty clothes to drop off. There's a woven hamper with a lid in the bedroom.",
        "Could you bring me to the wicker laundry hamper in the bedroom, not the plastic one?",
        "This is a lidded wicker hamper. It's in the bedroom.",
        "wicker hamper in the bedrom",
    ]),
    (FG, "ard", 5, [5], [
        "I need a screwdriver and a spanner.",
        "need tools",
        "The shelf is wobbly and I have to tighten a couple of screws. Where can I get what I need?",
        "Could you take me to where I'd find a hammer?",
        "My bike chain came off, I need a wrench.",
        "where are the pliers kept",
    ]),
    (FG, "s", 18, [18], [
        "Take me to the chair nearest the refrigerator.",
        "kitchen seat closest to the fridge",
        "There are two seats at the kitchen table. I want the one nearer the fridge.",
        "Could you bring me to whichever kitchen chair is closest to the fridge freezer?",
        "I mean the seat on the fridge side of the round table, not the one with the red cushion.",
        "seat nearest the frigde",
    ]),
    # ---------------- flat_h ----------------
    (FH, "od", 6, [6], [
        "Find the cream linen sofa.",
        "cream two-seater",
        "I want the small couch in cream linen, not the green velvet one.",
        "Could you bring me to the little cream loveseat?",
        "There's a compact two-seat couch. It's cream and linen.",
        "the cream-coloured loveseat",
    ]),
    (FH, "ord", 43, [43], [
        "Take me to the red lamp in the guest bedroom.",
        "guest room red bedside light",
        "In the guest bedroom there's a red ceramic reading light with a cream shade. That one please.",
        "Could you bring me to the red bedside light in the spare room?",
        "The guest bedroom has a red light on the bedside table. Take me to it.",
        "red lamp, guest bedrooom",
    ]),
    (FH, "s", 47, [47], [
        "Take me to the nightstand with the book on it.",
        "bedside table with the paperback",
        "In the master bedroom there are two white bedside tables. I want the one with the novel lying on top.",
        "Standing at the foot of the bed looking at the headboard, it's the bedside table on the right, the one with the orange book.",
        "There's a detective novel on a bedside table. Take me to that table, not the one with the lamp.",
        "nighstand with the book",
    ]),
    (FH, "or", 5, [5, 6], [
        "Show me a sofa in the living room.",
        "living room couch",
        "I want to lie down for ten minutes. Any couch in the living room is fine.",
        "Could you bring me to one of the couches in the lounge, either one?",
        "any settee, living room",
        "The living room has a big green couch and a small cream one. Either will do.",
    ]),
    (FH, "ard", 38, [38], [
        "I've just come back from a run and I'm covered in sweat.",
        "need to rinse off",
        "I want to wash my hair before going out. Where do I do that?",
        "Could you take me to where I can freshen up under running water?",
        "I got caught in the mud, I need to get clean all over.",
        "where can I have a quick wash head to toe",
    ]),
    # ---------------- flat_i ----------------
    (FI, "ord", 15, [15], [
        "Please go to the black leather chair in the studio.",
        "studio - black leather swivel seat",
        "In the studio there are two desk seats. I want the black leather one, not the blue mesh one.",
        "Could you bring me to the high-backed leather office seat in the studio?",
        "This is a black leather swivel seat. It's in the studio, at the white desk.",
        "black leather office seat in the studio",
    ]),
    (FI, "or", 6, [6, 7, 8, 9], [
        "Take me to a chair in the meeting room.",
        "meeting room seat",
        "I've got a client meeting soon. Any seat in the meeting room will do.",
        "Could you bring me to one of the seats around the meeting table? Red or gray, either.",
        "any seat in the meeting rm",
        "I'd like to sit in the meeting room, in whichever chiar is free.",
    ]),
    (FI, "o", 2, [2, 12, 13], [
        "Find me a desk.",
        "any workstation",
        "I need somewhere to fill in a form. The reception counter or one of the studio work tables, any.",
        "Could you bring me to one of the desks? It doesn't matter which.",
        "somewhere to work at, reception counter or drafting top, whichever",
        "I want a writing surface, the counter at reception or one of the drafting ones.",
    ]),
    (FI, "ard", 20, [20], [
        "I need to print out the A3 floor plans for the client.",
        "print a drawing",
        "The client wants a paper copy of the layout. Where can I get it printed?",
        "Could you take me to where I can scan a sketch?",
        "I have to make a hard copy of these plans before the meeting.",
        "need to copy and print a document",
    ]),
    (FI, "s", 36, [36], [
        "Take me to the mug on the coffee table.",
        "cup on the coffee table",
        "Someone left a cup of tea out. It's on the low table in front of the sofa.",
        "Could you bring me to the mug sitting on the coffee table, not the ones in the kitchen or on the desk?",
        "There's a cup of cold tea. It's on the teak coffee table in the living room.",
        "the mgu on the coffee table",
    ]),
]

# deliberately misspelt nouns: (group number, wording number, typo, intended)
TYPOS = [
    (1, 6, "armcahir", "armchair"), (2, 6, "bok", "book"), (3, 6, "bathrom", "bathroom"),
    (5, 5, "bwol", "bowl"), (6, 6, "armchiar", "armchair"), (8, 5, "cushoin", "cushion"),
    (9, 5, "dekss", "desks"), 
    (15, 2, "keybaord", "keyboard"), (17, 6, "dor", "door"), (18, 5, "pilow", "pillow"),
    (19, 6, "cusion", "cushion"), (20, 6, "lmap", "lamp"), (21, 5, "studo", "studio"),
    (23, 6, "stol ", "stool"), (25, 5, "chiars", "chairs"),
    (28, 6, "mirorr", "mirror"), (30, 6, "chiar", "chair"),
    (35, 6, "lampp", "lamp"), (36, 6, "bedrom", "bedroom"),
    (38, 6, "frigde", "fridge"), (40, 6, "bedrooom", "bedroom"),
    (41, 6, "nighstand", "nightstand"), 
    (45, 6, "chiar", "chair"), (48, 6, "mgu", "mug"),
]


def main() -> None:
    lines = []
    for n, (mp, typ, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, n
        assert target in accept, n
        g = f"b14-g{n:02d}"
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"{g}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": sorted(accept), "group": g}))
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    for gn, wn, typo, _ in TYPOS:
        q = GROUPS[gn - 1][4][wn - 1]
        assert typo in q, (gn, wn, typo, q)
    print(f"wrote {len(lines)} lines, {len(GROUPS)} groups to {OUT}")


if __name__ == "__main__":
    main()
