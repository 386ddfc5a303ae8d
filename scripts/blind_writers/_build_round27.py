"""Emit evals/blind/round27.jsonl (48 groups x 6 wordings). Written by the round-27 blind helper."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
COFF = "../../../shared/data/iesm_maps/scene_office3_caption.json"
APT = "apartment"
SK, SO, SL, SB = ("../maps/scan_kitchen.json", "../maps/scan_office.json",
                  "../maps/scan_livingroom.json", "../maps/scan_bedroom.json")
FD, FF, FG, FH = ("maps/flat_d.json", "maps/flat_f.json", "maps/flat_g.json", "maps/flat_h.json")

# (map, type, target, accept, [six wordings])
G = [
 (C829, "o", 112, [112, 157, 219, 229, 233], [
  "Go to a framed mirror.",
  "Could you head over to one of the mirrors that has a frame around it?",
  "mirror w/ frame",
  "I want to check my hair before I leave, so take me to any framed mirror in the house, whichever is closest.",
  "This is a mirror set in a frame. It hangs on a wall; any one of them is fine.",
  "find me a mirorr, the framed kind"]),
 (C829, "or", 261, [261, 263], [
  "Go to an easy chair in the bedroom.",
  "Would you mind going to one of the armchairs in the bedroom?",
  "bedroom armchair",
  "I'd like to sit and read somewhere comfy in the bedroom, so go to one of the lounge chairs in there, not the ones in the living room.",
  "This is a cushioned armchair. It is in the bedroom.",
  "bedroom, go to an armchair, any of em"]),
 (C829, "or", 14, [14, 33], [
  "Go to a curtain in the living room.",
  "Could you go over to one of the drapes in the lounge?",
  "living room drapes",
  "The sun is glaring on the TV. Go to one of the living room window drapes so we can pull it shut, not the one around the bed.",
  "This is a window curtain. It hangs in the living room.",
  "drapes, livingroom, either one"]),
 (C829, "od", 164, [164], [
  "Go to the set of towels embroidered with an H.",
  "Could you find the folded towels that have the letter H stitched on them?",
  "towels w/ the H monogram",
  "Guests are coming and I want the monogrammed ones. Take me to the towel stack with the H on it, not the plain folded piles.",
  "This is a stack of white folded towels. It has an embroidered letter H.",
  "the H towels, the ones on the rack"]),
 (C829, "od", 110, [110], [
  "Go to the small honey-coloured wooden table with the X-shaped metal legs.",
  "Could you take me to the little light-wood table that sits on a crossed metal base?",
  "honey wood table, X base",
  "I left my charger by the little table with the criss-cross metal legs. Go there, not to any of the dark wooden ones.",
  "This is a small stand in warm honey-toned wood. Its metal base forms an X.",
  "lil table thats honey colour w the X legs"]),
 (C829, "od", 184, [184], [
  "Go to the L-shaped couch.",
  "Could you go to the corner sofa, the one shaped like an L with a chaise?",
  "L-shaped sofa",
  "Go to the couch with the chaise end, not the one with the massage motor.",
  "This is a beige fabric sofa bent into an L. One end has a chaise lounge.",
  "the L sofa w the chaise thing"]),
 (C829, "ord", 261, [261], [
  "Go to the woven brown easy chair in the bedroom.",
  "In the bedroom, could you go to the brown armchair that's made of woven material rather than leather?",
  "bedroom armchair, woven brown",
  "There are two brown armchairs in the bedroom; I mean the woven fabric one, not the leather one.",
  "This is a deep brown armchair made of a sturdy weave. It is in the bedroom.",
  "the woven one - brown easy chair in bedroom"]),
 (C829, "ard", 192, [192], [
  "Take me to where the dog sleeps.",
  "Could you go to the spot where our pet curls up for a nap?",
  "pet's sleeping spot",
  "The puppy is tired and needs to lie down. Take me to the place where it sleeps, not our own bed.",
  "This is where the animal sleeps. It is soft and plush, white and brown.",
  "where does the doggo nap, go there"]),
 (COFF, "o", 8, [8, 13, 20, 40], [
  "Go to a pillow.",
  "Could you find me one of the cushions?",
  "any cushion",
  "My back hurts in this seat; go to any cushion I could use, it doesn't matter which colour.",
  "This is a soft throw cushion. Any one of them will do.",
  "cushon pls, whichever"]),
 (COFF, "or", 4, [4, 11, 12, 27], [
  "Go to a curtain in the rec room.",
  "Could you go over to one of the drapes in the recreation room?",
  "rec room drapes",
  "It's too bright in the rec room. Go to any of the drapes there, not the motorised blind.",
  "This is a fabric curtain hung from a rod. It is in the rec room.",
  "any drape in rec rm"]),
 (COFF, "od", 13, [13], [
  "Go to the navy blue velvet pillow.",
  "Could you find the dark blue velvety cushion?",
  "navy cushion",
  "Not the orange or the yellow one: I want the navy cushion, the velvet one with buttons.",
  "This is a soft velvet cushion in navy blue. It has a buttoned design.",
  "blue velvet pilow"]),
 (COFF, "ord", 7, [7], [
  "Go to the white desk in the rec room.",
  "In the recreation room, could you go to the white writing table?",
  "rec room, white worktable",
  "I need the white one in the rec room, not either of the brown wooden ones. That's where I do my work.",
  "This is a white wooden work table. It is in the rec room.",
  "the white work table w the usb port, rec rm"]),
 (COFF, "ard", 25, [25], [
  "Take me to where I can check the time.",
  "Could you go to wherever I can see what hour it is on the wall?",
  "wall time check",
  "My phone's dead and I've no idea how late it is. Go to the thing on the wall that would tell me.",
  "This is what I'd look at to see the hour. It hangs on the rec room wall, black with a red second hand.",
  "what time is it?? go where i can see"]),
 (C829, "o", 42, [42, 197, 212, 259], [
  "Go to a book.",
  "Could you find me one of the bound volumes lying around?",
  "a hardback, any",
  "I'm bored and want something to read. Head to any of the leather- or paper-bound volumes, no matter which room.",
  "This is a bound volume with a cover. Any one of them is fine.",
  "go find a bok to read"]),
 # flats
 (FD, "ard", 25, [25], [
  "Take me to where I can dry this load of wet laundry.",
  "Could you go to the machine I'd use to dry my clothes?",
  "dry wet clothes",
  "The wash just finished and everything is soaking. Go to where I can tumble it dry, not the washer.",
  "This is the appliance that gets damp clothes dry. It stands next to the washer in the laundry room.",
  "clothes r still wet, where do i dry em"]),
 (FD, "ord", 22, [22], [
  "Go to the wooden stool in the kitchenette.",
  "In the little kitchen, could you go to the wooden bar seat with the round top?",
  "kitchenette, wooden seat, round top",
  "Of the two bar seats in the kitchenette, go to the wooden one, not the black metal one.",
  "This is a round-seated wooden stool. It is in the kitchenette.",
  "kitchenete - the wood one w round seat, not metal"]),
 (FD, "s", 5, [5], [
  "Go to the chair on the east side of the round dining table.",
  "Could you go to the seat at the round table that's on the far side when you look at it from the bookcase?",
  "round table, east seat",
  "Go to the round table and pick the seat on the side nearer the big potted plant, not the one on the bookcase side.",
  "This is a seat at the round dining table. It is the one on the east side, farther from the bookcase.",
  "the seat at the round tabel on the east side, by the plant-ish"]),
 (FD, "s", 8, [8], [
  "Go to the lamp next to the sofa bed.",
  "Could you go to the light standing beside the fold-out couch?",
  "lamp by sofa bed",
  "Go to the floor light right beside the sofa bed, not the one on the writing desk.",
  "This is a tall standing light. It is next to the sofa bed, in the corner.",
  "the light next to the sofabed pls"]),
 (FF, "or", 12, [12, 13, 14, 15], [
  "Go to a chair in the kitchen.",
  "Could you go to one of the seats around the kitchen table?",
  "kitchen seat, any",
  "I need somewhere to sit while I eat. Any chair in the kitchen will do, not the rocking one on the porch.",
  "This is a wooden dining seat. It is in the kitchen.",
  "one of the kitchn seats, whichever"]),
 (FF, "ard", 25, [25], [
  "Take me to what I'd use to look at the stars.",
  "Could you go to the thing we use for stargazing?",
  "stargazing",
  "It's a clear night and I want to see the moon's craters up close. Go to what I'd need for that.",
  "This is what you look through to see planets and stars up close. It stands on a tripod on the porch.",
  "wanna look at saturn tonight, go where i can"]),
 (FF, "s", 13, [13], [
  "Go to the chair at the kitchen table that's closest to the tall green dresser.",
  "Could you go to the seat at the dining table nearest the big painted dresser with the plates on it?",
  "table seat by the dresser",
  "At the kitchen table, go to the seat at the south-east corner, next to the dresser, not the one by the range cooker.",
  "This is a chair at the kitchen table. It is the one nearest the sage-green dresser.",
  "the seat closest 2 the dresser, kitchen table"]),
 (FF, "s", 2, [2], [
  "Go to the armchair next to the fireplace.",
  "Could you go to the easy chair right by the hearth?",
  "armchair by fireplace",
  "I want to warm up by the fire. Go to the seat right beside the hearth in the living room, not the one near the floor lamp.",
  "This is a seat with arms. It is right next to the stone fireplace on the west side of the living room.",
  "comfy chair by the fire pls"]),
 (FG, "s", 32, [32], [
  "Go to the nightstand closer to the wardrobe.",
  "Could you go to the bedside table on the side of the bed nearest the closet?",
  "bedside table near wardrobe",
  "Go to the bedside table on the wardrobe side of the bed, not the one near the laundry hamper.",
  "This is a white bedside table. It is the one on the west side of the bed, nearer the tall wardrobe.",
  "nightstand, west side of bed"]),
 (FG, "s", 2, [2], [
  "Go to the bicycle nearer the workbench.",
  "Could you go to the bike that's closest to the workbench in the garage?",
  "bike by workbench",
  "Go to the bike at the workbench end of the back wall, not the one nearer the west wall.",
  "This is a bike leaning on the garage's back wall. It is the one to the east, closer to the workbench.",
  "the bike closest 2 the workbench"]),
 (FG, "ord", 34, [34], [
  "Go to the lamp with the teal glass base in the bedroom.",
  "In the bedroom, could you go to the bedside light whose base is turquoise glass?",
  "bedroom, teal bedside light",
  "I want the bedroom lamp with the teal glass bottom, not the beige ceramic one.",
  "This is a light by the bed whose base is teal glass, topped with a pale shade. It is in the bedroom.",
  "bedroom - the light w the teal base"]),
 (FG, "ard", 6, [6], [
  "Take me to where I can dump the grass clippings.",
  "Could you go to where the garden waste goes?",
  "garden waste",
  "I've just pruned the hedge and have a pile of cuttings. Go to where those should go, not the kitchen one.",
  "This is where yard waste is thrown away. It is green, on wheels, just inside the garage door.",
  "where do the hedge trimmings go"]),
 (FH, "o", 13, [13, 26, 32], [
  "Go to a mug.",
  "Could you find me one of the coffee cups?",
  "any cup",
  "I want a hot drink, so go to any mug in the house, I'm not fussy which one.",
  "This is a drinking cup with a handle. Any of them will do.",
  "find a mugg"]),
 (FH, "ord", 47, [47], [
  "Go to the nightstand with the paperback on it in the master bedroom.",
  "In the main bedroom, could you go to the bedside table that has a book lying on top?",
  "master bedroom bedside table w/ book",
  "In the master bedroom there are two white bedside tables; go to the one with the novel on top, not the one with the lamp.",
  "This is a white single-drawer bedside table in the master bedroom. A paperback rests on it.",
  "nightstand w the detective novel, master bed rm"]),
 (FH, "od", 6, [6], [
  "Go to the cream linen sofa.",
  "Could you go to the small off-white couch, the two-seater?",
  "cream loveseat",
  "Not the long green velvet one. Go to the little cream two-seat settee.",
  "This is a small two-seat sofa upholstered in cream linen.",
  "the creme colored loveseat"]),
 (FH, "s", 17, [17], [
  "Go to the dining chair closest to the window.",
  "Could you go to the seat at the dining table that's nearest the east window?",
  "dining seat by window",
  "Go to the chair at the dining table nearest the window, not the rattan one on the north side.",
  "This is a black metal seat at the dining table. It is on the south side, at the end toward the window.",
  "dining room, seat nearest the windo"]),
 (FH, "ard", 4, [4], [
  "Take me to where we drop the house keys.",
  "Could you go to the spot where we usually leave our keys when we come in?",
  "where keys go",
  "I just got home and want to put my keys where they belong. Go there, not the coat stand.",
  "This is the little thing where keys are tossed on the way in. It is green ceramic, on the hallway console.",
  "keys spot?? go"]),
 # apartment and scans
 (APT, "o", 14, [14, 36], [
  "Go to a pillow.",
  "Could you find one of the cushions?",
  "cushion, any",
  "My neck hurts; go to any cushion, the one on the couch or the one on the bed, doesn't matter.",
  "This is a soft pillow. Any one of them is fine.",
  "find a cushin"]),
 (APT, "or", 12, [12, 13], [
  "Go to a book in the living room.",
  "Could you go to one of the volumes in the lounge?",
  "living room reading material",
  "I want something to flip through in the living room, any of the volumes there, not the programming textbook in the office.",
  "This is a book on the living room bookshelf. Either of them will do.",
  "livingroom, something to read off the shelf"]),
 (APT, "od", 2, [2], [
  "Go to the brown leather loveseat.",
  "Could you go to the small brown leather couch?",
  "brown leather couch",
  "Not the big gray one facing the TV. I mean the little brown leather two-seater.",
  "This is a compact two-seat sofa in worn brown leather.",
  "the leather sofa, brown, small one"]),
 (APT, "ord", 43, [43], [
  "Go to the oval mirror in the bathroom.",
  "In the bathroom, could you go to the frameless oval looking glass?",
  "bathroom oval looking glass",
  "Go to the oval one with the built-in light in the bathroom, not the gold-framed one in the hall.",
  "This is a frameless oval mirror with its own light. It is in the bathroom above the washbasin.",
  "bathrm, the lit up oval one above the basin"]),
 (APT, "ard", 54, [54], [
  "Take me to where I can print my boarding pass.",
  "Could you go to the machine that puts documents on paper?",
  "print something",
  "I need a hard copy of this contract before the meeting. Go to what I'd use for that, not the laptop.",
  "This is what turns files into paper copies. It rests on the gray filing cabinet in the office.",
  "gotta print tickets, where"]),
 (APT, "s", 39, [39], [
  "Go to the plant on top of the dresser.",
  "Could you go to the little houseplant sitting on the chest of drawers?",
  "pot on dresser",
  "Go to the greenery that sits up on the dresser in the bedroom, not the big tree on the living room floor.",
  "This is a small potted plant. It is on top of the chest of drawers.",
  "the houseplant thats on the drawers"]),
 (SK, "or", 23, [23, 24, 25], [
  "Go to a cup in the kitchen.",
  "Could you find one of the mugs in the kitchen?",
  "kitchen mug",
  "I'm thirsty. Go to any of the cups in the kitchen, I don't mind which colour.",
  "This is a small drinking mug. It is in the kitchen; any one will do.",
  "kitchen, a mug, whichever"]),
 (SK, "s", 3, [3], [
  "Go to the kitchen cabinet under the sink.",
  "Could you go to the cupboard directly beneath the sink?",
  "cupboard under sink",
  "The dish soap is in the cupboard right below the sink. Go there, not the wall cupboards up top.",
  "This is a base cupboard. It sits directly under the sink.",
  "under-sink cupbord"]),
 (SK, "ard", 12, [12], [
  "Take me to where I can brew some coffee.",
  "Could you go to the machine that makes my morning coffee?",
  "coffee brewing",
  "I'm half asleep and need a fresh pot. Go to whatever makes that, not the microwave.",
  "This is what brews the coffee. It is black and sits on the counter at the west end.",
  "need caffeine asap, go"]),
 (SO, "o", 21, [21, 22], [
  "Go to a trash can.",
  "Could you find one of the wastebaskets?",
  "bin",
  "I have some scrap paper to throw out, so go to any rubbish bin in the office.",
  "This is a waste bin. Either one is fine.",
  "garbage can, any"]),
 (SO, "ord", 16, [16], [
  "Go to the white bookshelf in the office.",
  "In the office, could you go to the white bookcase?",
  "office white shelf unit",
  "There are three shelf units along the north wall of the office; go to the white one, not the brown wooden ones.",
  "This is a short white bookshelf. It is in the office.",
  "white bookcase, office"]),
 (SO, "s", 10, [10], [
  "Go to the office chair closest to the door.",
  "Could you go to the desk chair nearest the entrance?",
  "chair nearest door",
  "Go to the seat nearest the door. It's at the wooden table, on the north side, east end.",
  "This is an office chair. It is the one closest to the door.",
  "the desk chair by the dooor"]),
 (SO, "od", 30, [30], [
  "Go to the white keyboard.",
  "Could you find the white-coloured keypad for typing?",
  "white kb",
  "Not the black one: go to the white keyboard.",
  "This is a white typing keypad. It is the lighter of the two.",
  "the white keybaord"]),
 (SL, "o", 17, [17, 18], [
  "Go to a plant.",
  "Could you go to one of the houseplants?",
  "any greenery",
  "I want to water something, so go to any of the potted plants in here.",
  "This is a green houseplant in a pot. Either one will do.",
  "find a houseplnt"]),
 (SL, "s", 4, [4], [
  "Go to the pillow on the sofa closest to the brown armchair.",
  "Could you go to the cushion at the east end of the couch?",
  "sofa cushion, east end",
  "Sitting on the sofa facing the TV, go to the cushion furthest to your right, not the yellow one in the middle.",
  "This is a red pillow on the sofa. It is the one at the end nearest the brown armchair.",
  "cushion on the couch, east end by the side table"]),
 (SB, "or", 2, [2, 3, 4, 5], [
  "Go to a pillow in the bedroom.",
  "Could you go to one of the cushions in the bedroom?",
  "bedroom cushion",
  "Go to any pillow in the bedroom, the colour doesn't matter.",
  "This is a soft cushion. It is in the bedroom.",
  "a bedroom cushin, any"]),
 (SB, "s", 9, [9], [
  "Go to the lamp nearest the door.",
  "Could you go to the bedside light closest to the door?",
  "light by the door",
  "Go to the lamp on the nightstand near the door, not the one by the window.",
  "This is a small bedside light. It is on the nightstand on the door side of the bed.",
  "the light next to door side of bed"]),
]

def main():
    out = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round27.jsonl"
    lines = []
    for gi, (m, t, target, accept, ws) in enumerate(G, 1):
        assert len(ws) == 6, gi
        for wi, q in enumerate(ws, 1):
            lines.append(json.dumps({"id": f"b27-g{gi:02d}-w{wi}", "map": m, "query": q, "type": t,
                                     "target": target, "accept": sorted(accept), "group": f"b27-g{gi:02d}"}))
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(len(G), "groups,", len(lines), "lines ->", out)

if __name__ == "__main__":
    main()
