"""`generate_scene`: a seeded apartment (floor plan, structure, furniture, camera trajectory)."""

from __future__ import annotations

import numpy as np

from .camera import default_intrinsics, trajectory
from .floorplan import grow_floor_plan
from .furnish import furnish_all
from .world import World, WorldBuilder, build_structure, fine_grid, room_raster


def generate_scene(seed: int, size: str = "small", open_plan: bool = False) -> World:
    """The same `seed`, `size` ("small": a ~60 m^2 flat; "hm3d": ~30 m x 30 m) and `open_plan`
    always give the same world, poses included."""
    rng = np.random.default_rng([seed, {"small": 0, "hm3d": 1}.get(size, 2), int(open_plan)])
    plan = grow_floor_plan(size, open_plan, rng)
    builder = WorldBuilder()
    keep_out = build_structure(plan, builder, rng)
    grid = fine_grid(plan)
    walls = np.array([box for box, i in zip(builder.boxes, builder.box_instance)
                      if builder.instances[i - 1].label == "wall"])
    rooms = room_raster(plan, grid, walls)
    furnish_all(builder, grid, rooms, plan.labels, keep_out, size, rng)
    world = World(scene_id=f"sim-{size}-{seed}{'-open' if open_plan else ''}", seed=seed, size=size,
                  open_plan=open_plan, plan=plan, instances=builder.instances, boxes=np.array(builder.boxes),
                  box_instance=np.array(builder.box_instance, np.int32), grid=grid, room_raster=rooms,
                  intrinsics=default_intrinsics())
    world.poses = trajectory(plan, grid, rooms, world.occupancy(), size, rng)
    return world
