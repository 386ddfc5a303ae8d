"""Hand-written blind suite round 30: 48 groups x 6 wordings. Writes evals/blind/round30.jsonl.
    python3 scripts/emit.py"""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SB, SK, SL, SO = "../maps/scan_bedroom.json", "../maps/scan_kitchen.json", "../maps/scan_livingroom.json", "../maps/scan_office.json"

# (type, map, target, accept, [w1..w6])
GROUPS = [
    # ---------------- caption map scene_00829 (7) ----------------
    ("o", C829, 4, [191, 261, 263, 4, 9, 32, 79], [
        "Go to an easy chair.",
        "Could you take me to one of the lounge chairs?",
        "comfy lounge armchair",
        "I want to sink into something soft and padded to relax, so find me a lounging armchair, not a folding one.",
        "This is a cushioned seat made for relaxing. It is an easy chair with a back and arms.",
        "yo find me a cozy recliner-type seat to chill in, any of the lounge chiars is fine"]),
    ("or", C829, 182, [182, 250], [
        "Go to the side table in the bedroom.",
        "Could you take me to one of the little end tables in the bedroom?",
        "bedroom end table",
        "I want to set my glass down near where I sleep, so find a small end table in the bedroom, not the ones in the living room.",
        "This is a side table. It stands in the bedroom.",
        "take me to the bedrom end table pls"]),
    ("or", C829, 160, [160, 162, 164], [
        "Go to the set of towels in the living room.",
        "Could you bring me to the folded towel stacks in the living room?",
        "towel stack living room",
        "I just showered and need a dry towel; go to the stacked ones in the living room, not the single hand towel.",
        "This is a pile of folded bath linens. It is kept in the living room.",
        "wheres the stack of towles in the living room"]),
    ("od", C829, 110, [110], [
        "Go to the small honey-coloured table with the X-shaped metal base.",
        "Could you find the little warm-toned wooden stand that sits on crossed metal legs?",
        "honey wood stand, X base",
        "I need to charge my phone by USB, so find the small honey-wood table with crossed legs, not the dark wood ones.",
        "This is a small light-brown wooden table. It has a metal base shaped like an X.",
        "the lil honey colored table with the x shaped metl legs, where is it"]),
    ("ord", C829, 272, [272], [
        "Go to the pale blue bed curtain in the bedroom.",
        "Could you take me to the light blue flowery drape that hangs around the bed in the bedroom?",
        "bedroom bed drape, floral blue",
        "I want to close the drape around my bed for privacy; the flowery pale blue one in the bedroom, not the window curtain.",
        "This is a light blue fabric drape with flowers printed on it. It hangs by the bed in the bedroom.",
        "go to the flowery blue bed canopy curtian in the bedroom"]),
    ("ord", C829, 120, [120], [
        "Go to the weathered wooden bench in the bathroom.",
        "Could you show me the rustic outdoor-style bench that's in the bathroom?",
        "old wood bench, bathroom",
        "I need to sit down and put my shoes on after bathing; take me to the patio-style wooden bench in the bathroom, not the velvet chair.",
        "This is a bench made of worn, aged timber, like one you would put in a yard. It is in the bathroom and has storage built in.",
        "where's the old garden bnech in the bathroom"]),
    ("ard", C829, 192, [192], [
        "Go to where my dog can sleep.",
        "Could you take me to the spot where the cat curls up for a nap?",
        "place for pet to sleep",
        "My puppy is tired and needs a soft spot of its own to rest, not the couch.",
        "This is a soft little spot where an animal lies down. It is a place of its own for a pet to rest, easy to clean.",
        "take me to where the puppy sleeeps, his own comfy spot"]),
    # ---------------- caption map scene_office3 (5) ----------------
    ("o", OFF3, 8, [8, 13, 20, 40], [
        "Go to a pillow.",
        "Could you show me where the cushions are?",
        "throw cushion",
        "My back hurts on this hard seat, so bring me to any cushion; colour doesn't matter.",
        "This is a soft cushion. It is a small stuffed pillow meant to lean against.",
        "where's a cushon i can grab"]),
    ("or", OFF3, 7, [7, 55, 64], [
        "Go to a desk in the rec room.",
        "Could you take me to one of the workstations in the recreation room?",
        "rec room workstation",
        "I have to fill in a form and need a proper work surface in the rec room, not the sofa or the bench.",
        "This is a desk for working at. It is located in the rec room.",
        "need a workspace with a flat top to write on in the rec room, any of the deks"]),
    ("od", OFF3, 9, [9], [
        "Go to the monitor showing a world map.",
        "Could you find the computer screen that has a map of the globe on it?",
        "screen with world map",
        "I want to check where the time zones are, so go to the display with the blue world map, not the laptop.",
        "This is a computer display with a blue picture of the continents on it. It also has a small camera built in.",
        "the screeen with the map of the world on it, go there"]),
    ("od", OFF3, 13, [13], [
        "Go to the navy blue velvet pillow.",
        "Could you bring me to the dark blue velvety cushion with a button?",
        "navy velvet cushion",
        "I want the soft dark blue cushion, not the orange or yellow ones.",
        "This is a plush dark blue cushion. It has a button in the middle of it and a velvet feel.",
        "wheres the navy velvt cushion"]),
    ("ard", OFF3, 25, [25], [
        "Go to where I can check the time.",
        "Could you show me where I can see what time it is?",
        "need current time, wall",
        "My phone is dead and I need to know how late it is, so take me to whatever on the wall shows the hour.",
        "This is something that shows the current hour. It is hung on the wall so I can read it at a glance.",
        "what time is it?? take me to something on the wall that shows the tme"]),
    # ---------------- flats (18) ----------------
    ("o", FB, 5, [33, 34, 5, 7, 26], [
        "Go to a lamp.",
        "Could you take me to any of the lights in the flat?",
        "light, any",
        "It's getting dark in here and I want to switch on some light; any lamp will do, whichever room.",
        "This is a light fitting that stands on a table or the floor. It has a shade over the bulb.",
        "just take me to one of the lmaps, doesn't matter which"]),
    ("o", FE, 7, [29, 7], [
        "Go to a mirror.",
        "Could you take me to one of the looking glasses?",
        "looking glass",
        "I want to check my hair before I leave; any mirror will do, the bathroom one or the one in the lounge.",
        "This is a reflective glass panel on a wall. You can see yourself in it.",
        "take me to a looking glas, whichever is closest"]),
    ("o", FI, 31, [31, 36, 23], [
        "Go to a mug.",
        "Could you find me one of the coffee cups?",
        "coffee cup",
        "I want to pour myself some tea, so take me to any mug, I'm not fussy which.",
        "This is a ceramic drinking cup with a handle. It is the kind you drink tea or coffee from.",
        "where's a cofee cup, any of em"]),
    ("or", FG, 34, [34, 35], [
        "Go to a lamp in the bedroom.",
        "Could you take me to one of the bedside lights in the bedroom?",
        "bedroom reading light",
        "I want to read in bed, so go to a bedside light in the bedroom, not the yellow desk one in the kids room.",
        "This is a small light with a shade. It sits by the bed in the bedroom.",
        "go to one of the bedrom lamps, either side is fine"]),
    ("or", FI, 6, [6, 7, 8, 9], [
        "Go to a chair in the meeting room.",
        "Could you take me to one of the seats around the table in the meeting room?",
        "meeting room seat",
        "I have a client call and need to sit at the conference table; any seat in the meeting room, not the ones at the studio desks.",
        "This is a seat for one person at the conference table. It is in the meeting room.",
        "grab me a chiar in the meeting room pls"]),
    ("od", FG, 11, [11], [
        "Go to the ironing board with the blue flowery cover.",
        "Could you show me the board for pressing clothes, the one with a blue floral pattern?",
        "blue floral pressing board",
        "My shirt is creased and I need to press it, so take me to the board with the blue flower cover, not the laundry basket.",
        "This is a long narrow board for pressing shirts, with a blue cover printed with flowers. A steam iron sits on one end of it.",
        "where's the flowry blue ironing board"]),
    ("od", FI, 46, [46], [
        "Go to the lamp with the woven rattan shade.",
        "Could you find the bedside light whose shade is made of woven cane?",
        "rattan shade light",
        "I like the patterned glow it casts; take me to the wicker-shaded bedside light, not the white ceramic one.",
        "This is a small light on a bedside table. Its shade is woven from rattan and scatters a pattern on the wall.",
        "take me to the rattan lmap by the bed"]),
    ("ord", FE, 14, [14], [
        "Go to the black metal chair in the dining room.",
        "Could you take me to the odd one out at the dining table, the black bistro-style seat?",
        "black metal seat dining room",
        "Bring me to the mismatched black metal seat in the dining room, not the green painted ones.",
        "This is a black metal seat that doesn't match the rest. It sits at the table's northern edge in the dining room.",
        "go to the blak bistro chair in the dining room"]),
    ("ord", FG, 19, [19], [
        "Go to the wooden chair with the red checked cushion in the kitchen.",
        "Could you take me to the kitchen seat that has a red gingham pad on it?",
        "kitchen wood seat, red check cushion",
        "I want the comfy one with the cushion in the kitchen, not the white plastic chair.",
        "This is a wooden seat at the kitchen table. It has a red checkered cushion on it.",
        "the kitchen seat with the red checked cusion, go there"]),
    ("ord", FB, 3, [3], [
        "Go to the brown leather armchair in the living room.",
        "Could you take me to the tan leather easy chair in the living room?",
        "living room leather armchair",
        "Take me to the leather one in the living room, not the yellow velvet one by the window.",
        "This is a brown leather seat with arms and wooden legs. It stands toward the eastern wall of the living room.",
        "go to the brwon leather chair in the lounge"]),
    ("ard", FE, 33, [33], [
        "Go to the thing that dries wet laundry.",
        "Could you take me to where I can dry a load of wet clothes?",
        "dry wet laundry",
        "My clothes just finished washing and are soaking; I need to get them dry, not wash them again.",
        "This is a machine that gets damp washing dry. It is what I need once the wash cycle has finished.",
        "where can i dry my cloths quick"]),
    ("ard", FG, 5, [5], [
        "Go to where the tools are kept.",
        "Could you take me to where I can find a screwdriver and a spanner?",
        "need spanner, screwdriver",
        "The cupboard hinge is loose and I need a screwdriver to fix it; not the workbench itself, the thing the tools are kept in.",
        "This is what holds the hammer, pliers and screwdrivers. It is where I go when something needs repairing.",
        "need a hamer to fix a shelf, where are the tools"]),
    ("ard", FB, 18, [18], [
        "Go to where I can boil water for tea.",
        "Could you take me to something that heats water quickly for a cuppa?",
        "boil water, tea",
        "I want a cup of tea, so I need to boil some water, not heat up the oven.",
        "This is something that brings water to the boil. It is what I'd use to make instant coffee.",
        "fancy a brew, where can i boill some water"]),
    ("ard", FI, 20, [20], [
        "Go to where I can print out the site plans.",
        "Could you take me to something that puts my drawings onto A3 paper?",
        "print plans A3",
        "The client wants hard copies of the floor plans, so I need to print them, and scan the signed page too.",
        "This is a machine that puts my drawings onto paper. It is also able to copy a signed sheet into a file.",
        "need to prnt some drawings, where do i go"]),
    ("s", FB, 34, [34], [
        "Go to the bedroom lamp closest to the wardrobe.",
        "Could you take me to whichever bedside light is nearer the wardrobe?",
        "bedside light by wardrobe",
        "I'm getting dressed at the wardrobe and want the bedside light nearest it, not the one by the window.",
        "This is a light on a nightstand in the bedroom. Of the two, it is the one closer to the tall wardrobe.",
        "go to the bedside lamp nearer the wardorbe"]),
    ("s", FE, 16, [16], [
        "Go to the lamp that hangs highest.",
        "Could you take me to the light that's mounted highest up in the house?",
        "highest light",
        "I want to change the bulb that's up high, so the light hanging highest, not the floor or bedside ones.",
        "This is a light fixture. It is positioned higher than every other light in the flat.",
        "which lamp is the hihgest up? take me to it"]),
    ("s", FG, 2, [2], [
        "Go to the bicycle nearest the workbench.",
        "Could you take me to the bike that's closer to the workbench?",
        "bike near workbench",
        "I want to fix a puncture, so bring me to the bike nearer the workbench, not the one further off in the corner.",
        "This is a bike at the rear of the garage. It is the one closer to the workbench.",
        "the bikke closest to the workbench pls"]),
    ("s", FI, 17, [17], [
        "Go to the monitor closest to the tall shelving unit.",
        "Could you take me to the computer screen nearer the bookshelf in the studio?",
        "screen nearest bookshelf",
        "I need the screen on the desk closer to the shelves, not the one on the far desk on the west side.",
        "This is a computer display on a desk in the studio. It is the one nearer the bookshelf on the east wall.",
        "the monitr closest to the bookshelf, go"]),
    # ---------------- apartment (10) ----------------
    ("o", APT, 8, [8, 39, 55], [
        "Go to a plant.",
        "Could you take me to one of the houseplants?",
        "potted greenery",
        "I want to water something green today; any of the potted plants is fine, whichever room.",
        "This is a living green thing growing in a pot. It is a houseplant.",
        "take me to a potted plnat"]),
    ("or", APT, 12, [12, 13], [
        "Go to a book in the living room.",
        "Could you take me to one of the books in the lounge?",
        "living room volume",
        "I want something to read on the sofa, so a volume from the living room, not the programming textbook in the office.",
        "This is something printed and bound, to read. It is in the living room on the shelves.",
        "grab me a bok from the living room"]),
    ("or", APT, 23, [23, 24], [
        "Go to a chair in the kitchen.",
        "Could you take me to one of the dining seats in the kitchen?",
        "kitchen seat",
        "I want to eat at the table, so any seat in the kitchen, not the office swivel one.",
        "This is a wooden seat at the dining table. It is in the kitchen.",
        "grab me a chiar in the kitchen"]),
    ("od", APT, 2, [2], [
        "Go to the small brown leather loveseat.",
        "Could you take me to the little two-seater sofa in worn brown leather?",
        "brown leather two-seater",
        "Take me to the small leather couch, not the big gray three-seater.",
        "This is a compact couch for two people. It is covered in brown leather that looks a bit worn.",
        "the lil brown lether loveseat pls"]),
    ("ord", APT, 31, [31], [
        "Go to the lighthouse photo in the hallway.",
        "Could you take me to the little monochrome photograph in the hallway?",
        "hallway lighthouse photo",
        "I want to straighten the small framed photo in the hallway, not the big blue painting over the sofa.",
        "This is a little framed photograph in black and white showing a lighthouse. It hangs in the hallway.",
        "go to the lighthose picture in the hallway"]),
    ("ord", APT, 43, [43], [
        "Go to the oval mirror in the bathroom.",
        "Could you take me to the frameless mirror with the light in the bathroom?",
        "bathroom oval looking glass",
        "I need to shave, so the glass over the basin in the bathroom, not the gold-framed one in the hall.",
        "This is an oval looking glass with no frame. It hangs above the washbasin in the bathroom.",
        "the oval mirorr in the bathroom pls"]),
    ("ard", APT, 20, [20], [
        "Go to where I can warm up my leftovers quickly.",
        "Could you take me to something that can reheat a plate of food in a couple of minutes?",
        "reheat leftovers fast",
        "I want to heat yesterday's pasta quickly, without turning on the oven.",
        "This is something that heats cold food in a minute or two. It is what I'd use for soup that has gone cold.",
        "where can i nuke my lefovers"]),
    ("ard", APT, 45, [45], [
        "Go to where I can wash a load of dirty clothes.",
        "Could you take me to where I can do my laundry?",
        "wash dirty clothes",
        "My gym kit is filthy and needs a proper wash by machine, not by hand in the sink.",
        "This is a machine that cleans dirty shirts with water and detergent. It is what I need for a pile of laundry.",
        "where do i put my dirty laundy to get washed"]),
    ("s", APT, 12, [12], [
        "Go to the volume placed high up in the living room bookcase.",
        "Could you take me to the higher of the two books in the living room?",
        "living room shelf, upper volume",
        "I want the one up high on the living room shelves, not the one lying flat near the bottom.",
        "This is a book standing in the living room bookcase. It is higher up than the other one there.",
        "the bok higher up on the living room shelf"]),
    ("s", APT, 23, [23], [
        "Go to the dining chair closest to the stove.",
        "Could you take me to whichever kitchen seat is nearest the cooker?",
        "seat nearest cooker",
        "Bring me to the kitchen seat by the hob, not the white one across the table.",
        "This is a wooden seat at the dining table. It is the one nearest to the stove.",
        "the chiar closest to the stove, go there"]),
    ("s", APT, 39, [39], [
        "Go to the plant on top of the dresser.",
        "Could you take me to the little potted succulent sitting on the chest of drawers?",
        "pot on dresser",
        "I mean the pot sitting on the chest of drawers in the bedroom, not the big fig on the floor.",
        "This is a small potted plant. It rests on top of the bedroom chest of drawers.",
        "the lil plnat on the dresser, go to it"]),
    # ---------------- scans (6) ----------------
    ("o", SO, 11, [11, 12, 13], [
        "Go to a monitor.",
        "Could you take me to one of the computer screens?",
        "computer screen",
        "I need to look at something on a display, any of the screens, not the whiteboard.",
        "This is a computer display on a table. It is one of the screens in the office.",
        "go to any monitro"]),
    ("od", SK, 21, [21], [
        "Go to the red chair.",
        "Could you take me to the red seat?",
        "red seat",
        "I want the red one, not any of the black seats or the white one.",
        "This is a seat at the table. It is coloured red, unlike the others.",
        "go to the red chiar"]),
    ("s", SB, 8, [8], [
        "Go to the bedside lamp closer to the window.",
        "Could you take me to the bedside light nearest the window?",
        "light near window",
        "I'm reading on the window side, so the bedside light on that side, not the one by the door.",
        "This is a white light on a nightstand. It is the one of the pair nearer to the window.",
        "the lamp by the windw"]),
    ("s", SB, 5, [5], [
        "Go to the pillow nearest the foot of the bed.",
        "Could you take me to the cushion lying farthest from the headboard?",
        "cushion toward foot of bed",
        "Not the ones up against the headboard, the cushion lying further down toward the foot of the bed.",
        "This is a small cushion on the bed. It lies farther toward the foot than all the others.",
        "the pilow thats down near the end of the bed"]),
    ("s", SK, 25, [25], [
        "Go to the cup closest to the sink.",
        "Could you take me to the mug that's nearest the sink?",
        "mug by sink",
        "Not the ones on the table, I mean the mug over by the sink.",
        "This is a white mug on the cabinets. It stands nearest the sink.",
        "the cup next to the snik"]),
    ("s", SK, 3, [3], [
        "Go to the kitchen cabinet under the sink.",
        "Could you take me to the cupboard right below the sink?",
        "cupboard under sink",
        "I need the bin bags kept beneath the sink, so the cupboard below it, not the wall units above.",
        "This is a base cupboard in the kitchen. It sits directly beneath the sink.",
        "the cupbaord under the sink pls"]),
    ("s", SO, 16, [16], [
        "Go to the shortest bookshelf.",
        "Could you take me to the lowest of the bookcases?",
        "shortest bookcase",
        "I want to put a plant on top of the low shelving unit, not either of the tall brown ones.",
        "This is a shelf unit for books. It is shorter than the other two beside it.",
        "the short bookshlef, the white one"]),
]


def main():
    out = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round30.jsonl"
    lines = []
    for g, (typ, mp, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, g
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b30-g{g:02d}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": accept, "group": f"b30-g{g:02d}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"{len(GROUPS)} groups, {len(lines)} lines -> {out}")


if __name__ == "__main__":
    main()
