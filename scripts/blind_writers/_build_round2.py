# Builds round2.jsonl (blind helper, round 2). Queries hand-written; see round2_NOTES.md.
import json
H829="../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3="../../../shared/data/iesm_maps/scene_office3_caption.json"
APT="../../map_store/apartment.json"
SK="../maps/scan_kitchen.json"; SB="../maps/scan_bedroom.json"; SO="../maps/scan_office.json"; SL="../maps/scan_livingroom.json"
FC="maps/flat_c.json"
G=[
# ---------------- o ----------------
("o",H829,78,[78,234,6],[
 "Go to the TV.",
 "Where's the telly?",
 "Take me to a television, any one will do.",
 "could you find the flat screen tv for me",
 "I want to watch something - head over to the television.",
 "navigate to the tellevision"]),
("o",H829,23,[23,184],[
 "Find me a sofa.",
 "Where can I find a couch in this house?",
 "go to the settee",
 "I need to lie down for a bit, take me to a sofa please",
 "sofa pls",
 "Could you make your way over to the couch?"]),
("o",OFF3,8,[8,13,20,40],[
 "Find a cushion.",
 "Where's a pillow?",
 "go over to a throw pillow",
 "My back hurts, take me to a cushion I can use.",
 "cushion",
 "Could you navigate to one of the scatter cushions?"]),
("o",APT,7,[7,34,56],[
 "Go to a lamp.",
 "Where's a light fixture? Head there.",
 "It's gloomy in here, find me a reading light.",
 "go to one of the lamps",
 "Take me to any of the table or floor lights.",
 "swing by a lightt, doesn't matter which"]),
("o",APT,23,[23,24,48,10],[
 "Go to a chair.",
 "Where can I find a seat for one person?",
 "Find me a single seat - not the sofa.",
 "I need to sit down, take me to somewhere to sit that isn't a couch or a bed.",
 "any chair pls",
 "Head over to any one-person seat, whichever you reach first."]),
("o",SK,26,[26,27],[
 "Go to the trash can.",
 "Where's the bin?",
 "I need to throw this away - take me to a rubbish bin.",
 "garbage can",
 "Find a waste basket please.",
 "Head to a trashcan, either one is fine."]),
("o",FC,5,[5,7,28,36],[
 "Go to a lamp.",
 "Find me a light, any one.",
 "I can't see a thing, take me to a light I can switch on.",
 "where's a lamp",
 "Head to one of the reading lights.",
 "Stop by any of the lights in the flat, I don't mind which."]),
# ---------------- or ----------------
("or",H829,261,[261,263],[
 "Go to the armchair in the bedroom.",
 "Is there an armchair in the bedroom? Head there.",
 "bedroom easy chair",
 "I'd like to read in the bedroom - take me to one of the comfy chairs in there.",
 "Swing by the lounge chair in the bedroom.",
 "Can you navigate to an arm chair in the bed room?"]),
("or",H829,112,[112,233],[
 "Find the mirror in the bathroom.",
 "Where is the bathroom mirror?",
 "go to the looking glass in the bathroom",
 "I need to check my hair - take me to a mirror in one of the bathrooms.",
 "bathrom mirror please",
 "Make your way to the mirror in the washroom."]),
("or",OFF3,7,[7,55,64],[
 "Go to a desk in the rec room.",
 "Take me to a workstation in the recreation room.",
 "I need somewhere to put my laptop down and work in the games room - one of the desks.",
 "rec room work station",
 "Find me a study table in the rec room, please.",
 "Could you make your way over to somewhere I can work at in the rec room?"]),
("or",APT,12,[12,13],[
 "Find a book in the living room.",
 "Go to the books in the lounge.",
 "Is there anything to read in the sitting room? Take me to it.",
 "living room book",
 "Head over to something to read on the living-room shelves.",
 "Could you find me something to flick through in the livingroom?"]),
("or",APT,23,[23,24],[
 "Go to a chair in the kitchen.",
 "Take me to one of the dining seats in the kitchen.",
 "kitchen chair",
 "I want to sit down at the kitchen table - head to one of the seats there.",
 "Where are the kitchen seats?",
 "Make your way to a seat in the kithcen."]),
("or",FC,19,[19,20,21],[
 "Go to a chair in the kitchen.",
 "Find me a seat at the kitchen table.",
 "kitchen chair",
 "Where are the dining seats in the kitchen?",
 "I want to sit down in the kitchen - head to one of the seats.",
 "Navigate to a kichen seat."]),
("or",FC,31,[31],[
 "Go to the chair in the bedroom.",
 "Find the seat in the bedroom.",
 "Is there somewhere to sit in the bedroom apart from the bed? Take me there.",
 "bedroom chair",
 "Head over to the bedroom seat - I think there are clothes piled on it.",
 "Could you make your way to the seat in the bed room?"]),
# ---------------- od ----------------
("od",H829,211,[211],[
 "Find the blue bowl.",
 "Where's that dark blue ceramic bowl with the gold pattern?",
 "Go to the decorative bowl that's blue, not the white one.",
 "bring me to the navy bowl with the gold detailing",
 "Could you head to the ornamental bowl, the deep blue one?",
 "blue and gold bowl"]),
("od",H829,184,[184],[
 "Go to the L-shaped couch.",
 "Find the sectional sofa with the chaise.",
 "Where is the corner sofa - the L-shaped one?",
 "Take me to the settee that has a chaise longue built in.",
 "the L shaped sofa pls",
 "I want the big L-shaped sofa, not the other couch - head there."]),
("od",OFF3,40,[40],[
 "Find the orange pillow with white and yellow stripes.",
 "Where's the stripy orange cushion?",
 "go to the orange cushion that has stripes, not the plain one with the button",
 "striped orange throw pillow",
 "Take me to the cushion with orange, white and yellow stripes please.",
 "Can you locate the orange stripey cusion?"]),
("od",APT,12,[12],[
 "Find the red book.",
 "Where's the red hardback?",
 "Go to the novel with the red cover.",
 "red novle",
 "I want that crimson hardcover - bring me to it.",
 "Could you look for the book that's red, not the yellow or green one?"]),
("od",APT,2,[2],[
 "Go to the brown leather sofa.",
 "Take me to the leather loveseat.",
 "Where's the small two-seater couch, the brown one?",
 "brown leather setee",
 "Head to the smaller sofa - the worn leather one, not the grey fabric one.",
 "Navigate to the brown couch please."]),
("od",SK,21,[21],[
 "Go to the red chair.",
 "Find the red seat.",
 "Where's the red one of the dining seats?",
 "red chair pls",
 "Take me to the seat that's red - not the black or the white ones.",
 "Walk up to the scarlet dining seat."]),
("od",FC,2,[2],[
 "Go to the yellow armchair.",
 "Find the mustard-coloured easy chair.",
 "Where's the yellow fabric accent chair?",
 "mustard armchar",
 "Take me to the yellow lounge chair, not the grey one.",
 "Head to the ochre-yellow comfy chair."]),
# ---------------- ord ----------------
("ord",H829,261,[261],[
 "Go to the brown woven armchair in the bedroom.",
 "In the bedroom, find the fabric armchair - not the leather one.",
 "Take me to the bedroom's brown armchair with the woven upholstery.",
 "bedroom, woven brown easy chair",
 "Could you walk up to the armchair in the bedroom that's covered in woven fabric rather than leather?",
 "head to the woven armchiar in the bedroom"]),
("ord",H829,110,[110],[
 "Go to the small wooden table in the bathroom with the X-shaped metal base.",
 "In the bathroom there's a little honey-coloured table - take me there.",
 "Find the light wood side table with crossed metal legs in the bathroom.",
 "bathroom small table, honey colored wood",
 "Where's the small stand in the bathroom, the warm wood one on the X-frame?",
 "Please navigate to the little table with the metal X base that's in the bathroom."]),
("ord",OFF3,13,[13],[
 "Go to the navy blue velvet pillow in the rec room.",
 "In the rec room, find the dark blue velvety cushion.",
 "Where's the navy cushion in the recreation room?",
 "rec room - navy velevt cushion",
 "Could you take me to the soft blue velvet cushion in the games room, the big buttoned one?",
 "Head over to the deep blue cushion in the rec room, the velvet one."]),
("ord",APT,53,[53],[
 "Go to the gray cabinet in the office.",
 "In the study, find the grey metal filing cabinet.",
 "Where's the file drawer unit in the home office?",
 "office, grey metal drawers",
 "Take me to the metal two-drawer unit in the office - the one with the printer on it.",
 "Head over to the grey filing drawers in the workroom."]),
("ord",APT,24,[24],[
 "Go to the white chair in the kitchen.",
 "In the kitchen, find the white painted dining seat with the spindle back.",
 "kitchen, white wooden seat",
 "Take me to the white seat at the dining table in the kitchen - not the brown one with the green cushion.",
 "Where's the spindle-back chair in the kitchen?",
 "Could you walk over to the white dinning seat in the kitchen?"]),
("ord",FC,21,[21],[
 "Go to the black chair in the kitchen.",
 "In the kitchen, find the black metal chair.",
 "kitchen - black metal seat",
 "Take me to the metal kitchen seat, the black one.",
 "Where's the dark metal seat in the kitchen?",
 "Head over to the black seat in the kitchen, not the white wooden ones."]),
("ord",FC,7,[7],[
 "Go to the white lamp in the living room.",
 "Find the small table lamp with the white ceramic base in the lounge.",
 "living room, white ceramic light",
 "Take me to the little white light in the sitting room - not the tall brass one.",
 "Where's the small white porcelain light in the front room?",
 "Swing by the ceramic table light in the livingroom."]),
# ---------------- ard ----------------
("ard",H829,192,[192],[
 "Where does the dog sleep? Take me there.",
 "Go to the spot where the cat naps in the bathroom.",
 "Find the pet's sleeping cushion.",
 "the little spot the dog snoozes on in the batroom",
 "I want to check where the puppy sleeps - the white and brown thing.",
 "Head over to where the pet curls up at night, it's in the bathroom I think."]),
("ard",H829,78,[78,6],[
 "I want to watch the football - take me to what I can watch it on in the living room.",
 "Go to the thing on the living room wall that shows films.",
 "Where can I watch the news in the lounge?",
 "something to stream shows on, living room",
 "Find whatever we watch movies on in the living room.",
 "Head to the big screen in the living room I watch netflix on."]),
("ard",OFF3,25,[25],[
 "What time is it? Take me to the thing on the rec room wall that tells me.",
 "Go to whatever shows the time in the rec room.",
 "Find the thing with the ticking hands in the rec room.",
 "the black and red thing with the second hand, rec room",
 "I need to check the time - where's the thing mounted on the wall in the rec room that shows it?",
 "Walk up to the thing that keeps time in the recreation room."]),
("ard",APT,27,[27],[
 "I want a cup of tea - go to the thing that boils water in the kitchen.",
 "Find what I use to heat water for coffee, it's red and sits on the kitchen counter.",
 "Where's the thing that boils watter in the kitchen?",
 "thing for boiling water, kitchen",
 "Take me to the red appliance on the counter that heats water for tea.",
 "Head to whatever I boil water in, in the kitchen."]),
("ard",APT,45,[45],[
 "I need to do a load of laundry - take me to where I wash my clothes.",
 "Go to the appliance that cleans clothes, in the bathroom.",
 "Where do I put the dirty washing? The machine in the bathroom.",
 "landry appliance in the bathroom",
 "Find the thing that washes clothes.",
 "Head over to what I'd use to wash my jeans, it's in the bathroom."]),
("ard",SK,11,[11],[
 "I want to reheat my leftovers - where can I do that in the kitchen?",
 "Go to the thing that warms food up quickly, the black one on the counter.",
 "Find what I can heat my soup in, in the kitchen.",
 "thing for zapping lefovers, kitchen",
 "Take me to the appliance I nuke popcorn in.",
 "Head over to whatever I use to warm up a plate of food in the kitchen."]),
("ard",FC,14,[14],[
 "I want to cook some pasta - take me to what I cook on in the kitchen.",
 "Go to the thing with the burnners in the kitchen.",
 "Find where I can fry an egg.",
 "thing to cook on, kitchen",
 "Head to the black appliance with the gas rings and the oven.",
 "Where do I heat up a saucepan in the kitchen?"]),
# ---------------- s ----------------
("s",APT,14,[14],[
 "Go to the pillow on the grey sofa.",
 "Find the cushion sitting on the big fabric couch.",
 "Where's the cushion that's on the sofa facing the TV?",
 "cushion on the grey couch",
 "Take me to the throw pillow resting on the three-seater.",
 "Head to the cushion on the gray settee, not the one on the bed."]),
("s",APT,39,[39],[
 "Go to the plant on top of the dresser.",
 "Find the little succulent sitting on the chest of drawers.",
 "Where's the potted succulent that's on the dreser?",
 "plant on the dresser",
 "Take me to the houseplant perched on the chest of drawers in the bedroom.",
 "Could you head to the greenery on top of the drawers?"]),
("s",SB,8,[8],[
 "Go to the lamp closest to the window.",
 "Find the bedside light that's nearer the window.",
 "Which light is by the window? Take me there.",
 "lamp nearest window",
 "Head to the bedside light on the window side of the bed.",
 "Take me to the light on the nightstand next to the windoww."]),
("s",SL,17,[17],[
 "Go to the plant next to the bookshelf.",
 "Find the potted greenery beside the bookcase.",
 "Where's the houseplant by the shelves?",
 "plant near book shelf",
 "Take me to the tall leafy pot in the corner by the bookcase.",
 "Head over to the greenery next to the shelving unit."]),
("s",SO,11,[11],[
 "Go to the monitor on the white table.",
 "Find the computer screen sitting on the white desk.",
 "Which screen is on the white table? Take me to it.",
 "monitor on white table",
 "Head to the display on the white desk, not the ones on the wooden one.",
 "Walk over to the computer screen that's on the white tabel."]),
("s",FC,27,[27],[
 "Go to the nightstand with the alarm clock on it.",
 "Find the bedside table that has the clock.",
 "Which bedside cabinet has the alarm clock on top? Go there.",
 "nightstand with clock",
 "Take me to the bedside table holding the red alarm clock.",
 "Head to the night table where the clock sits, not the one with the lamp."]),
("s",FC,36,[36],[
 "Go to the lamp on the desk.",
 "Find the light sitting on the desk in the study.",
 "Which light is on the desk? Take me to it.",
 "desk lmap",
 "Head to the light on the writing desk.",
 "Take me to the little light on top of the desk, not the one by the bed."]),
]
order={"o":0,"or":1,"od":2,"ord":3,"ard":4,"s":5}
with open("/work/main/evals/blind/round2.jsonl","w") as f:
    for gi,(t,m,tgt,acc,ws) in enumerate(G,1):
        assert len(ws)==6 and tgt in acc
        for wi,q in enumerate(ws,1):
            f.write(json.dumps({"id":f"b2-g{gi:02d}-w{wi}","map":m,"query":q,"type":t,"target":tgt,"accept":acc,"group":f"b2-g{gi:02d}-{t}"})+"\n")
print(len(G))
