"""Hand-written holiday-cottage map flat_f.json (blind helper, round 5)."""
import json
rooms = [
    {"id": 1, "label": "living room", "polygon": [[0, 0], [5, 0], [5, 4.5], [0, 4.5]]},
    {"id": 2, "label": "kitchen", "polygon": [[5, 0], [9, 0], [9, 4.5], [5, 4.5]]},
    {"id": 3, "label": "porch", "polygon": [[9, 0], [12, 0], [12, 4.5], [9, 4.5]]},
    {"id": 4, "label": "hallway", "polygon": [[0, 4.5], [12, 4.5], [12, 5.5], [0, 5.5]]},
    {"id": 5, "label": "bedroom", "polygon": [[0, 5.5], [4.5, 5.5], [4.5, 9], [0, 9]]},
    {"id": 6, "label": "bathroom", "polygon": [[4.5, 5.5], [7, 5.5], [7, 9], [4.5, 9]]},
    {"id": 7, "label": "study", "polygon": [[7, 5.5], [12, 5.5], [12, 9], [7, 9]]},
]
O = []
def o(label, room, c, s, color, material, caption=None):
    d = {"id": len(O) + 1, "label": label, "center": c, "size": s, "room": room,
         "tags": {"color": color, "material": material}}
    if caption: d["caption"] = caption
    O.append(d)
# living room
o("sofa", "living room", [2.5, 0.5, 0.42], [2.0, 0.9, 0.85], "green", "fabric", "A moss-green corduroy sofa along the front wall with a knitted throw over the back.")
o("armchair", "living room", [0.8, 2.3, 0.45], [0.8, 0.8, 0.9], "red", "wool", "A red tartan wool wingback armchair beside the fireplace.")
o("armchair", "living room", [4.2, 2.3, 0.45], [0.8, 0.8, 0.9], "cream", "leather", "A cream leather armchair with rounded arms.")
o("fireplace", "living room", [0.2, 3.2, 0.6], [0.4, 1.4, 1.2], "gray", "stone", "A stone inglenook fireplace with a cast-iron wood-burning stove.")
o("coffee table", "living room", [2.5, 2.1, 0.22], [1.0, 0.6, 0.45], "light brown", "pine", "A low pine coffee table with a stack of walking maps on it.")
o("lamp", "living room", [4.6, 0.4, 0.8], [0.35, 0.35, 1.6], "gold", "brass", "A brass floor lamp with a pleated cream shade in the front corner of the lounge.")
o("rug", "living room", [2.5, 2.1, 0.01], [2.4, 1.6, 0.01], "red", "wool", "A red and cream patterned wool rug in the middle of the lounge.")
o("plant", "living room", [4.6, 4.1, 0.55], [0.5, 0.5, 1.1], "green", "ceramic", "A tall monstera in a blue glazed pot.")
o("basket", "living room", [0.5, 4.1, 0.2], [0.5, 0.4, 0.4], "brown", "wicker", "A wicker log basket full of firewood.")
o("bookshelf", "living room", [2.5, 4.3, 0.9], [1.2, 0.3, 1.8], "white", "wood", "A white painted bookcase with paperbacks, jigsaw puzzles and board games for guests.")
# kitchen
o("table", "kitchen", [7.0, 2.5, 0.38], [1.8, 0.9, 0.75], "light brown", "oak", "A long scrubbed oak farmhouse dining table.")
o("chair", "kitchen", [6.5, 1.75, 0.45], [0.45, 0.45, 0.9], "blue", "wood", "A blue painted wooden ladder-back chair at the dining table.")
o("chair", "kitchen", [7.5, 1.75, 0.45], [0.45, 0.45, 0.9], "blue", "wood", "A blue painted wooden ladder-back chair at the dining table.")
o("chair", "kitchen", [6.5, 3.25, 0.45], [0.45, 0.45, 0.9], "yellow", "wood", "A mustard-yellow painted wooden chair, the odd one out at the dining table.")
o("chair", "kitchen", [7.5, 3.25, 0.45], [0.45, 0.45, 0.9], "blue", "wood", "A blue painted wooden ladder-back chair at the dining table.")
o("cabinet", "kitchen", [8.7, 1.2, 1.0], [0.5, 1.2, 2.0], "green", "wood", "A tall sage-green painted kitchen dresser with plates and mugs on its open shelves.")
o("stove", "kitchen", [5.6, 4.15, 0.45], [0.9, 0.6, 0.9], "cream", "enamel", "A cream enamel range cooker that also keeps the kitchen warm.")
o("kettle", "kitchen", [5.4, 4.15, 1.02], [0.25, 0.25, 0.25], "copper", "metal", "A copper whistling kettle sitting on the hob of the range cooker.")
o("sink", "kitchen", [7.3, 4.2, 0.85], [0.8, 0.5, 0.25], "white", "ceramic", "A deep white butler sink under the back window.")
o("refrigerator", "kitchen", [8.6, 4.15, 0.85], [0.6, 0.6, 1.7], "white", "metal", "A small white fridge with a freezer compartment.")
# porch
o("chair", "porch", [9.8, 1.0, 0.5], [0.6, 0.9, 1.0], "white", "wood", "A white wooden rocking chair looking out over the garden.")
o("bench", "porch", [11.6, 2.3, 0.45], [0.5, 1.6, 0.9], "gray", "teak", "A weathered teak garden bench with a striped seat cushion.")
o("plant", "porch", [9.4, 4.1, 0.3], [0.4, 0.4, 0.6], "purple", "terracotta", "A pot of lavender in a terracotta planter by the back door.")
o("boots", "porch", [9.3, 0.3, 0.15], [0.35, 0.3, 0.3], "green", "rubber", "A pair of green wellington boots by the porch step.")
o("telescope", "porch", [11.0, 0.5, 0.7], [0.3, 0.3, 1.4], "black", "metal", "A small black telescope on a tripod, for stargazing.")
# hallway
o("coat rack", "hallway", [0.4, 5.1, 0.9], [0.4, 0.4, 1.8], "brown", "wood", "A wooden coat stand by the front door with waterproof jackets on it.")
o("mirror", "hallway", [3.0, 4.55, 1.5], [0.6, 0.05, 0.8], "beige", "wood", "A round mirror with a driftwood frame on the hallway wall.")
# bedroom
o("bed", "bedroom", [2.2, 7.9, 0.3], [1.5, 2.0, 0.6], "white", "cotton", "A double bed with a handmade patchwork quilt.")
o("nightstand", "bedroom", [3.3, 8.7, 0.3], [0.45, 0.4, 0.6], "light brown", "pine", "A small pine bedside table with one drawer.")
o("lamp", "bedroom", [3.3, 8.7, 0.78], [0.25, 0.25, 0.35], "white", "ceramic", "A bedside lamp with a white ceramic base and a linen shade.")
o("wardrobe", "bedroom", [0.35, 6.3, 1.0], [0.6, 1.2, 2.0], "light brown", "pine", "A tall pine wardrobe with spare blankets on top.")
o("rug", "bedroom", [2.2, 6.3, 0.01], [1.4, 0.9, 0.01], "blue", "cotton", "A blue and white striped cotton rag rug at the foot of the bed.")
o("chair", "bedroom", [4.0, 6.0, 0.45], [0.6, 0.6, 0.9], "brown", "wicker", "A wicker chair in the corner with a folded wool blanket on it.")
# bathroom
o("bathtub", "bathroom", [5.75, 8.5, 0.3], [1.6, 0.75, 0.6], "white", "enamel", "A white claw-foot bathtub.")
o("toilet", "bathroom", [6.6, 6.0, 0.4], [0.4, 0.65, 0.8], "white", "ceramic")
o("sink", "bathroom", [4.75, 7.2, 0.85], [0.5, 0.4, 0.2], "white", "ceramic", "A small white pedestal washbasin.")
o("cabinet", "bathroom", [4.58, 7.2, 1.55], [0.15, 0.6, 0.7], "white", "wood", "A white wooden medicine cabinet with a mirrored door, on the wall above the washbasin.")
# study
o("desk", "study", [11.6, 7.2, 0.38], [0.7, 1.4, 0.75], "brown", "walnut", "An old walnut writing desk under the study window.")
o("chair", "study", [11.0, 7.2, 0.45], [0.5, 0.5, 0.9], "dark brown", "wood", "A wooden desk chair with a black leather seat.")
o("lamp", "study", [11.7, 7.7, 0.97], [0.2, 0.3, 0.45], "green", "glass", "A brass banker's lamp with a green glass shade on the writing desk.")
m = {"scene_id": "flat_f", "source": "hand-written synthetic holiday cottage (evals/blind/maps/flat_f.json), blind helper round 5",
     "comment": "12 m x 9 m cottage. x east, y north, z up, metres. Axis-aligned boxes: center [x, y, z], size [dx, dy, dz].",
     "rooms": rooms, "objects": O}
json.dump(m, open("/work/main/evals/blind/maps/flat_f.json", "w"), indent=1)
print(len(O))
for x in O: print(x["id"], x["label"], x["room"], x["tags"]["color"])
