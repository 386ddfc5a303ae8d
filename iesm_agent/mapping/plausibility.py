"""Label plausibility from an instance's measured geometry (issue 29; `MappingConfig.size_prior_temperature`).

A fused label names the category whose text embedding is most similar to the instance's mean
embedding (Z = F E^T, Sec. 3.1). That evidence ignores what the map measured: a 0.02 m^2 item whose
top is 1.1 m above the floor is not a coffee table however its masks look. With the prior on, each
category j scores

    s_j = cos(f, e_j) / T + max(log p(area | j) + log p(top | j), floor)

(T the temperature that turns cosine similarities into log-odds, `floor` the lowest the geometry can
push a category, so no category is ruled out by it alone). p(x | j) is flat inside the category's
range of real-world sizes (`SIZE_PRIORS`) and falls off as a Gaussian outside it: in log area with
scale `AREA_SOFTNESS` (a partly seen object measures smaller, a noisy one larger) and in top height
with scale `TOP_SOFTNESS` m. A category without a prior gets 0 (nothing against it).

The ranges are real-world sizes of the objects as they stand in a home, not the simulator's:
footprint = the object's plan-view area (m^2), top = the height of its highest point above the floor
(m), wide enough for the usual variety (a single to a king-size bed; an item on the floor, a table or
a high shelf). Sources: typical furniture and fitting dimensions as given by standard references
(Neufert, *Architects' Data*; EN 1116 kitchen worktops 0.85-0.95 m; EN 527-1 office desks about
0.72-0.76 m; DIN 18101 door leaves about 2.0 m high; ceilings 2.4-2.7 m), and the sizes of common
household items; `scripts/published_footprints.py` checks the footprint ranges against the IESM paper's
published maps (docs/results.md). Heights are measured above z = 0, the floor of the map's world frame.
"""

from __future__ import annotations

import numpy as np

#: category -> ((footprint min, max) m^2, (top height min, max) m above the floor)
SIZE_PRIORS: dict[str, tuple[tuple[float, float], tuple[float, float]]] = {
    "armchair": ((0.25, 1.2), (0.65, 1.15)),
    "basket": ((0.01, 0.3), (0.1, 2.0)),
    "bathroom sink": ((0.06, 0.5), (0.75, 1.0)),
    "bathtub": ((0.5, 2.0), (0.4, 0.7)),
    "bed": ((0.9, 4.5), (0.4, 1.2)),
    "bench": ((0.15, 1.0), (0.35, 0.9)),
    "book": ((0.002, 0.08), (0.1, 2.2)),
    "bookshelf": ((0.1, 0.8), (0.8, 2.3)),
    "bowl": ((0.005, 0.1), (0.3, 2.0)),
    "cabinet": ((0.08, 1.0), (0.4, 2.3)),
    "candle": ((0.0005, 0.02), (0.1, 2.0)),
    "chair": ((0.1, 0.5), (0.7, 1.1)),
    "clock": ((0.002, 0.05), (0.2, 2.5)),
    "coat rack": ((0.03, 0.4), (1.2, 2.0)),
    "coffee table": ((0.2, 1.2), (0.3, 0.55)),
    "console table": ((0.12, 0.9), (0.65, 0.95)),
    "cup": ((0.001, 0.02), (0.3, 2.0)),
    "desk": ((0.25, 1.8), (0.65, 1.0)),
    "dining table": ((0.4, 2.5), (0.65, 0.85)),
    "door": ((0.02, 0.5), (1.9, 2.2)),
    "dresser": ((0.18, 1.2), (0.7, 1.3)),
    "dryer": ((0.2, 0.5), (0.8, 1.9)),
    "filing cabinet": ((0.1, 0.6), (0.6, 1.4)),
    "floor lamp": ((0.02, 0.25), (1.3, 2.0)),
    "ironing board": ((0.05, 0.7), (0.7, 1.5)),
    "kettle": ((0.008, 0.06), (0.85, 1.4)),
    "keyboard": ((0.02, 0.12), (0.6, 1.0)),
    "kitchen counter": ((0.25, 3.5), (0.8, 1.0)),
    "laptop": ((0.03, 0.15), (0.4, 1.2)),
    "laundry basket": ((0.06, 0.4), (0.3, 0.75)),
    "microwave": ((0.06, 0.3), (0.9, 1.8)),
    "mirror": ((0.004, 0.15), (1.2, 2.2)),
    "monitor": ((0.03, 0.2), (1.0, 1.4)),
    "mug": ((0.002, 0.02), (0.3, 2.0)),
    "nightstand": ((0.06, 0.4), (0.45, 0.75)),
    "office chair": ((0.15, 0.7), (0.85, 1.3)),
    "picture": ((0.003, 0.08), (1.0, 2.3)),
    "pillow": ((0.04, 0.5), (0.4, 1.2)),
    "plate": ((0.01, 0.08), (0.4, 2.0)),
    "potted plant": ((0.01, 0.5), (0.2, 2.0)),
    "refrigerator": ((0.2, 1.0), (0.8, 2.0)),
    "remote control": ((0.003, 0.025), (0.3, 1.2)),
    "shelf": ((0.04, 0.8), (0.8, 2.3)),
    "shoe rack": ((0.08, 0.45), (0.3, 1.1)),
    "sideboard": ((0.25, 1.4), (0.65, 1.0)),
    "sink cabinet": ((0.12, 0.9), (0.75, 1.0)),
    "soap dispenser": ((0.001, 0.015), (0.8, 1.3)),
    "sofa": ((0.6, 3.5), (0.65, 1.05)),
    "stool": ((0.04, 0.25), (0.4, 0.85)),
    "storage box": ((0.03, 0.35), (0.15, 2.2)),
    "stove": ((0.15, 0.75), (0.8, 1.1)),
    "table lamp": ((0.02, 0.2), (0.8, 1.5)),
    "television": ((0.02, 0.4), (0.9, 1.8)),
    "toaster": ((0.02, 0.08), (0.95, 1.3)),
    "toilet": ((0.12, 0.4), (0.38, 1.0)),
    "toothbrush holder": ((0.001, 0.015), (0.8, 1.3)),
    "towel": ((0.008, 0.15), (0.5, 1.8)),
    "towel rack": ((0.015, 0.35), (0.7, 1.6)),
    "trash can": ((0.02, 0.2), (0.25, 0.8)),
    "tv stand": ((0.2, 1.3), (0.35, 0.7)),
    "umbrella stand": ((0.015, 0.1), (0.4, 0.7)),
    "vacuum cleaner": ((0.03, 0.2), (0.25, 1.2)),
    "vase": ((0.003, 0.1), (0.2, 2.0)),
    "wall": ((0.04, 3.0), (2.2, 3.0)),
    "wardrobe": ((0.2, 1.8), (1.7, 2.5)),
    "washing machine": ((0.2, 0.5), (0.8, 1.0)),
    "window": ((0.02, 0.5), (1.6, 2.6)),
}

AREA_SOFTNESS = float(np.log(2.0))  # a footprint twice the range's bound costs 0.5 nats
TOP_SOFTNESS = 0.1                  # m: a top 0.1 m outside the range costs 0.5 nats
TOP_PERCENTILE = 90                 # an instance's top: this percentile of its cells' top heights


def instance_top(tops: np.ndarray) -> float:
    """An instance's top height (m) from its cells' top heights (C,): their `TOP_PERCENTILE`th percentile."""
    return float(np.percentile(tops, TOP_PERCENTILE)) if len(tops) else 0.0


def _outside(x: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """How far each x lies outside [lo, hi] (0 inside), broadcast (N, 1) x (J,) -> (N, J)."""
    return np.maximum(0.0, np.maximum(lo - x, x - hi))


def size_log_likelihood(area: np.ndarray, top: np.ndarray, categories: list[str], floor: float) -> np.ndarray:
    """(N, J) log p(area, top | category) up to a constant, floored at `floor` (<= 0): `area` (N,) m^2
    footprints, `top` (N,) m top heights. A category without a prior in `SIZE_PRIORS` gets 0."""
    known = np.array([c in SIZE_PRIORS for c in categories], bool)
    ranges = np.array([SIZE_PRIORS.get(c, ((1.0, 1.0), (0.0, 0.0))) for c in categories], np.float64)  # (J, 2, 2)
    log_area = np.log(np.maximum(np.asarray(area, np.float64), 1e-6))[:, None]
    d_area = _outside(log_area, np.log(ranges[:, 0, 0]), np.log(ranges[:, 0, 1])) / AREA_SOFTNESS
    d_top = _outside(np.asarray(top, np.float64)[:, None], ranges[:, 1, 0], ranges[:, 1, 1]) / TOP_SOFTNESS
    ll = np.maximum(-0.5 * (d_area ** 2 + d_top ** 2), floor)
    return np.where(known[None, :], ll, 0.0)


def plausible_scores(cosines: np.ndarray, log_likelihood: np.ndarray, temperature: float) -> np.ndarray:
    """(N, J) label scores: the cosine similarities over `temperature` plus the geometry's log-likelihood."""
    return np.asarray(cosines, np.float64) / temperature + log_likelihood
