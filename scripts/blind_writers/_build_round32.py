"""Hand-written blind suite round 32: 48 groups x 6 wordings. Writes evals/blind/round32.jsonl.

    python3 scripts/emit.py

Each group: map, type, target, accept, (label and room for o/or so check.py can re-derive the
accept set), claims (for s: numeric spatial claims checked by check.py), and six wordings w1..w6.
"""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
COFF = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

G = []


def g(map_, type_, target, accept, q, label=None, room=None, claims=None):
    assert len(q) == 6
    G.append(dict(map=map_, type=type_, target=target, accept=sorted(accept), q=q,
                  label=label, room=room, claims=claims or []))


# ---------------------------------------------------------------- caption map scene_00829
g(C829, "o", 112, [112, 157, 219, 229, 233], label="mirror frame", q=[
    "Go to one of the framed mirrors.",
    "Could you take me to a mirror with a frame around it?",
    "any framed mirror",
    "I want to check my hair before I leave, so find me a mirror, any of the framed ones will do.",
    "This is a looking glass set in a frame. It hangs on a wall, and any of them in the house is fine.",
    "just need a mirorr, whichever framed one is closest",
])
g(C829, "o", 79, [4, 9, 32, 79, 191, 261, 263], label="easy chair", q=[
    "Go to an easy chair.",
    "Could you bring me to one of the lounge chairs?",
    "nearest armchair, any",
    "My back hurts and I want a deep comfy armchair to sink into, not a folding one.",
    "This is a big upholstered lounging seat for one person. It is one of the easy chairs, and any will do.",
    "take me to a comfy reclner, any of them is fine",
])
g(C829, "or", 182, [182, 250], label="side table", room="bedroom", q=[
    "Go to a side table in the bedroom.",
    "Could you take me to one of the small occasional tables in the bedroom?",
    "bedroom occasional table",
    "I left my glasses on a little table in the bedroom, not one of the ones in the living room.",
    "This is a small occasional table. It is in the bedroom, and either one there is fine.",
    "go to the bedrom side table please, either of the two",
])
g(C829, "or", 85, [85, 109, 114, 130, 222], label="doorway", room="bathroom", q=[
    "Go to a doorway of the bathroom.",
    "Could you take me to one of the bathroom entrances?",
    "bathroom door",
    "I want to check that the bathroom door closes properly, so any bathroom doorway, not the bedroom ones.",
    "This is a wooden door opening. It belongs to one of the bathrooms.",
    "head to the bathroom doorwya, any of them",
])
g(C829, "od", 211, [211], q=[
    "Go to the blue bowl with gold patterns.",
    "Could you find the glossy dark blue ceramic dish with golden decoration?",
    "blue and gold ornamental bowl",
    "I want to show a guest the pretty blue ornamental bowl, not the white one for sweets.",
    "This is a shiny navy ceramic bowl. It is decorated with fine golden patterns and is just for display.",
    "where's that blue decrative bowl with the gold on it",
])
g(C829, "od", 23, [23], q=[
    "Go to the couch with the built-in massager.",
    "Could you take me to the plush beige sofa that has a massage function?",
    "massaging sofa",
    "My shoulders are sore, so I want the sofa that massages you, not the L-shaped one with the chaise.",
    "This is a soft beige sofa with plush upholstery. It has a motorised massage system built in.",
    "go to the massage sofa, the plush biege one",
])
g(C829, "ord", 197, [197], q=[
    "Go to the red leather-bound book in the bathroom.",
    "Could you take me to the red volume that's lying in the bathroom?",
    "bathroom red hardback",
    "I was reading the red leather one in the bathroom, not the dark brown one in the bedroom.",
    "This is a red hardback bound in leather with gold lettering on its cover. It is in the bathroom.",
    "find the red leather nvel in the bathroom",
])
g(C829, "ard", 192, [192], q=[
    "Go to where the dog sleeps.",
    "Could you show me where my cat can curl up for a nap?",
    "pet sleeping spot",
    "The puppy is tired and needs its own bed, not ours in the bedroom.",
    "This is where an animal rests. It is a soft cushioned spot made for a pet, not for people.",
    "where does the dog slepe",
])
# ---------------------------------------------------------------- caption map scene_office3
g(COFF, "o", 13, [8, 13, 20, 40], label="pillow", q=[
    "Go to a pillow.",
    "Could you bring me over to one of the cushions?",
    "any cushion",
    "My neck is stiff and I need something soft to prop it up, any cushion will do.",
    "This is a soft cushion for the sofa. It can be any of them, whatever the colour.",
    "take me to a cushon please",
])
g(COFF, "od", 64, [64], q=[
    "Go to the desk with the cable management.",
    "Could you take me to the wooden workstation that keeps its cords tidied away?",
    "wooden workstation, built-in cable organiser",
    "I need to plug in my laptop where the wires are neatly routed, not at the white one.",
    "This is a brown wooden work table. It has a system built in for tidying cables.",
    "the brown desk with the cabel tidy thing",
])
g(COFF, "ord", 40, [40], q=[
    "Go to the striped orange pillow in the rec room.",
    "Could you take me to the orange cushion with white and yellow stripes in the rec room?",
    "rec room striped orange cushion",
    "I want the orange cushion with stripes from the rec room, not the plain orange one with a button.",
    "This is an orange cushion striped in white and yellow. It is in the recreation room.",
    "the stripy orange pilow in the rec room",
])
g(COFF, "ard", 67, [67], q=[
    "Go to the thing I use to change the channel.",
    "Could you help me find something to switch the TV channel from the sofa?",
    "change channel",
    "I want to turn the volume down without getting up, so find what controls the screen, not my phone.",
    "This is what I need to flick between programmes. It is a small handheld thing with buttons.",
    "need to chnage the channel, help me out",
])
# ---------------------------------------------------------------- scans: o, od, ard
g(SK, "o", 17, [17, 18, 19, 20, 21, 22], label="chair", q=[
    "Go to a chair.",
    "Could you take me to one of the seats at the table?",
    "any seat",
    "My feet hurt; any chair at all, the colour doesn't matter.",
    "This is a seat with four legs and a backrest. Any of them is fine.",
    "go to a chiar",
])
g(SL, "o", 17, [17, 18], label="plant", q=[
    "Go to a plant.",
    "Could you take me to one of the houseplants?",
    "potted greenery",
    "The leaves need watering, so either of the potted plants, I don't mind which.",
    "This is something green growing in a pot. Either one in the room is fine.",
    "take me to a houseplnat",
])
g(SB, "od", 4, [4], q=[
    "Go to the red pillow.",
    "Could you take me to the red cushion?",
    "crimson cushion",
    "I want the red cushion, not the white ones or the blue one.",
    "This is a red cushion. It is the only one of that colour.",
    "the red pilow please",
])
g(SK, "od", 21, [21], q=[
    "Go to the red chair.",
    "Could you take me to the red seat?",
    "red seat",
    "I always sit in the red one, not the black or the white chairs.",
    "This is a seat painted red. It is the only red one in the kitchen.",
    "go to the rde seat",
])
g(SK, "ard", 12, [12], q=[
    "Go to what I can brew a coffee with.",
    "Could you take me to something that makes espresso?",
    "brew coffee",
    "I'm half asleep and need a fresh cup of coffee brewed, not just the cups on the table.",
    "This is what I need to make my morning coffee. It brews it for me.",
    "desperate for a cofee, where do i make one",
])
g(SO, "ard", 17, [17], q=[
    "Go to where I can sketch a diagram for the whole team to see.",
    "Could you take me to something I can write on with a marker during the meeting?",
    "write with markers on wall",
    "I need to explain a plan to colleagues with a drawing they can all see, not on paper.",
    "This is where I want to jot ideas in big letters for everyone. It should be wipeable.",
    "need to draw a quick diagrm for the team",
])
# ---------------------------------------------------------------- apartment: o, or, od, ord, ard
g(APT, "o", 6, [6, 31], label="picture", q=[
    "Go to a picture.",
    "Could you take me to one of the framed artworks on the walls?",
    "framed wall art",
    "I want to straighten something hanging on the wall, either of the framed pictures.",
    "This is a framed image hanging on a wall. Either one will do.",
    "go see a pcture on the wall",
])
g(APT, "or", 21, [21], label="cabinet", room="kitchen", q=[
    "Go to the cabinet in the kitchen.",
    "Could you take me to the kitchen cupboards?",
    "kitchen cupboard",
    "I need a plate, so the cupboard in the kitchen, not the one under the bathroom sink.",
    "This is a storage cupboard. It is in the kitchen.",
    "go to the kitchen cubpoard",
])
g(APT, "or", 37, [37], label="rug", room="bedroom", q=[
    "Go to the rug in the bedroom.",
    "Could you take me to the small mat on the bedroom floor?",
    "bedroom floor mat",
    "I spilled water on the rug in the bedroom, not the big one in the living room.",
    "This is a floor covering. It is in the bedroom.",
    "the bedroom rgu please",
])
g(APT, "od", 2, [2], q=[
    "Go to the brown leather loveseat.",
    "Could you take me to the small two-seater covered in brown leather?",
    "brown leather two-seater",
    "I want the little leather one against the wall, not the big gray sofa facing the TV.",
    "This is a compact settee in worn brown leather. It seats two people.",
    "the brown leathr loveseat",
])
g(APT, "ord", 30, [30], q=[
    "Go to the gold-framed mirror in the hallway.",
    "Could you take me to the ornate gilded looking glass in the hall?",
    "hall gold-framed looking glass",
    "I want a final check of my outfit in the hallway mirror, not the oval one in the bathroom.",
    "This is a tall rectangular looking glass with a fancy golden frame. It hangs in the hallway.",
    "the gold mirorr in the hallway",
])
g(APT, "ard", 45, [45], q=[
    "Go to where I can wash my dirty clothes.",
    "Could you take me to something that will clean a load of laundry?",
    "wash clothes",
    "My gym kit stinks and needs a proper wash, so take me to what does the laundry, not the sink.",
    "This is where I put dirty clothes to get them clean. It runs a wash cycle with water and detergent.",
    "i need to do a load of laundyr",
])
# ---------------------------------------------------------------- flats: o, or, od, ord, ard
g(FB, "o", 5, [5, 7, 26, 33, 34], label="lamp", q=[
    "Go to a lamp.",
    "Could you take me to one of the lights?",
    "any light",
    "It's getting dark and I want to switch on a light, any lamp in the flat.",
    "This is a light you switch on when the room is dim. Any of them is fine.",
    "go to a lmap",
])
g(FE, "or", 11, [11, 12, 13, 14, 15], label="chair", room="dining room", q=[
    "Go to a chair in the dining room.",
    "Could you take me to one of the dining room seats?",
    "dining room seat",
    "Guests are coming, so any seat in the dining room, not the little red one in the kids' room.",
    "This is a seat. It is in the dining room, and any of them will do.",
    "take me to a dinning room chair",
])
g(FG, "or", 34, [34, 35], label="lamp", room="bedroom", q=[
    "Go to a lamp in the bedroom.",
    "Could you take me to one of the bedside lights in the bedroom?",
    "bedroom light",
    "I want to read in bed, so a light in the bedroom, not the yellow bendy one in the kids' room.",
    "This is a small light. It is in the bedroom, and either one is fine.",
    "go to a bedroom lamp, doesn't matter which, it's too dakr",
])
g(FI, "or", 12, [12, 13], label="desk", room="studio", q=[
    "Go to a desk in the studio.",
    "Could you take me to one of the work tables in the studio?",
    "studio workstation",
    "I need to sit and draw, so a desk in the studio, not the reception counter.",
    "This is a work surface for drawing and computer work. It is in the studio, and either one is fine.",
    "go to a workspace in the stuido, any",
])
g(FI, "od", 23, [23], q=[
    "Go to the blue mug full of pencils.",
    "Could you find the cobalt cup that's being used as a pencil holder?",
    "blue pencil cup",
    "I need a pencil, so the blue mug stuffed with them, not the yellow one with cold tea.",
    "This is a deep blue ceramic cup. Pencils are standing in it.",
    "where's the blue mgu with all the pencils",
])
g(FB, "ord", 28, [28], q=[
    "Go to the green armchair in the study.",
    "Could you take me to the green reading chair in the study?",
    "study green reading chair",
    "I want to read in the quiet room, so the green chair in the study, not the yellow velvet one by the living room window.",
    "This is an upholstered green chair for reading. It stands in the study.",
    "the green armchiar in the study",
])
g(FE, "ord", 36, [36], q=[
    "Go to the red plastic chair in the kids' bedroom.",
    "Could you take me to the little red seat in the children's room?",
    "kids room red seat",
    "My son left his homework on the small red chair in his bedroom, not the black one in the dining room.",
    "This is a small red plastic seat. It sits at the homework desk in the children's bedroom.",
    "the litle red seat in the kids bedroom",
])
g(FG, "ord", 37, [37], q=[
    "Go to the laundry hamper in the bedroom.",
    "Could you take me to the wicker basket with a lid in the bedroom?",
    "bedroom wicker hamper",
    "I want to drop my dirty socks in the bedroom hamper, not the basket of clean clothes in the laundry room.",
    "This is a woven wicker container with a lid for dirty clothes. It is in the bedroom.",
    "the wicker hampr in the bedroom",
])
g(FI, "ord", 46, [46], q=[
    "Go to the lamp with the rattan shade in the bedroom.",
    "Could you take me to the bedside light with the woven shade in the bedroom?",
    "bedroom woven-shade light",
    "I like the patterned glow, so the bedroom lamp with the wicker-style shade, not the white ceramic one.",
    "This is a bedside light with a woven rattan shade. It stands on the white nightstand in the bedroom.",
    "the rattan lampp in the bedroom",
])
g(FG, "ard", 11, [11], q=[
    "Go to where I can iron my shirt.",
    "Could you take me to where I can press the creases out of my trousers?",
    "iron clothes",
    "My shirt is creased for tomorrow's interview and I need to get it smooth, not wash it.",
    "This is where I want to press my crumpled clothes. The iron should be there too.",
    "my shirt is wrinkled, need to iorn it",
])
g(FE, "ard", 15, [15], q=[
    "Go to where the baby sits to eat.",
    "Could you take me to where I can put the toddler for dinner?",
    "feed baby at table",
    "It's time to feed the little one, so take me to her seat with the tray, not a grown-up one.",
    "This is where the infant sits at mealtimes. It has a clip-on tray.",
    "the baby needs feding, where does she sit",
])
g(FI, "ard", 40, [40], q=[
    "Go to where I can play a vinyl record.",
    "Could you take me to where the turntable is so I can listen to some records?",
    "play vinyl",
    "I want to put on an old LP tonight, not stream something on the TV.",
    "This is where I want to spin some records. The record player is kept there.",
    "fancy listening to some vinly, where's the player",
])
# ---------------------------------------------------------------- spatial (s)
g(SO, "s", 15, [15], claims=[("between", 15, 14, 16, "x", [14, 15, 16])], q=[
    "Go to the middle one of the three bookshelves.",
    "Could you take me to the bookcase between the other two?",
    "middle bookcase",
    "The reference books are on the shelf unit in the middle, not the short white one on the end.",
    "This is a brown wooden bookcase against the back wall. It stands between the other two bookcases.",
    "the midle bookcase, between the other two",
])
g(SO, "s", 21, [21], claims=[("nearest", 21, 20, [21, 22])], q=[
    "Go to the trash can nearest the door.",
    "Could you take me to the bin closest to the door?",
    "bin by door",
    "I'm on my way out and want to throw this away, so the bin by the exit, not the one in the far corner.",
    "This is a black waste bin. It is the one nearest the door.",
    "the rubbish bin closest to the dor",
])
g(SK, "s", 25, [25], claims=[("on", 25, [1, 2, 3, 4, 5, 6], [23, 24, 25]), ("on", 23, [16], [23]),
                             ("on", 24, [16], [24])], q=[
    "Go to the cup on the counter.",
    "Could you take me to the mug sitting on the worktop?",
    "mug on worktop",
    "I want the cup standing on the counter, not either of the two on the table.",
    "This is a white mug. It sits on the counter top along the back wall, not on the table.",
    "the mug on the countr",
])
g(SK, "s", 8, [8], claims=[("above", 8, 10, [7, 8, 9])], q=[
    "Go to the wall cupboard above the sink.",
    "Could you take me to the overhead cabinet right over the sink?",
    "cupboard over sink",
    "The dish soap is kept up high over the sink, not in the cupboard under it.",
    "This is a white upper cupboard mounted on the wall. It is directly above the sink.",
    "the cupbaord above the sink",
])
g(SL, "s", 8, [8], claims=[("left", 8, 1, 14, [8, 9])], q=[
    "Go to the side table on your left when you sit on the sofa facing the TV.",
    "Could you take me to the end table on the left of the couch, as seen by someone sitting on it facing the television?",
    "left end table, sitting on sofa facing TV",
    "From the sofa looking at the TV, I put my tea on the little table to my left, not the right one.",
    "This is a small white table beside the sofa. Sitting on the sofa and facing the TV, it is on your left.",
    "sitting on the couch looking at the tv, the little tabel on my left",
])
g(SB, "s", 8, [8], claims=[("nearest", 8, 14, [8, 9]), ("nearest", 9, 15, [8, 9])], q=[
    "Go to the lamp nearest the window.",
    "Could you take me to the bedside light closer to the window?",
    "bedside light near window",
    "I want to read on the window side of the bed, so that light, not the one near the door.",
    "This is a white bedside light on a nightstand. Of the two, it is the one closer to the window.",
    "the bedside light closest to the windwo",
])
g(APT, "s", 12, [12], claims=[("higher", 12, [12, 13])], q=[
    "Go to the book sitting high up on the living room bookcase.",
    "Could you take me to the higher of the two volumes on the living room shelves?",
    "living room bookcase, upper volume",
    "I want the novel standing up high on the living room bookcase, not the one lying flat near the bottom.",
    "This is a hardcover on the tall shelf unit in the living room. It is the higher of the two there.",
    "the book up top on the living room bookcse",
])
g(APT, "s", 39, [39], claims=[("on", 39, [38], [8, 39, 55])], q=[
    "Go to the plant on top of the dresser.",
    "Could you take me to the little potted plant sitting on the chest of drawers?",
    "pot on chest of drawers",
    "I want to water the one on the dresser, not the ones standing on the floor.",
    "This is a small succulent in a pot. It rests on the chest of drawers in the bedroom.",
    "the succlent on the dresser",
])
g(FB, "s", 22, [22], claims=[("nearest", 22, 15, [20, 21, 22])], q=[
    "Go to the dining chair nearest the stove.",
    "Could you take me to the kitchen chair closest to the cooker?",
    "seat nearest cooker",
    "I want to sit close to the hob while the soup simmers, so the seat nearest it, not the ones further away.",
    "This is a seat at the round dining table. Of the three, it is the one closest to the cooker.",
    "the seat closest to the cookr",
])
g(FE, "s", 16, [16], claims=[("above", 16, 10, [4, 16, 26])], q=[
    "Go to the lamp hanging above the dining table.",
    "Could you take me to the light that hangs over the dining table?",
    "light over dining table",
    "The bulb over where we eat has gone, so that light, not the floor lamp by the sofa.",
    "This is a copper light. It hangs above the centre of the dining table.",
    "the lihgt hanging over the dining table",
])
g(FG, "s", 18, [18], claims=[("nearest", 18, 16, [18, 19])], q=[
    "Go to the chair nearest the fridge.",
    "Could you take me to the kitchen seat closest to the refrigerator?",
    "seat nearest fridge",
    "I want to sit by the fridge to sort the shopping, so that seat, not the one on the far side of the table.",
    "This is a seat at the round kitchen table. Of the two, it is the one nearer the fridge.",
    "the seat closest to the fidge",
])
g(FI, "s", 16, [16], claims=[("left", 16, (2.75, 8.4), (2.75, 10.0), [16, 17])], q=[
    "Go to the monitor on the left when you sit at the studio desks facing the wall.",
    "Could you take me to the left-hand screen, as seen by someone seated at the studio desks facing the north wall?",
    "left screen, studio desks, facing wall",
    "Sitting at the studio desks looking at the wall, I want the screen on the left, not the one on the right.",
    "This is a computer screen on a desk in the studio. Seen from the chairs facing the wall, it is the left one.",
    "the left screen in the studio when you sit facing the wal",
])

OUT = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round32.jsonl"


def rows():
    for n, grp in enumerate(G, 1):
        gid = f"b32-g{n:02d}"
        for k, text in enumerate(grp["q"], 1):
            yield {"id": f"{gid}-w{k}", "map": grp["map"], "query": text, "type": grp["type"],
                   "target": grp["target"], "accept": grp["accept"], "group": gid}


if __name__ == "__main__":
    with OUT.open("w", encoding="utf-8") as fh:
        for r in rows():
            fh.write(json.dumps(r, ensure_ascii=False) + "\n")
    print(f"wrote {OUT} ({len(G)} groups)")
