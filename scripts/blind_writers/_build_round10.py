"""Write evals/blind/round10.jsonl: 48 groups x 6 hand-written wordings.

Every wording below was written by hand for this round from the map files only
(the two caption maps under /work/shared/data/iesm_maps and the object lists in
/work/blind10/evals). Run:  python3 /work/blind10/build_round10.py
"""

from __future__ import annotations

import json
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "evals" / "blind" / "round10.jsonl"

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
CO3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SK = "../maps/scan_kitchen.json"
SB = "../maps/scan_bedroom.json"
SO = "../maps/scan_office.json"
SL = "../maps/scan_livingroom.json"


def flat(letter: str) -> str:
    return f"maps/flat_{letter}.json"


# (map, type, target, accept, [six wordings])
GROUPS: list[tuple[str, str, int, list[int], list[str]]] = [
    # ---------------- scene_office3 (caption map, one "rec room") ----------------
    (CO3, "o", 8, [8, 13, 20, 40], [
        "Show me all the cushions in here.",
        "where are the throw cushions",
        "Could you take me to the pillows? Any of them is fine.",
        "cushions, any colour",
        "I want to get comfy and need something soft to prop behind my back. Where are the cushions kept?",
        "Go to a pilow, whichever is closest.",
    ]),
    (CO3, "od", 13, [13], [
        "Take me to the navy blue velvet cushion.",
        "I'm looking for the dark blue cushion, the velvety one with the button in the middle. Not the orange or yellow ones.",
        "navy velvet cushion",
        "There's a cushion that's softer than the rest, made of velvet. It's deep navy and a bit bigger than the others.",
        "Could you find the blue pillow for me please?",
        "the one in navy velvet with the buttoned middle - that pillow",
    ]),
    (CO3, "od", 7, [7], [
        "Take me to the white wooden work table.",
        "Where's the white writing table? Not the brown wooden ones.",
        "white wood desk w/ usb port",
        "I need the work surface that's painted white. It's wooden and has a USB port built in.",
        "Could you please bring me over to the white desk?",
        "the white workstation, not either of the brown ones",
    ]),
    (CO3, "ard", 25, [25], [
        "What time is it? I need to check the time somewhere on the wall.",
        "I've lost track of time and my phone is dead. Where can I see the hour?",
        "need to see the time",
        "Is there something in here that tells me the time? Take me there.",
        "My meeting starts soon and I want to know how many minutes I have left - show me where to check.",
        "check current time, wall",
    ]),
    (CO3, "ord", 45, [45], [
        "Go to the golden brown wooden table in the rec room.",
        "In the rec room there's a warm honey-coloured wooden surface with power outlets built in. Take me to it.",
        "rec room, golden-brown wood one with the plug sockets, not the desks",
        "I need to charge my laptop. Where's the golden brown wooden table in the rec room, the one with outlets?",
        "In the recreation room, please find the wooden tabel with built-in power points.",
        "The thing I want is a piece of furniture made of golden brown wood. It's in the rec room and has charging outlets in it.",
    ]),
    # ---------------- scene_00829 (caption map, several rooms) ----------------
    (C829, "o", 42, [42, 197, 212, 259], [
        "Take me to the books.",
        "Any reading volumes around? Show me where they are.",
        "novels / hardbacks - any of them",
        "I'd like to browse the leather and paper bound volumes lying around the house. Where are they?",
        "Could you point me to a bok?",
        "I want something to read. Where are the books?",
    ]),
    (C829, "or", 9, [4, 9, 32, 79], [
        "Take me to the armchairs in the living room.",
        "living room lounge chairs, any",
        "Which comfy armchairs do you have in the living room? Bring me to one.",
        "I want to sink into one of the big comfy seats in the living room. Not the couch, not the folding chairs.",
        "Could you show me an easy chair in the living room?",
        "There are some plush armchairs, brown and beige. I mean the ones in the living room.",
    ]),
    (C829, "or", 112, [112, 233], [
        "Where are the mirrors in the bathroom?",
        "bathroom mirror, any",
        "I want to check my hair. Take me to a mirror in the bathroom.",
        "Could you go to one of the bathroom mirror frames, please?",
        "Take me to a looking glass in the bathroom - either one.",
        "There's a wooden-framed mirror hanging in a bathroom. Any of the bathroom ones will do, not the one in the living room.",
    ]),
    (C829, "od", 211, [211], [
        "Take me to the deep blue ceramic bowl with the gold patterns.",
        "the blue and gold dish",
        "I'm after the glossy blue decorative bowl, not the white one with sweets.",
        "There's an ornamental dish in deep blue. It has gold-tinged patterns all over the glaze.",
        "Can you find the blue bowl with golden swirls?",
        "blue glazed bowl gold pattern, the ornamental one",
    ]),
    (C829, "od", 184, [184], [
        "Take me to the L-shaped sofa.",
        "Where's the beige sectionnal with the chaise?",
        "I need the big corner sofa, the beige fabric one with a storage compartment. Not the one with the massage function.",
        "L shaped couch w/ chaise",
        "Could you find the sofa that bends round in an L shape, please?",
        "The one I want is a fabric settee in a light beige. It has a chaise longue built into one end.",
    ]),
    (C829, "ord", 110, [110], [
        "Take me to the small honey-coloured table in the bathroom.",
        "bathroom: little wooden side table with the X-shaped metal base",
        "In the bathroom there's a little table made of warm honey wood. Its legs form an X in metal. Go there.",
        "Could you go to the light wooden stand in the bathroom, the one with the USB port?",
        "Not the dark one in the living room - the honey-toned little table in the bathroom.",
        "I want to put my phone down to charge in the bathroom. Is there a small honey-wood table with a USB port in there?",
    ]),
    (C829, "ard", 192, [192], [
        "My dog is tired and needs a place to curl up. Where should I take him?",
        "Where does the cat sleep?",
        "puppy needs a nap spot",
        "I'm looking after the neighbour's dog tonight. Is there somewhere made for animals to sleep in this house?",
        "Take me to where the pet rests.",
        "The kitten keeps napping on the sofa. Show me the spot that's meant for her instead.",
    ]),
    # ---------------- flat_b ----------------
    (flat("b"), "o", 5, [5, 7, 26, 33, 34], [
        "Take me to a lamp.",
        "Where are the lights in the flat? Any reading light will do.",
        "It's getting dark in here. Show me where the lamps are.",
        "any light you can switch on - floor, desk or bedside",
        "Could you go to one of the standing or table lights, please?",
        "I want one of the lamsp - doesn't matter which room.",
    ]),
    (flat("b"), "s", 2, [2], [
        "Take me to the armchair closest to the window in the living room.",
        "living room: the easy chair right by the window",
        "There are two comfy chairs in the lounge. I want the one beside the window on the west wall.",
        "Which lounge seat is nearest the living room window? Go there.",
        "Not the one on the east side - the living room easy chair next to the window.",
        "I like to sit in the daylight. Bring me to the armchiar that's nearest the living-room window.",
    ]),
    # ---------------- flat_c ----------------
    (flat("c"), "ord", 36, [36], [
        "Take me to the green lamp in the study.",
        "study, green banker's light on the desk",
        "In the study there's a desk light with a green metal shade. Go to it.",
        "Could you please find the green desk light in the study?",
        "I need some light to read my papers. Where's the green lamp in the study?",
        "The light I mean is green and made of metal. It's the one in the study, not the pink one in the bedroom.",
    ]),
    (flat("c"), "s", 27, [27], [
        "Go to the bedside table that has the alarm clock on it.",
        "nightstand with red alarm clock on top",
        "There are two bedside tables in the bedroom. I want the one the red clock is sitting on.",
        "Can you take me to the bedside cabinet under the alarm clock?",
        "The alarm clock keeps ringing - take me to the bedside table it's sitting on, not the one with the pink lamp.",
        "Not the one with the lamp - the nightstand holding the clock.",
    ]),
    (flat("c"), "or", 19, [19, 20, 21], [
        "Take me to the chairs in the kitchen.",
        "kitchen seats, any one",
        "I want to sit down at the kitchen table. Where are the seats in there?",
        "Could you show me where the kitchen chairs are?",
        "Any of the dining seats in the kitchen - white or black, I don't mind.",
        "There are a few seats round the table. I mean the ones in the kitchen, not the rattan one in the bedroom.",
    ]),
    # ---------------- flat_d ----------------
    (flat("d"), "od", 22, [22], [
        "Take me to the wooden stool.",
        "the wood bar seat with the round top, not the black metal one",
        "I want the stool made of wood.",
        "There are two high seats in the kitchenette. The one I mean is brown wood with a round seat.",
        "Could you find the round-seated wooden perch in the kitchenette? Not the black metal one.",
        "wooden stol",
    ]),
    (flat("d"), "ard", 40, [40], [
        "I need somewhere to sit while I put my shoes on.",
        "Where can I sit down to lace up my boots before going out?",
        "sit + put shoes on, near the entrance",
        "My knee hurts when I bend over. Is there a seat by the entrance where I can pull my trainers on?",
        "Take me where I can sit to take off my shoes when I come in.",
        "Before heading out I always sit down to tie my laces. Where's the spot for that?",
    ]),
    (flat("d"), "s", 2, [2], [
        "Take me to the table in front of the sofa bed.",
        "the low one in front of the fold-out couch, not the dining one",
        "Sitting on the sofa bed, take me to the low surface right in front of my knees.",
        "table in front of sofa bed",
        "There's a couch that folds into a bed. I want the little coffee-height one standing just in front of it.",
        "Not the round one near the dining chairs - the low tabble by the sofa bed.",
    ]),
    (flat("d"), "or", 8, [8, 9], [
        "Take me to the lamps in the studio.",
        "studio lights, either one",
        "Could you show me where the lights are in the studio?",
        "I want to turn on some light in the main studio. Where are the lamps there?",
        "Any reading light in the studio is fine - the floor one or the desk one.",
        "The studio has a couple of lights. Go to one of them, not the moon one in the kids' room.",
    ]),
    # ---------------- flat_e ----------------
    (flat("e"), "or", 11, [11, 12, 13, 14, 15], [
        "Take me to the chairs in the dining room.",
        "dinning room seating",
        "We're having guests for dinner. Where are the seats in the dining room?",
        "Could you go to any chair in the dining room?",
        "Show me a seat at the dining-room table - any of them.",
        "There are several seats around the big oak table. I mean the ones in the dining room, not on the balcony.",
    ]),
    (flat("e"), "od", 14, [14], [
        "Take me to the black metal chair.",
        "the seat that doesn't match the others - the black metal bistro one",
        "I'm looking for the odd one out among the dining seats. It's black and made of metal.",
        "black metal bistro seat",
        "Could you find the black one, please? Not the sage green ones, and not the baby's high seat.",
        "There's one metal chair in black. It looks like it came from a cafe.",
    ]),
    (flat("e"), "s", 29, [29], [
        "Take me to the mirror above the washbasin.",
        "mirror over the bathroom sink",
        "Standing at the basin, I want the looking glass right above it.",
        "Where's the mirrored cabinet that hangs over the sink?",
        "I don't mean the round gold-framed thing in the lounge; I mean the one that hangs above the basin.",
        "There's a small white basin. Go to the glass that's mounted on the wall just over it.",
    ]),
    # ---------------- flat_f ----------------
    (flat("f"), "ord", 14, [14], [
        "Take me to the yellow chair in the kitchen.",
        "kitchen, mustard seat, the odd one out",
        "In the kitchen, three of the seats are blue. I want the mustard-yellow one.",
        "Could you go to the yellow painted seat at the kitchen table?",
        "Not the blue ones - the yellow chiar in the kitchen.",
        "I always sit in the mustard one in the kitchen. Bring me there.",
    ]),
    (flat("f"), "ard", 4, [4], [
        "I'm freezing. Where can I sit by a real fire?",
        "Where can I burn some logs to warm the room up?",
        "light a fire",
        "It's a cold evening and I'd love to watch the flames. Take me there.",
        "Take me to where I can get a wood fire going.",
        "My hands are numb from the walk. I want to warm them in front of some flames.",
    ]),
    (flat("f"), "o", 7, [7, 32], [
        "Take me to a rug.",
        "Where are the carpets in this place?",
        "any floor mat, lounge or bedroom",
        "I want to do some stretches on something soft on the floor. Where are the rugs?",
        "Could you show me one of the woven floor coverings?",
        "Find me a carpte, any of them.",
    ]),
    # ---------------- flat_g ----------------
    (flat("g"), "o", 2, [2, 3], [
        "Take me to the bikes.",
        "Where are the bicycles kept?",
        "bike, any",
        "I want to go for a ride this afternoon. Where's a bike?",
        "Could you show me where the cycles are, please?",
        "Either of the bikse is fine - the big one or the kids' one.",
    ]),
    (flat("g"), "s", 32, [32], [
        "Standing at the foot of the bed and facing the headboard, go to the bedside table on the left.",
        "facing the bed head: left nighstand",
        "Looking at the bed from its foot, I want the bedside table on my left-hand side.",
        "There are two bedside tables by the big bed. Take the left one as you face the headboard.",
        "From the end of the bed, which nightstand is on the left? Go there.",
        "Not the right one - the bedside cabinet on the left when you look at the bed from the foot.",
    ]),
    (flat("g"), "ord", 10, [10], [
        "Take me to the white plastic basket in the laundry room.",
        "laundry room, white plastic tub of clean clothes",
        "In the laundry room there's a white plastic hamper full of clean washing. Go to it.",
        "Could you find the white plastic tub of clean clothes in the laundry, please?",
        "I have to fold the clean clothes. Where's the white basket in the laundry room?",
        "Not the wicker hamper in the bedroom - the white plastic one in the laundry room.",
    ]),
    (flat("g"), "or", 34, [34, 35], [
        "Take me to the lamps in the bedroom.",
        "bedroom bedside ligths",
        "I want to read before sleeping. Where are the lights in the bedroom?",
        "Could you go to either of the bedside lamps in the bedroom?",
        "Any of the reading lights by the bed in the bedroom - teal or beige, don't care.",
        "There are two little lights on the nightstands. I mean the ones in the main bedroom, not the kids' room.",
    ]),
    # ---------------- flat_h ----------------
    (flat("h"), "o", 13, [13, 26, 32], [
        "Take me to a mug.",
        "Where are the coffee cups in this flat?",
        "I need something to drink from. Where are the mugs?",
        "any cup, any room",
        "Could you show me where the cups are?",
        "Find me one of the muggs, whichever is nearest.",
    ]),
    (flat("h"), "s", 10, [10], [
        "Take me to the armchair next to the bookshelf.",
        "living room, easy chair closest to the bookacse",
        "There are two armchairs in the living room. I want the one nearest the white bookshelf.",
        "Which lounge chair sits right by the shelves of paperbacks? Take me there.",
        "I want to grab a novel and sit down straight away - the comfy seat closest to the bookcase.",
        "Not the one in the far corner - the club chair beside the books.",
    ]),
    (flat("h"), "ard", 4, [4], [
        "Where should I drop my keys when I get home?",
        "I've just come in. Where do the house keys go?",
        "keys - where to leave them",
        "I keep losing my keys. Take me to where they're supposed to be kept.",
        "Could you take me to the place where we put keys by the door?",
        "I'm heading out and need my keys. Where are they usually left?",
    ]),
    (flat("h"), "ord", 6, [6], [
        "Take me to the cream sofa in the living room.",
        "living room, small cream two-seater under the window",
        "In the living room there's a little linen settee in cream. Go there.",
        "Could you please go to the cream couch in the living room, not the green velvet one?",
        "I want to sit in the sun. Where's the cream linen loveseat in the living room?",
        "The sofa I mean is a cream linen two-seater. It's in the living room by the east window.",
    ]),
    (flat("h"), "od", 43, [43], [
        "Take me to the red lamp.",
        "red ceramic bedside light",
        "I'm looking for the light with the red ceramic base and the cream shade.",
        "Could you find the red lamp please, not the brass or green ones?",
        "There's a bedside light that's bright red. Its shade is cream.",
        "the red ceramic lmap",
    ]),
    # ---------------- flat_i ----------------
    (flat("i"), "o", 1, [1, 11, 24, 47], [
        "Take me to a door.",
        "Where are the doorways in this building?",
        "I want to leave the room. Show me the doors.",
        "any exit or entrance",
        "Could you show me one of the entrances, please?",
        "Find me a dor, any one.",
    ]),
    (flat("i"), "or", 12, [12, 13], [
        "Take me to the desks in the studio.",
        "studio workstatoins",
        "I need to sit and draw for a bit. Where are the work tables in the studio?",
        "Could you go to one of the studio desks, please?",
        "Any of the drafting tables in the studio - oak or white, I'm not fussy.",
        "There are two work surfaces against the north wall. I mean the ones in the studio, not the reception counter.",
    ]),
    (flat("i"), "od", 15, [15], [
        "Take me to the black leather office chair.",
        "the high-backed black leather swivel seat",
        "I'm after the black leather one with the tall back, not the blue mesh one.",
        "black leather swivel",
        "Could you find the chair covered in black leather, please?",
        "There's a swivel seat upholstered in black leather. It has a high back.",
    ]),
    (flat("i"), "s", 17, [17], [
        "Take me to the monitor on the white desk.",
        "screen on the white desk",
        "There are two computer screens in the studio. I want the one sitting on the white desk, not the oak one.",
        "Which display is on the plain white desk? Go to it.",
        "I want to check my drawing on the screen that stands on the white desk.",
        "the monitr on the white desk, next to the little cactus",
    ]),
    (flat("i"), "ard", 20, [20], [
        "I need to print some plans.",
        "Where can I get a hard copy of these drawings on A3?",
        "print A3",
        "I've got a contract to scan for a client. Take me to where I can do that.",
        "Could you take me where I can print a document?",
        "The client wants paper copies of the floor plans. Where do I make them?",
    ]),
    # ---------------- apartment ----------------
    (APT, "or", 12, [12, 13], [
        "Take me to the books in the living room.",
        "living room: any book",
        "I want something to read on the sofa. Where are the novles in the living room?",
        "Could you show me where the reading material in the lounge is?",
        "Any of the volumes on the living-room shelves - red or yellow.",
        "There are a couple of hardbacks on the shelves. I mean the ones in the living room, not the textbook in the office.",
    ]),
    (APT, "s", 39, [39], [
        "Take me to the succulent on top of the dresser.",
        "potted plant on the chest of drawers",
        "In the bedroom there's a chest of drawers. I want the little succulent sitting on it.",
        "Which houseplant is standing on the dresser? Go there.",
        "Not the big fig in the living room - the small green thing on top of the drawers.",
        "the pot plant on the dressr",
    ]),
    (APT, "ard", 41, [41], [
        "I want to brush my teeth.",
        "Where can I wash my face before bed?",
        "brush teeth",
        "I've just woken up and need to freshen up and clean my teeth. Take me there.",
        "Could you take me where I can rinse out my toothbrush?",
        "Dinner was garlicky. Where do I go to brush my teeth?",
    ]),
    # ---------------- scans ----------------
    (SK, "o", 23, [23, 24, 25], [
        "Take me to a cup.",
        "Where are the mugs?",
        "I'm thirsty. Can you show me where the cups are?",
        "any mug",
        "Could you find me something to drink out of - a mug, blue, red or white, doesn't matter.",
        "Find a coffee mgu.",
    ]),
    (SB, "ord", 4, [4], [
        "Take me to the red pillow in the bedroom.",
        "bedroom, red cushion",
        "In the bedroom there's one red cushion among the white ones. Go to it.",
        "Could you please find the red cushion on the bed in the bedroom?",
        "Not the white ones or the blue one - the red cushon in the bedroom.",
        "The pillow I want is red. It's in the bedroom.",
    ]),
    (SO, "ord", 2, [2], [
        "Take me to the brown wooden table in the office.",
        "office, wooden table, not the white one",
        "In the office there are two big work surfaces. I want the one made of brown wood.",
        "Could you go to the wooden worktop in the office please?",
        "I spilled coffee on the brown wooden surface in the office. Take me there so I can wipe it.",
        "The one I need is wood, brown - in the office, not the white-topped one.",
    ]),
    (SL, "ard", 27, [27], [
        "I want to put my feet up.",
        "My legs are tired after the walk. Where can I rest my feet?",
        "rest feet",
        "Is there something low and soft I can prop my legs on while watching TV?",
        "Take me to where I can stretch my legs out and put my feet on something.",
        "After a long shift I just want to sit back with my feet raised. Where's the spot for that?",
    ]),
]


def main() -> None:
    assert len(GROUPS) == 48, len(GROUPS)
    lines = []
    for g, (map_, typ, target, accept, wordings) in enumerate(GROUPS, 1):
        assert len(wordings) == 6, (g, len(wordings))
        assert target in accept
        for k, text in enumerate(wordings, 1):
            lines.append(json.dumps({
                "id": f"b10-g{g:02d}-w{k}", "map": map_, "query": text, "type": typ,
                "target": target, "accept": sorted(accept), "group": f"b10-g{g:02d}",
            }, ensure_ascii=False))
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {OUT}")


if __name__ == "__main__":
    main()
