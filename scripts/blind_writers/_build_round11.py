"""Write evals/blind/round11.jsonl: 48 hand-written groups x 6 wordings.

Every wording below was written by hand for this round. Run from anywhere:
    python3 /work/blind11/make_round11.py
"""
import json
from pathlib import Path

OUT = Path(__file__).resolve().parent / "evals" / "blind" / "round11.jsonl"

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
COF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SLR = "../maps/scan_livingroom.json"
SOF = "../maps/scan_office.json"
SKI = "../maps/scan_kitchen.json"
SBE = "../maps/scan_bedroom.json"
FB, FC, FD, FE, FF, FG, FH, FI = (f"maps/flat_{c}.json" for c in "bcdefghi")

# (map, type, target, accept, [six wordings])
GROUPS = [
    # ---------------- scene_00829 (caption map) ----------------
    (C829, "o", 112, [112, 157, 219, 229, 233], [
        "Take me to a mirror.",
        "Could you show me where a mirror is? Any one will do.",
        "any looking glass pls",
        "I've got something in my eye and need to see my face. Where can I look at myself?",
        "Is there a mirorr somewhere around here?",
        "I'm looking for one of those framed looking glasses hanging on the wall.",
    ]),
    (C829, "or", 14, [14, 33], [
        "Go to the curtains in the living room.",
        "Would you take me over to the living room drapes?",
        "living room curtain",
        "It's too bright in the lounge. Take me to the drapes there so I can pull them shut.",
        "I'm after the sheer white drapes. They hang in the living room, not the blue ones in the bedroom.",
        "Can you find the window curtians in the sitting room?",
    ]),
    (C829, "od", 164, [164], [
        "Take me to the towels with the embroidered H.",
        "Where's the stack of towels that has a letter H stitched on it?",
        "towles w/ H monogram",
        "I want the monogrammed ones. Those fluffy white towels with an 'H' on them, folded on the rack.",
        "Could you bring me to the white towels, the ones embroidered with an H, not the plain piles?",
        "I need a fresh towel. Take me to the folded set marked with the H.",
    ]),
    (C829, "od", 56, [56], [
        "Take me to the door with the peephole.",
        "Which door has the little spyhole and the gold knob? Go there please.",
        "door w/ gold knob + peephole",
        "Someone's knocking and I want to see who it is first. Bring me to the door that has a peephole.",
        "It's a dark wooden door. It has a gold-coloured doorknob and a tiny peephole in it.",
        "the dorway with a peephole, not the ones with smart locks",
    ]),
    (C829, "ord", 184, [184], [
        "Take me to the couch in the bedroom.",
        "Could you guide me to the beige L-shaped sofa in the bedroom?",
        "bedroom sofa, beige, L-shape",
        "I want to stretch out on the chaise. The beige settee in the bedroom, not the one in the living room.",
        "There's a big beige corner sofa with a chaise end. It's in the bedroom.",
        "Please go to the beige sofa in the bedrom.",
    ]),
    (C829, "ard", 122, [122], [
        "I really need to pee.",
        "Where can I go to the loo around here?",
        "Excuse me, I need the restroom urgently, can you take me there?",
        "need the WC",
        "Too much coffee this morning. Please show me where I can relieve myself.",
        "My little boy needs to go potty, quick!",
    ]),
    (C829, "ard", 249, [249], [
        "I need to type up a long email.",
        "Where can I type out a few lines of text?",
        "want to type something",
        "Writing on a touchscreen drives me mad. Take me to something I can type on properly.",
        "Could you bring me to whatever I'd use to enter text into the computer?",
        "I have to write a report and I hate tapping it out on my phone. Where should I go?",
    ]),
    # ---------------- scene_office3 (caption map) ----------------
    (COF3, "o", 7, [7, 55, 64], [
        "Take me to a desk.",
        "Any free workstation around? Please take me to one.",
        "go to a deks",
        "I need somewhere to set up my laptop and work. Bring me to one of the work desks.",
        "Show me to a bureau where I could write something.",
        "Where's a computer workstation I can use?",
    ]),
    (COF3, "od", 20, [20], [
        "Take me to the yellow pillow.",
        "Could you find the soft yellow cushion with the pattern on it?",
        "yellow cushion",
        "This is a slightly lumpy cushion in a sunny yellow with a pattern. Please take me there.",
        "Bring me to the yellow one among the cushions, not the orange or the navy ones.",
        "I'd like the patterned yellow cushon, please.",
    ]),
    (COF3, "ord", 7, [7], [
        "Go to the white desk in the rec room.",
        "In the recreation room there's a white wooden workstation. Could you take me to it?",
        "rec room, white wood workstation",
        "Not the brown ones. I mean the white desk in the rec room.",
        "I left my notes on the white wooden writing surface in the games room. Bring me there.",
        "Take me over to the pale wooden workspace in the rec room, the white one with the USB port.",
    ]),
    (COF3, "ard", 25, [25], [
        "What time is it? Take me where I can check.",
        "I keep losing track of time. Where can I see the time on the wall?",
        "need to check the time",
        "My battery died and I've no idea how late it is. Take me to something on the wall that tells the time.",
        "Could you bring me somewhere I can see how many minutes are left before the meeting?",
        "I have to leave at three sharp, help me keep an eye on the hour.",
    ]),
    (COF3, "ard", 68, [68], [
        "I need to make a call.",
        "Could you take me to something I can ring my colleague on?",
        "need to call someone",
        "My mobile is dead and I have to call a taxi. Where can I do that?",
        "I'd like to dial a number, please take me there.",
        "Someone is expecting me to call them back right now. Where should I go?",
    ]),
    # ---------------- apartment ----------------
    (APT, "o", 1, [1, 2], [
        "Take me to a sofa.",
        "Where's a couch I could sit on?",
        "a couch pls",
        "I'm exhausted. Bring me to a settee so I can lie down.",
        "Could you guide me to one of the couches? Either is fine.",
        "any sofa, big or small",
    ]),
    (APT, "or", 12, [12, 13], [
        "Take me to a book in the living room.",
        "Is there any reading material on the shelves in the lounge? Take me to it.",
        "living room, something to read off the shelf",
        "I'm bored. Take me to something to read in the living room, a book off the shelf.",
        "Find me a volume in the sitting room, not the ones in the office.",
        "Which titles are on the sitting room shelves? Take me to one of them.",
    ]),
    (APT, "od", 23, [23], [
        "Take me to the wooden chair with the green seat cushion.",
        "Could you go to the dining seat that has a green pad on it?",
        "seat w/ green cushion",
        "I want the one with the green cushion, not the white spindle-back one.",
        "This is a plain wooden dining chair. Its seat has a green cushion.",
        "Where's the wooden seat with the green cushion tied on?",
    ]),
    (APT, "ord", 42, [42], [
        "Go to the grey cabinet in the bathroom.",
        "Could you take me to the grey vanity unit under the basin in the bathroom?",
        "bathroom, grey cupboard",
        "I need a fresh towel from the grey wooden cupboard in the bathroom, not the metal one in the office.",
        "It's a gray wooden cabnet. It's in the bathroom.",
        "Bathroom, the grey storage unit. Take me there please.",
    ]),
    (APT, "ard", 54, [54], [
        "I need to print my boarding pass.",
        "Where can I get a hard copy of this document?",
        "print something",
        "The landlord wants a signed paper copy of the lease. Take me where I can make one.",
        "Could you bring me to whatever puts my files onto paper?",
        "I have to print out a few pages for tomorrow's meeting, where should I go?",
    ]),
    (APT, "s", 12, [12], [
        "Take me to the book on the higher shelf of the living room bookcase.",
        "There are two things to read on the living room shelves. I mean the one up top, not the one at the bottom.",
        "upper volume, living room shelf",
        "Could you go to the novel that stands higher up on the living room bookcase?",
        "The hardback I want is on the shelving in the lounge. It's the higher of the two, not the one lying flat down low.",
        "get me to the top-shelf boook in the living room",
    ]),
    # ---------------- scan maps ----------------
    (SLR, "od", 6, [6], [
        "Take me to the brown leather armchair.",
        "Could you show me the leather easy chair?",
        "leather armchair",
        "I prefer leather seats. Bring me to the brown leather one, not the green one.",
        "It's a brown easy chair. It's upholstered in leather.",
        "Go to the brown leather armcahir please.",
    ]),
    (SOF, "o", 11, [11, 12, 13], [
        "Take me to a monitor.",
        "Could you bring me to one of the computer screens?",
        "any screen",
        "I need to look at something on a display. Go to any of the monitors.",
        "Where are the computer displays in this office? Take me to one.",
        "Go to a screeen, whichever is handy.",
    ]),
    (SKI, "o", 26, [26, 27], [
        "Take me to a trash can.",
        "Where's the bin?",
        "garbage bin",
        "I've got some peelings to throw away. Bring me to a rubbish bin.",
        "Could you take me to any of the waste bins in the kitchen?",
        "go to a wastebasket, either one",
    ]),
    (SLR, "s", 2, [2], [
        "Take me to the red cushion closest to the green armchair.",
        "Sitting on the sofa, it's the red pillow on my left.",
        "red cushion, end nearest the green chair",
        "Facing the sofa from the coffee table, I want the red cushion on the right-hand side.",
        "There are two red cushions on the couch. I mean the one nearer the green armchair, not the one by the leather chair.",
        "the red pilow next to the yellow one, on the side of the green armchair",
    ]),
    (SOF, "s", 7, [7], [
        "Take me to the blue office chair nearest the windows.",
        "Which blue swivel seat is closer to the window side? Go there.",
        "blue seat, window side",
        "Of the two blue seats, I want the one toward the windows, not the one on the far side of the wooden table.",
        "There's a blue desk seat at the wooden table. It's the one on the window side of that table.",
        "go to the blue chiar closest to the window",
    ]),
    (SKI, "s", 25, [25], [
        "Take me to the cup next to the sink.",
        "Is there a mug by the sink? Bring me to that one, not the ones on the table.",
        "mug beside sink",
        "I left my coffee by the sink. Go to that cup.",
        "The mug on the counter near the sink, not the ones on the table.",
        "Go to the mug that's sitting on the worktop by the sink.",
    ]),
    (SBE, "s", 8, [8], [
        "Take me to the bedside lamp nearest the window.",
        "Standing at the foot of the bed facing the headboard, I want the light on the left.",
        "bedside light, window side",
        "The reading light by the window, not the one by the door.",
        "It's a white lamp on a nightstand. That nightstand is the one closer to the desk and the window.",
        "go to the lmap on the window side of the bed",
    ]),
    # ---------------- flat_* maps ----------------
    (FH, "s", 47, [47], [
        "Take me to the nightstand with the book on it.",
        "In the master bedroom, which bedside table has a paperback lying on it? Go there.",
        "bedside table w/ novel on top",
        "I'm after the bedside cabinet with the orange detective novel on it, not the one with the lamp.",
        "There are two white bedside tables by the double bed. Mine is the one with a book on top.",
        "Go to the night stand where the orange paperback is.",
    ]),
    (FD, "s", 21, [21], [
        "Take me to the stool closest to the bin.",
        "Which bar seat is nearer the pedal bin? That one please.",
        "stoool by the trash",
        "I want to sit down, but not near the fridge. Take me to the other counter seat, the one by the rubbish bin.",
        "There are two stools in the kitchenette. I mean the one near the bin, on the studio side.",
        "Go to the seat that stands closest to the trash bin in the kitchenette.",
    ]),
    (FI, "s", 16, [16], [
        "Take me to the monitor next to the green lamp.",
        "Which computer screen sits beside the banker's lamp? Go there.",
        "screen nearest green lamp",
        "Facing the north wall of the studio, I want the screen on the left.",
        "There's a green glass desk light on one of the desks. Take me to the display on that same desk.",
        "go to the montior by the green-shaded lamp",
    ]),
    (FG, "o", 2, [2, 3], [
        "Take me to a bicycle.",
        "Where's a bike?",
        "any bike",
        "I want to cycle to the shop. Bring me to one of the bikes.",
        "Could you show me where the bikes are kept? Either one is fine.",
        "go to a bicyle",
    ]),
    (FH, "o", 13, [13, 26, 32], [
        "Take me to a mug.",
        "Where can I find a cup?",
        "any coffee cup",
        "I'm thirsty and want a hot drink. Take me to one of the mugs.",
        "Show me where a teacup is, in any room.",
        "go to a mugg",
    ]),
    (FD, "o", 8, [8, 9, 34], [
        "Take me to a lamp.",
        "Where's a light I can switch on?",
        "any light",
        "It's getting dark in here. Bring me to one of the lamps.",
        "Could you show me any reading light in the flat?",
        "take me to any floor or desk light",
    ]),
    (FB, "or", 33, [33, 34], [
        "Take me to a lamp in the bedroom.",
        "Could you bring me to one of the bedside lights?",
        "bedroom light",
        "I want to read in bed tonight. Go to a lamp in the bedroom.",
        "Not the ones in the living room or study. I need a light in the bedroom.",
        "Show me the lights on the nightstands in the bedroom.",
    ]),
    (FG, "or", 18, [18, 19], [
        "Take me to a chair in the kitchen.",
        "Is there a seat at the kitchen table? Take me to one.",
        "kitchen chair",
        "My knees hurt. Bring me to one of the kitchen seats.",
        "It's a dining seat. It's in the kitchen, at the round white table.",
        "go to a kitchen chiar",
    ]),
    (FH, "or", 46, [46, 47], [
        "Take me to a nightstand in the master bedroom.",
        "Could you go to one of the bedside tables in the main bedroom?",
        "master bedroom bedside table",
        "Not the guest room one. I mean a bedside table in the master bedroom.",
        "I need a bedside cabinet in the big bedroom, either side of the double bed.",
        "go to a nighstand in the master bedroom",
    ]),
    (FF, "or", 12, [12, 13, 14, 15], [
        "Take me to a chair in the kitchen.",
        "Find me somewhere to sit at the farmhouse table in the kitchen.",
        "kitchen chair, any",
        "I want to have breakfast. Bring me to one of the dining seats in the kitchen.",
        "Not the rocker on the porch. One of the seats in the kitchen.",
        "any seat in the kitchen, blue or yellow",
    ]),
    (FI, "or", 6, [6, 7, 8, 9], [
        "Take me to a chair in the meeting room.",
        "Could you show me a seat in the conference room?",
        "meeting room seat",
        "I have a client call in a minute. Bring me to one of the chairs around the meeting table.",
        "Any of the seats in the meeting room will do, red or gray.",
        "Go to the meeting room and find me somewhere to sit at the glass table.",
    ]),
    (FC, "or", 5, [5, 7], [
        "Take me to a lamp in the living room.",
        "Which lights are in the lounge? Take me to one.",
        "living room light",
        "I want to read on the sofa. Go to one of the lamps in the living room.",
        "Not the bedroom or the study. A light in the living room, please.",
        "a light in the sitting room, either one",
    ]),
    (FF, "od", 14, [14], [
        "Take me to the yellow chair.",
        "Which seat at the table is painted mustard? Go there.",
        "mustard chair",
        "It's the odd one out at the dining table. The mustard-painted one, not the blue ones.",
        "This is a wooden seat painted mustard yellow. It doesn't match the others.",
        "go to the yellow painted seat",
    ]),
    (FI, "od", 15, [15], [
        "Take me to the black leather office chair.",
        "Where's the high-backed leather swivel seat?",
        "black leather swivel chair",
        "I want the comfy executive one with the tall back, not the blue mesh one.",
        "It's a black leather seat. It has a high back and swivels.",
        "the leather desk seat with the high back",
    ]),
    (FE, "od", 7, [7], [
        "Take me to the round mirror with the gold frame.",
        "Could you find the circular gold-rimmed looking glass?",
        "gold round mirror",
        "Not the bathroom cabinet one. I want the round one with the thin gold frame.",
        "It's a round looking glass. Its frame is thin and golden.",
        "Where's the gold-framed mirorr?",
    ]),
    (FB, "ord", 3, [3], [
        "Take me to the brown leather armchair in the living room.",
        "In the lounge, which is the leather easy chair? Go there.",
        "living room, brown leather chair",
        "Not the yellow velvet one. The brown leather armchair in the living room.",
        "It's a brown leather seat with wooden legs. It's in the living room, on the east side.",
        "Take me to the leather armchiar in the sitting room.",
    ]),
    (FH, "ord", 26, [26], [
        "Take me to the white mug in the kitchen.",
        "Could you find the white cup with blue stripes in the kitchen?",
        "kitchen, white striped cup",
        "Not the yellow one in the living room. The white mug in the kitchen, next to the kettle.",
        "It's a white ceramic cup with blue stripes. It sits on the kitchen worktop.",
        "go to the white stripy cup by the kettle, kitchen",
    ]),
    (FG, "ord", 10, [10], [
        "Take me to the white basket in the laundry room.",
        "Where is the white plastic laundry basket in the utility room?",
        "laundry room, white hamper",
        "I need to fold the clean clothes. Bring me to the white clothes tub in the laundry room.",
        "Not the wicker one in the bedroom. The white plastic one in the laundry room, full of clean clothes.",
        "go to the white laundry baskett in the utility room",
    ]),
    (FI, "ord", 45, [45], [
        "Take me to the white lamp in the bedroom.",
        "Could you show me the bedside light with the white ceramic base in the bedroom?",
        "bedroom lamp, white ceramic",
        "Not the rattan one. The white bedside light in the bedroom.",
        "It's a light with a white ceramic base and a linen shade. It's in the bedroom.",
        "go to the white ceramic one beside the bed, in the bedroom",
    ]),
    (FC, "ord", 31, [31], [
        "Take me to the rattan chair in the bedroom.",
        "Where's the beige wicker seat in the bedroom?",
        "bedroom rattan seat",
        "I need to grab the clothes off the beige rattan chair in the bedroom.",
        "It's a beige rattan seat with clothes piled on it. You'll find it in the bedroom.",
        "go to the cane seat in the bedroom, the beige one",
    ]),
    (FF, "ard", 25, [25], [
        "I'd like to look at the stars tonight.",
        "Where can I go to watch the planets and the moon up close?",
        "stargazing",
        "It's a clear night. Take me to whatever I can use to see Saturn's rings.",
        "Could you bring me to the thing for looking at the night sky?",
        "My son wants to see the craters on the moon. Where should we go?",
    ]),
    (FD, "ard", 27, [27], [
        "I need to iron my shirt.",
        "My trousers are all creased. Where can I press them?",
        "press a shirt",
        "I have an interview tomorrow and my blouse is wrinkled. Take me where I can smooth it out.",
        "Could you take me to where I can get the creases out of my clothes?",
        "Where can I do some ironing?",
    ]),
    (FG, "ard", 5, [5], [
        "I need a screwdriver to fix a loose hinge.",
        "Where can I find a hammer and some nails?",
        "need tools",
        "The cupboard door is falling off. Take me to where the spanners and screwdrivers are kept.",
        "Could you bring me to something that has pliers in it?",
        "My bike chain came off and I need a wrench. Where should I look?",
    ]),
]


def main() -> None:
    assert len(GROUPS) == 48, len(GROUPS)
    lines = []
    for g, (mp, typ, target, accept, qs) in enumerate(GROUPS, 1):
        assert len(qs) == 6 and target in accept, g
        for w, q in enumerate(qs, 1):
            lines.append(json.dumps({
                "id": f"b11-g{g:02d}-w{w}", "map": mp, "query": q, "type": typ,
                "target": target, "accept": accept, "group": f"b11-g{g:02d}",
            }, ensure_ascii=False))
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {OUT}")


if __name__ == "__main__":
    main()
