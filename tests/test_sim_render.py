"""The box ray caster on hand-made scenes: depth and id at the centre pixel, back-projection onto
the box surface, floor depth, occlusion, the 10 m depth limit, and culling that changes nothing."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.frames import Intrinsics
from iesm_agent.sim import generate_scene
from iesm_agent.sim.camera import look_pose
from iesm_agent.sim.render import MAX_DEPTH, BoxRenderer

K = Intrinsics(width=65, height=49, fx=32.0, fy=32.0, cx=32.0, cy=24.0)  # centre pixel (24, 32) on the axis
BOX = np.array([[[3.0, -0.5, 0.5], [4.0, 0.5, 2.0]]])  # its near face at x = 3


def _back_project(depth: np.ndarray, pose: np.ndarray, k: Intrinsics) -> np.ndarray:
    v, u = np.mgrid[0:k.height, 0:k.width]
    cam = np.stack([(u - k.cx) / k.fx * depth, (v - k.cy) / k.fy * depth, depth], -1)
    return cam @ pose[:3, :3].T + pose[:3, 3]


def test_single_box_depth_id_and_back_projection():
    pose = look_pose((0.0, 0.0, 1.2), yaw=0.0, pitch_deg=0.0)
    frame = BoxRenderer(BOX, [[200, 30, 30]], [7], K, ceiling=2.6).render(pose)
    assert frame.instance_ids[24, 32] == 7
    assert frame.depth[24, 32] == pytest.approx(3.0, abs=1e-5)
    points = _back_project(frame.depth, pose, K)
    on_box = frame.instance_ids == 7
    assert on_box.sum() > 50
    assert np.allclose(points[on_box][:, 0], 3.0, atol=1e-4)  # all on the near face
    assert np.all((points[on_box][:, 1:] >= BOX[0, 0, 1:] - 1e-4) & (points[on_box][:, 1:] <= BOX[0, 1, 1:] + 1e-4))
    floor = (frame.instance_ids == 0) & (np.arange(K.height)[:, None] > K.cy) & (frame.depth > 0)
    assert floor.any() and np.allclose(points[floor][:, 2], 0.0, atol=1e-4)  # floor pixels land on z = 0
    ceiling = (frame.instance_ids == 0) & (np.arange(K.height)[:, None] < K.cy)
    assert np.allclose(points[ceiling & (frame.depth > 0)][:, 2], 2.6, atol=1e-4)
    assert tuple(frame.rgb[24, 32]) != (0, 0, 0) and frame.rgb[24, 32, 0] > frame.rgb[24, 32, 1]


def test_nearer_box_occludes_and_far_hits_have_no_depth():
    near = np.array([[[2.0, -0.1, 1.0], [2.2, 0.1, 1.4]]])
    far = np.array([[[MAX_DEPTH + 1, -3, 0], [MAX_DEPTH + 2, 3, 2.6]]])
    pose = look_pose((0.0, 0.0, 1.2), yaw=0.0, pitch_deg=0.0)
    frame = BoxRenderer(np.concatenate([BOX, near, far]), [[1, 1, 1]] * 3, [7, 8, 9], K, ceiling=2.6).render(pose)
    assert frame.instance_ids[24, 32] == 8 and frame.depth[24, 32] == pytest.approx(2.0, abs=1e-5)
    frame = BoxRenderer(far, [[1, 1, 1]], [9], K, ceiling=2.6).render(pose)
    assert frame.instance_ids[24, 32] == 9 and frame.depth[24, 32] == 0.0


def test_camera_turned_sees_the_box_at_the_same_depth_along_its_axis():
    pose = look_pose((3.5, -3.0, 1.2), yaw=np.pi / 2, pitch_deg=0.0)  # south of the box, facing +y
    frame = BoxRenderer(BOX, [[1, 1, 1]], [7], K, ceiling=2.6).render(pose)
    assert frame.instance_ids[24, 32] == 7 and frame.depth[24, 32] == pytest.approx(2.5, abs=1e-5)


def test_frustum_culling_and_screen_rectangles_change_nothing(monkeypatch):
    world = generate_scene(2, "small")
    renderer = BoxRenderer(world.boxes, world.box_rgb(), world.box_instance, world.intrinsics, ceiling=2.6)
    poses = world.poses[::9]
    fast = [renderer.render(p) for p in poses]
    full = np.tile([0, world.intrinsics.height, 0, world.intrinsics.width], (len(world.boxes), 1))
    monkeypatch.setattr(BoxRenderer, "_screen_rects", lambda self, rot, origin: full)
    for pose, got in zip(poses, fast):
        want = renderer.render(pose)
        assert np.array_equal(got.instance_ids, want.instance_ids)
        assert np.array_equal(got.depth, want.depth) and np.array_equal(got.rgb, want.rgb)


def test_same_pose_and_seed_render_identically():
    world = generate_scene(1, "small")
    renderer = BoxRenderer(world.boxes, world.box_rgb(), world.box_instance, world.intrinsics, ceiling=2.6)
    a = renderer.render(world.poses[3], np.random.default_rng(4))
    b = renderer.render(world.poses[3], np.random.default_rng(4))
    assert np.array_equal(a.rgb, b.rgb) and np.array_equal(a.depth, b.depth)
    assert len(np.unique(a.instance_ids)) > 3


def test_pixel_colours_name_the_ground_truth_colour():
    from iesm_agent.sim.catalog import COLORS

    world = generate_scene(0, "small")
    renderer = BoxRenderer(world.boxes, world.box_rgb(), world.box_instance, world.intrinsics, ceiling=2.6)
    names, palette = list(COLORS), np.array(list(COLORS.values()), float)
    pixels: dict[int, list[np.ndarray]] = {}
    rng = np.random.default_rng(0)
    for pose in world.poses[::3]:
        frame = renderer.render(pose, rng)
        for i in np.unique(frame.instance_ids[frame.instance_ids > 0]):
            pixels.setdefault(int(i), []).append(frame.rgb[frame.instance_ids == i])
    hits = [names[int(np.argmin(((palette - np.median(np.concatenate(p), 0)) ** 2).sum(1)))]
            == world.instances[i - 1].color for i, p in pixels.items()]
    assert len(hits) > 50 and np.mean(hits) >= 0.95
