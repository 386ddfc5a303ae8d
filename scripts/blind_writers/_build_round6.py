"""Builds round6.jsonl. A leading '~' marks a deliberate typo (stripped on output, listed in NOTES)."""
import json
G = []
def g(m, t, target, accept, qs): G.append((m, t, target, accept, qs))

# ---------------- scene 00829 (caption map) ----------------
g("00829","o",23,[23,184],[
 "Go to a couch.",
 "take me to the sofa",
 "Could you please head over to wherever there's a settee? I'd like to sit somewhere soft for a bit.",
 "I need to stretch out for a minute - find me a sofa.",
 "sofa pls",
 "Is there a couch anywhere around here? Go over to it."])
g("00829","o",160,[125,160,162,164],[
 "go to the towels",
 "My hands are wet - take me to a towel, please.",
 "Find a towel.",
 "~could u navigate to where the towles are",
 "Would you be so kind as to bring me over to some towels?",
 "Towel. Any towel will do."])
g("00829","or",34,[34,74,22],[
 "Go to the side table in the living room.",
 "Take me to an end table in the lounge.",
 "I want to put my cup down. Head to a small side table in the living room.",
 "living room, end table",
 "Could you find me one of the little occasional tables in the sitting room?",
 "~Navigate to a small end table in the livng room."])
g("00829","or",14,[14,33],[
 "Go to the curtains in the living room.",
 "Take me to the drapes in the lounge.",
 "It's too bright in the living room - go over to the curtains so we can close them.",
 "living room drapes",
 "Could you please make your way to the window drapes in the sitting room?",
 "Head to the drapes in the front room."])
g("00829","od",197,[197],[
 "Go over to the red leather-bound volume.",
 "Find the book with the red leather cover.",
 "I want to read that volume bound in red leather - take me to it.",
 "red leather-bound volume pls",
 "Could you locate the red, leather-covered book for me, please?",
 "~Where's that red leathr hardback? Go there."])
g("00829","od",164,[164],[
 "Go to the towels with the embroidered H.",
 "Take me to the folded towels that have a letter H stitched on them.",
 "I'd like the monogrammed towels, the ones with an H - can you head there?",
 "towels with H embroidery",
 "Could you please find the stack of white towels embroidered with an 'H'?",
 "I need a fresh towel. Go to the ones with the H on them."])
g("00829","ord",263,[263],[
 "Go to the brown leather easy chair in the bedroom.",
 "Take me to the leather armchair in the bedroom, not the fabric one.",
 "In the bedroom there's a deep brown leather lounge chair - head over to it.",
 "bedroom leather armchair",
 "~Could you go to the cushy brown leather armchair with lumbar support in the bedrom?",
 "I want to sit and read in the bedroom. Go to the leather armchair there."])
g("00829","ord",157,[157],[
 "Go to the mirror with the gold frame in the living room.",
 "Take me to the ornate gilt mirror in the lounge.",
 "I want to check my hair - head to the fancy mirror with gold detailing in the living room.",
 "gold-framed mirror, living room",
 "Could you kindly navigate to the living room mirror whose frame has intricate patterns and gold on it?",
 "~Go to the ornate mirrror in the sitting room - the dark wood and gold one."])
g("00829","ard",15,[15],[
 "I've got a sweet tooth - take me to where the sweets are kept in the living room.",
 "Where can I grab a candy in the lounge?",
 "Take me to the thing that holds the sweets in the living room.",
 "Go to the spot in the living room where I can help myself to a treat.",
 "fancy a sweet, living room",
 "I need some sugar. Any little candies around in the living room? Go to them."])

# ---------------- office3 (caption map, one rec room) ----------------
g("office3","o",14,[10,14,16,24],[
 "Go to a window.",
 "I need some fresh air - take me over to a window.",
 "Head to a pane of glass that looks outside.",
 "windowpane",
 "Please go to the glazing in the outside wall.",
 "~take me to a windw"])
g("office3","or",20,[8,13,20,40],[
 "Go to a pillow in the rec room.",
 "Take me to one of the cushions in the recreation room.",
 "My back hurts; find me a cushion in the rec room.",
 "rec room cushion",
 "Could you please head over to any of the throw pillows in the games room?",
 "Go to a cushion in the rec room, any one is fine."])
g("office3","od",40,[40],[
 "Go to the orange pillow with white and yellow stripes.",
 "Take me to the striped orange cushion.",
 "There's an orange cushion with stripes on it - go there, please.",
 "orange cushion, the stripy one",
 "Could you find the cushion that's orange with white and yellow stripes, not the plain one with the button?",
 "~Go to the orange striped throw pilow."])
g("office3","od",7,[7],[
 "Go to the white desk.",
 "Take me to the white wooden workstation.",
 "I need to write something down - head to the white work table, not the brown ones.",
 "white writing desk",
 "Could you make your way to the white wooden bureau, please?",
 "go to the white wood workstation"])
g("office3","ord",35,[35,36],[
 "Go to the blue fabric chair with the mesh back in the rec room.",
 "Take me to the blue office seat with the mesh backrest in the recreation room.",
 "My back is killing me - head to one of the blue seats with lumbar support and a mesh back in the rec room.",
 "blue mesh-back seat, rec room",
 "Could you please go to the blue chair in the rec room whose backrest is mesh?",
 "~Go to the bleu fabric seat with a mesh back in the games room."])
g("office3","ard",25,[25],[
 "I want to know what time it is - take me to where I can check the time on the wall in the rec room.",
 "Where can I see the time around here? Go there.",
 "I'm running late for something. Show me the thing on the wall that tells the time.",
 "check the time, rec room",
 "Could you kindly bring me to whatever shows the hour on the wall of the games room?",
 "Take me to something that tells the time."])
g("office3","ard",67,[67],[
 "I want to change the channel - take me to the thing that controls the TV.",
 "Where's the gadget for switching channels? Go to it.",
 "Go to whatever I use to turn the volume up without getting off the sofa.",
 "something to flip channels with",
 "Could you please find me the handheld device for controlling the screen in the rec room?",
 "I need to turn the volume down on the TV, take me to what I'd use for that."])

# ---------------- flat_g (own map) ----------------
g("flat_g","o",2,[2,3],[
 "Go to a bicycle.",
 "Take me to a bike.",
 "I want to go for a ride later. Head to one of the bikes, please.",
 "bike",
 "Could you navigate to wherever a bicycle is kept?",
 "Go to a pushbike."])
g("flat_g","o",23,[23,41],[
 "Go to a mirror.",
 "I want to see how my outfit looks. Take me to a mirror.",
 "Head to somewhere with a looking glass.",
 "looking glass pls",
 "Would you take me to a glass to check my reflection in?",
 "Any looking-glass in the house will do - go to one."])
g("flat_g","or",34,[34,35],[
 "Go to the lamp in the bedroom.",
 "Take me to a bedside light in the bedroom.",
 "It's dark in the bedroom - go to one of the lamps there so I can switch it on.",
 "bedroom light",
 "Could you please head to a reading light in the master bedroom?",
 "~Navigate to a bedsdie light in the bedroom."])
g("flat_g","or",18,[18,19],[
 "Go to a chair in the kitchen.",
 "Take me to a seat at the kitchen table.",
 "I want to sit down while the pasta cooks. Find me a seat in the kitchen.",
 "kitchen chair",
 "Could you please go to one of the kitchen seats?",
 "head to a seat in the kitchen"])
g("flat_g","or",13,[13],[
 "Go to the sink in the kitchen.",
 "Take me to the kitchen sink.",
 "I need to rinse these vegetables. Head to the basin in the kitchen.",
 "kitchen basin",
 "Could you please navigate to the basin where the dishes get done in the kitchen?",
 "go to the washing-up basin in the kitchen"])
g("flat_g","od",10,[10],[
 "Go to the white plastic laundry basket.",
 "Take me to the basket of clean clothes that need folding.",
 "I've got some folding to do - head to the white plastic tub full of clean washing.",
 "white laundry tub with clean clothes",
 "Could you find the plastic hamper with the freshly washed clothes in it?",
 "go to the white washing tub"])
g("flat_g","od",3,[3],[
 "Go to the small blue kids' bike with stabilisers.",
 "Take me to the children's bicycle with training wheels.",
 "My daughter wants to ride. Head to the little blue bike with the stabilisers.",
 "blue bike w/ training wheels",
 "Could you please go to the small blue bicycle that has stabilisers on it?",
 "~go to the tiny blue bike with stablisers"])
g("flat_g","ord",19,[19],[
 "Go to the wooden chair with the red checked cushion in the kitchen.",
 "Take me to the kitchen seat that has a red checked pad on it.",
 "In the kitchen, there's a wooden chair with a red cushion - go there, please.",
 "kitchen, wooden seat, red cushion",
 "Could you head to the wooden kitchen seat, not the plastic one - the one with the checked cushion?",
 "~Go to the wodden seat in the kitchen with the red cushon."])
g("flat_g","ord",44,[44],[
 "Go to the yellow desk lamp in the kids room.",
 "Take me to the little yellow bendy light on the children's desk.",
 "My son needs more light for his drawing. Head to the yellow lamp in his room.",
 "yellow bendy light, kids' room",
 "Could you go to the yellow reading light in the children's room?",
 "~Go to the yelow desk light in the kid's room."])
g("flat_g","ard",28,[28],[
 "I want to watch the news. Take me to where I can do that in the living room.",
 "Where can I catch the football match in the lounge? Go there.",
 "Go to the thing on the living room wall that I watch programmes on.",
 "watch a film, living room",
 "Could you please take me to whatever we use to watch shows in the sitting room?",
 "~I'd like to binge a serise tonight - take me to where I'd watch it in the living room."])
g("flat_g","ard",37,[37],[
 "Where do dirty clothes go in the bedroom? Take me there.",
 "I've got a sweaty shirt to get rid of - go to where the dirty laundry goes in the bedroom.",
 "Go to the thing in the bedroom I toss my worn clothes into.",
 "dirty laundry, bedroom",
 "Could you take me to the spot in the main bedroom where used clothes are collected before washing?",
 "~where do i chuck my dirty socks in the bedrom"])
g("flat_g","ard",11,[11],[
 "I need to iron my shirt for tomorrow. Take me to where I can do that.",
 "My trousers are all creased - where can I press them? Go there.",
 "Go to the thing in the laundry room I'd use to get the wrinkles out of a shirt.",
 "press a shirt",
 "Could you please bring me to what I'd lay a shirt on to iron it?",
 "I have to get the creases out of my dress. Take me to where I can do that."])
g("flat_g","s",5,[5],[
 "Go to the box sitting on the workbench.",
 "Take me to whatever's on top of the workbench in the garage.",
 "I need a screwdriver. Head to the red case that's resting on the workbench.",
 "thing on the workbench",
 "Could you go to the toolbox that's on the workbench, please?",
 "go to the box on top of the work bench"])
g("flat_g","s",41,[41],[
 "Go to the mirror above the washbasin.",
 "Take me to the mirror that hangs over the bathroom sink.",
 "I want to check my teeth - head to the glass right above the basin.",
 "looking glass over the sink",
 "Could you please go to the looking glass directly over the hand basin?",
 "~go to the mirrror over the sink"])
g("flat_g","s",2,[2],[
 "Go to the bike closest to the workbench.",
 "Take me to whichever bicycle is nearest the workbench.",
 "Head to the bike parked nearer the workbench, not the other one.",
 "bike nearest the workbench",
 "Could you please go to the bicycle that's closest to the workbench in the garage?",
 "go to the bike that's nearest the work bench"])
g("flat_g","s",35,[35],[
 "Go to the bedside lamp farthest from the wardrobe.",
 "Take me to the lamp on the nightstand on the far side of the bed from the wardrobe.",
 "In the bedroom, head to the bedside light that's further away from the wardrobe.",
 "bedside light, the one away from the wardrobe",
 "Could you go to the light on the bedside table nearer the laundry hamper?",
 "Go to the light on the nightstand furthest from the closet."])

# ---------------- apartment, scans, flat_f ----------------
g("apartment","o",1,[1,2],[
 "Go to a sofa.",
 "Take me to the couch.",
 "I want to have a nap. Head to a settee.",
 "couch",
 "Could you please navigate to any of the sofas?",
 "~go to the cuoch"])
g("apartment","ord",31,[31],[
 "Go to the black-and-white photo in the hallway.",
 "Take me to the little lighthouse photograph in the hall.",
 "I love that lighthouse picture - head to it in the hallway.",
 "hallway, black and white lighthouse photo",
 "Could you please go to the small framed monochrome photo in the corridor?",
 "~Go to the balck and white pic in the hall."])
g("apartment","ard",54,[54],[
 "I need to print a boarding pass. Take me to where I can do that.",
 "Where can I get a hard copy of this document? Go there.",
 "Go to the machine in the office that puts documents onto paper.",
 "print something, office",
 "Could you please bring me to whatever I'd use to print my essay in the office?",
 "need to print my tickets, go there"])
g("scan_kitchen","o",26,[26,27],[
 "Go to the trash can.",
 "Take me to a bin.",
 "I've got some rubbish to throw away - head to a garbage can.",
 "bin plz",
 "Could you kindly go to a rubbish bin?",
 "Where's a garbage can? Go there."])
g("scan_kitchen","ord",21,[21],[
 "Go to the red chair in the kitchen.",
 "Take me to the red seat at the kitchen table.",
 "I'd like to sit in the red one. Head to that chair in the kitchen.",
 "kitchen, red seat",
 "Could you please go to the only red seat in the kitchen?",
 "go to the red kitchen seat"])
g("scan_livingroom","or",5,[5,6],[
 "Go to an armchair in the living room.",
 "Take me to an easy chair in the lounge.",
 "I want to read for a bit. Find me an armchair in the living room.",
 "living room easy chair",
 "Could you please head to one of the comfy single seats in the sitting room?",
 "go to an easy chair in the living room"])
g("scan_livingroom","od",6,[6],[
 "Go to the brown leather armchair.",
 "Take me to the leather easy chair.",
 "I prefer the leather one - head to the brown leather seat, please.",
 "brown leather armchair",
 "Could you go to the brown easy chair, not the green one?",
 "~go to the leater chair"])
g("scan_office","od",7,[7,10],[
 "Go to a blue office chair.",
 "Take me to one of the blue desk chairs.",
 "I want the blue seat - head to one of the blue computer chairs.",
 "blue desk chair",
 "Could you please navigate to an office chair that's blue?",
 "go to a blue chair"])
g("scan_bedroom","or",2,[2,3,4,5],[
 "Go to a pillow in the bedroom.",
 "Take me to a cushion in the bedroom.",
 "I'm tired - head to a pillow in the bedroom.",
 "bedroom cushion",
 "Could you please go over to one of the bed cushions in the bedroom?",
 "go to a cushion in the bedroom"])
g("flat_f","o",2,[2,3],[
 "Go to an armchair.",
 "Take me to an easy chair.",
 "My feet are sore. Head to any armchair in the house.",
 "easy chair",
 "Could you please go to one of the cosy easy chairs in the lounge?",
 "~go to an armchiar"])
g("flat_f","ord",14,[14],[
 "Go to the yellow chair in the kitchen.",
 "Take me to the mustard-yellow seat at the kitchen table.",
 "In the kitchen, head to the odd one out at the dining table - the yellow chair.",
 "kitchen, yellow seat",
 "Could you please go to the mustard-coloured dining seat in the kitchen?",
 "go to the yellow kitchen seat"])
g("flat_f","ard",4,[4],[
 "I'm freezing. Take me somewhere in the living room where I can warm up.",
 "Where can I light a fire in the lounge? Go there.",
 "Go to the place in the living room where we burn logs.",
 "warm up, living room",
 "Could you please bring me to the spot in the sitting room where a fire can be lit?",
 "~im cold, take me to somewher warm in the living room"])
g("scan_kitchen","s",25,[25],[
 "Go to the cup next to the sink.",
 "Take me to the mug sitting by the sink.",
 "Head to the cup on the counter beside the sink, not the ones on the table.",
 "mug by the sink",
 "Could you please go to the mug closest to the sink?",
 "go to the mug near the sink"])
g("scan_livingroom","s",3,[3],[
 "Go to the pillow in the middle of the sofa.",
 "Take me to the cushion between the two red ones on the couch.",
 "Head to the centre cushion on the sofa.",
 "middle cushion on the couch",
 "Could you please go to the pillow sitting between the other two on the sofa?",
 "~go to the cushon in the midle of the couch"])
g("scan_bedroom","s",7,[7],[
 "Go to the nightstand with the book on it.",
 "Take me to the bedside table that has a book on top.",
 "I left my reading on one of the bedside tables - head to the one with the book.",
 "bedside table with the book",
 "Could you please go to the nightstand where the book is lying, not the one with the clock?",
 "~go to the bedside tabel with a book on it"])
g("scan_office","s",24,[24],[
 "Go to the plant next to the bookshelves.",
 "Take me to the houseplant beside the bookcases.",
 "Head to the little houseplant near the bookcases, not the big one in the corner.",
 "greenery next to the bookshelves",
 "Could you please navigate to the pot plant standing next to the bookcases?",
 "~go to the plnt near the book shelves"])

out = open('/work/blind6/round6.jsonl','w'); typos=[]
for gi,(m,t,target,acc,qs) in enumerate(G,1):
    for wi,q in enumerate(qs,1):
        lid=f"b6-g{gi:02d}-w{wi}"
        if q.startswith('~'): q=q[1:]; typos.append((lid,q))
        out.write(json.dumps({"id":lid,"map":m,"query":q,"type":t,"target":target,"accept":acc,"group":f"b6-g{gi:02d}"})+"\n")
out.close()
json.dump(typos,open('/work/blind6/typos.json','w'),indent=0)
print(len(G),'groups', len(typos),'typo lines')
