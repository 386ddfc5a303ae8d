"""Hand-written blind round 52: 48 groups, each with a check spec and six wordings.

Map keys -> suite map strings (relative to evals/blind/).
spec kinds:
  o/or : labels (set of map labels that count as the asked kind), room (or only)
  od/ord: labels (kind the target is told apart within), room (ord), keys (regexes that must
          all match the target's caption/tags text and no other candidate's)
  ard  : labels (labels of objects that can serve the need), room (optional)
  s    : rel (spatial relation), cands (labels compared), plus relation parameters
typo: (misspelt word in w6, intended word)
"""
M = {
    "B": "maps/flat_b.json", "E": "maps/flat_e.json", "G": "maps/flat_g.json", "I": "maps/flat_i.json",
    "APT": "apartment",
    "SB": "../maps/scan_bedroom.json", "SK": "../maps/scan_kitchen.json",
    "SL": "../maps/scan_livingroom.json", "SO": "../maps/scan_office.json",
    "C829": "../../../shared/data/iesm_maps/scene_00829_caption.json",
    "O3": "../../../shared/data/iesm_maps/scene_office3_caption.json",
}

G = []


def g(map_key, typ, target, accept, spec, words, typo):
    G.append(dict(map=map_key, type=typ, target=target, accept=accept, spec=spec, words=words, typo=typo))


# ---------------------------------------------------------------- o (7)
g("C829", "o", 259, [42, 197, 212, 259], {"labels": ["book"]}, [
    "Take me to a book, any one will do.",
    "Could you bring me over to one of the volumes lying around the house?",
    "Any bound volume, please",
    "I need something with a spine and pages to leaf through, not the loose sheets of paper, so any book works.",
    "This is a reading errand. Lead me to whichever volume is closest.",
    "just take me to some bok, it doesn't matter which one",
], ("bok", "book"))

g("C829", "o", 184, [23, 184], {"labels": ["couch"]}, [
    "Go to a sofa, whichever one is nearest.",
    "Could you take me to one of the settees in this place?",
    "Nearest sofa please",
    "I want to stretch out properly, so a couch rather than an armchair; either sofa is fine.",
    "This is the first thing I need after work. Walk me to the closest settee.",
    "take me over to a soffa, either one is fine by me",
], ("soffa", "sofa"))

g("O3", "o", 14, [10, 14, 16, 24], {"labels": ["window"]}, [
    "Go stand by one of the windows.",
    "Could you take me to one of the panes of glass that look outside?",
    "Any window, whichever nearest",
    "I want some daylight on my face, so anywhere I can look out is good, just not the door.",
    "This is way too stuffy. Get me to one of the panes so I can crack it open.",
    "need some air, take me to any windw",
], ("windw", "window"))

g("B", "o", 26, [5, 7, 26, 33, 34], {"labels": ["lamp"]}, [
    "Take me to a lamp.",
    "Could you find me a light I can switch on?",
    "Nearest lamp",
    "It's getting dark in here, so bring me to something I can turn on for light; any of them, not the TV.",
    "This is a quick one. I just need to get to a light, whichever is closest.",
    "it's dark, get me to some kind of lihgt",
], ("lihgt", "light"))

g("G", "o", 10, [10, 37, 45], {"labels": ["basket"]}, [
    "Go to a basket.",
    "Could you lead me to one of the hampers around the house?",
    "Any hamper, please",
    "I'm not fussy about which basket, so take me to the closest one, not the bins.",
    "This is for tidying up. Show me where a hamper of any sort is.",
    "take me to one of the hampres, whichever",
], ("hampres", "hampers"))

g("I", "o", 36, [23, 31, 36], {"labels": ["mug"]}, [
    "Take me to a mug.",
    "Could you show me where there's a coffee cup?",
    "Any cup lying around",
    "I'm thirsty, so find me something to drink out of, a cup and not the kettle.",
    "This is my caffeine emergency. Bring me to whichever mug is closest.",
    "please find me a cupp to drink from, any one",
], ("cupp", "cup"))

g("APT", "o", 8, [8, 39, 55], {"labels": ["plant"]}, [
    "Go to a houseplant.",
    "Could you take me to something green growing in a pot?",
    "Nearest potted greenery",
    "I'm on watering duty today, so any of the plants works, I don't mind which.",
    "This is watering day. Lead me to one of the pots with something growing in it.",
    "show me any of the plnts around here",
], ("plnts", "plants"))

# ---------------------------------------------------------------- or (7)
g("C829", "or", 9, [4, 9, 32, 79], {"labels": ["easy chair"], "room": "living room"}, [
    "Take me to an armchair in the living room.",
    "Could you bring me to one of the lounge chairs in the living room?",
    "Living room armchair",
    "I want to sit down in the living room, so any of the armchairs there, not the folding ones.",
    "This is about relaxing in the lounge. Find me an easy chair there.",
    "take me to a comfy armchiar in the living room",
], ("armchiar", "armchair"))

g("C829", "or", 162, [160, 162, 164], {"labels": ["set of towels"], "room": "living room"}, [
    "Go to the towels in the living room.",
    "Could you guide me to the folded towels that are in the living room?",
    "Living room towels",
    "I spilled juice on the couch, so get me to the towels in the living room rather than hunting in the bathroom.",
    "This is a spill situation. Take me to the stack of towels in the lounge.",
    "where are the towles in the living room, take me there",
], ("towles", "towels"))

g("O3", "or", 55, [7, 55, 64], {"labels": ["desk"], "room": "rec room"}, [
    "Take me to a desk in the rec room.",
    "Could you show me to one of the workstations in the recreation room?",
    "Rec room work desk",
    "I need to get some work done, so any of the writing tables in the rec room is fine, not the sofa.",
    "This is for some paperwork. Lead me to any workstation in the rec room.",
    "take me to one of the deks in the rec room, any is fine",
], ("deks", "desks"))

g("E", "or", 11, [11, 12, 13, 14, 15], {"labels": ["chair"], "room": "dining room"}, [
    "Go to a chair in the dining room.",
    "Could you take me to one of the seats in the dining room?",
    "Dining room seat",
    "I want to sit down to eat, so any seat in the dining room works, not the sofa.",
    "This is dinner time. Bring me to one of the dining room chairs.",
    "get me to a dining room seet, any of them",
], ("seet", "seat"))

g("G", "or", 34, [34, 35], {"labels": ["lamp"], "room": "bedroom"}, [
    "Take me to a lamp in the main bedroom.",
    "Could you bring me to one of the bedside lights in the master bedroom?",
    "Main bedroom lamp",
    "I want to read in bed, so any light in the grown-ups' bedroom, not the one in the kids' room.",
    "This is for bedtime reading. Lead me to a light in the main bedroom.",
    "take me to one of the lights in the main bedrom",
], ("bedrom", "bedroom"))

g("APT", "or", 13, [12, 13], {"labels": ["book"], "room": "living room"}, [
    "Go to a book in the living room.",
    "Could you show me the books on the living room shelves?",
    "Living room volumes",
    "I'd like to browse something to read in the lounge, so either volume there is fine, not the textbook in the office.",
    "This is a rainy afternoon. Take me to one of the volumes in the living room.",
    "take me to a living room boook, either one",
], ("boook", "book"))

g("SK", "or", 19, [17, 18, 19, 20, 21, 22], {"labels": ["chair"], "room": "kitchen"}, [
    "Head to a chair in the kitchen.",
    "Could you find me a seat in the kitchen?",
    "Kitchen seat, any",
    "My feet hurt, so get me to any of the kitchen chairs rather than the counter.",
    "This is a breakfast thing. Walk me to one of the seats around the kitchen table.",
    "any kichen seat is fine, just take me there",
], ("kichen", "kitchen"))

# ---------------------------------------------------------------- od (7)
g("C829", "od", 56, [56], {"labels": ["doorway", "door frame", "door/window frame"], "keys": [r"peephole"]}, [
    "Take me to the door with the little peephole.",
    "Could you bring me to the dark wooden doorway that has a gold knob and a spy hole?",
    "Door with peephole, gold knob",
    "I want to check who's outside, so the door that has a peephole, not one of the plain ones.",
    "This is the door with a golden handle and a peephole. Take me to it.",
    "go to the door with the peephoel and the gold knob",
], ("peephoel", "peephole"))

g("O3", "od", 7, [7], {"labels": ["desk"], "keys": [r"\bwhite\b"]}, [
    "Go to the white desk.",
    "Could you take me to the white wooden workstation?",
    "White writing table",
    "I need the pale one, not either of the brown wooden desks.",
    "This is about the white workstation. Bring me over to it.",
    "take me to the whte workstation please",
], ("whte", "white"))

g("E", "od", 14, [14], {"labels": ["chair", "armchair"], "keys": [r"\bblack\b", r"\bmetal\b"]}, [
    "Take me to the black metal chair.",
    "Could you go to the odd one out among the dining seats, the black metal bistro one?",
    "Black metal bistro seat",
    "I want the mismatched seat, the black metal one, not the green painted ones.",
    "This is the black iron-looking seat that doesn't match the rest. Lead me there.",
    "get me to the blak metal chair that doesn't match",
], ("blak", "black"))

g("I", "od", 22, [22], {"labels": ["plant"], "keys": [r"cactus"]}, [
    "Go to the tiny cactus.",
    "Could you show me where the little cactus sits in its earthenware pot?",
    "Tiny potted cactus",
    "I want the small spiky one, not the big leafy monstera by the entrance.",
    "This is the teeny succulent with spines. Take me to it.",
    "take me to the tiny catcus",
], ("catcus", "cactus"))

g("APT", "od", 30, [30], {"labels": ["mirror"], "keys": [r"gold"]}, [
    "Take me to the mirror with the fancy gold frame.",
    "Could you bring me to the looking glass in the ornate golden frame?",
    "Gold-framed looking glass",
    "I want to check my outfit in the tall gilded one, not the oval one without a frame.",
    "This is the ornate gilt mirror I'm after. Bring me to it.",
    "go to the big gold framed mirorr",
], ("mirorr", "mirror"))

g("SO", "od", 30, [30], {"labels": ["keyboard"], "keys": [r"\bwhite\b"]}, [
    "Go to the white keyboard.",
    "Could you find the keyboard that's white?",
    "White typing keys",
    "I prefer typing on the light one, not the black one.",
    "This is about the white thing I type on at the tables. Lead me to it.",
    "take me to the white keybaord",
], ("keybaord", "keyboard"))

g("SL", "od", 6, [6], {"labels": ["armchair"], "keys": [r"leather"]}, [
    "Take me to the leather armchair.",
    "Could you bring me to the brown leather easy chair?",
    "Brown leather lounge chair",
    "I'd rather sit in the brown leather one, not the green one.",
    "This is the tan leather seat with arms. Go there.",
    "go to the brown lether armchair",
], ("lether", "leather"))

# ---------------------------------------------------------------- ord (7)
g("C829", "ord", 267, [267], {"labels": ["sideboard", "cabinet kitchen", "cabinet table"], "room": "bedroom",
                              "keys": [r"LED"]}, [
    "Go to the sideboard with the LED strip in the bedroom.",
    "Could you take me to the low cabinet in the bedroom that has LED lighting built in?",
    "Bedroom LED-lit sideboard",
    "I want the one that glows, so the bedroom credenza with the light strip, not the one with wine storage.",
    "This is the dark wood credenza in the bedroom with built-in lighting. Take me there.",
    "the bedroom credenza with the led ligth strip, go there",
], ("ligth", "light"))

g("O3", "ord", 40, [40], {"labels": ["pillow"], "room": "rec room", "keys": [r"stripe"]}, [
    "Take me to the orange striped cushion in the rec room.",
    "Could you find the orange pillow striped in white and yellow, in the rec room?",
    "Striped orange cushion, rec room",
    "I want the stripy orange one in the rec room, not the orange one with a button.",
    "This is the striped orange cushion in the rec room. Bring me to it.",
    "go to the orange striped cushon in the rec room",
], ("cushon", "cushion"))

g("B", "ord", 28, [28], {"labels": ["armchair", "office chair", "chair"], "room": "study", "keys": [r"green"]}, [
    "Go to the green armchair in the study.",
    "Could you take me to the green fabric reading seat in the study?",
    "Study's green reading chair",
    "I want to read in the study, so the green upholstered chair there, not the office swivel chair.",
    "This is the green cloth chair in the study. Take me to it.",
    "take me to the green armcahir in the study room",
], ("armcahir", "armchair"))

g("G", "ord", 3, [3], {"labels": ["bicycle"], "room": "garage", "keys": [r"blue", r"child"]}, [
    "Take me to the little blue bike in the garage.",
    "Could you bring me to the child's bicycle with training wheels in the garage?",
    "Garage blue kids' bike",
    "My son wants to ride, so the small blue one with stabilisers in the garage, not the black mountain bike.",
    "This is the kid's blue bicycle out in the garage. Lead me to it.",
    "go to the little blue bkie in the garage",
], ("bkie", "bike"))

g("I", "ord", 43, [43], {"labels": ["nightstand"], "room": "bedroom", "keys": [r"oak"]}, [
    "Go to the oak bedside table in the bedroom.",
    "Could you show me the wooden nightstand with the open shelf in the bedroom?",
    "Bedroom oak bedside table",
    "I left my glasses on the natural wood one in the bedroom, not the white one with a drawer.",
    "This is the oak night table in the bedroom. Bring me there.",
    "take me to the oak bedside tabel in the bedroom",
], ("tabel", "table"))

g("APT", "ord", 24, [24], {"labels": ["chair"], "room": "kitchen", "keys": [r"white", r"spindle"]}, [
    "Take me to the white chair in the kitchen.",
    "Could you lead me to the white painted dining seat with the spindle back in the kitchen?",
    "Kitchen white spindle-back seat",
    "I want the white-painted seat in the kitchen, not the wooden one with the green cushion.",
    "This is the white dining chair in the kitchen. Go there.",
    "go to the whitte seat in the kitchen",
], ("whitte", "white"))

g("SB", "ord", 4, [4], {"labels": ["pillow"], "room": "bedroom", "keys": [r"red"]}, [
    "Go to the red pillow in the bedroom.",
    "Could you take me to the red cushion on the bed in the bedroom?",
    "Bedroom red cushion",
    "I want the red one in the bedroom, not the white or blue cushions.",
    "This is the scarlet cushion in the bedroom. Lead me to it.",
    "take me to the red cushin in the bedroom",
], ("cushin", "cushion"))

# ---------------------------------------------------------------- ard (8)
g("C829", "ard", 192, [192], {"labels": ["bed for pet"]}, [
    "Take me to where the dog sleeps.",
    "Could you find the spot where our pet curls up for a nap?",
    "Dog's sleeping spot",
    "The puppy is worn out, so take me to where it lies down, not where we sleep.",
    "This is for the dog. Go to where it rests at night.",
    "where does the dog slepe? take me there",
], ("slepe", "sleep"))

g("O3", "ard", 34, [34], {"labels": ["backpack"]}, [
    "Take me to something I can carry my laptop around in.",
    "Could you find me the thing to sling over my shoulders and haul my stuff with?",
    "Something to carry gear",
    "I'm heading out, so I need the black canvas thing to pack my things in, not a cup or a phone.",
    "This is for carrying my books home. Lead me to what I can pack them in.",
    "need something to carry my stuf home in, take me to it",
], ("stuf", "stuff"))

g("B", "ard", 39, [39], {"labels": ["shower", "bathtub"]}, [
    "Take me where I can rinse off standing up.",
    "Could you bring me somewhere to wash off after my run?",
    "Somewhere to rinse off",
    "I'm sweaty after the gym, so I need to wash my whole body, not just my hands at the basin.",
    "This is post-workout. Guide me to where I can stand under running water.",
    "i'm sweaty, get me somewhere to rinse off under runing water",
], ("runing", "running"))

g("E", "ard", 33, [33], {"labels": ["dryer"], "room": "utility room"}, [
    "Take me to where I can dry the wet laundry in the utility room.",
    "Could you show me what I'd use to dry a load of washing?",
    "Dry wet clothes, utility room",
    "The wash just finished, so I need to get the clothes dry, not washed again.",
    "This is laundry day. Lead me to whatever tumbles the clothes dry.",
    "where can i drie my wet clothes, take me there",
], ("drie", "dry"))

g("I", "ard", 20, [20], {"labels": ["printer"]}, [
    "Take me to whatever can print out my A3 floor plans.",
    "Could you bring me to the thing that makes paper copies of drawings in the studio?",
    "Print plans, studio",
    "I need a hard copy of this drawing, so take me to what prints, not to a screen.",
    "This is for a client meeting. Get me where I can make paper copies of my drawings.",
    "take me where i can print out some drawigns",
], ("drawigns", "drawings"))

g("APT", "ard", 45, [45], {"labels": ["washing machine"]}, [
    "Take me to where I can wash my dirty clothes.",
    "Could you lead me to where the laundry gets washed in the bathroom?",
    "Laundry washing spot",
    "These jeans are filthy, so I need to run a wash cycle, not just rinse them in the sink.",
    "This is laundry time. Show me where I can put a load of clothes on to wash.",
    "get me to where i can do a load of laundy",
], ("laundy", "laundry"))

g("APT", "ard", 29, [29], {"labels": ["coat rack"], "room": "hallway"}, [
    "Take me where I can hang my jacket by the front door.",
    "Could you bring me to a place in the hallway to hang up my coat?",
    "Hang coat, hallway",
    "I'm dripping wet, so I want to hang my raincoat near the entrance, not in the bedroom closet.",
    "This is my coat and umbrella. Show me where to hang them in the hall.",
    "where do i hang my jaket in the hallway",
], ("jaket", "jacket"))

g("SO", "ard", 17, [17], {"labels": ["whiteboard"]}, [
    "Take me to somewhere I can sketch ideas with a marker on the wall.",
    "Could you find me a place to scribble a diagram with dry-erase pens?",
    "Wall surface for markers",
    "I want to map out the plan for everyone to see, so somewhere to write big on the wall, not a notebook.",
    "This is brainstorming time. Lead me to where I can write with erasable markers.",
    "take me where i can draw with markres on the wall",
], ("markres", "markers"))

# ---------------------------------------------------------------- s (12)
g("B", "s", 5, [5], {"rel": "side", "cands": ["lamp"], "near": 1, "near_dist": 1.0, "facing": [0, 1], "side": "left"}, [
    "Go to the lamp on the left when you sit on the sofa facing the television.",
    "Could you take me to the light on my left side if I'm sitting on the couch looking at the TV?",
    "Lamp left of couch, facing TV",
    "I mean the light at the left end of the sofa from where you sit watching TV, not the one on the right.",
    "This is about the two lights beside the sofa. Take me to the left one when facing the screen.",
    "go to the light on the lft side of the couch, facing the television",
], ("lft", "left"))

g("E", "s", 29, [29], {"rel": "nearest", "cands": ["mirror"], "ref": 24}, [
    "Go to the mirror nearest the big bed.",
    "Could you bring me to whichever looking glass is closest to the king-size bed?",
    "Mirror nearest big bed",
    "I'd like the glass I can see myself in that's closest to where I sleep, not the round one down in the living room.",
    "This is for a quick look at my reflection before sleeping. Take me to the reflective glass nearest the king-size bed.",
    "take me to the mirrer closest to the big bed",
], ("mirrer", "mirror"))

g("G", "s", 33, [33], {"rel": "side", "cands": ["nightstand"], "near": 31, "near_dist": 1.0, "facing": [0, 1], "side": "right"}, [
    "Go to the bedside table on the right as you stand at the foot of the bed facing the headboard.",
    "Could you take me to the nightstand on my right if I'm at the end of the bed looking toward the headboard?",
    "Right nightstand, facing headboard",
    "From the foot of the bed looking at the headboard, I want the right-hand bedside table, not the left one.",
    "This is the bedside cabinet on the right, seen from the foot of the bed. Take me there.",
    "stand at the foot of the bed facing the headbord, take me to the bedside table on the right",
], ("headbord", "headboard"))

g("I", "s", 9, [9], {"rel": "nearest", "cands": ["chair"], "ref": 10}, [
    "Go to the chair closest to the big screen on the meeting room wall.",
    "Could you bring me to the seat nearest the presentation display?",
    "Seat nearest presentation screen",
    "I'm presenting, so give me the seat right next to the display, not the ones at the far end.",
    "This is for the client pitch. Take me to whichever chair is nearest the wall-mounted display.",
    "take me to the seat closest to the big scren",
], ("scren", "screen"))

g("APT", "s", 2, [2], {"rel": "nearest", "cands": ["sofa"], "ref": 4}, [
    "Take me to the sofa nearest the TV.",
    "Could you lead me to whichever couch is closer to the television?",
    "Couch closest to television",
    "I want to see the screen up close, so the settee nearer the TV, not the one further back.",
    "This is for watching the match. Guide me to the couch that sits closest to the television.",
    "get me to the couch closer to the televsion",
], ("televsion", "television"))

g("APT", "s", 53, [53], {"rel": "under", "cands": ["cabinet"], "ref": 54}, [
    "Go to the cabinet underneath the printer.",
    "Could you take me to the cupboard that the printer sits on?",
    "Cupboard below printer",
    "I need the drawers right below the printer, not the kitchen cupboards.",
    "This is the storage unit under the printer. Bring me to it.",
    "take me to the cabnet under the printer",
], ("cabnet", "cabinet"))

g("SB", "s", 2, [2], {"rel": "side", "cands": ["pillow"], "near": 1, "near_dist": 0.3, "facing": [0, 1], "side": "left"}, [
    "Go to the leftmost pillow on the bed, as seen from the foot of the bed.",
    "Could you take me to the cushion furthest to the left when I stand at the foot of the bed looking at the headboard?",
    "Leftmost pillow, seen from foot",
    "Standing at the end of the bed, I want the cushion farthest left, not the ones in the middle.",
    "This is about the cushions on the bed. Take me to the one on the far left, viewed from the foot.",
    "from the foot of the bed, go to the cushion on the far lefft",
], ("lefft", "left"))

g("SB", "s", 7, [7], {"rel": "nearest", "cands": ["nightstand"], "ref": 15, "other": {"ref": 14, "target": 6}}, [
    "Take me to the nightstand nearest the door.",
    "Could you bring me to the bedside table closest to the doorway?",
    "Bedside table by door",
    "I want the one near the way out, not the bedside table by the window.",
    "This is the night table closest to the exit. Lead me there.",
    "go to the bedsied table next to the door",
], ("bedsied", "bedside"))

g("SK", "s", 3, [3], {"rel": "under", "cands": ["kitchen cabinet"], "ref": 10}, [
    "Go to the cabinet right under the sink.",
    "Could you take me to the cupboard beneath the sink?",
    "Cupboard under sink",
    "The cleaning spray is kept below the sink, so that cupboard, not the ones beside it.",
    "This is the base unit directly below the sink. Take me to it.",
    "take me to the cupbord under the sink",
], ("cupbord", "cupboard"))

g("SK", "s", 27, [27], {"rel": "nearest", "cands": ["trash can"], "ref": 13, "other": {"ref": 15, "target": 26}}, [
    "Take me to the trash can nearest the fridge.",
    "Could you lead me to the bin closest to the refrigerator?",
    "Bin beside fridge",
    "I'm clearing out old food from the fridge, so the rubbish bin next to it, not the one by the door.",
    "This is the waste bin nearest the fridge. Bring me over.",
    "go to the garbage bin by the frdge",
], ("frdge", "fridge"))

g("SL", "s", 9, [9], {"rel": "side", "cands": ["side table"], "near": 1, "near_dist": 1.0, "facing": [0, 1], "side": "right"}, [
    "Go to the side table on your right when you're sitting on the sofa facing the TV.",
    "Could you take me to the end table at my right-hand side as I sit on the couch watching TV?",
    "Right-hand end table from sofa",
    "Sitting on the couch watching TV, I mean the little table on the right, not the left one.",
    "This is one of the two small tables by the sofa. Take me to the right one, looking toward the TV.",
    "take me to the little tabble on the right when sitting on the sofa facing the television",
], ("tabble", "table"))

g("SO", "s", 15, [15], {"rel": "between", "cands": ["bookshelf"]}, [
    "Go to the middle bookshelf of the three.",
    "Could you take me to the bookcase in between the other two?",
    "Middle bookcase",
    "I want the centre set of shelves, not the ones at either end.",
    "This is the shelving unit sitting between the other two. Lead me to it.",
    "go to the middle bookshelff",
], ("bookshelff", "bookshelf"))
