"""Hand-written groups of blind suite round 40; writes evals/blind/round40.jsonl.
Each group: (type, map, target, accept, meta, [w1..w6]). meta holds what check.py needs
(label/room for o/or, a spatial spec for s)."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
COF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

GROUPS = [
 # ---------------- scene_00829 (caption map) ----------------
 ("o", C829, 122, [122], {"label": "toilet"}, [
  "Go to the toilet.",
  "Could you take me to the loo, please?",
  "loo, urgently",
  "I really need to pee, so take me to the WC, not just to a sink.",
  "This is a white porcelain fixture you sit on. You flush it after use.",
  "hey where's the resroom"]),
 ("or", C829, 261, [261, 263], {"label": "easy chair", "room": "bedroom"}, [
  "Go to an easy chair in the bedroom.",
  "Could you bring me to one of the lounge chairs in the bedroom?",
  "armchair, bedroom",
  "I want to sit and read in the bedroom, so find me a comfy armchair there, not one in the living room.",
  "This is a cushioned easy chair. It is located in the bedroom.",
  "take me to a cozy armchiar in the bedroom"]),
 ("od", C829, 184, [184], {}, [
  "Go to the L-shaped couch.",
  "Could you take me to the sofa with the chaise section?",
  "corner sofa with chaise",
  "Take me to the L-shaped sofa, not the one with the massage system.",
  "This is a beige fabric sofa shaped like an L. One end is a chaise and it hides storage.",
  "where's the l-shaped sofa with the chasie bit"]),
 ("ord", C829, 34, [34], {"room": "living room"}, [
  "Go to the side table with the glass top in the living room.",
  "Could you take me to the glass-topped end table in the living room?",
  "living room end table, glass top",
  "In the living room, take me to the little table with a glass surface, not the one with the USB port.",
  "This is a small end table in the living room. It has a glass surface, dark wood and a metal foot.",
  "the glas topped little table in the living room pls"]),
 ("ard", C829, 192, [192], {}, [
  "Go to where the dog sleeps.",
  "Could you show me where our cat naps?",
  "pet's sleeping spot",
  "I want to put the puppy down for a nap, so take me to its own cushion, not my bed.",
  "This is what the family pet curls up on. It is plush and coloured white and brown.",
  "where does the doggy slep"]),
 ("or", C829, 195, [195, 216, 228], {"label": "cabinet kitchen", "room": "bathroom"}, [
  "Go to a cabinet in the bathroom.",
  "Could you take me to one of the wooden cupboards in the bathroom?",
  "bathroom cupboard",
  "I need to store some things, so take me to any cabinet in the bathroom, not the one in the bedroom.",
  "This is a dark brown wooden cupboard. It is in the bathroom.",
  "go to a bathroom cabnet"]),
 ("od", C829, 164, [164], {}, [
  "Go to the towels with the letter H embroidered on them.",
  "Could you take me to the stack of towels monogrammed with an H?",
  "towels with H monogram",
  "Find me the folded towels that carry a stitched H, not the plain ones.",
  "This is a pile of fluffy white towels. An H is sewn onto them and they sit on a rack.",
  "the towles with the h on them"]),
 # ---------------- scene_office3 (caption map) ----------------
 ("o", COF3, 8, [8, 13, 20, 40], {"label": "pillow"}, [
  "Go to a pillow.",
  "Could you take me to one of the cushions?",
  "throw cushion",
  "My back hurts, so take me to any cushion, I don't care which colour.",
  "This is a soft cushion for a sofa. There are several of them in the rec room.",
  "where can i find a cushon"]),
 ("ard", COF3, 25, [25], {}, [
  "Go to the thing that shows what time it is.",
  "Could you take me somewhere I can check the time?",
  "check time",
  "I don't want to look at my phone, I just want to see the time on the wall.",
  "This is what you glance at to see the hour. It hangs on the wall with a ticking second hand.",
  "i need to know what tiem it is"]),
 ("od", COF3, 7, [7], {}, [
  "Go to the white desk.",
  "Could you take me to the white wooden workstation?",
  "white writing surface",
  "Take me to the white desk, not the brown wooden ones.",
  "This is a white workstation made of wood. It has a USB port built in.",
  "the whte wooden workstation pls"]),
 ("or", COF3, 7, [7, 55, 64], {"label": "desk", "room": "rec room"}, [
  "Go to a desk in the rec room.",
  "Could you show me any of the work desks in the recreation room?",
  "rec room workstation",
  "I need to write something, so take me to one of the workstations in the rec room, any one will do.",
  "This is a wooden workstation. It stands in the rec room.",
  "any workstaton in the rec room"]),
 ("ord", COF3, 37, [37], {"room": "rec room"}, [
  "Go to the black plastic chair with the built-in speaker in the rec room.",
  "Could you take me to the seat in the rec room that has a speaker in it?",
  "rec room seat, speaker, massage",
  "In the rec room, find the black plastic chair with a speaker, not the mesh ones.",
  "This is a black plastic seat in the rec room. It can massage you and has a speaker.",
  "the black plastc seat with the speaker in the rec room"]),
 # ---------------- flat_b ----------------
 ("s", FB, 22, [22], {"rel": "nearest", "among": [20, 21, 22], "ref": 15}, [
  "Go to the chair closest to the stove.",
  "Could you take me to the dining seat nearest the cooker?",
  "seat nearest cooker",
  "I want to keep an eye on the pot, so take me to the kitchen seat nearest the hob, not the ones farther away.",
  "This is a seat at the round kitchen table. It is the one closest to the cooker.",
  "the chiar nearest the oven"]),
 ("ard", FB, 40, [40], {}, [
  "Go to what I can dry myself with after a shower.",
  "Could you take me to something I can dry off with after showering?",
  "dry off after shower",
  "I'm soaking wet from the shower and need to dry myself, not wipe the floor.",
  "This is what you wrap around yourself after bathing. It hangs on a rail in the bathroom.",
  "need to dry myself off after a showr"]),
 ("or", FB, 33, [33, 34], {"label": "lamp", "room": "bedroom"}, [
  "Go to a lamp in the bedroom.",
  "Could you take me to one of the bedside lights in the bedroom?",
  "bedroom reading light",
  "I want to read in bed, so take me to a light in the bedroom, not the ones in the living room.",
  "This is a small light with a shade. It is in the bedroom, on a nightstand.",
  "a bedside lihgt in the bedroom"]),
 ("od", FB, 2, [2], {}, [
  "Go to the yellow velvet armchair.",
  "Could you take me to the mustard-coloured velvet chair?",
  "mustard velvet seat",
  "Take me to the yellow velvet armchair, not the brown leather or the green one.",
  "This is a soft velvet chair in mustard yellow. It stands next to a window.",
  "the yelow velvet chair"]),
 # ---------------- flat_e ----------------
 ("s", FE, 16, [16], {"rel": "above", "among": [4, 16, 26], "ref": 10}, [
  "Go to the lamp hanging above the dining table.",
  "Could you take me to the light that hangs over the dining table?",
  "light over dining table",
  "I want the lamp above the table where we eat, not the floor one by the sofa.",
  "This is a light suspended from the ceiling. It hangs right over the dining table.",
  "the light hanging over the dinning table"]),
 ("o", FE, 7, [7, 29], {"label": "mirror"}, [
  "Go to a mirror.",
  "Could you take me to a looking glass?",
  "looking glass",
  "I want to check my hair, so any mirror works, the bathroom one or the living room one.",
  "This is a reflective glass panel on the wall. You can see yourself in it.",
  "take me to a mirorr"]),
 ("ard", FE, 33, [33], {}, [
  "Go to the machine that dries clothes.",
  "Could you take me to where I can dry my washed laundry?",
  "dry wet laundry",
  "The washing is done and soaking; I need to dry it, not wash it again.",
  "This is an appliance that dries laundry with heat. It stands beside the washer in the utility room.",
  "where do i dry my wet clohtes"]),
 ("ord", FE, 14, [14], {"room": "dining room"}, [
  "Go to the black metal chair in the dining room.",
  "Could you take me to the dark bistro-style seat in the dining room?",
  "dining room black metal seat",
  "In the dining room, take me to the odd black chair, not the green painted ones.",
  "This is a black metal seat that doesn't match the rest. It stands at the table's north edge in the dining room.",
  "the blak metal seat in the dining room"]),
 # ---------------- flat_g ----------------
 ("s", FG, 2, [2], {"rel": "nearest", "among": [2, 3], "ref": 4}, [
  "Go to the bicycle closest to the workbench.",
  "Could you take me to the bike that is nearer the workbench?",
  "bike nearest workbench",
  "I need to fix a puncture at the bench, so take me to the bike nearer to it, not the one farther away.",
  "This is a bike in the garage. Of the two, it is the one closer to the workbench.",
  "the bicyle nearer the work bench"]),
 ("or", FG, 18, [18, 19], {"label": "chair", "room": "kitchen"}, [
  "Go to a chair in the kitchen.",
  "Could you take me to one of the seats at the kitchen table?",
  "kitchen seat",
  "I want to sit down while the kettle boils, so any seat in the kitchen, not the sofa in the living room.",
  "This is a seat in the kitchen. It is by the round table.",
  "any chiar in the kitchen"]),
 ("ord", FG, 34, [34], {"room": "bedroom"}, [
  "Go to the teal glass lamp in the bedroom.",
  "Could you take me to the bedside light with the teal base in the bedroom?",
  "bedroom teal light",
  "In the bedroom, take me to the lamp with the teal glass base, not the beige ceramic one.",
  "This is a small bedside light in the bedroom. Its base is teal glass and its shade is white.",
  "the teal bedside lihgt in the bedroom"]),
 ("ard", FG, 11, [11], {}, [
  "Go to where I can iron my shirt.",
  "Could you take me somewhere I can press my trousers?",
  "press creased shirt",
  "My shirt is wrinkled and I have a meeting; I need to iron it, not wash it.",
  "This is where you smooth the creases out of clothes. It has a floral cover and a steam iron on it.",
  "need to iron my shrit"]),
 # ---------------- flat_i ----------------
 ("s", FI, 13, [13], {"rel": "right_facing_north", "among": [12, 13]}, [
  "In the studio, go to the desk on the right when you face the north wall.",
  "Could you take me to the right-hand workstation in the studio, as seen facing the north wall?",
  "studio, right workstation facing north",
  "Facing the north wall of the studio, take me to the workstation on the right, not the left one.",
  "This is a work surface in the studio. Looking toward the north wall, it is the one on the right.",
  "facing the north wall in the studio, the rigth desk pls"]),
 ("o", FI, 1, [1, 11, 24, 47], {"label": "door"}, [
  "Go to a door.",
  "Could you take me to any of the doors?",
  "any doorway",
  "I just need a way in or out, whichever entrance is handy.",
  "This is a hinged panel you open to pass between spaces. There are several of them in this flat.",
  "take me to an entrence"]),
 ("od", FI, 15, [15], {}, [
  "Go to the black leather office chair.",
  "Could you take me to the high-backed black leather swivel seat?",
  "black leather swivel seat",
  "Take me to the black leather chair with the high back, not the blue mesh one.",
  "This is a swivel seat upholstered in black leather. Its back is tall.",
  "the black lether swivel seat"]),
 ("ard", FI, 20, [20], {}, [
  "Go to where I can print out the floor plans.",
  "Could you take me to something that can put a drawing on A3 paper?",
  "print plans",
  "I need a paper copy of these drawings, not on screen, so take me where I can print them.",
  "This is the machine that puts documents onto paper and can scan too. It sits on a gray drawer unit.",
  "i need to prnit a plan"]),
 # ---------------- apartment ----------------
 ("s", APT, 12, [12], {"rel": "higher", "among": [12, 13]}, [
  "Go to the higher book on the living room bookshelf.",
  "Could you take me to the volume sitting higher up in the living room bookcase?",
  "upper-shelf novel, living room",
  "Take me to the book higher up on the living room shelves, not the one lying on the bottom shelf.",
  "This is a hardcover volume in the living room bookcase. It stands higher than the other one there.",
  "the hihger novel on the living room shelf"]),
 ("s", APT, 1, [1], {"rel": "nearest", "among": [1, 2], "ref": 11}, [
  "Go to the sofa closest to the bookshelf.",
  "Could you take me to the couch nearest the bookcase?",
  "couch nearest bookcase",
  "I'll grab a novel and then sit down, so take me to the settee nearest the bookshelf, not the other one.",
  "This is a couch in the living room. Of the two, it is nearer to the bookshelf.",
  "the sofa nearset the bookcase"]),
 ("ard", APT, 41, [41], {}, [
  "Go to where I can brush my teeth.",
  "Could you take me somewhere I can rinse after brushing my teeth?",
  "brush teeth",
  "I need to brush my teeth before bed, so not the kitchen; take me to the right basin.",
  "This is a basin where you wash up before bed. It sits on a gray vanity in the bathroom.",
  "where can i brush my teth"]),
 ("ard", APT, 54, [54], {}, [
  "Go to where I can print a document.",
  "Could you take me to something that will put my report on paper?",
  "print report",
  "I need a hard copy of this letter, not a PDF; where can I print it?",
  "This is the device that turns files into paper pages. It sits on top of a filing cabinet in the office.",
  "i need to prnt my boarding pass"]),
 ("o", APT, 8, [8, 39, 55], {"label": "plant"}, [
  "Go to a plant.",
  "Could you take me to any of the potted plants?",
  "houseplant",
  "I want to water the greenery, so take me to any pot with something growing in it, whichever.",
  "This is something green growing in a pot. There are a few around the flat.",
  "take me to some greenry"]),
 ("or", APT, 23, [23, 24], {"label": "chair", "room": "kitchen"}, [
  "Go to a chair in the kitchen.",
  "Could you take me to one of the dining seats in the kitchen?",
  "kitchen dining seat",
  "I want to eat at the table, so any seat in the kitchen is fine, not the armchair in the living room.",
  "This is a wooden seat pulled up to the table. It is in the kitchen.",
  "a kitchn seat please"]),
 ("od", APT, 48, [48], {}, [
  "Go to the red leather swivel chair.",
  "Could you take me to the red office seat on wheels?",
  "red leather desk seat",
  "Take me to the red leather chair with armrests, not the wooden dining ones.",
  "This is a swivel seat in red leather. It has armrests and rolls on castors.",
  "the red lether seat on wheels"]),
 ("ord", APT, 53, [53], {"room": "office"}, [
  "Go to the gray metal filing cabinet in the office.",
  "Could you take me to the grey metal drawers for paperwork in the office?",
  "office grey file drawers",
  "I need to file these papers, so take me to the metal cabinet in the office, not the bathroom vanity.",
  "This is a gray metal unit with two drawers. It stands in the office, with the printer on top.",
  "the grey metl filing drawers in the office"]),
 # ---------------- scans ----------------
 ("o", SB, 2, [2, 3, 4, 5], {"label": "pillow"}, [
  "Go to a pillow.",
  "Could you take me to one of the cushions on the bed?",
  "bed cushion",
  "My neck is sore and I need something soft under my head; any pillow is fine, colour doesn't matter.",
  "This is a soft cushion for resting your head. Several of them lie on the bed.",
  "where's a pilow"]),
 ("s", SB, 8, [8], {"rel": "left_facing_north", "among": [8, 9]}, [
  "Standing at the foot of the bed facing the headboard, go to the lamp on the left.",
  "Could you take me to the left bedside lamp, as seen from the foot of the bed?",
  "left bedside light, from bed foot",
  "Looking at the headboard from the foot of the bed, I want the light on the left side, not the right one.",
  "This is a bedside light on a nightstand. Seen from the foot of the bed, it is on the left.",
  "from the foot of the bed, the light on the lfet"]),
 ("s", SB, 4, [4], {"rel": "between", "among": [2, 3, 4, 5], "refs": [2, 3]}, [
  "Go to the pillow between the two white ones.",
  "Could you take me to the cushion sitting between the two white pillows?",
  "cushion between two white ones",
  "Not the blue one near the middle of the bed; I want the cushion between the pair of white ones at the head.",
  "This is a small cushion at the head of the bed. It sits between the two white ones.",
  "the cushon in between the two white ones"]),
 ("or", SK, 23, [23, 24, 25], {"label": "cup", "room": "kitchen"}, [
  "Go to a cup in the kitchen.",
  "Could you take me to any of the mugs in the kitchen?",
  "kitchen mug",
  "I'm thirsty, so take me to any cup in the kitchen, I don't mind which colour.",
  "This is a small drinking vessel. It is somewhere in the kitchen.",
  "any mgu in the kitchen"]),
 ("ord", SK, 4, [4], {"room": "kitchen"}, [
  "Go to the gray kitchen cabinet in the kitchen.",
  "Could you take me to the grey lower cupboard in the kitchen?",
  "kitchen grey cupboard",
  "In the kitchen, take me to the cupboard that is gray, not the white ones.",
  "This is a base cupboard under the counter in the kitchen. It is the only gray one.",
  "the gray cuboard in the kitchen"]),
 ("s", SK, 21, [21], {"rel": "nearest", "among": [17, 18, 19, 20, 21, 22], "ref": 15}, [
  "Go to the chair at the end of the table nearest the door.",
  "Could you take me to the seat at the table's end closest to the door?",
  "seat, table end by door",
  "I'll be in and out, so take me to the seat at the table end nearest the door, not the far end.",
  "This is a seat at the end of the table. It is the one closer to the door.",
  "the chair at the table end closest to the dor"]),
 ("s", SK, 25, [25], {"rel": "nearest", "among": [23, 24, 25], "ref": 10}, [
  "Go to the cup nearest the sink.",
  "Could you take me to the mug closest to the sink?",
  "mug by sink",
  "I want the mug sitting by the sink on the counter, not the ones on the table.",
  "This is a cup on the counter. It is the one closest to the sink.",
  "the mug next to the snik"]),
 ("od", SL, 6, [6], {}, [
  "Go to the brown leather armchair.",
  "Could you take me to the leather easy chair?",
  "brown leather seat",
  "Take me to the leather armchair, not the green one.",
  "This is a single seat covered in brown leather. It has arms and stands near the window.",
  "the brown lether easy chair"]),
 ("s", SL, 12, [12], {"rel": "corner", "among": [10, 11, 12]}, [
  "Go to the lamp in the corner of the room.",
  "Could you take me to the tall light standing in the corner?",
  "corner floor light",
  "Not the lamps on the side tables; take me to the one in the corner.",
  "This is a tall standing light. It is in a corner of the room.",
  "the standing light in the cornr"]),
 ("o", SO, 21, [21, 22], {"label": "trash can"}, [
  "Go to a trash can.",
  "Could you take me to a wastebasket?",
  "rubbish bin",
  "I need to throw this wrapper away, so any bin will do.",
  "This is a small container for rubbish. It stands on the floor.",
  "where's a garbage bni"]),
 ("ord", SO, 16, [16], {"room": "office"}, [
  "Go to the white bookshelf in the office.",
  "Could you take me to the white bookcase in the office?",
  "office white shelving",
  "In the office, take me to the short white bookshelf, not the brown wooden ones.",
  "This is a low white shelf unit for books. It is in the office, against the wall with the other shelves.",
  "the white bookcse in the office"]),
 ("s", SO, 11, [11], {"rel": "on", "among": [11, 12, 13], "ref": 1}, [
  "Go to the monitor on the white table.",
  "Could you take me to the screen sitting on the white table?",
  "screen on white table",
  "Not the screens on the wooden table; I want the one on the white table.",
  "This is a computer screen. It sits on top of the white table.",
  "the scren on the white table"]),
]


def rows():
    for g, (typ, mp, target, accept, meta, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, g
        for k, q in enumerate(words, 1):
            yield {"id": f"b40-g{g:02d}-w{k}", "map": mp, "query": q, "type": typ,
                   "target": target, "accept": sorted(accept), "group": f"b40-g{g:02d}"}


if __name__ == "__main__":
    out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round40.jsonl"
    out.write_text("".join(json.dumps(r) + "\n" for r in rows()), encoding="utf-8")
    print(out, len(GROUPS), "groups")
