"""Emit evals/blind/round29.jsonl from the hand-written groups below (b29, 48 groups x 6 wordings).
Each group: (map, type, target, accept, [w1..w6])."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")
AP = "apartment"

GROUPS = [
 # ---- scene_00829 (caption map) ----
 (C829, "o", 23, [23, 184], [
  "Go to the couch.",
  "Could you take me to a sofa, any of them is fine?",
  "settee, any",
  "I want to stretch out for a bit, so bring me to a couch, whichever is nearest.",
  "This is a long upholstered seat for several people. It is the kind of piece you sink into to watch a film.",
  "take me to a soffa pls, any one"]),
 (C829, "o", 112, [112, 157, 219, 229, 233], [
  "Go to a mirror.",
  "Could you show me where a mirror is?",
  "mirror, any",
  "I want to check my hair before going out, so any framed looking glass will do.",
  "This is a framed glass hanging on a wall. It is used to look at your own reflection.",
  "need a mirorr real quick, whichever one"]),
 (C829, "or", 34, [34, 74], [
  "Go to the side table in the living room.",
  "Could you take me to one of the end tables in the living room?",
  "living room end table",
  "I want to set my drink down in the living room, so an end table there please, not the ones in the bedroom.",
  "This is a low table meant to stand beside a seat. It is in the living room.",
  "go to a side tabel in the living room"]),
 (C829, "or", 261, [261, 263], [
  "Go to an easy chair in the bedroom.",
  "Could you bring me to one of the lounge chairs in the bedroom?",
  "bedroom armchair",
  "I'd like to relax in the bedroom; take me to a comfy armchair there, not the plain armless one.",
  "This is a cushioned easy chair for lounging. It is located in the bedroom.",
  "bedroom comfy armchiar please"]),
 (C829, "od", 254, [254], [
  "Go to the blue-grey silky curtain.",
  "Could you take me to the drape with the shimmering thread pattern?",
  "silky grey-blue drape",
  "I want the curtain with the glinting threads, not the plain white sheer ones.",
  "This is a window drape in a pale bluish grey. It is silky and woven with threads that shimmer.",
  "where's that silvery-blue silk curtian"]),
 (C829, "ord", 261, [261], [
  "Go to the woven brown easy chair in the bedroom.",
  "Could you take me to the bedroom armchair with the massage function?",
  "bedroom woven armchair, massaging",
  "In the bedroom, find the armchair upholstered in woven fabric, not the leather one.",
  "This is a brown lounge chair covered in sturdy woven material. It is in the bedroom and can massage you.",
  "the brown fabirc easy chair in the bedroom"]),
 (C829, "ard", 122, [122], [
  "Take me somewhere I can relieve myself.",
  "Could you show me where I can answer the call of nature?",
  "need to pee, urgent",
  "I've had three cups of tea and really need to go; not the washbasin, I mean somewhere to actually do my business.",
  "I need somewhere to relieve myself. It is rather urgent.",
  "gotta go to the bathroom realy bad"]),
 # ---- scene_office3 (caption map) ----
 (OF3, "o", 4, [4, 11, 12, 27], [
  "Go to a curtain.",
  "Could you take me to one of the drapes?",
  "drapes, any",
  "The sun is in my eyes, so take me to any of the window drapes, not the motorized blind.",
  "This is a fabric panel hung from a rod beside a window. It can be drawn to block out light.",
  "go to a curtian, whichever"]),
 (OF3, "od", 13, [13], [
  "Go to the navy velvet pillow.",
  "Could you find me the dark blue cushion with the velvety cover?",
  "navy velvet cushion",
  "I want the dark blue velvet cushion, not the orange or yellow ones.",
  "This is a cushion in a deep navy shade. It has a velvety cover and a button in it.",
  "the navy bleu cushion with the button"]),
 (OF3, "od", 37, [37], [
  "Go to the black plastic chair that has a speaker built in.",
  "Could you take me to the seat with a built-in loudspeaker?",
  "plastic seat with speaker",
  "I want to listen to music while I sit, so the black plastic seat with the speaker, not the mesh ones.",
  "This is a black seat made of plastic. It has its own speaker and a massage function.",
  "the plastc chair with the speaker in it"]),
 (OF3, "ord", 7, [7], [
  "Go to the white desk in the rec room.",
  "Could you take me to the white wooden writing table in the rec room?",
  "rec room white work table",
  "I need a work surface in the rec room, the white one, not the brown wooden ones.",
  "This is a white wooden work table. It is in the rec room and has a USB port.",
  "go to the whtie writing table in the rec room"]),
 (OF3, "ard", 25, [25], [
  "Take me to where I can check the time on the wall.",
  "Could you show me what I can look at to see what time it is?",
  "what time is it, need to see",
  "I need to know how long the meeting has run; not my phone, something on the wall that shows the hour.",
  "I want to know the current time. It should be something mounted on the wall.",
  "can i see the tiem somewhere, my phone's dead"]),
 # ---- flats ----
 (FD, "o", 8, [8, 9, 34], [
  "Go to a lamp.",
  "Could you take me to any light I can switch on?",
  "light fixture, any",
  "It's getting dark, so bring me to any reading light or night light, whichever is closest.",
  "This is a light you can turn on. Any one of them in the flat will do.",
  "go to a lammp, any of them"]),
 (FH, "o", 13, [13, 26, 32], [
  "Go to a mug.",
  "Could you take me to one of the coffee cups?",
  "coffee cup, any",
  "I need something to drink from; any mug is fine, not the vase.",
  "This is a cup with a handle for hot drinks. Any of them will do.",
  "find me a cofee cup please"]),
 (FC, "or", 26, [26, 27], [
  "Go to a nightstand in the bedroom.",
  "Could you take me to one of the bedside tables in the bedroom?",
  "bedroom bedside table",
  "I left my glasses by the bed, so take me to a bedside table in the bedroom, either side.",
  "This is a small table next to a bed. It is in the bedroom.",
  "go to the bedsied table in the bedroom, either one"]),
 (FH, "or", 16, [16, 17, 18], [
  "Go to a chair in the dining room.",
  "Could you take me to one of the dining room seats?",
  "dining room seat",
  "I want to sit down to eat, so any seat in the dining room, not the swivel seat in the study.",
  "This is something to sit on at the table. It is in the dining room.",
  "take me to a dinning room chair"]),
 (FF, "or", 6, [6], [
  "Go to the lamp in the living room.",
  "Could you take me to the light in the lounge?",
  "living room light",
  "I want to read on the sofa, so the living room lamp please, not the one by the bed.",
  "This is a light for brightening a room. It stands in the living room.",
  "the living room ligth please"]),
 (FC, "od", 28, [28], [
  "Go to the lamp with the pink shade.",
  "Could you take me to the light that has a pink fabric shade?",
  "pink-shaded light",
  "I want the light with the pink shade, not the green banker's lamp or the brass floor one.",
  "This is a small light topped with a pink cloth shade. It sits on a bedside table.",
  "the pnik lampshade one"]),
 (FF, "od", 14, [14], [
  "Go to the yellow chair.",
  "Could you take me to the mustard-coloured seat?",
  "mustard painted seat",
  "Take me to the one chair that is yellow, not the blue ladder-back ones.",
  "This is a wooden seat painted mustard yellow. It does not match the others around the table.",
  "the yelow seat at the table"]),
 (FH, "ord", 18, [18], [
  "Go to the rattan chair in the dining room.",
  "Could you take me to the wicker-style seat in the dining room?",
  "dining room rattan seat",
  "In the dining room I want the woven seat with a cushion, not the black metal ones.",
  "This is a woven seat with a linen cushion. It is in the dining room.",
  "the ratan chair in the dining room"]),
 (FD, "ord", 5, [5], [
  "Go to the yellow chair in the studio.",
  "Could you take me to the yellow painted wooden seat in the studio?",
  "studio yellow wooden seat",
  "In the studio, the yellow seat please, not the white plastic one.",
  "This is a wooden seat painted yellow. It is in the studio, at the round table.",
  "yelllow chair in the studio"]),
 (FF, "ord", 3, [3], [
  "Go to the cream leather armchair in the living room.",
  "Could you take me to the pale leather easy chair in the living room?",
  "living room cream leather armchair",
  "In the living room, the cream leather one, not the red tartan wingback by the fire.",
  "This is an easy chair upholstered in cream leather. It is in the living room and has rounded arms.",
  "the craem leather seat in the lounge"]),
 (FD, "ard", 25, [25], [
  "Take me to where I can dry my wet laundry.",
  "Could you show me where I can get my washed clothes dry?",
  "dry wet clothes",
  "My washing just finished, so I need to dry it now; I don't need the iron yet.",
  "I have a load of damp clothes. I need to get them dry quickly.",
  "where do i dry my cloths"]),
 (FH, "ard", 4, [4], [
  "Take me to where the house keys are usually put down.",
  "Could you show me where I should drop my keys when I come in?",
  "keys drop spot",
  "I just got home and want to leave my keys where they belong, not on the kitchen worktop.",
  "I am holding my house keys. I want to put them where they usually go.",
  "where do the kyes go"]),
 (FC, "s", 27, [27], [
  "Go to the nightstand that has the alarm clock on it.",
  "Could you take me to the bedside table with the alarm clock sitting on top?",
  "bedside table under clock",
  "I need to switch off the alarm, so take me to the bedside table it sits on, not the one with the lamp.",
  "This is a bedside table. It has a red alarm clock standing on it.",
  "the nighstand with the clock on top"]),
 (FH, "s", 11, [11], [
  "Go to the armchair closest to the TV.",
  "Could you take me to whichever easy chair is nearer the television?",
  "easy chair nearest television",
  "I want to watch the news up close, so the armchair nearer the telly, not the one farther away.",
  "This is an easy chair in the living room. It is the one closer to the television.",
  "the armchiar that's closest to the tv"]),
 (FF, "s", 12, [12], [
  "Go to the kitchen chair farthest from the fridge.",
  "Could you take me to the dining chair that is farthest away from the refrigerator?",
  "dining seat farthest from fridge",
  "The fridge hums too loudly, so I want the seat at the kitchen table that is farthest from it.",
  "This is a seat at the kitchen table. It is the one farthest from the fridge.",
  "the kitchen chiar furthest from the fridge"]),
 (FD, "s", 22, [22], [
  "Go to the stool farther from the bin.",
  "Could you take me to the stool that's further away from the trash can?",
  "high seat farther from bin",
  "The bin smells, so take me to the high seat that is further from it.",
  "This is a high seat in the kitchenette. Of the two, it is the one farther from the trash can.",
  "the tall seat furhter from the bin"]),
 # ---- scans ----
 (SL, "o", 2, [2, 3, 4], [
  "Go to a pillow.",
  "Could you take me to one of the cushions?",
  "cushion, any",
  "My back hurts, so bring me to any cushion, whichever you reach first.",
  "This is a soft cushion. Any of the ones on the couch will do.",
  "take me to a cushon"]),
 (SK, "ard", 26, [26, 27], [
  "Take me to where I can throw away this wrapper.",
  "Could you show me where I can get rid of some rubbish?",
  "throw away garbage",
  "I have peelings to dispose of; either place for rubbish is fine, just not the sink.",
  "I have some rubbish in my hand. I want to throw it away.",
  "where do i chuck this rubbsih"]),
 (SL, "ard", 24, [24], [
  "Take me to what I need to change the TV channel.",
  "Could you show me what I can use to turn the volume down from the sofa?",
  "change channel from couch",
  "I want to switch channels without getting up, so not the TV itself, the handheld thing.",
  "I am sitting on the couch. I want to change the channel without standing up.",
  "need to chnage the channel"]),
 (SB, "s", 5, [5], [
  "Go to the pillow nearest the foot of the bed.",
  "Could you take me to the cushion lying farthest from the headboard?",
  "cushion at foot of bed",
  "I want the cushion that's down by the foot of the bed, not the ones at the headboard.",
  "This is a pillow on the bed. It lies apart from the others, toward the foot end.",
  "the cushin near the bottom end of the bed"]),
 (SK, "s", 25, [25], [
  "Go to the cup nearest the sink.",
  "Could you take me to the mug closest to the sink?",
  "mug beside sink",
  "I want the cup on the counter by the sink, not the ones on the table.",
  "This is a small drinking vessel on the counter. It is the one closest to the sink.",
  "the mugg next to the sink"]),
 (SK, "s", 8, [8], [
  "Go to the wall cupboard right above the sink.",
  "Could you take me to the upper cabinet directly over the sink?",
  "wall cupboard over sink",
  "I need a glass, so the high cupboard over the sink, not the ones under the counter.",
  "This is an upper kitchen cabinet on the wall. It hangs directly above the sink.",
  "the cupbaord above the sink"]),
 (SO, "s", 16, [16], [
  "Go to the shortest bookshelf.",
  "Could you take me to the lowest of the bookcases?",
  "shortest bookcase",
  "I can't reach high shelves, so the lowest bookcase, not the tall wooden ones.",
  "This is a bookcase against the wall. It is the lowest one, shorter than the others.",
  "the smallest bookshlef"]),
 (SL, "s", 8, [8], [
  "Go to the side table on your left when you sit on the sofa facing the TV.",
  "Could you take me to the end table at the left of the couch, as seen by someone sitting on it?",
  "end table, left of seated person on sofa",
  "Sitting on the sofa and looking at the TV, I want the little table on my left, not the right.",
  "This is a small table beside the sofa. From the seat, facing the television, it is on the left.",
  "the side tabel to my left when i'm on the couch watching tv"]),
 # ---- apartment ----
 (AP, "o", 12, [12, 13, 52], [
  "Go to a book.",
  "Could you take me to something I can read, any volume?",
  "any book",
  "I'm bored and want to read; any hardback or paperback will do.",
  "This is a bound volume with pages. Any one of them will do.",
  "find me a novle or any volume"]),
 (AP, "or", 23, [23, 24], [
  "Go to a chair in the kitchen.",
  "Could you take me to one of the kitchen's dining seats?",
  "kitchen dining seat",
  "I want to eat at the table, so a seat in the kitchen, not the office chair.",
  "This is a seat pulled up to the table. It is in the kitchen.",
  "take me to a kitchn seat"]),
 (AP, "or", 30, [30], [
  "Go to the mirror in the hallway.",
  "Could you take me to the looking glass in the hall?",
  "hall looking glass",
  "I want a last check of my outfit before leaving, so the hallway mirror, not the bathroom one.",
  "This is a reflective glass panel on a wall. It is in the hallway.",
  "the hallway mirorr please"]),
 (AP, "od", 2, [2], [
  "Go to the brown leather sofa.",
  "Could you take me to the small leather loveseat?",
  "brown leather two-seater",
  "I want the worn brown leather couch, not the big gray fabric one.",
  "This is a small couch for two people. It is covered in brown leather that looks a bit worn.",
  "the broun leather couch"]),
 (AP, "od", 48, [48], [
  "Go to the red leather chair.",
  "Could you take me to the red swivel seat on wheels?",
  "red leather swivel seat",
  "I want the red leather seat with wheels, not the wooden dining chairs.",
  "This is a swivel seat covered in red leather. It has armrests and rolls on castors.",
  "the red lether desk seat"]),
 (AP, "ord", 24, [24], [
  "Go to the white chair in the kitchen.",
  "Could you take me to the white painted dining seat in the kitchen?",
  "kitchen white dining seat",
  "In the kitchen, the white seat with the spindle back, not the one with the green cushion.",
  "This is a white painted wooden seat. It is in the kitchen, across the dining table.",
  "the whit chair in the kitchen"]),
 (AP, "ord", 52, [52], [
  "Go to the green book in the office.",
  "Could you take me to the thick green textbook in the office?",
  "office green textbook",
  "I need the coding manual in the office, the green one, not the red novel in the living room.",
  "This is a thick textbook with a green cover. It is on the shelf in the office.",
  "the green programing book in the office"]),
 (AP, "ard", 20, [20], [
  "Take me to where I can reheat my leftovers in a couple of minutes.",
  "Could you show me what I can use to warm up a bowl of soup quickly?",
  "reheat food fast",
  "My coffee went cold and I want to heat it up quickly, without using the hob.",
  "I have a plate of cold leftovers. I want to warm it up in a minute or two.",
  "need to nuke my lefovers"]),
 (AP, "ard", 54, [54], [
  "Take me to where I can get a paper copy of a document.",
  "Could you show me where I can print out my boarding pass?",
  "print document",
  "I need a hard copy of this contract, the laptop screen isn't enough.",
  "I have a file I need on paper. I want to print it out.",
  "where can i pirnt something"]),
 (AP, "s", 12, [12], [
  "Go to the book sitting high up in the living room bookcase.",
  "Could you take me to the volume placed higher up on the living room shelves?",
  "living room upper shelf novel",
  "In the living room, the volume standing up high, not the one lying on the bottom shelf.",
  "This is a hardback in the living room bookcase. It is the higher of the two volumes there.",
  "the higer book in the living room bookcase"]),
 (AP, "s", 39, [39], [
  "Go to the plant on top of the dresser.",
  "Could you take me to the little potted plant sitting on the chest of drawers?",
  "succulent on chest of drawers",
  "I want to water the greenery on the dresser, not the big one in the living room.",
  "This is a small potted succulent. It sits on top of the chest of drawers in the bedroom.",
  "the pot plnat on the dresser"]),
 (AP, "s", 53, [53], [
  "Go to the cabinet under the printer.",
  "Could you take me to the filing drawers that the printer sits on?",
  "drawers beneath printer",
  "I need paperwork from the unit below the printer, not the kitchen cupboards.",
  "This is a metal storage unit in the office. The printer rests on top of it.",
  "the cabnet the printer is sitting on"]),
]


def main():
    out = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round29.jsonl"
    assert len(GROUPS) == 48, len(GROUPS)
    lines = []
    for g, (mp, typ, target, accept, words) in enumerate(GROUPS, 1):
        assert len(words) == 6, (g, len(words))
        for k, q in enumerate(words, 1):
            lines.append(json.dumps({"id": f"b29-g{g:02d}-w{k}", "map": mp, "query": q, "type": typ,
                                     "target": target, "accept": accept, "group": f"b29-g{g:02d}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {out}")


if __name__ == "__main__":
    main()
