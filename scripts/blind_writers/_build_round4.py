"""Round-4 blind suite, written by a blind helper from map data only (see round4_NOTES.md)."""
import json, os
H = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OF = "../../../shared/data/iesm_maps/scene_office3_caption.json"
AP = "../../map_store/apartment.json"
SK, SB, SO, SL = ("../maps/scan_kitchen.json", "../maps/scan_bedroom.json",
                  "../maps/scan_office.json", "../maps/scan_livingroom.json")
FE = "maps/flat_e.json"

G = []  # (group, type, map, target, accept, [6 queries])
def g(n, t, m, target, accept, qs):
    assert len(qs) == 6, n
    G.append((n, t, m, target, accept, qs))

# ---------------- HM3D house 00829 ----------------
g(1, "o", H, 219, [112, 157, 219, 229, 233], [
    "Walk me over to a mirror.",
    "where's the nearest looking glass in this house?",
    "I want to check my hair before I leave. Can you find me a mirror, please?",
    "looking glass",
    "Swing by one of the mirrors on your way, any of them will do.",
    "could u take me to a mirorr",
])
g(2, "o", H, 78, [78, 234, 6], [
    "Take me to the TV.",
    "Where is the television?",
    "find the telly",
    "The match starts in five minutes, navigate to the flat-screen.",
    "Could you go and wait by the television set, please?",
    "I'd like to watch something. Make your way to the tv, would you?",
])
g(3, "or", H, 263, [261, 263], [
    "Bring me to the armchair in the bedroom.",
    "Is there an easy chair in the bedroom? Take me to it.",
    "bedroom lounge chair",
    "I fancy reading somewhere comfy. The upholstered armchair in the bedroom, please.",
    "Head into the bedroom and stop at one of the armchairs.",
    "Where's the easy chair in the bedrom?",
])
g(4, "or", H, 14, [14, 33], [
    "Curtains in the living room: go there.",
    "Find the drapes in the lounge.",
    "living room curtain",
    "It's too bright in the sitting room. Could you head over to the curtains there?",
    "Where are the living-room drapes?",
    "Make your way to the lounge and stop at the window drapery.",
])
g(5, "od", H, 211, [211], [
    "Bring me to the blue bowl.",
    "Find the deep blue ceramic bowl with the gold pattern.",
    "Where's the decorative bowl — the blue one, not the white one with the sweets?",
    "blue and gold bowl",
    "Swing by the ornamental bowl that's navy with gold detailing.",
    "Can you locate the glossy blue dish with the gold patterns on it?",
])
g(6, "od", H, 157, [157], [
    "Take me to the gold mirror.",
    "Which looking glass has gold on its frame? Go there.",
    "the gilded mirror",
    "Find the ornate mirror with a gold frame, not one of the plain dark-wood ones.",
    "Head over to the looking glass with the golden frame please.",
    "navigate to the gold-framed mirorr",
])
g(7, "ord", H, 42, [42], [
    "Bring me to the dark leather-bound book in the living room.",
    "In the lounge there's a book with a dark leather cover. Find it for me.",
    "living room, dark leather volume",
    "Stop by the sitting room and go to the dark volume with the gold embossing on the cover.",
    "Could you find that old leather-bound thing I was reading in the living room? Dark cover, gold embossed.",
    "Where's the dark leather hardback in the livingroom?",
])
g(8, "ord", H, 110, [110], [
    "I'm after the small honey-coloured table in the bathroom; bring me to it.",
    "In the bathroom there's a little wooden side table with an X-shaped metal base. Take me there.",
    "bathroom, small honey wood stand",
    "Could you navigate to the little honey-colored wooden stand in the bathroom?",
    "Find the small table with the crossed metal legs in the washroom.",
    "Where's the warm-toned wooden side table in the bathrom?",
])
g(9, "ard", H, 265, [265], [
    "I need the black leather thing I carry my work papers in. It's in the bedroom somewhere.",
    "Take me to the black leather case I take to the office every morning; it should be in the bedroom.",
    "bedroom — the lockable black leather carrier for documents",
    "Head to the bedroom and find what I carry my contracts around in, the black leather one with the metal lock.",
    "Where did I put the thing I haul my files to work in? Black leather, bedroom.",
    "Stop by the bedroom and go to my black leather document carrier, the one with the lock.",
])
# ---------------- HM3D office3 ----------------
g(10, "o", OF, 55, [7, 55, 64], [
    "Desk, please. Any one.",
    "find me a workstation",
    "Is there a writing table in here? Head to it.",
    "Navigate to the nearest work desk please.",
    "I need a proper surface to work at for an hour. Take me to one of the workstations.",
    "Stop at one of the work stations, any of them is fine.",
])
g(11, "o", OF, 3, [3], [
    "Take me to the couch.",
    "Where's the sofa?",
    "go to settee",
    "Could you make your way over to the couch please? I need a break.",
    "find the lounge sofa",
    "Walk up to the couch in here, would you.",
])
g(12, "or", OF, 13, [8, 13, 20, 40], [
    "Pillow in the rec room, please, any of them.",
    "Find a cushion in the break room.",
    "recreation room cushion",
    "Can you head to the lounge area and find me one of the throw cushions?",
    "Where are the cushions in the games room?",
    "My back hurts and I want something soft to lean on. Bring me to a pillow in the rec room.",
])
g(13, "od", OF, 40, [40], [
    "Take me to the orange cushion with white and yellow stripes.",
    "the striped orange pillow",
    "Find the orange pillow — not the plain one, the one with stripes.",
    "Where's the stripy orange cushion?",
    "Navigate to the cushion that's orange with white and yellow stripes running across it.",
    "go to the orange stripped cushion",
])
g(14, "ord", OF, 42, [42], [
    "Come round to the brown chair in the rec room.",
    "In the recreation room there's one brown seat among all the black and blue ones. Take me there.",
    "rec room brown leather seat",
    "Could you find the brown armless seat in the lounge area?",
    "Walk over to the brown seat in the rec room, not a black mesh one.",
    "Where is the brwon chair in the rec room?",
])
g(15, "ard", OF, 67, [67], [
    "Take me to the handheld gadget you point at things to switch them on from across the room.",
    "I want to operate stuff from the sofa without getting up. Find what I'd use for that in the rec room.",
    "the black-and-white plastic handheld for operating devices from a distance",
    "Where's the little thing with buttons I use to control the equipment wirelessly in the rec room?",
    "Go to the small handset that lets me change channels from afar.",
    "find teh thing for changing channels",
])
# ---------------- apartment ----------------
g(16, "o", AP, 55, [8, 39, 55], [
    "Stop by a plant for me.",
    "Where are the houseplants?",
    "Take me to some greenery.",
    "The leafy things in pots need watering. Find one of them.",
    "swing by any of the potted greens pls",
    "Could you navigate to something growing in a pot? Doesnt matter which one.",
])
g(17, "or", AP, 23, [23, 24], [
    "Is there a chair in the kitchen? Go to it.",
    "Find me a seat in the kitchen.",
    "kitchen chair",
    "Can you pop into the kitchen and stop at one of the dining seats?",
    "I'd like to sit down at the kitchen table — bring me to one of the seats there.",
    "Make your way to a seat in the kitchen, whichever one.",
])
g(18, "or", AP, 12, [12, 13], [
    "Take me to a book in the living room.",
    "Where are the books in the lounge? Go to one.",
    "sitting room — any volume will do",
    "Is there a volume lying about in the front room? Head there.",
    "Walk me to one of the tomes in the living room, whichever.",
    "Stop by the living room shelves and pick out any hardback or album for me.",
])
g(19, "od", AP, 2, [2], [
    "Bring me to the brown leather sofa.",
    "the loveseat, please",
    "Not the big gray couch, the small leather one. Go there.",
    "Find the two-seater in brown leather.",
    "Where's the little worn brown settee?",
    "Could you navigate to the smaller of the two sofas, the leather one?",
])
g(20, "ord", AP, 12, [12], [
    "Red book, living room. Go.",
    "In the lounge, find the red hardcover up on the shelf.",
    "living room red novel",
    "Take me to the red volume in the sitting room, not the yellow photo album.",
    "Could you locate that red hardback in the living room for me?",
    "wheres the red book in the livng room",
])
g(21, "ord", AP, 42, [42], [
    "Walk over to the gray cabinet in the bathroom.",
    "The bathroom vanity unit, the grey wooden one under the basin. Take me there.",
    "bathroom gray cupboard",
    "I need a fresh towel. They're kept in the grey wooden cupboard under the bathroom sink, so go there.",
    "Head to the bathroom and stop at the gray vanity.",
    "Where's the grey storage cabinet in the bathroom?",
])
g(22, "ard", AP, 20, [20], [
    "I want to reheat my leftovers quickly. Which thing in the kitchen does that? Go to it.",
    "Take me to the small white box on the kitchen counter that heats food up.",
    "where do I zap my soup for two minutes?",
    "Bring me to the compact white appliance on the counter that warms things up in a minute or two.",
    "Pop into the kitchen and stop by whatever I'd use to heat a cold coffee fast. The white one, not the stove.",
    "navigate to the thing that nukes food, its white and sits on the counter",
])
g(23, "ard", AP, 29, [29], [
    "Where do I hang my coat? Take me there.",
    "Could you go to the thing by the front door that jackets and umbrellas hang on?",
    "I'm heading out and need my rain jacket. Bring me to where it's hanging in the hallway.",
    "the wooden stand in the hall for hanging outdoor wear",
    "Stop by the spot in the hallway where we put our coats.",
    "Navigate to the thing in the hall you hang coats on, the wodden one.",
])
g(24, "s", AP, 34, [34], [
    "Go to the lamp next to the bed.",
    "Bring me to the light beside the bed.",
    "the lamp right by the bed",
    "I want to read in bed. Find the light that sits beside it.",
    "Head over to whichever light is closest to the bed.",
    "Could you go to the light next to where I sleep?",
])
# ---------------- scan maps ----------------
g(25, "o", SO, 15, [14, 15, 16], [
    "Walk up to a bookshelf.",
    "Where are the bookcases?",
    "Find the shelving unit for books.",
    "Navigate to one of the bookcases, any is fine.",
    "I need to put this binder back, so take me to a bookcase.",
    "book shelf pls",
])
g(26, "or", SB, 6, [6, 7], [
    "Go to the nightstand in the bedroom.",
    "Bring me to a bedside table in the bedroom.",
    "bedroom night table",
    "Can you find one of the bedside cabinets in the bedroom for me?",
    "Head into the bedroom and stop at either nightstand.",
    "Where's the bedside table in the bedrom?",
])
g(27, "od", SK, 4, [4], [
    "Go to the gray kitchen cabinet.",
    "The grey cupboard, the only one that isn't white. Take me there.",
    "grey cupboard",
    "Among all those white units there's one gray base cupboard. Find it.",
    "Which cupboard is gray? Navigate to it.",
    "Where's the odd-coloured cupbaord — the gray one?",
])
g(28, "od", SL, 5, [5], [
    "Swing by the green armchair.",
    "Take me to the green easy chair, not the leather one.",
    "green chair",
    "Find the green seat.",
    "Can you head over to the armchair that's green?",
    "the grean lounge chair please",
])
g(29, "ord", SO, 1, [1], [
    "White table in the office, go there.",
    "Take me to the white desk in the office, not the wooden one.",
    "office white table",
    "In the office, could you find the white work surface? The other one is wooden.",
    "Head to the office and stop at the white one of the two big desks.",
    "Navigate to the white desk in teh office.",
])
g(30, "ard", SK, 12, [12], [
    "I need my morning caffeine fix. Take me to whatever brews it.",
    "Go to the black appliance on the counter I use to brew a cup of joe.",
    "where do I make a fresh pot in here?",
    "Find the black gadget on the worktop that brews coffee.",
    "Could you head over to the thing that makes my coffee? The black one on the counter.",
    "Navigate to what brews the coffe",
])
g(31, "ard", SO, 17, [17], [
    "Take me to where I can write with markers on the wall.",
    "I need to sketch a diagram for the team. Go to the thing we draw on.",
    "the wall-mounted board you write on with dry-erase pens",
    "Where can I jot down ideas with a marker so everyone can see?",
    "Head over to the white writing surface on the west wall.",
    "Brainstorm in ten minutes. Go to the thing we scribble on with erasable pens.",
])
g(32, "s", SK, 6, [6], [
    "Go to the cabinet under the microwave.",
    "Take me to the cupboard directly below the microwave.",
    "the base unit beneath the microwave",
    "Find the cupboard the microwave is sitting on.",
    "Which cupboard has the microwave on top? Go there.",
    "I need the cupboard right underneath the microwave oven. Make your way there.",
])
g(33, "s", SB, 7, [7], [
    "Go to the nightstand with the book on it.",
    "Bring me to the bedside table where the book is lying.",
    "nightstand that has a book on top",
    "Find the bedside table holding the book.",
    "Head over to the night table with a book sitting on it, not the one with the clock.",
    "Which bedside cabinet has my book on it? Go there.",
])
g(34, "s", SL, 12, [12], [
    "Go to the lamp by the door.",
    "Take me to the light next to the door.",
    "the floor light near the doorway",
    "Of all the lamps, which one's closest to the door? Go there.",
    "Head over to the standing light beside the entrance.",
    "Could you walk up to whichever light's nearest the door?",
])
g(35, "s", SO, 21, [21], [
    "Go to the trash can by the door.",
    "Bring me to the bin next to the door.",
    "wastebasket near the exit",
    "I've got rubbish to throw out. Find the bin closest to the door.",
    "Head to the garbage can right beside the doorway, not the one in the far corner.",
    "where's the trash can near the door",
])
# ---------------- flat_e (own map) ----------------
g(36, "o", FE, 26, [4, 16, 26], [
    "Go to a lamp.",
    "Take me to a light, any of them.",
    "Where's the nearest lamp?",
    "It's getting dark. Find one of the lights in the house, doesn't matter which.",
    "Could you swing by a light fitting for me?",
    "head to a lightt",
])
g(37, "o", FE, 24, [24, 34], [
    "Take me to a bed.",
    "Where's a bed? I need a lie-down.",
    "Find me a mattress to lie on.",
    "Go to any of the sleeping places, bunk or double, doesn't matter.",
    "Navigate to a bunk or a double, whichever's closer.",
    "Make your way to the nearest matress for me.",
])
g(38, "or", FE, 11, [11, 12, 13, 14, 15], [
    "Come round to a chair in the dining room.",
    "Take me to one of the dining-room seats.",
    "dining room seat",
    "Find me a seat at the dining table.",
    "Head over to the dining area and stop by any of the seats.",
    "Can u go to one of the dinning room chairs",
])
g(39, "or", FE, 30, [30], [
    "Go to the sink in the bathroom.",
    "Bring me to the washbasin in the bathroom.",
    "bathroom basin",
    "Find the hand basin in the loo.",
    "Could you head to the bathroom and stop at the wash basin?",
    "Where is the bathroom sink?",
])
g(40, "od", FE, 28, [28], [
    "Go to the rattan chair.",
    "The wicker armchair: take me to it.",
    "the woven cane seat",
    "Find the chair made of rattan, the natural-coloured one.",
    "Where's the wicker seat with the cream cushion?",
    "navigate to the ratan seat",
])
g(41, "od", FE, 7, [7], [
    "Go to the round mirror.",
    "Take me to the circular looking glass with the gold frame.",
    "gold round mirror",
    "Find the circular one on the wall with the thin gold rim, the looking glass, not the rectangular one in the bathroom.",
    "Make your way to the circular looking-glass, please.",
    "Where's that round gold-framed mirorr?",
])
g(42, "ord", FE, 15, [15], [
    "Go to the white plastic chair in the dining room.",
    "I need to feed the baby. Take me to the highchair in the dining room.",
    "dining room white highchair",
    "Find the little white plastic seat with a tray in the dining room.",
    "Could you stop at the white feeding seat in the dining room?",
    "Where's the white baby seat in the dinning room?",
])
g(43, "ord", FE, 17, [17], [
    "Make your way to the dark wooden shelf in the dining room.",
    "Take me to the walnut wall shelf with the plates on it, in the dining room.",
    "dining room walnut ledge with plates",
    "In the dining room there's a dark wood display ledge. Find it.",
    "Head over to the dining room and find the wall-mounted rack where the plates are displayed, the dark wood one, not the white unit in the lounge.",
    "Where's the dark brown plate rack on the dining room wall?",
])
g(44, "ard", FE, 33, [33], [
    "The laundry's washed. Take me to the machine that dries it.",
    "In the utility room, go to the appliance that dries clothes, not the one that washes them.",
    "where do the wet clothes go to dry",
    "Find the machine next to the washer that gets the clothes dry.",
    "Head to the utility room and stop at whatever tumbles the laundry dry.",
    "Navigate to the clothes-drying machine in the laundry room.",
])
g(45, "ard", FE, 9, [9], [
    "I want to change the channel. Find the thing for that.",
    "Go to the little black handheld for the telly, on the coffee table.",
    "the gadget I use to switch the TV over",
    "Where's the thing that turns the television on and off from the sofa?",
    "Head to the living room and find what I use to flick through channels.",
    "take me to the thingy for the tv chanels",
])
g(46, "s", FE, 16, [16], [
    "Bring me to the lamp above the dining table.",
    "Take me to the light hanging over the dining table.",
    "the light fixture over the table where we eat",
    "The lamp that hangs directly above the dining table, find it please.",
    "Head to the dining room and stand under the light that's suspended over the table.",
    "Which light is right over the dining table? Navigate there.",
])
g(47, "s", FE, 36, [36], [
    "Walk up to the chair at the desk.",
    "Take me to the seat pulled up to the desk.",
    "the chair in front of the desk",
    "Find whichever seat is next to the desk.",
    "Head over to the little seat tucked in at the desk.",
    "Where's the seat closest to the desk?",
])
g(48, "s", FE, 4, [4], [
    "Go to the lamp next to the sofa.",
    "Take me to the light beside the couch.",
    "the standing light at the end of the settee",
    "Find the lamp closest to the sofa.",
    "Swing by whatever light is right by the couch.",
    "Walk up to the floor light next to the sofa.",
])

out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "round4.jsonl")
with open(out, "w") as f:
    for n, t, m, target, accept, qs in G:
        for i, q in enumerate(qs, 1):
            f.write(json.dumps({"id": f"b4-g{n:02d}-w{i}", "map": m, "query": q, "type": t,
                                "target": target, "accept": accept, "group": f"b4-g{n:02d}"}) + "\n")
print(len(G), "groups written to", out)
