"""Generate evals/blind/round21.jsonl (blind round 21). All wordings hand-written here."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SOFF = "../maps/scan_office.json"
SLIV = "../maps/scan_livingroom.json"
FB, FD, FF, FI = "maps/flat_b.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_i.json"

G = [
# ---------------- o: every instance of a kind
("o", C829, 160, [160, 162, 164], [
 "Take me to the folded towels.",
 "Could you show me where the stacks of clean towels are?",
 "towels pls",
 "I just got out of the shower and I'm dripping. Where are the towles?",
 "There should be some fluffy white bath towels somewhere around here. Lead me to them.",
 "Which way to the set of towels?"]),
("o", OFF3, 8, [8, 13, 20, 40], [
 "Bring me over to a cushion.",
 "Would you mind taking me to one of the cushions?",
 "cushion, any",
 "My back hurts from sitting on this bench. Where can I grab a cusion?",
 "I'm looking for something soft to lean on, like a throw cushion. Any of them will do.",
 "Take me to a pillow, please."]),
("o", OFF3, 7, [7, 55, 64], [
 "Take me to a desk.",
 "Can you guide me to a workstation where I can sit down?",
 "workdesk, whichever",
 "I have to fill in some forms. Is there a workdesk around?",
 "I need a place to put my notebook and type. Any of the workdesks is fine.",
 "where's the nearest desk"]),
("o", FB, 5, [5, 7, 26, 33, 34], [
 "Take me to a light I can switch on.",
 "Could you bring me to any of the lamps in the flat?",
 "any lamp",
 "It's getting dark in here. Show me a lampp.",
 "I want one of the reading lights. It doesn't matter which room it is in.",
 "Find me something that gives light, a standing or table light."]),
("o", FD, 21, [21, 22], [
 "Take me to a bar seat.",
 "Could you show me where the stools are?",
 "stool",
 "My legs are tired. Is there a little backless seat somewhere?",
 "I'm looking for one of the high seats without a backrest. Either is fine.",
 "Where can I find a stoool to stand on?"]),
("o", APT, 12, [12, 13, 52], [
 "Take me to something to read.",
 "Could you bring me to one of the books?",
 "books",
 "I'm bored and want to flip through a volume. Where are they?",
 "I'm after a hardcover or a textbook, anything printed and bound. Show me one.",
 "Lead me to a novel or any other bound volume in the flat."]),
("o", FI, 23, [23, 31, 36], [
 "Take me to a mug.",
 "Could you find me one of the cups in the flat?",
 "coffee cup, any",
 "I want to pour myself some tea. Where's a cup?",
 "There are a few drinking cups lying around. Bring me to any of them.",
 "Show me where I can find a mugg."]),
# ---------------- or: every instance of a kind in a named room
("or", C829, 261, [261, 263], [
 "Take me to an easy chair in the bedroom.",
 "Could you show me the comfy armchairs in the bedroom?",
 "bedroom armchair",
 "I'd like to read before bed. Is there a lounge chair in the bedroom?",
 "I want a cushy chair to sink into. It has to be the one in the sleeping room, not the lounge.",
 "Which way to the recliner-style chairs in the bedrom?"]),
("or", C829, 34, [34, 74], [
 "Take me to a side table in the living room.",
 "Could you bring me to one of the little end tables in the lounge?",
 "living room end table",
 "I need to put my drink down while I'm on the couch. Is there a small side surface in the living room?",
 "Find me a small occasional table. It should be in the living room, not the bedroom.",
 "Where are the end tabels in the living room?"]),
("or", FF, 12, [12, 13, 14, 15], [
 "Take me to a chair in the kitchen.",
 "Could you bring me to one of the seats around the kitchen table?",
 "kitchen seat",
 "I'd like to sit down for breakfast. Where's a seat in the kitchen?",
 "I need one of the dining seats. They're in the kitchen, around the big oak table.",
 "Show me a kitchen dining chair, any colour."]),
("or", FI, 45, [45, 46], [
 "Take me to a lamp in the bedroom.",
 "Could you guide me to one of the bedside lights in the bedroom?",
 "bedroom light",
 "I want to read in bed, so where are the bedroom lights?",
 "I'm looking for a light by the bed. Either side of the bed is fine.",
 "Where's a bedside lmap in the bedroom?"]),
("or", FB, 2, [2, 3], [
 "Take me to an armchair in the living room.",
 "Would you bring me to one of the single easy chairs in the lounge?",
 "lounge easy chair",
 "I want to sit on my own while the others take the sofa. Where's an easy chair in the living room?",
 "I need a one-person upholstered chair. It's in the living room, not the study.",
 "Living room armchiar please."]),
("or", APT, 12, [12, 13], [
 "Take me to a book in the living room.",
 "Can you show me the books in the lounge?",
 "living room reading material",
 "I left something to read by the TV area. Which volumes are in the living room?",
 "I want a novel or a photo album. It's on the shelf in the living room, not the office one.",
 "Where are the living room bookss?"]),
("or", FD, 4, [4, 5, 7], [
 "Take me to a chair in the studio.",
 "Could you point me to a seat in the studio?",
 "studio seat",
 "I need to sit for a minute. Is there a seat in the main studio room?",
 "I'm after one of the chairs in the studio. Not the tiny one in the kids' room.",
 "Show me any of the studio seats."]),
# ---------------- od: one object by its look
("od", OFF3, 40, [40], [
 "Take me to the orange pillow with white and yellow stripes.",
 "Could you find the striped orange cushion for me?",
 "orange cushion, stripy one",
 "This is an orange cushion. It has white and yellow stripes across it.",
 "I want the orange cushion, not the plain puffy one with a button, the one with stripes.",
 "I'm decorating and need the stripey orange cushon."]),
("od", C829, 110, [110], [
 "Take me to the small honey-coloured wooden table with the X-shaped metal legs.",
 "Could you find the little light wood stand that has a crossed metal base?",
 "honey wood side stand, X base",
 "I'm looking for a small table. Its top is warm honey-toned wood and the legs form a metal X.",
 "The pale honey one with the criss-cross base, not the dark glossy one.",
 "Where's the little golden-wood stand with the X frame underneath?"]),
("od", C829, 211, [211], [
 "Take me to the deep blue bowl with gold patterns.",
 "Could you show me the glossy blue ceramic bowl?",
 "blue decorative bowl",
 "It's an ornamental dish. Deep blue glaze with little gold patterns on it.",
 "I mean the blue one with gold trim, not the white bowl full of sweets.",
 "Where did the blue ceramic bwol go?"]),
("od", FI, 23, [23], [
 "Take me to the cobalt blue mug full of pencils.",
 "Could you find the blue ceramic cup that holds the pencils?",
 "blue pencil cup",
 "I need a pencil. The dark blue cup with all the pencils in it is what I want.",
 "This is a blue ceramic cup. It's stuffed with pencils instead of coffee.",
 "Not the yellow one with cold tea, the blue one with the pencils."]),
("od", FF, 14, [14], [
 "Take me to the mustard-yellow chair.",
 "Could you show me the yellow painted wooden chair?",
 "yellow seat",
 "This is a painted wooden seat. It's mustard yellow, the odd one out among the blue ones.",
 "The one that isn't blue. I mean the yellow seat.",
 "I want the yellow wooden saet, please."]),
("od", APT, 48, [48], [
 "Take me to the red leather swivel chair.",
 "Could you bring me to the red leather office seat that turns?",
 "red swivel seat",
 "I'm looking for a seat covered in red leather. It spins round.",
 "The red one that swivels, not the wooden dining ones.",
 "Where's that red leather swivel sseat?"]),
("od", FD, 10, [10], [
 "Take me to the green ceramic mug.",
 "Could you find the green cup made of ceramic?",
 "green mug",
 "I'm looking for something to drink from. It's green and made of pottery.",
 "The green one, not a glass or a plastic one.",
 "Where's my green coffee mug?"]),
# ---------------- ord: look + room
("ord", C829, 263, [263], [
 "Take me to the brown leather easy chair in the bedroom.",
 "Could you show me the leather armchair in the bedroom?",
 "bedroom leather armchair",
 "There's a brown leather lounge chair with lumbar support. It's in the bedroom.",
 "The leather one in the bedroom, not the woven fabric one next to it.",
 "I want to sit on the brown leather recliner in the bedroom."]),
("ord", C829, 191, [191], [
 "Take me to the beige velvet easy chair in the bathroom.",
 "Could you find the beige velvet armchair in the bathroom?",
 "bathroom beige armchair",
 "I'm looking for a soft beige velvet lounge chair. It's in the bathroom, oddly enough.",
 "The velvet one that's in the bathroom, not any of the living room chairs.",
 "Where is the beige velvet seat in the bathrom?"]),
("ord", C829, 259, [259], [
 "Take me to the dark brown leather-bound book in the bedroom.",
 "Could you point me to the leather-covered book in the bedroom?",
 "bedroom leather-bound volume",
 "There's a volume with a dark brown leather binding. It's lying in the bedroom.",
 "The leather-bound volume in the bedroom, not the red one.",
 "I want to read the brown leather volume from the bedroom."]),
("ord", FB, 26, [26], [
 "Take me to the green glass lamp in the study.",
 "Could you show me the banker's light with the green shade in the study?",
 "study green desk light",
 "I'm looking for a brass desk light. It has a green glass shade and sits in the study.",
 "The green-shaded one in the study, not the bedside ones.",
 "Where is the green banker's lamp in the stuyd?"]),
("ord", FI, 13, [13], [
 "Take me to the white desk in the studio.",
 "Could you bring me to the plain white work table in the studio?",
 "studio white desk",
 "There's a plain white work table with a cable tray. It's in the studio.",
 "The white one in the studio, not the oak one and not the reception counter.",
 "I need the white workstation in the design studio."]),
("ord", APT, 53, [53], [
 "Take me to the gray metal cabinet in the office.",
 "Could you find the gray metal filing drawers in the office?",
 "office filing cabinet",
 "I need to file a letter. The grey metal drawer unit in the office is what I want.",
 "The metal one in the office, not the wooden vanity in the bathroom.",
 "Where's the gray filing cabnet in the office?"]),
("ord", FF, 37, [37], [
 "Take me to the white cabinet in the bathroom.",
 "Could you show me the mirrored medicine cupboard in the bathroom?",
 "bathroom medicine cupboard",
 "I need a plaster. The white wooden cupboard with a mirror door is in the bathroom.",
 "The white one in the bathroom, not the green dresser in the kitchen.",
 "Where's the white wall cupboard in the bathroom?"]),
# ---------------- ard: need, no object named
("ard", C829, 177, [177], [
 "I'm exhausted and want to go to sleep for the night.",
 "Where can I lie down properly and get a full night's rest?",
 "need to sleep",
 "It's late and my eyes are closing. Take me where I can turn in.",
 "I'm jet-lagged. Somewhere I can crawl under the covers, please.",
 "Could you take me somewhere to sleep until morning?"]),
("ard", OFF3, 25, [25], [
 "I need to know what time it is.",
 "Could you take me where I can check the time?",
 "check the time",
 "I think I'm late for my meeting. Where can I see the time?",
 "My phone died and I've lost track of the hour. Help me find out what time it is.",
 "What's the time? Show me where to look."]),
("ard", OFF3, 67, [67], [
 "I want to change the channel.",
 "Could you take me to whatever turns the volume down?",
 "switch channels",
 "The show is too loud. I need to turn it down from the sofa.",
 "I'd like to flick to another programme without getting up. What do I use?",
 "Take me to the thing I can zap through channels with."]),
("ard", FD, 27, [27], [
 "My shirt is all creased. Where can I press it?",
 "Could you take me where I can get the wrinkles out of my clothes?",
 "press shirt",
 "I have an interview tomorrow and my trousers are wrinkled.",
 "I need to iron something before I go out.",
 "Take me where I can smooth out my creased clothes."]),
("ard", FF, 25, [25], [
 "I want to look at the stars tonight.",
 "Could you take me to something I can use to see the planets up close?",
 "stargazing",
 "It's a clear night. Where can I get a close view of the moon?",
 "I'd love to spot Saturn's rings. Take me to what I'd need.",
 "Show me what I can use to watch the night sky."]),
("ard", APT, 20, [20], [
 "I want to heat up my leftovers.",
 "Could you take me where I can warm up this soup in a couple of minutes?",
 "reheat food quickly",
 "My lunch is cold. Where can I zap it?",
 "I need to defrost some bread fast.",
 "Take me to where I can warm my pizza slice in a minute or two."]),
("ard", FI, 20, [20], [
 "I need to scan a drawing.",
 "Could you take me where I can print out these plans?",
 "print a copy",
 "The client wants a paper copy of the floor plan. Where do I get one printed?",
 "I have a sketch I'd like to digitise.",
 "Take me where I can make a hard copy of this document."]),
("ard", FB, 18, [18], [
 "I'd like to boil some water for tea.",
 "Could you take me to where I can heat water for a cuppa?",
 "boil water",
 "I'm freezing. I want to make a hot drink.",
 "I want to make instant noodles, so I need hot water quickly.",
 "Take me where I can get the water boiling for coffee."]),
# ---------------- s: spatial (checked numerically in check_spatial.py)
("s", SOFF, 10, [10], [
 "Take me to the blue office chair nearest the door.",
 "Could you bring me to the blue desk seat that's closest to the exit?",
 "blue chair closest to door",
 "There are two blue swivel seats. I want the one nearer the door.",
 "The blue one by the door side, not the blue seat near the windows.",
 "Standing at the door, take me to the nearest blue chiar."]),
("s", SOFF, 16, [16], [
 "Take me to the shortest bookshelf.",
 "Could you show me the lowest of the shelving units along the back wall?",
 "smallest bookcase",
 "There are three bookcases by the wall. I want the short white one.",
 "The little one at the end, not the two tall wooden bookcases.",
 "Which is the smallest bokcase? Go there."]),
("s", SOFF, 21, [21], [
 "Take me to the trash can next to the door.",
 "Could you bring me to the bin by the exit?",
 "bin by door",
 "I need to throw this away. The rubbish bin near the door, please.",
 "Not the bin in the corner by the window, the one next to the door.",
 "Where's the garbage bin closest to the doorway?"]),
("s", SOFF, 24, [24], [
 "Take me to the plant next to the bookshelves.",
 "Could you show me the potted plant beside the bookcases?",
 "greenery by bookcases",
 "There's a small potted green. It's right beside the shelves on the back wall.",
 "Not the big one near the window, the one by the bookcases.",
 "I want to water the houseplant closest to the book shelves."]),
("s", SLIV, 3, [3], [
 "Take me to the pillow between the two red ones.",
 "Could you show me the middle cushion on the sofa?",
 "middle sofa cushion",
 "There are three cushions on the couch. I want the one in the centre, between the red ones.",
 "The cushion in the middle of the settee, not the ones at either end.",
 "Take me to the cushion sat between the two red pilows."]),
("s", SLIV, 11, [11], [
 "Take me to the lamp on the side table nearest the brown leather armchair.",
 "Could you bring me to the table light closest to the leather armchair?",
 "side-table light near leather armchair",
 "There are two little lights on side tables. I want the one closer to the brown leather chair.",
 "Not the light at the far end of the couch, the one beside the leather armchair.",
 "I want to read in the leather chair. Take me to the closest small light by it."]),
("s", SLIV, 15, [15], [
 "Take me to the picture hanging above the sofa.",
 "Could you show me the artwork on the wall behind the couch?",
 "artwork over couch",
 "There are two framed artworks. I want the one on the wall behind the settee.",
 "Not the one on the side wall, the artwork above the couch.",
 "Take me to the painting that hangs over the sofa."]),
("s", SLIV, 17, [17], [
 "Take me to the plant next to the bookshelf.",
 "Could you show me the potted green near the bookcase?",
 "greenery by bookcase",
 "There's a tall leafy pot. It's in the corner near the bookcase.",
 "Not the small one by the sofa, the one by the bookcase.",
 "I want to water the plnat that's closest to the books."]),
("s", APT, 13, [13], [
 "Take me to the book on the bottom shelf of the living room bookshelf.",
 "Could you bring me to the lower of the two books on the living room bookcase?",
 "lower volume on lounge shelf",
 "There are two volumes in the lounge shelving. I want the one lying lowest down.",
 "Not the one on the upper shelf, the one near the floor.",
 "The volume on the lowest shelf in the living room, please."]),
("s", APT, 39, [39], [
 "Take me to the plant on top of the dresser.",
 "Could you show me the little plant sitting on the chest of drawers?",
 "succulent on chest of drawers",
 "I'm looking for a small potted succulent. It's on top of the chest of drawers in the bedroom.",
 "The one resting on the drawers, not the big pots on the floor.",
 "Water the succulent that sits on the bedroom drawers."]),
("s", FB, 34, [34], [
 "Facing the bed from its foot, take me to the lamp on my right.",
 "Could you bring me to the bedside light on the right when you stand at the end of the bed looking at the headboard?",
 "bedside light, right side from foot of bed",
 "There are two bedside lights. Standing at the foot of the bed, I want the one on the right.",
 "Looking at the headboard, the light on the right side, not the left one.",
 "From the foot of the bed, go to the right-hand bedsied light."]),
("s", FD, 22, [22], [
 "Take me to the stool closest to the fridge.",
 "Could you bring me to the bar seat nearest the refrigerator?",
 "stool nearest fridge",
 "There are two high seats in the kitchenette. I want the one closer to the fridge.",
 "The seat nearer the fridge, not the one closer to the bin.",
 "Which high seat is closest to the fridge? Go to that one."]),
]

TYPOS = ['towles', 'cusion', 'lampp', 'stoool', 'mugg', 'bedrom', 'tabels', 'lmap', 'armchiar', 'bookss',
         'cushon', 'bwol', 'saet', 'sseat', 'bathrom', 'stuyd', 'cabnet', 'chiar', 'bokcase', 'pilows', 'plnat', 'bedsied']

def main():
    out = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round21.jsonl"
    lines = []
    for n, (typ, mp, tgt, acc, words) in enumerate(G, 1):
        assert len(words) == 6, n
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b21-g{n:02d}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": tgt, "accept": acc, "group": f"b21-g{n:02d}"}))
    text = "\n".join(lines) + "\n"
    for t in TYPOS:
        assert sum(t in json.loads(l)["query"].split(" ")[-1] or (" " + t) in json.loads(l)["query"] for l in lines) == 1, t
    out.write_text(text, encoding="utf-8")
    print(len(G), "groups,", len(lines), "lines ->", out)

if __name__ == "__main__":
    main()
