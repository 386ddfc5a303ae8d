"""What the simulator furnishes rooms with: named colours, room programs, furniture and the small
objects that stand on it. Sizes are (width, depth, height) in metres before rotation; `depth` is
the extent away from the wall the item backs onto."""

from __future__ import annotations

from dataclasses import dataclass

# GT colour vocabulary: XKCD colour-survey names with the survey's canonical sRGB, well apart from
# each other so a colour read back from shaded pixels names the same colour.
COLORS: dict[str, tuple[int, int, int]] = {
    "red": (0xE5, 0x00, 0x00), "blue": (0x03, 0x43, 0xDF), "green": (0x15, 0xB0, 0x1A),
    "yellow": (0xFF, 0xFF, 0x14), "white": (0xFF, 0xFF, 0xFF), "black": (0x00, 0x00, 0x00),
    "grey": (0x92, 0x95, 0x91), "brown": (0x65, 0x37, 0x00), "beige": (0xE6, 0xDA, 0xA6),
    "orange": (0xF9, 0x73, 0x06), "pink": (0xFF, 0x81, 0xC0), "purple": (0x7E, 0x1E, 0x9C),
    "navy": (0x01, 0x15, 0x3E), "dark brown": (0x34, 0x1C, 0x02), "light blue": (0x95, 0xD0, 0xFC),
    "cream": (0xFF, 0xFF, 0xC2), "teal": (0x02, 0x93, 0x86), "dark green": (0x03, 0x35, 0x00),
    "light grey": (0xD8, 0xDC, 0xD6), "tan": (0xD1, 0xB2, 0x6F), "maroon": (0x65, 0x00, 0x21),
    "lavender": (0xC7, 0x9F, 0xEF), "light brown": (0xAD, 0x81, 0x50), "mustard": (0xCE, 0xB3, 0x01),
}
FLOOR_RGB = (0xA0, 0x78, 0x50)  # not an instance; a light wood floor
CEILING_RGB = (0xF2, 0xF2, 0xF0)

WOODS = ("brown", "dark brown", "light brown", "tan", "white", "black")
FABRICS = ("grey", "blue", "navy", "beige", "green", "red", "cream", "teal", "maroon", "mustard", "light grey")
BRIGHT = ("red", "blue", "green", "yellow", "white", "black", "orange", "pink", "purple", "teal", "lavender")


@dataclass(frozen=True)
class ItemSpec:
    """A furniture or object kind. `shape` picks the box builder (see furnish.SHAPES); `place` is
    wall | corner | middle | on (stands on a support) | hang (on the wall above the previous item)
    | beside (faces the previous item, e.g. chairs at a table) | flank (beside the previous item
    against the same wall, e.g. a nightstand); `holds` lists (kind, probability) of
    small items placed on it; `count` the (min, max) copies."""

    label: str
    size: tuple[float, float, float]
    shape: str = "block"
    place: str = "wall"
    colors: tuple[str, ...] = WOODS
    materials: tuple[str, ...] = ("wood",)
    holds: tuple[tuple[str, float], ...] = ()
    count: tuple[int, int] = (1, 1)
    prob: float = 1.0


def _s(label, size, **kw) -> ItemSpec:
    return ItemSpec(label, size, **kw)


SMALL: dict[str, ItemSpec] = {s.label: s for s in [
    _s("cup", (0.09, 0.09, 0.11), place="on", colors=BRIGHT, materials=("ceramic",)),
    _s("mug", (0.1, 0.1, 0.12), place="on", colors=BRIGHT, materials=("ceramic",)),
    _s("book", (0.22, 0.16, 0.05), place="on", colors=BRIGHT, materials=("paper",)),
    _s("vase", (0.14, 0.14, 0.3), place="on", colors=BRIGHT, materials=("glass", "ceramic")),
    _s("potted plant", (0.25, 0.25, 0.4), place="on", colors=("green", "dark green"), materials=("ceramic",)),
    _s("table lamp", (0.3, 0.3, 0.45), shape="lamp", place="on", colors=("white", "cream", "beige", "black"),
       materials=("fabric", "metal")),
    _s("laptop", (0.34, 0.24, 0.03), place="on", colors=("grey", "black", "light grey"),
       materials=("metal", "plastic")),
    _s("bowl", (0.2, 0.2, 0.08), place="on", colors=BRIGHT, materials=("ceramic", "glass")),
    _s("remote control", (0.05, 0.18, 0.025), place="on", colors=("black", "grey"), materials=("plastic",)),
    _s("clock", (0.22, 0.08, 0.22), place="on", colors=("white", "black", "red"), materials=("plastic", "metal")),
    _s("candle", (0.08, 0.08, 0.15), place="on", colors=("white", "cream", "red"), materials=("wax",)),
    _s("pillow", (0.5, 0.35, 0.14), place="on", colors=FABRICS, materials=("fabric", "cotton")),
    _s("plate", (0.26, 0.26, 0.03), place="on", colors=("white", "cream", "blue"), materials=("ceramic",)),
    _s("kettle", (0.22, 0.16, 0.25), place="on", colors=("white", "black", "red", "light grey"),
       materials=("metal", "plastic")),
    _s("toaster", (0.3, 0.18, 0.2), place="on", colors=("white", "black", "red", "light grey"), materials=("metal",)),
    _s("microwave", (0.5, 0.38, 0.3), place="on", colors=("white", "black", "light grey"), materials=("metal",)),
    _s("television", (1.1, 0.1, 0.65), place="on", colors=("black",), materials=("plastic",)),
    _s("monitor", (0.55, 0.12, 0.4), place="on", colors=("black", "grey"), materials=("plastic",)),
    _s("keyboard", (0.44, 0.15, 0.03), place="on", colors=("black", "white"), materials=("plastic",)),
    _s("soap dispenser", (0.08, 0.08, 0.18), place="on", colors=("white", "green", "pink"), materials=("plastic",)),
    _s("toothbrush holder", (0.08, 0.08, 0.12), place="on", colors=("white", "blue", "teal"),
       materials=("ceramic",)),
    _s("towel", (0.4, 0.3, 0.08), place="on", colors=("white", "blue", "pink", "beige"), materials=("cotton",)),
    _s("basket", (0.35, 0.28, 0.22), place="on", colors=("tan", "light brown", "white"), materials=("wicker",)),
    _s("storage box", (0.4, 0.3, 0.25), place="on", colors=("white", "grey", "beige", "blue"),
       materials=("plastic", "cardboard")),
    _s("dryer", (0.6, 0.6, 0.85), place="on", colors=("white", "light grey"), materials=("metal",)),
    _s("picture", (0.7, 0.04, 0.5), shape="panel", place="hang", colors=BRIGHT, materials=("canvas", "paper")),
    _s("mirror", (0.6, 0.03, 0.8), shape="panel", place="hang", colors=("light grey",), materials=("glass",)),
]}

# Small items that go on shelves / boards of open shelving.
SHELF_ITEMS = (("book", 0.9), ("book", 0.7), ("vase", 0.4), ("potted plant", 0.3), ("clock", 0.3),
               ("storage box", 0.4), ("basket", 0.3))

FURNITURE: dict[str, tuple[ItemSpec, ...]] = {
    "living room": (
        _s("sofa", (2.0, 0.9, 0.85), shape="sofa", colors=FABRICS, materials=("fabric", "leather"),
           holds=(("pillow", 0.8), ("pillow", 0.5))),
        _s("picture", (0.9, 0.04, 0.6), shape="panel", place="hang", colors=BRIGHT, materials=("canvas",)),
        _s("coffee table", (1.1, 0.6, 0.42), shape="table", place="middle",
           holds=(("cup", 0.7), ("book", 0.6), ("remote control", 0.6), ("vase", 0.4))),
        _s("tv stand", (1.4, 0.45, 0.5), holds=(("television", 1.0), ("potted plant", 0.3))),
        _s("armchair", (0.85, 0.85, 0.9), shape="sofa", place="corner", colors=FABRICS,
           materials=("fabric", "leather"), holds=(("pillow", 0.4),)),
        _s("bookshelf", (0.9, 0.35, 1.8), shape="shelf", holds=SHELF_ITEMS),
        _s("floor lamp", (0.35, 0.35, 1.6), shape="lamp", place="corner", colors=("white", "black", "cream"),
           materials=("metal", "fabric")),
        _s("potted plant", (0.45, 0.45, 1.0), place="corner", colors=("green", "dark green"),
           materials=("ceramic",), prob=0.7),
    ),
    "kitchen": (
        _s("kitchen counter", (2.0, 0.62, 0.9), colors=("white", "light grey", "black", "tan", "navy"),
           materials=("stone", "wood"), holds=(("kettle", 0.7), ("toaster", 0.6), ("microwave", 0.7),
                                               ("bowl", 0.5), ("plate", 0.4))),
        _s("refrigerator", (0.75, 0.7, 1.85), place="corner", colors=("white", "light grey", "black"),
           materials=("metal",), holds=(("basket", 0.3),)),
        _s("stove", (0.6, 0.62, 0.9), colors=("white", "black", "light grey"), materials=("metal",)),
        _s("sink cabinet", (0.9, 0.62, 0.9), colors=("white", "light grey", "tan"), materials=("wood",),
           holds=(("soap dispenser", 0.6),)),
        _s("dining table", (1.3, 0.85, 0.75), shape="table", place="middle",
           holds=(("bowl", 0.6), ("plate", 0.6), ("cup", 0.5), ("vase", 0.3))),
        _s("chair", (0.45, 0.5, 0.9), shape="chair", place="beside", count=(2, 4), materials=("wood", "plastic")),
        _s("trash can", (0.35, 0.35, 0.6), place="corner", colors=("grey", "white", "black"),
           materials=("metal", "plastic")),
    ),
    "dining room": (
        _s("dining table", (1.8, 0.95, 0.75), shape="table", place="middle",
           holds=(("vase", 0.6), ("plate", 0.6), ("plate", 0.4), ("candle", 0.4), ("bowl", 0.4))),
        _s("chair", (0.45, 0.5, 0.95), shape="chair", place="beside", count=(4, 6), materials=("wood",)),
        _s("sideboard", (1.6, 0.45, 0.85), holds=(("table lamp", 0.6), ("vase", 0.5), ("candle", 0.4))),
        _s("picture", (0.9, 0.04, 0.6), shape="panel", place="hang", colors=BRIGHT, materials=("canvas",)),
        _s("potted plant", (0.45, 0.45, 1.1), place="corner", colors=("green", "dark green"), materials=("ceramic",)),
    ),
    "bedroom": (
        _s("bed", (1.6, 2.05, 0.55), shape="bed", colors=FABRICS + ("white",), materials=("fabric", "cotton"),
           holds=(("pillow", 0.9), ("pillow", 0.7), ("book", 0.3))),
        _s("nightstand", (0.48, 0.4, 0.55), place="flank", holds=(("table lamp", 0.9), ("clock", 0.5), ("book", 0.4)),
           count=(1, 2)),
        _s("picture", (0.8, 0.04, 0.55), shape="panel", place="hang", colors=BRIGHT, materials=("canvas",)),
        _s("wardrobe", (1.2, 0.6, 2.0), holds=(("storage box", 0.5),)),
        _s("dresser", (1.0, 0.5, 0.85), holds=(("vase", 0.4), ("basket", 0.3), ("clock", 0.3)), prob=0.7),
        _s("mirror", (0.6, 0.03, 0.8), shape="panel", place="hang", colors=("light grey",), materials=("glass",),
           prob=0.5),
        _s("desk", (1.1, 0.6, 0.75), shape="table", holds=(("laptop", 0.6), ("mug", 0.5), ("table lamp", 0.4)),
           prob=0.5),
        _s("stool", (0.38, 0.38, 0.48), place="beside", colors=WOODS, materials=("wood",), prob=0.5),
        _s("laundry basket", (0.45, 0.35, 0.55), place="corner", colors=("white", "tan", "grey"),
           materials=("wicker", "plastic"), prob=0.6),
    ),
    "bathroom": (
        _s("toilet", (0.4, 0.68, 0.78), colors=("white",), materials=("porcelain",)),
        _s("bathroom sink", (0.7, 0.48, 0.85), colors=("white", "light grey"), materials=("porcelain", "wood"),
           holds=(("soap dispenser", 0.8), ("toothbrush holder", 0.7))),
        _s("mirror", (0.6, 0.03, 0.8), shape="panel", place="hang", colors=("light grey",), materials=("glass",)),
        _s("bathtub", (1.6, 0.75, 0.55), place="corner", colors=("white",), materials=("porcelain",),
           holds=(("towel", 0.4),)),
        _s("towel rack", (0.6, 0.25, 1.0), colors=("light grey", "white", "black"), materials=("metal",),
           holds=(("towel", 0.8),), prob=0.6),
        _s("trash can", (0.25, 0.25, 0.35), place="corner", colors=("white", "grey"), materials=("plastic",),
           prob=0.7),
    ),
    "hallway": (
        _s("shoe rack", (0.8, 0.32, 0.5), colors=WOODS, holds=(("basket", 0.4), ("potted plant", 0.3))),
        _s("coat rack", (0.45, 0.45, 1.75), shape="lamp", place="corner", colors=("black", "brown", "white"),
           materials=("metal", "wood")),
        _s("console table", (1.0, 0.35, 0.8), shape="table", holds=(("vase", 0.6), ("bowl", 0.5), ("clock", 0.3)),
           prob=0.8),
        _s("mirror", (0.6, 0.03, 0.9), shape="panel", place="hang", colors=("light grey",), materials=("glass",),
           prob=0.7),
        _s("umbrella stand", (0.28, 0.28, 0.55), place="corner", colors=("black", "grey", "red"),
           materials=("metal",), prob=0.6),
        _s("bench", (1.0, 0.38, 0.45), colors=WOODS, holds=(("pillow", 0.3),), prob=0.5),
    ),
    "office": (
        _s("desk", (1.4, 0.7, 0.75), shape="table",
           holds=(("monitor", 0.9), ("keyboard", 0.8), ("laptop", 0.4), ("mug", 0.6), ("table lamp", 0.5))),
        _s("office chair", (0.6, 0.6, 1.05), shape="chair", place="beside", colors=("black", "grey", "blue"),
           materials=("fabric", "plastic")),
        _s("bookshelf", (0.9, 0.35, 1.9), shape="shelf", holds=SHELF_ITEMS),
        _s("filing cabinet", (0.45, 0.6, 1.0), colors=("grey", "light grey", "black"), materials=("metal",),
           holds=(("potted plant", 0.4), ("storage box", 0.4))),
        _s("potted plant", (0.4, 0.4, 0.9), place="corner", colors=("green", "dark green"), materials=("ceramic",)),
        _s("picture", (0.7, 0.04, 0.5), shape="panel", place="hang", colors=BRIGHT, materials=("canvas",)),
    ),
    "laundry room": (
        _s("washing machine", (0.6, 0.6, 0.85), colors=("white", "light grey"), materials=("metal",),
           holds=(("dryer", 0.6),)),
        _s("shelf", (1.0, 0.35, 1.6), shape="shelf", colors=("white", "light grey"), materials=("metal", "wood"),
           holds=(("storage box", 0.7), ("basket", 0.5), ("towel", 0.5))),
        _s("laundry basket", (0.45, 0.35, 0.55), place="corner", colors=("white", "tan"), materials=("wicker",)),
        _s("ironing board", (1.2, 0.35, 0.85), shape="table", colors=("light blue", "white", "grey"),
           materials=("metal", "fabric"), prob=0.6),
    ),
    "storage room": (
        _s("shelf", (1.0, 0.4, 1.8), shape="shelf", colors=("light grey", "white", "brown"),
           materials=("metal", "wood"), holds=(("storage box", 0.8), ("storage box", 0.6), ("basket", 0.5))),
        _s("cabinet", (0.9, 0.5, 1.2), holds=(("storage box", 0.5),)),
        _s("vacuum cleaner", (0.3, 0.3, 1.1), place="corner", colors=("red", "purple", "grey"),
           materials=("plastic",)),
    ),
}

# Room programs: (room type, target area m^2). Public rooms first: they seed the plan.
PROGRAMS: dict[str, tuple[tuple[str, float], ...]] = {
    "small": (("living room", 20.0), ("kitchen", 11.0), ("hallway", 7.0), ("bedroom", 13.0),
              ("bathroom", 6.0)),
    "hm3d": (("living room", 70.0), ("kitchen", 40.0), ("dining room", 50.0), ("hallway", 60.0),
             ("hallway", 45.0), ("bedroom", 55.0), ("bedroom", 50.0), ("bedroom", 45.0), ("bedroom", 45.0),
             ("bathroom", 22.0), ("bathroom", 20.0), ("bathroom", 18.0), ("office", 45.0), ("office", 40.0),
             ("laundry room", 25.0), ("storage room", 25.0), ("living room", 60.0), ("bedroom", 50.0),
             ("dining room", 40.0), ("storage room", 20.0)),
}
FOOTPRINTS = {"small": (9.0, 7.0), "hm3d": (30.0, 30.0)}  # apartment outline (x, y) in metres
# How many copies of each room's furniture list an hm3d room gets (bigger rooms, more things).
FURNITURE_PASSES = {"small": 1, "hm3d": 1}
PUBLIC = ("living room", "hallway", "kitchen", "dining room")
OPEN_PLAN_PAIRS = (("kitchen", "living room"), ("hallway", "living room"), ("dining room", "living room"),
                   ("kitchen", "dining room"))
WALL_COLORS = ("white", "cream", "beige", "light grey")

