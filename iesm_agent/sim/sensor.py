"""The realistic profile's image formation and depth sensor, applied to a `RenderedFrame`.

Colour: albedo (the named colour x a per-object factor x a per-box sinusoidal texture) lit by one
ceiling light per room (Lambert cosine x 1 / (1 + (d / falloff)^2), no shadows) plus ambient, then
auto exposure with a per-frame drift and white balance, then pixel noise. Depth: a structured-light sensor,
z + N(0, (k z^2)^2), no reading (0) outside [depth_min, depth_max], in a band along depth edges,
in blobs on dark and on shiny (metal, glass) surfaces and at grazing incidence.
"""

from __future__ import annotations

import numpy as np

from .realism import Realism
from .render import FACE_NORMALS, BoxRenderer, RenderedFrame

SHINY = ("metal", "glass")
BLOB_PX = 6  # side of the blocks dropout blobs are made of


def _luminance(rgb: np.ndarray) -> np.ndarray:
    return (rgb @ np.array([0.2126, 0.7152, 0.0722], np.float32)) / 255.0


def blob_field(shape: tuple[int, int], rng: np.random.Generator, block: int = BLOB_PX) -> np.ndarray:
    """(H, W) uniform [0, 1) values constant over `block` x `block` pixel blocks."""
    h, w = shape
    coarse = rng.random((h // block + 1, w // block + 1), dtype=np.float32)
    return np.repeat(np.repeat(coarse, block, 0), block, 1)[:h, :w]


class SensorModel:
    """Re-shades and corrupts frames of `renderer` (the world's `BoxRenderer`) under `profile`.
    `box_instance` (B,) instance id per box, `materials` instance id -> material, `lights` (L, 3)
    light positions (m); per-object albedo and texture are drawn once from `seed`."""

    def __init__(self, renderer: BoxRenderer, box_instance: np.ndarray, materials: dict[int, str],
                 lights: np.ndarray, profile: Realism, seed: int):
        rng = np.random.default_rng([seed, 11])
        self.r, self.p = renderer, profile
        n_boxes = len(box_instance)
        n_inst = int(max(materials, default=0)) + 1
        inst_factor = np.clip(1 + profile.albedo_jitter * rng.standard_normal(n_inst), 0.6, 1.4)
        factor = np.ones(n_boxes + 3, np.float32)
        factor[:n_boxes] = inst_factor[box_instance]
        self.albedo = (renderer.palette * factor[:, None]).astype(np.float32)
        self.albedo[n_boxes + 2] = 0.0
        self.freq = rng.uniform(0.5, 3.0, (n_boxes + 3, 3)).astype(np.float32)  # cycles per metre
        self.phase = rng.uniform(0, 2 * np.pi, n_boxes + 3).astype(np.float32)
        shiny = np.zeros(n_boxes + 3, bool)
        shiny[:n_boxes] = [materials.get(int(i), "") in SHINY for i in box_instance]
        self.shiny = shiny
        self.dark = _luminance(self.albedo) < profile.dark_level
        self.dark[n_boxes + 2] = False
        self.lights = np.asarray(lights, np.float32).reshape(-1, 3)

    def apply(self, frame: RenderedFrame, pose: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(rgb uint8, depth float32 m) of the frame as the profile's camera and sensor see it."""
        p, r = self.p, self.r
        rot, origin = pose[:3, :3].astype(np.float32), pose[:3, 3].astype(np.float32)
        dirs = (rot[:, 0][None, None] * r.x_over_z[None, :, None] + rot[:, 1][None, None] * r.y_over_z[:, None, None]
                + rot[:, 2][None, None])  # (H, W, 3), camera-z component 1
        t = frame.t
        seen = np.isfinite(t)
        t_safe = np.where(seen, t, 0.0).astype(np.float32)
        points = origin + dirs * t_safe[..., None]
        normals = FACE_NORMALS[frame.face].astype(np.float32)
        hit = frame.hit
        # lighting
        shade = np.full(t.shape, p.ambient, np.float32)
        for light in self.lights:
            to_light = light - points
            dist = np.linalg.norm(to_light, axis=-1) + 1e-6
            cos = np.maximum(np.einsum("hwc,hwc->hw", normals, to_light) / dist, 0.0)
            shade += p.light_strength * cos / (1.0 + (dist / p.light_falloff) ** 2)
        phase = np.einsum("hwc,hwc->hw", points, self.freq[hit]) * np.float32(2 * np.pi) + self.phase[hit]
        texture = 1.0 + p.texture_amp * np.sin(phase)
        rgb = self.albedo[hit] * (shade * texture)[..., None]
        # auto exposure: the 95th percentile of luminance to ~225, then per-frame drift
        bright = float(np.percentile(_luminance(rgb[seen]), 95)) * 255 if seen.any() else 225.0
        gain = np.float32(np.clip(225.0 / max(bright, 1.0), 0.5, 2.0) * np.exp(p.exposure_jitter * rng.standard_normal()))
        balance = (1.0 + p.white_balance_jitter * rng.standard_normal(3)).astype(np.float32)
        rgb = rgb * gain * balance
        rgb += rng.standard_normal(rgb.shape, dtype=np.float32) * np.float32(p.pixel_noise)
        rgb = np.clip(np.rint(rgb), 0, 255).astype(np.uint8)
        return rgb, self._depth(t_safe, seen, dirs, normals, hit, rng)

    def _depth(self, t: np.ndarray, seen: np.ndarray, dirs: np.ndarray, normals: np.ndarray, hit: np.ndarray,
               rng: np.random.Generator) -> np.ndarray:
        import cv2

        p = self.p
        z = t + rng.standard_normal(t.shape, dtype=np.float32) * np.float32(p.depth_sigma_z2) * t * t
        valid = seen & (t >= p.depth_min) & (t <= p.depth_max)
        # depth edges: a relative jump to a 4-neighbour
        jump = np.zeros(t.shape, bool)
        rel = np.abs(np.diff(t, axis=1)) > p.edge_jump * np.minimum(t[:, 1:], t[:, :-1]).clip(1e-3)
        jump[:, 1:] |= rel
        jump[:, :-1] |= rel
        rel = np.abs(np.diff(t, axis=0)) > p.edge_jump * np.minimum(t[1:], t[:-1]).clip(1e-3)
        jump[1:] |= rel
        jump[:-1] |= rel
        drop = jump & (rng.random(t.shape, dtype=np.float32) < p.edge_dropout)
        drop = cv2.dilate(drop.astype(np.uint8), np.ones((3, 3), np.uint8)).astype(bool)  # a band, as shadows
        blobs = blob_field(t.shape, rng)
        drop |= self.dark[hit] & (blobs < p.dark_dropout)
        drop |= self.shiny[hit] & (blob_field(t.shape, rng) < p.shiny_dropout)
        cos = np.abs(np.einsum("hwc,hwc->hw", normals, dirs)) / np.linalg.norm(dirs, axis=-1)
        drop |= cos < p.grazing_cos
        return np.where(valid & ~drop, z, 0.0).astype(np.float32)
