"""Parameters of room segmentation (metres unless stated)."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field

STRUCTURAL_LABELS = ("wall", "door", "doorframe", "door frame", "doorway", "window", "pillar", "column", "railing")
LARGE_FIXED_LABELS = ("wardrobe", "closet", "bookshelf", "bookcase", "shelf", "cabinet", "kitchen cabinet",
                      "refrigerator", "fridge", "counter", "kitchen counter", "kitchen island", "dresser")
class RoomConfig(BaseModel):
    """Room segmentation (paper Sec. 3.2 plus the contextual open-plan split).

    Structural instances (`structural_labels`, and `large_fixed_labels` with a footprint of at least
    `large_fixed_min_area` m^2) form the boundary mask; LSD (run at image scale `lsd_scale`) segments shorter than `min_segment` are
    dropped; collinear segments (angle <= `merge_angle_deg`, offset <= `merge_offset`) whose ends are
    at most `merge_gap` apart are merged (this closes door gaps); the raster is drawn
    `line_thickness` cells wide, dilated by `dilate` and closed by `close`. Free components smaller
    than `min_room_area` m^2, or with less than `min_observed` of their cells observed, are not rooms.
    Rooms then grow over the raster margin (stopped by the drawn lines, so closed doors hold), into
    unobserved space inside the building and over large fixed furniture; wall and boundary cells
    within `wall_share` m of a room go to the nearest one (walls are split between the rooms they
    separate; rooms stop at the lines drawn along a wall's face, and under realistic depth the
    mapped wall and its raster cover up to a few tenths of a metre of the true room behind them:
    90 % of such cells left without a room at 0.15 m were within 0.35 m of one; chosen on tuning
    seeds 0-4 from 0.15-0.4 m, where 0.25-0.4 m score alike).
    The contextual split runs on the grown rooms of at least `split_min_area` m^2: each cell takes
    the label with the most evidence within a Gaussian of `split_smoothing` m (per-cell labels plus
    `object_vote_weight` x the votes of room-typical objects, per footprint cell); connected cells
    of one label form a part, parts under `min_room_area` join their longest-bordering neighbour,
    and the parts are kept when their own majorities explain `split_gain` more of the evidence than
    the room's single majority (or, for a single part, when its own label beats the room's majority
    inside it by `split_gain` and objects typical of its label stand in it). A part labelled as a
    room behind the wall it borders (within the growth margin, not touching it) that holds more
    evidence of that label than the part is that room seen through the door: it stays. With the split on,
    every room then takes the label with the most evidence (per-cell labels plus
    `object_vote_weight` x object votes); off, the paper's majority per-cell label.
    `split_smoothing`, with the other split settings, was chosen on tuning seeds 0-4 (walled and
    open-plan, realistic profile).
    An instance none of whose footprint cells lies in a room (a window in the outer wall, a lamp
    whose mapped cells fall just outside the room) takes the room nearest to its footprint when that
    is within `instance_reach` m; 0 leaves it without a room.
    """

    model_config = ConfigDict(extra="forbid")

    structural_labels: tuple[str, ...] = STRUCTURAL_LABELS
    large_fixed_labels: tuple[str, ...] = LARGE_FIXED_LABELS
    large_fixed_min_area: float = Field(0.5, ge=0)
    lsd_scale: float = Field(0.5, gt=0, le=1)
    min_segment: float = Field(0.3, ge=0)
    merge_angle_deg: float = Field(5.0, ge=0, le=90)
    merge_offset: float = Field(0.15, ge=0)
    merge_gap: float = Field(1.1, ge=0)
    line_thickness: int = Field(2, ge=1)
    dilate: float = Field(0.05, ge=0)
    close: float = Field(0.4, ge=0)
    min_room_area: float = Field(1.0, ge=0)
    wall_share: float = Field(0.3, ge=0)
    min_observed: float = Field(0.2, ge=0, le=1)
    split: bool = True
    split_min_area: float = Field(6.0, ge=0)
    split_smoothing: float = Field(0.5, ge=0)
    split_gain: float = Field(0.1, ge=0, le=1)
    object_vote_weight: float = Field(0.5, ge=0)
    instance_reach: float = Field(0.5, ge=0)
