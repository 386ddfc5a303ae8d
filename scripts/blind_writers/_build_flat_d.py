import json
rooms = [
 {"id": 1, "label": "studio", "polygon": [[0,0],[6,0],[6,5],[0,5]]},
 {"id": 2, "label": "kitchenette", "polygon": [[6,0],[9,0],[9,3],[6,3]]},
 {"id": 3, "label": "laundry room", "polygon": [[6,3],[9,3],[9,5],[6,5]]},
 {"id": 4, "label": "kids room", "polygon": [[0,5],[4,5],[4,8.5],[0,8.5]]},
 {"id": 5, "label": "bathroom", "polygon": [[4,5],[6.5,5],[6.5,8.5],[4,8.5]]},
 {"id": 6, "label": "entrance hall", "polygon": [[6.5,5],[9,5],[9,8.5],[6.5,8.5]]},
]
O = []
def o(label, c, s, room, color=None, material=None, caption=None, **extra):
    tags = {}
    if color: tags["color"] = color
    if material: tags["material"] = material
    tags.update(extra)
    d = {"id": len(O)+1, "label": label, "center": c, "size": s, "room": room, "tags": tags}
    if caption: d["caption"] = caption
    O.append(d)
S="studio"; K="kitchenette"; L="laundry room"; C="kids room"; B="bathroom"; E="entrance hall"
o("sofa bed",[1.5,0.5,0.4],[2.0,0.9,0.8],S,"green","fabric","A green fabric sofa bed against the south wall of the studio that folds out into a double bed at night.")
o("table",[1.5,1.8,0.22],[0.9,0.5,0.44],S,"black","metal","A low black metal table with a glass top in front of the sofa bed.")
o("table",[4.0,3.0,0.375],[1.0,1.0,0.75],S,"light brown","wood","A round pine dining table for two.",shape="round")
o("chair",[3.35,3.0,0.45],[0.45,0.45,0.9],S,"white","plastic","A white moulded plastic chair at the round dining table.")
o("chair",[4.65,3.0,0.45],[0.45,0.45,0.9],S,"yellow","wood","A yellow painted wooden chair at the round dining table.")
o("desk",[5.3,0.35,0.375],[1.1,0.55,0.75],S,"white","wood","A narrow white writing desk under the south window of the studio.")
o("chair",[5.3,0.95,0.5],[0.6,0.6,1.0],S,"black","mesh","A black mesh office chair on castors at the writing desk.")
o("lamp",[0.3,0.3,0.8],[0.35,0.35,1.6],S,"white","metal","A tall white metal floor lamp in the corner beside the sofa bed.")
o("lamp",[5.75,0.35,0.95],[0.2,0.2,0.4],S,"silver","metal","A small silver desk lamp with an adjustable arm on the writing desk.")
o("cup",[4.1,3.1,0.8],[0.09,0.09,0.1],S,"green","ceramic","A green ceramic mug on the round dining table.")
o("rug",[1.5,1.8,0.005],[2.2,1.5,0.01],S,"gray","wool","A rectangular gray wool rug under the low table.")
o("bookshelf",[0.2,3.3,0.9],[0.35,1.0,1.8],S,"white","wood","A tall white bookcase along the west wall, full of paperbacks and board games.")
o("tv",[2.2,4.95,1.3],[1.0,0.08,0.6],S,"black","plastic","A wall-mounted black flat-screen TV on the north wall of the studio.")
o("plant",[5.65,4.6,0.6],[0.5,0.5,1.2],S,"green","ceramic","A large monstera in a white ceramic pot in the north-east corner of the studio.")
o("refrigerator",[8.65,0.35,0.85],[0.6,0.65,1.7],K,"white","metal","A slim white fridge-freezer in the corner of the kitchenette.")
o("counter",[7.3,0.3,0.45],[2.0,0.6,0.9],K,"white","laminate","A short white laminate worktop with cupboards underneath.")
o("sink",[7.6,0.3,0.88],[0.5,0.4,0.15],K,"silver","stainless steel","A single stainless steel sink set into the worktop.")
o("cooktop",[6.6,0.3,0.91],[0.55,0.5,0.05],K,"black","glass","A two-ring black glass induction hob on the worktop.")
o("kettle",[7.0,0.3,1.0],[0.2,0.18,0.25],K,"white","plastic","A white plastic electric kettle on the worktop.")
o("toaster",[8.0,0.3,1.0],[0.3,0.18,0.2],K,"red","metal","A red two-slice toaster on the worktop.")
o("stool",[7.2,2.0,0.35],[0.35,0.35,0.7],K,"black","metal","A black metal bar stool.")
o("stool",[7.9,2.0,0.35],[0.35,0.35,0.7],K,"brown","wood","A wooden stool with a round seat.")
o("trash can",[6.25,2.7,0.3],[0.3,0.3,0.6],K,"gray","metal","A gray metal pedal bin.")
o("washing machine",[6.4,4.65,0.425],[0.6,0.6,0.85],L,"white","metal","A white front-loading washing machine.")
o("dryer",[7.05,4.65,0.425],[0.6,0.6,0.85],L,"white","metal","A white tumble dryer standing next to the washing machine.")
o("laundry basket",[8.0,4.4,0.25],[0.5,0.35,0.5],L,"blue","plastic","A blue plastic laundry basket full of clean clothes.")
o("ironing board",[8.75,3.9,0.45],[0.35,1.2,0.9],L,"gray","metal","An ironing board with a gray cover, standing open by the east wall.")
o("bunk bed",[0.55,6.9,0.85],[1.0,2.0,1.7],C,"blue","wood","A blue wooden bunk bed along the west wall of the kids' room.")
o("teddy bear",[0.6,6.2,0.5],[0.3,0.25,0.35],C,"brown","plush","A brown plush teddy bear on the lower bunk.")
o("toy box",[2.5,5.35,0.25],[0.8,0.45,0.5],C,"red","plastic","A red plastic toy chest full of building blocks.")
o("rug",[2.2,7.0,0.005],[1.6,1.6,0.01],C,"multicolored","cotton","A round, rainbow-striped cotton play rug.",shape="round")
o("desk",[3.5,8.15,0.3],[0.9,0.5,0.6],C,"yellow","plastic","A small yellow children's desk.")
o("chair",[3.5,7.65,0.3],[0.35,0.35,0.6],C,"green","plastic","A small green plastic children's chair at the yellow desk.")
o("lamp",[3.75,8.2,0.72],[0.2,0.2,0.25],C,"pink","plastic","A little pink night-light lamp shaped like a moon, on the children's desk.")
o("toilet",[6.1,8.1,0.4],[0.4,0.65,0.8],B,"white","ceramic","A white ceramic toilet.")
o("sink",[4.35,6.6,0.85],[0.5,0.4,0.2],B,"white","ceramic","A white ceramic pedestal washbasin.")
o("shower",[4.55,8.0,1.0],[0.9,0.9,2.0],B,"transparent","glass","A glass-walled shower cubicle.")
o("plant",[6.2,5.35,0.3],[0.3,0.3,0.6],B,"green","clay","A small fern in a terracotta pot on the bathroom floor.")
o("coat rack",[8.7,8.2,0.9],[0.4,0.4,1.8],E,"black","metal","A black metal coat stand in the entrance hall.")
o("bench",[7.6,8.25,0.23],[1.0,0.35,0.45],E,"brown","wood","A wooden shoe bench to sit on while putting shoes on.")
m = {"scene_id": "flat_d", "source": "hand-written by a blind helper for evals/blind/round3.jsonl",
     "comment": "Studio flat with kitchenette, laundry room, kids room, bathroom and entrance hall, 9 m x 8.5 m. x east, y north, z up, metres. Boxes are axis-aligned: center [x, y, z], size [dx, dy, dz].",
     "rooms": rooms, "objects": O}
json.dump(m, open("/work/main/evals/blind/maps/flat_d.json","w"), indent=1)
print(len(O))
