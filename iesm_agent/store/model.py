"""The map model: instances, rooms, the grid spec and the 2.5D layers.

Coordinates: world x, y, z in metres, z up. Grid cell (row, col) covers
x in [origin_x + col * cell_size, origin_x + (col + 1) * cell_size) and
y in [origin_y + row * cell_size, origin_y + (row + 1) * cell_size).
Flat cell index = row * width + col.
"""

from __future__ import annotations

from typing import Annotated, Any, Optional

import numpy as np
from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, ValidationError, model_validator

from ..errors import MapFormatError
from ..fileio import validation_message

SCHEMA_VERSION = 1
#: largest grid a map may have (cells); 5000 x 5000 is 125 m square at 2.5 cm
MAX_GRID_CELLS = 25_000_000
#: largest coordinate (m) accepted anywhere in a map or a map's input
MAX_COORD = 1e6
#: ids fit a signed 32-bit integer
MAX_ID = 2**31 - 1


def _not_bool(value: Any) -> Any:
    if isinstance(value, bool):
        raise ValueError("expected an integer id, not a boolean")
    return value


#: an instance or room id: an integer (not `true`) of at most 32 bits
Id = Annotated[int, BeforeValidator(_not_bool), Field(ge=-MAX_ID, le=MAX_ID)]
#: a count (frames, cells): a non-negative integer (not `true`) of at most 32 bits
Count = Annotated[int, BeforeValidator(_not_bool), Field(ge=0, le=MAX_ID)]
#: a finite coordinate or height in metres, |v| <= MAX_COORD
Metres = Annotated[float, Field(allow_inf_nan=False, ge=-MAX_COORD, le=MAX_COORD)]


def check_grid_size(height: int, width: int, source: Any = None, where: str | None = "grid") -> None:
    """Refuse a grid too large to hold in memory (far-apart objects, a corrupted input, a tiny
    cell size) with a `MapFormatError` naming the limit, before anything is allocated."""
    if height * width > MAX_GRID_CELLS:
        raise MapFormatError(f"a grid of {height} x {width} cells is more than the {MAX_GRID_CELLS:,} cells "
                             "allowed: check the coordinates or use a larger --cell-size", source, where)


def arrays_equal(a: Optional[np.ndarray], b: Optional[np.ndarray]) -> bool:
    """Same dtype, shape and values (NaN equal to NaN); two Nones are equal."""
    if a is None or b is None:
        return a is None and b is None
    return (a.dtype == b.dtype and a.shape == b.shape
            and bool(np.array_equal(a, b, equal_nan=a.dtype.kind in "fc")))


class Room(BaseModel):
    """A room (region) of the map. `polygon` is a list of (x, y) vertices in metres."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    id: Id
    label: str
    polygon: Optional[list[tuple[Metres, Metres]]] = None


class Instance(BaseModel):
    """One object instance of the instance dictionary.

    `tags` holds structured attributes (e.g. color, material, shape) as strings;
    `alt_labels` holds other plausible categories (e.g. the paper's top-5);
    `mean_height` is in metres above the floor; `weight` is the observation count;
    `centroid` is (x, y, z) in metres; `footprint_cells` is the number of grid cells it occupies.
    """

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    id: Id
    label: str
    room_id: Optional[Id] = None
    room_label: Optional[str] = None
    caption: str = ""
    tags: dict[str, str] = Field(default_factory=dict)
    alt_labels: list[str] = Field(default_factory=list)
    mean_height: Optional[Metres] = None
    weight: float = Field(1.0, ge=0)
    frames: list[Annotated[int, Field(ge=0, le=MAX_ID)]] = Field(default_factory=list)
    centroid: Optional[tuple[Metres, Metres, Metres]] = None
    footprint_cells: int = Field(0, ge=0, le=MAX_GRID_CELLS)


class GridSpec(BaseModel):
    """Top-down grid: `cell_size` in metres, `origin` (x, y) of cell (0, 0)'s corner, `height` rows x `width` cols."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    cell_size: float = Field(gt=0, le=1000)
    origin: tuple[Metres, Metres] = (0.0, 0.0)
    height: int = Field(ge=0, le=MAX_GRID_CELLS)
    width: int = Field(ge=0, le=MAX_GRID_CELLS)

    @model_validator(mode="after")
    def _bounded(self) -> "GridSpec":
        if self.height * self.width > MAX_GRID_CELLS:
            raise ValueError(f"a grid of {self.height} x {self.width} cells is more than the "
                             f"{MAX_GRID_CELLS:,} cells allowed")
        return self

    @classmethod
    def checked(cls, source: Any = None, where: str | None = "grid", **fields: Any) -> "GridSpec":
        """A grid computed from input data (frames, boxes): the size limit is checked before
        anything else and any problem is a one-line `MapFormatError`, not a pydantic error."""
        check_grid_size(int(fields.get("height", 0)), int(fields.get("width", 0)), source, where)
        try:
            return cls(**fields)
        except ValidationError as exc:
            message, field = validation_message(exc)
            raise MapFormatError(f"{field}: {message}" if field else message, source, where) from None

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        """(row, col) of the cell containing world point (x, y); may be outside the grid."""
        return (int(np.floor((y - self.origin[1]) / self.cell_size)),
                int(np.floor((x - self.origin[0]) / self.cell_size)))

    def center_of(self, row: int, col: int) -> tuple[float, float]:
        """World (x, y) in metres of the centre of cell (row, col)."""
        return (self.origin[0] + (col + 0.5) * self.cell_size,
                self.origin[1] + (row + 0.5) * self.cell_size)

    def contains(self, row: int, col: int) -> bool:
        return 0 <= row < self.height and 0 <= col < self.width


class InstanceGrid(BaseModel):
    """The 2.5D map M in CSR layout over occupied cells only.

    `cells` (K,) int64: sorted flat indices of occupied cells.
    `indptr` (K + 1,) int64: entries of cell k are `ids[indptr[k]:indptr[k + 1]]`.
    `ids` (nnz,) int64: instance ids occupying the cell (several = stacked, multi-occupancy).
    `top` (nnz,) float32: height in metres of the instance's top in that cell (NaN if unknown).
    """

    model_config = ConfigDict(arbitrary_types_allowed=True, extra="forbid")

    cells: np.ndarray
    indptr: np.ndarray
    ids: np.ndarray
    top: np.ndarray

    @model_validator(mode="after")
    def _check_shapes(self) -> "InstanceGrid":
        for name in ("cells", "indptr", "ids", "top"):
            arr = getattr(self, name)
            if not isinstance(arr, np.ndarray) or arr.ndim != 1 or arr.dtype.kind not in ("f" if name == "top" else "iu"):
                raise ValueError(f"{name} must be a 1-D {'float' if name == 'top' else 'integer'} array")
        k, nnz = len(self.cells), len(self.ids)
        if len(self.indptr) != k + 1:
            raise ValueError(f"indptr has {len(self.indptr)} entries, expected {k + 1}")
        if k and (self.indptr[0] != 0 or self.indptr[-1] != nnz):
            raise ValueError("indptr must start at 0 and end at len(ids)")
        if k == 0 and len(self.indptr) and self.indptr[0] != 0:
            raise ValueError("indptr must start at 0")
        if np.any(np.diff(self.indptr) < 0):
            raise ValueError("indptr must be non-decreasing")
        if np.any(np.diff(self.cells) <= 0):
            raise ValueError("cells must be strictly increasing")
        if len(self.top) != nnz:
            raise ValueError(f"top has {len(self.top)} entries, expected {nnz}")
        return self

    @classmethod
    def empty(cls) -> "InstanceGrid":
        return cls(cells=np.zeros(0, np.int64), indptr=np.zeros(1, np.int64),
                   ids=np.zeros(0, np.int64), top=np.zeros(0, np.float32))

    @classmethod
    def from_entries(cls, flat_cells: np.ndarray, ids: np.ndarray, top: np.ndarray | None = None) -> "InstanceGrid":
        """Build from parallel (flat cell, instance id[, top height]) entries; duplicates
        of (cell, id) are merged keeping the highest top."""
        flat_cells = np.asarray(flat_cells, np.int64)
        ids = np.asarray(ids, np.int64)
        top = np.full(len(ids), np.nan, np.float32) if top is None else np.asarray(top, np.float32)
        if len(flat_cells) == 0:
            return cls.empty()
        # sort by cell, id, then descending top so the first of each (cell, id) run is the highest
        order = np.lexsort((-np.nan_to_num(top, nan=-np.inf), ids, flat_cells))
        flat_cells, ids, top = flat_cells[order], ids[order], top[order]
        keep = np.ones(len(ids), bool)
        keep[1:] = (flat_cells[1:] != flat_cells[:-1]) | (ids[1:] != ids[:-1])
        flat_cells, ids, top = flat_cells[keep], ids[keep], top[keep]
        cells, starts = np.unique(flat_cells, return_index=True)
        indptr = np.append(starts, len(ids)).astype(np.int64)
        return cls(cells=cells.astype(np.int64), indptr=indptr, ids=ids, top=top)

    def entries(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(flat cell per entry, id per entry, top per entry), each (nnz,)."""
        counts = np.diff(self.indptr)
        return np.repeat(self.cells, counts), self.ids, self.top

    def at(self, flat_cell: int) -> np.ndarray:
        """Instance ids in one cell (empty array if unoccupied)."""
        k = np.searchsorted(self.cells, flat_cell)
        if k < len(self.cells) and self.cells[k] == flat_cell:
            return self.ids[self.indptr[k]:self.indptr[k + 1]]
        return self.ids[:0]

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, InstanceGrid):
            return NotImplemented
        return all(arrays_equal(getattr(self, k), getattr(other, k)) for k in ("cells", "indptr", "ids", "top"))

    @property
    def multi_occupancy_cells(self) -> int:
        """Number of cells holding more than one instance."""
        return int(np.count_nonzero(np.diff(self.indptr) > 1))


class SceneMap(BaseModel):
    """An instance-enriched 2.5D semantic map of one scene (what a `.iesm` file holds).

    `room_map` (H, W) int32: room id per cell, -1 where none. `obstacles` (H, W) bool.
    `embeddings` (N, D) float array aligned with `instances` (row i = instances[i]); `embedding_model`
    names the model that produced them. `observations` (M, 5) float64, maps built from frames only:
    rows [instance_id, frame_index, mask_index_in_that_frame, mask_area_px, mask_score].
    """

    model_config = ConfigDict(arbitrary_types_allowed=True, extra="forbid")

    schema_version: int = SCHEMA_VERSION
    scene_id: str
    source: str = ""
    grid: GridSpec
    instances: list[Instance]
    rooms: list[Room] = Field(default_factory=list)
    occupancy: InstanceGrid = Field(default_factory=InstanceGrid.empty)
    room_map: Optional[np.ndarray] = None
    obstacles: Optional[np.ndarray] = None
    embeddings: Optional[np.ndarray] = None
    embedding_model: Optional[str] = None
    observations: Optional[np.ndarray] = None
    meta: dict[str, str] = Field(default_factory=dict)

    @model_validator(mode="after")
    def _check_consistency(self) -> "SceneMap":
        ids = [inst.id for inst in self.instances]
        if len(set(ids)) != len(ids):
            raise ValueError("instance ids must be unique")
        room_ids = [room.id for room in self.rooms]
        if len(set(room_ids)) != len(room_ids):
            raise ValueError("room ids must be unique")
        hw = (self.grid.height, self.grid.width)
        for name in ("room_map", "obstacles"):
            layer = getattr(self, name)
            if layer is not None and layer.shape != hw:
                raise ValueError(f"{name} has shape {layer.shape}, grid is {hw}")
        if self.embeddings is not None and (self.embeddings.ndim != 2 or len(self.embeddings) != len(self.instances)):
            raise ValueError(f"embeddings must be (N={len(self.instances)}, D), got {self.embeddings.shape}")
        if self.observations is not None:
            obs = self.observations
            if obs.ndim != 2 or obs.shape[1] != 5:
                raise ValueError(f"observations must be (M, 5), got {obs.shape}")
            unknown_obs = set(np.unique(obs[:, 0]).tolist()) - set(ids)
            if unknown_obs:
                raise ValueError(f"observations refer to unknown instance ids {sorted(unknown_obs)[:5]}")
        n_cells = self.grid.height * self.grid.width
        if len(self.occupancy.cells) and (self.occupancy.cells[0] < 0 or self.occupancy.cells[-1] >= n_cells):
            raise ValueError("occupancy cells fall outside the grid")
        unknown = set(np.unique(self.occupancy.ids).tolist()) - set(ids)
        if unknown:
            raise ValueError(f"occupancy refers to unknown instance ids {sorted(unknown)[:5]}")
        return self

    def __eq__(self, other: object) -> bool:
        """Field-wise equality; arrays must match in dtype, shape and values (NaN == NaN)."""
        if not isinstance(other, SceneMap):
            return NotImplemented
        arrays = ("room_map", "obstacles", "embeddings", "observations")
        return (self.model_dump(exclude={"occupancy", *arrays}) == other.model_dump(exclude={"occupancy", *arrays})
                and self.occupancy == other.occupancy
                and all(arrays_equal(getattr(self, k), getattr(other, k)) for k in arrays))

    def instance(self, instance_id: int) -> Instance:
        for inst in self.instances:
            if inst.id == instance_id:
                return inst
        raise KeyError(instance_id)

    def cells_of(self, instance_ids) -> np.ndarray:
        """(H, W) bool: cells occupied by any of `instance_ids`."""
        flat, ids, _ = self.occupancy.entries()
        mask = np.zeros(self.grid.height * self.grid.width, bool)
        mask[flat[np.isin(ids, np.asarray(list(instance_ids), np.int64))]] = True
        return mask.reshape(self.grid.height, self.grid.width)
