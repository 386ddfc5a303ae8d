"""Segmentation on Ray Data: the frame indices become a dataset, `map_batches` runs an actor pool
with one segmenter (one model) per actor, on GPUs when the cluster has them. Local and in process
by default; `RAY_ADDRESS` (or an already initialised Ray) runs the same job on a cluster, whose
nodes must see the frame directory at the same path. Ray is imported here only (optional extra
`ray`). Each row returned: frame index, the seg.npz bytes (`frames.encode_segmentation`, the same
encoder as the serial path) and the frame feature (D,) float32 (empty when the segmenter has none)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Iterator

import numpy as np

from . import SegmenterSpec


class SegmentActor:
    """Ray Data callable class: builds the segmenter once, then segments batches of indices."""

    def __init__(self, directory: str, spec: dict):
        from ..frames import FrameSet
        from . import make_segmenter

        self.frames = FrameSet.open(directory)
        self.segmenter = make_segmenter(SegmenterSpec.model_validate(spec))

    def __call__(self, batch: dict) -> dict:
        from ..frames import encode_segmentation

        out_seg, out_feat = [], []
        for index in batch["index"]:
            frame = self.frames.read(int(index))
            out_seg.append(encode_segmentation(self.segmenter.segment(frame)))
            feature = self.segmenter.frame_feature(frame) if hasattr(self.segmenter, "frame_feature") else None
            out_feat.append(np.zeros(0, np.float32) if feature is None else feature.astype(np.float32))
        return {"index": np.asarray(batch["index"], np.int64), "seg": np.array(out_seg, dtype=object),
                "feature": np.array(out_feat + [None], dtype=object)[:-1]}


def init_ray() -> None:
    """Connect to `RAY_ADDRESS` when set, else start Ray in this machine (quietly)."""
    import ray

    if not ray.is_initialized():
        ray.init(address=os.environ.get("RAY_ADDRESS") or None, include_dashboard=False,
                 log_to_driver=False, configure_logging=False)


def segment_on_ray(directory: Path, spec: SegmenterSpec, n_frames: int,
                   workers: int | None = None) -> Iterator[tuple[int, bytes, np.ndarray | None]]:
    """(index, seg.npz bytes, frame feature or None) for every frame, in index order."""
    import ray

    init_ray()
    gpus = int(ray.cluster_resources().get("GPU", 0))
    cpus = int(ray.cluster_resources().get("CPU", 1))
    size = workers or max(1, min(n_frames, gpus if gpus else cpus))
    ctx = ray.data.DataContext.get_current()
    ctx.enable_progress_bars = False
    ds = ray.data.from_items([{"index": i} for i in range(n_frames)], override_num_blocks=max(1, min(n_frames, 4 * size)))
    ds = ds.map_batches(SegmentActor, fn_constructor_kwargs={"directory": str(directory), "spec": spec.model_dump()},
                        batch_size=1, batch_format="numpy", concurrency=size,
                        num_gpus=1 if gpus else 0, num_cpus=0 if gpus else 1)
    rows = sorted(ds.take_all(), key=lambda r: int(r["index"]))
    for row in rows:
        feature = row["feature"]
        yield int(row["index"]), bytes(row["seg"]), (np.asarray(feature, np.float32) if feature is not None and
                                                    len(feature) else None)
