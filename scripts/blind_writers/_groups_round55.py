"""Round 55 blind suite, written by hand: one entry per group.

Each group holds its map, type, target, the intent spec that scripts/check.py uses to re-derive
the accept set (o/or) or re-check the single-id claim (od/ord/ard/s), the typo of w6, and the six
wordings in the brief's order (w1 imperative, w2 "Could you ...?", w3 telegraphic, w4 reason or
contrast, w5 "This is ..." + second sentence, w6 casual lower case with one typo).
"""

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

# spec keys:
#   kind: labels that make up the kind; room: room name (None = whole map)
#   keys (od/ord/ard): list of alternatives-lists; the target's text must match every item and no
#         other candidate may match them all (candidates: the kind in the room, or for ard every
#         object in the room / map)
#   claim (s): spatial claim checked numerically, see check.py
G = [
 # ---------------- caption map scene_00829 ----------------
 dict(map=C829, type="o", target=42, accept=[42, 197, 212, 259], spec=dict(kind=["book"]), typo=("novle", "novel"), w=[
  "Take me to a book.",
  "Could you lead me to any of the books lying around?",
  "Any novel or hardback",
  "I want to read for a while, so guide me to a bound volume, not the loose paper.",
  "This is for a quiet evening of reading. Show me where there's a hardcover I can pick up.",
  "show me where a novle is"]),
 dict(map=C829, type="or", target=4, accept=[4, 9, 32, 79], spec=dict(kind=["easy chair"], room="living room"), typo=("armchiar", "armchair"), w=[
  "Lead me to an armchair in the living room.",
  "Could you take me to one of the easy chairs in the living room?",
  "Living room armchair",
  "My back hurts, so find me a cushioned armchair in the lounge, not a folding one.",
  "This is where I like to sit and watch TV. Bring me to a comfy lounge chair in the living room.",
  "take me to a comfy armchiar in the living room"]),
 dict(map=C829, type="or", target=112, accept=[112, 233], spec=dict(kind=["mirror frame"], room="bathroom"), typo=("mirorr", "mirror"), w=[
  "Head to a mirror in the bathroom.",
  "Could you show me to a bathroom mirror?",
  "Bathroom looking glass",
  "I need to check my hair, so any mirror in the bathroom will do, not the bedroom one.",
  "This is about fixing my makeup. Guide me to a framed mirror in the washroom.",
  "need a mirorr in the bathroom please"]),
 dict(map=C829, type="od", target=184, spec=dict(kind=["couch"], keys=[["l-shaped"], ["chaise"]]), typo=("chaize", "chaise"), w=[
  "Take me to the L-shaped sofa with the chaise end.",
  "Could you bring me to the corner sofa that has a built-in chaise?",
  "L-shaped sectional with chaise",
  "I want to put my feet up, so the L-shaped settee, not the plain beige couch with the massager.",
  "This is the big sectional with a chaise longue. Take me over to it.",
  "go to the l-shaped sofa with the chaize"]),
 dict(map=C829, type="ord", target=263, spec=dict(kind=["easy chair", "chair", "folded chair"], room="bedroom", keys=[["leather"], ["lumbar"]]), typo=("suport", "support"), w=[
  "Bring me to the brown leather armchair with lumbar support in the bedroom.",
  "Could you take me to the leather easy chair in the bedroom, the one with back support?",
  "Bedroom leather armchair, lumbar support",
  "My lower back aches, so I want the leather lounge chair with lumbar support in the bedroom, not the woven one.",
  "This is the bedroom seat with proper lower-back support. Lead me to the brown leather one.",
  "bedroom, the leather armchair with lumbar suport"]),
 dict(map=C829, type="ard", target=192, spec=dict(keys=[["pet"]]), typo=("sleps", "sleeps"), w=[
  "Take me to the soft spot where the dog curls up to sleep.",
  "Could you show me where my cat naps, the soft white-and-brown thing?",
  "Where pet sleeps",
  "The puppy looks tired, so take me to its cushioned sleeping spot, not where I sleep.",
  "This is for the kitten, she needs her nap. Where does she usually snooze?",
  "take me to where the kitty sleps"]),
 # ---------------- caption map scene_office3 ----------------
 dict(map=OFF3, type="o", target=13, accept=[8, 13, 20, 40], spec=dict(kind=["pillow"]), typo=("cushon", "cushion"), w=[
  "Take me to a pillow.",
  "Could you guide me to one of the cushions?",
  "Any throw cushion",
  "I want something soft behind my head, so any cushion will do, whatever the colour.",
  "This is for a nap on the couch. Show me a pillow.",
  "bring me to a cushon"]),
 dict(map=OFF3, type="or", target=11, accept=[4, 11, 12, 27], spec=dict(kind=["curtain"], room="rec room"), typo=("curtians", "curtains"), w=[
  "Go to a curtain in the rec room.",
  "Could you take me to the drapes in the rec room?",
  "Rec room drapes",
  "The sun is in my eyes, so head for the rec room drapes rather than the blinds.",
  "This is about shutting out the light. Bring me to one of the curtains in the games room.",
  "take me to the rec room curtians"]),
 dict(map=OFF3, type="od", target=7, spec=dict(kind=["desk"], keys=[["white"]]), typo=("writting", "writing"), w=[
  "Show me the way to the white desk.",
  "Could you bring me to the white wooden workstation?",
  "White wooden writing desk",
  "I left my notes on the white workstation, so go there, not to the brown wooden ones.",
  "This is the pale, painted-white work table. Show me to it.",
  "go to the white writting table"]),
 dict(map=OFF3, type="ord", target=42, spec=dict(kind=["chair"], room="rec room", keys=[["brown"], ["leather"]]), typo=("lether", "leather"), w=[
  "Guide me to the brown leather chair in the rec room.",
  "Could you lead me to the armless leather seat in the rec room?",
  "Rec room brown leather seat",
  "I prefer leather to mesh, so the brown seat in the rec room, not the black mesh ones.",
  "This is the only leather seat in the rec room, dark brown and without arms. Guide me there.",
  "go to the brown lether seat in the rec room"]),
 dict(map=OFF3, type="ard", target=3, spec=dict(room="rec room", keys=[["sofa"], ["gray"]], need="lie down on something soft and gray"), typo=("napp", "nap"), w=[
  "Take me somewhere soft in the rec room where I can stretch out and nap.",
  "Could you find me somewhere gray and padded in the rec room where I can lie down?",
  "Somewhere gray to lie down",
  "I'm exhausted and want to lie flat, so somewhere long and soft, not the hard bench.",
  "This is nap time for me. Where in the rec room can I stretch out on something soft and gray?",
  "i need a quick napp, somewhere soft and gray in the rec room"]),
 dict(map=OFF3, type="ard", target=68, spec=dict(keys=[["phone"]], need="make a call"), typo=("dail", "dial"), w=[
  "Take me to something in the rec room I can use to ring my sister.",
  "Could you take me to whatever I can make a call on?",
  "Something to make calls",
  "I have to call the office, so bring me to whatever I can dial out on, not the laptop.",
  "This is urgent, I have to call home. Where in the rec room is something I can dial on?",
  "i need to ring my mum, show me something to dail on"]),
 # ---------------- flat_c ----------------
 dict(map=FC, type="o", target=5, accept=[5, 7, 28, 36], spec=dict(kind=["lamp"]), typo=("ligth", "light"), w=[
  "Go to a lamp.",
  "Could you take me to a light I can switch on?",
  "Any lamp, please",
  "It's getting dark in here, so lead me to any light I can turn on.",
  "This is for reading after sunset. Bring me to one of the lights.",
  "take me to a ligth"]),
 dict(map=FC, type="od", target=2, spec=dict(kind=["armchair"], keys=[["mustard", "yellow"]]), typo=("yelow", "yellow"), w=[
  "Bring me over to the mustard-yellow armchair.",
  "Could you bring me to the yellow fabric easy chair?",
  "Mustard yellow armchair",
  "I like the warm colour, so the yellow lounge chair, not the gray one.",
  "This is the mustard-coloured seat in the lounge. Guide me over to it.",
  "go to the yelow comfy chair"]),
 dict(map=FC, type="ard", target=24, spec=dict(room="hallway", keys=[["coat"]], need="hang a coat in the hallway"), typo=("jakcet", "jacket"), w=[
  "Take me to where I can hang my coat by the front door.",
  "Could you show me where to hang up my jacket in the hallway?",
  "Hang coat near front door",
  "I just came in from the rain, so somewhere in the hall to hang my wet jacket, not the bedroom wardrobe.",
  "This is my soaked raincoat. Where in the hallway can I hang it?",
  "where can i hang my jakcet in the hallway"]),
 dict(map=FC, type="s", target=26, spec=dict(kind=["nightstand"], claim=dict(rel="side", stand=[2.0, 5.8], facing=[0, 1], side="left")), typo=("headbord", "headboard"), w=[
  "Take me to the bedside table on the left when you face the headboard from the foot of the bed.",
  "Could you go to the nightstand that's on your left if you stand at the end of the bed looking at the headboard?",
  "Left nightstand, facing headboard",
  "Facing the bed head from the foot end, I mean the bedside table on the left side, not the right one.",
  "This is from the foot of the bed, looking toward the headboard. Take me to the night table on my left.",
  "from the foot of the bed facing the headbord, the bedside table on the left"]),
 # ---------------- flat_d ----------------
 dict(map=FD, type="or", target=8, accept=[8, 9], spec=dict(kind=["lamp"], room="studio"), typo=("studo", "studio"), w=[
  "Go to a lamp in the studio.",
  "Could you take me to one of the lights in the main studio room?",
  "Light in studio",
  "I want to read on the sofa bed, so any lamp in the studio will do, not the kids' night-light.",
  "This is the open living space, the studio. Bring me to a light there.",
  "take me to a light in the studo"]),
 dict(map=FD, type="ord", target=5, spec=dict(kind=["chair", "stool"], room="studio", keys=[["yellow"], ["wood"]]), typo=("wodden", "wooden"), w=[
  "Lead me to the yellow wooden chair in the studio.",
  "Could you bring me to the yellow painted seat at the round table in the studio?",
  "Studio yellow wooden seat",
  "The plastic one wobbles, so the yellow wooden seat in the studio, not the white one.",
  "This is the painted yellow dining seat in the studio. Lead me there.",
  "go to the yellow wodden chair in the studio"]),
 dict(map=FD, type="ard", target=27, spec=dict(keys=[["ironing"]], need="iron a shirt"), typo=("iorn", "iron"), w=[
  "Take me to where I can iron my shirt in the laundry room.",
  "Could you show me where to press my trousers?",
  "Somewhere to press shirts",
  "My shirt is creased for the interview, so somewhere to iron it, not the dryer.",
  "This is a wrinkled blouse. Where can I get the creases out?",
  "where can i iorn my shirt"]),
 dict(map=FD, type="s", target=22, spec=dict(kind=["stool"], claim=dict(rel="side", stand=[7.55, 0.75], facing=[0, 1], side="right")), typo=("seet", "seat"), w=[
  "Go to the stool on your right when you stand with your back to the kitchenette worktop.",
  "Could you take me to the right-hand bar seat, as seen with your back to the counter?",
  "Right stool, back to counter",
  "With my back against the worktop, I want the seat on the right, not the one on the left.",
  "This is with my back to the kitchen counter. Take me to the high seat on my right.",
  "the bar seet on the right, with your back to the worktop"]),
 # ---------------- flat_f ----------------
 dict(map=FF, type="or", target=12, accept=[12, 13, 14, 15], spec=dict(kind=["chair"], room="kitchen"), typo=("kichen", "kitchen"), w=[
  "Go to a chair in the kitchen.",
  "Could you take me to one of the dining seats around the kitchen table?",
  "Kitchen dining seat",
  "I want to eat breakfast, so any seat at the kitchen table, not the porch rocker.",
  "This is for sitting down to dinner. Bring me to a kitchen chair, any colour.",
  "take me to a seat in the kichen"]),
 dict(map=FF, type="od", target=21, spec=dict(kind=["chair"], keys=[["rocking"]]), typo=("whte", "white"), w=[
  "Walk me over to the rocking chair.",
  "Could you lead me to the white wooden rocker?",
  "White wooden rocker",
  "I want to rock gently while I read, so the rocker, not a ladder-back seat.",
  "This is the white seat that rocks back and forth. Guide me there.",
  "go to the whte rocker"]),
 dict(map=FF, type="ard", target=25, spec=dict(keys=[["stargazing", "telescope"]], need="look at the stars"), typo=("starrs", "stars"), w=[
  "Take me somewhere on the porch where I can look at the stars.",
  "Could you bring me to whatever I'd use for stargazing tonight?",
  "Something for watching stars",
  "The sky is clear tonight, so take me to where I can see the planets up close, not the bedroom window.",
  "This is a perfect night for astronomy. Where can I get a close look at the moon?",
  "i want to look at the starrs tonight"]),
 dict(map=FF, type="s", target=14, spec=dict(kind=["chair"], claim=dict(rel="nearest", anchor=17)), typo=("cookr", "cooker"), w=[
  "Go to the kitchen chair closest to the range cooker.",
  "Could you take me to the dining seat nearest the stove?",
  "Seat nearest range cooker",
  "I want to stay warm, so the table seat right by the cooker, not the ones farther away.",
  "This is the seat closest to the big cream cooker. Take me to it.",
  "the dining chair nearest the cookr"]),
 # ---------------- flat_h ----------------
 dict(map=FH, type="o", target=26, accept=[13, 26, 32], spec=dict(kind=["mug"]), typo=("coffe", "coffee"), w=[
  "Take me to a mug.",
  "Could you bring me to any coffee cup?",
  "Any cup, please",
  "I'm thirsty, so take me to any cup, whichever is nearest.",
  "This is my tea break. Show me where there's a mug.",
  "take me to a coffe cup"]),
 dict(map=FH, type="ord", target=6, spec=dict(kind=["sofa"], room="living room", keys=[["cream"], ["linen"]]), typo=("lovesat", "loveseat"), w=[
  "Get me to the cream linen two-seater in the living room.",
  "Could you take me to the small cream settee in the living room?",
  "Living room cream loveseat",
  "I'd rather sit by the window, so the little cream couch in the lounge, not the long green velvet one.",
  "This is the pale linen sofa in the living room. Take me over there.",
  "the cream lovesat in the living room"]),
 dict(map=FH, type="s", target=46, spec=dict(kind=["nightstand"], room="master bedroom", claim=dict(rel="under", top=48)), typo=("lampp", "lamp"), w=[
  "Go to the bedside table in the master bedroom that has the lamp on it.",
  "Could you take me to the nightstand in the main bedroom with a lamp standing on it?",
  "Master bedroom nightstand under lamp",
  "I want to switch the light off, so the bedside table with the lamp in the main bedroom, not the one with the novel.",
  "This is the master bedroom. Take me to the bedside cabinet the lamp sits on.",
  "in the master bedroom, the bedside table under the lampp"]),
 dict(map=FH, type="s", target=17, spec=dict(kind=["chair"], room="dining room", claim=dict(rel="nearest", anchor=20)), typo=("windw", "window"), w=[
  "Take me to the dining chair closest to the window.",
  "Could you bring me to the dining room seat nearest the big east window?",
  "Dining seat nearest window",
  "I want the daylight, so the table seat right by the window, not the rattan one.",
  "This is the dining room. Go to the chair that's nearest the window.",
  "the dining seat closest to the windw"]),
 # ---------------- apartment ----------------
 dict(map=APT, type="o", target=30, accept=[30, 43], spec=dict(kind=["mirror"]), typo=("glas", "glass"), w=[
  "Take me to a mirror.",
  "Could you guide me to a looking glass?",
  "Nearest mirror",
  "I want to check my outfit, so any reflective glass on the wall, not a window.",
  "This is a quick check of my hair. Where can I see my reflection?",
  "bring me to a looking glas"]),
 dict(map=APT, type="or", target=24, accept=[23, 24], spec=dict(kind=["chair"], room="kitchen"), typo=("kitchn", "kitchen"), w=[
  "Navigate to a chair in the kitchen.",
  "Could you take me to one of the kitchen dining seats?",
  "Seat at kitchen table",
  "I want to eat my lunch, so any seat by the kitchen table, not the office one.",
  "This is lunchtime. Bring me to one of the chairs in the kitchen.",
  "take me to a seat in the kitchn"]),
 dict(map=APT, type="od", target=2, spec=dict(kind=["sofa"], keys=[["leather"]]), typo=("leathr", "leather"), w=[
  "Take me to the brown leather loveseat.",
  "Could you bring me to the small leather couch?",
  "Brown leather two-seater",
  "I spilled something on the fabric one, so the leather couch, not the big gray sofa.",
  "This is the worn brown leather two-seat couch. Lead me to it.",
  "go to the brown leathr loveseat"]),
 dict(map=APT, type="ord", target=13, spec=dict(kind=["book"], room="living room", keys=[["yellow"], ["photo"]]), typo=("foto", "photo"), w=[
  "Show me the way to the yellow photo album in the living room.",
  "Could you take me to the big yellow photo book in the living room?",
  "Yellow photo album, living room",
  "I want to show the holiday pictures, so the yellow album in the lounge, not the red novel.",
  "This is the large yellow book of photos in the living room. Take me to it.",
  "the yellow foto album in the living room"]),
 dict(map=APT, type="ard", target=45, spec=dict(room="bathroom", keys=[["washing machine", "washer"]], need="wash clothes"), typo=("clotehs", "clothes"), w=[
  "Take me to where I can wash my dirty clothes.",
  "Could you show me where to do a load of laundry in the bathroom?",
  "Somewhere to wash clothes",
  "My gym kit stinks, so somewhere to put it through a wash cycle, not the bathtub.",
  "This is a basket of dirty laundry. Where in the bathroom can I get it washed?",
  "where can i wash my clotehs"]),
 dict(map=APT, type="s", target=12, spec=dict(kind=["book"], room="living room", claim=dict(rel="higher")), typo=("higer", "higher"), w=[
  "Bring me to the book on the higher shelf of the living room bookcase.",
  "Could you take me to the upper of the two books on the living room shelves?",
  "Upper-shelf volume, living room",
  "I can't reach down easily, so the volume higher up on the lounge bookshelf, not the one lying on the bottom.",
  "This is the living room bookcase. Bring me to the volume that sits higher up.",
  "the volume on the higer shelf in the living room"]),
 dict(map=APT, type="s", target=23, spec=dict(kind=["chair"], claim=dict(rel="nearest", anchor=19)), typo=("stvoe", "stove"), w=[
  "Take me to the kitchen chair closest to the stove.",
  "Could you bring me to the dining seat nearest the cooker?",
  "Seat nearest oven",
  "I'm cooking and want to sit close by, so the seat nearest the hob, not the one across the table.",
  "This is the kitchen table. Go to the chair nearest the oven.",
  "the seat closest to the stvoe"]),
 dict(map=APT, type="s", target=6, spec=dict(kind=["picture"], claim=dict(rel="above", base=1)), typo=("paintng", "painting"), w=[
  "Go to the picture hanging above the sofa.",
  "Could you take me to the painting on the wall over the couch?",
  "Artwork above couch",
  "I want to straighten it, so the artwork over the sofa, not the little photo in the hallway.",
  "This is the framed art hung over the big couch. Lead me there.",
  "the paintng above the couch"]),
 # ---------------- scan_bedroom ----------------
 dict(map=SB, type="o", target=9, accept=[8, 9], spec=dict(kind=["lamp"]), typo=("ligt", "light"), w=[
  "Head to a lamp.",
  "Could you take me to one of the bedside lights?",
  "Any reading light",
  "I want to read in bed, so either lamp will do, not the window.",
  "This is for reading before sleep. Bring me to a light.",
  "show me a ligt"]),
 dict(map=SB, type="od", target=4, spec=dict(kind=["pillow"], keys=[["red"]]), typo=("redd", "red"), w=[
  "Guide me to the red pillow.",
  "Could you bring me to the red cushion?",
  "Red cushion",
  "It matches my scarf, so I want the red cushion, not the white or blue ones.",
  "This is the red throw pillow. Guide me to it.",
  "go to the redd cushion"]),
 dict(map=SB, type="s", target=7, spec=dict(kind=["nightstand"], claim=dict(rel="nearest", anchor=15)), typo=("dorr", "door"), w=[
  "Go to the nightstand closest to the door.",
  "Could you take me to the bedside table nearer the door?",
  "Bedside table by door",
  "I want to drop my keys on the way in, so the night table nearest the door, not the one by the window.",
  "This is the side of the bed near the door. Take me to the bedside table there.",
  "the nightstand nearest the dorr"]),
 # ---------------- scan_kitchen ----------------
 dict(map=SK, type="o", target=26, accept=[26, 27], spec=dict(kind=["trash can"]), typo=("garbge", "garbage"), w=[
  "Take me to a trash can.",
  "Could you show me to a bin?",
  "Nearest rubbish bin",
  "I've got food scraps to throw away, so any bin will do.",
  "This is some garbage I need to get rid of. Where's a waste bin?",
  "take me to a garbge bin"]),
 dict(map=SK, type="ord", target=4, spec=dict(kind=["kitchen cabinet"], room="kitchen", keys=[["gray", "grey"]]), typo=("cuboard", "cupboard"), w=[
  "Head over to the gray cabinet in the kitchen.",
  "Could you take me to the grey cupboard in the kitchen?",
  "Kitchen grey cupboard",
  "The spices are in the gray one, so the kitchen cupboard that isn't white.",
  "This is the single grey base cupboard in the kitchen. Bring me to it.",
  "the gray cuboard in the kitchen"]),
 dict(map=SK, type="s", target=8, spec=dict(kind=["kitchen cabinet"], claim=dict(rel="above", base=10)), typo=("snik", "sink"), w=[
  "Go to the wall cupboard directly above the sink.",
  "Could you take me to the overhead cabinet right over the sink?",
  "Cupboard above sink",
  "The glasses are kept up high, so the wall unit above the sink, not the one under it.",
  "This is the upper cupboard over the sink. Take me there.",
  "the cupboard above the snik"]),
 # ---------------- scan_livingroom ----------------
 dict(map=SL, type="or", target=12, accept=[10, 11, 12], spec=dict(kind=["lamp"], room="living room"), typo=("lihgt", "light"), w=[
  "Take me to a lamp in the living room.",
  "Could you bring me to one of the lights in the lounge?",
  "Living room light",
  "It's too dim to read here, so any lamp in the living room is fine.",
  "This is for some evening light in the sitting room. Guide me to a light there.",
  "take me to a lihgt in the living room"]),
 dict(map=SL, type="od", target=6, spec=dict(kind=["armchair"], keys=[["leather"]]), typo=("brwon", "brown"), w=[
  "Lead me to the leather armchair.",
  "Could you take me to the brown leather easy chair?",
  "Brown leather armchair",
  "I'd like to sit on leather, so the brown club chair, not the green one.",
  "This is the brown leather seat with arms. Lead me there.",
  "the brwon leather chair"]),
 dict(map=SL, type="s", target=4, spec=dict(kind=["pillow"], claim=dict(rel="nearest", anchor=22, among=[2, 4])), typo=("cusion", "cushion"), w=[
  "Go to the red cushion nearest the door.",
  "Could you take me to whichever red pillow on the sofa is closest to the door?",
  "Red cushion nearest door",
  "Not the red one at the far end, I mean the red cushion on the sofa end closer to the door.",
  "This is one of the two red cushions on the sofa. Take me to the one nearer the door.",
  "the red cusion nearest the door"]),
 # ---------------- scan_office ----------------
 dict(map=SO, type="ord", target=2, spec=dict(kind=["table"], room="office", keys=[["wood"]]), typo=("tabel", "table"), w=[
  "Walk me to the wooden table in the office.",
  "Could you bring me to the brown wood table in the office?",
  "Office wooden worktable",
  "I like real wood, so the brown wooden desk in the office, not the white one.",
  "This is the wood-topped shared desk in the office. Lead me there.",
  "the wooden tabel in the office"]),
 dict(map=SO, type="ard", target=17, spec=dict(keys=[["whiteboard"]], need="draw with markers"), typo=("markrs", "markers"), w=[
  "Take me to where I can sketch a diagram with markers in the office.",
  "Could you show me where I can draw out ideas with a dry-erase pen?",
  "Somewhere to write with markers",
  "I need to explain the plan to the team, so somewhere to draw with markers, not a sheet of paper.",
  "This is a brainstorming session. Where in the office can we scribble ideas on the wall?",
  "where can i draw with markrs in the office"]),
 dict(map=SO, type="s", target=15, spec=dict(kind=["bookshelf"], claim=dict(rel="between")), typo=("midle", "middle"), w=[
  "Head to the bookshelf in the middle of the three along the north wall.",
  "Could you take me to the bookcase between the other two?",
  "Middle bookcase",
  "The atlas is in the middle one, so the bookcase between the other two, not either end.",
  "This is the row of three bookcases on the north wall. Take me to the middle one.",
  "the bookcase in the midle"]),
]
