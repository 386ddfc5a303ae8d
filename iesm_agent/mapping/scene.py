"""Turn a final instance dictionary into a store `SceneMap`: ids 1..N, the CSR 2.5D map
(every instance in every cell it occupies, with its per-cell top height), categorisation,
frame lists sorted by mask area, and the `observations` array."""

from __future__ import annotations

import numpy as np

from ..config import MappingConfig
from ..store.model import GridSpec, Instance, InstanceGrid, SceneMap
from .association import unit_rows
from .categorize import category_scores, ranked_labels
from .cells import rowcol_of
from .dictionary import InstanceDictionary
from .plausibility import instance_top, plausible_scores, size_log_likelihood

MARGIN_CELLS = 5  # free cells around the occupied bounds


def grid_around(keys: np.ndarray, cell_size: float) -> GridSpec:
    """The smallest grid (plus `MARGIN_CELLS`) over global cell `keys`, aligned with the global cells."""
    if len(keys) == 0:
        return GridSpec(cell_size=cell_size, origin=(0.0, 0.0), height=0, width=0)
    rows, cols = rowcol_of(keys)
    r0, c0 = int(rows.min()) - MARGIN_CELLS, int(cols.min()) - MARGIN_CELLS
    return GridSpec.checked(None, "frames", cell_size=cell_size, origin=(c0 * cell_size, r0 * cell_size),
                            height=int(rows.max()) - r0 + 1 + MARGIN_CELLS, width=int(cols.max()) - c0 + 1 + MARGIN_CELLS)


def cells_of_keys(keys: np.ndarray, grid: GridSpec) -> np.ndarray:
    """Flat indices in `grid` of global cell `keys` built by `grid_around` with the same cell size."""
    rows, cols = rowcol_of(keys)
    r0 = round(grid.origin[1] / grid.cell_size)
    c0 = round(grid.origin[0] / grid.cell_size)
    return (rows - r0) * grid.width + (cols - c0)


def frames_by_area(observations: list[tuple[int, int, int, float]]) -> list[int]:
    """Distinct frame indices, largest mask area first (a frame's area = its largest mask)."""
    best: dict[int, int] = {}
    for frame, _mask, area, _score in observations:
        best[frame] = max(best.get(frame, 0), area)
    return sorted(best, key=lambda fr: (-best[fr], fr))


def label_scores(d: InstanceDictionary, categories: list[str], category_embeddings: np.ndarray,
                 cfg: MappingConfig) -> np.ndarray:
    """(N, J) scores the labels are ranked by: Z = F E^T (Sec. 3.1), or with `cfg.size_prior_temperature`
    the cosines weighed with the plausibility of each entry's footprint and top height
    (`mapping.plausibility`)."""
    if cfg.size_prior_temperature is None:
        return category_scores(d.embeddings, category_embeddings)
    z = category_scores(unit_rows(d.embeddings), unit_rows(category_embeddings))
    area = d.sizes * cfg.cell_size ** 2
    top = np.array([instance_top(t) for t in d.tops])
    return plausible_scores(z, size_log_likelihood(area, top, categories, cfg.size_prior_floor),
                            cfg.size_prior_temperature)


def to_scene_map(d: InstanceDictionary, categories: list[str], category_embeddings: np.ndarray, *,
                 cfg: MappingConfig, scene_id: str, embedding_space: str, meta: dict[str, str]) -> SceneMap:
    """The built `SceneMap` of dictionary `d` (entry i becomes instance id i + 1)."""
    cell_size = cfg.cell_size
    grid = grid_around(np.concatenate(d.keys) if len(d) else np.zeros(0, np.int64), cell_size)
    labels = ranked_labels(label_scores(d, categories, category_embeddings, cfg), categories) if len(d) else []
    instances, cells, ids, tops, obs_rows = [], [], [], [], []
    for i in range(len(d)):
        iid = i + 1
        flat = cells_of_keys(d.keys[i], grid)
        rows, cols = rowcol_of(d.keys[i])
        label, alt = labels[i]
        instances.append(Instance(
            id=iid, label=label, alt_labels=alt, mean_height=float(d.mean_heights[i]), weight=float(d.weights[i]),
            frames=frames_by_area(d.observations[i]),
            centroid=(float((cols.mean() + 0.5) * cell_size), float((rows.mean() + 0.5) * cell_size),
                      float(d.mean_heights[i])),
            footprint_cells=int(len(flat))))
        cells.append(flat)
        ids.append(np.full(len(flat), iid, np.int64))
        tops.append(d.tops[i])
        obs_rows += [(iid, *row) for row in d.observations[i]]
    occupancy = (InstanceGrid.from_entries(np.concatenate(cells), np.concatenate(ids), np.concatenate(tops))
                 if instances else InstanceGrid.empty())
    embeddings = unit_rows(d.embeddings).astype(np.float32) if len(d) else None
    observations = np.asarray(obs_rows, np.float64).reshape(-1, 5)
    return SceneMap(scene_id=scene_id, source="iesm build-map", grid=grid, instances=instances,
                    occupancy=occupancy, embeddings=embeddings,
                    embedding_model=embedding_space if len(d) else None, observations=observations, meta=meta)
