import json
rooms = [
 (1,"garage",[[0,0],[4,0],[4,6],[0,6]]),
 (2,"laundry room",[[4,0],[7,0],[7,3],[4,3]]),
 (3,"kitchen",[[7,0],[12,0],[12,5],[7,5]]),
 (4,"hallway",[[4,3],[7,3],[7,14],[4,14]]),
 (5,"living room",[[7,5],[12,5],[12,10],[7,10]]),
 (6,"kids room",[[7,10],[12,10],[12,14],[7,14]]),
 (7,"bedroom",[[0,6],[4,6],[4,11],[0,11]]),
 (8,"bathroom",[[0,11],[4,11],[4,14],[0,14]]),
]
O = [
 # garage
 ("car",[1.6,3.1,0.75],[1.8,4.2,1.5],"garage","red","metal","A small red hatchback parked nose-first in the garage."),
 ("bicycle",[2.9,5.65,0.5],[1.7,0.5,1.0],"garage","black","aluminium","A black adult mountain bike leaning against the back wall of the garage."),
 ("bicycle",[1.0,5.65,0.35],[1.1,0.45,0.7],"garage","blue","metal","A small blue children's bike with stabilisers."),
 ("workbench",[3.65,2.8,0.45],[0.6,1.8,0.9],"garage","brown","wood","A sturdy wooden workbench along the garage wall with a vice at one end."),
 ("toolbox",[3.65,2.3,1.0],[0.5,0.25,0.2],"garage","red","metal","A red metal toolbox sitting on the workbench."),
 ("trash can",[0.3,0.35,0.55],[0.5,0.6,1.1],"garage","green","plastic","A green wheelie bin for garden waste just inside the garage door."),
 # laundry room
 ("washing machine",[4.4,0.35,0.425],[0.6,0.6,0.85],"laundry room","white","metal","A white front-loading washing machine."),
 ("dryer",[5.0,0.35,0.425],[0.6,0.6,0.85],"laundry room","white","metal","A white tumble dryer standing next to the washing machine."),
 ("cabinet",[4.7,0.2,1.7],[1.2,0.35,0.6],"laundry room","white","wood","A white wall cupboard above the washer and dryer, holding detergent and fabric softener."),
 ("basket",[4.4,2.6,0.3],[0.55,0.4,0.6],"laundry room","white","plastic","A white plastic laundry basket full of clean clothes waiting to be folded."),
 ("ironing board",[6.0,2.2,0.45],[1.3,0.35,0.9],"laundry room","blue","metal","An ironing board with a blue floral cover, set up with a steam iron resting on its end."),
 # kitchen
 ("counter",[8.8,0.3,0.45],[3.0,0.6,0.9],"kitchen","gray","granite","A long gray granite worktop with cupboards underneath, along the back wall of the kitchen."),
 ("sink",[9.3,0.3,0.85],[0.8,0.5,0.2],"kitchen","black","composite","A black composite kitchen sink set into the worktop under the window."),
 ("kettle",[7.8,0.3,1.025],[0.2,0.2,0.25],"kitchen","silver","steel","A brushed steel electric kettle on the worktop."),
 ("stove",[10.6,0.3,0.45],[0.6,0.6,0.9],"kitchen","white","enamel","A white gas cooker with four burners and an oven below."),
 ("refrigerator",[11.5,0.4,0.95],[0.9,0.7,1.9],"kitchen","silver","stainless steel","A tall stainless steel double-door fridge freezer with an ice dispenser."),
 ("table",[9.5,2.7,0.375],[1.2,1.2,0.75],"kitchen","white","wood","A round white kitchen table that seats four."),
 ("chair",[9.5,1.8,0.45],[0.45,0.45,0.9],"kitchen","white","plastic","A white moulded plastic chair at the kitchen table."),
 ("chair",[9.5,3.6,0.45],[0.45,0.45,0.9],"kitchen","brown","wood","A wooden kitchen chair with a red checked seat cushion."),
 ("trash can",[7.3,4.6,0.35],[0.4,0.4,0.7],"kitchen","silver","stainless steel","A stainless steel pedal bin in the corner of the kitchen."),
 # hallway
 ("coat rack",[4.4,13.5,0.9],[0.4,0.4,1.8],"hallway","black","metal","A black metal coat stand by the front door with a raincoat and a school bag hanging on it."),
 ("shoe rack",[6.8,13.2,0.25],[0.3,1.0,0.5],"hallway","brown","wood","A low wooden shoe rack by the front door with trainers and wellies on it."),
 ("mirror",[4.03,8.0,1.0],[0.05,0.6,1.6],"hallway","black","glass","A tall full-length mirror with a thin black frame on the hallway wall."),
 ("table",[6.8,7.0,0.4],[0.3,1.0,0.8],"hallway","white","wood","A narrow white console table against the hallway wall with a dish for keys on it."),
 # living room
 ("sofa",[9.5,9.5,0.425],[2.2,0.9,0.85],"living room","navy","fabric","A navy blue three-seater sofa against the back wall of the living room."),
 ("armchair",[11.4,7.5,0.45],[0.8,0.8,0.9],"living room","yellow","velvet","A mustard yellow velvet armchair by the window."),
 ("coffee table",[9.5,8.2,0.225],[1.1,0.6,0.45],"living room","silver","glass","A glass-topped coffee table with a chrome frame in front of the sofa."),
 ("tv",[9.5,5.05,1.3],[1.3,0.08,0.75],"living room","black","plastic","A large flat-screen television mounted on the wall opposite the sofa."),
 ("lamp",[7.4,9.6,0.8],[0.35,0.35,1.6],"living room","white","metal","A white arched floor lamp in the corner beside the sofa."),
 ("bookshelf",[7.2,7.5,0.9],[0.35,1.0,1.8],"living room","dark brown","wood","A dark wood bookcase full of novels and family photo albums."),
 # bedroom
 ("bed",[2.0,9.9,0.3],[1.6,2.1,0.6],"bedroom","gray","fabric","A king-size bed with a gray upholstered headboard and a white duvet."),
 ("nightstand",[0.75,10.7,0.3],[0.45,0.4,0.6],"bedroom","white","wood","A white bedside table with two drawers."),
 ("nightstand",[3.25,10.7,0.3],[0.45,0.4,0.6],"bedroom","white","wood","A white bedside table with two drawers and a stack of paperbacks beside the lamp."),
 ("lamp",[0.75,10.7,0.8],[0.25,0.25,0.4],"bedroom","teal","glass","A bedside lamp with a teal glass base and a white shade."),
 ("lamp",[3.25,10.7,0.8],[0.25,0.25,0.4],"bedroom","beige","ceramic","A bedside lamp with a beige ceramic base and a linen shade."),
 ("wardrobe",[0.35,7.0,1.0],[0.6,1.6,2.0],"bedroom","light brown","oak","A tall oak wardrobe with two sliding doors."),
 ("basket",[3.6,6.4,0.3],[0.45,0.45,0.6],"bedroom","brown","wicker","A lidded wicker laundry hamper for dirty clothes."),
 # bathroom
 ("bathtub",[1.0,13.6,0.3],[1.7,0.75,0.6],"bathroom","white","acrylic","A white built-in bathtub with a shower over it and a glass screen."),
 ("toilet",[3.6,13.6,0.4],[0.4,0.65,0.8],"bathroom","white","ceramic","A white toilet with a wooden seat."),
 ("sink",[2.5,11.3,0.85],[0.55,0.45,0.2],"bathroom","white","ceramic","A white washbasin on a small wooden vanity unit."),
 ("mirror",[2.5,11.03,1.5],[0.6,0.05,0.7],"bathroom","silver","glass","A round mirror on the wall above the washbasin."),
 # kids room
 ("bed",[7.55,12.9,0.8],[1.0,2.0,1.6],"kids room","white","wood","A white wooden bunk bed with a space-themed duvet on the top bunk."),
 ("desk",[11.6,12.5,0.35],[0.7,1.2,0.7],"kids room","white","wood","A small white children's desk covered in crayons and drawings."),
 ("lamp",[11.7,12.9,0.875],[0.2,0.2,0.35],"kids room","yellow","plastic","A yellow bendy desk lamp on the children's desk."),
 ("basket",[9.5,10.35,0.2],[0.5,0.4,0.4],"kids room","gray","fabric","A gray felt toy basket full of soft toys and building blocks."),
]
objs=[]
for i,(lab,c,s,room,col,mat,cap) in enumerate(O,1):
    objs.append({"id":i,"label":lab,"center":c,"size":s,"room":room,"tags":{"color":col,"material":mat},"caption":cap})
d={"scene_id":"flat_g","source":"hand-written synthetic family house with garage and laundry room, blind helper round 6",
   "comment":"12 m x 14 m single-storey family house. x east, y north, z up, metres. Front door at the north end of the hallway, garage door on the south wall. Axis-aligned boxes: center [x, y, z], size [dx, dy, dz].",
   "rooms":[{"id":i,"label":l,"polygon":p} for i,l,p in rooms],"objects":objs}
json.dump(d,open('/work/blind6/maps/flat_g.json','w'),indent=1)
print(len(objs))
for o in objs: print(o['id'],o['label'],o['room'])
