"""Round 59 groups, written by hand from the maps. Each group: map key, type, target, accept,
check spec (kind labels, room, keywords or spatial relation), six wordings, and the w6 typo."""

G = []


def g(map_, type_, target, accept, spec, w, typo):
    G.append(dict(map=map_, type=type_, target=target, accept=accept, spec=spec, w=w, typo=typo))


# ---------------- scene_00829 (caption map) ----------------
g('00829', 'o', 42, [42, 197, 212, 259], dict(kind=['book']), [
    "Take me to any of the books lying around.",
    "Could you guide me to something I can read, whichever volume is closest?",
    "Any volume to read",
    "I'm bored and want to read for a while, so find me a volume; it doesn't matter which one.",
    "This is for a quiet evening. Head to wherever there's a bound volume I could leaf through.",
    "just take me to a bok, any of them is fine",
], ('bok', 'book'))

g('00829', 'or', 261, [261, 263], dict(kind=['easy chair'], room='bedroom'), [
    "Go to one of the armchairs in the bedroom.",
    "Could you take me to a comfy lounge chair in the bedroom?",
    "Bedroom armchair, either one",
    "I want a soft seat where I sleep, so an armchair in the bedroom, not the one in the bathroom.",
    "This is about the bedroom. Find me one of the big cosy easy chairs in there.",
    "take me to an armchiar in the bedroom pls",
], ('armchiar', 'armchair'))

g('00829', 'od', 184, [184], dict(kind=['couch'], must=['l-shaped', 'chaise']), [
    "Take me to the L-shaped couch with the chaise.",
    "Could you show me the way to the corner sofa that has a lounger end?",
    "L-shaped sofa with chaise",
    "I want to stretch right out, so the big L-shaped settee, not the one with the massager.",
    "This is for a long nap. Take me to the beige sectional with the chaise end.",
    "take me to the beige sectoinal with the chaise bit",
], ('sectoinal', 'sectional'))

g('00829', 'od', 78, [78], dict(kind=['wall tv', 'screen'], must=['soundbar']), [
    "Go to the television that has the soundbar built in.",
    "Could you take me to the glossy black TV with its own soundbar?",
    "Black TV with soundbar",
    "I want to watch a film with decent sound, so the telly with the soundbar, not the silver-framed one.",
    "This is for movie night. Head to the shiny black telly with the built-in speaker bar.",
    "the black tv with the sound bar, the glosy one",
], ('glosy', 'glossy'))

g('00829', 'ord', 110, [110], dict(kind=['stand/small table', 'small table/stand', 'side table', 'bed table',
                                          'cabinet table'], room='bathroom', must=['honey']), [
    "Take me to the little honey-coloured wooden table in the bathroom.",
    "Could you lead me to the small table with the crossed metal legs in the bathroom?",
    "Honey-wood bathroom stand, X legs",
    "I need to set my glass down in the bathroom, so the light honey wood stand, not a dark wooden one.",
    "This is in the bathroom. Go to the small warm-toned wooden table sitting on an X-shaped metal frame.",
    "little honey wood tabel in the bathroom, the one with the x base",
], ('tabel', 'table'))

g('00829', 'ard', 192, [192], dict(kind=['bed for pet', 'bed', 'couch', 'bedframe'], must=['pet']), [
    "Take me to the spot where our pet curls up to sleep.",
    "Could you take me to the place the cat naps, the soft white and brown one?",
    "Where pet sleeps",
    "The puppy needs a nap, so find where the animal sleeps, not where people sleep.",
    "This is for the cat. Go to its soft white-and-brown sleeping spot in the bathroom.",
    "where does the dog sleap, take me there",
], ('sleap', 'sleep'))

g('00829', 'ard', 265, [265], dict(kind=['briefcase', 'backpack', 'clothes bag', 'toiletry bag', 'clothes container'],
                                   must=['leather', 'lock']), [
    "Take me to what I carry my work documents in, the black leather one with the lock.",
    "Could you find the thing I take my papers to meetings in, the black leather one in the bedroom?",
    "Lockable leather thing for papers",
    "I have a meeting, so I need what I carry my files in, the leather one with the metal lock, not the backpack.",
    "This is for work tomorrow. Head to the lockable black leather thing I take documents to the office in.",
    "need the thing i carry my paperwork in, black lether with a lock",
], ('lether', 'leather'))

# ---------------- scene_office3 (caption map) ----------------
g('office3', 'o', 8, [8, 13, 20, 40], dict(kind=['pillow']), [
    "Go to a cushion, any of them.",
    "Could you take me to one of the throw cushions?",
    "Nearest pillow, any colour",
    "My back hurts, so take me to any cushion; the colour doesn't matter.",
    "This is for my sore neck. Lead me to a pillow, whichever one.",
    "any cushon will do, just take me to one",
], ('cushon', 'cushion'))

g('office3', 'or', 7, [7, 55, 64], dict(kind=['desk'], room='rec room'), [
    "Take me to one of the desks in the rec room.",
    "Could you bring me to a writing desk in the games room?",
    "Rec room workstation, any",
    "I need to sit and write, so any workstation in the rec room is fine, not the sofa.",
    "This is for homework. Head to a computer workspace in the rec room, whichever.",
    "take me to a dsek in the rec room",
], ('dsek', 'desk'))

g('office3', 'od', 10, [10], dict(kind=['window'], must=['blind', 'clock']), [
    "Go to the red-tinted window with the white blind.",
    "Could you take me to the window that has a clock above it?",
    "Red glass, white blind, clock above",
    "I want some daylight, so the red glass with the white blind, not the frosted one.",
    "This is the one under the clock. Take me to that red pane with the blind.",
    "the red glas with the white blind and the clock over it",
], ('glas', 'glass'))

g('office3', 'ord', 64, [64], dict(kind=['desk', 'table'], room='rec room', must=['cable']), [
    "Take me to the brown wooden desk with the cable management in the rec room.",
    "Could you lead me to the wooden workstation in the rec room that keeps its cables tidy?",
    "Rec room desk, tidy cables",
    "My charger lead keeps tangling, so the rec room one with the cable organiser, not the one with the USB port.",
    "This is in the rec room. Go to the wooden work surface with built-in cord management.",
    "the wodden one in the rec room with the cable organiser",
], ('wodden', 'wooden'))

g('office3', 'ard', 68, [68], dict(kind=['phone', 'remote-control', 'laptop', 'monitor'], must=['charging port']), [
    "Take me to something I can call my mum on in the rec room.",
    "Could you take me to whatever I can make a call with in the rec room?",
    "Something to ring someone, rec room",
    "I need to ring the plumber, so take me to what I can dial out on, not the remote.",
    "This is urgent, I have to make a call. Go to whatever I can ring someone on in the rec room.",
    "need to make a calll to my sister, where can i do that",
], ('calll', 'call'))

# ---------------- flat_c ----------------
g('flat_c', 's', 19, [19], dict(kind=['chair', 'office chair'], rel=('nearest', 14)), [
    "Go to the dining chair closest to the cooker.",
    "Could you take me to the kitchen chair nearest the oven?",
    "Kitchen seat nearest cooker",
    "I want to keep an eye on the pan, so the table seat nearest the hob, not the ones by the fridge.",
    "This is so I can watch the oven. Take me to the table seat that's closest to it.",
    "the kitchen seat closest to the cookr please",
], ('cookr', 'cooker'))

g('flat_c', 'o', 10, [10, 37], dict(kind=['plant']), [
    "Take me to a houseplant.",
    "Could you bring me to one of the plants?",
    "Any potted greenery",
    "I need to water something, so any of the potted plants will do.",
    "This is watering day. Head to whichever pot with something green growing in it is nearest.",
    "take me to a houseplnt, any one is fine",
], ('houseplnt', 'houseplant'))

g('flat_c', 'or', 26, [26, 27], dict(kind=['nightstand'], room='bedroom'), [
    "Go to a bedside table in the bedroom.",
    "Could you take me to one of the night tables in the bedroom?",
    "Bedroom bedside table, either",
    "I left my glasses by the bed, so either bedside table in the bedroom, not the desk.",
    "This is about the bedroom. Take me to one of the little tables beside the bed.",
    "either of the bedsde tables in the bedroom",
], ('bedsde', 'bedside'))

g('flat_c', 'ard', 24, [24], dict(kind=['coat rack', 'wardrobe', 'chair'], room='hallway', must=[]), [
    "Take me to where I can hang my coat by the front door.",
    "Could you show me where to hang up my jacket in the hallway?",
    "Hang jacket, hallway",
    "I'm soaked, so somewhere in the hall to hang my coat, not the bedroom wardrobe.",
    "This is me just coming in. Lead me to the spot in the hallway for hanging outdoor clothes.",
    "where do i hang my jaket in the hall",
], ('jaket', 'jacket'))

# ---------------- flat_d ----------------
g('flat_d', 's', 22, [22], dict(kind=['stool'], rel=('left_facing', 'south')), [
    "Go to the stool on the left as you face the kitchen counter.",
    "Could you take me to the left-hand bar seat when you're facing the worktop?",
    "Left seat facing worktop",
    "Facing the counter, I want the left stool, not the right one.",
    "This is in the kitchenette. Facing the counter, go to the left-hand perch.",
    "facing the countr, take me to the left hand seat",
], ('countr', 'counter'))

g('flat_d', 'od', 31, [31], dict(kind=['rug'], must=['rainbow', 'round']), [
    "Take me to the round rainbow-striped rug.",
    "Could you take me to the circular multicoloured mat?",
    "Round rainbow play mat",
    "The kids want to play on the colourful round carpet, not the grey rectangular one.",
    "This is the play area. Go to the circular striped carpet with every colour of the rainbow.",
    "the round rainbow rugg please",
], ('rugg', 'rug'))

g('flat_d', 'ord', 4, [4], dict(kind=['chair', 'stool'], room='studio', must=['white', 'plastic']), [
    "Go to the white plastic chair in the studio.",
    "Could you bring me to the white moulded seat in the main studio room?",
    "White plastic studio seat",
    "I'd rather not mark the wooden one, so the white plastic seat in the studio, not the yellow one.",
    "This is in the studio. Take me to the white plastic chair by the little dining table.",
    "the white plastik seat in the studio",
], ('plastik', 'plastic'))

g('flat_d', 'ard', 27, [27], dict(kind=['ironing board'], must=[]), [
    "Take me to where I can iron my shirt.",
    "Could you take me somewhere I can press the creases out of my trousers?",
    "Somewhere to iron clothes",
    "I have an interview, so I need to press my shirt, not wash it.",
    "This is for my wrinkled blouse. Lead me to where the ironing gets done in the laundry room.",
    "my shirt is all creased, where can i iorn it",
], ('iorn', 'iron'))

# ---------------- flat_f ----------------
g('flat_f', 's', 15, [15], dict(kind=['chair'], rel=('nearest', 20)), [
    "Take me to the dining chair nearest the fridge.",
    "Could you take me to the kitchen seat closest to the refrigerator?",
    "Table seat nearest fridge",
    "I'll be grabbing drinks, so the chair closest to the fridge, not one by the cooker.",
    "This is so I can reach the milk easily. Go to the table seat that's nearest the fridge.",
    "the seat closest to the frige",
], ('frige', 'fridge'))

g('flat_f', 'o', 7, [7, 32], dict(kind=['rug']), [
    "Go to a rug, either one.",
    "Could you take me to one of the rugs?",
    "Any floor mat",
    "I want to stretch on something soft, so any carpet will do, not the bare floor.",
    "This is for my yoga. Take me to one of the woven floor coverings, whichever.",
    "take me to any of the carpts",
], ('carpts', 'carpets'))

g('flat_f', 'od', 2, [2], dict(kind=['armchair', 'chair'], must=['tartan']), [
    "Take me to the red tartan armchair.",
    "Could you take me to the wingback in the plaid fabric?",
    "Red plaid wingback",
    "I want the cosy tartan one, not the cream leather chair.",
    "This is my favourite reading seat. Go to the red checked wool wingback.",
    "the red tartin armchair please",
], ('tartin', 'tartan'))

g('flat_f', 'ard', 25, [25], dict(kind=['telescope'], must=[]), [
    "Take me to where I can look at the stars.",
    "Could you take me to something I can do some stargazing with on the porch?",
    "Something for stargazing",
    "It's a clear night, so I want to view the planets, not sit and read.",
    "This is for the meteor shower tonight. Lead me to the thing on the tripod for watching the sky.",
    "want to see the plannets up close",
], ('plannets', 'planets'))

# ---------------- flat_h ----------------
g('flat_h', 's', 17, [17], dict(kind=['chair'], room='dining room', rel=('nearest', 20)), [
    "Go to the dining chair nearest the window.",
    "Could you take me to the seat at the dining table that's closest to the window?",
    "Dining seat nearest window",
    "I want the afternoon light, so the dining chair nearest the window, not the rattan one.",
    "This is for reading the paper in daylight. Take me to the table seat closest to the east window in the dining room.",
    "the dining seat closest to the windw",
], ('windw', 'window'))

g('flat_h', 'or', 5, [5, 6], dict(kind=['sofa'], room='living room'), [
    "Take me to one of the couches in the living room.",
    "Could you take me to a settee in the living room, either one?",
    "Living room couch, any",
    "I want to lie down, so either sofa in the living room, not an armchair.",
    "This is for a nap. Go to whichever sofa in the lounge is closest.",
    "any of the cuoches in the living room",
], ('cuoches', 'couches'))

g('flat_h', 'ord', 11, [11], dict(kind=['armchair', 'sofa', 'chair'], room='living room', must=['yellow', 'velvet']), [
    "Go to the mustard velvet armchair in the living room.",
    "Could you take me to the yellow velvet easy chair in the lounge?",
    "Yellow velvet living-room armchair",
    "I want the soft mustard one in the living room, not the leather club chair.",
    "This is in the living room. Take me to the plush yellow seat in the corner.",
    "the yelow velvet chair in the lounge",
], ('yelow', 'yellow'))

g('flat_h', 'ard', 4, [4], dict(kind=['bowl'], must=['keys']), [
    "Take me to where I drop my house keys when I get in.",
    "Could you take me to the spot in the hallway where the keys get left?",
    "Where keys go",
    "I'm heading out and can't find my keys, so the little green ceramic spot for them, not the coat stand.",
    "This is my usual drop-off for keys. Go to the small green ceramic thing in the hall.",
    "where do my kees go when i come home",
], ('kees', 'keys'))

# ---------------- apartment ----------------
g('apartment', 'o', 8, [8, 39, 55], dict(kind=['plant']), [
    "Take me to a plant, any of them.",
    "Could you bring me to one of the potted plants?",
    "Any houseplant",
    "The soil might be dry, so take me to something green in a pot; I don't mind which.",
    "This is the watering round. Go to whichever pot with leaves in it is nearest.",
    "take me to any pottted greenery",
], ('pottted', 'potted'))

g('apartment', 'or', 12, [12, 13], dict(kind=['book'], room='living room'), [
    "Go to a book in the living room.",
    "Could you take me to one of the books in the living room?",
    "Living room reading material",
    "I want something to read on the sofa, so any volume from the living room, not the office textbook.",
    "This is for a lazy afternoon in the lounge. Take me to one of the volumes there, either is fine.",
    "any of the voluems in the living room",
], ('voluems', 'volumes'))

g('apartment', 'od', 31, [31], dict(kind=['picture'], must=['lighthouse']), [
    "Take me to the photo of the lighthouse.",
    "Could you take me to the little black-and-white lighthouse picture?",
    "Lighthouse photo",
    "I want to show my friend the lighthouse shot, not the big abstract painting.",
    "This is the framed print I love. Go to the small monochrome one of a lighthouse.",
    "the litle lighthouse photo in the hall",
], ('litle', 'little'))

g('apartment', 'ord', 23, [23], dict(kind=['chair'], room='kitchen', must=['green']), [
    "Go to the wooden chair with the green cushion in the kitchen.",
    "Could you take me to the kitchen seat that has the green pad on it?",
    "Kitchen chair, green cushion",
    "I want the padded one in the kitchen, not the white spindle-back.",
    "This is in the kitchen. Take me to the wooden seat with a green cushion.",
    "the kitchn seat with the green cushion",
], ('kitchn', 'kitchen'))

g('apartment', 'ard', 54, [54], dict(kind=['printer'], must=[]), [
    "Take me to where I can print out a document.",
    "Could you take me to somewhere I can print my boarding pass?",
    "Somewhere to print",
    "I need a paper copy of the contract, so take me to what prints, not the laptop.",
    "This is for my tickets. Go to the black machine in the office that makes paper copies.",
    "need to prnt a letter, where do i go",
], ('prnt', 'print'))

g('apartment', 's', 1, [1], dict(kind=['sofa'], rel=('under', 6)), [
    "Take me to the sofa beneath the painting.",
    "Could you take me to the couch with the artwork hanging above it?",
    "Couch under painting",
    "I want to sit under the art, so the settee below the canvas, not the one by the west wall.",
    "This is the seat right under the abstract picture. Go there, please.",
    "the sofa under the paintng",
], ('paintng', 'painting'))

g('apartment', 's', 30, [30], dict(kind=['mirror'], rel=('nearest', 29)), [
    "Go to the mirror closest to the coat stand.",
    "Could you take me to the looking glass nearest the coat rack?",
    "Looking glass nearest coats",
    "I want to check my outfit before heading out, so the looking glass near the coats, not the bathroom one.",
    "This is for a last check before I leave. Take me to the one I can see myself in, closest to where the jackets hang.",
    "the mirror closest to the coat stnd",
], ('stnd', 'stand'))

g('apartment', 's', 14, [14], dict(kind=['pillow'], rel=('on', 1)), [
    "Go to the cushion sitting on the sofa.",
    "Could you take me to the pillow that's on the couch?",
    "Cushion on couch",
    "I want to prop my back up on the sofa, so the cushion on there, not the one on the bed.",
    "This is the one I lean against while watching TV. Take me to the cushion on the big couch.",
    "the cusion on the sofa",
], ('cusion', 'cushion'))

# ---------------- scans ----------------
g('scan_bedroom', 's', 8, [8], dict(kind=['lamp'], rel=('nearest', 11)), [
    "Go to the bedside lamp nearest the desk.",
    "Could you take me to the light on the nightstand closest to the desk?",
    "Lamp closest to desk",
    "I want to read by the one near my workspace, so the bedside light on the desk side, not the far one.",
    "This is the bedside light near where I work. Take me to the one on the nightstand closest to the desk.",
    "the light nearest the dsk",
], ('dsk', 'desk'))

g('scan_bedroom', 'o', 6, [6, 7], dict(kind=['nightstand']), [
    "Take me to a bedside table.",
    "Could you take me to either night table?",
    "Any bedside table",
    "I left my phone by the bed, so either bedside cabinet works, not the dresser.",
    "This is where my book usually ends up. Go to one of the little tables next to the bed.",
    "either of the bedside tabels",
], ('tabels', 'tables'))

g('scan_bedroom', 'ord', 5, [5], dict(kind=['pillow'], room='bedroom', must=['blue']), [
    "Go to the blue pillow in the bedroom.",
    "Could you take me to the blue cushion in the bedroom?",
    "Blue bedroom cushion",
    "I want the blue one in the bedroom, not the red or white pillows.",
    "This is in the bedroom. Take me to the cushion that's blue.",
    "the bule cushion in the bedroom",
], ('bule', 'blue'))

g('scan_kitchen', 's', 3, [3], dict(kind=['kitchen cabinet'], rel=('under', 10)), [
    "Go to the cupboard under the sink.",
    "Could you take me to the cabinet directly beneath the sink?",
    "Cupboard under sink",
    "I need the bleach, so the cupboard below the sink, not the wall units.",
    "This is where the cleaning stuff lives. Take me to the unit right under the sink.",
    "the cuboard under the sink",
], ('cuboard', 'cupboard'))

g('scan_kitchen', 's', 26, [26], dict(kind=['trash can'], rel=('nearest', 15)), [
    "Take me to the bin nearest the door.",
    "Could you take me to the rubbish bin closest to the doorway?",
    "Bin by door",
    "I'm taking the rubbish out, so the bin next to the door, not the one by the fridge.",
    "This is so I don't trek across the room. Go to the trash can closest to the kitchen door.",
    "the trashcan nearest the dor",
], ('dor', 'door'))

g('scan_kitchen', 'or', 23, [23, 24, 25], dict(kind=['cup'], room='kitchen'), [
    "Go to a cup in the kitchen.",
    "Could you take me to one of the mugs in the kitchen?",
    "Any kitchen mug",
    "I'm thirsty, so any mug in the kitchen will do, not the bowl.",
    "This is for my tea. Take me to whichever cup in the kitchen is closest.",
    "any of the mugz in the kitchen",
], ('mugz', 'mugs'))

g('scan_livingroom', 's', 2, [2], dict(kind=['pillow'], rel=('nearest', 5)), [
    "Go to the cushion nearest the green armchair.",
    "Could you take me to the pillow closest to the green easy chair?",
    "Cushion nearest green armchair",
    "I need support for my back in the green chair, so the cushion closest to it, not the ones further along the sofa.",
    "This is the sofa cushion on the green armchair's side. Go to it, please.",
    "the cusshion closest to the green armchair",
], ('cusshion', 'cushion'))

g('scan_livingroom', 'od', 6, [6], dict(kind=['armchair'], must=['leather']), [
    "Go to the brown leather armchair.",
    "Could you take me to the leather easy chair?",
    "Brown leather armchair",
    "I want the leather one, not the green chair.",
    "This is my dad's favourite, the brown leather seat. Take me to it.",
    "the brwon leather chair",
], ('brwon', 'brown'))

g('scan_livingroom', 'or', 10, [10, 11, 12], dict(kind=['lamp'], room='living room'), [
    "Go to a lamp in the living room.",
    "Could you take me to any light in the living room?",
    "Any living room lamp",
    "It's getting dark, so any reading light in the lounge will do; I don't mind which.",
    "This is getting too dim. Take me to one of the lights in the living room.",
    "any of the lihgts in the living room",
], ('lihgts', 'lights'))

g('scan_office', 's', 15, [15], dict(kind=['bookshelf'], rel=('between', 14, 16)), [
    "Go to the middle bookcase of the three.",
    "Could you take me to the bookcase that stands between the other two bookcases?",
    "Middle bookshelf",
    "I want the middle one of the bookcases, not the white one at the end.",
    "This is the row of three shelf units along the north wall. Take me to the one in the centre.",
    "the bookcase in the midle",
], ('midle', 'middle'))

g('scan_office', 'o', 21, [21, 22], dict(kind=['trash can']), [
    "Take me to a bin.",
    "Could you take me to a wastepaper basket?",
    "Any rubbish bin",
    "I need to throw this wrapper away, so any bin will do.",
    "This is just rubbish. Go to the nearest trash can.",
    "where is a wastebaskit",
], ('wastebaskit', 'wastebasket'))

g('scan_office', 'ord', 30, [30], dict(kind=['keyboard'], room='office', must=['white']), [
    "Go to the white keyboard in the office.",
    "Could you take me to the white set of computer keys in the office?",
    "White office keys",
    "I need to type something, so the white one in the office, not the black one.",
    "This is at the wooden desk in the office. Go to the white keyboard.",
    "the white keybord in the office",
], ('keybord', 'keyboard'))
