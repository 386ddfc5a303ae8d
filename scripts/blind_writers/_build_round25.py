"""Generate evals/blind/round25.jsonl (blind round 25). Wordings hand-written; '*' marks a line with a deliberate typo."""
import json
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "evals/blind/round25.jsonl"
C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SO, SL, SK = "../maps/scan_office.json", "../maps/scan_livingroom.json", "../maps/scan_kitchen.json"
FB, FD, FF, FG, FH = (f"maps/flat_{c}.json" for c in "bdfgh")

G = [
# ---------------- caption maps ----------------
(OFF3, "o", 8, [8, 13, 20, 40], [
  "Take me to the cushions.",
  "Could you show me where the throw cushions are?",
  "cushions on the couch",
  "I want to find something soft to put behind my back, one of the cushions.",
  "Where are all the *cusions in here?",
  "Any of the pillows will do, just take me to one.",
]),
(C829, "o", 160, [160, 162, 164], [
  "Where are the folded towels?",
  "I just showered and need something to dry off with from the stack of fresh towels, which one is closest?",
  "stack of white towels",
  "Could you bring me over to the neatly folded bath towels, please?",
  "Take me to the pile of clean *towles.",
  "There are some fluffy white towels folded up somewhere. Go to those.",
]),
(OFF3, "o", 11, [4, 11, 12, 27], [
  "Go to the drapes.",
  "Can you take me over to the window drapes?",
  "drapes by the windows",
  "The room is too bright. Bring me to one of the curtains so I can pull it shut.",
  "I'm looking for the window *curtians.",
  "Where do the fabric drapes hang? Any of them is fine.",
]),
(C829, "or", 261, [261, 263], [
  "Take me to an armchair in the bedroom.",
  "Is there a comfy armchair in the bedroom? Take me there.",
  "bedroom armchair",
  "I'd like to sit down in the bedroom. There should be a lounge chair in there.",
  "Find me the lounge chairs that are in the bedroom, either one.",
  "Go to the easy chair in the *bedrom.",
]),
(C829, "or", 112, [112, 233], [
  "Take me to the mirror in the bathroom.",
  "Could you show me the framed mirror in the bathroom?",
  "bathroom mirror",
  "I want to check my hair. Which mirror is there in the bathroom?",
  "Go to the wooden-framed looking glass in the washroom.",
  "Where's the mirror frame in the bathroom?",
]),
(OFF3, "od", 9, [9], [
  "Take me to the screen that shows a world map.",
  "Could you bring me to the display with the blue map of the world on it?",
  "screen with world map",
  "There's a computer display with a built-in camera showing a blue map. I need that one.",
  "Go to the white and blue *moniter.",
  "The one with the globe map on the screen, please.",
]),
(C829, "od", 15, [15], [
  "Take me to the candy dish.",
  "Where's the white bowl with the gold rim?",
  "white ceramic dish with gold edge",
  "I fancy a sweet. Where's the little bowl with the sweets?",
  "It's a white ceramic bowl with a small handle. Take me to it.",
  "Not the blue decorative one, the white bowl with sweets in it.",
]),
(C829, "od", 265, [265], [
  "Take me to the black leather briefcase.",
  "Could you find the leather case with the metal lock?",
  "black work case with lock",
  "This is a black leather bag for documents. It has a metal lock on it.",
  "I left my *brifecase somewhere, the black leather one.",
  "Not the backpack, the stiff black leather case for papers.",
]),
(C829, "ord", 191, [191], [
  "Take me to the beige velvet armchair in the bathroom.",
  "Is there a soft beige lounge chair in the bathroom? Please go there.",
  "beige velvet chair, bathroom",
  "There's an easy chair with a curved shape in the bathroom. It's beige and velvety.",
  "I want the cream velvet seat that's in the washroom, not any of the brown leather ones.",
  "Go to the bathroom easy chair, the beige one.",
]),
(OFF3, "ord", 13, [13], [
  "Take me to the navy velvet cushion in the rec room.",
  "Could you show me the dark blue cushion in the games room?",
  "navy cushion rec room",
  "This is a velvety navy blue cushion with a button. It's in the rec room.",
  "Not an orange or yellow one, the navy *cushoin in the rec room.",
  "Where's the big blue velvet pillow in the recreation room?",
]),
(OFF3, "ard", 25, [25], [
  "I need to know what time it is.",
  "My phone is dead, what can I check the time on?",
  "check the time",
  "I think I'm running late. Show me where I can see the hour.",
  "Is there something on the wall that tells the time?",
  "Am I late for my meeting? Take me to whatever shows the time.",
]),
(C829, "ard", 122, [122], [
  "I really need to pee.",
  "Where can I go to the loo?",
  "need the lavatory",
  "I drank way too much water. Take me where I can relieve myself.",
  "Excuse me, where can I do my business?",
  "Nature calls, please hurry.",
]),
(OFF3, "ard", 67, [67], [
  "I want to change the channel.",
  "The TV is too loud, what can I use to turn it down from here?",
  "change channel",
  "I'm bored of this show. Bring me what I need to switch it.",
  "How do I turn the volume up without getting up every time?",
  "I want to flick through the channels.",
]),
# ---------------- flat maps ----------------
(FG, "o", 10, [10, 37, 45], [
  "Take me to the hampers.",
  "Could you show me where the laundry and toy tubs are kept?",
  "hampers and baskets",
  "I'm collecting all the woven and plastic tubs for storage. Take me to one.",
  "Where are the *baskests?",
  "Go to any basket in the flat, laundry or toy, it doesn't matter.",
]),
(FH, "o", 26, [13, 26, 32], [
  "Take me to a mug.",
  "Could you find me a cup? Any one in the flat.",
  "coffee cups",
  "I want a hot drink. Where are the mugs?",
  "Go to one of the cups, I don't mind which.",
  "There are several cups lying around. Bring me to one of them.",
]),
(FD, "o", 21, [21, 22], [
  "Take me to the bar seats.",
  "Where are the stools?",
  "backless seats",
  "I need a high seat without a back. Any of them.",
  "Can you show me the little backless seats in the flat?",
  "Go to one of the perches at the kitchenette, either is fine.",
]),
(FG, "or", 34, [34, 35], [
  "Take me to a lamp in the bedroom.",
  "Could you show me the bedside lights in the bedroom?",
  "bedroom reading lights",
  "It's dark in the bedroom. Take me to one of the lights in there.",
  "Go to a bedroom light, either side.",
  "Which lamps are in the main bedroom? Take me to one.",
]),
(FF, "or", 12, [12, 13, 14, 15], [
  "Take me to a chair in the kitchen.",
  "Could you find me a seat at the kitchen table?",
  "kitchen seats",
  "I want to sit down in the kitchen. Bring me to a seat there, any colour.",
  "Where are the kitchen *chiars?",
  "Go to one of the seats around the farmhouse table in the kitchen.",
]),
(FH, "or", 46, [46, 47], []),  # placeholder, replaced below
(FH, "od", 30, [30], [
  "Take me to the green banker's lamp.",
  "Could you find the desk light with the green glass shade?",
  "green glass shade desk light",
  "It's a brass light with a green shade and a pull chain. Take me there.",
  "Not the red one or the white one, the green *lampp.",
  "I'd like the old-fashioned library-style light with the green glass.",
]),
(FF, "od", 14, [14], [
  "Take me to the mustard yellow chair.",
  "Which seat is the odd yellow one? Go there.",
  "yellow painted seat",
  "Not one of the blue ladder-backs, the yellow one.",
  "This is a wooden seat painted mustard. It doesn't match the others.",
  "Go to the yellow *chiar.",
]),
(FD, "od", 22, [22], [
  "Take me to the wooden perch in the kitchenette.",
  "Could you go to the seat with the round wooden top?",
  "wood stool round seat",
  "Not the black metal one, the wooden bar seat.",
  "This is a plain wooden stool. It has a round seat.",
  "I'd like the timber seat, the round one.",
]),
(FG, "ord", 34, [34], [
  "Take me to the teal lamp in the bedroom.",
  "Is there a bedside light with a teal glass base in the bedroom? Go there.",
  "teal glass bedside light bedroom",
  "Not the beige ceramic one, the teal glass light in the bedroom.",
  "It's a bedside lamp with a blue-green glass base. It's in the bedroom.",
  "Go to the bedroom light with the teal base.",
]),
(FB, "ord", 2, [2], [
  "Take me to the yellow velvet armchair in the living room.",
  "Could you show me the mustard chair in the lounge?",
  "yellow armchair living room",
  "Not the brown leather one, the yellow velvet seat in the living room.",
  "It's a mustard velvet chair. It sits in the living room.",
  "Go to the yellow *armcahir in the lounge.",
]),
(FD, "ard", 27, [27], [
  "My shirt is all wrinkled.",
  "I need to press my trousers before the interview.",
  "press clothes",
  "These creases won't come out on their own. Where can I flatten them?",
  "I have to get the creases out of my dress.",
  "Help me smooth out this crumpled blouse.",
]),
(FF, "ard", 25, [25], [
  "I want to look at the stars tonight.",
  "Is there anything here for watching the night sky?",
  "stargazing",
  "The sky is so clear. I'd love a closer view of the moon.",
  "I want to see Saturn's rings up close.",
  "Where can I peer at the planets?",
]),
(FG, "ard", 1, [1], [
  "I need to drive to the shops.",
  "I've got to drive to the station quickly. Where's the family runabout?",
  "go for a drive",
  "I'm late for work. I need wheels with an engine.",
  "Where do we keep the motor? I have to pick up the kids.",
  "I have to drive to the airport.",
]),
(FB, "s", 7, [7], [
  "Take me to the lamp on the side table.",
  "Could you go to the small light sitting on the little round table next to the sofa?",
  "light on the side table",
  "There's a small table at the east end of the couch. The light on it is the one I want.",
  "Not the tall floor light, the one standing on top of the little table.",
  "Go to the table *lmap at the end of the sofa.",
]),
(FH, "s", 47, [47], [
  "Take me to the bedside table with the book on it.",
  "Standing at the foot of the double bed and facing it, which bedside table is on the right? Go there.",
  "nightstand right of double bed",
  "There are two bedside tables by the big bed. I want the one holding the paperback.",
  "Facing the master bed from its foot, the bedside table on your right.",
  "Not the one with the lamp, the *nighstand with the novel on top.",
]),
(FG, "s", 18, [18], [
  "Take me to the kitchen chair closest to the worktop.",
  "Which seat at the kitchen table is nearest the counter? Go there.",
  "seat nearest the counter",
  "The kitchen table has two seats. I want the one on the worktop side.",
  "Go to the seat between the table and the sink.",
  "Not the one on the far side of the table, the one nearer the cooker and sink.",
]),
(FD, "s", 21, [21], [
  "Take me to the stool nearest the bin.",
  "Which of the two bar seats is closer to the trash? Go there.",
  "bar seat closest to bin",
  "There are two bar seats in the kitchenette. I'd like the one next to the pedal bin.",
  "Go to the high seat on the bin side.",
  "Not the one further from the rubbish bin, the nearer *stoool.",
]),
# ---------------- apartment + scans ----------------
(APT, "o", 1, [1, 2], [
  "Take me to a couch.",
  "Could you show me the settees?",
  "couches",
  "I want to lie down on a settee. Any one will do.",
  "Where are the *cocuhes in this flat?",
  "Go to one of the sofas, whichever.",
]),
(APT, "or", 12, [12, 13], [
  "Take me to the books in the living room.",
  "Could you show me a novel in the lounge?",
  "living room reading material",
  "I'd like something to read while I'm in the living room. Where are the novels there?",
  "Go to one of the *boks on the living room shelves.",
  "Any of the novels in the sitting room is fine.",
]),
(APT, "or", 23, [23, 24], [
  "Take me to a chair in the kitchen.",
  "Could you find me a seat at the kitchen table?",
  "kitchen dining seats",
  "I want to sit down and eat in the kitchen. Show me a seat there.",
  "Where are the dining seats in the kitchen?",
  "Go to any seat in the kitchen.",
]),
(SL, "od", 6, [6], [
  "Take me to the brown leather armchair.",
  "Could you go to the leather chair?",
  "brown leather seat",
  "Not the green one, the brown leather one.",
  "This is a brown chair. It's made of leather.",
  "The one covered in brown leather, please.",
]),
(APT, "ord", 2, [2], [
  "Take me to the brown leather loveseat in the living room.",
  "Could you show me the small brown couch in the lounge?",
  "brown leather sofa living room",
  "Not the big gray one, the little leather two-seater in the living room.",
  "This is a brown leather settee. It's in the living room against the wall.",
  "Go to the leather *couhc in the lounge.",
]),
(APT, "ord", 53, [53], [
  "Take me to the gray metal filing cabinet in the office.",
  "Could you go to the metal drawer unit in the study?",
  "grey file drawers office",
  "Not the white kitchen cupboards, the gray metal one in the office.",
  "It's a gray metal unit with two drawers. It's in the office, under the printer.",
  "Go to the office filing *cabniet.",
]),
(APT, "ord", 52, [52], [
  "Take me to the green book in the office.",
  "Could you find the thick green textbook in the study?",
  "green programming textbook office",
  "Not the red or yellow ones, the green volume in the office.",
  "It's a thick green manual on coding. It's on the office shelf.",
  "I need my green *texbook from the office.",
]),
(APT, "ard", 27, [27], [
  "I'd like a cup of tea.",
  "I want a pot of tea, what boils water fastest around here?",
  "boil water",
  "I'm cold. I want to make a hot drink.",
  "Could you take me to whatever heats water for coffee?",
  "Fancy a cuppa? Show me what to boil the water in.",
]),
(SO, "ard", 25, [25], [
  "I need to print out my boarding pass.",
  "Where can I get a paper copy of this document?",
  "print document",
  "My boss wants a hard copy of the report. Where do I get one?",
  "I have to make a printout of these slides.",
  "Where do I pick up the pages I just sent to print?",
]),
(SO, "s", 7, [7], [
  "Take me to the blue office chair closest to the windows.",
  "Of the two blue chairs, which is nearer the windows? Go there.",
  "blue chair nearest window",
  "There are two blue swivel chairs. I want the one by the window wall.",
  "Not the blue seat on the far side of the desk, the one near the glass.",
  "Go to the blue seat by the windows.",
]),
(SO, "s", 29, [29], [
  "Take me to the keyboard on the white table.",
  "Could you find the keys lying on the white desk?",
  "typing board on white table",
  "There are two of them. I want the one on the white table, not the wooden one.",
  "It's a black thing you type on. It sits on the white table.",
  "Go to the *keybaord on the white desk.",
]),
(SO, "s", 15, [15], [
  "Take me to the middle bookshelf.",
  "Which bookcase is between the other two? Go there.",
  "middle of three bookshelves",
  "There are three bookcases along the back wall. I want the one in the middle.",
  "Go to the shelf unit between the small white one and the other brown one.",
  "Not the end ones, the bookcase in the centre.",
]),
(SL, "s", 3, [3], [
  "Take me to the cushion in the middle of the sofa.",
  "Which pillow is between the two red ones? Go there.",
  "middle cushion on couch",
  "There are three cushions on the couch. I want the centre one.",
  "Not the ones at the ends, the cushion in between them.",
  "Go to the centre *pilow on the sofa.",
]),
(SL, "s", 10, [10], [
  "Sitting on the sofa facing the TV, take me to the lamp on the left side table.",
  "Facing the television from the couch, which side-table light is on my left? Go there.",
  "left side table light, facing TV",
  "There are two small lights at the ends of the couch. From the sofa looking at the TV, I want the left one.",
  "Not the floor lamp and not the right-hand one, the left table lamp when you face the TV.",
  "Looking at the telly from the settee, go to the light on your left.",
]),
(SK, "s", 21, [21], [
  "Take me to the chair closest to the door.",
  "Which seat at the table is nearest the door? Go there.",
  "seat nearest door",
  "There are six seats round the table. I'd like the one at the end by the door.",
  "Not the one at the far end, the red seat at the door end of the table.",
  "Go to the seat at the door end of the table.",
]),
(SK, "s", 25, [25], [
  "Take me to the cup on the counter next to the sink.",
  "Could you find the mug that's by the sink, not on the table?",
  "mug beside sink",
  "There are three of them. I want the drinking vessel on the worktop near the sink.",
  "Not the ones on the dining table, the mug next to the sink.",
  "Go to the cup sitting on the counter by the sink.",
]),
(APT, "s", 39, [39], [
  "Take me to the plant on top of the dresser.",
  "Could you find the little succulent sitting on the chest of drawers?",
  "potted succulent on dresser",
  "There's a chest of drawers in the bedroom. I want the pot on top of it.",
  "Not the big fig or the tall one in the office, the small pot on the drawers.",
  "Go to the *succlent on the chest of drawers.",
]),
]

# the flat_h or group (nightstands in the master bedroom)
G[18] = (FH, "or", 46, [46, 47], [
  "Take me to a bedside table in the master bedroom.",
  "Could you show me the nightstands in the main bedroom?",
  "master bedroom bedside tables",
  "I put my glasses down in the big bedroom. Go to one of the bedside tables there.",
  "Where's a *nighstand in the master bedroom? Either side.",
  "Go to one of the little tables next to the double bed.",
])


def main() -> None:
    rows, typos = [], []
    assert len(G) == 48, len(G)
    for n, (m, t, target, accept, words) in enumerate(G, 1):
        assert len(words) == 6, (n, len(words))
        gid = f"b25-g{n:02d}"
        for k, q in enumerate(words, 1):
            if "*" in q:
                q = q.replace("*", "")
                typos.append((f"{gid}-w{k}", q))
            rows.append({"id": f"{gid}-w{k}", "map": m, "query": q, "type": t, "target": target,
                         "accept": accept, "group": gid})
    OUT.write_text("".join(json.dumps(r) + "\n" for r in rows), encoding="utf-8")
    print(len(rows), "lines")
    (HERE / "typos.txt").write_text("".join(f"{i}\t{q}\n" for i, q in typos))


if __name__ == "__main__":
    main()
