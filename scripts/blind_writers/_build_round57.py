"""Write evals/blind/round57.jsonl from the hand-written groups below (the writer's copy also wrote
scripts/specs.json, the per-group specs that _check_round57.py now takes from G directly).

Every wording was written by hand from the maps. `spec` holds what check.py needs to re-derive
each group's accept set or single-id claim from the map (kind labels, room, distinguishing
attributes, spatial relation), `typo` names the one misspelt token of w6, and `forbid` lists
words an `ard` group must not use (the object's kind).
"""

import json
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

G = []


def g(map_, type_, target, accept, spec, typo, w, forbid=()):
    assert len(w) == 6
    G.append(dict(map=map_, type=type_, target=target, accept=sorted(accept), spec=spec,
                  typo=typo, forbid=list(forbid), w=w))


# ---------------------------------------------------------------- caption map scene_00829
g(C829, "o", 42, [42, 197, 212, 259], {"kinds": ["book"]}, "novle", [
    "Take me to a book, any one will do.",
    "Could you guide me to one of the books lying around the place?",
    "Novel or hardback, whichever",
    "I want something to read while I wait, so any bound volume works, not a loose sheet of paper.",
    "This is my reading hour. Bring me over to whichever novel is closest.",
    "just take me to some novle, whichever one",
])
g(C829, "or", 160, [160, 162, 164], {"kinds": ["set of towels"], "room": "living room"}, "towles", [
    "Take me to the folded towels in the living room.",
    "Could you bring me to one of the stacks of towels in the lounge?",
    "Towel pile, living room",
    "I spilled my drink on the sofa, so I need one of those towel stacks in the sitting room, not anything from the bathroom.",
    "This is a mess I need to mop up. Go to the neatly stacked towels in the living room.",
    "where are the fluffy towles in the living room, take me there",
])
g(C829, "od", 211, [211], {"kinds": ["decorative bowl", "bowl with sweets"], "attrs": ["blue", "gold"]}, "paterns", [
    "Go to the deep blue bowl with the gold patterning.",
    "Could you take me to the glossy blue ceramic dish decorated in gold?",
    "Blue-and-gold ceramic bowl",
    "I want the blue dish with gold swirls, not the white one with the golden rim that holds sweets.",
    "This is for a photo of my favourite piece. Take me to the cobalt bowl with gilded patterns.",
    "the shiny blue bowl with gold paterns, go there",
])
g(C829, "od", 184, [184], {"kinds": ["couch"], "attrs": ["l-shaped", "beige"]}, "chaize", [
    "Take me to the L-shaped beige couch with the chaise end.",
    "Could you guide me to the corner sofa, the beige fabric one with a chaise?",
    "Beige L-shaped sectional",
    "I want to lie down with my legs up, so the sectional with the chaise, not the plush beige one with massage.",
    "This is where I like to nap. Head to the beige corner settee with the storage compartment.",
    "take me to the big corner sofa with the chaize",
])
g(C829, "ord", 254, [254], {"kinds": ["curtain", "bed curtain"], "room": "bedroom", "attrs": ["silky", "shimmering"]}, "bedrom", [
    "Go to the silky blue-grey curtain in the bedroom.",
    "Could you take me to the shimmery pale blue drapes in the bedroom?",
    "Shimmery blue-gray bedroom drape",
    "I want to draw the silky grey-blue drape in the bedroom, not the flowery one hanging round the bed.",
    "This is about the light waking me up. Bring me to the bedroom curtain with the shimmering threads.",
    "the glossy blue-grey drape in the bedrom please",
])
g(C829, "ard", 192, [192], {"need_kinds": ["bed for pet"], "need_words": ["pet", "dog", "cat"]}, "pupy", [
    "Take me to where the dog sleeps, the soft white and brown spot.",
    "Could you show me where the puppy curls up for its naps?",
    "Dog's sleeping spot",
    "The cat looks tired, so take me to its own little sleeping place, not where the humans sleep.",
    "This is the dog's nap time. Go to the plush spot where it curls up.",
    "where does the pupy sleep, take me to its comfy spot",
], forbid=["bed", "basket", "cushion"])

# ---------------------------------------------------------------- caption map scene_office3
g(OFF3, "o", 8, [8, 13, 20, 40], {"kinds": ["pillow"]}, "cusion", [
    "Take me to a cushion.",
    "Could you bring me to any of the pillows around here?",
    "Any cushion, please",
    "My back hurts from this chair, so any cushion will do, not a blanket.",
    "This is for my sore neck. Go to one of the cushions, whichever is nearest.",
    "take me to a cusion, any one is fine",
])
g(OFF3, "or", 11, [4, 11, 12, 27], {"kinds": ["curtain"], "room": "rec room"}, "recreaton", [
    "Go to the curtains in the rec room.",
    "Could you take me to a set of drapes in the recreation room?",
    "Rec room drapes",
    "The sun is in my eyes, so I need a curtain in the games room, not the blinds.",
    "This is too much glare. Bring me to the drapes hanging in the rec room.",
    "take me to the drapes in the recreaton room",
])
g(OFF3, "od", 7, [7], {"kinds": ["desk"], "attrs": ["white"]}, "wodden", [
    "Take me to the white wooden desk.",
    "Could you lead me to the white workstation, the wooden one?",
    "White wood writing table",
    "I want to work at the white wooden workstation, not either of the brown ones.",
    "This is where I left my notes. Go to the desk that's painted white.",
    "the white wodden work table, take me there",
])
g(OFF3, "ord", 24, [24], {"kinds": ["window"], "room": "rec room", "attrs": ["red", "frosted"]}, "lookng", [
    "Go to the frosted red window in the rec room.",
    "Could you take me to the red frosted glass pane in the recreation room?",
    "Frosted red glass, rec room",
    "I want to see the red frosted pane in the rec room, not the red one with the white blind and clock.",
    "This is the odd coloured glass I mentioned. Head to the rec room window with red frosted glass in a metal frame.",
    "take me to the frosted red pane in the rec room, the foggy lookng one",
])
g(OFF3, "ard", 25, [25], {"need_kinds": ["clock"], "need_words": []}, "tiem", [
    "Take me to where I can check the time in the rec room.",
    "Could you bring me somewhere I can see what time it is?",
    "Need time check, rec room",
    "I'm running late, so take me to whatever on the wall tells the hour, black with a red dot.",
    "This is about being on time. Go to the black wall-mounted thing that shows the hour.",
    "what time is it, take me to where i can see the tiem",
], forbid=["clock", "watch", "timer"])
g(OFF3, "ard", 67, [67], {"need_kinds": ["remote-control"], "need_words": []}, "chanels", [
    "Take me to whatever I use to switch channels in the rec room.",
    "Could you help me find what I'd use to flip through channels?",
    "Something to change channels",
    "I want to turn the volume down, so take me to the little black and white handheld gadget.",
    "This is movie night. Go to the handheld gadget that flips the channels.",
    "take me to the thing that changes the chanels",
], forbid=["remote", "control", "controller", "clicker"])

# ---------------------------------------------------------------- flat_c
g(FC, "o", 5, [5, 7, 28, 36], {"kinds": ["lamp"]}, "ligth", [
    "Take me to a lamp.",
    "Could you guide me to any light I can switch on?",
    "Any standing or table light",
    "It's getting dark, so any lamp will do, not the ceiling light.",
    "This is too dim for reading. Bring me to one of the lights in the flat.",
    "take me to any ligth at all",
])
g(FC, "s", 27, [27], {"kinds": ["nightstand"], "rel": "holds", "ref": 29}, "clok", [
    "Go to the bedside table that has the alarm clock on it.",
    "Could you take me to the nightstand with the red clock sitting on top?",
    "Bedside table under alarm clock",
    "I want to switch off the alarm, so the bedside table holding the clock, not the one with the pink lamp.",
    "This is the side of the bed where my alarm sits. Take me to the night table underneath it.",
    "go to the bedside table with the alarm clok on it",
])
g(FC, "ard", 40, [40], {"need_kinds": ["sink"], "room": "bathroom", "need_words": []}, "bathrom", [
    "Take me somewhere in the bathroom to wash my hands.",
    "Could you bring me to where I can rinse my face in the bathroom?",
    "Hand washing, bathroom",
    "I've got paint on my fingers, so somewhere in the bathroom to wash up, not the kitchen.",
    "This is before dinner. Go where I can wash my hands in the bathroom.",
    "i need to wash my hands in the bathrom",
], forbid=["sink", "basin", "washbasin", "tap", "faucet"])
g(FC, "od", 2, [2], {"kinds": ["armchair"], "attrs": ["mustard"]}, "musturd", [
    "Take me to the mustard yellow armchair.",
    "Could you take me to the yellow fabric easy chair?",
    "Mustard-coloured easy chair",
    "I want to sit in the yellow one, not the grey armchair.",
    "This is my favourite seat. Lead me to the mustard upholstered chair.",
    "the musturd yellow comfy chair, take me there",
])

# ---------------------------------------------------------------- flat_d
g(FD, "or", 21, [21, 22], {"kinds": ["stool"], "room": "kitchenette"}, "kitchenete", [
    "Take me to the stools in the kitchenette.",
    "Could you lead me to one of the bar seats in the little kitchen?",
    "Kitchenette bar stool",
    "I only want a quick snack, so a perch in the kitchenette is fine, not the dining table in the studio.",
    "This is breakfast time. Go to either of the backless seats in the kitchenette.",
    "take me to one of the bar seats in the kitchenete",
])
g(FD, "s", 4, [4], {"kinds": ["chair"], "rel": "nearest", "ref": 12}, "bookcace", [
    "Go to the chair closest to the bookcase.",
    "Could you take me to the seat at the round table on the bookshelf side?",
    "Dining chair nearest bookcase",
    "I want a board game off the shelves, so the dining seat nearest the bookcase, not the one on the far side of the table.",
    "This is the spot nearest the books. Take me to the dining seat closest to the tall bookcase.",
    "take me to the dining seat closest to the bookcace",
])
g(FD, "ard", 27, [27], {"need_kinds": ["ironing board"], "need_words": []}, "iorn", [
    "Take me somewhere I can press my shirt.",
    "Could you bring me to where I can get the creases out of my trousers?",
    "Press shirt, laundry room",
    "I have an interview tomorrow, so take me where I can smooth out my wrinkled blouse, not where clothes get washed.",
    "This is a crumpled shirt. Go to where I can flatten out the creases in the laundry room.",
    "my shirt is all creased, take me where i can iorn it",
], forbid=["board", "ironing board"])
g(FD, "ord", 2, [2], {"kinds": ["table"], "room": "studio", "attrs": ["black", "glass"]}, "blak", [
    "Go to the low black table with the glass top in the studio.",
    "Could you take me to the glass-topped coffee table in the studio, the black metal one?",
    "Studio's low black glass-top",
    "I want to put my drink down by the sofa bed, so the low black glass-top in the studio, not the round pine one.",
    "This is where the magazines go. Take me to the low metal piece with a glass surface in the studio.",
    "the low blak glass-top in the studio, take me there",
])

# ---------------------------------------------------------------- flat_f
g(FF, "s", 37, [37], {"kinds": ["cabinet"], "rel": "above", "ref": 36}, "cupbord", [
    "Go to the cupboard above the bathroom basin.",
    "Could you take me to the cabinet mounted over the washbasin?",
    "Cupboard over washbasin",
    "I need a plaster, so the little cupboard above the basin, not the big green dresser in the kitchen.",
    "This is where the medicine is kept. Take me to the wall cabinet right over the sink.",
    "take me to the cupbord above the sink",
])
g(FF, "o", 7, [7, 32], {"kinds": ["rug"]}, "carpit", [
    "Take me to a rug.",
    "Could you lead me to one of the carpets on the floor?",
    "Any floor mat",
    "I want to do some stretches on something soft, so any rug will do, not the bare floorboards.",
    "This is yoga time. Go to whichever carpet is nearest.",
    "take me to any carpit in the house",
])
g(FF, "od", 3, [3], {"kinds": ["armchair"], "attrs": ["cream", "leather"]}, "lether", [
    "Take me to the cream leather armchair.",
    "Could you bring me to the off-white leather chair with the rounded arms?",
    "Cream leather easy chair",
    "I'd rather sit on leather than wool, so the cream one, not the red tartan wingback.",
    "This is the comfiest seat in the lounge. Go to the pale leather armchair.",
    "take me to the cream lether chair with round arms",
])
g(FF, "ard", 25, [25], {"need_kinds": ["telescope"], "need_words": []}, "starz", [
    "Take me to where I can look at the stars.",
    "Could you bring me to the thing on a tripod for stargazing?",
    "Stargazing gear, porch",
    "The sky is clear tonight, so take me where I can see the planets up close, not just sit and look at the garden.",
    "This is a clear night. Go to whatever lets me see the moon up close on the porch.",
    "take me where i can look at the starz on the porch",
], forbid=["telescope", "scope", "binoculars"])

# ---------------------------------------------------------------- flat_h
g(FH, "s", 26, [26], {"kinds": ["mug"], "rel": "nearest", "ref": 25}, "ketle", [
    "Go to the mug beside the kettle.",
    "Could you take me to the cup standing right beside the kettle?",
    "Cup next to kettle",
    "I'm making tea, so the cup by the kettle, not the one on the coffee table.",
    "This is my morning routine. Take me to the mug right by the kettle.",
    "the cup next to the ketle, go there",
])
g(FH, "s", 46, [46], {"kinds": ["nightstand"], "room": "master bedroom", "rel": "holds", "ref": 48}, "lmap", [
    "Go to the bedside table with the lamp on it in the main bedroom.",
    "Could you take me to the nightstand in the master bedroom that the lamp stands on?",
    "Main bedroom, bedside table under lamp",
    "I want to turn the light on, so the bedside table with the lamp in the big bedroom, not the one holding the paperback.",
    "This is my side of the double bed. Take me to the bedside cabinet topped by the white ceramic lamp.",
    "go to the night table with the lmap on top in the main bedroom",
])
g(FH, "or", 16, [16, 17, 18], {"kinds": ["chair"], "room": "dining room"}, "dinig", [
    "Take me to the chairs in the dining room.",
    "Could you bring me to one of the seats in the dining room?",
    "Dining room seat",
    "We're about to eat, so any chair in the dining room, not the armchairs in the lounge.",
    "This is dinner time. Go to a seat in the dining room.",
    "take me to a seat in the dinig room",
])
g(FH, "ord", 10, [10], {"kinds": ["armchair"], "room": "living room", "attrs": ["leather"]}, "leathr", [
    "Take me to the brown leather armchair in the living room.",
    "Could you guide me to the cognac club chair with brass studs in the lounge?",
    "Leather club chair, living room",
    "I want to read by the bookshelf, so the tan leather armchair in the lounge, not the mustard velvet one.",
    "This is Dad's reading seat. Go to the studded leather chair in the sitting room.",
    "the brown leathr club chair in the living room",
])

# ---------------------------------------------------------------- apartment
g(APT, "o", 8, [8, 39, 55], {"kinds": ["plant"]}, "housplant", [
    "Take me to a plant.",
    "Could you bring me to any of the houseplants?",
    "Any potted greenery",
    "I want to water something, so any houseplant at all, big or small.",
    "This is watering day. Go to one of the plants.",
    "take me to any housplant",
])
g(APT, "or", 12, [12, 13], {"kinds": ["book"], "room": "living room"}, "raed", [
    "Take me to the books in the living room.",
    "Could you lead me to one of the volumes on the lounge shelves?",
    "Living room reading material",
    "I'm bored, so something to read in the living room, not the textbook in the office.",
    "This is a lazy afternoon. Go to a book in the sitting room.",
    "take me to something to raed in the lounge",
])
g(APT, "od", 2, [2], {"kinds": ["sofa"], "attrs": ["brown", "leather"]}, "brwon", [
    "Take me to the small brown leather loveseat.",
    "Could you guide me to the worn brown leather two-seater?",
    "Brown leather two-seat couch",
    "I want the leather one, not the big grey fabric sofa.",
    "This is where the dog naps. Go to the little brown couch that's a bit worn.",
    "the small brwon leather couch please",
])
g(APT, "ord", 42, [42], {"kinds": ["cabinet"], "room": "bathroom", "attrs": ["gray", "wood"]}, "bathrooom", [
    "Go to the grey wooden vanity cabinet in the bathroom.",
    "Could you take me to the grey wood unit under the washbasin in the bathroom?",
    "Bathroom grey vanity unit",
    "I need a fresh towel, so the grey wooden vanity in the bathroom, not the grey metal filing one in the office.",
    "This is where the toiletries are kept. Head to the grey wood cupboard in the bathroom.",
    "take me to the gray wooden vanity in the bathrooom",
])
g(APT, "ard", 30, [30], {"need_kinds": ["mirror"], "room": "hallway", "need_words": []}, "halway", [
    "Take me where I can check my outfit in the hallway before leaving.",
    "Could you bring me to where I can see how I look by the front door in the hall?",
    "Check appearance, hallway, gold frame",
    "I have a date tonight, so take me to the spot in the hall where I can check my hair, not the one in the bathroom.",
    "This is my final check before I head out. Go to the gold-framed reflective spot in the hallway.",
    "where can i check my hair in the halway",
], forbid=["mirror", "looking glass"])
g(APT, "s", 6, [6], {"kinds": ["picture"], "rel": "above", "ref": 1}, "paintng", [
    "Go to the picture above the sofa.",
    "Could you take me to the painting hanging over the couch?",
    "Painting over big couch",
    "I want to straighten the artwork above the sofa, not the little photo in the hallway.",
    "This is the frame that keeps tilting. Take me to the picture on the wall over the settee.",
    "the paintng above the couch, go there",
])
g(APT, "s", 39, [39], {"kinds": ["plant"], "rel": "on", "ref": 38}, "dressr", [
    "Go to the plant on top of the chest of drawers.",
    "Could you take me to the little potted plant sitting on the dresser?",
    "Pot on top of drawers",
    "I only want to water the small one up on the dresser, not the tall ones on the floor.",
    "This is the one that always gets forgotten. Take me to the greenery on top of the bedroom drawers.",
    "the little pot on top of the dressr",
])
g(APT, "s", 23, [23], {"kinds": ["chair", "armchair"], "rel": "nearest", "ref": 16}, "frige", [
    "Go to the chair closest to the fridge.",
    "Could you take me to the dining seat nearest the refrigerator?",
    "Dining chair nearest fridge",
    "I want to grab a cold drink and sit, so the dining seat nearest the fridge, not the white one on the far side.",
    "This is the handiest spot to sit. Take me to the seat at the dining table closest to the fridge.",
    "the seat nearest the frige",
])

# ---------------------------------------------------------------- scans
g(SB, "s", 5, [5], {"kinds": ["pillow"], "rel": "foot_of_bed", "ref": 1}, "fot", [
    "Go to the pillow near the foot of the bed.",
    "Could you take me to the cushion lying down by the foot end of the bed?",
    "Cushion at bed's foot",
    "I want the cushion that slid down to the foot of the bed, not the ones up at the head end.",
    "This is the one that fell down the bed. Take me to the pillow at the foot end.",
    "the cushion down at the fot of the bed",
])
g(SB, "o", 8, [8, 9], {"kinds": ["lamp"]}, "ligt", [
    "Take me to one of the lamps.",
    "Could you guide me to a light I can turn on?",
    "Any reading light",
    "I want to read in bed, so any light, either side is fine.",
    "This is far too dark to read. Bring me to a lamp.",
    "take me to any ligt in here",
])
g(SB, "ord", 4, [4], {"kinds": ["pillow"], "room": "bedroom", "attrs": ["red"]}, "cushon", [
    "Take me to the red pillow in the bedroom.",
    "Could you bring me to the bright red cushion in the bedroom?",
    "Red bedroom cushion",
    "I want the red one, not the white or blue cushions in the bedroom.",
    "This is the accent cushion I bought. Go to the red one in the bedroom.",
    "the red cushon in the bedroom",
])
g(SK, "s", 3, [3], {"kinds": ["kitchen cabinet"], "rel": "under", "ref": 10}, "cupbaord", [
    "Go to the cupboard under the sink.",
    "Could you take me to the cabinet right below the sink?",
    "Cupboard beneath sink",
    "I need the bin bags kept under the sink, so that base cupboard, not the wall units above.",
    "This is where the cleaning stuff lives. Take me to the kitchen cabinet directly under the sink.",
    "the cupbaord under the sink",
])
g(SK, "or", 17, [17, 18, 19, 20, 21, 22], {"kinds": ["chair"], "room": "kitchen"}, "seet", [
    "Take me to a chair in the kitchen.",
    "Could you lead me to one of the kitchen seats?",
    "Kitchen seat, any",
    "My feet hurt, so any seat in the kitchen will do, I just need to sit.",
    "This is a quick rest. Go to a chair in the kitchen.",
    "take me to a seet in the kitchen",
])
g(SK, "od", 24, [24], {"kinds": ["cup"], "attrs": ["red"]}, "mugg", [
    "Take me to the red cup.",
    "Could you bring me to the red mug?",
    "Red mug",
    "That one is mine, so the red mug, not the blue or white ones.",
    "This is my favourite coffee mug. Go to the cup that is red.",
    "the red mugg please",
])
g(SL, "s", 11, [11], {"kinds": ["lamp"], "rel": "right_beside", "ref": 1, "facing": 14}, "rigth", [
    "Go to the lamp beside the sofa on the right-hand side, as you sit facing the TV.",
    "Could you take me to the little light on the side table at the right end of the couch, from the viewpoint of someone sitting on it?",
    "Sofa's right-hand side light",
    "I want to read on the sofa, so the light right next to it on my right as I face the TV, not the one on my left.",
    "This is from the viewpoint of someone sitting on the sofa watching TV. Take me to the table lamp right beside it on the right.",
    "the light right next to the sofa on the rigth, facing the tv",
])
g(SL, "o", 15, [15, 16], {"kinds": ["picture"]}, "artwrk", [
    "Take me to a painting.",
    "Could you bring me to any of the framed pictures on the walls?",
    "Any wall art",
    "I want to dust some artwork, so any framed piece on the wall, not the TV.",
    "This is about the artwork. Go to one of the pictures on the wall.",
    "take me to a framed artwrk",
])
g(SL, "ard", 27, [27], {"need_kinds": ["ottoman"], "need_words": [], "gray_low": True}, "paded", [
    "Take me somewhere low and grey to rest my feet on in the living room.",
    "Could you bring me to the little grey spot where I can prop up my legs?",
    "Feet up, small grey",
    "My legs are tired, so take me to the low grey thing I can rest my feet on, the small square one in the middle of the room.",
    "This is my lazy evening. Go to the small grey padded thing I rest my feet on.",
    "take me to the small grey paded thing for resting my feet",
], forbid=["ottoman", "footstool", "pouf", "stool", "footrest"])
g(SO, "s", 16, [16], {"kinds": ["bookshelf"], "rel": "shortest"}, "bookcse", [
    "Go to the shortest bookcase.",
    "Could you take me to the bookcase that isn't as tall as the other two?",
    "Shortest shelving unit",
    "I can't reach high shelves, so the short bookcase, not the two tall ones.",
    "This is the squat one at the end. Take me to the bookshelf that's smaller than the others.",
    "the shortest bookcse, go there",
])
g(SO, "or", 3, [3, 4, 5, 6, 7, 8, 9, 10], {"kinds": ["office chair"], "room": "office"}, "chiar", [
    "Take me to a desk chair in the office.",
    "Could you lead me to any of the wheeled work chairs in the office?",
    "Office swivel seat, any",
    "I need to sit down for a call, so any desk chair in the office, doesn't matter which.",
    "This is my first day here. Go to a swivel chair in the office.",
    "take me to a desk chiar in the office",
])
g(SO, "ord", 2, [2], {"kinds": ["table"], "room": "office", "attrs": ["wood"]}, "ofice", [
    "Take me to the wooden table in the office.",
    "Could you guide me to the brown wood work table in the office?",
    "Office's brown wooden worktable",
    "I want to spread my papers out on wood, so the brown wooden work surface in the office, not the white one.",
    "This is where the meeting is. Go to the wooden worktable in the office.",
    "the brown wooden worktable in the ofice",
])


def main():
    assert len(G) == 48, len(G)
    lines, specs = [], {}
    for i, grp in enumerate(G, 1):
        gid = f"b57-g{i:02d}"
        specs[gid] = {k: grp[k] for k in ("map", "type", "target", "accept", "spec", "typo", "forbid")}
        for j, q in enumerate(grp["w"], 1):
            lines.append(json.dumps({"id": f"{gid}-w{j}", "map": grp["map"], "query": q, "type": grp["type"],
                                     "target": grp["target"], "accept": grp["accept"], "group": gid}))
    (ROOT / "evals/blind/round57.jsonl").write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(len(lines), "lines,", len(specs), "groups")


if __name__ == "__main__":
    main()
