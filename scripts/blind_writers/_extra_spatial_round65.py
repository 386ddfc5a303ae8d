"""Extra spatial look-ups for doubtful wordings that use a broader word ("seat") than the kind."""
import math
from _common_round65 import load_objects

SEATS = {"chair", "armchair", "sofa", "bench", "stool", "office chair", "sofa bed"}
for name, anchor, label in [("maps/flat_f.json", 17, "g21 seat nearest the range cooker"),
                            ("apartment", 19, "g36 seat nearest the stove"),
                            ("maps/flat_h.json", 20, "g25 seat nearest the dining-room window")]:
    objs, _ = load_objects(name)
    a = objs[anchor]["center"]
    d = sorted((math.dist(o["center"][:2], a[:2]), i, o["label"], o["room"]) for i, o in objs.items()
               if o["label"] in SEATS)
    print(label + ":", ", ".join(f"{i} {lab} ({room}) {x:.2f}" for x, i, lab, room in d[:4]))
