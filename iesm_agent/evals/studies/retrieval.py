"""The retrieval table on built maps: O-SR per query type and N-SR per method on simulated scenes.

    python -m iesm_agent.evals.studies.retrieval --seeds 10-12 --realism realistic --out docs/results/retrieval-realistic

Per seed: simulate a `--size small` scene, build, segment rooms and caption offline (as the demo,
through the API: `storage.captioned_map`), write a query suite from ground truth
(`evals/gt_queries.py`, types o,or,od,ord,ard, 10 per type, seed = scene seed; targets among the
objects the frames show, translated to built instances by observed-footprint IoU > 0.5, else to the
object's own instances, `gt_queries.built_instances`) and run methods
mtefr, spr and keyword with the offline model, N-SR against the ground truth.
"""

from __future__ import annotations

import asyncio
import statistics
from pathlib import Path
from typing import TYPE_CHECKING, Optional

from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, seeds_note, run_checked, scene_frames, scene_rows, study_command,
               study_main, write_table)

if TYPE_CHECKING:
    from ..gt_queries import TargetCounts
    from ..runner import RunOutcome

TYPES = ("o", "or", "od", "ord", "ard")
METHODS = ("mtefr", "spr", "keyword")


def run_scene(frames: Path, seed: int, work: Path) -> tuple[Path, "TargetCounts", "RunOutcome", dict]:
    """Caption the map of `frames`, write its ground-truth suite and run every method on it in
    `work`: (captioned map path, how the targets were found, the run's outcome, its summary)."""
    from ..gt_queries import generate_gt_suite
    from ..runner import make_config, make_variants, run_eval, write_run_outputs
    from .storage import captioned_map

    map_path = frames.with_suffix(".captioned.iesm")
    captioned_map(frames, seed, map_path)
    suite = work / f"suite-{seed}.jsonl"
    _, counts = asyncio.run(generate_gt_suite(str(map_path), frames, suite, list(TYPES), per_type=10, seed=seed))
    config = make_config([suite], make_variants(list(METHODS), []), "offline", gt=[str(frames)])
    run_dir = work / f"run-{seed}"
    outcome = asyncio.run(run_eval(config, run_dir, resume=run_dir.exists()))
    return map_path, counts, outcome, write_run_outputs(run_dir, config, outcome)


def score_scene(frames: Path, seed: int, work: Path) -> dict:
    """O-SR per type and overall, N-SR overall, per method, on the captioned map of `frames`."""
    _, counts, outcome, summary = run_scene(frames, seed, work)
    out = {"queries": len(outcome.suite.entries), "dropped": counts.dropped, "by_own_instance": counts.own}
    for method in METHODS:
        m = summary["methods"][method]
        out[method] = {"osr": {t: m["by_type"][t]["osr"] for t in TYPES if t in m["by_type"]},
                       "osr_all": m["overall"]["osr"], "nsr": m["overall"].get("nsr")}
    return out


def mean_scores(rows: list[dict]) -> dict:
    """Mean over scenes of each method's O-SR per type (scenes that have the type), overall O-SR and N-SR."""
    out = {}
    for method in METHODS:
        osr = {t: statistics.fmean(vals) for t in TYPES
               if (vals := [r[method]["osr"][t] for r in rows if t in r[method]["osr"]])}
        nsr = [r[method]["nsr"] for r in rows if r[method]["nsr"] is not None]
        out[method] = {"osr": osr, "osr_all": statistics.fmean(r[method]["osr_all"] for r in rows) if rows else None,
                       "nsr": statistics.fmean(nsr) if nsr else None}
    return out


def _pct(v) -> str:
    return "-" if v is None else f"{100 * v:.1f}"


def render_table(summary: dict) -> str:
    lines = [f"Profile `{summary['realism']}`; seeds {summary['seeds_arg']} ({seeds_note(summary['seeds_arg'])}); simulated "
             "`--size small` scenes, built maps with rooms (simulator labels) and offline captions; queries from "
             "ground truth (`evals/gt_queries.py`, types " + ",".join(TYPES) + ", 10 per type, seed = scene seed, "
             "targets among the objects the frames show; "
             f"{sum(r['queries'] for r in summary['scenes'])} queries kept, "
             f"{sum(r['by_own_instance'] for r in summary['scenes'])} of them with a target no built instance "
             "matches by observed footprint (top-down IoU > 0.5) but held by its own instances (most of whose "
             "masks show it), "
             f"{sum(r['dropped'] for r in summary['scenes'])} dropped because the map holds the target in no "
             "instance of its own); offline model; "
             "N-SR against the ground truth. O-SR and N-SR in %, mean over seeds.", "",
             "| Method | " + " | ".join(TYPES) + " | O-SR | N-SR |", "|---|" + "---:|" * (len(TYPES) + 2)]
    for method in METHODS:
        m = summary["mean"].get(method)
        if not m:
            continue
        lines.append(f"| {method} | " + " | ".join(_pct(m["osr"].get(t)) for t in TYPES)
                     + f" | {_pct(m['osr_all'])} | {_pct(m['nsr'])} |")
    lines += ["", f"Skipped: {'; '.join(summary['skipped'])}"] if summary["skipped"] else []
    return "\n".join(lines) + "\n"


def run_study(seeds: list[int], out: Path, work: Optional[Path], seeds_arg: str, realism: str = "realistic") -> dict:
    with scene_frames(work) as cache:
        rows, skipped = scene_rows(
            seeds, lambda seed: score_scene(cache.prepare(seed, "small", False, realism), seed, cache.root),
            lambda r: ", ".join(f"{m} O-SR {_pct(r[m]['osr_all'])}" for m in METHODS), realism)
    summary = {"seeds": seeds, "seeds_arg": seeds_arg, "realism": realism, "size": "small", "scenes": rows,
               "skipped": skipped, "mean": mean_scores(rows) if rows else {}}
    write_table(out, f"Retrieval on built maps of simulated scenes ({realism} profile)",
                study_command("retrieval", seeds_arg, realism, out), render_table(summary), summary)
    return summary


def command(seeds: Seeds = "10-12", realism: Realism = "realistic",
            out: Out = Path("docs/results/retrieval-realistic"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, work, seeds, realism))


def main(argv: list[str] | None = None) -> int:
    return study_main("retrieval", __doc__, command, argv)


if __name__ == "__main__":
    raise SystemExit(main())
