"""Colour constancy across keyframes: each frame's white balance brought to the scene's own.

A camera's auto white balance drifts from frame to frame, so one surface is recorded bluer in one
keyframe and warmer in the next. Per frame we estimate the illuminant's colour from the frame
itself (white patch: the mean sRGB of the pixels at or above the `WHITE_PATCH_PERCENTILE` of luma)
and correct each frame's chromaticity towards the scene's reference (the mean white-patch
chromaticity over the scene's keyframes), not towards neutral grey: a room's light and walls have
a colour of their own, which a grey-world or absolute white-patch balance would remove (both
lowered caption colour accuracy on the tuning seeds). Brightness is left alone: lighting, not the
camera, sets most of it, and the colour naming allows for shading (`colours.OBSERVED_SHADING`).
"""

from __future__ import annotations

import numpy as np

#: luma percentile above which a frame's pixels form its white patch; chosen on tuning seeds 0-4
#: (realistic profile, offline captions of built maps) from {80, 90, 95, 98, 99}
WHITE_PATCH_PERCENTILE = 80.0
#: Rec. 709 luma weights of sRGB values
LUMA = np.array([0.2126, 0.7152, 0.0722])


def white_patch(rgb: np.ndarray) -> np.ndarray:
    """(3,) mean sRGB (0-255) of the brightest pixels of an (H, W, 3) frame (uint8 or floats in
    0-255): those at or above the `WHITE_PATCH_PERCENTILE` of luma; zeros for an empty frame."""
    pixels = np.asarray(rgb, np.float64).reshape(-1, 3)
    if len(pixels) == 0:
        return np.zeros(3)
    luma = pixels @ LUMA
    return pixels[luma >= np.percentile(luma, WHITE_PATCH_PERCENTILE)].mean(axis=0)


def relative_gains(patches: dict[int, np.ndarray]) -> dict[int, np.ndarray]:
    """Frame -> (3,) per-channel factor (mean 1 over the channels of the frame's white patch) that
    brings the frame's white patch `patches[frame]` to the scene's mean white-patch chromaticity;
    all ones for a frame with a channel below 1 (black, or a channel missing)."""
    usable = {f: p / p.mean() for f, p in patches.items() if np.all(p >= 1.0)}
    gains = {f: np.ones(3) for f in patches}
    if usable:
        reference = np.mean(list(usable.values()), axis=0)
        gains.update({f: reference / chroma for f, chroma in usable.items()})
    return gains
