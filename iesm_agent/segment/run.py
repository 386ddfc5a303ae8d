"""`iesm segment`'s runner: a segmenter over every frame of a frame directory, serially or on Ray
Data, writing each frame's seg.npz, and for segmenters with a text tower the vocabulary
(categories and rooms embedded in the masks' space) and per-frame image features."""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Optional

import numpy as np

from ..frames import (FrameSet, SceneMeta, encode_segmentation, write_frame_features, write_segmentation,
                      write_vocabulary)
from ..fileio import write_text
from . import SegmenterSpec, make_segmenter


@dataclass
class SegmentReport:
    """`n_frames` segmented, `n_masks` in all, `seconds` of segmentation (wall), the backend."""

    n_frames: int
    n_masks: int
    seconds: float
    backend: str
    space: str
    notes: list[str] = field(default_factory=list)


def default_vocabulary() -> tuple[list[str], list[str]]:
    """(categories, room names) from the shipped lexicon."""
    from ..lexicon import read_data

    return sorted(read_data("categories.json")["groups"]), list(read_data("rooms.json")["rooms"])


def segment_frame_set(frames: FrameSet, seg_dir: Path, *, spec: Optional[SegmenterSpec] = None, segmenter=None,
                      backend: str = "serial", workers: int | None = None, categories: list[str] | None = None,
                      rooms: list[str] | None = None,
                      on_frame: Callable[[int], None] | None = None) -> SegmentReport:
    """Segment every frame of `frames`, writing `seg_dir`/NNNNNN.seg.npz (the caller moves them
    into place) and, for CLIP segmenters, vocabulary.npz and frame_features.npz into the frame
    directory; scene.json then names the masks' embedding space and the categories.

    Give `spec` (rebuildable anywhere; needed for `backend="ray"`) or a ready `segmenter`."""
    seg_dir = Path(seg_dir)
    seg_dir.mkdir(parents=True, exist_ok=True)
    n = len(frames)
    features: dict[int, np.ndarray] = {}
    n_masks = 0
    start = time.perf_counter()
    if backend == "ray":
        from .ray_batch import segment_on_ray

        for index, data, feature in segment_on_ray(frames.directory, spec, n, workers):
            write_segmentation(seg_dir / f"{index:06d}.seg.npz", data)
            n_masks += int(np.load(_buffer(data), allow_pickle=False)["scores"].shape[0])
            if feature is not None and feature.size:
                features[index] = feature
            if on_frame is not None:
                on_frame(index)
        segmenter_for_text = None
        space = None
    else:
        segmenter = segmenter or make_segmenter(spec)
        for i in range(n):
            frame = frames.read(i)
            seg = segmenter.segment(frame)
            write_segmentation(seg_dir / f"{i:06d}.seg.npz", encode_segmentation(seg))
            n_masks += len(seg.scores)
            if hasattr(segmenter, "frame_feature"):
                features[i] = segmenter.frame_feature(frame)
            if on_frame is not None:
                on_frame(i)
        segmenter_for_text = segmenter
        space = segmenter.space
    seconds = time.perf_counter() - start
    name = spec.name if spec is not None else getattr(segmenter, "name", "custom")
    notes = []
    meta_update: dict = {}
    if name == "sam-clip":
        if segmenter_for_text is None:
            from .samclip import ClipText

            segmenter_for_text = ClipText(spec)
        default_cats, default_rooms = default_vocabulary()
        categories = categories or default_cats
        rooms = rooms or default_rooms
        write_vocabulary(frames.directory, categories, segmenter_for_text.text_embeddings(categories),
                         rooms, segmenter_for_text.text_embeddings(rooms))
        write_frame_features(frames.directory, np.stack([features[i] for i in range(n)]))
        weights = spec.clip_pretrained if spec.clip_pretrained else f"random-seed{spec.seed}"
        space = f"open_clip:{spec.clip_model}:{Path(weights).name}"
        meta_update = {"embedding_space": space, "categories": categories}
        notes.append(f"vocabulary: {len(categories)} categories and {len(rooms)} rooms embedded with CLIP's text tower")
    elif name == "geometric":
        from .geometric import SPACE

        space = SPACE
        meta_update = {"embedding_space": space, "categories": []}
        notes.append("geometric masks carry no category: instances will be labelled 'object'")
    elif space is not None:
        meta_update = {"embedding_space": space}
    if meta_update:
        meta = frames.meta.model_copy(update=meta_update)
        write_text(frames.directory / "scene.json", SceneMeta.model_validate(meta.model_dump()).model_dump_json(
            indent=1, exclude_none=True))
        frames.meta = meta
    return SegmentReport(n, n_masks, seconds, backend, space or frames.meta.embedding_space, notes)


def _buffer(data: bytes):
    import io

    return io.BytesIO(data)
