"""`caption_map`: keyframes -> crops -> a captioner -> captions, tags and rooms in the map."""

from __future__ import annotations

import asyncio
import json
from pathlib import Path
from typing import Callable, Optional, Protocol

import numpy as np

from ..errors import IesmError
from ..store.model import SceneMap
from .keyframes import select_keyframes
from .schema import TAG_KEYS, CaptionResult
from .views import InstanceView, build_views, frames_seen

#: tag keys a captioning run owns (replaced on every run; other tags are kept)
CAPTION_TAG_KEYS = (*TAG_KEYS, "size", "height")


class Captioner(Protocol):
    """Anything that captions one instance view (`OfflineCaptioner`, `VisionCaptioner`)."""

    name: str

    async def acaption(self, view: InstanceView) -> CaptionResult: ...


Progress = Callable[[str, int, int], None]


def observations_of(scene: SceneMap) -> np.ndarray:
    """The map's (M, 5) observation rows; IesmError when the map has none (not built from frames)."""
    obs = getattr(scene, "observations", None)
    if obs is None:
        raise IesmError("the map has no frame observations (build it from frames with "
                        "`iesm build-map`); captioning needs them to find each instance's masks",
                        scene.scene_id)
    return np.asarray(obs, np.float64).reshape(-1, 5)


def caption_map(scene: SceneMap, frames, captioner: Captioner, *, keyframes: int = 3,
                progress: Optional[Progress] = None) -> SceneMap:
    """A copy of `scene` with a caption, caption tags and room label for every instance.

    `frames`: a `frames.FrameSet` or its directory. `keyframes`: K, the most keyframes per
    instance. `progress(stage, done, total)` is called with stage "frames" then "instances".
    The map's meta records the captioner (`captioner`), K (`caption_keyframes`) and the
    instances whose captioner fell back, with why (`caption_failures`, JSON)."""
    from ..frames import FrameSet

    frame_set = frames if isinstance(frames, FrameSet) else FrameSet.open(Path(frames))
    obs = observations_of(scene)
    if len(obs) and (obs[:, 1].min() < 0 or obs[:, 1].max() >= len(frame_set)):
        raise IesmError(f"the map's observations refer to frames up to {int(obs[:, 1].max())}, "
                        f"the frame directory has {len(frame_set)}", frame_set.directory)
    chosen = select_keyframes(obs, keyframes)
    n_frames = len({kf.frame for kfs in chosen.values() for kf in kfs})
    views = build_views(scene, chosen, frame_set.read, frames_seen(obs),
                        progress=(lambda n: progress("frames", n, n_frames)) if progress else None)
    results = asyncio.run(_caption_all(captioner, views, progress))
    return apply_captions(scene, views, results, captioner.name, keyframes)


async def _caption_all(captioner: Captioner, views: list[InstanceView],
                       progress: Optional[Progress]) -> list[CaptionResult]:
    done = 0

    async def one(view: InstanceView) -> CaptionResult:
        nonlocal done
        result = await captioner.acaption(view)
        done += 1
        if progress is not None:
            progress("instances", done, len(views))
        return result

    try:
        return await asyncio.gather(*(one(v) for v in views))
    finally:
        model = getattr(captioner, "model", None)
        if model is not None:
            await model.aclose()


def apply_captions(scene: SceneMap, views: list[InstanceView], results: list[CaptionResult],
                   captioner_name: str, keyframes: int) -> SceneMap:
    """`scene` with each view's result written into its instance (caption tags replaced)."""
    by_id = {v.instance.id: (v, r) for v, r in zip(views, results, strict=True)}
    instances, failures = [], {}
    for inst in scene.instances:
        view, result = by_id[inst.id]
        tags = {k: v for k, v in inst.tags.items() if k not in CAPTION_TAG_KEYS}
        tags.update(result.tags)
        update = {"caption": result.caption, "tags": tags}
        if inst.room_label is None and view.room is not None:
            update.update(room_label=view.room, room_id=view.room_id)
        instances.append(inst.model_copy(update=update))
        if result.failure:
            failures[str(inst.id)] = result.failure
    meta = {**scene.meta, "captioner": captioner_name, "caption_keyframes": str(keyframes),
            "caption_failures": json.dumps(failures, sort_keys=True)}
    return scene.model_copy(update={"instances": instances, "meta": meta})


def strip_captions(scene: SceneMap) -> SceneMap:
    """`scene` with every caption emptied and the caption tags removed (labels-only ablation);
    rooms and other tags stay. The map's meta records `captioner` = "stripped"."""
    instances = [i.model_copy(update={"caption": "", "tags": {k: v for k, v in i.tags.items()
                                                                if k not in CAPTION_TAG_KEYS}})
                 for i in scene.instances]
    meta = {k: v for k, v in scene.meta.items() if not k.startswith("caption")}
    return scene.model_copy(update={"instances": instances, "meta": {**meta, "captioner": "stripped"}})
