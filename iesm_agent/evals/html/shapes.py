"""A map as vector shapes for the HTML pages: each instance's footprint, each room and the
stacked (multi-occupancy) cells traced into outline paths, and one SVG drawing of them.

SVG user units are grid cells of a possibly coarsened grid (`MAX_SIDE` cells a side at most, so
a page's map is bounded whatever the map's resolution), x = column and y = rows from the top
edge, so world y points up as in `iesm render`. `to_svg(layers, x, y)` converts metres.
"""

from __future__ import annotations

import math
from html import escape

import numpy as np

from ...store.model import SceneMap

#: the longest side of the drawn grid (cells); finer maps are coarsened (a block is occupied
#: when any of its cells is)
MAX_SIDE = 400

#: matplotlib's tab20, the palette of `iesm render`: the 20 most frequent categories
PALETTE = ["#1f77b4", "#aec7e8", "#ff7f0e", "#ffbb78", "#2ca02c", "#98df8a", "#d62728", "#ff9896",
           "#9467bd", "#c5b0d5", "#8c564b", "#c49c94", "#e377c2", "#f7b6d2", "#7f7f7f", "#c7c7c7",
           "#bcbd22", "#dbdb8d", "#17becf", "#9edae5"]
OTHER = "#8c8c8c"


def outline_path(mask: np.ndarray, offset: tuple[int, int] = (0, 0), height: int | None = None) -> str:
    """SVG path data of the boundary of the True cells of `mask` (rows, cols): closed rectilinear
    loops through cell corners (holes run the other way round, so the nonzero rule keeps them
    empty), collinear corners dropped. `offset` (row, col) places the mask in a grid of `height`
    rows (default the mask's), whose row 0 is drawn at the bottom."""
    mask = np.asarray(mask, bool)
    rows, cols = mask.shape
    height = rows if height is None else height
    pad = np.pad(mask, 1)
    edges: dict[tuple[int, int], list[tuple[int, int]]] = {}
    # horizontal edges on corner row r between cells (r-1, c) and (r, c)
    below, above = pad[1:, 1:-1], pad[:-1, 1:-1]
    for r, c in np.argwhere(below & ~above).tolist():
        edges.setdefault((r, c), []).append((r, c + 1))
    for r, c in np.argwhere(above & ~below).tolist():
        edges.setdefault((r, c + 1), []).append((r, c))
    # vertical edges on corner column c between cells (r, c-1) and (r, c)
    right, left = pad[1:-1, 1:], pad[1:-1, :-1]
    for r, c in np.argwhere(right & ~left).tolist():
        edges.setdefault((r + 1, c), []).append((r, c))
    for r, c in np.argwhere(left & ~right).tolist():
        edges.setdefault((r, c), []).append((r + 1, c))
    parts = []
    r0, c0 = offset
    while edges:
        start = next(iter(edges))
        loop, here = [start], start
        while True:
            ends = edges[here]
            nxt = ends.pop()
            if not ends:
                del edges[here]
            if nxt == start:
                break
            loop.append(nxt)
            here = nxt
        corners = [p for i, p in enumerate(loop) if _turns(loop[i - 1], p, loop[(i + 1) % len(loop)])]
        parts.append(_loop_data(corners, r0, c0, height))
    return "".join(parts)


def _turns(a, b, c) -> bool:
    return (b[0] - a[0], b[1] - a[1]) != (c[0] - b[0], c[1] - b[1])


def _loop_data(corners: list[tuple[int, int]], r0: int, c0: int, height: int) -> str:
    r, c = corners[0]
    out = [f"M{c + c0} {height - (r + r0)}"]
    for (pr, pc), (r, c) in zip(corners, corners[1:]):
        out.append(f"H{c + c0}" if r == pr else f"V{height - (r + r0)}")
    return "".join(out) + "Z"


def _coarsen(cells: np.ndarray, width: int, factor: int) -> tuple[np.ndarray, np.ndarray]:
    row, col = np.divmod(cells, width)
    return row // factor, col // factor


def category_colours(scene: SceneMap) -> dict[str, str]:
    """Category label -> colour: tab20 for the 20 categories with most cells (as `iesm render`),
    grey beyond."""
    flat, ids, _ = scene.occupancy.entries()
    label_of = {inst.id: inst.label for inst in scene.instances}
    counts: dict[str, int] = {}
    for iid, n in zip(*np.unique(ids, return_counts=True)):
        counts[label_of[int(iid)]] = counts.get(label_of[int(iid)], 0) + int(n)
    for inst in scene.instances:
        counts.setdefault(inst.label, 0)
    ranked = sorted(counts, key=lambda lab: (-counts[lab], lab))
    return {lab: PALETTE[i] if i < len(PALETTE) else OTHER for i, lab in enumerate(ranked)}


def map_layers(scene: SceneMap) -> dict:
    """The drawable map: grid facts, instances (id, label, room, caption, tags, colour, outline,
    label anchor) drawn lowest first, rooms (outline, anchor) and the stacked cells' outline."""
    grid = scene.grid
    factor = max(1, math.ceil(max(grid.height, grid.width) / MAX_SIDE))
    height, width = math.ceil(grid.height / factor), math.ceil(grid.width / factor)
    flat, ids, top = scene.occupancy.entries()
    rows, cols = _coarsen(flat, grid.width, factor)
    colours = category_colours(scene)
    order = np.argsort(ids, kind="stable")
    ids_sorted = ids[order]
    starts = np.searchsorted(ids_sorted, [inst.id for inst in scene.instances], side="left")
    stops = np.searchsorted(ids_sorted, [inst.id for inst in scene.instances], side="right")
    instances = []
    for inst, lo, hi in zip(scene.instances, starts, stops):
        sel = order[lo:hi]
        entry = {"id": inst.id, "label": inst.label, "room": inst.room_label, "caption": inst.caption,
                 "tags": inst.tags, "colour": colours[inst.label], "d": "", "at": None,
                 "top": float(np.nanmax(top[sel])) if len(sel) and not np.all(np.isnan(top[sel])) else 0.0}
        if len(sel):
            r, c = rows[sel], cols[sel]
            local = np.zeros((r.max() - r.min() + 1, c.max() - c.min() + 1), bool)
            local[r - r.min(), c - c.min()] = True
            entry["d"] = outline_path(local, (int(r.min()), int(c.min())), height)
            entry["at"] = [round(float(c.mean()) + 0.5, 1), round(height - float(r.mean()) - 0.5, 1)]
        instances.append(entry)
    instances.sort(key=lambda e: e["top"])  # the top-most drawn last, as seen from above
    counts = np.zeros(height * width, np.int32)
    np.add.at(counts, rows * width + cols, 1)
    cell_counts = np.zeros(grid.height * grid.width, np.int32)
    cell_counts[scene.occupancy.cells] = np.diff(scene.occupancy.indptr)
    stacked_cells = np.flatnonzero(cell_counts > 1)
    stacked = np.zeros((height, width), bool)
    sr, sc = _coarsen(stacked_cells, grid.width, factor)
    stacked[sr, sc] = True
    rooms = []
    if scene.room_map is not None:
        for room in scene.rooms:
            r, c = np.nonzero(scene.room_map == room.id)
            if not len(r):
                continue
            mask = np.zeros((height, width), bool)
            mask[r // factor, c // factor] = True
            rooms.append({"id": room.id, "label": room.label, "d": outline_path(mask),
                          "at": [round(float(c.mean()) / factor + 0.5, 1),
                                 round(height - float(r.mean()) / factor - 0.5, 1)]})
    return {"scene": scene.scene_id, "width": width, "height": height, "cell": grid.cell_size * factor,
            "origin": list(grid.origin), "coarsened": factor, "instances": instances, "rooms": rooms,
            "stacked": outline_path(stacked), "stacked_cells": int(len(stacked_cells)),
            "legend": [{"label": lab, "colour": col} for lab, col in colours.items()]}


def to_svg(layers: dict, x: float, y: float) -> tuple[float, float]:
    """World (x, y) in metres -> SVG user units of `layers`."""
    ox, oy = layers["origin"]
    return (x - ox) / layers["cell"], layers["height"] - (y - oy) / layers["cell"]


def svg_markup(layers: dict, title: str, css_class: str = "map") -> str:
    """One inline SVG of `layers`: rooms outlined, instances filled by category (each a focusable
    path with its id, label and a tooltip title), stacked cells hatched, room labels. Every text
    is escaped."""
    w, h = layers["width"], layers["height"]
    out = [f'<svg class="{css_class}" viewBox="-1 -1 {w + 2} {h + 2}" role="img" '
           f'aria-label="{escape(title)}" preserveAspectRatio="xMidYMid meet">',
           '<defs><pattern id="hatch" width="4" height="4" patternUnits="userSpaceOnUse" '
           'patternTransform="rotate(45)"><line x1="0" y1="0" x2="0" y2="4" class="hatch-line"/></pattern></defs>',
           f'<rect x="0" y="0" width="{w}" height="{h}" class="floor"/>']
    out += [f'<path class="room" d="{r["d"]}"><title>room: {escape(r["label"])}</title></path>'
            for r in layers["rooms"]]
    for inst in layers["instances"]:
        if not inst["d"]:
            continue
        tip = f'#{inst["id"]} {inst["label"]}' + (f' ({inst["room"]})' if inst["room"] else "")
        out.append(f'<path class="inst" data-id="{inst["id"]}" d="{inst["d"]}" fill="{inst["colour"]}" '
                   f'tabindex="-1"><title>{escape(tip)}</title></path>')
    if layers["stacked"]:
        out.append(f'<path class="stacked" d="{layers["stacked"]}"><title>stacked cells</title></path>')
    size = max(4.0, min(w, h) / 40)
    out += [f'<text class="room-label" x="{r["at"][0]}" y="{r["at"][1]}" font-size="{size:.1f}">'
            f'{escape(r["label"])}</text>' for r in layers["rooms"]]
    out.append('<g class="overlay"></g></svg>')
    return "".join(out)
