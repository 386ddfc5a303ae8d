"""Top-down PNG of a map: each occupied cell coloured by the category of its topmost instance,
room outlines with labels, multi-occupancy (stacked) cells hatched, and a category legend.
matplotlib (Agg) is imported lazily."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import IesmError
from ..fileio import pyplot, save_figure
from .model import SceneMap

MAX_LEGEND = 24  # categories beyond this (by cell count) are drawn as "other"


def _top_instance_per_cell(scene: SceneMap) -> tuple[np.ndarray, np.ndarray]:
    """(K,) occupied flat cells and (K,) id of the instance with the highest top in each."""
    occ = scene.occupancy
    cells, ids, top = occ.entries()
    order = np.lexsort((ids, -np.nan_to_num(top, nan=-np.inf), cells))
    first = np.ones(len(order), bool)
    first[1:] = cells[order][1:] != cells[order][:-1]
    return cells[order][first], ids[order][first]


def _check_grid(scene: SceneMap) -> None:
    if scene.grid.height == 0 or scene.grid.width == 0:
        raise IesmError("the map has an empty grid (imported without a PLY?): nothing to render", scene.scene_id)


def _extent(scene: SceneMap) -> tuple[float, float, float, float]:
    """(x0, x1, y0, y1) of the grid in metres, for imshow(origin="lower")."""
    g = scene.grid
    return (g.origin[0], g.origin[0] + g.width * g.cell_size, g.origin[1], g.origin[1] + g.height * g.cell_size)


def render_map(scene: SceneMap, path: str | Path, dpi: int = 150) -> None:
    """Write the top-down render of `scene` to `path` (PNG, written atomically)."""
    plt = pyplot("render")
    from matplotlib.patches import Patch

    _check_grid(scene)
    grid = scene.grid
    cells, top_ids = _top_instance_per_cell(scene)
    label_of = {inst.id: inst.label for inst in scene.instances}
    cell_labels = np.array([label_of[i] for i in top_ids.tolist()], dtype=object)
    names, counts = np.unique(cell_labels, return_counts=True) if len(cells) else (np.array([]), np.array([]))
    ranked = [str(n) for n in names[np.argsort(-counts, kind="stable")]]
    shown = ranked[:MAX_LEGEND]
    cmap = plt.get_cmap("tab20", 20)
    colours = {name: (cmap(i % 20) if i < 20 else plt.get_cmap("Set3")(i - 20)) for i, name in enumerate(shown)}
    other = (0.55, 0.55, 0.55, 1.0)
    image = np.ones((grid.height * grid.width, 4))
    if len(cells):
        image[cells] = np.array([colours.get(lab, other) for lab in cell_labels])
    image = image.reshape(grid.height, grid.width, 4)
    extent = _extent(scene)
    aspect = grid.height / grid.width
    fig, ax = plt.subplots(figsize=(10, max(4.0, 10 * aspect * 0.8)))
    ax.imshow(image, origin="lower", extent=extent, interpolation="nearest")
    xs = grid.origin[0] + (np.arange(grid.width) + 0.5) * grid.cell_size
    ys = grid.origin[1] + (np.arange(grid.height) + 0.5) * grid.cell_size
    counts_per_cell = np.zeros(grid.height * grid.width)
    counts_per_cell[scene.occupancy.cells] = np.diff(scene.occupancy.indptr)
    multi = (counts_per_cell > 1).reshape(grid.height, grid.width).astype(float)
    if multi.any():
        ax.contourf(xs, ys, multi, levels=[0.5, 1.5], colors="none", hatches=["xxxx"])
        ax.contour(xs, ys, multi, levels=[0.5], colors="black", linewidths=0.4)
    if scene.room_map is not None:
        for room in scene.rooms:
            mask = scene.room_map == room.id
            if not mask.any():
                continue
            ax.contour(xs, ys, mask.astype(float), levels=[0.5], colors="dimgray", linewidths=1.2,
                       linestyles="dashed")
            r, c = np.argwhere(mask).mean(0)
            ax.text(xs[int(round(c))], ys[int(round(r))], room.label, ha="center", va="center", fontsize=8,
                    color="black", bbox={"facecolor": "white", "alpha": 0.7, "edgecolor": "none", "pad": 1})
    handles = [Patch(facecolor=colours[n], label=n) for n in shown]
    if len(ranked) > len(shown):
        handles.append(Patch(facecolor=other, label=f"other ({len(ranked) - len(shown)})"))
    handles.append(Patch(facecolor="white", edgecolor="black", hatch="xxxx", label="stacked cells"))
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7, frameon=False)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"{scene.scene_id}: {len(scene.instances)} instances, "
                 f"{scene.occupancy.multi_occupancy_cells} stacked cells")
    save_figure(fig, path, dpi)


def render_rooms(scene: SceneMap, path: str | Path, dpi: int = 150) -> None:
    """Write the room map of `scene` to `path` (PNG): each room's cells in its own colour with its
    label and id, obstacles dark grey, cells outside every room white."""
    plt = pyplot("render")
    from matplotlib.patches import Patch

    _check_grid(scene)
    if scene.room_map is None or not scene.rooms:
        raise IesmError("the map has no rooms: run `iesm rooms` (or import rooms) first", scene.scene_id)
    grid = scene.grid
    cmap = plt.get_cmap("tab20", 20)
    image = np.ones((grid.height, grid.width, 4))
    if scene.obstacles is not None:
        image[scene.obstacles] = (0.3, 0.3, 0.3, 1.0)
    handles = []
    xs = grid.origin[0] + (np.arange(grid.width) + 0.5) * grid.cell_size
    ys = grid.origin[1] + (np.arange(grid.height) + 0.5) * grid.cell_size
    centres = []
    for k, room in enumerate(scene.rooms):
        mask = scene.room_map == room.id
        if not mask.any():
            continue
        colour = cmap(k % 20)
        image[mask & ~(scene.obstacles if scene.obstacles is not None else False)] = colour
        handles.append(Patch(facecolor=colour, label=f"{room.id}: {room.label}"))
        r, c = np.argwhere(mask).mean(0)
        centres.append((xs[int(round(c))], ys[int(round(r))], room.label))
    fig, ax = plt.subplots(figsize=(10, max(4.0, 8 * grid.height / grid.width)))
    ax.imshow(image, origin="lower", extent=_extent(scene), interpolation="nearest")
    for x, y, label in centres:
        ax.text(x, y, label, ha="center", va="center", fontsize=8,
                bbox={"facecolor": "white", "alpha": 0.7, "edgecolor": "none", "pad": 1})
    if scene.obstacles is not None:
        handles.append(Patch(facecolor=(0.3, 0.3, 0.3), label="obstacle"))
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7, frameon=False)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"{scene.scene_id}: {len(scene.rooms)} rooms")
    save_figure(fig, path, dpi)
