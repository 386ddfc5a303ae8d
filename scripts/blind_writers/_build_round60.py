"""Write evals/blind/round60.jsonl from the hand-written groups below.

Every wording here was written by hand from the maps; this script only numbers and serialises them.
Each group: (map, type, target, accept, [w1..w6], (typo, intended word) for w6).
"""
import json
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "evals" / "blind" / "round60.jsonl"

M829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
MOF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

GROUPS = [
    # ---------------- scene_00829 (caption map) ----------------
    (M829, "o", 23, [23, 184], [
        "Take me to a sofa.",
        "Could you bring me over to any of the sofas in the house?",
        "Any sofa will do",
        "I just want to lie down for a bit, so any couch is fine.",
        "This is nap time for me. Find me a settee, whichever one.",
        "whichever sofa, i just need to strech out for a bit",
    ], ("strech", "stretch")),
    (M829, "or", 261, [261, 263], [
        "Head to an armchair in the bedroom.",
        "Could you take me to one of the lounge chairs in the bedroom?",
        "Bedroom armchair, either one",
        "I want to read before bed, so any of the bedroom armchairs works, not the couch in there.",
        "This is for some quiet reading in the bedroom. Take me to an easy chair there.",
        "any comfy armchiar in the bedroom works for me",
    ], ("armchiar", "armchair")),
    (M829, "od", 56, [56], [
        "Take me to the dark wooden door with the peephole and gold knob.",
        "Could you go to the door that has a little spyhole in it?",
        "Door with peephole, gold knob",
        "I want to see who's outside, so the door with the peephole, not the one with the smart lock.",
        "This is the door with the gold handle I mean. It's the one with a tiny peephole, so take me there.",
        "go to the wooden door with the peephole and the gold doorknbo",
    ], ("doorknbo", "doorknob")),
    (M829, "od", 164, [164], [
        "Bring me to the towels that have an H embroidered on them.",
        "Could you show me the stack of towels monogrammed with the letter H?",
        "Towels with embroidered H",
        "Those are my monogrammed ones, so the towels with the H, not the plain folded piles.",
        "This is the pile with a letter H sewn onto it. Please lead me to those towels.",
        "take me to the towles with the letter h stitched on",
    ], ("towles", "towels")),
    (M829, "ord", 114, [114], [
        "Walk me to the bathroom door with the electronic lock.",
        "Could you find the door into the bathroom that has an electronic lock?",
        "Bathroom door, electronic lock",
        "I need the bathroom door with the electronic lock, not the living room one with the smart lock.",
        "This is the bathroom entrance I mean. It's the dark wood one fitted with an electronic lock.",
        "the bathroom door with the electonic lock please",
    ], ("electonic", "electronic")),
    (M829, "ard", 192, [192], [
        "Take me to where the dog sleeps in the bathroom.",
        "Could you show me the spot where our dog curls up for naps, the white and brown one in the bathroom?",
        "Dog's napping spot, bathroom",
        "The puppy is worn out, so I need its cosy sleeping spot in the bathroom, not the couch.",
        "This is for the dog's afternoon nap. Where does it sleep in the bathroom?",
        "where does the dog snoze, the soft white and brown thing in the bathroom",
    ], ("snoze", "snooze")),
    # ---------------- scene_office3 (caption map) ----------------
    (MOF3, "o", 13, [8, 13, 20, 40], [
        "Go to a cushion.",
        "Could you lead me to any of the throw pillows?",
        "Any cushion",
        "My back is sore, so bring me to a cushion, whichever one.",
        "This is for propping up my back. Go to a pillow, any of them.",
        "just need a cushon, any one will do",
    ], ("cushon", "cushion")),
    (MOF3, "or", 55, [7, 55, 64], [
        "Take me to a desk in the rec room.",
        "Could you get me to one of the desks in the rec room?",
        "Rec room workstation",
        "I have emails to answer, so any workstation in the rec room will do, not the sofa.",
        "This is about the rec room. Bring me to any of the workstations in there.",
        "any workstaton in the rec room is fine",
    ], ("workstaton", "workstation")),
    (MOF3, "od", 40, [40], [
        "Head to the orange cushion with the white and yellow stripes.",
        "Could you go to the striped orange pillow?",
        "Striped orange cushion",
        "I want the striped one, not the orange cushion with the button in the middle.",
        "This is the orange cushion with stripes on it. Please bring me over to it.",
        "go to the orange cusion with white and yellow stripes",
    ], ("cusion", "cushion")),
    (MOF3, "ord", 10, [10], [
        "Go to the rec room window that has a clock above it.",
        "Could you take me to the window in the rec room with the clock over it?",
        "Rec room pane below clock",
        "I want to lower the blind, so the rec room pane with the clock above it, not the frosted one.",
        "This is the red-tinted glass in the rec room. Take me to the one under the clock.",
        "the red glass pane in the rec room with the clokc above it",
    ], ("clokc", "clock")),
    (MOF3, "ard", 25, [25], [
        "Take me to whatever shows the time on the rec room wall.",
        "Could you go to the thing on the rec room wall that tells the time?",
        "Check time, rec room wall",
        "I'm worried I'm running late, so take me to what shows the time on the wall, not my phone.",
        "This is about knowing the time. Go to the black and red thing with a second hand on the rec room wall.",
        "take me to the thing on the rec room wall that shows the tiem",
    ], ("tiem", "time")),
    (MOF3, "ard", 67, [67], [
        "Bring me to whatever I can use to change the channel in the rec room.",
        "Could you take me to the thing I use to switch channels?",
        "Switch channels, rec room",
        "I'm sick of this show, so I need the thing with buttons for flipping channels, not the phone.",
        "This is for switching the programme. Go to the black and white plastic gadget with a small screen.",
        "i want to flip the chnnel, take me to the thing for that",
    ], ("chnnel", "channel")),
    # ---------------- flat_b ----------------
    (FB, "o", 5, [5, 7, 26, 33, 34], [
        "Take me to a lamp.",
        "Could you show me to any one of the lamps?",
        "Any reading light",
        "It's getting dark in here, so any light I can switch on will do.",
        "This is getting too dim for me. Bring me to any table or floor light.",
        "take me to any ligt you can find",
    ], ("ligt", "light")),
    (FB, "or", 31, [31, 32], [
        "Go to a bedside table in the bedroom.",
        "Could you take me to either nightstand in the bedroom?",
        "Bedroom bedside table, either side",
        "I left my glasses on one, so either bedside table in the bedroom is fine.",
        "This is about the bedroom. Go to a bedside cabinet there, either side.",
        "take me to either bedsdie table in the bedroom",
    ], ("bedsdie", "bedside")),
    (FB, "ord", 28, [28], [
        "Lead me to the green reading chair in the study.",
        "Could you go to the green upholstered armchair in the study?",
        "Green reading chair, study",
        "I want to read, so the green chair in the study, not the mesh desk chair.",
        "This is the comfy green one in the study. Please take me to that seat.",
        "the grean comfy chair in the study please",
    ], ("grean", "green")),
    (FB, "s", 33, [33], [
        "Go to the bedroom lamp closest to the window.",
        "Could you take me to the bedside light nearest the bedroom window?",
        "Bedroom lamp nearest window",
        "I want to read by the window, so the bedroom light nearer to it, not the far one.",
        "This is in the bedroom. Take me to whichever bedside light sits nearest the window.",
        "the bedroom light closest to the windwo",
    ], ("windwo", "window")),
    # ---------------- flat_e ----------------
    (FE, "or", 30, [30], [
        "Take me to the washbasin in the bathroom.",
        "Could you go to the sink in the bathroom?",
        "Bathroom basin",
        "I need to wash my face, so the bathroom basin, not the kitchen one.",
        "This is for brushing my teeth. Go to the basin in the bathroom.",
        "the basin in the bathroom, i need to wahs my hands",
    ], ("wahs", "wash")),
    (FE, "ord", 14, [14], [
        "Go to the black metal chair in the dining room.",
        "Could you take me to the odd one out among the dining room chairs, the black bistro one?",
        "Dining room's black metal seat",
        "The green ones wobble, so I want the black metal seat in the dining room, not the painted wooden ones.",
        "This is the mismatched seat in the dining room. Take me to the black metal one.",
        "the black metal chiar in the dining room",
    ], ("chiar", "chair")),
    (FE, "ard", 33, [33], [
        "Take me to where I can dry the wet laundry in the utility room.",
        "Could you take me to wherever I can tumble the washing dry?",
        "Dry clothes, utility room",
        "It's raining and the washing is soaking wet, so I need somewhere indoors to dry it.",
        "This is a load of damp towels. Where in the utility room can I get them dry?",
        "where can i dyr my clothes in the utility room",
    ], ("dyr", "dry")),
    (FE, "s", 6, [6], [
        "Go to the plant next to the TV.",
        "Could you take me to the houseplant closest to the television?",
        "Greenery nearest telly",
        "I want to water the one indoors by the TV, not the tree out on the balcony.",
        "This is the big leafy one in the corner beside the TV. Take me to it.",
        "the leafy pot rigth by the tv",
    ], ("rigth", "right")),
    # ---------------- flat_g ----------------
    (FG, "o", 2, [2, 3], [
        "Take me to a bike.",
        "Could you go to one of the bicycles?",
        "Any bike",
        "I need to pump up a tyre, so either bike will do.",
        "This is for a quick ride to the shops. Find me a bike, whichever.",
        "take me to any of the bkies",
    ], ("bkies", "bikes")),
    (FG, "od", 19, [19], [
        "Go to the wooden chair with the red checked cushion.",
        "Could you show me the chair that has the red gingham seat pad?",
        "Wooden seat, red checked cushion",
        "I prefer a soft seat, so the wooden one with the red checked pad, not the white plastic one.",
        "This is the wooden seat with the red checked padding. Please bring me to it.",
        "the wodden seat with the red check cushion",
    ], ("wodden", "wooden")),
    (FG, "ard", 11, [11], [
        "Take me to where I can iron my shirt.",
        "Could you go to the spot in the laundry room where I can press clothes?",
        "Press shirts, laundry room",
        "I've got a job interview, so I need somewhere to iron my shirt.",
        "This is a very creased shirt. Where can I get it smoothed out?",
        "need to iron my trousres, where can i do that",
    ], ("trousres", "trousers")),
    (FG, "s", 41, [41], [
        "Go to the mirror over the washbasin.",
        "Could you take me to the looking glass hanging above the sink?",
        "Shaving glass above basin",
        "I want to shave, so the glass above the basin, not the full-length one in the hall.",
        "This is the round one over the washbasin. Take me there.",
        "the round mirror hanging above the washbsin",
    ], ("washbsin", "washbasin")),
    # ---------------- flat_i ----------------
    (FI, "o", 23, [23, 31, 36], [
        "Take me to a mug.",
        "Could you go to any of the cups lying around?",
        "Any coffee cup",
        "I'm thirsty, so any mug will do.",
        "This is tea time. Find me a cup, whichever one.",
        "just want a cupp, any of them",
    ], ("cupp", "cup")),
    (FI, "ord", 46, [46], [
        "Go to the bedroom lamp with the woven rattan shade.",
        "Could you take me to the light in the bedroom whose shade is woven wicker?",
        "Bedroom rattan-shade light",
        "I want the bedroom light that throws patterns on the wall, not the white ceramic lamp.",
        "This is in the bedroom, on the white bedside table. Take me to the light with the woven shade.",
        "the bedroom light with the rattan shaed",
    ], ("shaed", "shade")),
    (FI, "ard", 20, [20], [
        "Take me to where I can print out the A3 drawings in the studio.",
        "Could you go to whatever prints plans in the studio?",
        "Print A3 plans, studio",
        "The client wants paper copies, so I need somewhere to print big drawings.",
        "This is a batch of floor plans. Where can I print them out?",
        "need to prnt out some plans in the studio",
    ], ("prnt", "print")),
    (FI, "s", 13, [13], [
        "Go to the desk on the right when you face the studio's north wall.",
        "Could you take me to the right-hand desk in the studio, looking toward the north wall?",
        "Studio, right workspace facing north",
        "Facing the north wall of the studio, I want the workspace on the right, not the left one.",
        "This is the studio, looking toward the north wall. Take me to the right-hand workspace.",
        "in the studio facing north, the dsek on the right",
    ], ("dsek", "desk")),
    # ---------------- apartment ----------------
    (APT, "o", 8, [8, 39, 55], [
        "Take me to a plant.",
        "Could you go to any of the houseplants?",
        "Any potted greenery",
        "I'm doing the watering today, so any potted plant will do.",
        "This is for watering. Bring me to a houseplant, any one.",
        "take me to any plnt in the flat",
    ], ("plnt", "plant")),
    (APT, "or", 12, [12, 13], [
        "Go to a book in the living room.",
        "Could you take me to one of the books in the living room?",
        "Living room reading material",
        "I'm bored, so any novel or photo album in the living room will do.",
        "This is for something to read on the sofa. Take me to any volume in the living room.",
        "take me to something to read in the livng room, any of the volumes",
    ], ("livng", "living")),
    (APT, "or", 43, [43], [
        "Take me to the mirror in the bathroom.",
        "Could you go to the bathroom mirror?",
        "Bathroom looking glass",
        "I need to check my teeth, so the glass in the bathroom, not the one in the hallway.",
        "This is for doing my makeup. Go to the looking glass in the bathroom.",
        "take me to the looking glass in the bathrom",
    ], ("bathrom", "bathroom")),
    (APT, "od", 31, [31], [
        "Go to the black-and-white photo of the lighthouse.",
        "Could you take me to the little lighthouse photograph?",
        "Lighthouse photo, black frame",
        "I want the lighthouse print, not the big blue and orange painting.",
        "This is a small monochrome photo in a thin frame. Take me to the one showing a lighthouse.",
        "the lighthose photo in black and white",
    ], ("lighthose", "lighthouse")),
    (APT, "ord", 24, [24], [
        "Take me to the white painted chair in the kitchen.",
        "Could you go to the kitchen chair with the spindle back?",
        "White spindle seat, kitchen",
        "I want the white one in the kitchen, not the one with the green cushion.",
        "This is the white wooden seat across the kitchen table. Take me there.",
        "the white spindel-back seat in the kitchen",
    ], ("spindel", "spindle")),
    (APT, "ard", 45, [45], [
        "Take me to where I can wash a load of clothes.",
        "Could you go to where the laundry gets washed, in the bathroom?",
        "Wash dirty clothes",
        "My gym kit stinks, so I need somewhere to wash it, not the sink.",
        "This is a pile of dirty laundry. Where can I put it on a wash?",
        "where can i do the laundrey in the bathroom",
    ], ("laundrey", "laundry")),
    (APT, "s", 2, [2], [
        "Go to the sofa closest to the TV.",
        "Could you take me to the couch nearest the television?",
        "Settee nearest television",
        "I want to see the screen properly, so the couch nearer the TV, not the big one against the far wall.",
        "This is for watching the match up close. Take me to whichever couch is nearest the telly.",
        "the coutch closest to the tv",
    ], ("coutch", "couch")),
    (APT, "s", 12, [12], [
        "Go to the book higher up on the living room bookshelf.",
        "Could you take me to the book on the upper shelf in the living room?",
        "Higher shelf volume, living room",
        "I can't bend down today, so the volume up high on the living room shelves, not the one at the bottom.",
        "This is on the living room bookcase. I want the volume sitting higher up.",
        "the higher one of the two volumes on the living room shlef",
    ], ("shlef", "shelf")),
    # ---------------- scan_bedroom ----------------
    (SB, "od", 4, [4], [
        "Take me to the red pillow.",
        "Could you go to the red cushion on the bed?",
        "Red cushion",
        "I want the red one, not the white pillows.",
        "This is the only red cushion in here. Take me to it.",
        "the red cushin please",
    ], ("cushin", "cushion")),
    (SB, "s", 8, [8], [
        "Go to the lamp on the left nightstand when you stand at the foot of the bed.",
        "Could you take me to the left-hand bedside light, facing the bed from its foot?",
        "Left bedside light, facing headboard",
        "Facing the headboard, I want the light on the left side, not the right.",
        "This is from the foot of the bed, looking at the headboard. Take me to the lamp on the left.",
        "standing at the foot of the bed, the lmap on the left",
    ], ("lmap", "lamp")),
    (SB, "s", 5, [5], [
        "Go to the pillow down by the foot of the bed.",
        "Could you take me to the cushion closest to the foot end of the bed?",
        "Cushion at bed's foot",
        "I want the one lying near the foot, not the pillows up by the headboard.",
        "This is at the bottom end of the bed. Take me to the cushion lying there.",
        "the cusion nearest the foot of the bed",
    ], ("cusion", "cushion")),
    # ---------------- scan_kitchen ----------------
    (SK, "o", 26, [26, 27], [
        "Take me to a bin.",
        "Could you go to any of the garbage cans?",
        "Any rubbish bin",
        "I need to throw away this wrapper, so either bin will do.",
        "This is rubbish to throw out. Bring me to a trash can, any one.",
        "take me to whichever bin, i have some rubish",
    ], ("rubish", "rubbish")),
    (SK, "ard", 12, [12], [
        "Take me to where I can brew a coffee.",
        "Could you go to the thing that makes my morning coffee?",
        "Brew coffee",
        "I'm half asleep, so take me to whatever brews coffee.",
        "This is my caffeine emergency. Where can I get some coffee brewed?",
        "where can i make some cofee",
    ], ("cofee", "coffee")),
    (SK, "s", 3, [3], [
        "Go to the cupboard under the sink.",
        "Could you take me to the cabinet right below the sink?",
        "Cupboard beneath sink",
        "I need the dish soap, so the cupboard under the sink, not the wall ones above.",
        "This is the low cabinet directly under the sink. Take me there.",
        "the cuboard under the sink",
    ], ("cuboard", "cupboard")),
    # ---------------- scan_livingroom ----------------
    (SL, "or", 8, [8, 9], [
        "Take me to a side table in the living room.",
        "Could you go to either of the little end tables in the living room?",
        "Living room end table",
        "I need to put my drink down, so either end table in the living room will do, not the coffee table.",
        "This is about the living room. Take me to one of the small side tables there.",
        "either end tabel in the living room",
    ], ("tabel", "table")),
    (SL, "ord", 5, [5], [
        "Go to the green armchair in the living room.",
        "Could you take me to the green easy chair in the living room?",
        "Living room's green armchair",
        "I want the green one in the living room, not the brown leather chair.",
        "This is the green seat in the living room. Bring me over to it.",
        "the grene comfy chair in the living room",
    ], ("grene", "green")),
    (SL, "s", 4, [4], [
        "Go to the red pillow on the left as you face the sofa.",
        "Could you take me to the red cushion that's on your left when you stand facing the couch?",
        "Red cushion, left facing sofa",
        "Standing in front of the sofa looking at it, I want the red cushion on the left, not the one on the right.",
        "This is from in front of the couch, facing it. Take me to the red cushion on the left-hand side.",
        "facing the sofa, the red cushon on the left",
    ], ("cushon", "cushion")),
    # ---------------- scan_office ----------------
    (SO, "od", 30, [30], [
        "Take me to the white keyboard.",
        "Could you go to the keyboard that's white?",
        "White computer keys",
        "I prefer the pale one, so the white set of keys, not the black one.",
        "This is the white typing board I mean. Take me to it.",
        "the white keybaord please",
    ], ("keybaord", "keyboard")),
    (SO, "s", 11, [11], [
        "Go to the monitor sitting on the white table.",
        "Could you take me to the screen that's on the white table?",
        "Screen on white table",
        "I want the screen on the white table, not the two on the wooden one.",
        "This is on the white table. Take me to the computer screen there.",
        "the scren on the white table",
    ], ("scren", "screen")),
    (SO, "s", 23, [23], [
        "Take me to the taller of the two plants.",
        "Could you go to the bigger plant, the tall one?",
        "Taller houseplant",
        "I want the big one, not the little one by the bookshelves.",
        "This is the big leafy one. Take me to the taller houseplant.",
        "take me to the tallr houseplant in the office",
    ], ("tallr", "taller")),
]


def rows():
    for g, (mp, typ, target, accept, words, _typo) in enumerate(GROUPS, 1):
        group = f"b60-g{g:02d}"
        for w, q in enumerate(words, 1):
            yield {"id": f"{group}-w{w}", "map": mp, "query": q, "type": typ, "target": target,
                   "accept": accept, "group": group}


if __name__ == "__main__":
    lines = [json.dumps(r, ensure_ascii=False) for r in rows()]
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {OUT}")
