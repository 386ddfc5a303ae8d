"""Hand-written blind suite round 41: 48 groups x 6 wordings. Writes evals/blind/round41.jsonl."""
import json
from pathlib import Path

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

# (group no, map, type, target, accept, [w1..w6])
G = [
 (1, C829, "o", 160, [160, 162, 164], [
  "Go to the folded towels.",
  "Could you show me where the stacks of towels are kept?",
  "folded towels",
  "I just got out of the shower and need something to dry off with, so take me to the towels.",
  "This is a pile of neatly folded white cotton towels. It is the kind you grab after a bath.",
  "where r the towles, the fluffy white folded ones"]),
 (2, C829, "o", 4, [4, 9, 32, 79, 191, 261, 263], [
  "Go to an easy chair.",
  "Could you take me to one of the comfy lounge chairs?",
  "armchair for lounging",
  "My back is sore and a hard seat won't do, so find me a cushy recliner-style chair to sink into.",
  "This is an upholstered lounge seat with arms. It is made for relaxing rather than working.",
  "any easy chiar will do, just want to sit back and relax"]),
 (3, C829, "or", 195, [195, 216, 228], [
  "Go to the cupboards in the bathroom.",
  "Could you bring me to one of the wooden storage cabinets in the bathroom?",
  "bathroom cupboard",
  "I keep spare soap in a cupboard, the one in the bathroom, not the kitchen one.",
  "This is a dark wooden storage cabinet. It is in the bathroom.",
  "take me to one of the bathroom cupbaords, any is fine"]),
 (4, C829, "or", 219, [219], [
  "Go to the mirror frame in the bedroom.",
  "Could you lead me to the framed mirror that hangs in the bedroom?",
  "bedroom mirror",
  "I want to check my outfit in the bedroom mirror, not the one over in the bathroom.",
  "This is a looking glass set in a carved wooden surround. It is in the bedroom.",
  "take me to the mirorr in the bedroom pls"]),
 (5, C829, "od", 192, [192], [
  "Go to the pet bed.",
  "Could you show me where the dog's bed is?",
  "white and brown pet cushion",
  "The cat is missing and she usually naps in her little bed, so take me to it, not a person's bed.",
  "This is a soft sleeping spot for an animal. It is white and brown and sits on a wooden base.",
  "where is the bed for the ptes, the small plush one"]),
 (6, C829, "ord", 34, [34], [
  "Go to the side table with the glass top in the living room.",
  "Could you take me to the little glass-topped end table in the living room?",
  "glass-top end table living room",
  "I left my glasses on the end table with a glass surface in the living room, not the one with the USB port.",
  "This is a small dark wooden table on a metal stand with a glass surface. It is in the living room.",
  "the lil side tabel in the living room, one with glass on top"]),
 (7, C829, "ard", 122, [122], [
  "Take me where I can use the loo.",
  "Could you point me to where I can relieve myself?",
  "need to pee",
  "I really need the lavatory right now, not a sink, please hurry.",
  "This is where someone goes when nature calls. It is white porcelain and flushes.",
  "gotta go to the bathroom real quick, where's the wc for a wee, urgnet"]),
 (8, OFF3, "o", 8, [8, 13, 20, 40], [
  "Go to a pillow.",
  "Could you find me one of the cushions?",
  "throw cushion",
  "My neck hurts from sitting, so bring me to any of the soft cushions lying around.",
  "This is a small soft cushion. It is the sort you tuck behind your back on a couch.",
  "any cushon is fine, just need something soft"]),
 (9, OFF3, "or", 7, [7, 55, 64], [
  "Go to a desk in the rec room.",
  "Could you take me to one of the writing desks in the rec room?",
  "workstation rec room",
  "I need somewhere flat to write a letter, a proper work surface in the rec room, not the sofa.",
  "This is a wooden workstation for writing or computer work. It is in the rec room.",
  "which dseks are in the rec room, take me to one"]),
 (10, OFF3, "od", 13, [13], [
  "Go to the navy blue velvet pillow.",
  "Could you bring me to the dark blue velvety cushion?",
  "navy velvet cushion",
  "I want the dark blue velvet cushion, not the orange or yellow ones.",
  "This is a plush cushion in deep navy. It has buttons and is a bit bigger than its neighbours.",
  "the navy blue cusion, the soft velvet one"]),
 (11, OFF3, "od", 45, [45], [
  "Go to the golden-brown wooden table with power outlets.",
  "Could you show me the honey-coloured wooden surface that has sockets built into it?",
  "wooden top with power sockets",
  "My phone is dying, so take me to the warm brown wooden surface with plugs in it, not one of the desks.",
  "This is a wooden surface in a warm golden-brown tone. It has electrical sockets built in for charging gadgets.",
  "where's that brown wood thing with the plugs in it, need to chrage"]),
 (12, OFF3, "ard", 67, [67], [
  "Take me to the thing I can use to change the channel.",
  "Could you help me find what I'd use to switch the TV to another programme?",
  "change channel",
  "I want to turn the volume down from my seat, not by walking over to the screen.",
  "This is a small handheld gadget for operating a television from afar. It is made of black and white plastic.",
  "wheres the clicker, wanna flip channles"]),
 (13, FC, "or", 5, [5, 7], [
  "Go to a lamp in the living room.",
  "Could you take me to one of the lights in the living room?",
  "living room light",
  "It's getting dark in the lounge, so find me a light there, not the one in the bedroom or study.",
  "This is a source of light you can switch on. It is in the living room.",
  "any lamp in the livng room, it's dark"]),
 (14, FC, "ord", 31, [31], [
  "Go to the rattan chair in the bedroom.",
  "Could you bring me to the wicker seat in the bedroom that has clothes piled on it?",
  "bedroom wicker seat",
  "I left my jumper draped over a seat in the bedroom, the cane one in the corner, not a kitchen chair.",
  "This is a beige woven rattan seat with garments thrown over it. It is in a corner of the bedroom.",
  "the wicker seat in the bedrom with clothes on it"]),
 (15, FC, "s", 20, [20], [
  "Go to the chair closest to the fridge.",
  "Could you take me to the dining seat that is nearest the refrigerator?",
  "seat nearest fridge",
  "I want to sit where I can reach the fridge easily, so the seat right next to it, not the ones farther off.",
  "This is a dining seat at the round kitchen table. It is the one nearest to the refrigerator.",
  "the seat closest to the frigde pls"]),
 (16, FC, "ard", 29, [29], [
  "Take me to something that tells me the time.",
  "Could you show me where I can check what time it is?",
  "check time",
  "My phone is dead and I need to know the hour, so take me to whatever shows the time in this flat.",
  "This is a small red device that shows the time and rings to wake you up. It sits by the bed.",
  "what time is it, take me to somthing that shows the time"]),
 (17, FD, "or", 4, [4, 5, 7], [
  "Go to a chair in the studio.",
  "Could you take me to any seat in the studio?",
  "studio seat",
  "I need somewhere to sit in the studio, not the little kids' one in the children's room.",
  "This is a seat for one person with a back. It is in the studio.",
  "any chiar in the studio is fine"]),
 (18, FD, "ard", 25, [25], [
  "Take me to where I can dry my wet laundry.",
  "Could you show me where my washed clothes can be dried?",
  "dry clothes",
  "The wash just finished and everything is damp, so I need the machine that gets it dry, not the washer.",
  "This is a white appliance that tumbles damp clothes until they are dry. It stands in the laundry room.",
  "my clothes are soaking wet, where can i dry them quikly"]),
 (19, FD, "s", 22, [22], [
  "Go to the stool farther from the bin.",
  "Could you take me to whichever bar seat is more distant from the rubbish bin?",
  "seat away from bin",
  "I don't want to sit next to the rubbish, so take me to the seat that is farther from the bin, not the one near it.",
  "This is one of the two backless seats in the kitchenette. It is the one farther away from the trash bin.",
  "the stool furthest from the trahs can"]),
 (20, FF, "od", 14, [14], [
  "Go to the mustard-yellow dining chair.",
  "Could you take me to the yellow painted chair at the dining table?",
  "yellow wooden seat",
  "Find me the seat that doesn't match the rest around the dining table, the yellow one, not the blue ladder-backs.",
  "This is a wooden dining seat painted mustard yellow. It stands out from the blue ones around it.",
  "the yelow seat at the table, the one that doesnt match"]),
 (21, FF, "o", 2, [2, 3], [
  "Go to an armchair.",
  "Could you take me to one of the armchairs?",
  "upholstered easy chair",
  "I want a comfy single seat with arms, not the sofa or a dining chair.",
  "This is a padded seat for one with armrests. It is in the living room.",
  "any comfy armcahir, want to read"]),
 (22, FF, "s", 15, [15], [
  "Go to the blue dining chair nearest the range cooker.",
  "Could you take me to the blue seat at the table that is closest to the cooker?",
  "blue seat nearest cooker",
  "I want the blue seat that is nearest the stove, not the yellow one and not the blue ones farther away.",
  "This is a blue ladder-back seat at the long table. Of the blue ones, it is the closest to the range.",
  "the blue chair closest to the stvoe"]),
 (23, FF, "ard", 25, [25], [
  "Take me to something I can use to look at the stars.",
  "Could you show me what I could use to watch the night sky?",
  "stargazing",
  "It's a clear night and I want to look at the moon up close, not just through a window.",
  "This is an instrument on a tripod for viewing faraway things in the sky. It is on the porch.",
  "wanna look at the stras tonight, where's the thing for that"]),
 (24, FH, "s", 32, [32], [
  "Go to the mug on the desk.",
  "Could you bring me to the cup that is sitting on the writing desk?",
  "cup on desk",
  "I left my coffee on the desk, not the one on the coffee table or the kitchen worktop.",
  "This is a black cup with a chipped handle. It is sitting on top of the oak writing desk.",
  "the mug thats on the dsek"]),
 (25, FH, "ord", 6, [6], [
  "Go to the cream linen sofa in the living room.",
  "Could you take me to the small cream two-seater in the living room?",
  "cream loveseat living room",
  "I want the small pale couch in the living room, not the big green velvet one.",
  "This is a compact two-seat couch covered in cream linen. It sits below the window on the east side of the lounge.",
  "the little creem couch in the living room"]),
 (26, FH, "or", 46, [46, 47], [
  "Go to a nightstand in the master bedroom.",
  "Could you take me to one of the bedside tables in the master bedroom?",
  "master bedroom bedside table",
  "I left my watch on a bedside table in the main bedroom, not the guest room.",
  "This is a white bedside table with a drawer. It is in the master bedroom.",
  "any of the bedside tabels in the master bedroom"]),
 (27, APT, "o", 1, [1, 2], [
  "Go to a sofa.",
  "Could you take me to one of the couches?",
  "couch",
  "I want to lie down on a couch, not a chair or the bed.",
  "This is a padded seat for several people with a back and arms. It is in the living room.",
  "any sofa is fine, wanna nap on the cuoch"]),
 (28, APT, "or", 12, [12, 13], [
  "Go to a book in the living room.",
  "Could you take me to one of the books in the living room?",
  "reading material living room",
  "I want something to read in the living room, not the programming text in the office.",
  "This is a volume to read. It is on the shelf in the living room.",
  "any novle or photo album in the living room"]),
 (29, APT, "od", 7, [7], [
  "Go to the black floor lamp with the arched neck.",
  "Could you take me to the tall black standing light with the curved neck?",
  "arched black floor light",
  "I want the tall black light with a curved arm, not the bedside or desk ones.",
  "This is a tall black metal light that stands on the floor. Its neck curves over like an arch.",
  "the tall black lmap with the bendy neck"]),
 (30, APT, "ord", 48, [48], [
  "Go to the red leather chair in the office.",
  "Could you take me to the red swivel seat in the office?",
  "red office swivel seat",
  "I need a seat with wheels in the office, the red leather one, not a dining seat in the kitchen.",
  "This is a red leather seat with armrests that rolls and swivels. It is at the desk in the office.",
  "the red swivle chair in the office"]),
 (31, APT, "ard", 54, [54], [
  "Take me to where I can print a document.",
  "Could you show me where I can get a paper copy of my file?",
  "print document",
  "I need a hard copy of my boarding pass, so take me to the thing that puts it on paper.",
  "This is a machine that puts text from a computer onto paper. It rests on the metal filing unit in the office.",
  "need to prnit my ticket, where can i do that"]),
 (32, APT, "ard", 45, [45], [
  "Take me to where I can wash my dirty clothes.",
  "Could you show me where I can do a load of laundry?",
  "wash clothes",
  "My jeans are muddy and need a proper wash, not just a rinse in the sink.",
  "This is an appliance that cleans clothes with water and soap. It is in the bathroom.",
  "where can i do my laundy"]),
 (33, APT, "s", 12, [12], [
  "Go to the book that sits higher up on the living room bookshelf.",
  "Could you take me to whichever of the two living room books is on the upper shelf?",
  "upper-shelf living room novel",
  "I want the volume up high on the lounge shelves, not the one lying flat near the bottom.",
  "This is one of two volumes on the living room shelving. It is the one placed higher up.",
  "the bok on the upper shelf in the living room"]),
 (34, APT, "s", 36, [36], [
  "Go to the pillow on the bed.",
  "Could you take me to the cushion lying on the bed?",
  "cushion on bed",
  "I want the cushion that's on the bed, not the one on the sofa.",
  "This is a white cushion. It lies at the head end of the bed.",
  "the pilow on the bed"]),
 (35, APT, "ord", 24, [24], [
  "Go to the white spindle-back chair in the kitchen.",
  "Could you take me to the white painted wooden seat in the kitchen?",
  "white kitchen seat",
  "I want the white seat at the kitchen table, not the one with the green cushion.",
  "This is a white painted wooden seat with a spindle back. It is in the kitchen by the table.",
  "the white chiar in the kitchen"]),
 (36, APT, "od", 8, [8], [
  "Go to the fiddle-leaf fig.",
  "Could you take me to the big-leafed fig in the white pot?",
  "fig tree white pot",
  "I want to water the tall fig with glossy leaves, not the succulent or the snake plant.",
  "This is a tall potted fig with large shiny leaves. It sits in a white ceramic pot.",
  "the fiddle leaf fgi"]),
 (37, APT, "ord", 42, [42], [
  "Go to the gray vanity cabinet in the bathroom.",
  "Could you take me to the gray wooden cupboard in the bathroom?",
  "gray bathroom vanity",
  "I need a clean towel from the bathroom storage unit, not the gray filing cabinet in the office.",
  "This is a gray wooden storage unit with doors. It is in the bathroom.",
  "the grey vanity in the bathrom"]),
 (38, SK, "s", 25, [25], [
  "Go to the cup on the counter.",
  "Could you take me to the mug sitting on the worktop?",
  "mug on worktop",
  "I want the mug on the kitchen worktop, not one of the two on the dining table.",
  "This is a white mug. It sits on the worktop near the sink.",
  "the cup on the countr"]),
 (39, SK, "s", 22, [22], [
  "Go to the chair at the east end of the table.",
  "Could you take me to the seat at the far eastern head of the dining table?",
  "seat east end table",
  "I want the seat at the east end of the table, not the west end or the sides.",
  "This is a white seat. It sits at the east end of the table.",
  "the chair at the east end of the tabel"]),
 (40, SK, "ard", 12, [12], [
  "Take me to where I can brew a coffee.",
  "Could you show me where I can make myself an espresso?",
  "brew coffee",
  "I need caffeine to wake up, so take me to the thing that brews it, not the microwave or the sink.",
  "This is a black machine for making a hot drink. It sits on the worktop.",
  "need a cofee asap, where do i make one"]),
 (41, SK, "od", 4, [4], [
  "Go to the gray kitchen cabinet.",
  "Could you take me to the gray cupboard?",
  "gray cupboard",
  "I want the gray cupboard, not one of the white ones.",
  "This is a gray lower cupboard. It is the only gray one in the row.",
  "the gray cupbord"]),
 (42, SL, "s", 10, [10], [
  "Go to the lamp on your left when you sit on the sofa.",
  "Could you take me to the light on the left when seated on the couch?",
  "light left of couch",
  "Sitting on the couch facing the TV, I want the light on my left, not the right or the floor one.",
  "This is a white table light. It is on your left when you sit on the couch facing the TV.",
  "the lmap on the left of the sofa when u sit"]),
 (43, SL, "s", 18, [18], [
  "Go to the plant farthest from the TV.",
  "Could you take me to the potted greenery most distant from the television?",
  "greenery far from TV",
  "I want the greenery farthest from the TV, not the one by the bookcase.",
  "This is a leafy thing in a pot. It is the one farthest away from the television.",
  "the plnat furthest from the tv"]),
 (44, SL, "o", 2, [2, 3, 4], [
  "Go to a pillow.",
  "Could you take me to one of the cushions?",
  "cushion",
  "My back aches, so bring me to any of the cushions, whichever is closest.",
  "This is a small soft cushion. It lies on the couch.",
  "any cusion will do"]),
 (45, SB, "s", 4, [4], [
  "Go to the pillow between the two white pillows.",
  "Could you take me to the cushion sitting between the two white ones?",
  "cushion between white ones",
  "I want the cushion in the middle of the two white ones, not the blue one further down the bed.",
  "This is a small cushion on the bed. It sits between the two white ones at the head.",
  "the pilow in between the two white ones"]),
 (46, FH, "ord", 48, [48], [
  "Go to the white ceramic lamp in the master bedroom.",
  "Could you take me to the white bedside light in the master bedroom?",
  "white light master bedroom",
  "I want the white lamp in the main bedroom, not the red one in the guest room.",
  "This is a white ceramic light with a pleated shade. It is in the master bedroom.",
  "the white lapm in the master bedroom"]),
 (47, SO, "s", 12, [12], [
  "Go to the monitor farthest from the whiteboard.",
  "Could you take me to the screen most distant from the whiteboard?",
  "screen far from whiteboard",
  "I want the display farthest from the whiteboard, not the ones near it.",
  "This is a black computer screen. It is the one farthest from the whiteboard.",
  "the monitr furthest from the whiteboard"]),
 (48, SO, "o", 14, [14, 15, 16], [
  "Go to a bookshelf.",
  "Could you take me to one of the bookcases?",
  "bookcase",
  "I need a book, so take me to any of the shelves along the wall, not the cabinet.",
  "This is a tall unit with shelves for books. It stands against the north wall.",
  "any bookshlef is fine"]),
]


def main():
    out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round41.jsonl"
    rows = []
    for n, m, t, tgt, acc, ws in G:
        assert len(ws) == 6, n
        for k, q in enumerate(ws, 1):
            rows.append({"id": f"b41-g{n:02d}-w{k}", "map": m, "query": q, "type": t,
                         "target": tgt, "accept": sorted(acc), "group": f"b41-g{n:02d}"})
    out.write_text("".join(json.dumps(r) + "\n" for r in rows), encoding="utf-8")
    print(len(rows), "rows ->", out)


if __name__ == "__main__":
    main()
