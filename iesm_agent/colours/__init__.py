"""Colours, in one place: sRGB -> CIELAB, colour names and colour families.

Pixels are converted to CIELAB (D65; L in 0-100; scikit-image's `skimage.color`), the object's colour is a
lightness-robust median (see `masked_lab`), and its name is the nearest entry of the shipped
XKCD colour-survey table (`colours.json`, CC0) under CIEDE2000 (`skimage.color`). The family of a colour
name ("reddish brown" -> brown) is the lexicon's canonical colour of its last colour word.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np

# LIGHTNESS_BAND was chosen on tuning seeds 0-4 (realistic profile, offline captions of built
# maps) from {(50, 90), (70, 95), (80, 98)}. OBSERVED_SHADING was chosen on tuning seeds 0-4 of both
# profiles with the keyframes brought to the scene's white balance (`constancy`, where the sweep is
# recorded), from (0.2, 1), (0.3, 2), (0.3, 4) (and on the realistic seeds alone from lowest
# {0.1, 0.2, 0.3, 0.5} x cost {1, 2, 3, 4, 6}): under room light a white surface is mostly seen
# dimmed (vertical faces, distance from the lamp), and white is far more common than light grey,
# so shading is charged little.
#: the pixels whose lightness lies between these percentiles set the colour (see `masked_lab`)
LIGHTNESS_BAND = (80.0, 98.0)
#: (lowest shading factor, CIEDE2000 units charged per unit of shading 1 - s) for a colour given
#: as a value (importers, ground truth): a little shading allowed, charged dearly
DECLARED_SHADING = (0.5, 8.0)
#: the same for a colour measured from pixels under room lighting (the offline captioner)
OBSERVED_SHADING = (0.2, 1.0)
#: shading factors per profile: this many, evenly from the lowest to 1
SHADING_STEPS = 11


@dataclass(frozen=True)
class ColourTable:
    """Named colours: `names` (N,), `families` (N,) lexicon colour families, `lab` (N, 3) float64."""

    names: tuple[str, ...]
    families: tuple[str, ...]
    lab: np.ndarray
    rgb: np.ndarray  # (N, 3) float64 sRGB 0-255


def _shade(rgb: np.ndarray, factor: float) -> np.ndarray:
    """sRGB (0-255) of colours `rgb` (N, 3) under `factor` of full light (scaled in linear RGB)."""
    c = np.asarray(rgb, np.float64) / 255.0
    linear = np.where(c > 0.04045, ((c + 0.055) / 1.055) ** 2.4, c / 12.92) * factor
    srgb = np.where(linear > 0.0031308, 1.055 * np.power(linear, 1 / 2.4) - 0.055, 12.92 * linear)
    return srgb * 255.0


def rgb_to_lab(rgb: np.ndarray) -> np.ndarray:
    """(..., 3) sRGB uint8 (or floats in 0-255) -> (..., 3) float64 CIELAB (D65, 2-degree
    observer; `skimage.color.rgb2lab`)."""
    from skimage.color import rgb2lab

    arr = np.asarray(rgb, np.float64)
    return rgb2lab(arr.reshape(-1, 1, 3) / 255.0).reshape(arr.shape)


@lru_cache(maxsize=1)
def colour_table() -> ColourTable:
    """The shipped colour table (read once)."""
    data = json.loads(resources.files(__package__).joinpath("colours.json").read_text("utf-8"))
    rows = data["colours"]
    rgb = np.array([[int(r["hex"][i:i + 2], 16) for i in (1, 3, 5)] for r in rows], np.float64)
    return ColourTable(tuple(r["name"] for r in rows), tuple(r["family"] for r in rows), rgb_to_lab(rgb), rgb)


@lru_cache(maxsize=4)
def _shaded_table(lowest: float) -> tuple[np.ndarray, np.ndarray]:
    """(shading factors (S,), Lab of every table colour under each (S, N, 3))."""
    factors = np.linspace(lowest, 1.0, SHADING_STEPS)
    return factors, np.stack([rgb_to_lab(_shade(colour_table().rgb, f)) for f in factors])


def ciede2000(lab1: np.ndarray, lab2: np.ndarray) -> np.ndarray:
    """CIEDE2000 colour difference (kL = kC = kH = 1) between broadcastable (..., 3) Lab arrays
    (`skimage.color.deltaE_ciede2000`)."""
    from skimage.color import deltaE_ciede2000

    lab1, lab2 = np.broadcast_arrays(np.asarray(lab1, np.float64), np.asarray(lab2, np.float64))
    return deltaE_ciede2000(lab1, lab2, channel_axis=-1)


def name_lab(lab: np.ndarray, shading: tuple[float, float] | None = DECLARED_SHADING) -> np.ndarray:
    """Indices into `colour_table()` of the best named colour for (..., 3) Lab.

    `shading` None: the nearest name under CIEDE2000. With `shading` = (lowest, cost), a surface
    is taken to show its colour dimmed by some factor s from `lowest` to 1 (pixels are never
    brighter than the surface under full light): a name's distance is min over s of
    CIEDE2000(pixel, name under s) + cost (1 - s), so white seen in shade is still white, while
    a grey that fits as it is stays grey (`DECLARED_SHADING`, `OBSERVED_SHADING`)."""
    table = colour_table()
    lab = np.asarray(lab, np.float64)
    if shading is None:
        return np.argmin(ciede2000(lab[..., None, :], table.lab), axis=-1)
    factors, shaded = _shaded_table(shading[0])
    d = ciede2000(lab[..., None, None, :], shaded) + shading[1] * (1 - factors)[:, None]
    return np.argmin(d.min(axis=-2), axis=-1)


def colour_name(rgb: np.ndarray | tuple[int, int, int] | list[int]) -> str:
    """Table name of one sRGB triple (0-255) given as a value (`DECLARED_SHADING`); ValueError
    outside that range."""
    values = np.asarray(rgb, np.float64)
    if values.shape != (3,) or not np.all((values >= 0) & (values <= 255)):
        raise ValueError(f"RGB components must be three numbers in 0-255, got {list(np.ravel(values))}")
    return colour_table().names[int(name_lab(rgb_to_lab(np.asarray(rgb, np.float64).reshape(3))))]


def masked_lab(rgb: np.ndarray, mask: np.ndarray) -> tuple[np.ndarray, int] | None:
    """Lightness-robust colour of the masked pixels: (Lab (3,), pixel count used), None if the
    mask is empty. `rgb` (H, W, 3) uint8, `mask` (H, W) bool.

    Shading scales a surface's colour (lightness and chroma) while its hue stays; a plain median
    mixes lit and shadowed faces. Under Lambert shading the lit faces are nearest the albedo, so
    we keep the pixels whose lightness lies in the `LIGHTNESS_BAND` percentiles (the brightest
    fifth without the top 2 %: highlights, bright background at the rim) and take the
    per-channel median of those."""
    if mask.shape != rgb.shape[:2]:
        raise ValueError(f"mask shape {mask.shape} differs from image shape {rgb.shape[:2]}")
    pixels = rgb[mask]
    if len(pixels) == 0:
        return None
    lab = rgb_to_lab(pixels)
    low, high = np.percentile(lab[:, 0], LIGHTNESS_BAND)
    keep = (lab[:, 0] >= low) & (lab[:, 0] <= high)
    chosen = lab[keep] if keep.any() else lab
    return np.median(chosen, axis=0), int(len(chosen))


def colour_family(name: str | None) -> str | None:
    """The lexicon's canonical colour of the last colour word in `name` ("reddish brown" ->
    "brown"), None when it names no colour."""
    if not name:
        return None
    from ..lexicon import load_lexicon

    lex = load_lexicon()
    spans = [s for s in lex.scan([lex.lemma(t) for t in lex.tokens(name)]) if s.has("color")]
    return spans[-1].values("color")[0] if spans else None
