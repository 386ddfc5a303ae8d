"""Write evals/blind/round54.jsonl from the hand-written groups below (blind helper, round 54)."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

# (map, type, target, accept, [w1..w6], (typo, intended word))
GROUPS = [
 # ---- scene_00829 (caption map) ----
 (C829, "o", 42, [42, 197, 212, 259], [
  "Take me to one of the books lying around.",
  "Could you guide me to something I can read, like a hardback volume?",
  "Any novel or hardback, please",
  "I want to read for a while, so bring me to a bound volume, not a loose sheet of paper.",
  "This is going to be a quiet evening. Lead me to something bound that I can read.",
  "just get me to any bok lying around, i feel like reading"], ("bok", "book")),
 (C829, "or", 261, [261, 263], [
  "Go to an armchair in the bedroom.",
  "Could you bring me over to one of the armchairs in the bedroom?",
  "Bedroom armchair",
  "I want to sit down comfortably in the bedroom, so an armchair there, not the couch.",
  "This is where I like to unwind before bed. Take me to an easy chair in the bedroom.",
  "can you get me to one of the armchiars in the bedroom"], ("armchiars", "armchairs")),
 (C829, "od", 184, [184], [
  "Take me to the L-shaped sofa with the chaise end.",
  "Could you lead me to the corner settee that has a built-in chaise?",
  "L-shaped beige settee",
  "I want to stretch my legs out, so the L-shaped one with the chaise, not the massaging couch.",
  "This is the big beige corner sofa with a lounger at one end. Please head over to it.",
  "go to the l-shaped sofa with the lounging end, the biege one"], ("biege", "beige")),
 (C829, "od", 164, [164], [
  "Go to the towels embroidered with the letter H.",
  "Could you find the folded towels that have an H stitched on them?",
  "Towels with embroidered H",
  "I'm after the monogrammed towels with the H, not the plain folded ones.",
  "This is about the monogrammed towel stack. Take me to the pile with the letter H sewn on.",
  "take me to the towels with the big h embroidred on them"], ("embroidred", "embroidered")),
 (C829, "ord", 191, [191], [
  "Take me to the beige velvet armchair in the bathroom.",
  "Could you go to the soft cream-coloured lounge chair that sits in the bathroom?",
  "Bathroom beige velvet armchair",
  "The one in the bathroom, not the beige chairs in the living room, because that's where I left my robe.",
  "This is the curvy velvet armchair in beige. Find the one in the bathroom for me.",
  "go to the beige velvet armchair in the bathrom"], ("bathrom", "bathroom")),
 (C829, "ard", 192, [192], [
  "Take me to where the dog sleeps.",
  "Could you show me the spot where our pet curls up to sleep?",
  "Pet's sleeping spot",
  "The puppy is tired, so take me to the place where animals nap, not where people sleep.",
  "This is for the cat, who looks sleepy. Take me to the cosy place made for her to snooze.",
  "where does the dog snooze, take me to his comfy spott"], ("spott", "spot")),
 # ---- scene_office3 (caption map) ----
 (OFF3, "o", 13, [8, 13, 20, 40], [
  "Go to a cushion.",
  "Could you take me to any of the throw pillows?",
  "Any cushion",
  "My back hurts, so I need a cushion, any colour is fine.",
  "This is for propping up my back. Bring me to one of the cushions.",
  "take me to a cushon, whichever is closest"], ("cushon", "cushion")),
 (OFF3, "or", 7, [7, 55, 64], [
  "Head to a desk in the rec room.",
  "Could you take me to one of the work desks in the recreation room?",
  "Rec room workstation",
  "I have paperwork to get through, so one of the workstations in the rec room, not the sofa.",
  "This is for some homework. Lead me to a workstation in the rec room.",
  "take me to a workstaton in the rec room"], ("workstaton", "workstation")),
 (OFF3, "od", 40, [40], [
  "Go to the orange cushion with white and yellow stripes.",
  "Could you find the striped orange pillow for me?",
  "Orange striped cushion",
  "I want the stripy orange one, not the orange cushion with the button.",
  "This is the orange cushion that has stripes on it. Take me to it.",
  "take me to the orange cushion with the yelow and white stripes"], ("yelow", "yellow")),
 (OFF3, "ord", 42, [42], [
  "Take me to the brown seat in the rec room.",
  "Could you head to the brown leather chair in the rec room?",
  "Brown seat, rec room",
  "Not the black mesh ones, the brown chair in the rec room, since it's the only one I like.",
  "This is the brown one without armrests. Go to it in the rec room.",
  "go to the brown seat in the rec room, the lether one"], ("lether", "leather")),
 (OFF3, "ard", 9, [9], [
  "Take me to where I can look at the world map.",
  "Could you bring me somewhere I can see the map of the world?",
  "World map, please",
  "I need to check where Lisbon is, so take me to wherever the world map is shown.",
  "This is for planning our trip. Go where the world map is showing in the rec room.",
  "take me to whatever shows the wrold map"], ("wrold", "world")),
 (OFF3, "ard", 25, [25], [
  "Go to where I can see the time on the wall.",
  "Could you take me to whatever on the wall tells the time?",
  "Check time on wall",
  "I'm worried I'm late, so I need to read the hour somewhere on the wall.",
  "This is urgent, I might be late. Take me to something on the wall that shows the hour.",
  "what time is it, take me to the thing on the wal with the second hand"], ("wal", "wall")),
 # ---- flat_b ----
 (FB, "o", 5, [5, 7, 26, 33, 34], [
  "Take me to a lamp.",
  "Could you lead me to any light I can switch on?",
  "Any lamp at all",
  "It's getting dark, so I need a light, any of them will do.",
  "This is too dim to read in. Go to one of the lights.",
  "getting dark here, take me to a lmap please"], ("lmap", "lamp")),
 (FB, "ord", 22, [22], [
  "Go to the white plastic seat in the kitchen.",
  "Could you take me to the white moulded chair by the kitchen table?",
  "White plastic kitchen seat",
  "I want the white plastic one in the kitchen, not the brown wooden chairs.",
  "This is the white seat at the dining table in the kitchen. Take me there.",
  "go to the white plastik seat in the kitchen"], ("plastik", "plastic")),
 (FB, "ard", 29, [29], [
  "Take me to where I can hang my jacket in the hallway.",
  "Could you show me where coats get hung up in the hall?",
  "Hang jacket, hallway",
  "I'm dripping wet, so I need to hang up my coat by the entrance, not in the bedroom.",
  "This is my wet raincoat. Bring me to the spot in the hallway for hanging it.",
  "where do i hang my jaket in the hallway, take me there"], ("jaket", "jacket")),
 (FB, "s", 31, [31], [
  "Go to the bedside table nearest the bedroom window.",
  "Could you take me to the nightstand on the window side of the bed?",
  "Bedside table by window",
  "I left my glasses on the bedside table near the window, not the other one.",
  "This is the bedside table closest to the window in the bedroom. Head there.",
  "go to the nightstand next to the bedrom window"], ("bedrom", "bedroom")),
 # ---- flat_e ----
 (FE, "or", 11, [11, 12, 13, 14, 15], [
  "Take me to a chair in the dining room.",
  "Could you go to any seat in the dining room?",
  "Dining room seat",
  "Dinner's ready, so I need a seat in the dining room, not the sofa.",
  "This is dinner time. Bring me to one of the dining room chairs.",
  "take me to any seat in the dinning room"], ("dinning", "dining")),
 (FE, "ord", 38, [38], [
  "Go to the little white metal table out on the balcony.",
  "Could you take me to the small round bistro set on the balcony, the white metal one?",
  "White metal balcony tabletop",
  "I want my coffee outside, so the round white table on the balcony, not the oak dining one.",
  "This is where I like breakfast in summer. Take me to the small white metal bistro set on the balcony.",
  "take me to the litle round white bistro thing on the balcony"], ("litle", "little")),
 (FE, "ard", 15, [15], [
  "Take me to where the baby sits to eat in the dining room.",
  "Could you go to the spot where we feed the baby at the dining table?",
  "Where baby eats, dining room",
  "It's the toddler's lunchtime, so take me to where she sits for meals, not where the grown-ups sit.",
  "This is lunchtime for the little one. Bring me to the place in the dining room where she gets fed.",
  "take me to where the bbay eats in the dining room"], ("bbay", "baby")),
 (FE, "s", 16, [16], [
  "Go to the light hanging above the dining table.",
  "Could you take me to the lamp that dangles over the dining table?",
  "Pendant light over dining table",
  "The bulb's flickering in the one over the dining table, not the floor lamp by the sofa.",
  "This is the light suspended over where we eat. Take me underneath it.",
  "go to the light hanging above the dinng table"], ("dinng", "dining")),
 # ---- flat_g ----
 (FG, "or", 2, [2, 3], [
  "Take me to a bike in the garage.",
  "Could you lead me to one of the bicycles parked in the garage?",
  "Garage bike",
  "I fancy a ride, so any bike in the garage, not the car.",
  "This is a nice day for cycling. Go to one of the bikes in the garage.",
  "take me to a bike in the garrage"], ("garrage", "garage")),
 (FG, "od", 19, [19], [
  "Go to the wooden chair with the red checked cushion.",
  "Could you find the seat that has a red gingham pad on it?",
  "Seat with red check cushion",
  "I want the wooden one with the red checked cushion, not the white plastic chair.",
  "This is the wooden seat with the red check pad. Take me to it.",
  "go to the wooden seat with the red checked cushin"], ("cushin", "cushion")),
 (FG, "ard", 11, [11], [
  "Take me to where I can iron my shirt.",
  "Could you bring me to the spot set up for pressing clothes?",
  "Press my shirt",
  "My shirt is all creased, so I need to press it before work.",
  "This is a wrinkled shirt. Take me where I can get the creases out of it.",
  "my trousers are crumpled, take me where i can iorn them"], ("iorn", "iron")),
 (FG, "s", 34, [34], [
  "Go to the bedside light closer to the wardrobe.",
  "Could you take me to the bedside lamp nearest the tall oak wardrobe?",
  "Bedside light near wardrobe",
  "I need the bedside light nearer the wardrobe, not the other one, because my book is there.",
  "This is the bedside lamp on the wardrobe side of the bed. Go to it.",
  "go to the bedside light closest to the wardobe"], ("wardobe", "wardrobe")),
 # ---- flat_i ----
 (FI, "o", 31, [23, 31, 36], [
  "Take me to a mug.",
  "Could you go to any coffee cup?",
  "Any cup",
  "I'm thirsty, so any cup will do, whichever is nearest.",
  "This is tea time. Bring me to one of the mugs.",
  "take me to a coffe cup, any one"], ("coffe", "coffee")),
 (FI, "or", 6, [6, 7, 8, 9], [
  "Go to a seat in the meeting room.",
  "Could you take me to one of the chairs in the conference room?",
  "Meeting room seat",
  "The client is about to arrive, so I need a seat in the meeting room, not the studio.",
  "This is for the client meeting. Lead me to a chair in the meeting room.",
  "take me to a seat in the meting room"], ("meting", "meeting")),
 (FI, "ord", 43, [43], [
  "Take me to the oak bedside table in the bedroom.",
  "Could you go to the wooden bedside cabinet with the open shelf in the bedroom?",
  "Oak bedside table, bedroom",
  "My phone is on the oak one in the bedroom, not the white bedside table.",
  "This is the light wood nightstand with an open shelf. Go to it in the bedroom.",
  "go to the oak bedsde table in the bedroom"], ("bedsde", "bedside")),
 (FI, "s", 17, [17], [
  "Go to the computer screen closest to the tall white shelves.",
  "Could you take me to the monitor nearer the big metal shelving unit in the studio?",
  "Screen nearest tall shelving",
  "The screen near the bookshelves, not the one by the green desk lamp.",
  "This is the computer screen on the side near the tall white shelving. Take me there.",
  "go to the computer screan closest to the big shelves"], ("screan", "screen")),
 # ---- apartment ----
 (APT, "o", 8, [8, 39, 55], [
  "Take me to a houseplant.",
  "Could you go to any potted plant?",
  "Potted greenery, any",
  "I want to water something, so take me to a houseplant, any one.",
  "This is watering day. Bring me to one of the plants.",
  "take me to a potted plnat, any of them"], ("plnat", "plant")),
 (APT, "or", 23, [23, 24], [
  "Go to a chair in the kitchen.",
  "Could you take me to one of the seats at the kitchen table?",
  "Kitchen seat",
  "I want to eat breakfast, so a seat in the kitchen, not the office one.",
  "This is breakfast time. Take me to one of the kitchen chairs.",
  "take me to a seat in the kitchn"], ("kitchn", "kitchen")),
 (APT, "od", 2, [2], [
  "Take me to the small brown leather loveseat.",
  "Could you go to the little two-seater couch in brown leather?",
  "Brown leather two-seater",
  "I want the worn leather one, not the big gray couch.",
  "This is the smaller couch, brown and a bit worn. Go to it.",
  "go to the small brown leather sette"], ("sette", "settee")),
 (APT, "ord", 52, [52], [
  "Go to the thick green textbook in the office.",
  "Could you take me to the green coding book on the office shelves?",
  "Green textbook, office",
  "I need to look up some code, so the green textbook in the office, not the red novel.",
  "This is the chunky programming manual with a green cover. Take me to it in the office.",
  "go to the green programing book in the office"], ("programing", "programming")),
 (APT, "ard", 30, [30], [
  "Take me somewhere in the hallway to check how I look before going out.",
  "Could you go to where I can see my reflection in the hall?",
  "Check outfit, hallway",
  "I'm heading out, so I want to see my reflection by the front door, not in the bathroom.",
  "This is my last check before leaving. Take me to where I can see myself in the hallway.",
  "take me where i can check my reflction in the hallway"], ("reflction", "reflection")),
 (APT, "s", 1, [1], [
  "Go to the couch under the painting.",
  "Could you take me to the sofa that sits below the framed picture?",
  "Couch beneath painting",
  "I want the couch under the painting, not the small one.",
  "This is the couch with the artwork hanging over it. Head there.",
  "go to the couch under the paintng"], ("paintng", "painting")),
 (APT, "s", 13, [13], [
  "Take me to the book sitting lowest down.",
  "Could you go to whichever volume is nearest the floor?",
  "Volume nearest floor",
  "Not the ones up high, I want the lowest book, since I can't reach the top shelves.",
  "This is the volume that sits lowest of them all. Take me there.",
  "go to the lowest volum on the shelves"], ("volum", "volume")),
 (APT, "s", 42, [42], [
  "Go to the cupboard under the washbasin.",
  "Could you take me to the cabinet right below the bathroom basin?",
  "Cupboard below basin",
  "I need fresh towels, so the cupboard under the basin, not the one above the kitchen counter.",
  "This is the cupboard tucked under the basin. Take me to it.",
  "go to the cubpoard under the sink"], ("cubpoard", "cupboard")),
 # ---- scan_bedroom ----
 (SB, "ord", 4, [4], [
  "Take me to the red cushion in the bedroom.",
  "Could you go to the red pillow in the bedroom?",
  "Red bedroom cushion",
  "The red one in the bedroom, not the white pillows.",
  "This is the red cushion on the bed. Bring me to it in the bedroom.",
  "go to the red cusion in the bedroom"], ("cusion", "cushion")),
 (SB, "s", 8, [8], [
  "Go to the bedside light nearest the window.",
  "Could you take me to the lamp on the window side of the bed?",
  "Light nearest window",
  "The lamp by the window, not the one near the door.",
  "This is the bedside light closest to the window. Take me there.",
  "go to the light by the windw"], ("windw", "window")),
 (SB, "s", 2, [2], [
  "Go to the leftmost pillow as you face the headboard from the foot of the bed.",
  "Could you take me to the cushion on the far left when looking at the head of the bed from its foot?",
  "Leftmost cushion, facing headboard",
  "Facing the headboard, I mean the cushion furthest left, not the red one in the middle.",
  "This is the leftmost cushion when you look at the bed from its foot. Take me there.",
  "from the end of the bed looking at the headbord, go to the cushion on the far left"], ("headbord", "headboard")),
 # ---- scan_kitchen ----
 (SK, "o", 26, [26, 27], [
  "Take me to a bin.",
  "Could you go to any garbage can?",
  "Any rubbish bin",
  "I have peelings to throw away, so any bin will do.",
  "This is rubbish I need to get rid of. Take me to a waste bin.",
  "take me to a trash can, i have some garbge"], ("garbge", "garbage")),
 (SK, "ard", 11, [11], [
  "Take me to where I can reheat my leftovers quickly.",
  "Could you go to something that will warm my soup up in a couple of minutes?",
  "Reheat leftovers fast",
  "My lunch has gone cold, so I need to zap it, not eat it cold.",
  "This is yesterday's pasta. Take me where I can heat it up fast.",
  "take me where i can warm up my lefovers"], ("lefovers", "leftovers")),
 (SK, "s", 3, [3], [
  "Go to the cupboard right under the sink.",
  "Could you take me to the base unit beneath the sink?",
  "Cupboard under sink",
  "The dish soap is kept under the sink, so that cupboard, not the ones beside it.",
  "This is the lower cupboard directly below the sink. Head there.",
  "go to the cupbord under the sink"], ("cupbord", "cupboard")),
 # ---- scan_livingroom ----
 (SL, "or", 8, [8, 9], [
  "Take me to a side table in the living room.",
  "Could you go to one of the little end tables in the living room?",
  "Living room end table",
  "I want to set my drink down, so an end table in the living room, not the coffee table.",
  "This is for putting my glass down. Go to one of the living room side tables.",
  "take me to an end table in the livng room"], ("livng", "living")),
 (SL, "od", 6, [6], [
  "Go to the brown leather armchair.",
  "Could you take me to the leather easy chair in brown?",
  "Brown leather easy chair",
  "I want the leather one, not the green armchair.",
  "This is the brown leather lounge chair. Take me to it.",
  "go to the brown leathr easy chair"], ("leathr", "leather")),
 (SL, "s", 10, [10], [
  "Go to the lamp on your left when you sit on the sofa facing the TV.",
  "Could you take me to the table light on the left-hand side, as seen from the couch looking at the telly?",
  "Left light, viewed from couch",
  "Sitting on the couch facing the television, I mean the light to my left, not the one on the right.",
  "This is the light at the left end of the couch as you sit watching TV. Head there.",
  "go to the ligth on the left when sitting on the couch facing the tv"], ("ligth", "light")),
 # ---- scan_office ----
 (SO, "o", 14, [14, 15, 16], [
  "Take me to a bookcase.",
  "Could you go to any of the bookshelves?",
  "Any bookcase",
  "I need a reference book, so any set of shelves with books will do.",
  "This is for finding a reference book. Bring me to one of the bookcases.",
  "take me to a bookcsae, whichever"], ("bookcsae", "bookcase")),
 (SO, "od", 30, [30], [
  "Go to the white keyboard.",
  "Could you take me to the white set of computer keys?",
  "White computer keys",
  "I need to type something, so the white set of keys, not the black one.",
  "This is the pale keyboard rather than the dark one. Take me to it.",
  "go to the white keybaord"], ("keybaord", "keyboard")),
 (SO, "s", 8, [8], [
  "Go to the desk chair nearest the red backpack.",
  "Could you take me to the office chair closest to the red rucksack on the floor?",
  "Chair nearest red backpack",
  "My bag is the red one, so I want the swivel chair right next to it, not the others.",
  "This is the seat closest to the red backpack. Take me there.",
  "go to the desk chair next to the red backpak"], ("backpak", "backpack")),
]

def main():
    out = Path(__file__).resolve().parents[2] / "evals/blind/round54.jsonl"
    lines = []
    for g, (m, t, target, accept, words, _typo) in enumerate(GROUPS, 1):
        assert len(words) == 6
        for w, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b54-g{g:02d}-w{w}", "map": m, "query": q, "type": t,
                                     "target": target, "accept": sorted(accept), "group": f"b54-g{g:02d}"},
                                    ensure_ascii=False))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(len(GROUPS), "groups,", len(lines), "lines ->", out)

if __name__ == "__main__":
    main()
