"""Why retrieval on built maps fails: every wrong MTEFR answer of the retrieval study, one cause each.

    python -m iesm_agent.evals.studies.retrieval_causes --seeds 0-4 --realism realistic --allow-tuning-seeds --out docs/results/retrieval-causes-tuning

Per seed, the retrieval study's scene, captioned map, ground-truth suite and run (`retrieval.run_scene`);
each wrong MTEFR answer gets the first cause of `evals.retrieval_causes.CAUSES` that holds, beside
the map: the target's ground truth (label, room, colour and material), its built instances'
labels, rooms and captions, the pick's and the object the pick holds (`gt_queries.built_instances`).
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path
from typing import Optional

from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, run_checked, scene_frames, scene_rows, seeds_note,
               study_command, study_main, write_table)
from .retrieval import TYPES

METHOD = "mtefr"


def wrong_answers(frames: Path, seed: int, work: Path) -> dict:
    """{"queries": per type, "wrong": [one row per wrong MTEFR answer, with its cause]} for `frames`."""
    from ...sim.ground_truth import GroundTruth
    from ...store import open_map
    from ..mapping import EvalContext
    from ..mapping_causes import built_instances
    from ..observed import observed_masks
    from ..retrieval_causes import classify, gt_objects, names_abstract, read_wrongly, said
    from ..vocab import Vocabulary
    from .retrieval import run_scene

    map_path, _, outcome, _ = run_scene(frames, seed, work)
    scene, gt, vocab = open_map(map_path), GroundTruth.load(frames), Vocabulary.load()
    pieces, _ = built_instances(scene, gt, frames, observed_masks(frames, gt))
    holds = {inst: obj for obj, insts in pieces.items() for inst in insts}
    objects = gt_objects(gt.objects, gt.rooms_list, vocab)
    stacked = EvalContext.create(gt, frames).stacked
    by_id = {i.id: i for i in scene.instances}
    records = [r for r in outcome.records if r.method == METHOD]
    rows = []
    for r in records:
        if r.correct:
            continue
        target = objects[holds[r.target]]
        picked = by_id.get(r.predicted) if r.predicted is not None else None
        picked_gt = objects.get(holds.get(r.predicted, -1))
        misread = read_wrongly(r.type, r.hints, vocab.spoken(target.label), target.room if "r" in r.type else None,
                               said(r.query, target, vocab) if "d" in r.type else {}, vocab)
        cause, detail = classify(r.type, r.query, r.hints, target, [by_id[i] for i in pieces[target.id]],
                                 [by_id[i] for i in r.accept if i in by_id], picked, picked_gt, vocab)
        rows.append({"id": r.id, "type": r.type, "query": r.query, "cause": cause, "detail": detail,
                     "target": f"{target.label} ({target.room}) {target.attributes}",
                     "map": "; ".join(f"#{i} {by_id[i].label} ({by_id[i].room_label}): {by_id[i].caption}"
                                      for i in pieces[target.id]),
                     "picked": f"#{picked.id} {picked.label} ({picked.room_label}): {picked.caption}" if picked else "-",
                     "picked_holds": f"{picked_gt.label} ({picked_gt.room}) {picked_gt.attributes}" if picked_gt
                     else "no object", "hints": dict(r.hints), "misread": misread,
                     "stacked": target.id in stacked})
    abstract = Counter((r.correct, names_abstract(r.hints, vocab.spoken(objects[holds[r.target]].label)))
                       for r in records if r.type == "ard")
    return {"queries": dict(Counter(r.type for r in records)), "wrong": rows,
            "stacked_queries": sum(holds[r.target] in stacked for r in records),
            "abstract": {f"{'right' if right else 'wrong'}, {'names' if named else 'misses'}": n
                         for (right, named), n in abstract.items()}}


def _cell(text: str) -> str:
    return str(text).replace("|", "/").replace("\n", " ")


def render_table(summary: dict) -> str:
    from ..retrieval_causes import CAUSES, MAP_CAUSES

    scenes = summary["scenes"]
    wrong = [dict(w, seed=s["seed"]) for s in scenes for w in s["wrong"]]
    queries = Counter()
    for s in scenes:
        queries.update(s["queries"])
    counts = Counter((w["cause"], w["type"]) for w in wrong)
    lines = [f"Profile `{summary['realism']}`; seeds {summary['seeds_arg']} ({seeds_note(summary['seeds_arg'])}); "
             "the retrieval study's scenes, captioned maps, ground-truth suites and runs "
             f"(`evals/studies/retrieval.py`); every wrong {METHOD.upper()} answer given the first cause "
             "that holds, in the order of the rows (`evals/retrieval_causes.py`). "
             f"{sum(queries.values())} queries, {len(wrong)} wrong; the map's side (labels, rooms, captions): "
             f"{sum(counts[c, t] for c in MAP_CAUSES for t in TYPES)}.", "",
             "Stacked target: the target lies over another object by half its footprint or more (an item on a "
             "table, shelf or counter, a picture or window in its wall: the mapping and stacked tables' rule).", "",
             "| cause | " + " | ".join(TYPES) + " | all | stacked target |", "|---|" + "---:|" * (len(TYPES) + 2),
             "| queries | " + " | ".join(str(queries[t]) for t in TYPES) + f" | {sum(queries.values())} | {sum(s['stacked_queries'] for s in scenes)} |",
             "| wrong | " + " | ".join(str(sum(w['type'] == t for w in wrong)) for t in TYPES)
             + f" | {len(wrong)} | {sum(w['stacked'] for w in wrong)} |"]
    for cause in CAUSES:
        stacked = sum(w["stacked"] for w in wrong if w["cause"] == cause)
        lines.append(f"| {cause} | " + " | ".join(str(counts[cause, t]) for t in TYPES)
                     + f" | {sum(counts[cause, t] for t in TYPES)} | {stacked} |")
    misread = [w for w in wrong if w["misread"]]
    lines += ["", f"The reading, whatever the cause above: {len(misread)} of the {len(wrong)} wrong answers have a "
              "reading (the gate's hints) that misses the query's category (not for ard), room or a said colour or "
              "material (`retrieval_causes.read_wrongly`)" + (":" if misread else ".")]
    lines += [f"- seed {w['seed']} {w['type']} \"{_cell(w['query'])}\" ({w['cause']}): {_cell(w['misread'])}"
              for w in misread]
    abstract = Counter()
    for s in scenes:
        abstract.update(s["abstract"])
    lines += ["", "The abstract reading of ard queries (the gate's `abs` hint: the categories the use phrase points "
              "to) names the target's category in "
              f"{abstract['right, names']} of the {abstract['right, names'] + abstract['right, misses']} right answers "
              f"and {abstract['wrong, names']} of the {abstract['wrong, names'] + abstract['wrong, misses']} wrong "
              "ones (`retrieval_causes.names_abstract`; the wrong ones' hints are in the lists below)."]
    lines += ["", "## Every wrong answer beside the map", "",
              "Reading: the gate's hints. Target: ground truth (label, room, colour and material). On the map: the target's built "
              "instances (label, room, caption). Picked: the instance MTEFR named, and the object it holds.", ""]
    for cause in CAUSES:
        group = [w for w in wrong if w["cause"] == cause]
        if not group:
            continue
        lines += [f"### {cause} ({len(group)})", "", "| seed | query | type | detail | reading | target | stacked | on the map | picked | picked holds |",
                  "|---:|---|---|---|---|---|---|---|---|---|"]
        lines += [f"| {w['seed']} | {_cell(w['query'])} | {w['type']} | {_cell(w['detail'])} | "
                  f"{_cell(', '.join(f'{k}={v}' for k, v in sorted(w['hints'].items())))} | {_cell(w['target'])} | "
                  f"{'yes' if w['stacked'] else ''} | {_cell(w['map'])} | {_cell(w['picked'])} | {_cell(w['picked_holds'])} |" for w in group]
        lines.append("")
    lines += ["", f"Skipped: {'; '.join(summary['skipped'])}"] if summary["skipped"] else []
    return "\n".join(lines) + "\n"


def run_study(seeds: list[int], out: Path, work: Optional[Path], seeds_arg: str, realism: str = "realistic") -> dict:
    with scene_frames(work) as cache:
        rows, skipped = scene_rows(
            seeds, lambda seed: wrong_answers(cache.prepare(seed, "small", False, realism), seed, cache.root),
            lambda r: f"{len(r['wrong'])} wrong of {sum(r['queries'].values())}", realism)
    summary = {"seeds": seeds, "seeds_arg": seeds_arg, "realism": realism, "size": "small", "scenes": rows,
               "skipped": skipped}
    write_table(out, f"Why retrieval on built maps fails ({realism} profile)",
                study_command("retrieval_causes", seeds_arg, realism, out), render_table(summary), summary)
    return summary


def command(seeds: Seeds = "0-4", realism: Realism = "realistic",
            out: Out = Path("docs/results/retrieval-causes-tuning"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, work, seeds, realism))


def main(argv: list[str] | None = None) -> int:
    return study_main("retrieval_causes", __doc__, command, argv)


if __name__ == "__main__":
    raise SystemExit(main())
