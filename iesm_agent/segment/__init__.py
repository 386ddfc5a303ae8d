"""Perception before mapping: segmenters behind `frames.Segmenter` and `iesm segment`'s runner.

- `geometric` (`geometric.GeometricSegmenter`): no weights; colour + depth superpixels; no category.
- `sam-clip` (`samclip.SamClipSegmenter`): Segment Anything masks (`segment-anything`, a user
  checkpoint) and an open_clip embedding per mask crop; its text tower embeds the category and room
  lists (written to vocabulary.npz) and its frame features give per-cell room labels.
- `sim`: the simulator's synthetic segmenter (made by the CLI, which may import `sim`).

`run.segment_frame_set` runs one over a frame directory, serially or on Ray Data (`ray_batch`)."""

from __future__ import annotations

from typing import Optional

from pydantic import BaseModel, ConfigDict, Field

from ..errors import IesmError

SEGMENTERS = ("geometric", "sam-clip", "sim")


class SegmenterSpec(BaseModel):
    """Everything needed to build a segmenter again in another process (a Ray actor): plain data.

    sam-clip: `sam_checkpoint` (path to a SAM .pth), `sam_model` (vit_h, vit_l, vit_b, or "tiny", a
    small random-weights configuration for tests), `clip_model` (open_clip architecture name),
    `clip_pretrained` (a checkpoint path or a tag the user has cached; None = random weights),
    `clip_config` (a JSON model config to register first, e.g. a small one for tests),
    `random_weights` must be True to run without checkpoints (tests), `seed` for random weights,
    `points_per_side`, `pred_iou_thresh`, `stability_score_thresh`, `device` ("cpu", "cuda", None =
    cuda when available), `threads` torch threads (None: torch's default)."""

    model_config = ConfigDict(extra="forbid")

    name: str
    sam_checkpoint: Optional[str] = None
    sam_model: str = "vit_h"
    clip_model: str = "ViT-B-32"
    clip_pretrained: Optional[str] = None
    clip_config: Optional[str] = None
    random_weights: bool = False
    seed: int = 0
    points_per_side: int = Field(32, ge=1)
    pred_iou_thresh: float = 0.88
    stability_score_thresh: float = 0.95
    min_mask_area: int = Field(100, ge=0)
    device: Optional[str] = None
    threads: Optional[int] = Field(None, ge=1)


def make_segmenter(spec: SegmenterSpec):
    """The segmenter `spec` names (geometric or sam-clip; the CLI makes `sim`)."""
    if spec.name == "geometric":
        from .geometric import GeometricSegmenter

        return GeometricSegmenter()
    if spec.name == "sam-clip":
        from .samclip import SamClipSegmenter

        return SamClipSegmenter(spec)
    raise IesmError(f"unknown segmenter {spec.name!r} (choose from {', '.join(SEGMENTERS)})", None, "--segmenter")
