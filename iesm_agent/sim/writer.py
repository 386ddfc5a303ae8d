"""`render_frames`: render a world's trajectory, segment every frame and write the frame
directory (see frames.py) with ground truth in gt/."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Callable, Optional

import numpy as np

from ..fileio import write_png, write_text
from ..frames import Frame, SceneMeta, write_frame, write_frame_set
from .ground_truth import GroundTruth
from .catalog import CEILING_RGB, FLOOR_RGB, FURNITURE, SMALL
from .realism import Realism, get_profile
from .render import BoxRenderer
from .segmenter import FaultConfig, SyntheticSegmenter
from .world import WALL_HEIGHT, World

STRUCTURAL = ("wall", "door", "window")


def categories(config: FaultConfig) -> list[str]:
    """The open vocabulary written to scene.json: every label the simulator can place, plus
    structural labels and confusable labels."""
    labels = {s.label for specs in FURNITURE.values() for s in specs} | set(SMALL) | set(STRUCTURAL)
    labels |= {c for cs in config.confusables.values() for c in cs}
    return sorted(labels)


def ground_truth(world: World) -> GroundTruth:
    """Instances as an object list (iesm import format + "structural", "on"), rooms with
    polygons, and the fine rasters."""
    bounds = world.instance_bounds()
    objects = []
    for inst in world.instances:
        lo, hi = bounds[inst.id]
        objects.append({"id": inst.id, "label": inst.label, "center": np.round((lo + hi) / 2, 4).tolist(),
                        "size": np.round(hi - lo, 4).tolist(), "color_rgb": list(inst.rgb), "room": inst.room,
                        "tags": {"color": inst.color, "material": inst.material},
                        "structural": inst.structural, "on": inst.on})
    rooms = [{"id": rid, "label": label, "polygon": [list(p) for p in world.plan.polygon(rid)]}
             for rid, label in sorted(world.plan.labels.items())]
    return GroundTruth(world.scene_id, objects, rooms, world.grid, world.room_raster, world.occupancy(),
                       world.instance_grid())


def room_lights(world: World) -> np.ndarray:
    """(rooms, 3) one ceiling light per room, above the centroid of its cells."""
    lights = []
    for room in sorted(world.plan.labels):
        rows, cols = np.nonzero(world.room_raster == room)
        if len(rows):
            x, y = world.grid.center_of(int(np.median(rows)), int(np.median(cols)))
            lights.append((x, y, WALL_HEIGHT - 0.05))
    return np.array(lights, np.float64).reshape(-1, 3)


def render_frames(world: World, out_dir: str | Path, faults: Optional[FaultConfig] = None,
                  space: Optional[str] = None, progress: Optional[Callable[[int], None]] = None,
                  realism: str | Realism | None = None) -> dict:
    """Write world's frames (rgb, depth, pose, seg, inst) and gt/ into `out_dir`; `progress(i)`
    is called after frame i; `realism` the profile (sim/realism.py: "easy" | "realistic", default
    realistic). Under a profile with a depth sensor model, gt/depth/NNNNNN.png keeps the exact
    depth (mm) the ground truth's observed footprints use; gt/sim.json records the profile.
    Returns a summary: scene_id, rooms, instances, structural, stacked, frames, seen (instances
    covering at least `min_area_px` pixels in some frame), embedding_space, realism."""
    from .sensor import SensorModel

    faults = faults or FaultConfig(seed=world.seed)
    profile = get_profile(realism)
    out_dir = Path(out_dir)
    renderer = BoxRenderer(world.boxes, world.box_rgb(), world.box_instance, world.intrinsics, WALL_HEIGHT,
                           floor_rgb=FLOOR_RGB, ceiling_rgb=CEILING_RGB)
    sensor = None if profile.easy else SensorModel(
        renderer, world.box_instance, {i.id: i.material for i in world.instances}, room_lights(world), profile,
        world.seed)
    segmenter = SyntheticSegmenter({i.id: i.label for i in world.instances}, faults, space, profile,
                                   categories(faults))
    meta = SceneMeta(scene_id=world.scene_id, n_frames=len(world.poses), embedding_space=segmenter.space,
                     categories=categories(faults), cell_size=world.grid.cell_size)
    write_frame_set(out_dir, meta, world.intrinsics)
    best_view = np.zeros(len(world.instances) + 1, np.int64)
    if sensor is not None:
        (out_dir / "gt" / "depth").mkdir(parents=True, exist_ok=True)
    for index, pose in enumerate(world.poses):
        rng = np.random.default_rng([world.seed, 7, index])
        rendered = renderer.render(pose, rng if sensor is None else None)
        rgb, depth = (rendered.rgb, rendered.depth) if sensor is None else sensor.apply(rendered, pose, rng)
        frame = Frame(index, rgb, depth, pose, instance_ids=rendered.instance_ids)
        frame.segmentation = segmenter.segment(frame)
        write_frame(out_dir, frame)
        if sensor is not None:
            exact = np.rint(np.clip(rendered.depth, 0, 65.535) * 1000).astype(np.uint16)
            write_png(out_dir / "gt" / "depth" / f"{index:06d}.png", exact)
        counts = np.bincount(rendered.instance_ids.ravel(), minlength=len(best_view))
        np.maximum(best_view, counts, out=best_view)
        if progress:
            progress(index)
    ground_truth(world).save(out_dir)
    write_text(out_dir / "gt" / "sim.json", json.dumps({"realism": profile.model_dump(), "seed": world.seed,
                                                        "size": world.size, "open_plan": world.open_plan,
                                                        "faults": faults.model_dump()}, indent=1))
    return {"scene_id": world.scene_id, "rooms": len(world.plan.labels), "instances": len(world.instances),
            "structural": sum(i.structural for i in world.instances),
            "stacked": sum(i.on is not None for i in world.instances), "frames": len(world.poses),
            "seen": int(np.sum(best_view[1:] >= faults.min_area_px)), "embedding_space": segmenter.space,
            "realism": profile.name, "open_plan": [[world.plan.labels[a], world.plan.labels[b]] for a, b in world.plan.open_pairs]}
