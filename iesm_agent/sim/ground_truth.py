"""Simulator ground truth of a frame directory (DIR/gt/), written by `iesm sim` and read only by
the simulator and the evaluation (`iesm eval-map --gt DIR`, `iesm eval --gt DIR`); maps never
point to it."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from pydantic import ValidationError

from ..errors import IesmError
from ..fileio import atomic_write, load_json, read_json_model, read_npy, read_npz, validation_message, write_text
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
        data = load_json(objects_path)
        try:
            scene_id, objects, rooms_list = str(data["scene_id"]), list(data["objects"]), list(data.get("rooms", []))
        except (ValueError, KeyError, TypeError, AttributeError) as exc:
            raise IesmError(f"not a readable object list ({exc})", objects_path) from None
        grid = read_json_model(gt / "grid.json", GridSpec)
        hw = (grid.height, grid.width)
        layers = {}
        for name in ("rooms", "occupancy"):
            path = gt / f"{name}.npy"

            def check(shape: tuple[int, ...], _dtype, path: Path = path) -> None:  # before reading
                if shape != hw:
                    raise IesmError(f"shape {shape} differs from grid.json {hw}", path)

            try:
                with path.open("rb") as stream:
                    layers[name] = read_npy(stream, path, check=check)
            except OSError as exc:
                raise IesmError(f"not a readable .npy ({exc.strerror or exc})", path) from None
        cells_path = gt / "cells.npz"
        z = read_npz(cells_path, ("cells", "indptr", "ids", "top"))
        try:
            cells = InstanceGrid(cells=z["cells"], indptr=z["indptr"], ids=z["ids"], top=z["top"])
        except ValidationError as exc:
            raise IesmError(f"not a valid CSR map ({validation_message(exc)[0]})", cells_path) from None
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
