"""Round 5 blind suite (written by a blind helper from map data only)."""
import json
H = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OF = "../../../shared/data/iesm_maps/scene_office3_caption.json"
AP = "../../map_store/apartment.json"
SK, SB, SO, SL = "../maps/scan_kitchen.json", "../maps/scan_bedroom.json", "../maps/scan_office.json", "../maps/scan_livingroom.json"
FF = "maps/flat_f.json"

G = []  # (map, type, target, accept, [6 queries])
def g(m, t, target, accept, qs):
    assert len(qs) == 6, qs
    G.append((m, t, target, accept, qs))

# ---------------- HM3D house 00829 ----------------
g(H, "o", 219, [112, 157, 219, 229, 233], [
    "Go find a mirror.",
    "Can you take me to a mirror? I want to check my hair before I head out.",
    "looking glass, any one will do",
    "Where can I see my reflection around here? A wall mirror, whatever you've got.",
    "Navigate to a mirror frame please.",
    "I've got something in my eye - is there a mirorr anywhere in this house?",
])
g(H, "o", 162, [125, 160, 162, 164], [
    "Fetch me a towel.",
    "I just washed my hands and there's nothing to dry them on. Where are the towels kept?",
    "towels pls",
    "Could you head over to wherever there's a clean towel?",
    "Find a set of towels.",
    "Need something to dry off with - a bath towel or a hand towel, either is fine.",
])
g(H, "or", 263, [261, 263], [
    "Go to the armchair in the bedroom.",
    "Is there a comfy armchair in the bedroom? Take me there.",
    "bedroom easy chair",
    "I'd like to read in the bedroom for a bit, so make your way to one of the armchairs in there.",
    "Could you please navigate to an easy chair in the bed room?",
    "The bedroom has a couple of armchairs, right? Head to either one.",
])
g(H, "or", 33, [14, 33], [
    "Go to the curtains in the living room.",
    "Could you walk over to the drapes in the lounge?",
    "living room curtain",
    "It's far too bright in the sitting room. Head over to the window drapes in there so we can draw them.",
    "where are the living-room drapes",
    "Swing by the curtians in the living room, would you?",
])
g(H, "od", 56, [56], [
    "Take me to the door with the peephole.",
    "Which door has the little spy hole and the gold doorknob? Go there.",
    "door w/ peephole + gold knob",
    "Walk up to the dark wooden door that has a gold-coloured knob and a peephole.",
    "Head over to the doorway that's got the peep hole in it.",
    "I think someone's outside. Bring me to the door I can look through before opening.",
])
g(H, "od", 164, [164], [
    "Get me the towels with the H embroidered on them.",
    "Which set of towels has the monogram on it? The one with an 'H'. Go there.",
    "the H towels",
    "Make your way to the white towels folded on the towel rack, the ones with the embroidered letter H.",
    "I want the monogrammed towels, not the plain ones.",
    "Could you find the towles that have an H stitched on?",
])
g(H, "ord", 181, [181], [
    "Go to the armless brown leather seat in the bedroom.",
    "In the bedroom there's a leather seat with no armrests - take me to it, not one of the armchairs.",
    "bedroom: armless brown chair",
    "Could you navigate to the seat with the curved back in the bedroom? The one without arms.",
    "Stop by the bedroom and find the brown leather chair that has no arms.",
    "I left my phone charging on that armless leather seat in the bedroom, bring me there.",
])
g(H, "ord", 110, [110], [
    "Go to the little honey-coloured table in the bathroom.",
    "There's a small wooden side table with an X-shaped metal base in the bathroom. Head over there.",
    "bathroom small table, light honey wood",
    "Could you find the small table in the bathroom - the warm golden wood one with crossed metal legs?",
    "Take me to the stand in the bathroom with the X-shaped legs, the honey-toned one.",
    "walk up to the honey colored end table in the bathrom",
])
g(H, "ard", 78, [78, 6], [
    "Take me to the thing we watch films on in the living room.",
    "I want to catch the news - go to whatever we watch it on in the lounge.",
    "living room, whatever you watch shows on",
    "Where do we watch telly in the sitting room? Navigate there.",
    "Head to the flat black thing on the living room wall so I can put the match on.",
    "Could you go to whatever in the livingroom shows programmes and films?",
])
g(H, "ard", 192, [192], [
    "Go to where the pet sleeps.",
    "Where does our pet curl up for a nap? The white and brown cushiony thing. Take me there.",
    "the pet's sleeping spot, white and brown",
    "Can you head to the pet's spot in the bathroom, the soft white-and-brown one?",
    "Swing by wherever our furry friend naps - I think it's in the bathroom.",
    "I need to wash the pet's bedding. Find the soft thing it sleeps on.",
])
# ---------------- HM3D office3 ----------------
g(OF, "o", 13, [8, 13, 20, 40], [
    "Bring me to a cushion.",
    "Can you find a throw pillow for me?",
    "cushion",
    "My back hurts on this seat - go find something soft to put behind me, like a sofa cushion.",
    "Where are the cushions in here?",
    "Navigate to any pillow you can find.",
])
g(OF, "or", 55, [7, 55, 64], [
    "Go to a workstation in the rec room.",
    "Is there a desk in the recreation room? Take me to one.",
    "rec room workstation",
    "I need somewhere to set my laptop down and type in the rec room - head to one of the desks there.",
    "Could you stop by one of the work stations in the rec room?",
    "rec room... any workstation is ok, i just need to plug my laptop in",
])
g(OF, "od", 7, [7], [
    "Take me to the white desk.",
    "Which of the workstations is white? Go to that one.",
    "white workstation, not the brown wooden ones",
    "Head over to the white wooden desk with the USB port.",
    "I'm looking for the pale one among the workstations - the white one.",
    "Go to the workstaton that's white, not wood-coloured.",
])
g(OF, "od", 10, [10], [
    "Go to the window that has the clock above it.",
    "Take me to the red glass pane with the white blind.",
    "windowpane under the wall clock",
    "Could you head over to the red-tinted glazing with a blind - the one the clock hangs over?",
    "Navigate to the window with a white blind, the red one below the clock.",
    "Which of the red panes has the clock mounted above it? Walk up to that one.",
])
g(OF, "ord", 40, [40], [
    "Go to the orange cushion with white and yellow stripes in the rec room.",
    "In the rec room there are two orange pillows - I want the striped one.",
    "striped orange cushion, rec room",
    "Could you find the stripy orange throw cushion in the games room? Not the one with the button.",
    "Head to the rec room and look for the orange cushion that has stripes on it (white and yellow).",
    "bring me to the orange strped pillow in the rec room",
])
g(OF, "ard", 67, [67], [
    "Go to the thing I change the channel with in the rec room.",
    "I want to turn the volume down from the sofa - find the black and white handheld gadget that does that, in the rec room.",
    "rec room: the handheld thing for switching channels",
    "Could you locate the little black-and-white device you point at the screen to change channels?",
    "Head over to the gadget that switches programs, it's somewhere in the rec room.",
    "Nobody can find the thing to flick between chanels in the rec room. Go look for it.",
])
# ---------------- apartment ----------------
g(AP, "o", 55, [8, 39, 55], [
    "Go to a plant.",
    "Find me some greenery - any potted houseplant.",
    "houseplant",
    "Head over to some potted greenery so I can check whether it needs water.",
    "Where's a plant I could water?",
    "take me to a houseplnat, any of them is fine",
])
g(AP, "or", 24, [23, 24], [
    "Go to a chair in the kitchen.",
    "Can you find me somewhere to sit in the kitchen? One of the dining seats.",
    "kitchen seat",
    "I want to have breakfast - head to one of the seats at the kitchen table.",
    "Make your way to a kitchen chair, either one.",
    "Which seats are there in the kitchen? Go to one of them.",
])
g(AP, "or", 34, [34], [
    "Go to the lamp in the bedroom.",
    "Take me to the bedroom light, the one you switch on to read.",
    "bedroom light",
    "It's dark in the bedroom; make your way over to the reading light in there.",
    "Could you navigate to the bedroom lamp?",
    "Where's the little light in the bedrom?",
])
g(AP, "od", 2, [2], [
    "Go to the brown leather sofa.",
    "Take me to the small leather couch, not the big gray one.",
    "loveseat, brown leather",
    "Could you walk up to the two-seater settee that's brown?",
    "Head to the couch that's leather - the worn brown one.",
    "I'd rather sit on the brown sofa than the grey fabric one; go there.",
])
g(AP, "ord", 12, [12], [
    "Go to the red book in the living room.",
    "In the lounge, find the red hardback novel on the shelf.",
    "living room red novel",
    "Could you fetch me the red hardcover from the sitting-room bookcase? Not the yellow one.",
    "Head into the living room and get the novel with the red cover.",
    "bring me to that red book in the livingroom",
])
g(AP, "ord", 53, [53], [
    "Go to the gray filing cabinet in the office.",
    "In the study there's a metal filing cabinet with two drawers - take me to it.",
    "office filing drawers, grey metal",
    "Navigate to the grey metal drawer unit in the office where the paperwork goes.",
    "Head to the office and find the two-drawer metal file chest under the printer.",
    "Could you please go to the office's grey paperwork drawers, the metal ones?",
])
g(AP, "ard", 16, [16], [
    "Go to the thing that keeps the food cold in the kitchen.",
    "I need the milk - take me to where it's kept chilled.",
    "kitchen: the cold food storage",
    "Head over to the tall stainless steel appliance with the water dispenser.",
    "Where can I get chilled water from the door dispenser in the kitchen? Go there.",
    "Could you swing by whatever we keep leftovers in so they don't go off, in the kitchen?",
])
g(AP, "ard", 29, [29], [
    "Go to where I hang my coat by the front door.",
    "Take me to the wooden thing in the hallway with the umbrella hanging on it.",
    "hallway - where jackets get hung",
    "I need my rain jacket; head to whatever it's hanging on in the hall.",
    "Could you make your way to the place in the hallway for hanging coats?",
    "Stop by the wooden stand near the front door that the jackets go on.",
])
g(AP, "s", 39, [39], [
    "Go to the plant on top of the dresser.",
    "Take me to the little pot sitting on the chest of drawers.",
    "succulent on the dresser",
    "Find the potted plant that's on the chest of drawers in the bedroom.",
    "Whatever's growing on top of the dresser - walk over to it.",
    "Could you head to the small green thing in a terracotta pot, the one on the drawers?",
])
g(AP, "s", 48, [48], [
    "Go to the chair at the desk.",
    "Take me to the seat pulled up to the desk.",
    "desk chair",
    "Make your way over to whatever I sit on when I'm working at the desk.",
    "Navigate to the seat in front of the desk, pleaes.",
    "Where's the seat by the desk with the monitor on it?",
])
# ---------------- scan_kitchen ----------------
g(SK, "o", 23, [23, 24, 25], [
    "Get me a cup.",
    "Is there a mug anywhere? Go to it.",
    "mug",
    "I'd like a coffee - head over to any mug you can see.",
    "Find a cup, doesn't matter which.",
    "Could you make your way to a drinking mug?",
])
g(SK, "od", 4, [4], [
    "Go to the grey cupboard.",
    "Which of the kitchen cabinets is gray? Take me to that one.",
    "gray cupboard, the odd one out among the white ones",
    "Head over to the one cupboard that isn't white - the grey one.",
    "navigate to the gray base cupbaord",
    "I want the kitchen cabinet that's grey, not white.",
])
g(SK, "ard", 12, [12], [
    "Go to the thing that brews coffee.",
    "I need my morning coffee - take me to whatever makes it.",
    "the black machine that makes coffee",
    "Head over to the appliance I use to brew a pot of joe.",
    "Where's the gadget that makes coffee? It's black, on the counter.",
    "Could you find the black machine for making coffe?",
])
g(SK, "s", 21, [21], [
    "Go to the chair closest to the door.",
    "Take me to the seat nearest the doorway.",
    "chair nearest the door",
    "Which seat at the table is closest to the way out? Walk up to it.",
    "Head to whichever seat is nearest to the kitchen door.",
    "Make your way to the seat at the end of the table by the door.",
])
# ---------------- scan_livingroom ----------------
g(SL, "od", 12, [12], [
    "Go to the black lamp.",
    "Take me to the tall black floor light, not the white ones.",
    "black floor light",
    "Could you head over to the standing light that's black?",
    "Walk up to the only dark-coloured lamp in here.",
    "The white lights are the small table ones; I want the black standing one.",
])
g(SL, "s", 5, [5], [
    "Go to the armchair next to the bookshelf.",
    "Take me to the easy chair by the bookcase.",
    "armchair beside bookcase",
    "Which comfy chair is nearer to the bookshelves? Head there.",
    "Make your way to the lounge chair closest to the bookcase.",
    "I want to read; go to the chair near where the books are kept.",
])
# ---------------- scan_office ----------------
g(SO, "or", 22, [21, 22], [
    "Go to a trash can in the office.",
    "Where's a bin in the office? Take me to one.",
    "office wastebasket",
    "I've got rubbish to throw away - head to one of the office bins.",
    "Find a garbage can in this office.",
    "could you stop by a waste paper bin in the ofice",
])
g(SO, "ord", 16, [16], [
    "Go to the white bookshelf in the office.",
    "In the office, find the short white bookcase - not the brown wooden ones.",
    "office white bookcase",
    "Head to the low white shelving unit in the office.",
    "Could you navigate to the office bookcase that's white?",
    "The white bookshelf in the offce please",
])
g(SO, "ard", 25, [25], [
    "Go to the machine that prints documents in the office.",
    "I need to pick up my printout - take me to where it comes out.",
    "the white thing that prints",
    "Head over to the white device on the cabinet that spits out pages.",
    "Where do I colect my printed pages in the office? Go there.",
    "Could you find the office gadget for making paper copies of files?",
])
g(SO, "s", 10, [10], [
    "Go to the office chair closest to the door.",
    "Take me to the seat nearest the door.",
    "chair nearest the exit",
    "Which desk chair is closest to the door? Walk up to that one.",
    "Make your way to the work chair nearest the door.",
    "Head to whichever seat is the shortest walk from the door.",
])
# ---------------- scan_bedroom ----------------
g(SB, "o", 4, [2, 3, 4, 5], [
    "Go to a pillow.",
    "Find me a cushion.",
    "pillow",
    "Can you head to any of the cushions on the bed?",
    "I need a cushion to prop up my neck - go find one.",
    "Where are the cushoins? Take me to one of them.",
])
g(SB, "s", 8, [8], [
    "Go to the lamp next to the clock.",
    "Take me to the bedside light beside the alarm clock.",
    "light by the clock",
    "Which of the two bedside lights has the clock next to it? Head there.",
    "Walk up to the lamp that's right by the clock on the nightstand.",
    "Find the reading light near the little black clock.",
])
# ---------------- flat_f (holiday cottage) ----------------
g(FF, "o", 40, [6, 30, 40], [
    "Go to a lamp.",
    "Take me to a light I can switch on.",
    "reading light",
    "It's getting dark - find me one of the lights, any will do.",
    "Where's a lamp in this cottage?",
    "Could you head to a light, floor or table, doesn't matter.",
])
g(FF, "o", 23, [8, 23], [
    "Go to a plant.",
    "Find me a houseplant or a potted plant.",
    "potted greenery",
    "I want to water something - head over to any of the pots with greenery in them.",
    "Where's some greenery?",
    "Take me to a houseplnt.",
])
g(FF, "or", 14, [12, 13, 14, 15], [
    "Go to a chair in the kitchen.",
    "Take me to one of the kitchen seats.",
    "kitchen seat",
    "I want to sit at the farmhouse table - head to one of the seats around it.",
    "Find a kitchen chair for me.",
    "Could you make your way to a dining seat in the kitchen?",
])
g(FF, "or", 32, [32], [
    "Go to the rug in the bedroom.",
    "Take me to the bedroom mat.",
    "bedroom rug",
    "Head to the floor coverring in the bedroom.",
    "Where's the mat on the bedroom floor? Go there.",
    "Could you navigate to the bedroom's rag mat?",
])
g(FF, "od", 2, [2], [
    "Go to the tartan armchair.",
    "Take me to the red plaid wingback.",
    "red tartan chair",
    "I'd like the red woollen easy chair, not the cream leather one.",
    "Walk up to the wingback chair in red tartan.",
    "Find the red armchair please.",
])
g(FF, "ord", 37, [37], [
    "Go to the mirrored cabinet in the bathroom.",
    "In the bathroom, take me to the white medicine cabinet above the basin.",
    "bathroom mirror cupboard, white",
    "Could you head to the wall cupboard with the mirror door over the washbasin in the bathroom?",
    "Make your way to the white bathroom wall unit with the mirror on the front.",
    "Where's the white mirrored medicine cupbord in the bathroom?",
])
g(FF, "ord", 40, [40], [
    "Go to the green lamp in the study.",
    "Take me to the banker's light with the green glass shade in the study.",
    "study desk light, green shade",
    "Head to the study and find the brass reading light with the green shade.",
    "Could you navigate to the green-shaded lamp on the desk in the study?",
    "In the study there's an old-fashioned green desk light - go there.",
])
g(FF, "ard", 25, [25], [
    "Go to the thing I use to look at the stars on the porch.",
    "Take me to the black thing on a tripod out on the veranda.",
    "porch stargazing gadget",
    "I want to see the moon up close tonight - head to whatever we use for that out on the porch.",
    "Could you find the device for stargazing, the black one on the tripod?",
    "Swing by the porch thing you peer at the night sky thru.",
])
g(FF, "s", 30, [30], [
    "Go to the lamp on the nightstand.",
    "Take me to the light on the bedside table.",
    "lamp on bedside table",
    "Head over to the light sitting on top of the little table by the bed.",
    "Which light is on the night table? Walk up to it.",
    "Find the light next to the bed, the one on the bedside table.",
])
g(FF, "s", 15, [15], [
    "Go to the chair closest to the fridge.",
    "Take me to the seat nearest the refrigerator.",
    "seat closest to fridge",
    "Which of the kitchen seats is nearest the fridge? Walk up to it.",
    "Make your way to the chair next to the fridge, at the table.",
    "Head to whichever dining seat is the shortest walk from the fridge.",
])

out = open("/work/main/evals/blind/round5_dev.jsonl", "w")
for gi, (m, t, target, accept, qs) in enumerate(G, 1):
    for wi, q in enumerate(qs, 1):
        out.write(json.dumps({"id": f"b5-g{gi:02d}-w{wi}", "map": m, "query": q, "type": t,
                              "target": target, "accept": accept, "group": f"b5-g{gi:02d}"}) + "\n")
out.close()
print(len(G), "groups")
