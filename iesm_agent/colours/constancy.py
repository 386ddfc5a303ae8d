"""Colour constancy across keyframes: each frame's exposure and white balance brought to the
scene's own.

A camera's auto exposure and white balance drift from frame to frame, so one surface is recorded
brighter or bluer in one keyframe than in the next. Per frame we estimate the illuminant from the
frame itself (white patch: the mean sRGB of the pixels at or above the `WHITE_PATCH_PERCENTILE`
of luma, and that percentile as the exposure level) and correct each frame towards the scene's
reference (the mean white-patch chromaticity and the median level over the scene's keyframes),
not towards neutral grey: a room's light and walls have a colour of their own, which a grey-world
or absolute white patch would remove (both lowered caption colour accuracy on the tuning seeds).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: luma percentile of a frame taken as its white patch and exposure level (tuning seeds 0-4)
WHITE_PATCH_PERCENTILE = 95.0
#: Rec. 709 luma weights of sRGB values
LUMA = np.array([0.2126, 0.7152, 0.0722])


@dataclass(frozen=True)
class Illuminant:
    """One frame's estimate: `white` (3,) mean sRGB (0-255) of its brightest pixels, `level` the
    luma (0-255) at `WHITE_PATCH_PERCENTILE`."""

    white: np.ndarray
    level: float


def frame_illuminant(rgb: np.ndarray) -> Illuminant:
    """White patch and exposure level of an (H, W, 3) sRGB frame (uint8 or floats in 0-255)."""
    pixels = np.asarray(rgb, np.float64).reshape(-1, 3)
    luma = pixels @ LUMA
    level = float(np.percentile(luma, WHITE_PATCH_PERCENTILE)) if len(luma) else 0.0
    bright = pixels[luma >= level]
    return Illuminant(bright.mean(axis=0) if len(bright) else np.zeros(3), level)


def relative_gains(illuminants: dict[int, Illuminant]) -> dict[int, np.ndarray]:
    """Frame -> (3,) per-channel factor that brings that frame to the scene's reference exposure and
    white balance (all ones for a frame with no usable estimate: a black frame or a zero channel)."""
    usable = {f: i for f, i in illuminants.items() if i.level >= 1.0 and np.all(i.white >= 1.0)}
    gains = {f: np.ones(3) for f in illuminants}
    if not usable:
        return gains
    chroma = {f: i.white / i.white.mean() for f, i in usable.items()}
    reference_chroma = np.mean(list(chroma.values()), axis=0)
    reference_level = float(np.median([i.level for i in usable.values()]))
    for f, i in usable.items():
        gains[f] = (reference_level / i.level) * reference_chroma / chroma[f]
    return gains
