"""Hand-written source of blind suite round 63: 48 groups x 6 wordings.

Every wording below was written by hand from the maps. `spec` is the claim that
scripts/check.py re-derives from the map; `typo` is the (misspelt, intended) word in w6.
"""

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

G = []


def g(map_, type_, target, accept, spec, w, typo):
    G.append(dict(map=map_, type=type_, target=target, accept=accept, spec=spec, w=w, typo=typo))


# ---------------------------------------------------------------- scene_00829 (caption map)
g(C829, "o", 233, [112, 157, 219, 229, 233], {"labels": ["mirror frame"]}, [
    "Take me to a mirror.",
    "Could you bring me over to one of the wall mirrors?",
    "Any mirror, whichever is handy",
    "I want to check my hair before the call, so any looking glass in the house will do.",
    "This is just about seeing my own reflection. Find me any framed mirror, I don't mind which.",
    "just need a mirorr somewhere, any of them is fine",
], ("mirorr", "mirror"))

g(C829, "o", 212, [42, 197, 212, 259], {"labels": ["book"]}, [
    "Take me to one of the books.",
    "Could you lead me to any volume I could flick through?",
    "Some bound volume to read",
    "I'm bored and want something proper to read, not loose sheets of paper, so any hardback will do.",
    "This is a reading request. Point me toward any of the bound volumes lying around the place.",
    "take me to a bok, doesn't matter which one",
], ("bok", "book"))

g(C829, "or", 164, [160, 162, 164], {"labels": ["set of towels"], "room": "living room"}, [
    "Go to the towels in the living room.",
    "Could you take me to where the folded towels are kept in the lounge?",
    "Living room towels",
    "I need to dry off, so take me to the towel piles in the living room, not the bathroom.",
    "This is for drying my hands. Where are the neatly folded bath sheets in the sitting room?",
    "living room towles pls, any of the folded stacks",
], ("towles", "towels"))

g(C829, "or", 263, [261, 263], {"labels": ["easy chair"], "room": "bedroom"}, [
    "Take me to an armchair in the bedroom.",
    "Could you find me one of the bedroom's easy chairs?",
    "Bedroom armchair, either one",
    "I want to sit down and read where it's quiet, so any armchair in the bedroom is fine, not the ones in the lounge.",
    "This is the bedroom seating I mean. Head to either of the deep brown lounge chairs there.",
    "any comfy armchiar in the bedroom",
], ("armchiar", "armchair"))

g(C829, "od", 184, [184], {"labels": ["couch"], "words": ["l-shaped"]}, [
    "Go to the L-shaped sofa with the chaise end.",
    "Could you take me to the corner couch that has a chaise longue built in?",
    "L-shaped beige sofa",
    "I want to put my feet up, so the sofa with the long lounger bit, not the one that massages you.",
    "This is the sofa shaped like an L. Take me to it, the one with the stretch-out section.",
    "the l-shaped setee with the chaise bit",
], ("setee", "settee"))

g(C829, "ord", 259, [259], {"labels": ["book"], "room": "bedroom", "words": ["brown", "leather"]}, [
    "Take me to the dark leather book in the bedroom.",
    "Could you go to the brown leather-bound volume with gold lettering that's in the bedroom?",
    "Bedroom brown leather book",
    "I left my reading in the bedroom, so the brown leather volume there, not the one in the living room.",
    "This is the old-looking leather hardback with gilt on its cover. It's the copy kept in the bedroom.",
    "the brown leathr volume in the bedroom, gold on the cover",
], ("leathr", "leather"))

g(C829, "ard", 192, [192], {"labels": ["bed for pet"], "room": "bathroom"}, [
    "Take me to where the dog can curl up and sleep in the bathroom.",
    "Could you show me the spot in the bathroom where the cat sleeps?",
    "Dog's sleeping spot, bathroom",
    "The puppy is worn out, so take me to where it naps in the bathroom, not our own bedroom.",
    "This is for the dog, who needs a nap. Find the soft white-and-brown place it lies down in the bathroom.",
    "where does the kitty snooze in the bathrom",
], ("bathrom", "bathroom"))

# ---------------------------------------------------------------- scene_office3 (caption map)
g(OFF3, "o", 13, [8, 13, 20, 40], {"labels": ["pillow"]}, [
    "Take me to a cushion.",
    "Could you lead me to any of the throw pillows?",
    "Any cushion will do",
    "My back is aching, so I need something soft to lean on, whichever cushion is handiest.",
    "This is just about a cushion. Go to any of them in the room.",
    "any cusion is fine, just take me there",
], ("cusion", "cushion"))

g(OFF3, "od", 42, [42], {"labels": ["chair"], "words": ["brown", "leather"]}, [
    "Go to the brown leather seat with no arms.",
    "Could you take me to the only brown chair, the leather one?",
    "Brown leather armless seat",
    "My phone's dying, so take me to the brown leather seat that charges it wirelessly, not the black mesh ones.",
    "This is the one brown chair among all the black and blue ones. Bring me to it.",
    "the brwon leather seat without armrests",
], ("brwon", "brown"))

g(OFF3, "od", 7, [7], {"labels": ["desk"], "words": ["white"]}, [
    "Take me to the white desk.",
    "Could you go to the white wooden workstation?",
    "Pale wooden work table",
    "I prefer light furniture, so the white one to work at, not the brown wooden ones.",
    "This is the pale-coloured place to work I mean. Head to the white wooden one.",
    "go to the whtie wooden work desk",
], ("whtie", "white"))

g(OFF3, "ord", 40, [40], {"labels": ["pillow"], "room": "rec room", "words": ["orange", "stripes"]}, [
    "Go to the orange cushion with stripes in the rec room.",
    "Could you take me to the striped orange pillow in the games room?",
    "Rec room striped orange cushion",
    "It matches my blanket, so the orange pillow striped white and yellow in the rec room, not the buttoned one.",
    "This is the stripy orange cushion I'm after. It's in the recreation room.",
    "the orange strpied cushion in the rec room",
], ("strpied", "striped"))

g(OFF3, "ard", 67, [67], {"labels": ["remote-control"], "room": "rec room"}, [
    "Take me to whatever I can use to change the channel in the rec room.",
    "Could you find the thing for flipping channels in the rec room?",
    "Something for switching channels",
    "I'm too comfy to get up, so take me to the handheld gadget that changes channels in the rec room, not the phone.",
    "This is for changing what's on without getting up. Where's the little handheld gadget for that in the rec room?",
    "need to swich channels, take me to what does that in the rec room",
], ("swich", "switch"))

# ---------------------------------------------------------------- flat_c
g(FC, "o", 28, [5, 7, 28, 36], {"labels": ["lamp"]}, [
    "Take me to a lamp.",
    "Could you bring me to any light I can switch on?",
    "Any lamp at all",
    "It's getting dark, so any reading light will do, floor or table.",
    "This is about getting some light. Go to one of the lights in the flat.",
    "take me to a lmap, whichever",
], ("lmap", "lamp"))

g(FC, "s", 20, [20], {"kind": "nearest", "ref": 13, "cands": ["chair"], "room": "kitchen",
                      "broad": ["chair", "armchair", "office chair", "sofa"]}, [
    "Go to the dining chair closest to the fridge.",
    "Could you take me to whichever kitchen seat sits nearest the refrigerator?",
    "Seat nearest fridge",
    "I want to sit near the fridge while I snack, so take me to the dining seat closest to it, not the others round the table.",
    "This is one of the chairs around the round white table. I want the one nearest the fridge-freezer.",
    "the seat by the frige in the kitchen",
], ("frige", "fridge"))

g(FC, "ord", 40, [40], {"labels": ["sink"], "room": "bathroom", "words": ["white"]}, [
    "Take me to the white basin in the bathroom.",
    "Could you go to the bathroom washbasin, the white porcelain one?",
    "Bathroom washbasin, white porcelain",
    "I need to wash my face, so the white basin in the bathroom, not the kitchen one.",
    "This is the little white basin on the vanity unit. It's in the bathroom.",
    "the white wahsbasin in the bathroom",
], ("wahsbasin", "washbasin"))

g(FC, "ard", 24, [24], {"labels": ["coat rack", "wardrobe"], "room": "hallway"}, [
    "Take me to somewhere I can hang my coat in the hallway.",
    "Could you show me where to hang up my jacket in the hall by the front door?",
    "Hang jacket, hallway",
    "I'm dripping from the rain, so take me to where coats get hung in the hall, not the bedroom wardrobe.",
    "This is about my coat. Where in the hallway can I hang it up?",
    "somewhere to hang my jaket in the hall",
], ("jaket", "jacket"))

# ---------------------------------------------------------------- flat_d
g(FD, "s", 21, [21], {"kind": "nearest", "ref": 23, "cands": ["stool"],
                      "broad": ["stool", "chair"], "broad_room": "kitchenette"}, [
    "Go to the stool nearest the bin.",
    "Could you take me to the bar seat that's closest to the trash bin?",
    "Kitchenette seat nearest bin",
    "I want to throw stuff away while sitting, so the stool by the bin, not the one nearer the fridge.",
    "This is about the two high seats in the kitchenette. I want whichever is nearer the gray waste bin.",
    "the barstool closest to the rubish bin",
], ("rubish", "rubbish"))

g(FD, "or", 5, [4, 5, 7], {"labels": ["chair"], "room": "studio"}, [
    "Take me to a chair in the studio.",
    "Could you bring me to any seat in the main studio room that isn't the sofa bed?",
    "Any studio chair",
    "My legs are tired, so any proper seat in the studio will do, just not the sofa bed.",
    "This is about sitting at a table or desk in the studio. Any of the seats there is fine.",
    "any chiar in the studio is fine",
], ("chiar", "chair"))

g(FD, "od", 31, [31], {"labels": ["rug"], "words": ["round", "rainbow"]}, [
    "Go to the round rainbow rug.",
    "Could you take me to the circular multicoloured play mat?",
    "Round striped play mat",
    "The kids want to play on it, so the colourful round rug, not the gray rectangular one.",
    "This is the bright, stripy circle of carpet. Take me there.",
    "the rainbow coloured play carpit, the round one",
], ("carpit", "carpet"))

g(FD, "ard", 25, [25], {"labels": ["dryer", "clothes horse"], "room": "laundry room"}, [
    "Take me to where I can dry my wet washing in the laundry room.",
    "Could you go to whatever gets clothes dry in the laundry room?",
    "Drying clothes, laundry room",
    "The wash has finished but everything is soaking, so take me to what dries it, not the machine that washes.",
    "This is for drying a load of laundry. Where's the thing that does that in the utility room?",
    "need to dry my clothes off, take me there in the landry room",
], ("landry", "laundry"))

# ---------------------------------------------------------------- flat_f
g(FF, "s", 13, [13], {"kind": "nearest", "ref": 16, "cands": ["chair"], "room": "kitchen"}, [
    "Go to the dining chair nearest the green dresser.",
    "Could you take me to the kitchen seat that's closest to the tall dresser with the plates?",
    "Dining seat nearest dresser",
    "I want to reach the mugs from my seat, so take me to the dining chair nearest the dresser rather than any of the others.",
    "This is one of the four seats round the oak farmhouse table. It's the one closest to the green painted dresser.",
    "the dining seat closest to the dreser",
], ("dreser", "dresser"))

g(FF, "o", 32, [7, 32], {"labels": ["rug"]}, [
    "Take me to a rug.",
    "Could you lead me to one of the floor rugs?",
    "Any carpet or mat",
    "I dropped an earring somewhere on soft flooring, so check any of the carpets, it doesn't matter which.",
    "This is about the floor coverings. Take me to whichever carpet you like.",
    "take me to a carpt, any one",
], ("carpt", "carpet"))

g(FF, "ord", 14, [14], {"labels": ["chair"], "room": "kitchen", "words": ["yellow"]}, [
    "Take me to the yellow chair in the kitchen.",
    "Could you go to the mustard-coloured seat at the kitchen table?",
    "Kitchen yellow chair",
    "I always sit in the odd one out, so the yellow seat in the kitchen, not the blue ladder-back ones.",
    "This is the mustard seat in the kitchen. It's the only one that isn't blue.",
    "the yelow one at the kitchen table",
], ("yelow", "yellow"))

g(FF, "ard", 25, [25], {"labels": ["telescope"], "room": "porch"}, [
    "Take me to where I can look at the stars from the porch.",
    "Could you take me to whatever I'd use for stargazing on the porch?",
    "Stargazing kit, porch",
    "The sky is clear tonight, so take me to the thing on the tripod out on the porch, not the rocking chair.",
    "This is for watching the planets tonight. Show me what I'd peer through out on the porch.",
    "want to look at the moon up close, take me to that thing on the porch with the tripd",
], ("tripd", "tripod"))

# ---------------------------------------------------------------- flat_h
g(FH, "s", 5, [5], {"kind": "largest", "cands": ["sofa"]}, [
    "Take me to the bigger sofa.",
    "Could you go to the larger of the two couches in the living room?",
    "Biggest couch, living room",
    "We need room for three people, so the long sofa, not the little two-seater.",
    "This is the main couch, the longer one of the pair. Head over there.",
    "the big settee, not the smal one",
], ("smal", "small"))

g(FH, "or", 18, [16, 17, 18], {"labels": ["chair"], "room": "dining room"}, [
    "Go to a chair in the dining room.",
    "Could you take me to any of the seats around the dining table?",
    "Dining room seat, any",
    "Dinner is nearly ready, so any chair in the dining room is fine, metal or rattan.",
    "This is for sitting down to eat. Bring me to whichever of the dining room seats is free.",
    "any dinning room seat will do",
], ("dinning", "dining"))

g(FH, "od", 14, [14], {"labels": ["plant"], "words": ["olive"]}, [
    "Take me to the little olive tree.",
    "Could you bring me to the olive tree in the big clay pot?",
    "Potted olive tree",
    "It needs watering, so the olive tree in terracotta, not the tiny cactus.",
    "This is the olive sapling in the large terracotta planter. Go to it.",
    "the olive tre in the big pot",
], ("tre", "tree"))

g(FH, "ord", 41, [41], {"labels": ["towel"], "room": "guest bedroom", "words": ["white"]}, [
    "Go to the white towels in the guest bedroom.",
    "Could you take me to the stack of folded white towels in the spare room?",
    "Guest room white bath linen",
    "My visitor needs a shower, so the clean white pile in the guest bedroom, not the green one on the heated rail.",
    "This is the pile of white towelling on the spare bed. Take me there.",
    "the fresh wihte ones folded up in the guest room",
], ("wihte", "white"))

# ---------------------------------------------------------------- apartment
g(APT, "o", 55, [8, 39, 55], {"labels": ["plant"]}, [
    "Take me to a plant.",
    "Could you go to any of the house plants?",
    "Any potted greenery",
    "I want to check the soil is damp, so any of the potted green things will do.",
    "This is about watering. Lead me to any pot with something growing in it.",
    "take me to a houseplnt, any one",
], ("houseplnt", "houseplant"))

g(APT, "or", 24, [23, 24], {"labels": ["chair"], "room": "kitchen"}, [
    "Go to a chair in the kitchen.",
    "Could you take me to one of the dining chairs by the kitchen table?",
    "Kitchen seat, either one",
    "I want to sit while the kettle boils, so any kitchen seat, not the office one.",
    "This is for sitting down in the kitchen. Either of the seats at the table will do.",
    "any seat in the kitchn",
], ("kitchn", "kitchen"))

g(APT, "od", 2, [2], {"labels": ["sofa"], "words": ["brown", "leather"]}, [
    "Go to the brown leather loveseat.",
    "Could you take me to the small leather two-seater?",
    "Brown leather couch",
    "I like the worn leather one, so not the big gray fabric sofa, the small brown one.",
    "This is the little brown couch made of leather. Head there.",
    "the brown lether two-seater",
], ("lether", "leather"))

g(APT, "ord", 13, [13], {"labels": ["book"], "room": "living room", "words": ["yellow"]}, [
    "Take me to the yellow book in the living room.",
    "Could you go to the big yellow photo album in the lounge?",
    "Living room yellow photobook",
    "I want to look at old holiday pictures, so the yellow album in the living room, not the red novel.",
    "This is the large yellow picture book on the bottom shelf. It's in the living room.",
    "the yellow photo albm in the living room",
], ("albm", "album"))

g(APT, "ard", 54, [54], {"labels": ["printer"], "room": "office"}, [
    "Take me to where I can print out a document in the office.",
    "Could you show me where to get a paper copy of my boarding pass in the office?",
    "Printing documents, office",
    "I need a hard copy for the meeting, so take me to what prints in the office, not the laptop.",
    "This is about putting my file on paper. Where in the office does that happen?",
    "need to print my tickts, take me to the office spot for that",
], ("tickts", "tickets"))

g(APT, "s", 30, [30], {"kind": "nearest", "ref": 29, "cands": ["mirror"]}, [
    "Go to the mirror closest to the coat stand.",
    "Could you take me to whichever mirror hangs nearest the coat rack?",
    "Looking glass nearest coat stand",
    "I want a last check before heading out, so the glass near the coat stand, not the bathroom one.",
    "This is the looking glass I check before going out. I mean the one nearest where the coats hang.",
    "the looking glass nearest the coat stnad",
], ("stnad", "stand"))

g(APT, "s", 7, [7], {"kind": "tallest", "cands": ["lamp"]}, [
    "Take me to the tallest lamp.",
    "Could you go to the tallest light in the flat?",
    "Tallest light in flat",
    "I need light across the whole room, so the tall standing one, not the little desk or bedside ones.",
    "This is the light that's taller than the others. Bring me to it.",
    "the tallst light we have",
], ("tallst", "tallest"))

g(APT, "s", 23, [23], {"kind": "nearest", "ref": 17, "cands": ["chair"], "room": "kitchen"}, [
    "Go to the dining chair nearest the kitchen sink.",
    "Could you take me to the seat at the table that's closest to the sink?",
    "Kitchen seat nearest sink",
    "I'll be rinsing cups, so the chair closest to the sink, not the one across the table.",
    "This is one of the two kitchen table seats. I want whichever is nearer the sink.",
    "the kitchen seat closest to the sinck",
], ("sinck", "sink"))

# ---------------------------------------------------------------- scan_bedroom
g(SB, "s", 7, [7], {"kind": "nearest", "ref": 15, "cands": ["nightstand"]}, [
    "Go to the nightstand closest to the door.",
    "Could you take me to the bedside table nearest the bedroom door?",
    "Bedside table by door",
    "I want to drop my keys as I come in, so the bedside table by the door, not the one near the window.",
    "This is one of the two little tables either side of the bed. I mean the one closer to the door.",
    "the nightstnd next to the door",
], ("nightstnd", "nightstand"))

g(SB, "s", 4, [4], {"kind": "between", "refs": [2, 3], "cands": ["pillow"]}, [
    "Take me to the small pillow between the two big white ones.",
    "Could you go to the cushion sitting in between the two white pillows?",
    "Cushion between two white ones",
    "I want the middle one, so the little cushion tucked between the two white ones, not the blue one further down the bed.",
    "This is the little cushion in the middle at the head of the bed. It sits between the two white ones.",
    "the cushon between the two white ones",
], ("cushon", "cushion"))

g(SB, "ard", 17, [17], {"labels": ["mirror"], "room": "bedroom"}, [
    "Take me to where I can see my reflection in the bedroom.",
    "Could you take me somewhere in the bedroom to check my outfit?",
    "Check outfit, bedroom",
    "I'm about to leave for a wedding, so take me to where I can see how I look in the bedroom.",
    "This is about checking my hair before I go. Where in the bedroom can I see myself?",
    "where can i see my refelction in the bedroom",
], ("refelction", "reflection"))

# ---------------------------------------------------------------- scan_kitchen
g(SK, "s", 8, [8], {"kind": "above", "ref": 10, "cands": ["kitchen cabinet"], "min_z": 1.5}, [
    "Go to the wall cupboard above the sink.",
    "Could you take me to the upper cabinet right over the sink?",
    "Cupboard over sink",
    "The glasses are kept over the sink, so the top cupboard there, not the lower one under it.",
    "This is one of the high cupboards on the back wall. I want the one directly above the sink.",
    "the uper cupboard over the sink",
], ("uper", "upper"))

g(SK, "or", 22, [17, 18, 19, 20, 21, 22], {"labels": ["chair"], "room": "kitchen"}, [
    "Take me to a chair in the kitchen.",
    "Could you bring me to any seat at the kitchen table?",
    "Any kitchen seat",
    "I just need to sit down for a minute, so any chair in the kitchen will do.",
    "This is about sitting down in the kitchen. Whichever seat around the table is fine.",
    "any seet in the kitchen",
], ("seet", "seat"))

g(SK, "od", 4, [4], {"labels": ["kitchen cabinet"], "words": ["gray"]}, [
    "Go to the gray cupboard.",
    "Could you take me to the grey base unit among the white ones?",
    "Grey lower cupboard",
    "The bin bags are in the odd-coloured one, so the gray cupboard, not any of the white ones.",
    "This is the only cabinet that isn't white. Take me to the gray one.",
    "the gray cuboard down low",
], ("cuboard", "cupboard"))

# ---------------------------------------------------------------- scan_livingroom
g(SL, "s", 8, [8], {"kind": "left", "cands": ["side table"], "view_from": 1, "facing": [0, 1]}, [
    "Take me to the side table on the left when you're sitting on the sofa facing the TV.",
    "Could you go to the end table to my left if I sit on the couch looking at the television?",
    "Left end table, sofa facing TV",
    "I'm left-handed and sit on the sofa facing the TV, so the side table on my left, not the right.",
    "This is from the couch, looking towards the television. Go to the small table on that left-hand side.",
    "sitting on the sofa watching tv, the side tabel on my left",
], ("tabel", "table"))

g(SL, "o", 16, [15, 16], {"labels": ["picture"]}, [
    "Take me to a painting on the wall.",
    "Could you go to any of the framed pictures?",
    "Any wall art",
    "I want to straighten one of them, so any framed artwork will do.",
    "This is about the wall art. Bring me to either of the framed pieces.",
    "take me to a paintng, either one",
], ("paintng", "painting"))

g(SL, "ord", 5, [5], {"labels": ["armchair"], "room": "living room", "words": ["green"]}, [
    "Go to the green armchair in the living room.",
    "Could you take me to the green easy chair in the lounge?",
    "Green lounge armchair",
    "I want my usual reading spot, so the green chair in the living room, not the brown leather one.",
    "This is the green upholstered seat in the living room. Head there.",
    "the gren comfy seat in the living room",
], ("gren", "green"))

# ---------------------------------------------------------------- scan_office
g(SO, "s", 12, [12], {"kind": "nearest", "ref": 20, "cands": ["monitor"]}, [
    "Go to the monitor closest to the door.",
    "Could you take me to whichever computer screen is nearest the office door?",
    "Screen nearest door",
    "I want to be able to slip out quickly, so the screen nearest the door, not the ones further in.",
    "This is one of the three monitors on the tables. I want whichever is nearest the exit.",
    "the scren nearest the door",
], ("scren", "screen"))

g(SO, "or", 21, [21, 22], {"labels": ["trash can"], "room": "office"}, [
    "Take me to a bin in the office.",
    "Could you go to any of the wastepaper baskets in the office?",
    "Any office bin",
    "I have an apple core to throw away, so any bin in the office is fine.",
    "This is about getting rid of some rubbish. Head to either of the office trash cans.",
    "any garbge bin in the office",
], ("garbge", "garbage"))

g(SO, "ard", 17, [17], {"labels": ["whiteboard"], "room": "office"}, [
    "Take me to where I can sketch out ideas with a marker in the office.",
    "Could you show me where to draw a diagram for the team in the office?",
    "Marker sketching spot, office",
    "Paper is too small for this plan, so take me to the big wall surface for writing on with markers.",
    "This is for a brainstorm with dry-erase pens. Where in the office can we write on the wall?",
    "need to scribble a flowchart with markers, take me to the spot for that in the ofice",
], ("ofice", "office"))
