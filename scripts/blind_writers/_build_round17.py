"""Generate evals/blind/round17.jsonl (48 groups x 6 wordings). Wordings hand-written; a leading '*'
marks a wording with a deliberate typo (stripped on output, listed in the notes)."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SOFF = "../maps/scan_office.json"
SBED = "../maps/scan_bedroom.json"
FD, FF, FG, FI = ("maps/flat_%s.json" % c for c in "dfgi")

G = [
 # ---- scene_00829 (caption) ----
 (C829, "o", 112, [112, 157, 219, 229, 233], [
  "Take me to a mirror.",
  "Could you bring me to one of the mirrors in the house?",
  "mirror, any",
  "I want to check my hair before I head out. Where's a looking glass?",
  "Go to a framed mirror please",
  "*Can you find me a mirrror?"]),
 (C829, "or", 261, [261, 263], [
  "Take me to an armchair in the bedroom.",
  "Could you show me where the comfy lounge chairs in the bedroom are?",
  "bedroom armchair",
  "I'd like to sit and read in the bedroom. Take me to one of the easy chairs there.",
  "There are a couple of cushy armchairs in the bedroom. Go to one of them.",
  "*armchiar in the bedroom pls"]),
 (C829, "od", 184, [184], [
  "Go to the L-shaped sofa with the chaise.",
  "Could you take me to the corner sofa that has a built-in chaise longue?",
  "L-shaped couch, beige fabric",
  "I'm looking for a settee. It's the L-shaped one with a storage compartment.",
  "The one shaped like an L, with the lounger end - take me there.",
  "L-shaped sofa, not the one with the massage motor"]),
 (C829, "od", 211, [211], [
  "Take me to the deep blue bowl with gold patterns.",
  "Where's the blue ceramic bowl, the ornamental one?",
  "blue glazed bowl gold trim",
  "There's an ornamental dish that's deep blue. Bring me to it.",
  "Not the white sweets dish - the blue one with the golden pattern.",
  "*Could you guide me to the dark blue bwol?"]),
 (C829, "ord", 138, [138], [
  "In the bedroom, take me to the doorway with the round white handle.",
  "Could you bring me to the bedroom door that has a white circular knob?",
  "bedroom door, white round knob",
  "I'm after a door in the bedroom. It's dark wood and the handle is a white circle.",
  "The bedroom door - not the one with the sliding lock, the one with the white handle.",
  "*Which bedroom dorr has the white knob? Go there."]),
 (C829, "ard", 122, [122], [
  "I really need to pee.",
  "Sorry, where can I relieve myself?",
  "need the loo",
  "I've been holding it for an hour. Please take me where I can go.",
  "Could you point me to the WC?",
  "nature calls, take me to the john"]),
 (C829, "ard", 192, [192], [
  "My puppy is worn out, where can he curl up?",
  "Take me to where the cat sleeps.",
  "somewhere for the dog to nap",
  "I brought my dog along and she needs a rest. Where's her own little sleeping spot?",
  "Could you show me the spot made for the animals to sleep in?",
  "Where does the kitty snooze at night?"]),
 # ---- scene_office3 (caption) ----
 (OFF3, "o", 35, [32, 35, 36, 37, 42, 44, 48, 59, 60, 65, 66, 69, 70, 71, 74, 82, 86, 87], [
  "Take me to a chair.",
  "I need a seat, any office seat will do.",
  "somewhere to sit - a chair",
  "Could you bring me to one of the seats around here?",
  "My legs are tired after the meeting. Find me a desk seat, whichever.",
  "*Go to a chiar."]),
 (OFF3, "od", 13, [13], [
  "Take me to the navy blue velvet cushion.",
  "Could you find the dark blue pillow with the button?",
  "navy cushion, velvet",
  "I want the soft blue pillow. It's the velvety one, a bit bigger than the others.",
  "Not the orange or yellow ones - the navy cushion.",
  "*Where's the blue pilow?"]),
 (OFF3, "od", 40, [40], [
  "Go to the orange cushion with the stripes.",
  "Could you show me the striped orange pillow?",
  "orange cushion, white and yellow stripes",
  "There's an orange pillow on the couch. I mean the one with white and yellow stripes.",
  "The orange one, not the plain one with a button - the stripy cushion.",
  "*I want the stripey orange cusion."]),
 (OFF3, "ord", 7, [7], [
  "In the rec room, take me to the white desk.",
  "Could you bring me to the white wooden writing table in the rec room?",
  "rec room, white desk",
  "I'm after a work table in the rec room. It's the white one, not the brown ones.",
  "Head to the recreation room and find the white-painted bureau.",
  "*the white one of the deks in the rec room"]),
 (OFF3, "ard", 25, [25], [
  "What time is it? Take me to where I can check.",
  "I'm worried I'll miss my bus; where can I see the time?",
  "need to know the time",
  "Could you show me something on the wall that tells the hour?",
  "My phone died and I want to know how late it is.",
  "Where can I check the time in here?"]),
 (OFF3, "ard", 3, [3], [
  "I'm exhausted and want to stretch out for a nap.",
  "Where could I lie down for a bit?",
  "somewhere to lie down",
  "My back hurts from sitting. Is there anywhere I can lie flat and rest?",
  "Could you take me somewhere comfy to doze off for twenty minutes?",
  "need a lie-down, something soft and long"]),
 # ---- flat_d ----
 (FD, "o", 8, [8, 9, 34], [
  "Take me to a lamp.",
  "Could you show me where the lights are?",
  "any lamp",
  "It's getting dark in here. Bring me to one of the lights I can switch on.",
  "Find me a reading light, doesn't matter which.",
  "*go to a lmap"]),
 (FD, "or", 4, [4, 5, 7], [
  "Take me to a chair in the studio.",
  "Could you bring me to one of the seats in the main studio room?",
  "studio seat",
  "I want to sit down in the studio. Any chair there is fine.",
  "In the studio there are a few seats. Take me to one.",
  "a seat in the studio plz, any of them"]),
 (FD, "ord", 22, [22], [
  "In the kitchenette, take me to the wooden stool.",
  "Could you find the wooden bar seat in the kitchenette?",
  "kitchenette stool, wood not metal",
  "I'm looking for a seat in the kitchenette. It's the one made of wood with a round top.",
  "Not the black metal one - the brown wooden perch in the kitchenette.",
  "*wooden stoool in the kitchenette"]),
 (FD, "ard", 27, [27], [
  "My shirt is all creased; I need to press it.",
  "Where can I get the wrinkles out of my trousers?",
  "need to iron clothes",
  "I have a job interview in an hour and my blouse is crumpled. Take me where I can fix that.",
  "Could you take me to where I can do some pressing?",
  "somewhere to smooth out a wrinkled dress"]),
 (FD, "s", 4, [4], [
  "Take me to the chair closest to the TV.",
  "Could you bring me to the seat nearest the television?",
  "seat nearest tv",
  "There's a TV on the north wall of the studio. Go to the chair nearest to it.",
  "The seat at the round table that's nearer the telly, not the yellow one.",
  "the white seat by the round table, the side toward the television"]),
 # ---- flat_f ----
 (FF, "o", 2, [2, 3], [
  "Take me to an armchair.",
  "Could you show me one of the big upholstered single seats?",
  "armchair, either one",
  "I want to sit by myself with a book. Take me to a comfy chair with arms.",
  "Where are the overstuffed easy chairs in the lounge?",
  "*an armchiar please"]),
 (FF, "or", 12, [12, 13, 14, 15], [
  "Take me to a chair in the kitchen.",
  "Could you bring me to one of the dining seats in the kitchen?",
  "kitchen chair",
  "We're about to eat. Show me a seat at the kitchen table.",
  "Any of the seats around the farmhouse table in the kitchen will do.",
  "*kitchen seet, any"]),
 (FF, "od", 14, [14], [
  "Take me to the mustard yellow chair.",
  "Could you find the yellow painted seat, the odd one out?",
  "yellow chair",
  "I'm after a wooden seat. It's the yellow one among the blue ones.",
  "Not a blue one - the mustard-coloured seat please.",
  "the one painted yellow at the dining table"]),
 (FF, "ard", 25, [25], [
  "I'd love to look at the stars tonight.",
  "Where can I get a closer view of the moon?",
  "stargazing",
  "There's a meteor shower later. Take me to what I'd need to watch it properly.",
  "Could you bring me to the thing for looking at planets?",
  "want to see Saturn's rings up close"]),
 # ---- flat_g ----
 (FG, "o", 10, [10, 37, 45], [
  "Take me to a basket.",
  "Could you find me one of the baskets in the house?",
  "any hamper",
  "I need something to carry these toys in. Take me to a hamper.",
  "Where is a laundry or toy hamper?",
  "*bakset please"]),
 (FG, "or", 34, [34, 35], [
  "Take me to a lamp in the bedroom.",
  "Could you bring me to one of the bedside lights in the bedroom?",
  "bedroom lamp",
  "I want to read in bed. Show me one of the lights in the bedroom.",
  "Go to the bedroom and find a reading light there.",
  "bedroom light, either side"]),
 (FG, "ord", 44, [44], [
  "In the kids' room, take me to the yellow lamp.",
  "Could you find the bendy yellow light in the children's room?",
  "kids room yellow desk light",
  "I'm looking for a light in the kids room. It's yellow and you can bend it.",
  "The little yellow lamp in the children's bedroom, please.",
  "*yellow lampp in the kids room"]),
 (FG, "ard", 8, [8], [
  "The laundry is washed and soaking wet; I need to dry it quickly.",
  "Where can I tumble my wet towels?",
  "dry wet clothes fast",
  "It's raining so I can't hang the washing outside. Take me to what will get it dry.",
  "Could you show me the machine that dries clothes?",
  "my socks are damp, need them dry"]),
 (FG, "s", 32, [32], [
  "Standing at the foot of the bed facing the headboard, take me to the bedside table on the left.",
  "Facing the head of the bed, which nightstand is on your left? Go to that one.",
  "bedside table, left side when facing the headboard",
  "There are two bedside tables. I mean the one on the left when you look at the bed from its foot.",
  "The bedside table on the west side of the bed.",
  "*left nighstand, looking at the bed from the foot"]),
 (FG, "s", 2, [2], [
  "Take me to the bigger bike.",
  "Could you bring me to the larger of the two bicycles?",
  "big bike, not the kids' one",
  "There are two bikes in the garage. I mean the full-size one.",
  "The larger bicycle, please.",
  "*the bigger bkie"]),
 # ---- flat_i ----
 (FI, "o", 1, [1, 11, 24, 47], [
  "Take me to a door.",
  "Could you show me one of the doors?",
  "any doorway",
  "I want to step out for a moment. Take me to an exit, any of them.",
  "Bring me to one of the entrances.",
  "*a dooor, any"]),
 (FI, "or", 6, [6, 7, 8, 9], [
  "Take me to a chair in the meeting room.",
  "Could you find me a seat in the conference room?",
  "meeting room seat",
  "The client is coming and I want to sit down in the meeting room. Any seat will do.",
  "One of the chairs around the glass table in the meeting room.",
  "meeting room, somewhere to sit, any of the four"]),
 (FI, "or", 45, [45, 46], [
  "Go to one of the bedroom lamps.",
  "Could you take me to a bedside light in the bedroom?",
  "bedroom light",
  "I can't see to read in bed. Bring me to one of the bedroom lights.",
  "Either of the lights on the bedside tables in the bedroom.",
  "lamp in bedroom, whichever"]),
 (FI, "ord", 43, [43], [
  "In the bedroom, take me to the oak bedside table.",
  "Could you bring me to the wooden nightstand with the open shelf in the bedroom?",
  "bedroom, oak nightstand",
  "I'm after a bedside table in the bedroom. It's the natural oak one, not the white one.",
  "The light-wood bedside cabinet in the bedroom, please.",
  "oak bedside table in the bedroom, the one with the shelf"]),
 (FI, "od", 18, [18], [
  "Take me to the lamp with the green glass shade.",
  "Could you find the banker's light with the green shade?",
  "green glass desk light",
  "I'm looking for an old-fashioned desk light. It has a green glass shade.",
  "Not the black floor one or the bedside ones - the green banker's lamp.",
  "*the green bankers lmap"]),
 (FI, "s", 36, [36], [
  "Take me to the mug on the coffee table.",
  "Could you bring me to the cup sitting on the low table in the living room?",
  "cup on coffee table",
  "There's a cup on the low table in front of the sofa. Go to it.",
  "The one on the coffee table, not the mugs in the kitchen or studio.",
  "the cup left on the teak table by the sofa"]),
 (FI, "s", 15, [15], [
  "Take me to the chair at the white desk.",
  "Could you find the seat pulled up to the plain white desk in the studio?",
  "seat at white desk",
  "There's a white desk in the studio. Bring me to the seat in front of it.",
  "The chair right by the white desk, not the one at the oak desk.",
  "the seat closest to the white desk with the cable tray"]),
 # ---- apartment ----
 (APT, "or", 12, [12, 13], [
  "Take me to a book in the living room.",
  "Could you show me one of the books in the lounge?",
  "living room reading material",
  "I want something to read on the sofa. Bring me to a volume in the living room.",
  "any of the hardbacks or photo albums in the living room",
  "*living room boook"]),
 (APT, "ord", 48, [48], [
  "In the office, take me to the red leather chair.",
  "Could you bring me to the red swivel seat in the office?",
  "office red chair",
  "I'm looking for a seat in the office. It's red leather with wheels.",
  "The red seat with armrests in the office, please.",
  "red leather desk seat, office"]),
 (APT, "ard", 27, [27], [
  "I'd like to make a cup of tea.",
  "Where can I boil some water quickly?",
  "boil water for tea",
  "I'm freezing and want a hot drink. Take me to what heats water.",
  "Could you bring me to what I'd use to get water boiling for instant noodles?",
  "fancy a cuppa, where do I start?"]),
 (APT, "od", 2, [2], [
  "Take me to the brown leather loveseat.",
  "Could you bring me to the small brown leather couch?",
  "brown leather sofa, two-seater",
  "I'm after a couch. It's the small brown leather one against the wall.",
  "Not the big gray one - the little leather sofa.",
  "*the brown two-seat cuoch"]),
 (APT, "s", 7, [7], [
  "Take me to the lamp next to the sofa.",
  "Could you find the light standing beside the couch?",
  "light by the sofa",
  "There's a big gray couch in the living room. Take me to the light right next to it.",
  "The lamp beside the sofa, not the bedside or desk one.",
  "floor light in the corner near the couch"]),
 (APT, "s", 42, [42], [
  "Take me to the cabinet under the washbasin.",
  "Could you bring me to the cupboard beneath the bathroom sink?",
  "cupboard under bathroom basin",
  "There's a washbasin in the bathroom. Go to the cupboard right below it.",
  "the vanity underneath the basin, not the cupboards above the kitchen counter",
  "*cabniet under the washbasin"]),
 # ---- scan_office ----
 (SOFF, "o", 22, [21, 22], [
  "Take me to a bin.",
  "Could you show me where the rubbish bins are?",
  "trash can, any",
  "I have a banana peel to throw away. Take me to a trash can.",
  "Find me a wastebasket.",
  "*garbage binn"]),
 (SOFF, "s", 21, [21], [
  "Take me to the bin by the door.",
  "Could you bring me to the wastebasket next to the door, not the one in the far corner?",
  "bin near door",
  "There's a door on the east side. Go to the trash can beside it.",
  "the rubbish bin closest to the exit",
  "the trash can by the doorway"]),
 (SOFF, "s", 15, [15], [
  "Take me to the middle bookshelf.",
  "Could you find the bookcase between the other two?",
  "bookcase in the middle of the three",
  "There are three bookcases along the back wall. I want the one in the middle.",
  "Not the white one at the end or the first brown one - the middle shelving unit.",
  "the bookshelf in between the other bookcases"]),
 (SOFF, "s", 11, [11], [
  "Take me to the monitor on the white table.",
  "Could you bring me to the screen sitting on the white desk?",
  "screen on white table",
  "There's a white table and a brown one. Go to the computer screen on the white one.",
  "The display on the white table, not the ones on the wooden table.",
  "*monitr on the white table"]),
 # ---- scan_bedroom ----
 (SBED, "ord", 4, [4], [
  "In the bedroom, take me to the red pillow.",
  "Could you find the red cushion on the bed in the bedroom?",
  "bedroom red cushion",
  "I'm after a cushion in the bedroom. It's the red one, not the white or blue ones.",
  "The red throw pillow in the bedroom, please.",
  "red scatter cushion, bedroom"]),
 (SBED, "s", 8, [8], [
  "Take me to the lamp farthest from the door.",
  "Could you bring me to the bedside light on the side away from the door?",
  "light farthest from door",
  "There are two bedside lights. Go to the one farther from the bedroom door.",
  "Not the light near the door - the other one, next to the little clock.",
  "the farther lamp from the door"]),
 (SBED, "s", 7, [7], [
  "Take me to the nightstand with the book on it.",
  "Could you bring me to the bedside table that has a book lying on top?",
  "bedside table with book",
  "There's a blue book on one of the bedside tables. Go to that table.",
  "Not the one with the clock - the bedside table holding the book.",
  "*nighstand with the blue book on top"]),
]


def main():
    out = Path(__file__).resolve().parent.parent / "evals" / "blind" / "round17.jsonl"
    lines, typos = [], []
    for n, (mp, typ, tgt, acc, words) in enumerate(G, 1):
        assert len(words) == 6, n
        rot = (n * 5) % 6  # vary which style/typo sits at which wording index
        words = words[rot:] + words[:rot]
        for k, w in enumerate(words, 1):
            rid = "b17-g%02d-w%d" % (n, k)
            if w.startswith("*"):
                w = w[1:]
                typos.append((rid, w))
            lines.append(json.dumps({"id": rid, "map": mp, "query": w, "type": typ, "target": tgt,
                                     "accept": sorted(acc), "group": "b17-g%02d" % n}, ensure_ascii=False))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(len(G), "groups,", len(lines), "lines ->", out)
    print("typos:", len(typos))
    for t in typos:
        print("  ", t[0], "|", t[1])


if __name__ == "__main__":
    main()
