"""Hand-written blind suite round 49: emits evals/blind/round49.jsonl and scripts/spec.json.
Each group: (type, map key, target, accept, spec for check.py, six wordings w1..w6)."""
import json
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MAPS = {
    "C829": "../../../shared/data/iesm_maps/scene_00829_caption.json",
    "O3": "../../../shared/data/iesm_maps/scene_office3_caption.json",
    "FC": "maps/flat_c.json", "FD": "maps/flat_d.json", "FF": "maps/flat_f.json", "FH": "maps/flat_h.json",
    "APT": "apartment",
    "SB": "../maps/scan_bedroom.json", "SK": "../maps/scan_kitchen.json",
    "SL": "../maps/scan_livingroom.json", "SO": "../maps/scan_office.json",
}

# spec: o -> {"label"}; or -> {"label","room"}; s -> {"check": name, ...}; od/ord/ard -> {"note"}
G = [
 # ---------------- o: category, accept = every object with that label ----------------
 ("o", "O3", 8, [8, 13, 20, 40], {"label": "pillow"}, [
  "Go to a pillow.",
  "Could you find me a cushion somewhere in here?",
  "cushion, any",
  "My neck is sore, so bring me to any pillow in the room, whichever one is closest.",
  "This is a soft cushion. It is the kind of thing you rest your head or back against.",
  "can u take me to a cushoin, any of them is fine"]),
 ("o", "C829", 112, [112, 157, 219, 229, 233], {"label": "mirror frame"}, [
  "Go to a mirror frame.",
  "Could you take me to one of the mirrors?",
  "any framed mirror",
  "I want to check my hair before going out, so any mirror will do, whichever is nearest.",
  "This is a looking glass in a frame. It lets you see your own reflection.",
  "take me to a mirrror, any one"]),
 ("o", "FC", 5, [5, 7, 28, 36], {"label": "lamp"}, [
  "Go to a lamp.",
  "Could you take me to one of the lamps?",
  "any light, floor or table",
  "It is getting dark in here, so lead me to a light I can switch on; any one will do.",
  "This is a light fitting that stands on the floor or on furniture. It lights up the room when switched on.",
  "where's a lmap i can turn on"]),
 ("o", "FH", 13, [13, 26, 32], {"label": "mug"}, [
  "Go to a mug.",
  "Could you find me a coffee cup?",
  "coffee cup, any",
  "I just want something to drink tea from, so take me to any cup with a handle, whichever is closest.",
  "This is a small drinking vessel with a handle. It holds one hot drink.",
  "where did i leave a mgu, any of them"]),
 ("o", "APT", 12, [12, 13, 52], {"label": "book"}, [
  "Go to a book.",
  "Could you take me to something I can read, like a novel or a textbook?",
  "reading material, bound volume",
  "I'm bored and want to read, so any book at all will do; I'm not fussy about which.",
  "This is a bound volume with printed pages. It might be a novel, a photo album or a manual.",
  "find me something to read, any hardback or paperbak"]),
 ("o", "SK", 26, [26, 27], {"label": "trash can"}, [
  "Go to a trash can.",
  "Could you take me to a bin?",
  "rubbish bin",
  "I've got some vegetable peelings to throw away, so any waste bin will do.",
  "This is a container for rubbish. It stands on the floor of the kitchen.",
  "where's the garbage bni"]),
 ("o", "FD", 21, [21, 22], {"label": "stool"}, [
  "Go to a stool.",
  "Could you show me one of the backless bar seats?",
  "bar seat, no back",
  "I just need a quick perch in the kitchenette, so either of the seats without a back is fine, not the dining chairs.",
  "This is a seat without a backrest. It stands in the kitchenette.",
  "take me to a barr stool"]),
 # ---------------- or: category in a named room ----------------
 ("or", "O3", 7, [7, 55, 64], {"label": "desk", "room": "rec room"}, [
  "Go to a desk in the rec room.",
  "Could you take me to one of the work tables in the recreation room?",
  "writing table, rec room",
  "I need to fill in a form, so any of the desks in the rec room will do.",
  "This is a work surface for writing or computing. It is in the rec room.",
  "take me to a wrok table in the rec room"]),
 ("or", "C829", 261, [261, 263], {"label": "easy chair", "room": "bedroom"}, [
  "Go to an easy chair in the bedroom.",
  "Could you take me to one of the lounge chairs in the bedroom?",
  "bedroom armchair",
  "I want to sit down in the bedroom; any comfy armchair there, not the ones in the living room.",
  "This is a padded armchair for relaxing. It is in the bedroom.",
  "find me a comfy armchiar in the bedroom"]),
 ("or", "C829", 160, [160, 162, 164], {"label": "set of towels", "room": "living room"}, [
  "Go to the set of towels in the living room.",
  "Could you take me to the folded towels in the living room?",
  "towel stack, living room",
  "I spilled water on the sofa, so take me to any of the towel piles in the living room; there is no need to go elsewhere.",
  "These are folded cotton bath towels. They are kept in the living room.",
  "where are the towles in the living room"]),
 ("or", "FH", 46, [46, 47], {"label": "nightstand", "room": "master bedroom"}, [
  "Go to a nightstand in the master bedroom.",
  "Could you take me to one of the bedside tables in the main bedroom?",
  "bedside table, master bedroom",
  "I want to charge my phone by the big bed, so either bedside table in the master bedroom, not the one in the guest room.",
  "This is a small table next to the bed. It is in the master bedroom.",
  "go to a bedsied table in the main bedroom"]),
 ("or", "FF", 12, [12, 13, 14, 15], {"label": "chair", "room": "kitchen"}, [
  "Go to a chair in the kitchen.",
  "Could you find me a seat at the table in the kitchen?",
  "kitchen dining seat",
  "I want to eat breakfast, so any dining seat in the kitchen is fine, not the rocker on the porch.",
  "This is a wooden dining seat with a back. It stands at the table in the kitchen.",
  "take me to a kitchen chiar"]),
 ("or", "APT", 12, [12, 13], {"label": "book", "room": "living room"}, [
  "Go to a book in the living room.",
  "Could you take me to one of the books in the living room?",
  "living room reading material",
  "I want something to read on the sofa, so any volume from the living room, not the textbook in the office.",
  "This is a bound volume on a shelf. It is in the living room.",
  "find a volumme in the living room"]),
 ("or", "FC", 19, [19, 20, 21], {"label": "chair", "room": "kitchen"}, [
  "Go to a chair in the kitchen.",
  "Could you take me to one of the seats around the kitchen table?",
  "seat, kitchen",
  "I'd like to sit while the kettle boils, so any dining seat in the kitchen, not the rattan one in the bedroom.",
  "This is a seat with a back at the dining table. It is in the kitchen.",
  "can i sit on a chiar in the kitchen"]),
 # ---------------- od: described object ----------------
 ("od", "O3", 37, [37], {"note": "only chair whose caption has a speaker; black plastic"}, [
  "Go to the black plastic chair that has a speaker built in.",
  "Could you take me to the seat with the built-in speaker and massager?",
  "plastic seat with speaker",
  "I want to play music while I sit, so the black plastic seat with a speaker in it, not the mesh ones.",
  "This is a black plastic seat. It has a speaker and a massager built in.",
  "the chair with the speakr in it pls"]),
 ("od", "C829", 56, [56], {"note": "only doorway with a peephole and a gold doorknob"}, [
  "Go to the doorway with the peephole.",
  "Could you take me to the door that has a gold knob and a little spyhole?",
  "door with peephole, gold knob",
  "Someone knocked and I want to see who it is, so the door with the peephole, not the other wooden ones.",
  "This is a dark wooden door. It has a spyhole to look through and a knob in gold.",
  "go to the door with the peephloe"]),
 ("od", "FH", 13, [13], {"note": "only yellow enamel mug"}, [
  "Go to the yellow enamel mug.",
  "Could you take me to the yellow camping cup?",
  "yellow enamel cup",
  "I left my camp cup somewhere; it's the yellow one, not the striped white one or the black one.",
  "This is a small yellow cup made of enamel. It looks like something taken on camping trips.",
  "where's my yelow camping mug"]),
 ("od", "FD", 5, [5], {"note": "only yellow chair"}, [
  "Go to the yellow wooden chair.",
  "Could you take me to the seat painted yellow?",
  "yellow painted seat",
  "I want to sit at the dining table on the yellow seat, not the white plastic one.",
  "This is a wooden seat painted bright yellow. It has a back and sits at the round table.",
  "take me to the yelow chair"]),
 ("od", "APT", 2, [2], {"note": "only brown leather sofa (loveseat)"}, [
  "Go to the brown leather loveseat.",
  "Could you take me to the small leather couch?",
  "brown leather two-seater",
  "I prefer leather, so the little brown couch, not the big gray fabric one.",
  "This is a small couch covered in brown leather. It seats two people and looks a bit worn.",
  "go to the brown lether couch"]),
 ("od", "SK", 21, [21], {"note": "only red chair"}, [
  "Go to the red chair.",
  "Could you take me to the red seat at the table?",
  "red seat",
  "I always sit on the red one, not the black or white seats.",
  "This is a red dining seat. It is the only one in that colour.",
  "take me to the rde chair"]),
 ("od", "FF", 14, [14], {"note": "only mustard-yellow chair"}, [
  "Go to the mustard-yellow chair.",
  "Could you take me to the yellow painted seat at the dining table?",
  "yellow wooden seat",
  "Bring me to the yellow seat, not any of the blue ladder-back ones at the table.",
  "This is a wooden seat painted mustard yellow. It is different from the blue ones around it.",
  "the mustard chiar please"]),
 # ---------------- ord: described + room ----------------
 ("ord", "O3", 40, [40], {"note": "orange pillow with white and yellow stripes (vs plain orange 8)"}, [
  "Go to the striped orange pillow in the rec room.",
  "Could you take me to the orange cushion with white and yellow stripes in the rec room?",
  "striped orange cushion, rec room",
  "In the rec room, I want the orange cushion with stripes, not the plain puffy orange one with the button.",
  "This is an orange cushion with white and yellow stripes. It is in the rec room.",
  "get me the stripy orange pilow in the rec room"]),
 ("ord", "C829", 83, [83], {"note": "dark blue woven basket with lid, kitchen"}, [
  "Go to the dark blue woven basket in the kitchen.",
  "Could you take me to the blue woven hamper with a lid in the kitchen?",
  "kitchen blue basket with lid",
  "I need to put away some laundry, so the dark blue woven basket in the kitchen, not the bag in the living room.",
  "This is a woven hamper in deep navy. It has a carrying handle and a metal lid, and it is in the kitchen.",
  "take me to the blue baskett in the kitchen"]),
 ("ord", "C829", 272, [272], {"note": "pale blue floral bed curtain, bedroom (vs curtain 254)"}, [
  "Go to the pale blue bed curtain in the bedroom.",
  "Could you take me to the light blue drape with flowers on it in the bedroom?",
  "floral bed drape, bedroom",
  "In the bedroom I mean the floral blue bed drape, not the silky blue-gray one.",
  "This is a light blue fabric drape with a floral pattern that hangs by a bed. It is in the bedroom.",
  "the flowery bed curtian in the bedroom"]),
 ("ord", "FC", 21, [21], {"note": "black metal chair in kitchen (others white wood)"}, [
  "Go to the black metal chair in the kitchen.",
  "Could you take me to the dark metal seat in the kitchen?",
  "black metal seat, kitchen",
  "In the kitchen, I want the black metal seat, not the white wooden ones.",
  "This is a black seat made of metal. It is in the kitchen, at the dining table.",
  "go to the blak metal chair in the kitchen"]),
 ("ord", "FH", 43, [43], {"note": "red ceramic lamp, guest bedroom"}, [
  "Go to the red lamp in the guest bedroom.",
  "Could you take me to the red ceramic bedside light in the guest room?",
  "red bedside light, guest room",
  "I'm staying over, so the red bedside light in the guest bedroom, not the white one in the master bedroom.",
  "This is a bedside light with a red ceramic base and a cream shade. It is in the guest bedroom.",
  "the red lamp in the gest bedroom"]),
 ("ord", "APT", 43, [43], {"note": "oval frameless mirror, bathroom (vs gold hallway mirror 30)"}, [
  "Go to the oval mirror in the bathroom.",
  "Could you take me to the lit frameless looking glass in the bathroom?",
  "oval bathroom looking glass",
  "I want to brush my teeth with a good view, so the oval glass in the bathroom, not the gold-framed one in the hall.",
  "This is an oval looking glass without a frame and with a light built in. It hangs in the bathroom above the basin.",
  "the ovel mirror in the bathroom pls"]),
 ("ord", "FD", 31, [31], {"note": "round rainbow rug, kids room (vs gray rug 11 in studio)"}, [
  "Go to the round rainbow rug in the kids room.",
  "Could you take me to the striped play mat in the children's room?",
  "round play mat, kids room",
  "The kids want to play on the floor, so the round colourful mat in their room, not the gray wool one in the studio.",
  "This is a round cotton floor mat with rainbow stripes. It is in the kids room.",
  "take me to the rainbow rugg in the kids room"]),
 # ---------------- ard: need / activity ----------------
 ("ard", "O3", 25, [25], {"note": "only wall-mounted timepiece"}, [
  "Take me to something on the wall that tells the time.",
  "Could you show me where I can check the time on the wall?",
  "wall timepiece",
  "My phone is dead and I need to know what time it is; something mounted on the wall, not a screen.",
  "This is what I would look at to see the hour. It hangs on the wall and has a second hand.",
  "need to chek the time, what's on the wall for that"]),
 ("ard", "C829", 122, [122], {"note": "only toilet"}, [
  "Take me somewhere I can relieve myself.",
  "Could you bring me to where I can go to the loo?",
  "need loo",
  "I really need to pee; take me to the WC, not the sink.",
  "This is what you sit on to relieve yourself. It is white porcelain and it flushes.",
  "urgently need to use the lavatroy"]),
 ("ard", "FD", 24, [24], {"note": "washing machine, not the dryer"}, [
  "Take me to where I can wash my dirty clothes.",
  "Could you show me what I use to do the laundry washing?",
  "wash dirty clothes",
  "My gym kit is filthy and I want to clean it, not dry it; where do I do that?",
  "This is where you put soiled clothes with detergent. It fills with water and spins them clean.",
  "where do i wash my muddy cloths"]),
 ("ard", "FF", 25, [25], {"note": "telescope"}, [
  "Take me to something I can use to look at the stars.",
  "Could you bring me to what I would use for watching the night sky?",
  "stargazing",
  "There's a full moon tonight and I want a close look at it, not just from the window.",
  "This is the thing you point at the sky to see planets up close. It stands on three legs.",
  "want to see the plantes up close tonight"]),
 ("ard", "FH", 4, [4], {"note": "key dish on console table; the table itself not accepted"}, [
  "Take me to where I should leave my house keys.",
  "Could you show me where the keys are usually dropped when coming home?",
  "key drop spot",
  "I just came in and don't want to lose my keys again, so where do they normally go? Not the coat stand.",
  "This is the spot near the entrance where keys are tossed. It is small, green and sits on a narrow table in the hallway.",
  "where do my kyes go when i get home"]),
 ("ard", "APT", 54, [54], {"note": "only printer"}, [
  "Take me to something that can put my document on paper.",
  "Could you bring me to where I can print my boarding pass?",
  "print document",
  "I need a paper copy of my ticket, not just on the screen.",
  "This is what turns files into pages. It sits on the gray metal drawer unit in the office.",
  "need to prnit my tickets"]),
 ("ard", "FC", 29, [29], {"note": "only alarm clock"}, [
  "Take me to what will wake me up in the morning.",
  "Could you show me what I can set to wake me at six?",
  "wake-up ringer",
  "I have an early flight and must not oversleep; not my phone, the bedside thing that rings.",
  "This is what rings in the morning to get you out of bed. It is small and red.",
  "i need to set a wake-up alrm for tomorrow"]),
 ("ard", "SO", 17, [17], {"note": "only whiteboard"}, [
  "Take me to somewhere I can draw a diagram with markers.",
  "Could you bring me to where I can sketch out a plan for the team?",
  "sketch with markers",
  "I want to explain an idea to my colleagues with a drawing, on the wall, not on paper.",
  "This is the wall surface you write on and wipe clean. It is mounted on the west wall.",
  "need to draw a diagarm for the meeting"]),
 # ---------------- s: spatial ----------------
 ("s", "SB", 6, [6], {"check": "nearest", "label": "nightstand", "ref": 14, "also_nearest_other": [7, 15]}, [
  "Go to the nightstand closest to the window.",
  "Could you take me to the bedside table nearest the window?",
  "bedside table near window",
  "I want the bedside table by the window, not the one over by the door.",
  "This is a bedside table beside the bed. It is the one closer to the window.",
  "go to the nighstand by the window"]),
 ("s", "SK", 3, [3], {"check": "under", "label": "kitchen cabinet", "ref": 10}, [
  "Go to the kitchen cabinet under the sink.",
  "Could you take me to the cupboard beneath the sink?",
  "cupboard below sink",
  "I need the cleaning spray, which is in the cupboard right under the sink, not the wall units above.",
  "This is a white base cupboard along the back wall. The sink sits directly on top of it.",
  "go to the cupbaord under the sink"]),
 ("s", "SL", 3, [3], {"check": "between", "label": "pillow", "refs": [2, 4], "on": 1}, [
  "Go to the pillow between the other two on the sofa.",
  "Could you take me to the middle cushion on the couch?",
  "middle sofa cushion",
  "Not the cushions at either end of the sofa, the one in the centre between them.",
  "This is a cushion on the sofa. It sits in the middle, between two other cushions.",
  "the midle cushion on the couch pls"]),
 ("s", "SO", 10, [10], {"check": "nearest", "label": "office chair", "ref": 20, "near_obj": 2}, [
  "Go to the office chair closest to the door.",
  "Could you take me to the desk chair nearest the door?",
  "swivel seat nearest door",
  "I have to leave quickly later, so the seat nearest the exit, not one by the windows.",
  "This is a swivel seat at the wooden table. It is the closest one to the door.",
  "take me to the office chiar nearest the door"]),
 ("s", "SO", 16, [16], {"check": "lowest", "label": "bookshelf"}, [
  "Go to the shortest bookshelf.",
  "Could you take me to the lowest of the bookcases?",
  "shortest bookcase",
  "I can't reach high shelves, so the low bookcase, not the tall ones.",
  "This is a bookcase against the north wall. It is the shortest of the three.",
  "the shortest bookshlef please"]),
 ("s", "FC", 27, [27], {"check": "supports", "label": "nightstand", "ref": 29, "other_ref": 28}, [
  "Go to the nightstand with the alarm clock on it.",
  "Could you take me to the bedside table that has the clock on top?",
  "bedside table with clock",
  "I want the bedside table holding the clock, not the one with the pink lamp.",
  "This is a white bedside table. A small red clock stands on it.",
  "the bedside tabel with the clock on it"]),
 ("s", "FF", 14, [14], {"check": "nearest", "label": "chair", "ref": 17}, [
  "Go to the chair nearest the stove.",
  "Could you take me to the dining seat closest to the range cooker?",
  "seat nearest cooker",
  "I'm cold, so the seat closest to the warm range cooker, not the ones farther down the table.",
  "This is a dining seat at the kitchen table. Of all the seats it is the nearest to the cooker.",
  "the chiar closest to the oven"]),
 ("s", "FH", 13, [13], {"check": "on", "label": "mug", "ref": 7}, [
  "Go to the mug on the coffee table.",
  "Could you take me to the cup sitting on the coffee table?",
  "cup on coffee table",
  "Not the one on the desk or in the kitchen; the cup left on the low table in the living room.",
  "This is a cup resting on the low table in front of the sofa. It is in the living room.",
  "grab the mug on the cofee table"]),
 ("s", "FD", 2, [2], {"check": "nearest", "label": "table", "ref": 1}, [
  "Go to the table nearest the sofa bed.",
  "Could you take me to the low surface right in front of the fold-out couch?",
  "low table by sofa bed",
  "I want to put my drink down while on the fold-out couch, so the low one in front of it, not the round dining one.",
  "This is a low glass-topped piece of furniture. It is the one closest to the fold-out couch.",
  "put my cup on the low tabel by the sofa bed"]),
 ("s", "FH", 11, [11], {"check": "corner", "label": "armchair", "room": "living room"}, [
  "Go to the armchair in the corner.",
  "Could you take me to the easy chair tucked into the corner of the living room?",
  "corner lounge chair",
  "I want the corner seat, not the one next to the bookshelf.",
  "This is a single upholstered seat with arms. It sits in the corner of the living room.",
  "take me to the armchiar in the corner"]),
 ("s", "APT", 12, [12], {"check": "higher", "label": "book", "among": [12, 13], "in_obj": 11}, [
  "Go to the higher of the two books on the living room bookshelf.",
  "Could you take me to the book on the upper shelf in the living room?",
  "upper-shelf novel, living room",
  "Not the one lying flat at the bottom, the volume standing higher up on the living room shelves.",
  "This is a volume standing on the lounge bookcase. It is the higher of the two there.",
  "the higher novle on the living room shelf"]),
 ("s", "APT", 34, [34], {"check": "on", "label": "lamp", "ref": 33}, [
  "Go to the lamp on the nightstand.",
  "Could you take me to the light sitting on the bedside table?",
  "bedside table light",
  "Not the floor lamp in the lounge or the desk one; the light standing on the bedside table.",
  "This is a small light with a white shade. It stands on top of the bedside table.",
  "turn on the lihgt on the nightstand"]),
]


def main():
    out = ROOT / "evals/blind/round49.jsonl"
    spec = {}
    lines = []
    assert len(G) == 48, len(G)
    for i, (typ, mk, target, accept, sp, words) in enumerate(G, 1):
        assert len(words) == 6
        gid = f"b49-g{i:02d}"
        spec[gid] = {"type": typ, "map": MAPS[mk], "target": target, "accept": accept, **sp}
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"{gid}-w{k}", "map": MAPS[mk], "query": q, "type": typ,
                                     "target": target, "accept": sorted(accept), "group": gid}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    (ROOT / "scripts/blind_writers/_specs_round49.json").write_text(json.dumps(spec, indent=1), encoding="utf-8")
    print(f"wrote {len(lines)} lines to {out}")


if __name__ == "__main__":
    main()
