import json
H1 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
H2 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
AP = "../../map_store/apartment.json"
SK = "../maps/scan_kitchen.json"; SB = "../maps/scan_bedroom.json"
SO = "../maps/scan_office.json"; SL = "../maps/scan_livingroom.json"
FD = "maps/flat_d.json"
G = []  # (type, map, target, accept, [6 queries])
def g(t, m, target, accept, qs):
    assert len(qs) == 6, qs
    G.append((t, m, target, accept, qs))

# ---------------- o : category only ----------------
g("o", H1, 153, [153], [
 "Go find the rucksack.",
 "where's my knapsak?",
 "Could you head over to wherever the school bag is lying around?",
 "backpack",
 "I need my daypack before I leave - can you take me to it?",
 "Navigate to the bag you wear on your back, the one with shoulder straps."])
g("o", H1, 42, [42, 197, 212, 259], [
 "Find me a book, any book.",
 "I fancy a read. Go to any volume lying around, whichever is easiest.",
 "Where can I find something to read in this house? A book, I mean.",
 "Take me to a volume of some kind - I'm not picky.",
 "bring me to something bound with pages that I can read",
 "Swing by a novel or any other bok please, doesn't matter which."])
g("o", H2, 8, [8, 13, 20, 40], [
 "Find a cushion.",
 "Where are the throw pillows?",
 "Can you go to a pillow?",
 "My back hurts, I need something soft to stuff behind it - a cushion would do.",
 "Make your way to any of the cushions lying about.",
 "cusion pls"])
g("o", H2, 6, [6], [
 "Where's the laptop?",
 "Go to the notebook computer.",
 "I left my portable computer somewhere, can you find it?",
 "Walk up to the lap top.",
 "I need to check my email on the laptop computer - take me there.",
 "find the notebook PC"])
g("o", AP, 8, [8, 39, 55], [
 "Find a plant.",
 "Take me to one of the houseplants.",
 "Where's some greenery in the flat?",
 "I need to water something - go to anything growing in a pot.",
 "Head to some foliage, I'm not fussy which.",
 "Could you navigate to a houseplant plz"])
g("o", AP, 30, [30, 43], [
 "Go to a mirror.",
 "I want to check my hair - where's a looking glass?",
 "Find me somewhere I can see my reflection, like a mirror.",
 "Head over to the glass I can check my outfit in.",
 "Where do we have a looking-glass on the wall? Go there.",
 "Stop by anything reflective I can fix my makeup in - a mirorr or similar."])
g("o", SK, 26, [26, 27], [
 "Go to the bin.",
 "Where's the garbage can?",
 "I need to throw this away - take me to a rubbish bin.",
 "trash can",
 "Find the wastebasket please.",
 "Head over to the trash, whichever one is closer."])
g("o", FD, 21, [21, 22], [
 "Find a stool.",
 "Where's a barstool?",
 "I need a backless seat to stand on to reach the top shelf - go to one of the stools.",
 "Take me to one of those little backless seats.",
 "Head over to one of the tall seats without a backrest.",
 "Come round to a high seat, the kind with no back."])

# ---------------- or : category + room ----------------
g("or", H1, 160, [160, 162, 164], [
 "Go to the towels in the living room.",
 "Where are the folded towels in the lounge?",
 "I just showered and need a towel - the stack in the sitting room, please.",
 "Head to the living room and find a set of towels.",
 "Towels. Living room.",
 "Can you navigate to the bath towels that are in the livingroom?"])
g("or", H1, 261, [261, 263], [
 "Go to the armchair in the bedroom.",
 "Where's an arm chair in the bedroom?",
 "Take me to an easy chair in the bedroom.",
 "I want to read in the bedroom, find me an armchair there.",
 "bedroom armchair",
 "Head over to the room where we sleep and find one of the big comfy armchairs."])
g("or", H2, 7, [7, 55, 64], [
 "Go to a desk in the rec room.",
 "Find a workstation in the recreation room.",
 "In the games room, where's a desk I can work at?",
 "I need somewhere to put my laptop down and work in the rec room - a computer workstation please.",
 "Head to the recreation room and stop at any of the work stations.",
 "rec room... any of the workspaces people put their computers on"])
g("or", AP, 23, [23, 24], [
 "Go to a chair in the kitchen.",
 "Find me a seat at the kitchen table.",
 "Where's a dining seat in the kitchen?",
 "My legs are tired - take me to a kitchen chair.",
 "Kitchen. A seat. Any of them.",
 "Could you walk over to one of the seats round the table in the kitchn?"])
g("or", AP, 12, [12, 13], [
 "Go to a book in the living room.",
 "Find one of the books in the lounge.",
 "Is there something to read on the shelves in the sitting room? Take me to it.",
 "Head to the front room and pick out any volume.",
 "Living room, some reading material, doesn't matter which.",
 "I'm bored in the living room; walk me over to something I could read."])
g("or", FD, 8, [8, 9], [
 "Go to a lamp in the studio.",
 "Find a light in the main living space of the studio.",
 "It's too dark in the studio, take me to one of the lamps there.",
 "Where's a reading light in the studio room?",
 "Studio - any of the lights you can switch on.",
 "Could you make your way to a standing or desk light in the studoi?"])
g("or", FD, 31, [31], [
 "Go to the rug in the kids' room.",
 "Find the play mat in the children's bedroom.",
 "Where's the carpet in the kids room?",
 "Take me to the floor rug in the children's room.",
 "Kids' bedroom, the mat on the floor.",
 "I spilled juice on the carpet in the childrens room, head over there."])
g("or", SL, 15, [15, 16], [
 "Go to a picture in the living room.",
 "Find one of the paintings in the lounge.",
 "Where's the artwork hanging in the living room?",
 "Take me to a framed picture in the sitting room.",
 "Head to any wall art in the living room.",
 "living room - a photo or painting on the wall, whichever"])

# ---------------- od : category + description ----------------
g("od", H1, 211, [211], [
 "Go to the blue bowl.",
 "Find the deep blue ceramic dish with gold patterns.",
 "Where's the decorative bowl - the blue one, not the white one with sweets?",
 "Take me to the navy-ish dish with the golden pattern on it.",
 "I want the ornamental dish that's blue, not the candy dish.",
 "Head over to the blue and gold ceramic centrepiece pls"])
g("od", H1, 184, [184], [
 "Go to the L-shaped couch.",
 "Find the corner sofa with the chaise.",
 "Where's the sectional - the L-shaped one, not the plush couch?",
 "Take me to the sofa that has a built-in chaise longue.",
 "The settee shaped like an L. Go there.",
 "Walk up to the L shaped fabric sofa with the storage compartment"])
g("od", H2, 40, [40], [
 "Go to the orange pillow with the stripes.",
 "Find the striped orange cushion.",
 "Where's the cushion with white and yellow stripes?",
 "Take me to the orange throw pillow - the stripy one, not the puffy one with the button.",
 "I want the orange cushion that has stripes on it",
 "Head over to the orange-and-white striped cushon."])
g("od", H2, 7, [7], [
 "Go to the white desk.",
 "Find the white wooden workstation.",
 "Where's the desk that's painted white, not one of the brown ones?",
 "Take me to the white work table.",
 "The white one - the workstation, I mean.",
 "Swing by the white wooden work surface where people sit with their computers."])
g("od", AP, 2, [2], [
 "Go to the brown leather sofa.",
 "Find the small brown loveseat.",
 "Where's the little leather couch, not the big grey one?",
 "Take me to the two-seater settee in brown leather.",
 "I'd like to sit on the small brown couch, go there.",
 "Head to the slightly worn leather sofa against the west wall."])
g("od", SK, 4, [4], [
 "Go to the gray kitchen cabinet.",
 "Find the grey cupboard - the only one that isn't white.",
 "Where's the gray base unit?",
 "Take me to the cupboard that's grey rather than white.",
 "The odd grey cabinet among all the white ones - head there.",
 "Navigate to the grey lower cupbaord."])
g("od", FD, 5, [5], [
 "Go to the yellow chair.",
 "Find the wooden chair that's painted yellow.",
 "Where's the yellow seat?",
 "Take me to the mustard-coloured wooden dining seat.",
 "The yellow one, not the white plastic one. The seat at the round table.",
 "head over to the yelow wooden seat at the dining table"])
g("od", SO, 2, [2], [
 "Go to the wooden table.",
 "Find the brown table, not the white one.",
 "Where's the brown wood work surface?",
 "Take me to the brown wooden desk.",
 "The wooden one. Brown. The big shared worktop.",
 "Navigate to the brown wooden worktable please"])

# ---------------- ord : category + room + description ----------------
g("ord", H1, 259, [259], [
 "Go to the dark brown leather book in the bedroom.",
 "Find the leather-bound volume in the bedroom.",
 "Where's the brown tome with the gold-embossed cover, in the bedroom?",
 "Take me to the bedroom - I want the brown leather-bound book there.",
 "Bedroom. Dark leather-bound thing to read, with gold on the cover.",
 "Could you make your way to the gold-embossed brown volume in the bedrom"])
g("ord", H1, 263, [263], [
 "Go to the leather armchair in the bedroom.",
 "Find the brown leather easy chair in the bedroom.",
 "Where's the leather armchair in the bedroom, not the woven one?",
 "In the bedroom there are two armchairs - take me to the leather one, not the woven fabric one.",
 "bedroom, leather armchair",
 "Head over to the deep brown leather armchair with lumbar support in the bedroom."])
g("ord", H1, 87, [87], [
 "Go to the white washbasin counter in the bathroom.",
 "Find the glossy white vanity unit in the bathroom, the one with the sink built in.",
 "Where's the shiny white bathroom vanity counter?",
 "Take me to the high-gloss white countertop with the integrated basin - the bathroom one, not the one in the living room.",
 "Bathroom. White glossy vanity.",
 "Head over to the bathroom's white gloss wash-basin counter."])
g("ord", H2, 13, [13], [
 "Go to the navy blue pillow in the rec room.",
 "Find the dark blue velvet cushion in the recreation room.",
 "Where's the velvety navy cushion in the games room?",
 "Rec room - take me to the blue velvet pillow, the big one with buttons.",
 "I'd like the navy cushion from the rec room; go to it.",
 "Head to the rec room and find the midnight-blue velvet cusion"])
g("ord", AP, 36, [36], [
 "Go to the white pillow in the bedroom.",
 "Find the fluffy white pillow at the head of the bed in the bedroom.",
 "Where's the white cushion in the bedroom?",
 "Take me to the bedroom, to the white cotton pilow",
 "Bedroom. White cushion for sleeping on.",
 "I'm making the bed - go to the white cotton cushion at the top of it in the bedroom."])
g("ord", AP, 42, [42], [
 "Go to the gray cabinet in the bathroom.",
 "Find the grey vanity cupboard under the sink in the bathroom.",
 "Where's the grey wooden unit beneath the washbasin in the bathroom?",
 "Bathroom - the grey cupboard where the towels and toiletries go.",
 "Take me to the gray wood cabinet in the bathroom, not the metal filing one.",
 "Head over to the bathroom and stop at the grey storage cupboard."])
g("ord", FD, 21, [21], [
 "Go to the black stool in the kitchenette.",
 "Find the black metal barstool in the kitchen area.",
 "Where's the metal high seat in the kitchenette, not the wooden one?",
 "Kitchenette: the black metal seat without a back.",
 "Take me to the dark metal stool in the little kitchen.",
 "Could you swing by the black backless seat in the kitchnette?"])
g("ord", SB, 4, [4], [
 "Go to the red pillow in the bedroom.",
 "Find the red cushion on the bed in the bedroom.",
 "Where's the red throw pillow in the bedroom?",
 "Bedroom - the crimson cushion.",
 "Take me to the red one in the bedroom, the cushion, not the white or blue ones.",
 "Head over to the bedroom and find the scarlet cusion"])

# ---------------- ard : function / abstract + room and/or description ----------------
g("ard", H1, 191, [191], [
 "I need somewhere to sit down in the bathroom - the beige velvet one.",
 "Take me to the soft beige thing you can sink into, in the bathroom.",
 "Where can I sit comfortably in the bathroom? Something upholstered in beige velvet.",
 "In the bathroom, find me the cosy velvety seat, not the wooden bench.",
 "Bathroom. Something plush to sit on. Beige.",
 "My feet hurt, head to the velvet seat in the bathrom"])
g("ard", H1, 192, [192], [
 "Where does our pet sleep?",
 "Take me to the place where the furry one naps - the white and brown cushioned spot in the bathroom.",
 "Go to the spot our pet curls up on at night.",
 "Find the animal's sleeping cushion, the white and brown one.",
 "Head to where Fido sleeps.",
 "Can you go to the pet's resting spot in the bathroom?"])
g("ard", H1, 265, [265], [
 "Take me to the thing I carry my work documents in - black leather, in the bedroom.",
 "Where's my black leather case for teh office papers?",
 "Go to the black leather carrier with the metal lock in the bedroom.",
 "Find the thing I take to meetings with my papers in, the black leather one.",
 "I'm late for work - head to my document case in the bedroom!",
 "Bedroom. Black leather. The one with the lock, for paperwork."])
g("ard", H2, 25, [25], [
 "What time is it? Take me to whatever on the wall shows the time in the rec room.",
 "Go to the thing that tells the time, the black one with a red dot.",
 "Find the thing on the wall with hands that go round.",
 "Where on the wall of the games room can I check the time?",
 "Head over to the wall-mounted thing with the second hand.",
 "Navigate to the black thing in the rec room that shows the hour"])
g("ard", H2, 67, [67], [
 "Find me the handheld thing you use to change channels.",
 "Where's the little gadget with buttons you point at the screen?",
 "Go to the black and white handheld controller in the rec room.",
 "I want to turn the volume down from the sofa - take me to whatever does that.",
 "Head to the plastic hand-held unit for operating the telly.",
 "Rec room: the thing you press to switch chanels, black and white plastic."])
g("ard", AP, 29, [29], [
 "Where do I hang my coat when I come in the front door?",
 "Take me to the wooden thing by the front door where the rain jacket and umbrella hang.",
 "Go to where jackets get hung up in the hallway.",
 "Find the stand I can put my coat on, in the hall.",
 "I'm dripping wet - head over to whatever holds coats in the hallway.",
 "Hallway, wooden, for coats."])
g("ard", FD, 25, [25], [
 "Take me to the machine that dries the washing.",
 "Which appliance in the laundry room gets wet clothes dry? Go there.",
 "Go to the white appliance next to the washer that gets clothes dry.",
 "My laundry's soaking - head over to the thing that tumbles it dry.",
 "Laundry room, the machine for drying, not the one for washing.",
 "Find whatever dries clothes in the utilty room."])
g("ard", SK, 11, [11], [
 "Go to the thing I can heat up leftovers in.",
 "Where can I warm my soup up in a couple of minutes?",
 "Take me to the black appliance for reheating food.",
 "Find the box that zaps food hot in thirty seconds.",
 "I want to defrost something quickly - head over to whatever does that.",
 "Kitchen: the black appliance you nuke popcorn in."])

# ---------------- s : spatial ----------------
g("s", AP, 6, [6], [
 "Go to the picture above the grey sofa.",
 "Find the painting hanging over the big gray couch.",
 "Which artwork is on the wall above the three-seater? Take me there.",
 "Head to the framed art directly over the grey settee.",
 "The picture. The one above the grey sofa, not the photo in the hall.",
 "Walk up to the canvas hanging over the gray fabric couch"])
g("s", AP, 39, [39], [
 "Go to the plant on top of the dresser.",
 "Find the little plant sitting on the chest of drawers.",
 "Which houseplant is on the dresser? Head there.",
 "Take me to the potted thing on top of the chest of drawers.",
 "The pot on the bedroom chest of drawers, the green thing.",
 "Make your way to the greenery perched on top of the drawes."])
g("s", SK, 21, [21], [
 "Go to the chair closest to the door.",
 "Find the seat nearest the doorway.",
 "Which chair is right by the entrance? Take me to it.",
 "Head to the dining seat nearest where you come in.",
 "Take me to the seat at the table that's next to the door.",
 "Walk up to whichever seat is nearest the dor."])
g("s", SK, 25, [25], [
 "Go to the cup next to the sink.",
 "Find the mug beside the sink.",
 "Which cup is on the counter by the sink, not on the table?",
 "Take me to the mug sitting near the sink.",
 "Head to the drinking vessel by teh basin.",
 "The mug - the one near the kitchen sink, not the ones on the dining table."])
g("s", SB, 5, [5], [
 "Go to the pillow near the foot of the bed.",
 "Find the cushion lying at the bottom end of the bed, nearest the rug.",
 "Which pillow is at the foot of the bed, away from the head end?",
 "Take me to the cushion that's been left toward the foot of the bed, not the ones up at the head.",
 "Head over to the cushion on the bed that's closest to the rug.",
 "Navigate to the pilow at the end of the bed, far from where you lay your head"])
g("s", SO, 11, [11], [
 "Go to the monitor on the white table.",
 "Find the screen sitting on the white desk.",
 "Which display is on the white table? Take me there.",
 "Head over to the computer screen on the white table, not the ones on the wooden one.",
 "The monitor - on the white table.",
 "Walk up to the display that's on the white-coloured table."])
g("s", SL, 3, [3], [
 "Go to the pillow in the middle of the sofa.",
 "Find the cushion in the centre of the couch.",
 "Which cushion sits between the other two on the sofa? Take me there.",
 "Head over to the middle cushion on the grey settee.",
 "The pillow on the couch - the center one, not either end.",
 "Walk up to the cushion in betwen the two others on the sofa"])
g("s", FD, 8, [8], [
 "Go to the lamp beside the sofa bed.",
 "Find the light standing next to the sofa bed.",
 "Which lamp is in the corner by the fold-out couch? Take me there.",
 "Head over to the light right next to the sofa bed.",
 "Bring me to the standing light next to the sofa bed, please.",
 "Walk up to the light that's near the pull-out sofa."])

with open("/work/main/evals/blind/round3.jsonl", "w") as f:
    for gi, (t, m, target, accept, qs) in enumerate(G, 1):
        for wi, q in enumerate(qs, 1):
            f.write(json.dumps({"id": f"b3-g{gi:02d}-w{wi}", "map": m, "query": q, "type": t,
                                "target": target, "accept": accept, "group": f"b3-g{gi:02d}"}) + "\n")
print(len(G), "groups")
