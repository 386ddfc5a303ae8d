"""Query suites for a built map written from ground truth (`iesm gen-queries MAP --gt DIR`).

Queries are generated from the objects of gt/objects.json that the frames show (seen in at least
`min_mask_pixels` pixels of the instance images; all objects when there are none), imported in
memory as an object-list map so the built map's own labels never leak into the queries. Each
query's target and accepted ids are translated to built-map ids (`built_instances`): the instance
`match_instances` pairs the object with (observed footprints, top-down IoU > 0.5, as the mapping
table) and, for a map built from these frames, the object's own instances (those most of whose
masks show it, holding at least half of its masks; `evals.mapping_causes`) that no other object is
paired with: the map holds the object even when its footprint is too large, too small or in pieces
for IoU > 0.5, and each of its pieces is the object. A query whose target has neither (the object
never reached the map or went into other objects' instances) is dropped; accepted ids without
either are left out. Each query gets a
seeded random robot start (x, y) in metres on free ground-truth floor, so `iesm eval` can report
N-SR on the map.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import NamedTuple, Optional, Sequence

import numpy as np

from .generate import GenerationResult, generate_suite
from .mapping_causes import built_instances
from .observed import observed_masks
from .suite import SuiteQuery, write_suite
from ..sim.ground_truth import GroundTruth
from ..store import open_map
from ..store.importers.objects import ObjectSpec
from ..store.refs import resolve_map_path


#: a start keeps at least this much free floor around it, metres
START_CLEARANCE_M = 0.3


def free_starts(gt: GroundTruth, n: int, seed: int) -> list[tuple[float, float]]:
    """`n` seeded (x, y) metre positions on ground-truth floor inside a room, at least
    START_CLEARANCE_M from anything that blocks a robot; [] when there is no such floor."""
    import cv2

    free = ((gt.rooms >= 0) & ~gt.occupancy).astype(np.uint8)
    clearance = cv2.distanceTransform(free, cv2.DIST_L2, 5) * gt.grid.cell_size
    cells = np.argwhere(clearance >= START_CLEARANCE_M)
    if not len(cells) or n == 0:
        return []
    picks = cells[np.random.default_rng(seed).integers(0, len(cells), n)]
    return [tuple(round(v, 2) for v in gt.grid.center_of(int(r), int(c))) for r, c in picks]


class TargetCounts(NamedTuple):
    """How a suite's queries found their targets on the built map: paired by footprint IoU, by the
    object's own instances (`built_instances`), or dropped (neither)."""

    matched: int
    own: int
    dropped: int


def translate(queries: Sequence[SuiteQuery], instances: dict[int, Sequence[int]], map_ref: str,
              matched: Optional[set[int]] = None) -> tuple[list[SuiteQuery], TargetCounts]:
    """`queries` on ground-truth ids -> the same queries on built-map ids (`map_ref`): the target is
    the first of `instances[target]`, accept every instance of every accepted id; returns them and
    the counts (targets in `matched`, default all of `instances`, count as paired by IoU)."""
    matched = set(instances) if matched is None else matched
    kept, by_iou, dropped = [], 0, 0
    for q in queries:
        if not instances.get(q.target):
            dropped += 1
            continue
        by_iou += q.target in matched
        accept = sorted({p for a in q.accept for p in instances.get(a, ())})
        kept.append(SuiteQuery(id=q.id, map=map_ref, query=q.query, type=q.type, target=instances[q.target][0],
                               accept=accept, group=q.group))
    return kept, TargetCounts(by_iou, len(kept) - by_iou, dropped)


async def generate_gt_suite(built_map: str, frames_dir: str | Path, out: str | Path, types: Sequence[str], *,
                            per_type: int = 10, seed: int = 0, model=None, paraphrases: int = 1,
                            id_prefix: str = "") -> tuple[GenerationResult, TargetCounts]:
    """Write a suite for `built_map` whose queries come from the ground truth in `frames_dir`
    (`paraphrases`, `id_prefix` as in `generate_suite`); returns the generation result and how the
    targets were found on the map (`TargetCounts`); objects the frames never show are not targets."""
    out = Path(out)
    map_path = resolve_map_path(built_map)
    scene = open_map(map_path)
    gt = GroundTruth.load(frames_dir)
    observed = observed_masks(frames_dir, gt)
    seen = set(np.unique(observed[1]).tolist()) if observed is not None else {int(o["id"]) for o in gt.objects}
    known = set(ObjectSpec.model_fields)
    objects = [{k: v for k, v in o.items() if k in known} for o in gt.objects if int(o["id"]) in seen]
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / f"{gt.scene_id}_gt.json"
        src.write_text(json.dumps({"scene_id": gt.scene_id, "rooms": gt.rooms_list or None, "objects": objects}))
        result = await generate_suite([str(src)], Path(tmp) / "suite.jsonl", types, per_type=per_type, seed=seed,
                                      model=model, paraphrases=paraphrases, id_prefix=id_prefix)
    ref = Path(os.path.relpath(map_path, out.resolve().parent)).as_posix()
    instances, matched = built_instances(scene, gt, frames_dir, observed)
    queries, counts = translate(result.queries, instances, ref, matched)
    starts = free_starts(gt, len(queries), seed)
    if starts:
        queries = [q.model_copy(update={"start": start}) for q, start in zip(queries, starts)]
    write_suite(queries, out)
    result.queries = queries
    return result, counts

