"""Write evals/blind/round53.jsonl from the hand-written groups below (round 53, blind helper)."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = (f"maps/flat_{x}.json" for x in "cdfh")
APT = "apartment"
SB, SK, SL, SO = (f"../maps/scan_{x}.json" for x in ("bedroom", "kitchen", "livingroom", "office"))

# (map, type, target, accept, [w1..w6])
G = [
# ---- scene_00829 (caption map) ----
(C829, "o", 42, [42, 197, 212, 259], [
 "Take me to any book in the house.",
 "Could you lead me to one of the books lying around?",
 "Any bound volume to read",
 "I fancy some reading, so go to one of the hardbacks, not the loose sheets of paper.",
 "This is about reading material. Find me a bound volume, whichever is closest.",
 "just get me to a bok, any of them is fine"]),
(C829, "or", 261, [261, 263], [
 "Go to an armchair in the bedroom.",
 "Could you take me to one of the big comfy armchairs in the bedroom?",
 "Bedroom armchair",
 "My back hurts, so find me a padded easy chair in the bedroom, not one out in the living room.",
 "This is the bedroom I mean. Take me to one of the lounge chairs in there.",
 "head to one of the armchiars in the bedroom, either will do"]),
(C829, "od", 184, [184], [
 "Take me to the L-shaped sofa with the chaise end.",
 "Could you find the corner settee that has a built-in lounger section?",
 "L-shaped settee with chaise",
 "I want to stretch my legs out, so go to the corner sofa with the long seat, not the straight one that massages you.",
 "This is the sofa bent into an L. Head over to it, please.",
 "take me over to the l shaped couch with the long lounger bit, the one with storge in it"]),
(C829, "od", 56, [56], [
 "Go to the door that has a little peephole in it.",
 "Could you take me to the wooden door with the spyhole and the gold knob?",
 "Door with peephole",
 "Someone's knocking and I want to see who it is, so go to the door with the peephole, not any of the plain ones.",
 "This is the dark wooden door with a golden handle and a spyhole. Go there.",
 "which door has the little spyhole? take me to that doorwy"]),
(C829, "ord", 191, [191], [
 "Take me to the beige velvet armchair in the bathroom.",
 "Could you go to the soft cream-coloured velvet armchair that's in the bathroom?",
 "Bathroom beige velvet lounge chair",
 "I'd like to sit somewhere soft while the bath runs, so head to the velvety beige lounge chair in the bathroom, not the ones in the living room.",
 "This is the odd comfy chair that sits in a bathroom. Take me to it, the beige velvet one.",
 "go to the bathroom and find the beige velvt lounge chair in there"]),
(C829, "ard", 192, [192], [
 "Go to the spot where the pet curls up to sleep in the bathroom.",
 "Could you show me where our cat naps, the soft white and brown thing in the bathroom?",
 "Where pet sleeps, bathroom",
 "The puppy looks tired, so take me to its sleeping spot in the bathroom, not anywhere people sleep.",
 "This is for the dog. Take me to the plush place it snoozes on, in the bathroom.",
 "where does the cat snooze? the soft white and brown one in the bathrom"]),
(C829, "ard", 249, [249], [
 "Take me to whatever I can type on in the bedroom.",
 "Could you lead me to something in the bedroom I can type an email with?",
 "Something to type on, bedroom",
 "I need to enter a long password, so go to what I'd type with in the bedroom rather than anything to read.",
 "This is about typing. Find me the white plastic thing with keys in the bedroom.",
 "i want to tpye up some notes, take me to what i'd type on in the bedroom"]),
# ---- scene_office3 (caption map) ----
(OFF3, "o", 11, [4, 11, 12, 27], [
 "Go to one of the curtains.",
 "Could you take me to any of the drapes?",
 "Any drapes",
 "The sun's in my eyes, so head to some drapes I can pull across, not the motorised blind.",
 "This is about the window fabric. Go to one of the hanging drapes, red or white, either works.",
 "take me to the curtians, whichever set is nearest"]),
(OFF3, "or", 14, [10, 14, 16, 24], [
 "Take me to a window in the rec room.",
 "Could you find me a spot in the rec room where I can look out through the glass?",
 "Rec room window",
 "I need daylight on this page, so go to one of the panes of glass in the rec room, not the door.",
 "This is the recreation room. Take me over to any of its outside-facing panes.",
 "bring me to a windw in the rec room, any is fine"]),
(OFF3, "od", 13, [13], [
 "Go to the navy velvet cushion.",
 "Could you find the dark blue velvety cushion that has a button at its centre?",
 "Navy velvet cushion",
 "I want the softest one, so take me to the navy velvet cushion, not the orange or yellow ones.",
 "This is the dark blue cushion, a bit bigger than the rest. Take me there.",
 "take me to the navy velvet pilow please"]),
(OFF3, "ord", 7, [7], [
 "Take me to the white wooden desk in the rec room.",
 "Could you go to the white writing table in the recreation room?",
 "White workstation, rec room",
 "I need a bright surface to draw on, so go to the white desk in the rec room, not the brown wooden ones.",
 "This is the pale wooden workspace in the rec room. Take me there, the white one.",
 "go to the white writng surface in the rec room, the pale one"]),
(OFF3, "ard", 25, [25], [
 "Take me to whatever tells the time in the rec room.",
 "Could you show me where I can check what time it is in the rec room?",
 "Check time, rec room",
 "I don't want to be late, so go to the thing on the wall showing the hour, not a phone.",
 "This is about the time. Take me to the black and red thing on the rec room wall with a second hand.",
 "what tiem is it? take me to whatever shows it on the rec room wall"]),
# ---- flat_c ----
(FC, "o", 5, [5, 7, 28, 36], [
 "Go to a lamp.",
 "Could you take me to any light fitting that stands on a table or the floor?",
 "Any reading light",
 "It's getting dark, so find me a light I can switch on, not the TV.",
 "This is about light. Take me to any lamp, floor or table, doesn't matter.",
 "any ligth will do, just get me to the nearest one"]),
(FC, "ord", 3, [3], [
 "Take me to the grey armchair in the living room.",
 "Could you go to the light grey fabric easy chair in the lounge?",
 "Grey easy chair, lounge",
 "I like the quieter colour, so head to the grey armchair in the living room, not the mustard one.",
 "This is the pale grey upholstered chair in the sitting room. Go to it.",
 "take me to the gray comfy chiar in the living room"]),
(FC, "ard", 29, [29], [
 "Take me to the thing that wakes me up in the morning, in the bedroom.",
 "Could you go to whatever rings to get me up, on the bedside in the bedroom?",
 "Set wake-up time, bedroom",
 "I have an early train, so go to what I set my wake-up with in the bedroom, not the laptop in the study.",
 "This is about getting up early tomorrow. Take me to the little red thing by the bed that rings.",
 "take me to the red thing that goes off in the mornign by the bed"]),
(FC, "s", 20, [20], [
 "Go to the kitchen chair closest to the fridge.",
 "Could you take me to whichever dining chair is nearest the refrigerator?",
 "Seat nearest fridge",
 "I want to sit near the cold drinks, so take me to the dining seat by the fridge, not the ones farther off.",
 "This is the seat at the table on the fridge side. Head there.",
 "get me to the seat at the table that's closest to the frige"]),
# ---- flat_d ----
(FD, "or", 4, [4, 5, 7], [
 "Take me to a chair in the studio.",
 "Could you find me somewhere to sit, a chair in the main studio room?",
 "Upright seat, studio",
 "My feet hurt, so take me to one of the studio's upright seats, not the sofa bed.",
 "This is the studio, the big open room. Take me to any of the upright seats in there.",
 "any upright seat in the studoi will do"]),
(FD, "od", 21, [21], [
 "Go to the black metal bar stool.",
 "Could you take me to the metal stool, the black one?",
 "Black metal bar seat",
 "I'd rather not sit on wood, so go to the black metal perch at the breakfast bar, not the wooden one.",
 "This is the tall black metal seat, not the round wooden one. Go there.",
 "take me to the blak metal bar seat"]),
(FD, "ard", 40, [40], [
 "Take me somewhere I can sit to put my shoes on by the front door.",
 "Could you show me where to sit while I lace up my boots in the entrance hall?",
 "Sit, lace shoes, entrance hall",
 "My back's stiff, so take me to where I can sit down to pull my trainers on in the hall, not the sofa bed.",
 "This is for getting my shoes on. Where can I sit in the entrance hall?",
 "where can i sit down to put my sneakres on in the hall"]),
(FD, "s", 11, [11], [
 "Go to the rug under the low coffee table.",
 "Could you take me to the mat lying beneath the glass-topped table?",
 "Mat beneath low table",
 "I dropped an earring onto the floor covering under the low table, so go there, not the kids' play mat.",
 "This is the carpet under the low table by the sofa bed. Take me to it.",
 "take me to the carpet under the glass tabel"]),
# ---- flat_f ----
(FF, "o", 7, [7, 32], [
 "Take me to a rug.",
 "Could you find one of the rugs for me?",
 "Any floor mat",
 "I want to do some stretches somewhere soft, so go to a floor covering, not the bare boards.",
 "This is about something woven on the floor. Take me to any of the carpets, whichever.",
 "just take me to a carpt, either one"]),
(FF, "ord", 14, [14], [
 "Go to the mustard-yellow chair in the kitchen.",
 "Could you take me to the yellow seat at the kitchen table?",
 "Yellow kitchen seat",
 "That's my favourite seat, so head to the yellow one in the kitchen, not the blue ladder-backs.",
 "This is the kitchen chair that doesn't match the others. Take me to the yellow one.",
 "go to the yelow seat in the kitchen"]),
(FF, "ard", 25, [25], [
 "Take me to where I can look at the stars from the porch.",
 "Could you go to the thing on the porch for stargazing?",
 "Stargazing spot, porch",
 "It's a clear night, so take me to what I'd use to see the planets up close on the porch, not the window.",
 "This is for watching the night sky. Go to the black thing on a tripod out on the porch.",
 "i want to look at the moon up close, take me to the tripod thing on the porhc"]),
(FF, "s", 2, [2], [
 "Go to the armchair next to the fireplace.",
 "Could you take me to the easy chair right by the hearth?",
 "Armchair beside hearth",
 "I'm cold, so go to the easy chair closest to the wood burner, not the one across the room.",
 "This is the easy chair nearest the fire. Take me there.",
 "take me to the comfy chair by the fireplce"]),
# ---- flat_h ----
(FH, "or", 46, [46, 47], [
 "Take me to a bedside table in the master bedroom.",
 "Could you go to one of the nightstands in the main bedroom?",
 "Master bedroom bedside table",
 "I left my glasses by the bed, so go to a bedside table in the main bedroom, not the guest room.",
 "This is the master bedroom. Take me to either table beside the double bed.",
 "go to one of the nighstands in the main bedroom"]),
(FH, "od", 10, [10], [
 "Go to the brown leather armchair with the brass studs.",
 "Could you take me to the cognac leather club chair?",
 "Studded leather club chair",
 "I want to read in something sturdy, so take me to the leather club chair, not the yellow velvet one.",
 "This is the tan leather armchair with metal studs. Head over to it.",
 "take me to the brown lether club chair"]),
(FH, "ord", 18, [18], [
 "Take me to the rattan chair in the dining room.",
 "Could you go to the woven wicker-style seat at the dining table?",
 "Woven dining room seat",
 "The metal ones are cold, so head to the woven seat with the cushion in the dining room, not the black bistro ones.",
 "This is the only woven seat in the dining room. Take me to it.",
 "go to the rattan seat in the dinig room"]),
(FH, "s", 39, [39], [
 "Go to the towel that's hanging higher up.",
 "Could you take me to whichever towel hangs highest off the floor?",
 "Bath sheet hung up high",
 "I need to dry my hands at standing height, so go to the bath sheet hung high on the wall, not the folded pile lower down.",
 "This is about drying off. Take me to the bath sheet hanging higher than the other one.",
 "take me to the towl that's hung up higher"]),
# ---- apartment ----
(APT, "o", 30, [30, 43], [
 "Take me to a mirror.",
 "Could you find me a looking glass so I can check my hair?",
 "Any looking glass",
 "I've got spinach in my teeth, so go to a mirror, not the dark TV screen.",
 "This is about checking how I look. Take me to any reflective glass on a wall, either one.",
 "take me to a miror, whichever is nearest"]),
(APT, "or", 23, [23, 24], [
 "Go to a chair in the kitchen.",
 "Could you take me to one of the dining seats in the kitchen?",
 "Kitchen seat, either one",
 "I want to eat breakfast sitting down, so head to a kitchen chair, not the office one.",
 "This is the kitchen I mean. Take me to any seat at the table there.",
 "any seat in the kitchn is fine"]),
(APT, "od", 7, [7], [
 "Take me to the tall black floor lamp with the curved neck.",
 "Could you go to the arched black metal standing light?",
 "Black arched standing light",
 "I need light over the sofa, so go to the tall black arc light, not the bedside one or the desk one.",
 "This is the tall black light with a bent neck. Take me to it.",
 "take me to the tall blck arc light"]),
(APT, "ord", 42, [42], [
 "Go to the grey vanity unit in the bathroom.",
 "Could you take me to the grey wooden cupboard under the basin in the bathroom?",
 "Grey bathroom cupboard",
 "I need a fresh towel from storage, so head to the grey cupboard in the bathroom, not the grey filing one in the office.",
 "This is the grey wooden storage unit in the bathroom. Go there.",
 "get me to the grey cuboard in the bathroom"]),
(APT, "ard", 54, [54], [
 "Take me to where I can print out a document in the office.",
 "Could you show me what I'd use to get a paper copy of this file in the office?",
 "Print document, office",
 "I need my boarding pass on paper, so go to what prints in the office, not the laptop.",
 "This is about getting a hard copy. Take me to the black machine on the filing cabinet in the office.",
 "i need to prnt my ticket, take me to what does that in the office"]),
(APT, "s", 13, [13], [
 "Go to the book that's lowest down.",
 "Could you take me to the book sitting nearest the floor?",
 "Lowest-lying volume",
 "I can't reach up high, so take me to the volume lying lowest, not the ones up on higher shelves.",
 "This is the volume closest to the floor. Take me to it.",
 "take me to the volum lying lowest"]),
(APT, "s", 1, [1], [
 "Take me to the bigger sofa.",
 "Could you go to the larger of the two couches?",
 "Larger couch",
 "We need room for three, so go to the bigger settee, not the small two-seater.",
 "This is the larger couch of the two. Head over to it.",
 "go to the biger couch please"]),
(APT, "s", 39, [39], [
 "Go to the plant on top of the chest of drawers.",
 "Could you take me to the potted plant sitting on the dresser?",
 "Greenery atop drawers",
 "It needs watering, so head to the little pot sitting up on the chest of drawers, not the ones on the floor.",
 "This is the houseplant perched on the dresser in the bedroom. Take me to it.",
 "take me to the greenery on top of the dressr"]),
# ---- scan_bedroom ----
(SB, "o", 2, [2, 3, 4, 5], [
 "Take me to a pillow.",
 "Could you go to any of the cushions on the bed?",
 "Any bed cushion",
 "I want to prop myself up, so take me to a pillow, not the rug.",
 "This is about something soft to rest my head on. Go to any of the cushions.",
 "any cusion will do, take me there"]),
(SB, "ard", 21, [21], [
 "Take me to whatever shows the time in the bedroom.",
 "Could you lead me to where I can see what time it is by the bed?",
 "Check time near bed",
 "I think I've overslept, so go to what tells the time on the bedside, not the laptop.",
 "This is about the time. Take me to the little black thing on the nightstand that shows it.",
 "take me to the thing that tells the tmie in here"]),
(SB, "s", 6, [6], [
 "Go to the bedside table on the left as you face the headboard from the foot of the bed.",
 "Could you take me to the left-hand nightstand, as seen from the foot of the bed looking toward the pillows?",
 "Left bedside table, facing headboard",
 "I sleep on that side, so go to the bedside table on the left when you face the headboard from the foot, not the right one.",
 "This is the bedside table on the left as you look at the head of the bed from its foot. Take me there.",
 "from the foot of the bed, facing the pillows, take me to the left nightstnd"]),
# ---- scan_kitchen ----
(SK, "or", 23, [23, 24, 25], [
 "Go to a cup in the kitchen.",
 "Could you find me a mug in the kitchen?",
 "Kitchen mug, any",
 "I'm thirsty, so take me to something to drink from in the kitchen, a cup, not the bowl.",
 "This is the kitchen. Take me to any mug in there.",
 "any mug in the kitchin will do"]),
(SK, "od", 4, [4], [
 "Take me to the grey kitchen cupboard.",
 "Could you go to the one grey cupboard among the white ones?",
 "Grey cupboard",
 "The cereal is in the odd-coloured one, so go to the grey cupboard, not the white ones.",
 "This is the only grey cupboard in the room. Take me to it.",
 "go to the gray cupbord"]),
(SK, "s", 21, [21], [
 "Go to the chair nearest the door.",
 "Could you take me to the seat at the table that's closest to the doorway?",
 "Seat closest to door",
 "I need to leave quickly after, so go to the table seat nearest the way out, not one on the far side.",
 "This is the seat at the end of the table nearest the door. Head there.",
 "take me to the chair closest to the dorr"]),
# ---- scan_livingroom ----
(SL, "o", 15, [15, 16], [
 "Take me to a picture on the wall.",
 "Could you go to one of the framed artworks?",
 "Any wall art",
 "I want to look at some art, so take me to a painting or print, not the TV.",
 "This is about the wall decorations. Take me to either of the framed pictures.",
 "take me to a paintng on the wall, any of them"]),
(SL, "ord", 5, [5], [
 "Go to the green armchair in the living room.",
 "Could you take me to the green easy chair in the lounge?",
 "Green lounge chair",
 "I don't like sitting on leather, so head to the green armchair in the living room, not the brown one.",
 "This is the green seat for one in the sitting room. Take me there.",
 "take me to the grean comfy chair in the living room"]),
(SL, "s", 3, [3], [
 "Go to the cushion in the middle of the sofa, between the other two.",
 "Could you take me to the pillow sitting between the other two on the couch?",
 "Middle sofa cushion",
 "The middle one is the firmest, so go to the centre cushion on the sofa, not the ones at the ends.",
 "This is the cushion flanked by the two others on the sofa. Take me to it.",
 "take me to the midle cushion on the sofa"]),
# ---- scan_office ----
(SO, "or", 11, [11, 12, 13], [
 "Take me to a monitor in the office.",
 "Could you go to one of the computer screens in the office?",
 "Office computer screen",
 "I need to check my email, so go to any of the office's screens, not the whiteboard.",
 "This is the office. Take me to any computer display there.",
 "any scren in the office will do"]),
(SO, "s", 16, [16], [
 "Go to the shortest bookshelf.",
 "Could you take me to the lowest of the bookcases?",
 "Shortest bookcase",
 "I can't reach high shelves, so take me to the short bookcase, not the tall ones.",
 "This is the smallest of the three bookcases. Go to it.",
 "take me to the shortest bookcse"]),
(SO, "s", 22, [22], [
 "Take me to the trash can farthest from the door.",
 "Could you go to the bin on the far side of the room from the door?",
 "Bin furthest from door",
 "The one by the entrance is full, so go to the wastebasket farthest from the door, not that one.",
 "This is the rubbish bin at the opposite end from the door. Take me to it.",
 "take me to the bin farthest from the dooor"]),
]

def main():
    out = Path(__file__).resolve().parents[2] / "evals/blind/round53.jsonl"
    lines = []
    for gi, (m, t, target, accept, ws) in enumerate(G, 1):
        assert len(ws) == 6, gi
        grp = f"b53-g{gi:02d}"
        for wi, q in enumerate(ws, 1):
            lines.append(json.dumps({"id": f"{grp}-w{wi}", "map": m, "query": q, "type": t,
                                     "target": target, "accept": sorted(accept), "group": grp}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(len(G), "groups,", len(lines), "lines")

if __name__ == "__main__":
    main()
