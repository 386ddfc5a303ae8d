"""A vectorised box ray caster: RGB, depth and instance ids for axis-aligned boxes plus a floor
and a ceiling plane.

Per frame: world ray directions for every pixel (camera-z component 1, so the hit parameter t is
depth along the optical axis), frustum culling of boxes, and for each remaining box a slab test
over the pixels of its projected screen rectangle only. Lambert shading with a high ambient term
keeps each surface within ~1.5 % of its named colour (the top face shows it exactly), so a
colour read back from the pixels names the ground-truth colour.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..frames import Intrinsics

NEAR = 0.05  # m
MAX_DEPTH = 10.0  # m; farther hits keep their colour and id but get depth 0 (no reading)
AMBIENT = 0.985  # shade of faces turned away from the light; the brightest face gets 1.0
LIGHT = np.array([0.3, 0.5, 0.81]) / np.linalg.norm([0.3, 0.5, 0.81])
# face index = 2 * axis + (1 if the ray travels towards +axis, i.e. it hits the face with normal -axis)
FACE_NORMALS = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)
FACE_SHADE = AMBIENT + (1 - AMBIENT) * np.maximum(FACE_NORMALS @ LIGHT, 0.0) / LIGHT.max()
_CORNERS = np.array([[i >> 0 & 1, i >> 1 & 1, i >> 2 & 1] for i in range(8)])
_EDGES = np.array([(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1])


@dataclass
class RenderedFrame:
    """rgb (H, W, 3) uint8; depth (H, W) float32 metres (0 = none); instance_ids (H, W) int32
    (0 = floor, ceiling or nothing); `hit` (H, W) palette row hit (box index, then floor, ceiling,
    nothing), `face` (H, W) face index (see FACE_NORMALS) and `t` (H, W) float32 depth before the
    range cut (inf = nothing): what `sensor.SensorModel` re-shades."""

    rgb: np.ndarray
    depth: np.ndarray
    instance_ids: np.ndarray
    hit: np.ndarray | None = None
    face: np.ndarray | None = None
    t: np.ndarray | None = None


class BoxRenderer:
    """Renders `boxes` (B, 2, 3) [lo, hi] with per-box `colors` (B, 3) sRGB 0-255 and instance
    ids `box_ids` (B,) under `intrinsics`; floor at z = 0 and ceiling at `ceiling` metres."""

    def __init__(self, boxes: np.ndarray, colors: np.ndarray, box_ids: np.ndarray, intrinsics: Intrinsics,
                 ceiling: float, floor_rgb=(160, 120, 80), ceiling_rgb=(242, 242, 240), noise: float = 2.0):
        self.boxes = np.asarray(boxes, np.float64)
        self.ids = np.asarray(box_ids, np.int32)
        # palette rows: boxes, then floor, ceiling, sky (nothing hit)
        self.palette = np.vstack([np.asarray(colors, np.float32).reshape(-1, 3),
                                  np.array([floor_rgb, ceiling_rgb, (0, 0, 0)], np.float32)])
        self.k = intrinsics
        self.ceiling = ceiling
        self.noise = noise
        # normalised image coordinates of pixel centres: column -> x / z, row -> y / z
        self.x_over_z = ((np.arange(intrinsics.width) - intrinsics.cx) / intrinsics.fx).astype(np.float32)
        self.y_over_z = ((np.arange(intrinsics.height) - intrinsics.cy) / intrinsics.fy).astype(np.float32)
        self.corners = self.boxes[:, 0][:, None, :] + _CORNERS[None] * (self.boxes[:, 1] - self.boxes[:, 0])[:, None]

    def _screen_rects(self, rot: np.ndarray, origin: np.ndarray) -> np.ndarray:
        """(B, 4) int [r0, r1, c0, c1) pixel rectangles bounding each box's projection, empty for
        boxes outside the view frustum; boxes crossing the near plane are clipped to it."""
        k = self.k
        cam = np.einsum("bcj,jk->bck", self.corners - origin, rot)  # (B, 8, 3) camera coordinates
        z = cam[..., 2]
        # clip the 12 box edges against the near plane: crossing points lie on z = NEAR
        za, zb = z[:, _EDGES[:, 0]], z[:, _EDGES[:, 1]]
        crosses = (za - NEAR) * (zb - NEAR) < 0
        t = np.where(crosses, (NEAR - za) / np.where(crosses, zb - za, 1.0), 0.0)
        pa, pb = cam[:, _EDGES[:, 0]], cam[:, _EDGES[:, 1]]
        cross_pts = pa + t[..., None] * (pb - pa)
        pts = np.concatenate([cam, cross_pts], axis=1)  # (B, 20, 3)
        valid = np.concatenate([z >= NEAR, crosses], axis=1)
        pz = np.maximum(pts[..., 2], NEAR)
        u = k.fx * pts[..., 0] / pz + k.cx
        v = k.fy * pts[..., 1] / pz + k.cy
        inf = np.inf
        c0 = np.floor(np.where(valid, u, inf).min(1)).clip(-1, k.width)
        c1 = np.ceil(np.where(valid, u, -inf).max(1)).clip(-1, k.width) + 1
        r0 = np.floor(np.where(valid, v, inf).min(1)).clip(-1, k.height)
        r1 = np.ceil(np.where(valid, v, -inf).max(1)).clip(-1, k.height) + 1
        far = z.min(1) > MAX_DEPTH * 1.8  # wholly beyond any depth we would keep (and then some)
        rect = np.stack([r0, r1, c0, c1], 1)
        rect[:, [0, 2]] = np.maximum(rect[:, [0, 2]], 0)
        rect[:, 1] = np.minimum(rect[:, 1], k.height)
        rect[:, 3] = np.minimum(rect[:, 3], k.width)
        empty = ~valid.any(1) | far | (rect[:, 1] <= rect[:, 0]) | (rect[:, 3] <= rect[:, 2])
        rect[empty] = 0
        return rect.astype(np.int64)

    def render(self, pose: np.ndarray, rng: np.random.Generator | None = None) -> RenderedFrame:
        """Render from camera-to-world `pose` (4, 4); `rng` adds per-pixel colour noise."""
        rot, origin = pose[:3, :3], pose[:3, 3]
        # world ray direction per pixel, one (H, W) float32 plane per axis; camera-z component 1
        dirs = [rot[j, 0] * self.x_over_z[None, :] + rot[j, 1] * self.y_over_z[:, None] + np.float32(rot[j, 2])
                for j in range(3)]
        inv = [1.0 / np.where(np.abs(d) < 1e-9, np.float32(1e-9), d) for d in dirs]
        h, w = dirs[0].shape
        n_boxes = len(self.boxes)
        dz = dirs[2]
        with np.errstate(divide="ignore"):
            t_floor = np.where(dz < 0, -origin[2] / dz, np.inf).astype(np.float32)
            t_ceil = np.where(dz > 0, (self.ceiling - origin[2]) / dz, np.inf).astype(np.float32)
        zbuf = np.minimum(t_floor, t_ceil)
        hit = np.where(t_floor <= t_ceil, n_boxes, n_boxes + 1)
        hit[~np.isfinite(zbuf)] = n_boxes + 2
        face = np.where(t_floor <= t_ceil, 4, 5)
        rects = self._screen_rects(rot, origin)
        lo = (self.boxes[:, 0] - origin).astype(np.float32)
        hi = (self.boxes[:, 1] - origin).astype(np.float32)
        for b in np.flatnonzero((rects[:, 1] > rects[:, 0]) & (rects[:, 3] > rects[:, 2])):
            r0, r1, c0, c1 = rects[b]
            near, far = [], []
            for j in range(3):
                inv_j = inv[j][r0:r1, c0:c1]
                ta, tb = lo[b, j] * inv_j, hi[b, j] * inv_j
                near.append(np.minimum(ta, tb))
                far.append(np.maximum(ta, tb))
            t_near = np.maximum(np.maximum(near[0], near[1]), near[2])
            t_far = np.minimum(np.minimum(far[0], far[1]), far[2])
            zsub = zbuf[r0:r1, c0:c1]
            closer = (t_far >= t_near) & (t_near > NEAR) & (t_near < zsub)
            if not closer.any():
                continue
            zsub[closer] = t_near[closer]
            hit[r0:r1, c0:c1][closer] = b
            nx, ny, nz = (n[closer] for n in near)
            axis = np.where((nx >= ny) & (nx >= nz), 0, np.where(ny >= nz, 1, 2))
            towards_plus = np.choose(axis, [inv[j][r0:r1, c0:c1][closer] > 0 for j in range(3)])
            face[r0:r1, c0:c1][closer] = 2 * axis + towards_plus
        shade = FACE_SHADE[face].astype(np.float32)
        rgb = self.palette[hit] * shade[..., None]
        if rng is not None and self.noise > 0:
            rgb += rng.standard_normal(rgb.shape, dtype=np.float32) * np.float32(self.noise)
        depth = np.where(zbuf <= MAX_DEPTH, zbuf, 0.0).astype(np.float32)
        ids = np.zeros((h, w), np.int32)
        on_box = hit < n_boxes
        ids[on_box] = self.ids[hit[on_box]]
        return RenderedFrame(np.clip(np.rint(rgb), 0, 255).astype(np.uint8), depth, ids, hit, face, zbuf)
