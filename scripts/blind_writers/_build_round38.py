"""Hand-written blind query suite round 38 (48 groups x 6 wordings). Writes evals/blind/round38.jsonl.
Each group: (map, type, target, accept, [w1..w6]). Wording styles: w1 imperative, w2 polite question,
w3 telegraphic, w4 context/contrast, w5 two-sentence description, w6 casual lower-case with one typo."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
CO3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

GROUPS = [
 # ---------------- caption maps (12) ----------------
 (C829, "o", 229, [229, 157, 112, 233, 219], [
  "Go to a mirror frame.",
  "Could you take me to one of the framed mirrors?",
  "framed mirror",
  "I want to check my hair, so find me any mirror with a frame; which room doesn't matter.",
  "This is a mirror in a decorative frame. It hangs on a wall so you can see yourself.",
  "take me to a mirorr frame pls"]),
 (C829, "o", 212, [212, 42, 197, 259], [
  "Go to a book.",
  "Could you find me something to read, like a bound volume?",
  "bound volume, any",
  "I feel like reading; any hardback volume will do, not the bookrack itself.",
  "This is a bound volume with a cover. It has pages you can read.",
  "where's a bok i can read"]),
 (CO3, "o", 8, [8, 13, 20, 40], [
  "Go to a pillow.",
  "Could you show me where a cushion is?",
  "cushion",
  "My back is sore, find me a soft cushion to put behind me, any colour is fine.",
  "This is a small soft cushion. It is the kind you lean against on a couch.",
  "wheres a pilow around here"]),
 (C829, "or", 261, [261, 263], [
  "Go to the easy chair in the bedroom.",
  "Could you take me to an armchair in the bedroom?",
  "bedroom lounge chair",
  "I want to sit and read before sleep, so an armchair in the bedroom, not the ones in the living room.",
  "This is a comfy upholstered armchair. It is located in the bedroom.",
  "need a comfy armchiar in the bedroom"]),
 (C829, "or", 195, [195, 216, 228], [
  "Go to a cupboard in the bathroom.",
  "Could you take me to one of the bathroom cabinets?",
  "bathroom cupboard",
  "I need to put away some toiletries, so any cupboard in the bathroom, not the one in the bedroom.",
  "This is a wooden storage cupboard with doors. It is in the bathroom.",
  "take me to a bathroom cuboard"]),
 (C829, "od", 211, [211], [
  "Go to the deep blue bowl with gold patterns.",
  "Could you find the blue ceramic bowl decorated in gold?",
  "blue gold ornamental bowl",
  "I want to show a guest the pretty blue bowl with golden patterns, not the white one that holds sweets.",
  "This is a glossy blue ceramic dish. It is decorated with gold-coloured patterns.",
  "where is the blue and gold boowl"]),
 (C829, "od", 56, [56], [
  "Go to the doorway with the gold doorknob and the peephole.",
  "Could you take me to the door that has a little peephole?",
  "door with peephole, gold knob",
  "Someone is knocking and I want to look out first, so the door with the spyhole, not any of the plain ones.",
  "This is a dark wooden door opening. It has a golden knob and a small peephole.",
  "go to the door with the peephloe"]),
 (CO3, "od", 13, [13], [
  "Go to the navy blue velvet pillow.",
  "Could you find the dark blue velvety cushion?",
  "navy velvet cushion",
  "I want the soft dark blue cushion with buttons, not the orange or yellow ones.",
  "This is a navy cushion with a velvety cover. It is fastened with a button and a bit bigger than the others.",
  "where's the navy cushon"]),
 (C829, "ord", 87, [87], [
  "Go to the washbasin counter in the bathroom.",
  "Could you take me to the glossy white vanity with the sink in the bathroom?",
  "bathroom vanity, white glossy",
  "I need to wash my face, so the white sink counter in the bathroom, not the one in the living room.",
  "This is a white glossy basin unit. It is in the bathroom and has a sink built into it.",
  "go to the white sink countr in the bathroom"]),
 (CO3, "ord", 7, [7], [
  "Go to the white desk in the rec room.",
  "Could you take me to the white wooden writing table in the rec room?",
  "white desk, rec room",
  "I need a clean surface to write on: the white wooden work table in the recreation room, not the brown ones.",
  "This is a white wooden work table. It stands in the rec room and has a USB port.",
  "go to the whte work table in the rec room"]),
 (C829, "ard", 192, [192], [
  "Go to where my dog can curl up and sleep.",
  "Could you show me where the cat sleeps?",
  "spot for pet to nap",
  "The puppy is tired; take me to its own sleeping place, not my bed.",
  "This is where the pet rests. It is a soft cushioned spot meant for an animal.",
  "where does the dog slep"]),
 (CO3, "ard", 25, [25], [
  "Go to the thing on the wall that shows the hour.",
  "Could you take me to where I can read the time off the wall?",
  "tell time, on wall",
  "I think I'm late for a meeting and my phone is dead, so I need to see the time on the wall.",
  "This is what you look at on the wall to know the hour. It has a second hand ticking round.",
  "what time is it, take me to the thing on the wal that shows it"]),
 # ---------------- flats (17) ----------------
 (FB, "o", 5, [5, 7, 26, 33, 34], [
  "Go to a lamp.",
  "Could you take me to any light I can switch on?",
  "light fixture, any",
  "It's getting dark and I want to read, take me to any lamp, it doesn't matter which room.",
  "This is a light source with a shade. It can be switched on to light up the room.",
  "go to a lmap"]),
 (FI, "o", 24, [1, 11, 24, 47], [
  "Go to a door.",
  "Could you take me to a doorway?",
  "any doorway",
  "I want to step out of here, so any door will do, front or inside.",
  "This is a hinged panel you open to go between spaces. It has a handle or knob.",
  "take me to a doorr"]),
 (FI, "or", 6, [6, 7, 8, 9], [
  "Go to a chair in the meeting room.",
  "Could you take me to a seat in the meeting room?",
  "meeting room seat",
  "I'm joining the client call, so any seat in the meeting room, not the ones in the studio.",
  "This is a chair for sitting at the glass table. It is in the meeting room.",
  "find me a seaat in the meeting room"]),
 (FG, "or", 34, [34, 35], [
  "Go to a lamp in the bedroom.",
  "Could you take me to one of the bedside lights in the bedroom?",
  "bedroom bedside light",
  "I want to read in bed, so either light by the bed, not the kids room one.",
  "This is a small bedside light with a shade. It is in the bedroom.",
  "go to a bedroom lmap, either one"]),
 (FB, "or", 2, [2, 3], [
  "Go to an armchair in the living room.",
  "Could you take me to one of the single seats in the living room?",
  "living room easy chair",
  "I want to watch TV on my own, so a one-person chair in the living room, not the green one in the study.",
  "This is an upholstered chair for one person. It is in the living room.",
  "take me to a livng room armchair"]),
 (FE, "od", 14, [14], [
  "Go to the black metal bistro chair.",
  "Could you find the odd black metal seat that doesn't match the green ones?",
  "black metal cafe seat",
  "The green painted ones are taken, so take me to the black metal bistro seat instead.",
  "This is a black metal cafe-style seat. It sits at the dining table and is unlike the others.",
  "go to the blak metal chair"]),
 (FG, "od", 19, [19], [
  "Go to the wooden chair with the red checked cushion.",
  "Could you take me to the wooden seat with the red check pad?",
  "wooden seat red gingham cushion",
  "Not the white plastic one; I want the wooden seat that has a red checked cushion.",
  "This is a wooden kitchen seat. It has a red checkered cushion on it.",
  "the wodden chair with the red cushion"]),
 (FI, "ord", 46, [46], [
  "Go to the lamp with the rattan shade in the bedroom.",
  "Could you take me to the bedroom light with a woven shade?",
  "bedroom light, wicker shade",
  "I want the patterned light on the walls, so the woven-shade one in the bedroom, not the ceramic one.",
  "This is a bedside light with a woven rattan shade. It is in the bedroom on the white side table.",
  "go to the rattan lmap in the bedroom"]),
 (FG, "ord", 45, [45], [
  "Go to the gray felt basket in the kids room.",
  "Could you take me to the toy bin in the kids room?",
  "kids room felt toy bin",
  "I want to tidy away the building blocks, so the soft gray toy tub in the kids room, not the laundry ones.",
  "This is a soft gray felt container full of toys. It is on the floor of the kids room.",
  "go to the grey toy baskte in the kids room"]),
 (FB, "ord", 3, [3], [
  "Go to the brown leather armchair in the living room.",
  "Could you take me to the leather easy chair in the living room?",
  "living room brown leather seat",
  "Not the yellow velvet one; I want the brown leather single seat in the living room.",
  "This is a brown leather seat for one. It stands near the eastern wall of the living room.",
  "go to the brwon leather armchair in the living room"]),
 (FG, "ard", 11, [11], [
  "Go to where I can iron my shirt.",
  "Could you take me to where I can press some clothes?",
  "press creased shirt",
  "My shirt is all creased before the interview, so take me where I can get the wrinkles out.",
  "This is where you flatten wrinkles from clothes. An iron is resting on it, ready to use.",
  "i need to iorn my trousers"]),
 (FE, "ard", 33, [33], [
  "Go to where I can dry my wet laundry.",
  "Could you take me to the machine that dries clothes?",
  "dry wet clothes",
  "The wash just finished and it's raining outside, so I need to get my clothes dry indoors.",
  "This is where damp laundry gets dried. It tumbles clothes with warm air.",
  "where can i dry my wet towles"]),
 (FI, "ard", 20, [20], [
  "Go to where I can print a floor plan.",
  "Could you take me to where I can scan a document?",
  "print A3 drawing",
  "The client wants a paper copy of the plans, so take me where I can get them printed.",
  "This is where you get a paper copy of a file. It can also make a scan.",
  "i need to print a drawnig"]),
 (FB, "s", 7, [7], [
  "Go to the lamp on the side table.",
  "Could you take me to the light sitting on the small side table?",
  "light on side table",
  "Not the tall floor lamp by the sofa; the little one standing on the side table.",
  "This is a small light. It sits on top of the round side table next to the sofa.",
  "go to the ligt on the side table"]),
 (FE, "s", 16, [16], [
  "Go to the lamp that hangs highest.",
  "Could you take me to the light that hangs highest up?",
  "highest light",
  "Not the floor or bedside ones; I mean the light hanging highest above the floor.",
  "This is a light hanging from above. It is higher than every other lamp in the flat.",
  "go to the higest light"]),
 (FG, "s", 3, [3], [
  "Go to the bicycle on the left as you stand by the car facing the rear wall of the garage.",
  "Could you take me to the left-hand bike as you face the garage's rear wall?",
  "left bike, facing garage back wall",
  "Facing the garage's back wall, I want the bike on the left, not the one on the right.",
  "This is a bike leaning at the back of the garage. Facing that back wall, it is the one on the left.",
  "facing the rear wall in the garage, the bicycel on the left"]),
 (FI, "s", 36, [36], [
  "Go to the mug on the coffee table.",
  "Could you take me to the cup sitting on the coffee table?",
  "cup on coffee table",
  "Not the one on the kitchen worktop or the pencil pot; the cup left on the low table in front of the sofa.",
  "This is a cup. It sits on top of the coffee table.",
  "go to the mug on the coffe table"]),
 # ---------------- apartment and scans (19) ----------------
 (APT, "o", 1, [1, 2], [
  "Go to a sofa.",
  "Could you take me to a couch?",
  "couch",
  "I want to lie down for a bit; any couch is fine, big or small.",
  "This is an upholstered seat for several people. You can stretch out on it.",
  "take me to a soffa"]),
 (SK, "o", 26, [26, 27], [
  "Go to a trash can.",
  "Could you take me to a bin?",
  "rubbish bin",
  "I have some peelings to throw away; either bin will do.",
  "This is a container for waste. You throw rubbish into it.",
  "where's a rubish bin"]),
 (APT, "or", 12, [12, 13], [
  "Go to a book in the living room.",
  "Could you take me to one of the books in the living room?",
  "something to read, living room",
  "I'd like something to flip through on the sofa, so a volume from the living room shelf, not the office textbook.",
  "This is a bound volume with printed pages. It is kept in the living room.",
  "take me to a bok in the living room"]),
 (APT, "or", 23, [23, 24], [
  "Go to a chair in the kitchen.",
  "Could you take me to a dining seat in the kitchen?",
  "kitchen seat",
  "I want to sit down to eat, so a seat at the kitchen table, not the office one.",
  "This is a wooden seat by the dining table. It is in the kitchen.",
  "find me a kitchn chair"]),
 (APT, "od", 31, [31], [
  "Go to the black-and-white photo of a lighthouse.",
  "Could you take me to the small lighthouse photograph?",
  "lighthouse photo, black frame",
  "I want to show my friend the lighthouse print, not the big blue and orange painting.",
  "This is a small monochrome photograph in a thin dark frame. It shows a lighthouse.",
  "go to the lighthose picture"]),
 (SL, "od", 3, [3], [
  "Go to the yellow pillow.",
  "Could you take me to the yellow cushion?",
  "yellow cushion",
  "Not the red ones; I want the yellow cushion.",
  "This is a cushion in yellow. It is the only one that is not red.",
  "the yelow cushion pls"]),
 (APT, "ord", 52, [52], [
  "Go to the green textbook in the office.",
  "Could you take me to the thick green programming book in the office?",
  "office green coding book",
  "I need to look up some code, so the green programming manual in the office, not the novels in the living room.",
  "This is a thick green textbook about programming. It is on a shelf in the office.",
  "go to the green programing textbook in the office"]),
 (APT, "ord", 42, [42], [
  "Go to the gray vanity cabinet in the bathroom.",
  "Could you take me to the gray cupboard under the basin in the bathroom?",
  "bathroom gray vanity unit",
  "I need a fresh towel, so the gray cupboard under the bathroom sink, not the kitchen cupboards.",
  "This is a gray wooden vanity unit. It is in the bathroom beneath the washbasin.",
  "go to the grey vanity cabnet in the bathroom"]),
 (APT, "ard", 27, [27], [
  "Go to where I can boil water for tea.",
  "Could you take me to what I'd use to heat water for a cuppa?",
  "boil water for tea",
  "I fancy a cup of tea but don't want to use the hob, so take me to what boils water quickly.",
  "This is what you use to bring water to the boil for a hot drink. It plugs into the wall.",
  "i want to bol some water for tea"]),
 (APT, "ard", 30, [30, 43], [
  "Go to where I can check how I look.",
  "Could you take me to somewhere I can see my reflection?",
  "check my reflection",
  "I've got a date tonight, so I need to see whether my hair looks okay; any place with a reflection will do.",
  "This is somewhere you can see your own face. It shows your reflection.",
  "where can i see my reflction"]),
 (SK, "ard", 12, [12], [
  "Go to where I can brew some coffee.",
  "Could you take me to what makes coffee?",
  "brew coffee",
  "I'm half asleep and need an espresso before work, take me to what makes it.",
  "This is where you make a hot coffee. It brews it for you from ground beans.",
  "i need a cofee, take me there"]),
 (APT, "s", 12, [12], [
  "Go to the higher of the two books on the living room bookshelf.",
  "Could you take me to the book sitting higher up in the living room bookcase?",
  "higher volume, living room bookcase",
  "Not the one lying flat at the bottom; the volume higher up on the living room bookcase.",
  "This is a volume on the living room bookshelf. It is the one placed higher up.",
  "the higher bok on the living room shelf"]),
 (APT, "s", 1, [1], [
  "Go to the sofa closest to the armchair.",
  "Could you take me to the couch nearest the blue armchair?",
  "couch nearest armchair",
  "Not the one by the west wall; the couch that is nearer to the blue velvet armchair.",
  "This is a couch in the living room. It is the one closer to the armchair.",
  "go to the couch closest to the armchiar"]),
 (APT, "s", 39, [39], [
  "Go to the plant on top of the dresser.",
  "Could you take me to the potted plant sitting on the chest of drawers?",
  "little pot on chest of drawers",
  "Not the big fig or the one in the office; the little potted thing sitting on the chest of drawers.",
  "This is a little succulent in a pot. It sits on top of the dresser.",
  "go to the plnt on the dresser"]),
 (SB, "s", 6, [6], [
  "Go to the nightstand closest to the desk.",
  "Could you take me to the bedside table nearer the desk?",
  "bedside table nearest desk",
  "Not the one by the door; the bedside table on the desk side.",
  "This is a bedside table next to the bed. It is the one closer to the desk.",
  "go to the nighstand by the desk"]),
 (SB, "s", 5, [5], [
  "Go to the pillow lying nearest the foot of the bed.",
  "Could you take me to the cushion closest to the foot end of the bed, away from the others?",
  "pillow at foot of bed",
  "Not the ones stacked by the headboard; the cushion down near the foot of the bed.",
  "This is a blue cushion on the bed. It lies farthest from the head of the bed.",
  "the pilow down by the foot of the bed"]),
 (SK, "s", 3, [3], [
  "Go to the cabinet right under the sink.",
  "Could you take me to the cupboard directly beneath the sink?",
  "cupboard under sink",
  "I need the dish soap, so the lower cupboard below the sink, not the wall units above.",
  "This is a low cupboard along the counter. It sits directly under the sink.",
  "go to the cupbaord under the sink"]),
 (SO, "s", 15, [15], [
  "Go to the bookshelf in the middle of the three.",
  "Could you take me to the bookcase between the other two?",
  "middle bookcase",
  "Not the white one on the end, nor the one by the corner; the bookcase sitting between the other two.",
  "This is a tall wooden bookcase against the wall. It stands between the other two bookcases.",
  "the bokcase in the middle"]),
 (SL, "s", 12, [12], [
  "Go to the lamp in the corner.",
  "Could you take me to the tall light standing in the corner?",
  "corner floor light",
  "Not the little ones on the side tables; the light standing in the corner near the door.",
  "This is a tall floor light. It stands in the north-east corner of the room.",
  "the lmap in the corner"]),
]


def main():
    out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round38.jsonl"
    lines = []
    assert len(GROUPS) == 48, len(GROUPS)
    for g, (mp, typ, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, (g, len(words))
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b38-g{g:02d}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": sorted(accept), "group": f"b38-g{g:02d}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {out}")


if __name__ == "__main__":
    main()
