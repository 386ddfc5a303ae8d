"""The offline captioner: only what pixels and geometry can tell (no language model).

Colour: the lightness-robust median of the masked pixels of every keyframe crop
(`colours.masked_lab`) after bringing the keyframe to the scene's white balance
(`Crop.gain`, `colours.constancy`), the median over crops, named by the nearest XKCD colour under
CIEDE2000 allowing for room lighting (`colours.OBSERVED_SHADING`). Size and height class from the map: footprint area and the highest top.
"""

from __future__ import annotations

from typing import Optional

import numpy as np

from ..colours import OBSERVED_SHADING, colour_table, masked_lab, name_lab
from .schema import CaptionResult
from .views import InstanceView

#: footprint (m^2) below which an instance is "small" / above which it is "large"
SMALL_M2, LARGE_M2 = 0.09, 1.2
#: an instance is "tall" when its top is at least TALL_TOP_M and its mean height at most
#: TALL_MEAN_M (it rises from low down: a wardrobe, not a picture on a wall); "low" below LOW_TOP_M
TALL_TOP_M, TALL_MEAN_M, LOW_TOP_M = 1.6, 1.1, 0.5
#: pixels of a mask's rim are dropped (one erosion) when the mask has at least this many pixels
ERODE_MIN_PX = 100


def measured_colour(view: InstanceView) -> Optional[str]:
    """XKCD name of the instance's colour over its crops, None when no crop has pixels."""
    import cv2

    labs = []
    for crop in view.crops:
        mask = crop.mask
        if mask.sum() >= ERODE_MIN_PX:
            eroded = cv2.erode(mask.astype(np.uint8), np.ones((3, 3), np.uint8)).astype(bool)
            mask = eroded if eroded.any() else mask
        found = masked_lab(crop.balanced_rgb(), mask)
        if found is not None:
            labs.append(found[0])
    if not labs:
        return None
    return colour_table().names[int(name_lab(np.median(np.stack(labs), axis=0), OBSERVED_SHADING))]


def size_words(view: InstanceView) -> dict[str, str]:
    """{"size": "small"|"large", "height": "tall"|"low"} where the geometry says so."""
    g = view.geometry
    out = {}
    if 0 < g.footprint_m2 < SMALL_M2:
        out["size"] = "small"
    elif g.footprint_m2 > LARGE_M2:
        out["size"] = "large"
    if g.top_m is not None:
        if g.top_m >= TALL_TOP_M and (g.mean_height_m is None or g.mean_height_m <= TALL_MEAN_M):
            out["height"] = "tall"
        elif g.top_m < LOW_TOP_M:
            out["height"] = "low"
    return out


def _article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"


class OfflineCaptioner:
    """Captions from pixels and geometry; deterministic, no model calls."""

    name = "offline"

    def caption(self, view: InstanceView) -> CaptionResult:
        colour = measured_colour(view)
        words = size_words(view)
        label = view.instance.label
        noun = " ".join(w for w in (words.get("size"), words.get("height"), colour, label) if w)
        text = f"{_article(noun)} {noun}"
        if view.room:
            text += f" in the {view.room}"
        if view.geometry.top_m is not None:
            text += f", top at {view.geometry.top_m:.1f} m"
        tags = dict(words)
        if colour:
            tags["color"] = colour
        return CaptionResult(caption=text, tags=tags)

    async def acaption(self, view: InstanceView) -> CaptionResult:
        return self.caption(view)
