"""Hand-written blind suite round 34: 48 groups x 6 wordings. Writes evals/blind/round34.jsonl.

Each group: (gid, map key, type, target, accept, spec, [w1..w6]).
spec is used by check.py: for o/or ("label", room-or-None); for s a relation tuple; else None.
"""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SBED, SKIT, SLIV, SOFF = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                          "../maps/scan_livingroom.json", "../maps/scan_office.json")

GROUPS = [
    # ---------------- o: category, accept = every object with the label
    ("g01", C829, "o", 42, [42, 197, 212, 259], ("book", None), [
        "Go to a book.",
        "Could you lead me to any volume I could sit down and read?",
        "reading volume, any",
        "I want something to read before bed, so any bound volume will do, whichever room it's in.",
        "This is a book. It is a bound volume with a cover, and any of them in the house will do.",
        "take me to a boook, any one is fine"]),
    ("g02", OFF3, "o", 8, [8, 13, 20, 40], ("pillow", None), [
        "Go to a cushion.",
        "Could you bring me over to one of the pillows?",
        "throw cushion",
        "My back hurts on these hard seats, so find me a soft cushion to lean on; any colour works.",
        "This is a pillow. It is a soft stuffed cushion you can prop behind you on a seat.",
        "where's a cusion i can grab"]),
    ("g03", FG, "o", 2, [2, 3], ("bicycle", None), [
        "Go to a bike.",
        "Could you show me where a bicycle is kept?",
        "pedal bike",
        "I want to cycle to the shops, so take me to a bike; the car is not what I mean.",
        "This is a bicycle. It has two wheels and pedals and is kept out in the garage.",
        "where do we keep the bkies"]),
    ("g04", FI, "o", 16, [16, 17], ("monitor", None), [
        "Go to a computer screen.",
        "Could you take me to one of the monitors?",
        "computer display",
        "I need to check a drawing on a desktop display, not the big wall-hung one in the meeting room.",
        "This is a monitor. It is a flat display that sits on a desk and shows what the computer is doing.",
        "take me to a pc scren pls"]),
    ("g05", APT, "o", 11, [11, 51], ("bookshelf", None), [
        "Go to a bookcase.",
        "Could you take me to one of the bookshelves?",
        "shelving unit for books",
        "I want to put this novel away, so any bookcase will do, just not the kitchen cupboards.",
        "This is a tall shelf unit. It holds books or folders and stands against a wall.",
        "where's a bookcsae around here"]),
    ("g06", SLIV, "o", 17, [17, 18], ("plant", None), [
        "Go to a plant.",
        "Could you take me to one of the potted plants?",
        "greenery in pot",
        "The leaves need watering, so take me to any of the houseplants, not the vase.",
        "This is something green growing in a pot. It is a leafy indoor specimen standing on the floor.",
        "where's a houseplnat"]),
    ("g07", SOFF, "o", 21, [21, 22], ("trash can", None), [
        "Go to a bin.",
        "Could you take me to a wastebasket?",
        "rubbish bin",
        "I have scrap paper to throw out, so either waste bin works, whichever is closer.",
        "This is a trash can. It is a small black container for waste sitting on the floor.",
        "where can i find a garbage bni"]),
    # ---------------- or: category in a named room
    ("g08", C829, "or", 261, [261, 263], ("easy chair", "bedroom"), [
        "Go to an easy chair in the bedroom.",
        "Could you take me to one of the armchairs in the bedroom?",
        "bedroom lounge chair",
        "I want to sit and read in the bedroom, so any of the comfy armchairs there, not the ones in the living room.",
        "This is an easy chair. It is a cushioned seat with arms, located in the bedroom.",
        "take me to a bedrom armchair"]),
    ("g09", C829, "or", 34, [34, 74], ("side table", "living room"), [
        "Go to a side table in the living room.",
        "Could you bring me to one of the little end tables in the living room?",
        "living room end table",
        "I need to set my drink down while on the couch, so an end table in the living room, not the one by the bed.",
        "This is a side table. It is a small low surface for putting things on, in the living room.",
        "go to an end tabel in the living room"]),
    ("g10", OFF3, "or", 10, [10, 14, 16, 24], ("window", "rec room"), [
        "Go to a window in the rec room.",
        "Could you take me to one of the rec room windows?",
        "glazing, rec room",
        "It's stuffy in here, so take me to any of the glass panes in the rec room wall, not the door.",
        "This is an opening in the wall of the recreation room. It is fitted with glass to let light in.",
        "take me to a windo in the rec room"]),
    ("g11", FB, "or", 33, [33, 34], ("lamp", "bedroom"), [
        "Go to a lamp in the bedroom.",
        "Could you take me to one of the bedside lights in the bedroom?",
        "bedroom reading light",
        "I want to read in bed, so any light in the bedroom, not the floor lamp in the living room.",
        "This is a small light source in the bedroom. It sits on a nightstand beside the bed.",
        "take me to a ligth in the bedroom"]),
    ("g12", FE, "or", 11, [11, 12, 13, 14, 15], ("chair", "dining room"), [
        "Go to a chair in the dining room.",
        "Could you take me to a seat at the table in the dining room?",
        "dining room seat",
        "Guests are arriving for dinner, so any seat in the dining room works, not the sofa in the living room.",
        "This is a chair in the dining room. It is one of the seats placed around the table there.",
        "find me a seet in the dining room"]),
    ("g13", FI, "or", 6, [6, 7, 8, 9], ("chair", "meeting room"), [
        "Go to a chair in the meeting room.",
        "Could you show me a seat in the meeting room?",
        "meeting room seat",
        "The client meeting starts soon, so find me somewhere to sit in the meeting room, not at the studio desks.",
        "This is a seat in the conference room. It is placed around the glass table there.",
        "i need a chiar in the meeting room"]),
    ("g14", APT, "or", 12, [12, 13], ("book", "living room"), [
        "Go to a book in the living room.",
        "Could you find me a volume on the living room shelves?",
        "living room reading volume",
        "I'd like something to read on the sofa, so any book from the living room, not the textbook in the office.",
        "This is a bound volume in the living room. It is kept on the tall shelf unit there.",
        "take me to a voluem in the living room"]),
    # ---------------- od: described object
    ("g15", C829, "od", 261, [261], None, [
        "Go to the brown lounge chair made of woven fabric.",
        "Could you take me to the easy chair upholstered in woven cloth?",
        "woven-fabric brown armchair",
        "I want the armchair covered in woven fabric, not any of the leather ones.",
        "This is a deep brown armchair. It is covered in a woven textile rather than leather.",
        "the woven brwon armchair pls"]),
    ("g16", OFF3, "od", 13, [13], None, [
        "Go to the navy velvet cushion.",
        "Could you take me to the dark blue pillow with the velvety cover?",
        "navy velvet cushion, buttoned",
        "I want the navy velvet cushion, not the orange or yellow ones.",
        "This is a pillow in a dark navy shade. It has a soft velvet cover with a button on it.",
        "get me the navy velvt cushion"]),
    ("g17", FB, "od", 28, [28], None, [
        "Go to the green fabric armchair.",
        "Could you take me to the green upholstered reading seat?",
        "green cloth reading chair",
        "I want the green cloth easy chair, not the mustard velvet one or the leather one.",
        "This is a green upholstered armchair. It is a cloth-covered seat meant for reading.",
        "the grean reading chair please"]),
    ("g18", FG, "od", 34, [34], None, [
        "Go to the lamp with the teal glass base.",
        "Could you take me to the light whose base is turquoise glass?",
        "teal glass bedside light",
        "I need the bedside light with the blue-green glass foot, not the beige ceramic one.",
        "This is a small lamp. Its base is made of teal-coloured glass and it has a white shade.",
        "the teal glas light plz"]),
    ("g19", FI, "od", 23, [23], None, [
        "Go to the cobalt blue mug holding pencils.",
        "Could you find the blue ceramic cup that is stuffed with pencils?",
        "blue pencil pot",
        "I need a pencil, so find the blue cup they're kept in, not the yellow one with cold tea.",
        "This is a blue ceramic mug. It is used as a pencil holder.",
        "where's the blue cup full of pencls"]),
    ("g20", APT, "od", 48, [48], None, [
        "Go to the red leather swivel chair.",
        "Could you take me to the red leather seat on wheels?",
        "red leather desk seat",
        "I want to sit at the computer, so the red leather swivel seat, not a dining chair.",
        "This is a red leather office seat. It swivels, has armrests and rolls on castors.",
        "the red lether swivel seat"]),
    ("g21", SKIT, "od", 24, [24], None, [
        "Go to the red cup.",
        "Could you take me to the red mug?",
        "red cup",
        "I want my red mug, not the blue or the white one.",
        "This is a small red drinking vessel. It holds coffee or tea.",
        "where's my red mgu"]),
    # ---------------- ord: described object + room
    ("g22", C829, "ord", 259, [259], None, [
        "Go to the brown leather-covered book in the bedroom.",
        "Could you take me to the brown leather volume in the bedroom?",
        "bedroom leather volume",
        "I left my leather volume by the bed in the bedroom; not the dark one in the living room.",
        "This is a volume bound in brown leather. It lies in the bedroom and has gold lettering pressed into its cover.",
        "the leathr book in the bedroom"]),
    ("g23", C829, "ord", 157, [157], None, [
        "Go to the ornate mirror frame in the living room.",
        "Could you take me to the gilded, dark wooden mirror surround in the living room?",
        "living room ornate mirror",
        "I want to check my hair in the living room mirror, not the ones in the bathrooms or the bedroom.",
        "This is a frame around a mirror in the living room. It is dark wood with gold details and fancy patterns.",
        "the fancy mirorr in the living room"]),
    ("g24", OFF3, "ord", 7, [7], None, [
        "Go to the white desk in the rec room.",
        "Could you show me the white wooden work table in the rec room?",
        "white desk, rec room",
        "I'd like to work at the white writing table in the rec room, not at the brown ones.",
        "This is a white wooden work surface in the rec room. It has a built-in USB socket.",
        "take me to the whtie work table in the rec room"]),
    ("g25", FE, "ord", 14, [14], None, [
        "Go to the black metal chair in the dining room.",
        "Could you take me to the mismatched black metal seat in the dining room?",
        "dining room black bistro seat",
        "In the dining room, I want the odd black metal seat, not the sage green wooden ones.",
        "This is a black metal bistro chair in the dining room. It does not match the green seats around the table.",
        "the blak metal seat in the dining room"]),
    ("g26", FG, "ord", 19, [19], None, [
        "Go to the wooden chair with the red checked cushion in the kitchen.",
        "Could you take me to the wooden kitchen seat with a checked red pad?",
        "kitchen wooden seat, red check cushion",
        "In the kitchen, I mean the wooden seat with the red gingham cushion, not the white plastic one.",
        "This is a wooden seat in the kitchen. It has a red checked cushion on it.",
        "the wodden kitchen chair with the red cushion"]),
    ("g27", FI, "ord", 43, [43], None, [
        "Go to the oak nightstand in the bedroom.",
        "Could you take me to the oak bedside table in the bedroom?",
        "bedroom oak bedside table, open shelf",
        "In the bedroom, I want the oak bedside table, not the white one with the drawer.",
        "This is an oak bedside cabinet in the bedroom. It has an open shelf instead of a drawer.",
        "the oak bedsdie table in the bedroom"]),
    ("g28", APT, "ord", 51, [51], None, [
        "Go to the black metal bookshelf in the office.",
        "Could you take me to the black metal shelving in the office?",
        "office black metal shelves",
        "I need a manual from the office shelves, the black metal ones, not the walnut bookcase in the living room.",
        "This is an industrial shelf unit in the office. It is black metal and holds binders.",
        "the black metl shelf in the office"]),
    # ---------------- ard: need or activity, no category named
    ("g29", C829, "ard", 192, [192], None, [
        "Go to where the dog can curl up and sleep.",
        "Could you show me where our pet can nap?",
        "pet sleeping spot",
        "The puppy is tired and needs its own place to sleep, not the people's bed; where is it?",
        "This is where the family animal rests. It is a soft cushioned spot made for a cat or dog.",
        "where does the dog sleeep"]),
    ("g30", OFF3, "ard", 25, [25], None, [
        "Go to the thing on the wall that tells the time.",
        "Could you take me to where I can check the time on the wall?",
        "wall time check",
        "I need to see what time it is without unlocking my phone; something hanging on the wall.",
        "This is what I would look at to know the hour. It hangs on the wall and has a second hand.",
        "where can i check the tiem on the wall"]),
    ("g31", FB, "ard", 18, [18], None, [
        "Go to what I can use to boil water for tea.",
        "Could you take me to what I'd use to heat water for a cuppa?",
        "boil water, tea",
        "I want hot water for tea quickly, without putting a pan on the cooker.",
        "This is what I need to make tea. It heats water electrically on the worktop.",
        "i need to biol some water for tea"]),
    ("g32", FE, "ard", 33, [33], None, [
        "Go to where I can dry my washed clothes.",
        "Could you take me to the appliance that dries laundry?",
        "dry wet laundry",
        "The wash just finished and the clothes are soaking, so I need to dry them, not wash them again.",
        "This is what dries wet clothes. It tumbles them with warm air in the utility room.",
        "where can i dry my laundy"]),
    ("g33", FG, "ard", 11, [11], None, [
        "Go to where I can iron my shirt.",
        "Could you take me to where I can press the creases out of my trousers?",
        "press shirt creases",
        "My shirt is all wrinkled for the interview, so I need somewhere to smooth it out, not the washing machine.",
        "This is where I smooth wrinkled clothes. It is a long padded surface with an iron lying at one end.",
        "where can i get the creaes out of my shirt"]),
    ("g34", FI, "ard", 20, [20], None, [
        "Go to where I can print a plan on paper.",
        "Could you take me to what I'd use to make a paper copy of a drawing?",
        "print A3 plans",
        "I need to scan this sketch and then print it out large, not just view it on a screen.",
        "This is what turns a digital drawing into paper. It also scans and takes big sheets.",
        "where can i prnit this drawing"]),
    ("g35", APT, "ard", 29, [29], None, [
        "Go to where I can hang up my coat.",
        "Could you show me where I can hang my wet jacket when I come in?",
        "hang coat by door",
        "I'm dripping from the rain and just want to hang up my jacket by the front door, not put it in the bedroom wardrobe.",
        "This is where outdoor jackets get hung. It stands upright by the front door.",
        "where do i hang my jakcet"]),
    ("g36", SKIT, "ard", 26, [26, 27], None, [
        "Go to where I can throw away this banana peel.",
        "Could you take me to somewhere I can get rid of food scraps?",
        "throw away rubbish",
        "I have an empty yoghurt pot to get rid of; either spot for rubbish will do.",
        "This is where kitchen waste goes. It is a container on the floor for rubbish.",
        "where do i thorw out this wrapper"]),
    # ---------------- s: spatial relation picks one object among several of its kind
    ("g37", FB, "s", 2, [2], ("nearest", 13, "armchair", "living room"), [
        "Go to the armchair closest to the living room window.",
        "Could you take me to the easy chair nearest the window in the living room?",
        "easy chair nearest living room window",
        "I want to sit in the sun, so the armchair right by the living-room window, not the one on the far east side.",
        "This is a single-seat upholstered chair in the living room. It is the one nearest the window on the west wall.",
        "the comfy chair closest to the livng room window"]),
    ("g38", FE, "s", 16, [16], ("above", 10, "lamp", None), [
        "Go to the lamp hanging above the dining table.",
        "Could you take me to the light that hangs over the dining table?",
        "light over dining table",
        "I want the light directly above where we eat, not the floor lamp by the sofa or the bedside one.",
        "This is a pendant light. It hangs from the ceiling above the table in the dining room.",
        "the light hangnig over the dining table"]),
    ("g39", FG, "s", 32, [32], ("left", 31, "nightstand", "bedroom"), [
        "Standing at the foot of the bed and facing the headboard, go to the nightstand on the left.",
        "Could you take me to the bedside table on the left when I'm at the foot of the bed looking toward the headboard?",
        "left bedside table, facing headboard from foot",
        "Facing the head of the bed from its foot, I want the bedside table on my left, not the one with the paperbacks.",
        "This is a white bedside table in the bedroom. Seen from the foot of the bed facing the headboard, it is the one on the left.",
        "from the end of the bed, the left bedside tabel"]),
    ("g40", FI, "s", 9, [9], ("nearest", 11, "chair", "meeting room"), [
        "Go to the meeting room chair closest to the door.",
        "Could you take me to the seat in the meeting room that's nearest its door?",
        "meeting room seat nearest door",
        "I'll need to slip out early, so give me the meeting-room seat right by the door, not one at the far end.",
        "This is a gray upholstered seat in the meeting room. Of all the seats there it is the one nearest the door.",
        "the chiar nearest the meeting room door"]),
    ("g41", APT, "s", 12, [12], ("higher", None, "book", "living room"), [
        "Go to the book on the higher shelf of the living room bookcase.",
        "Could you take me to the book sitting higher up on the living room bookshelf?",
        "upper-shelf volume, living room",
        "I want the volume on the upper shelf in the living room, not the photo album lying on the bottom one.",
        "This is a volume standing on the living room shelving. It is the higher of the two there.",
        "the bok up high on the living room shelf"]),
    ("g42", APT, "s", 1, [1], ("under", 6, "sofa", None), [
        "Go to the sofa under the painting.",
        "Could you take me to the couch that sits beneath the framed picture?",
        "couch below painting",
        "I mean the settee under the abstract painting, not the small leather one by the west wall.",
        "This is a large gray couch in the living room. It sits right below the painting on the wall.",
        "the sofa under the paintng"]),
    ("g43", SBED, "s", 9, [9], ("right_lamp", 1, "lamp", None), [
        "Standing at the foot of the bed facing the pillows, go to the lamp on the right.",
        "Could you take me to the right-hand bedside lamp, as seen from the foot of the bed?",
        "right bedside light, viewed from bed's foot",
        "Looking at the bed from its foot, I want the light on the right-hand nightstand, not the left one.",
        "This is a small white light on a nightstand. From the foot of the bed looking toward its head, it is on the right.",
        "the rigth bedside light from the foot of the bed"]),
    ("g44", SKIT, "s", 21, [21], ("nearest", 15, "chair", None), [
        "Go to the chair closest to the door.",
        "Could you take me to the seat nearest the kitchen door?",
        "seat nearest door",
        "I just want to sit down as soon as I come in, so the seat right by the door, not the ones across the table.",
        "This is a seat at the kitchen table. It is the one nearest the door, at the table's end.",
        "the chiar closest to the door"]),
    ("g45", SKIT, "s", 8, [8], ("above", 10, "kitchen cabinet", None), [
        "Go to the upper cabinet right above the sink.",
        "Could you take me to the wall cupboard directly over the sink?",
        "cupboard over sink",
        "The glasses are kept above where I wash up, so the wall cupboard over the sink, not the ones beside it.",
        "This is a wall-mounted cupboard in the kitchen. It hangs directly above the sink.",
        "the cuboard above the sink"]),
    ("g46", SOFF, "s", 13, [13], ("between", None, "monitor", None), [
        "Go to the monitor between the other two.",
        "Could you take me to the middle one of the three screens?",
        "middle screen of three",
        "Not the screen at either end; I want the display in the middle of the row.",
        "This is a black computer display on the wooden table. It is the middle one of the three, between the others.",
        "the midle screen of the three"]),
    ("g47", SOFF, "s", 16, [16], ("shortest", None, "bookshelf", None), [
        "Go to the shortest bookshelf.",
        "Could you take me to the lowest of the bookcases?",
        "shortest bookcase",
        "I can't reach high shelves, so the low bookcase, not the two tall brown ones.",
        "This is a white shelving unit against the north wall. It is much shorter than the other two bookcases.",
        "the shortst bookcase"]),
    ("g48", SLIV, "s", 3, [3], ("between_on", 1, "pillow", None), [
        "Go to the pillow in the middle of the sofa.",
        "Could you take me to the cushion sitting between the other two on the couch?",
        "middle sofa cushion",
        "I want the cushion in the centre of the couch, not either one at the ends.",
        "This is a yellow cushion on the gray sofa. It sits between the two red ones.",
        "the cushon in the middle of the couch"]),
]


def main():
    out = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round34.jsonl"
    lines = []
    for gid, mp, typ, target, accept, _spec, ws in GROUPS:
        assert len(ws) == 6, gid
        for k, q in enumerate(ws, 1):
            lines.append(json.dumps({"id": f"b34-{gid}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": accept, "group": f"b34-{gid}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines, {len(GROUPS)} groups to {out}")


if __name__ == "__main__":
    main()
