"""Convert a `Recording` into our frame directory: frames checked, bad ones refused (or skipped
and counted with `skip_bad`), depth in millimetres, poses gravity-aligned. Written into a staging
directory beside the target and renamed into place only when every frame is done, so a failure
leaves nothing behind."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from ..errors import IesmError
from .checks import BadFrame, SkipLog, check_depth_unit, pose_reason
from .gravity import Alignment, estimate_alignment, identity
from .ours import Frame, SceneMeta, write_frame, write_frame_set
from ..fileio import read_image, utf8_text
from .recording import Recording

ALIGN_SAMPLE = 30  # frames used to find the floor


@dataclass
class ImportReport:
    """What the conversion did: frames written, the skip log, the alignment, notes."""

    n_frames: int
    log: SkipLog
    alignment: Alignment
    notes: list[str] = field(default_factory=list)

    def lines(self) -> list[str]:
        return [*self.notes, self.alignment.description, self.log.summary()]




def _read(rec: Recording, i: int, log: SkipLog, skip_bad: bool) -> Frame | None:
    try:
        return rec.read(i, log)
    except BadFrame as exc:
        if not skip_bad:
            raise IesmError(f"{exc.message} (frame {rec.refs[i].name}; --skip-bad-frames skips such frames)",
                            exc.source, exc.where) from None
        log.skip(rec.refs[i].name, pose_reason(exc))
        return None


def import_recording(rec: Recording, out_dir: Path, *, scene_id: str, embedding_space: str,
                     categories: list[str], skip_bad: bool = False, align: bool = True,
                     on_frame: Callable[[Frame], None] | None = None) -> ImportReport:
    """Write `rec` into `out_dir` (our layout, no seg.npz yet). Frames are renumbered 0..N-1 in the
    recording's order; `on_frame(frame)` sees each written frame (aligned pose)."""
    log = SkipLog()
    # frames the format marks as pose-less (ScanNet's -inf, TUM without ground truth) are skipped
    # whatever `skip_bad` says: the format itself says so
    usable = []
    for i, ref in enumerate(rec.refs):
        if ref.pose is not None and np.isneginf(ref.pose).any():
            log.skip(ref.name, "invalid pose (-inf: tracking lost)")
        elif ref.pose is None and "ground-truth pose within" in ref.pose_error:
            log.skip(ref.name, "no ground-truth pose")
        else:
            usable.append(i)
    if not usable:
        raise IesmError(f"none of the {len(rec)} frames has a usable pose ({log.summary()})", rec.directory)
    sample_idx = [usable[j] for j in np.linspace(0, len(usable) - 1, min(ALIGN_SAMPLE, len(usable))).astype(int)]
    sample = [f for f in (_read(rec, i, SkipLog(), skip_bad) for i in sorted(set(sample_idx))) if f is not None]
    if not sample:
        raise IesmError(f"no readable frame ({log.summary()})", rec.directory)
    for f in sample[:3]:  # the raw readings: clean_depth would already have dropped "too far" ones
        path = rec.refs[f.index].depth
        raw = read_image(path, color=False, error=BadFrame).astype(np.float64)
        check_depth_unit(raw[np.isfinite(raw)] / rec.depth_scale, rec.depth_scale, path, rec.layout)
    alignment = estimate_alignment(sample, rec.intrinsics, up=rec.up) if align else \
        identity("gravity: not aligned (--no-align): poses kept in the recording's world")
    n = 0
    write_frame_set(out_dir, SceneMeta(scene_id=scene_id, n_frames=0, embedding_space=embedding_space,
                                       categories=categories), rec.intrinsics)
    for i in usable:
        frame = _read(rec, i, log, skip_bad)
        if frame is None:
            continue
        frame = Frame(index=n, rgb=frame.rgb, depth=frame.depth, pose=alignment.apply(frame.pose))
        write_frame(out_dir, frame)
        if on_frame is not None:
            on_frame(frame)
        n += 1
    if n == 0:
        raise IesmError(f"no usable frame ({log.summary()})", rec.directory)
    source = {"layout": rec.layout, "path": str(rec.directory), "notes": "; ".join(rec.notes),
              "alignment": alignment.description, "alignment_method": alignment.method,
              "transform": " ".join(f"{v:.9g}" for v in alignment.transform.ravel()), **log.as_meta()}
    source = {k: utf8_text(v) for k, v in source.items()}  # a path need not be UTF-8
    write_frame_set(out_dir, SceneMeta(scene_id=scene_id, n_frames=n, embedding_space=embedding_space,
                                       categories=categories, source=source), rec.intrinsics)
    return ImportReport(n, log, alignment, list(rec.notes))
