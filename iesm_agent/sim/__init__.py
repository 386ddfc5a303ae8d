"""Seeded procedural apartments with ground truth: floor plans grown room by room, furniture and
stacked small objects as boxes, a camera trajectory through every room, a vectorised RGB-D +
instance renderer and a synthetic segmenter with configurable faults.

`generate_scene(seed, size, open_plan) -> World`, then `render_frames(world, out_dir, realism=...)`
writes the frame directory described in iesm_agent/frames (realism profiles: sim/realism.py).
"""

from .realism import EASY, REALISTIC, Realism, get_profile
from .scene import generate_scene
from .segmenter import FaultConfig, SyntheticSegmenter
from .world import World
from .writer import render_frames

__all__ = ["EASY", "REALISTIC", "FaultConfig", "Realism", "SyntheticSegmenter", "World", "generate_scene",
           "get_profile", "render_frames"]
