"""Write evals/blind/round51.jsonl from hand-written groups (blind round 51).

Every wording below was written by hand from the maps printed by scripts/show.py.
Order of wordings: w1 imperative, w2 "Could you ...?", w3 telegraphic, w4 reason/contrast,
w5 "This is ..." + second sentence, w6 casual lower case with one typo.
"""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

# (map, type, target, accept, [w1..w6])
GROUPS = [
    # ---------------- scene_00829 (caption map) ----------------
    (C829, "o", 42, [42, 197, 212, 259], [
        "Take me to one of the books lying around here.",
        "Could you bring me over to any bound volume in the place?",
        "Any volume to read",
        "I want something to leaf through, so any book will do, not a loose sheet of paper.",
        "This is just about finding reading material. Show me where any bound volume is kept.",
        "take me to some kind of volum i can flip through",
    ]),
    (C829, "o", 160, [125, 160, 162, 164], [
        "Go to where the towels are.",
        "Could you show me where I can grab something to dry off with, like a towel?",
        "Towels, any of them",
        "I just washed my face, so find me a towel; a small hand one or a folded stack both work.",
        "This is a bit urgent, I'm dripping wet. Lead me to a fluffy towel of any sort.",
        "where are the towls kept",
    ]),
    (C829, "or", 261, [261, 263], [
        "Take me to an armchair in the bedroom.",
        "Could you walk me to one of the lounge chairs in the bedroom?",
        "Bedroom armchair",
        "I'd like to sit somewhere comfy while I'm in the bedroom, so an armchair there, not one of the living room ones.",
        "This is for a quiet read before sleep. Point me to one of the deep brown lounge chairs in the bedroom.",
        "take me to a comfy armchiar in the bedroom",
    ]),
    (C829, "od", 56, [56], [
        "Go to the doorway that has a peephole.",
        "Could you take me to the dark wooden door with the gold knob and the spy hole?",
        "Door with peephole",
        "I want to check who's knocking, so head to the door with the little viewer, not the one with the smart lock.",
        "This is the dark wood door with a golden knob I mean. Go to the one you can peek through.",
        "take me to the wooden door with the little peephol in it",
    ]),
    (C829, "ord", 191, [191], [
        "Take me to the beige velvet armchair in the bathroom.",
        "Could you lead me to the soft cream-coloured lounge chair that's in the bathroom?",
        "Beige velvet chair, bathroom",
        "I need to sit down while I'm in the bathroom, so the velvety beige one there, not the ones in the living room.",
        "This is odd, but there's an easy chair in one of the bathrooms. Take me to that beige velvet one.",
        "go to the beige velvet armchair in the bathrom",
    ]),
    (C829, "ard", 192, [192], [
        "Take me to the soft white-and-brown spot where the dog sleeps.",
        "Could you show me where our dog's cushy sleeping place is, the one in the bathroom?",
        "Pet's sleeping spot, bathroom",
        "The puppy is worn out, so head to his plush napping spot in the bathroom, not my own bed.",
        "This is for the dog. Where's the soft brown-and-white place he naps in?",
        "where's the dog's sleepign spot in the bathroom",
    ]),
    (C829, "ard", 264, [264], [
        "Take me to where the wine is kept behind glass in the bedroom.",
        "Could you find the spot in the bedroom where I can store bottles of wine behind a glass front?",
        "Bedroom wine storage, glass door",
        "I want to put away a bottle of red, so go to the glass-fronted wine spot in the bedroom, not the one without glass.",
        "This is a wine question. Where in the bedroom can I stash bottles behind a glass door?",
        "where do i keep the wine in the bedroom, the bit with the glas door",
    ]),
    # ---------------- scene_office3 (caption map) ----------------
    (OFF3, "o", 14, [10, 14, 16, 24], [
        "Take me to a window.",
        "Could you get me over to any of the windows?",
        "Any pane looking outside",
        "It's stuffy in here, so take me to a glazed opening I can look out of, not the glass door.",
        "This is about getting some daylight. Lead me to one of the panes looking outside.",
        "take me over to one of the windos",
    ]),
    (OFF3, "or", 8, [8, 13, 20, 40], [
        "Go to a cushion in the rec room.",
        "Could you bring me to one of the throw pillows in the rec room?",
        "Rec room cushion",
        "My back aches, so find me a scatter cushion in the rec room; any colour is fine.",
        "This is just for comfort. Where's a cushion in the recreation room?",
        "show me a cusion in the rec room",
    ]),
    (OFF3, "od", 13, [13], [
        "Take me to the navy velvet cushion.",
        "Could you go to the dark blue velvety pillow with the button?",
        "Navy velvet cushion",
        "I want the soft dark blue one, not the orange or yellow cushions.",
        "This is the plush navy cushion I mean. Please head over to it.",
        "go to the navy blue velvet cushon",
    ]),
    (OFF3, "ord", 7, [7], [
        "Go to the white wooden desk in the rec room.",
        "Could you take me to the white writing table in the rec room?",
        "White desk, rec room",
        "I need a bright surface to work at in the rec room, the white one, not the brown wooden ones.",
        "This is where I left my notes, the white wooden workstation. Take me there in the rec room.",
        "head to the whtie workstation in the rec room",
    ]),
    (OFF3, "ard", 25, [25], [
        "Take me to whatever on the wall shows the time in the rec room.",
        "Could you take me to where I can read the time on the rec room wall?",
        "Check time, rec room wall",
        "I'm running late, so go to the thing on the rec room wall that tells the hour, not the phone.",
        "This is a timing thing. Where on the rec room wall can I watch the seconds ticking?",
        "i need to see the tiem, take me to what shows it on the wall",
    ]),
    # ---------------- flat_c ----------------
    (FC, "o", 5, [5, 7, 28, 36], [
        "Take me to a lamp.",
        "Could you walk me over to any light I can switch on?",
        "Any reading light",
        "It's getting dark, so find me something to turn on for light, any lamp at all.",
        "This is a simple one. I just want any table or floor light in the flat.",
        "go to one of the lmaps",
    ]),
    (FC, "or", 19, [19, 20, 21], [
        "Go to a chair in the kitchen.",
        "Could you find me a seat at the kitchen table?",
        "Kitchen seat",
        "I want to eat my breakfast sitting down, so a chair in the kitchen, not the swivel one in the study.",
        "This is for lunch. Bring me to somewhere to sit in the kitchen, any of the dining seats.",
        "take me to a kitchen chiar",
    ]),
    (FC, "od", 2, [2], [
        "Take me to the mustard-coloured armchair.",
        "Could you go to the yellow fabric easy chair?",
        "Yellow easy chair",
        "I want to curl up in the yellow one, not the grey armchair.",
        "This is my favourite seat, the mustard one. Please take me to it.",
        "head to the mustrad yellow easy chair",
    ]),
    (FC, "s", 20, [20], [
        "Go to the chair closest to the fridge.",
        "Could you take me to whichever chair is nearest the refrigerator?",
        "Seat nearest fridge",
        "I want to grab a cold drink and sit straight away, so the seat nearest the fridge, not the one on the far west side of the table.",
        "This is the dining seat I mean: the one closest to the fridge-freezer. Take me there.",
        "take me to the seat closest to the frdige",
    ]),
    # ---------------- flat_d ----------------
    (FD, "or", 8, [8, 9], [
        "Take me to a lamp in the studio.",
        "Could you lead me to one of the lights in the studio room?",
        "Studio light, any",
        "I'm reading on the sofa bed and it's dim, so any lamp in the studio, not the night-light in the kids' room.",
        "This is the main room I mean, the studio. Find me a light there I can switch on.",
        "take me to a light in the studoi",
    ]),
    (FD, "ord", 34, [34], [
        "Go to the moon-shaped night light in the kids' room.",
        "Could you take me to the little pink lamp on the children's desk?",
        "Pink moon light, kids room",
        "My daughter's scared of the dark, so head to the pink moon light in her room, not the silver reading light on the studio desk.",
        "This is the little glowing moon in the children's bedroom. Please go over to it.",
        "go to the pink moon lamp in the childern's room",
    ]),
    (FD, "ard", 27, [27], [
        "Take me to where I can iron my shirt in the laundry room.",
        "Could you show me where to press my trousers in the laundry?",
        "Laundry room, iron shirts",
        "I've got a creased shirt for tomorrow, so go to where I can smooth it out in the laundry room, not the dryer.",
        "This is about wrinkles. Where do I press clothes in the laundry room?",
        "where can i iorn my shirt in the laundry room",
    ]),
    (FD, "s", 21, [21], [
        "Go to the stool nearest the bin.",
        "Could you take me to the bar stool closest to the rubbish bin?",
        "Seat nearest pedal bin",
        "I'm tossing out scraps and want to sit right after, so the perch nearest the bin, not the one nearer the fridge.",
        "This is the kitchenette seat on the west side, by the trash. Take me to it.",
        "take me to the perch closest to the tarsh can",
    ]),
    # ---------------- flat_f ----------------
    (FF, "o", 2, [2, 3], [
        "Take me to an armchair.",
        "Could you lead me to one of the easy chairs?",
        "Either armchair, please",
        "I fancy a sit-down in something padded, so one of the easy chairs, not a hard dining chair.",
        "This is just about resting my legs. Find me an upholstered seat with arms, either one.",
        "go to one of the eazy chairs",
    ]),
    (FF, "ord", 32, [32], [
        "Go to the blue and white striped rug in the bedroom.",
        "Could you take me to the striped rag mat in the bedroom?",
        "Striped bedroom mat",
        "I want to stand somewhere soft while dressing, so the blue-striped mat in the bedroom, not the red patterned one in the lounge.",
        "This is the cotton one with stripes. Bring me to that mat in the bedroom.",
        "take me to the stripy blue rug in the bedroon",
    ]),
    (FF, "ard", 25, [25], [
        "Take me to what I can use to look at the stars on the porch.",
        "Could you bring me to the thing on the porch for watching the night sky?",
        "Stargazing kit, porch",
        "There's a meteor shower tonight, so go to the tripod thing on the porch for viewing planets, not the rocking chair.",
        "This is for the night sky. Where's the black thing on the porch that magnifies the stars?",
        "take me to the porch thing for looking at plannets",
    ]),
    (FF, "s", 13, [13], [
        "Go to the kitchen chair nearest the tall dresser.",
        "Could you take me to the dining chair closest to the plate dresser?",
        "Dining seat nearest dresser",
        "I want to reach the mugs on the dresser without getting up, so the seat at the table nearest it, not the one by the stove.",
        "This is the dining seat on the dresser side, toward the south-east. Please take me there.",
        "go to the dinning seat closest to the dresser",
    ]),
    # ---------------- flat_h ----------------
    (FH, "od", 37, [37], [
        "Take me to the mirror with the LED light around its edge.",
        "Could you go to the rectangular looking glass that lights up?",
        "Backlit rectangular mirror",
        "I need good light to shave, so the illuminated one, not the oval brass-framed one.",
        "This is the one that glows around the edges. Head over to that looking glass.",
        "take me to the glowing rectangualr glass",
    ]),
    (FH, "ord", 11, [11], [
        "Go to the yellow velvet armchair in the living room.",
        "Could you lead me to the mustard easy chair in the lounge?",
        "Mustard velvet chair, living room",
        "I want the soft yellow one in the living room, not the brown leather club chair.",
        "This is the velvet seat in the corner of the living room. Take me to the mustard one.",
        "take me to the mustard velvt armchair in the living room",
    ]),
    (FH, "ard", 4, [4], [
        "Take me to where I can drop my keys in the hallway.",
        "Could you show me where house keys get left near the front door?",
        "Keys spot, hallway",
        "I'm heading out and need my keys, so go to the little green spot in the hall where they're left, not the kitchen worktop.",
        "This is the hallway I mean. Where do I toss my keys when I come in?",
        "where do i put my kyes in the hallway",
    ]),
    (FH, "s", 47, [47], [
        "Go to the bedside table with the paperback on it.",
        "Could you take me to the nightstand that has a book lying on top?",
        "Nightstand with novel on top",
        "I want to finish my novel, so go to the bedside table it's lying on, not the one with the lamp.",
        "This is the bedside table on the east side of the double bed, with the orange book. Take me there.",
        "go to the bedside table with the orange paprback on it",
    ]),
    # ---------------- apartment ----------------
    (APT, "o", 1, [1, 2], [
        "Take me to a couch.",
        "Could you bring me to either of the sofas?",
        "Any settee",
        "I'm exhausted and want to lie down in the living room, so any couch, not an armchair.",
        "This is nap time. Find me a sofa, big or small.",
        "take me to a coutch",
    ]),
    (APT, "or", 12, [12, 13], [
        "Go to a book in the living room.",
        "Could you take me to one of the volumes in the living room?",
        "Living room book, any",
        "I fancy a read on the sofa, so any volume from the living room, not the textbook in the office.",
        "This is for a lazy afternoon. Point me to a hardcover or photo album in the living room.",
        "go to a volume in the livng room",
    ]),
    (APT, "or", 23, [23, 24], [
        "Take me to a chair in the kitchen.",
        "Could you show me a dining seat in the kitchen?",
        "Kitchen dining seat",
        "I'm eating at the table, so any kitchen chair, not the red office chair.",
        "This is for dinner. Where can I sit at the kitchen table?",
        "go to a seat by the kitchn table",
    ]),
    (APT, "od", 2, [2], [
        "Go to the small brown leather loveseat.",
        "Could you take me to the worn two-seater couch in leather?",
        "Brown leather two-seater",
        "I like the cosy little one, not the big gray three-seater sofa.",
        "This is the slightly worn brown settee. Take me to it.",
        "go to the brown lether loveseat",
    ]),
    (APT, "ord", 52, [52], [
        "Take me to the green textbook in the office.",
        "Could you bring me to the thick green book on the office shelf?",
        "Green coding book, office",
        "I have to debug something, so the green programming volume in the office, not the novels in the living room.",
        "This is my coding reference, thick and green. Go to it in the office.",
        "go to the thick green textbok in the office",
    ]),
    (APT, "ard", 54, [54], [
        "Take me to where I can print a document in the office.",
        "Could you show me where to get a hard copy of my report in the office?",
        "Print something, office",
        "I need a paper copy of my boarding pass, so go to what prints in the office, not the laptop.",
        "This is about a paper copy. Where in the office do I print it?",
        "where can i prnit my tickets in the office",
    ]),
    (APT, "s", 12, [12], [
        "Go to the book higher up on the bookcase in the living room.",
        "Could you take me to the higher of the two volumes on the living room shelves?",
        "Top-shelf volume, living room",
        "I can reach up easily, so the one standing higher on the lounge bookcase, not the one lying on the bottom shelf.",
        "This is on the living room bookcase, up high. Take me to the book there.",
        "go to the volume higher up on the lving room shelves",
    ]),
    (APT, "s", 39, [39], [
        "Go to the plant sitting on top of the chest of drawers.",
        "Could you take me to the greenery that's on the dresser?",
        "Plant atop bedroom dresser",
        "I want to water the one up off the floor, so the pot on the drawers, not the big ones standing on the floor.",
        "This is the little pot perched on the chest of drawers. Take me there.",
        "go to the pot on top of the drawres",
    ]),
    # ---------------- scan_bedroom ----------------
    (SB, "od", 4, [4], [
        "Take me to the red pillow.",
        "Could you go to the red cushion on the bed?",
        "Red cushion",
        "I want the red one, not the white or blue pillows.",
        "This is the bright red cushion. Please head to it.",
        "go over to the red cushoin",
    ]),
    (SB, "s", 7, [7], [
        "Go to the nightstand with the book on it.",
        "Could you take me to the bedside table where the blue book is lying?",
        "Bedside table holding book",
        "I want my book, so the bedside table it's on, not the one with the clock.",
        "This is the bedside table on the door side of the bed. Go there.",
        "go to the bedside tabel with the book",
    ]),
    (SB, "s", 9, [9], [
        "Go to the lamp closest to the door.",
        "Could you take me to the bedside light nearer the door?",
        "Light nearest door",
        "I'm coming in from the hall and want light right away, so the one by the door, not the one near the window.",
        "This is the bedside light on the side near the door. Please go there.",
        "go to the lamp by the dorr",
    ]),
    # ---------------- scan_kitchen ----------------
    (SK, "o", 17, [17, 18, 19, 20, 21, 22], [
        "Take me to a chair.",
        "Could you find me somewhere to sit, any seat at the table?",
        "Any seat",
        "My feet hurt, so any chair will do, red, white or black.",
        "This is a quick one. Bring me to a seat, whichever is free.",
        "take me to a seet",
    ]),
    (SK, "s", 3, [3], [
        "Go to the cabinet under the sink.",
        "Could you take me to the cupboard right below the sink?",
        "Cupboard under sink",
        "I need the dish soap, so the cupboard beneath the sink, not the one under the microwave.",
        "This is the base unit directly below the basin. Take me there.",
        "go to the cuboard under the sink",
    ]),
    (SK, "ard", 12, [12], [
        "Take me to where I can brew coffee in the kitchen.",
        "Could you show me where to make a fresh pot of coffee in the kitchen?",
        "Morning brew, kitchen",
        "I'm half asleep and need caffeine, so go to where coffee gets brewed in the kitchen, not the microwave.",
        "This is about caffeine. Where in the kitchen do I make my morning coffee?",
        "where do i make cofee in the kitchen",
    ]),
    # ---------------- scan_livingroom ----------------
    (SL, "or", 10, [10, 11, 12], [
        "Go to a lamp in the living room.",
        "Could you take me to any light in the living room?",
        "Living room light",
        "It's too dark to read, so any lamp in the living room works, floor or table.",
        "This is about light. Find me a reading light in the lounge.",
        "take me to any lihgt in the living room",
    ]),
    (SL, "s", 4, [4], [
        "Go to the red pillow nearest the leather armchair.",
        "Could you take me to the red cushion at the end of the sofa closest to the brown armchair?",
        "Red cushion by leather armchair",
        "I want the red cushion on the east end of the couch, not the red one on the west end.",
        "This is the red cushion nearer the leather chair. Please go to it.",
        "go to the red pilow closest to the brown armchair",
    ]),
    (SL, "od", 5, [5], [
        "Take me to the green armchair.",
        "Could you lead me to the green easy chair?",
        "Green lounge chair",
        "I want the green one, not the brown leather armchair.",
        "This is the green one I mean. Take me to that chair with arms.",
        "go to the gren easy chair",
    ]),
    # ---------------- scan_office ----------------
    (SO, "ord", 2, [2], [
        "Go to the wooden table in the office.",
        "Could you take me to the brown timber table in the office?",
        "Brown wooden worktable, office",
        "I'd rather work at the wood one in the office, not the white one.",
        "This is the brown wood work surface in the office. Take me there.",
        "take me to the woodden desk in the office",
    ]),
    (SO, "s", 16, [16], [
        "Go to the shortest bookshelf.",
        "Could you take me to the lowest of the bookcases?",
        "Shortest bookcase",
        "I can't reach high shelves, so the short one, not the tall wooden ones.",
        "This is the shortest shelving unit in the office. Take me there.",
        "go to the shortst bookshelf",
    ]),
    (SO, "s", 8, [8], [
        "Go to the office chair nearest the red backpack.",
        "Could you take me to the chair closest to the red rucksack?",
        "Chair beside red backpack",
        "Someone left their bag there, so the seat nearest the red backpack, not the blue one beside it.",
        "This is the chair with the red backpack on the floor beside it. Go there.",
        "take me to the seat closest to the red backpak",
    ]),
]


def main():
    out = Path(__file__).resolve().parents[2] / "evals/blind/round51.jsonl"
    lines = []
    for g, (mp, typ, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, g
        group = f"b51-g{g:02d}"
        for w, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"{group}-w{w}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": sorted(accept), "group": group},
                                    ensure_ascii=False))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines, {len(GROUPS)} groups to {out}")


if __name__ == "__main__":
    main()
