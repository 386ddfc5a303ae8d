"""Colour constancy across keyframes: each frame's white balance brought to the scene's own.

A camera's auto white balance drifts from frame to frame, so one surface is recorded bluer in one
keyframe and warmer in the next. Per frame we estimate the illuminant's colour from the frame
itself (white patch: the mean sRGB of the near-neutral pixels, saturation at most
`NEUTRAL_SATURATION`, among those at or above the `WHITE_PATCH_PERCENTILE` of luma: a cream wall or
a wooden floor filling the view would otherwise pass for a warm illuminant) and correct each frame's chromaticity towards the scene's reference (the mean white-patch
chromaticity over the scene's keyframes), not towards neutral grey: a room's light and walls have
a colour of their own, which a grey-world or absolute white-patch balance would remove (both
lowered caption colour accuracy on the tuning seeds). Brightness is left alone: lighting, not the
camera, sets most of it, and the colour naming allows for shading (`colours.OBSERVED_SHADING`).
"""

from __future__ import annotations

import numpy as np

# WHITE_PATCH_PERCENTILE and NEUTRAL_SATURATION (with `colours.OBSERVED_SHADING`) were chosen on
# tuning seeds 0-4 of both profiles (offline captions of built maps, colour family accuracy, mean
# of realistic and easy) from percentile {80, 95} x saturation {none, 0.1, 0.2, 0.3}: realistic
# 0.880, easy 0.996 (no neutral test: 0.884 / 0.927; no balance: 0.759 / 1.000).
#: luma percentile above which a frame's pixels may form its white patch
WHITE_PATCH_PERCENTILE = 95.0
#: largest saturation (max - min) / max of the sRGB channels of a white-patch pixel
NEUTRAL_SATURATION = 0.2
#: Rec. 709 luma weights of sRGB values
LUMA = np.array([0.2126, 0.7152, 0.0722])


def white_patch(rgb: np.ndarray) -> np.ndarray:
    """(3,) mean sRGB (0-255) of the bright near-neutral pixels of an (H, W, 3) frame (uint8 or
    floats in 0-255): at or above the `WHITE_PATCH_PERCENTILE` of luma, saturation at most
    `NEUTRAL_SATURATION`; zeros when there are none."""
    pixels = np.asarray(rgb, np.float64).reshape(-1, 3)
    if len(pixels) == 0:
        return np.zeros(3)
    luma = pixels @ LUMA
    high, low = pixels.max(axis=1), pixels.min(axis=1)
    chosen = (luma >= np.percentile(luma, WHITE_PATCH_PERCENTILE)) & (high - low <= NEUTRAL_SATURATION * high)
    return pixels[chosen].mean(axis=0) if chosen.any() else np.zeros(3)


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
