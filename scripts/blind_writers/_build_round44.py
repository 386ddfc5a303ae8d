"""Hand-written blind suite round 44: 48 groups x 6 wordings. Writes evals/blind/round44.jsonl."""
import json
from pathlib import Path

C1 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
C2 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FB, FE, FG, FI = "maps/flat_b.json", "maps/flat_e.json", "maps/flat_g.json", "maps/flat_i.json"
AP = "apartment"
SB, SK, SL, SO = "../maps/scan_bedroom.json", "../maps/scan_kitchen.json", "../maps/scan_livingroom.json", "../maps/scan_office.json"

# (map, type, target, accept, [w1..w6])
G = [
 # ---------------- caption maps ----------------
 (C1, "o", 160, [160, 162, 164], [
  "Go to the folded towels.",
  "Could you take me to where the clean towels are?",
  "stack of towels",
  "I just got out of the shower and need something to dry off with, so any pile of towels will do.",
  "This is a set of white cotton towels. They sit folded in a tidy pile.",
  "where r the fresh towles kept"]),
 (C1, "o", 112, [112, 157, 219, 229, 233], [
  "Go to a mirror.",
  "Could you bring me to any of the mirrors in the house?",
  "framed mirror",
  "I want to check my hair before heading out; any mirror is fine, just not a window.",
  "This is a mirror frame, usually made of dark wood. It surrounds a looking glass on the wall.",
  "need a mirorr to fix my hair real quick"]),
 (C2, "o", 8, [8, 13, 20, 40], [
  "Go to a pillow.",
  "Could you find me one of the cushions?",
  "cushion, any",
  "My back hurts in this chair, so get me a cushion, whichever colour.",
  "This is a soft cushion. It is a small fabric pillow to rest against.",
  "can u grab me a cushon from the rec room"]),
 (C1, "or", 261, [261, 263], [
  "Go to the easy chair in the bedroom.",
  "Could you show me the lounge armchairs in the bedroom?",
  "bedroom armchair",
  "I want to read somewhere quiet, so take me to a comfy armchair in the bedroom, not the ones out in the living room.",
  "This is a deep, padded lounge armchair. It stands in the bedroom.",
  "take me to the comfy lounging armchiar in the bedroom"]),
 (C1, "or", 195, [195, 216, 228], [
  "Go to the cupboards in the bathroom.",
  "Could you take me to one of the bathroom cabinets?",
  "bathroom cupboard",
  "I'm looking for spare storage in the bathroom, so a cabinet there, not the one in the kitchen.",
  "This is a dark wooden storage cabinet. It is in the bathroom.",
  "go to a cabnet in the bathroom pls"]),
 (C1, "or", 34, [34, 74], [
  "Go to the side table in the living room.",
  "Could you take me to an end table in the living room?",
  "living room end table",
  "I need to set my drink down while on the couch, so a side table in the living room, not the bedroom ones.",
  "This is a small occasional table with a dark wood top and a metal base. It is in the living room.",
  "find the end tabel in the living room"]),
 (C1, "od", 184, [184], [
  "Go to the L-shaped couch.",
  "Could you take me to the corner sofa with the chaise?",
  "L-shaped sofa",
  "I want to stretch my legs out, so the sectional with the chaise lounge, not the plain beige one that massages.",
  "This is a beige fabric sofa shaped like an L. It has a chaise end and hidden storage.",
  "take me to the l shaped sofa with the chase part"]),
 (C2, "od", 13, [13], [
  "Go to the navy velvet pillow.",
  "Could you find the dark blue cushion with buttons?",
  "navy velvet cushion",
  "Bring me to the blue cushion, not the orange or yellow ones.",
  "This is a velvety cushion in a dark navy shade. It is buttoned and a bit bigger than the others.",
  "where's the navy bleu pillow"]),
 (C1, "od", 15, [15], [
  "Go to the bowl of sweets.",
  "Could you show me the white candy dish with the gold rim?",
  "candy bowl, gold rim",
  "I fancy a treat, so take me to the white dish holding sweets, not the blue decorative one.",
  "This is a white ceramic dish edged in gold. It has a little handle and holds candies.",
  "where's the dish with swets in it"]),
 (C1, "ord", 157, [157], [
  "Go to the mirror in the living room.",
  "Could you take me to the ornate mirror frame in the living room?",
  "living room mirror, gold trim",
  "I want the fancy mirror in the living room, not any of the bathroom ones.",
  "This is a patterned dark wood mirror frame with golden touches. It hangs in the living room.",
  "go to the living room miror"]),
 (C1, "ord", 87, [87], [
  "Go to the washbasin counter in the bathroom.",
  "Could you bring me to the glossy white vanity counter in the bathroom?",
  "bathroom vanity, white gloss",
  "I need to wash my face, so the shiny white vanity in the bathroom, not the one that's in the living room.",
  "This is a shiny white vanity unit with an integrated basin. It sits in the bathroom.",
  "take me to the shiny white bathroom vanty"]),
 (C1, "ard", 122, [122], [
  "Go to where I can relieve myself.",
  "Could you take me somewhere I can go to the bathroom?",
  "need to pee",
  "I really need to pee, and a sink won't do, so take me to the right spot.",
  "I have to relieve myself urgently. Please find the fixture meant for that.",
  "gotta pee realy badly where do i go"]),
 (C2, "ard", 3, [3], [
  "Go to somewhere I can lie down and nap.",
  "Could you find me a place to stretch out for a short nap?",
  "place to lie down",
  "I'm exhausted and want to lie flat for a bit; the office chairs and the hard bench won't do.",
  "I want to rest lying flat for twenty minutes. Find the soft seat long enough for me to lie on.",
  "need somewhere to lay down and take a nap, im so tierd"]),
 # ---------------- flats ----------------
 (FG, "o", 10, [10, 37, 45], [
  "Go to a basket.",
  "Could you take me to one of the hampers or carry baskets?",
  "any hamper",
  "I need something to carry stuff in; a hamper in any room will do, laundry or toy one.",
  "This is a carrying container, like a hamper. It can hold clothes or toys.",
  "find me a hampper, doesnt matter which"]),
 (FI, "o", 23, [23, 31, 36], [
  "Go to a mug.",
  "Could you find me one of the coffee cups?",
  "any cup",
  "I'd like to see where the cups have been left, any of them, not the kettle.",
  "This is a ceramic drinking cup with a handle. It is one of several around the flat.",
  "where's a mugg i can use"]),
 (FE, "or", 11, [11, 12, 13, 14, 15], [
  "Go to a chair in the dining room.",
  "Could you take me to one of the dining room seats?",
  "dining room seat",
  "I need to sit at the dining table; any seat there, not the ones in the bedrooms or on the balcony.",
  "This is a seat in the dining room. It stands at the dining table.",
  "take me to a seat in the dinning room"]),
 (FB, "or", 33, [33, 34], [
  "Go to a lamp in the bedroom.",
  "Could you take me to one of the lights in the bedroom?",
  "bedroom light",
  "I want to read in bed, so a light in the bedroom, not the living room ones.",
  "This is a bedside light with a shade. It is in the bedroom.",
  "go to a lamp in the bedrom, either side is fine"]),
 (FB, "od", 22, [22], [
  "Go to the white plastic chair.",
  "Could you take me to the white moulded seat at the dining table?",
  "white plastic seat",
  "Take me to the white plastic chair, not the wooden dining ones.",
  "This is a white moulded seat made of plastic. It is at the round dining table.",
  "the white plastc seat pls"]),
 (FG, "od", 3, [3], [
  "Go to the little blue bike.",
  "Could you show me the child's bicycle with training wheels?",
  "kids bike, blue",
  "My son wants to ride, so the small blue one with stabilisers, not the black mountain bike.",
  "This is a small blue bicycle for a child. It has training wheels fitted.",
  "wheres the kids bike with the trainig wheels"]),
 (FI, "ord", 18, [18], [
  "Go to the green banker's lamp in the studio.",
  "Could you take me to the desk light with the green glass shade in the studio?",
  "studio green desk light",
  "I need light at the drawing desk in the studio, the green-shaded one, not a bedroom light.",
  "This is a green glass-shaded banker's lamp. It sits on the oak desk in the studio.",
  "go to the gren glass light in the studio"]),
 (FE, "ord", 14, [14], [
  "Go to the black metal chair in the dining room.",
  "Could you take me to the bistro-style seat in the dining room?",
  "dining room odd black seat",
  "In the dining room I want the mismatched black one, not the sage green chairs.",
  "This is a dark metal cafe seat that doesn't match its neighbours. It sits at the table in the dining room.",
  "the black metal seat in the dinning room"]),
 (FG, "ord", 35, [35], [
  "Go to the beige ceramic lamp in the bedroom.",
  "Could you take me to the bedroom bedside light with the beige pottery base?",
  "bedroom beige light",
  "In the bedroom, I want the light with the beige base, not the teal glass one.",
  "This is a bedside light on a beige ceramic base with a linen shade. It is in the bedroom.",
  "go to the biege lamp in the bedroom"]),
 (FE, "ard", 33, [33], [
  "Go to where I can dry my wet laundry.",
  "Could you take me where my washed clothes can be dried?",
  "dry wet clothes",
  "The wash just finished and the clothes are soaking; I need them dry fast, and it's raining so not the balcony.",
  "My laundry is damp after washing. I need the appliance that will dry it.",
  "where can i dry my clohtes"]),
 (FG, "ard", 11, [11], [
  "Go to where I can iron my shirt.",
  "Could you take me where I can press my creased trousers?",
  "press wrinkled shirt",
  "My shirt is all wrinkled for the interview; I need to press it, not wash it.",
  "My blouse is creased. I need somewhere set up to iron it.",
  "need to get the wrinkels out of my shirt"]),
 (FI, "ard", 20, [20], [
  "Go to where I can print a drawing.",
  "Could you take me somewhere I can get a paper copy of these plans?",
  "print plans A3",
  "I need a hard copy of a large plan for the client, so somewhere that prints, not the screens.",
  "I have to make a paper copy of a document. Take me to the device that can do it.",
  "i need to scan a documnet"]),
 (FB, "s", 34, [34], [
  "Go to the bedside lamp that is east of the bed.",
  "Could you take me to the light on the nightstand to the right of the bed, as seen from its foot?",
  "light, east nightstand",
  "I want the bedside light on the east side, not the one on the west nightstand.",
  "This is a light standing on a bedside table. It is on the eastern side of the bed.",
  "the lamp on the rigth nightstand when u look at the bed from the foot"]),
 (FE, "s", 11, [11], [
  "Go to the dining chair farthest from the black metal one.",
  "Could you take me to the seat at the dining table that's farthest from the mismatched black metal seat?",
  "dining seat farthest from black metal one",
  "I don't want to sit near the black bistro seat, so take me to the dining seat farthest from it.",
  "This is a sage green chair at the dining table. It is the one farthest from the black bistro seat.",
  "the dinig seat furthest from the black metal one"]),
 (FG, "s", 34, [34], [
  "Go to the bedside lamp nearest the wardrobe.",
  "Could you take me to the bedside light that is closest to the wardrobe?",
  "bedside light nearest wardrobe",
  "I want the reading light closer to the wardrobe, not the other one nearer the hamper.",
  "This is a bedside light on a nightstand. Of the two, it is the one closer to the wardrobe.",
  "the bedside lamp closest to the wardobe"]),
 (FI, "s", 36, [36], [
  "Go to the mug on the coffee table.",
  "Could you take me to the cup sitting on the low table in front of the sofa?",
  "cup on coffee table",
  "Bring me to the cup on the coffee table, not the ones on the desk or the worktop.",
  "This is a ceramic cup. It sits on top of the coffee table in the living room.",
  "the cup on the cofee table"]),
 (FI, "s", 12, [12], [
  "Go to the left-hand desk in the studio, as you face the north wall.",
  "Could you take me to the westernmost of the two work tables in the studio?",
  "studio workstation, west one",
  "Facing the studio's north wall, I want the workspace on the left, not the one on the right.",
  "This is a work table set against the studio's north wall. Facing that wall, it is the one on the left.",
  "in the studio, the left desk when u face the north wal"]),
 (FB, "s", 2, [2], [
  "Go to the armchair nearest the window.",
  "Could you take me to the easy chair closest to the living room window?",
  "armchair by window",
  "I want to sit in the light, so the lounge chair closest to the window, not the one on the east side.",
  "This is an upholstered lounge seat. Of the seats in the living room, it is the one nearest the west window.",
  "the comfy seat closest to the windw"]),
 # ---------------- apartment and scans ----------------
 (AP, "o", 12, [12, 13, 52], [
  "Go to a book.",
  "Could you find me something to read, any of the books?",
  "any volume, whichever",
  "I don't care which title, just take me to any volume to read; not the picture frames.",
  "This is a bound volume with printed pages. It is one of several in the apartment.",
  "take me to any bok"]),
 (SK, "o", 23, [23, 24, 25], [
  "Go to a cup.",
  "Could you find me one of the mugs?",
  "any drinking cup",
  "I'm thirsty, so any mug will do, not the bowl.",
  "This is a small vessel for drinking. There are several of them in the kitchen.",
  "find me a mugg"]),
 (AP, "or", 23, [23, 24], [
  "Go to a chair in the kitchen.",
  "Could you take me to one of the dining seats in the kitchen?",
  "kitchen seat",
  "I want to sit down to eat, so any seat at the kitchen table, not the office chair.",
  "This is a wooden seat pulled up to the table. It is in the kitchen.",
  "a seat in the kitchn please"]),
 (AP, "or", 43, [43], [
  "Go to the mirror in the bathroom.",
  "Could you take me to the looking glass in the bathroom?",
  "bathroom looking glass",
  "I need to shave, so the one in the bathroom, not the gold-framed hall mirror.",
  "This is a reflective glass on the wall above the basin. It is in the bathroom.",
  "the bathrom looking glass"]),
 (AP, "od", 2, [2], [
  "Go to the brown leather loveseat.",
  "Could you take me to the small two-seater leather couch?",
  "brown leather two-seater",
  "Take me to the little brown leather couch, not the big gray one.",
  "This is a compact two-person couch in brown leather. It looks a little worn.",
  "the small brown lether couch"]),
 (AP, "od", 31, [31], [
  "Go to the photo of the lighthouse.",
  "Could you show me the black-and-white lighthouse photograph?",
  "lighthouse photo",
  "I want the small monochrome photo, not the big blue abstract painting.",
  "This is a small framed photograph in black and white. It shows a lighthouse.",
  "wheres the lighthose pic"]),
 (AP, "ord", 53, [53], [
  "Go to the filing cabinet in the office.",
  "Could you take me to the gray metal drawer unit for paperwork in the office?",
  "office file drawers, gray",
  "I need to file some papers, so the gray metal drawers in the office, not the wooden vanity in the bathroom.",
  "This is a two-drawer metal storage unit in gray. It is in the office, under the printer.",
  "the gray filling cabinet in the office"]),
 (AP, "ord", 24, [24], [
  "Go to the white chair in the kitchen.",
  "Could you take me to the painted white dining seat with the spindle back in the kitchen?",
  "kitchen white spindle seat",
  "In the kitchen I want the white-painted seat, not the one with the green cushion.",
  "This is a white painted wooden seat with a spindled back. It stands across the table from the other kitchen seat.",
  "the whte seat in the kitchen"]),
 (AP, "ard", 27, [27], [
  "Go to where I can boil water for tea.",
  "Could you take me to something that will boil water for a cuppa?",
  "boil water tea",
  "I want to make tea, so something to heat water quickly, not the microwave.",
  "I'd like a hot cup of tea. Find the appliance that boils the water.",
  "i want to boil some watter for tea"]),
 (AP, "ard", 29, [29], [
  "Go to where I can hang my coat.",
  "Could you take me somewhere to hang up my jacket?",
  "hang up jacket",
  "I just came in from the rain and want to hang my wet jacket, not put it in the wardrobe.",
  "I've just come home wearing a coat. Take me to where I can hang it by the door.",
  "where do i hang my jaket"]),
 (SK, "ard", 26, [26, 27], [
  "Go to where I can throw away this wrapper.",
  "Could you take me somewhere to dispose of these scraps?",
  "throw out rubbish",
  "I need to get rid of some food waste; either spot is fine, not the sink.",
  "I have an empty packet to get rid of. Take me to where waste goes.",
  "where do i thow this away"]),
 (SO, "s", 7, [7], [
  "Go to the blue office chair closest to the windows.",
  "Could you take me to the blue desk seat nearer the windows?",
  "blue desk seat, window side",
  "Of the two blue swivel seats, I want the one nearer the windows, not the one farther back.",
  "This is a blue swivel seat at the wooden table. It is the one closer to the windows.",
  "the blue office chair nearest the windos"]),
 (SO, "s", 15, [15], [
  "Go to the middle bookshelf of the three.",
  "Could you take me to the bookcase between the other two?",
  "middle bookcase",
  "I want the bookcase in the middle, not the one at either end of the row.",
  "This is a wooden bookcase along the north wall. It stands between the other two shelf units.",
  "the midle bookshelf"]),
 (SB, "s", 5, [5], [
  "Go to the pillow farthest from the headboard.",
  "Could you take me to the cushion lying farthest down the bed, away from the head end?",
  "cushion near foot of bed",
  "I want the cushion that's down toward the foot of the bed, not the ones up by the headboard.",
  "This is a small cushion on the bed. It lies the farthest from the head of the bed.",
  "the pilow closest to the foot of the bed"]),
 (SK, "s", 25, [25], [
  "Go to the cup on the counter.",
  "Could you take me to the mug sitting on the countertop by the sink?",
  "mug on counter",
  "I want the mug on the counter, not the ones on the dining table.",
  "This is a white drinking vessel. It sits on the counter next to the sink.",
  "the cup on the countr"]),
 (SL, "s", 9, [9], [
  "Go to the side table on your left when you stand at the TV and face the sofa.",
  "Could you take me to the end table that's on the left if you're looking at the sofa from the TV?",
  "end table, left, facing sofa from TV",
  "Standing by the TV looking at the couch, I want the end table on the left, not the one on the right.",
  "This is a small end table beside the sofa. Seen from the TV, it is on the left side.",
  "from the tv facing the couch, the end tabel on the left"]),
 (AP, "s", 12, [12], [
  "Go to the book higher up on the living room bookshelf.",
  "Could you take me to the novel on the upper shelf of the bookcase in the living room?",
  "upper-shelf novel, living room",
  "On the living room bookcase, I want the volume up high, not the one on the bottom shelf.",
  "This is a hardcover volume on the living room bookcase. It is the higher of the two volumes there.",
  "the book up high on the livng room shelf"]),
]


def main():
    out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round44.jsonl"
    lines = []
    assert len(G) == 48, len(G)
    for gi, (m, t, target, accept, ws) in enumerate(G, 1):
        assert len(ws) == 6 and target in accept
        for wi, q in enumerate(ws, 1):
            lines.append(json.dumps({"id": f"b44-g{gi:02d}-w{wi}", "map": m, "query": q, "type": t,
                                     "target": target, "accept": sorted(accept), "group": f"b44-g{gi:02d}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} lines to {out}")


if __name__ == "__main__":
    main()
