"""Simulator ground truth of a frame directory (DIR/gt/), written by `iesm sim` and read only by
the simulator and the evaluation (`iesm eval-map --gt DIR`, `iesm eval --gt DIR`); maps never
point to it."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import IesmError
from ..fileio import atomic_write, read_json_model, write_text
from ..store.model import GridSpec, InstanceGrid


@dataclass
class GroundTruth:
    """Simulator ground truth in DIR/gt: `objects` (dicts in the `iesm import` object format plus
    "structural" and "on"), `rooms_list` (dicts id/label/polygon), top-down `grid`, `rooms` (H, W)
    int32 room id (-1 none), `occupancy` (H, W) bool, `cells` the 2.5D CSR map."""

    scene_id: str
    objects: list[dict]
    rooms_list: list[dict]
    grid: GridSpec
    rooms: np.ndarray
    occupancy: np.ndarray
    cells: InstanceGrid

    @classmethod
    def load(cls, directory: str | Path) -> "GroundTruth":
        gt = Path(directory) / "gt"
        if not gt.is_dir():
            raise IesmError("no ground truth (gt/ directory) in this frame directory", directory)
        objects_path = gt / "objects.json"
        if not objects_path.is_file():
            raise IesmError("file is missing", objects_path)
        try:
            data = json.loads(objects_path.read_text(encoding="utf-8"))
            scene_id, objects, rooms_list = str(data["scene_id"]), list(data["objects"]), list(data.get("rooms", []))
        except (OSError, ValueError, KeyError, TypeError) as exc:
            raise IesmError(f"not a readable object list ({exc})", objects_path) from None
        grid = read_json_model(gt / "grid.json", GridSpec)
        hw = (grid.height, grid.width)
        layers = {}
        for name in ("rooms", "occupancy"):
            path = gt / f"{name}.npy"
            try:
                layers[name] = np.load(path, allow_pickle=False)
            except (OSError, ValueError) as exc:
                raise IesmError(f"not a readable .npy ({exc})", path) from None
            if layers[name].shape != hw:
                raise IesmError(f"shape {layers[name].shape} differs from grid.json {hw}", path)
        cells_path = gt / "cells.npz"
        try:
            with np.load(cells_path, allow_pickle=False) as z:
                cells = InstanceGrid(cells=z["cells"], indptr=z["indptr"], ids=z["ids"], top=z["top"])
        except (OSError, ValueError, KeyError) as exc:
            raise IesmError(f"not a readable CSR map ({exc})", cells_path) from None
        return cls(scene_id, objects, rooms_list, grid, layers["rooms"].astype(np.int32),
                   layers["occupancy"].astype(bool), cells)  # type: ignore[arg-type]

    def save(self, directory: str | Path) -> None:
        """Write DIR/gt/{objects.json, grid.json, rooms.npy, occupancy.npy, cells.npz}."""
        gt = Path(directory) / "gt"
        gt.mkdir(parents=True, exist_ok=True)
        write_text(gt / "objects.json", json.dumps(
            {"scene_id": self.scene_id, "rooms": self.rooms_list, "objects": self.objects}, indent=1))
        write_text(gt / "grid.json", self.grid.model_dump_json(indent=1))
        atomic_write(gt / "rooms.npy", lambda p: np.save(p, self.rooms.astype(np.int32)))
        atomic_write(gt / "occupancy.npy", lambda p: np.save(p, self.occupancy.astype(bool)))
        c = self.cells
        atomic_write(gt / "cells.npz", lambda p: np.savez_compressed(
            p, cells=c.cells, indptr=c.indptr, ids=c.ids, top=c.top))
