"""RGB -> everyday colour name (nearest named colour in CIELAB), for captions and tags."""

from __future__ import annotations

import numpy as np

# Everyday names a person would use in a query, with a typical sRGB value each.
_PALETTE: dict[str, tuple[int, int, int]] = {
    "black": (20, 20, 20), "dark gray": (70, 70, 70), "gray": (128, 128, 128),
    "light gray": (190, 190, 190), "white": (245, 245, 245), "silver": (170, 172, 178),
    "red": (200, 30, 35), "dark red": (120, 20, 25), "pink": (240, 150, 170),
    "orange": (240, 130, 30), "yellow": (240, 215, 40), "beige": (220, 200, 160),
    "cream": (245, 235, 205), "brown": (130, 80, 40), "dark brown": (75, 45, 25),
    "tan": (195, 155, 105), "olive": (120, 120, 40), "green": (50, 150, 60),
    "dark green": (25, 80, 35), "teal": (30, 128, 128), "turquoise": (60, 200, 200),
    "light blue": (150, 190, 230), "blue": (40, 80, 190), "navy": (25, 35, 90),
    "purple": (120, 50, 150), "lavender": (190, 170, 225), "gold": (210, 170, 60),
}
_NAMES = list(_PALETTE)


def _to_lab(rgb: np.ndarray) -> np.ndarray:
    """(N, 3) sRGB in 0-255 -> (N, 3) CIELAB (D65)."""
    c = np.asarray(rgb, np.float64) / 255.0
    c = np.where(c > 0.04045, ((c + 0.055) / 1.055) ** 2.4, c / 12.92)
    xyz = c @ np.array([[0.4124, 0.2126, 0.0193], [0.3576, 0.7152, 0.1192], [0.1805, 0.0722, 0.9505]])
    xyz /= np.array([0.95047, 1.0, 1.08883])
    f = np.where(xyz > 0.008856, np.cbrt(xyz), 7.787 * xyz + 16 / 116)
    return np.stack([116 * f[:, 1] - 16, 500 * (f[:, 0] - f[:, 1]), 200 * (f[:, 1] - f[:, 2])], axis=1)


_PALETTE_LAB = _to_lab(np.array(list(_PALETTE.values())))


def color_name(rgb: tuple[int, int, int] | list[int]) -> str:
    """Nearest everyday colour name for an sRGB triple with components in 0-255."""
    values = np.asarray(rgb, np.float64).reshape(1, 3)
    if not np.all((values >= 0) & (values <= 255)):
        raise ValueError(f"RGB components must be in 0-255, got {list(rgb)}")
    d = np.linalg.norm(_PALETTE_LAB - _to_lab(values), axis=1)
    return _NAMES[int(np.argmin(d))]
