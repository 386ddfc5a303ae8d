"""Numeric check of every type-"s" group in round10 from the map centres and sizes.

Each check names the relation used in the wordings, computes it for the target and for every
competitor of the same label, and requires a clear margin. Reads only the map object lists.
    python3 /work/blind10/check_spatial.py
"""

from __future__ import annotations

import json
import math
from pathlib import Path

BLIND = Path(__file__).resolve().parent / "evals" / "blind"
MARGIN = 0.3  # metres


def load(map_string: str) -> dict[int, dict]:
    data = json.loads((BLIND / map_string).resolve().read_text())
    return {o["id"]: o for o in data["objects"]}


def box(o):
    (x, y, z), (dx, dy, dz) = o["center"], o["size"]
    return (x - dx / 2, x + dx / 2, y - dy / 2, y + dy / 2, z - dz / 2, z + dz / 2)


def xy_overlap(a, b) -> float:
    """Overlap area of the footprints of a and b."""
    A, B = box(a), box(b)
    ox = min(A[1], B[1]) - max(A[0], B[0])
    oy = min(A[3], B[3]) - max(A[2], B[2])
    return max(ox, 0) * max(oy, 0)


def dist_xy(a, b) -> float:
    return math.dist(a["center"][:2], b["center"][:2])


def gap(a, b) -> float:
    """Shortest horizontal distance between the two footprints (0 if they touch/overlap)."""
    A, B = box(a), box(b)
    dx = max(A[0] - B[1], B[0] - A[1], 0)
    dy = max(A[2] - B[3], B[2] - A[3], 0)
    return math.hypot(dx, dy)


def same(objs, label, room=None):
    return [o for o in objs.values() if o["label"] == label and (room is None or o["room"] == room)]


def resting_on(top, support) -> bool:
    """top's bottom within 5 cm of support's top and footprints overlapping."""
    return xy_overlap(top, support) > 0 and abs(box(top)[4] - box(support)[5]) < 0.05


def report(name, ok, detail):
    print(("OK  " if ok else "FAIL"), name, detail)
    return ok


def main() -> int:
    good = True

    # g14 flat_b: the armchair nearest the living-room window.
    m = load("maps/flat_b.json")
    win = m[13]
    d = sorted((dist_xy(o, win), o["id"]) for o in same(m, "armchair"))
    good &= report("g14 flat_b armchair nearest window 13 -> 2", d[0][1] == 2 and d[1][0] - d[0][0] > MARGIN, d)

    # g16 flat_c: the nightstand the alarm clock (29) rests on.
    m = load("maps/flat_c.json")
    hits = [o["id"] for o in same(m, "nightstand") if resting_on(m[29], o)]
    good &= report("g16 flat_c nightstand under alarm clock -> 27", hits == [27], hits)

    # g20 flat_d: the table in front of the sofa bed (sofa on the south wall faces north, +y).
    m = load("maps/flat_d.json")
    sofa = m[1]
    sb = box(sofa)
    rows = []
    for o in same(m, "table"):
        b = box(o)
        ahead = b[2] - sb[3]  # gap north of the sofa's front edge
        overlap_x = min(b[1], sb[1]) - max(b[0], sb[0])
        rows.append((o["id"], round(ahead, 2), round(overlap_x, 2)))
    front = [r for r in rows if r[1] >= -0.05 and r[2] > 0 and r[1] < 1.5]
    good &= report("g20 flat_d table in front of sofa bed -> 2", [r[0] for r in front] == [2], rows)

    # g24 flat_e: the mirror above the washbasin (sink 30).
    m = load("maps/flat_e.json")
    sink = m[30]
    rows = []
    for o in same(m, "mirror"):
        above = box(o)[4] - box(sink)[5]
        rows.append((o["id"], round(gap(o, sink), 2), round(above, 2)))
    hits = [r[0] for r in rows if r[1] < 0.3 and r[2] > 0]
    good &= report("g24 flat_e mirror above washbasin -> 29", hits == [29], rows)

    # g29 flat_g: facing the headboard (north, +y) from the foot of bed 31, the nightstand on the left (-x).
    m = load("maps/flat_g.json")
    bed = m[31]
    stands = same(m, "nightstand", "bedroom")
    facing = (0.0, 1.0)
    left = (-facing[1], facing[0])  # rotate +90 degrees
    foot = (bed["center"][0], box(bed)[2])
    head_north = all(o["center"][1] > bed["center"][1] for o in stands)  # nightstands at the north end
    side = sorted(((o["center"][0] - foot[0]) * left[0] + (o["center"][1] - foot[1]) * left[1], o["id"]) for o in stands)
    good &= report("g29 flat_g left nightstand facing headboard -> 32",
                   head_north and side[-1][1] == 32 and side[-1][0] > MARGIN and side[0][0] < -MARGIN, side)

    # g33 flat_h: the armchair nearest the (living-room) bookshelf 12.
    m = load("maps/flat_h.json")
    d = sorted((round(gap(o, m[12]), 2), o["id"]) for o in same(m, "armchair"))
    d2 = sorted((round(min(gap(o, s) for s in same(m, "bookshelf")), 2), o["id"]) for o in same(m, "armchair"))
    good &= report("g33 flat_h armchair nearest bookshelf -> 10",
                   d[0][1] == 10 and d[1][0] - d[0][0] > MARGIN and d2[0][1] == 10 and d2[1][0] - d2[0][0] > MARGIN,
                   (d, d2))

    # g40 flat_i: the monitor standing on the white desk 13.
    m = load("maps/flat_i.json")
    hits = [o["id"] for o in same(m, "monitor") if resting_on(o, m[13])]
    good &= report("g40 flat_i monitor on white desk -> 17", hits == [17], hits)

    # g43 apartment: the plant on top of the dresser 38.
    m = load("apartment")
    hits = [o["id"] for o in same(m, "plant") if resting_on(o, m[38])]
    good &= report("g43 apartment plant on dresser -> 39", hits == [39], hits)

    print("all spatial groups hold" if good else "SOME SPATIAL GROUPS FAIL")
    return 0 if good else 1


if __name__ == "__main__":
    raise SystemExit(main())
