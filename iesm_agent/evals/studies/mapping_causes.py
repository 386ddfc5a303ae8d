"""Why seen objects go unmatched: the per-cause table of the mapping study, one command:

    python -m iesm_agent.evals.studies.mapping_causes --seeds 0-4 --allow-tuning-seeds --realism realistic --out docs/results/mapping-causes-tuning
    python -m iesm_agent.evals.studies.mapping_causes --seeds 10-14 --realism realistic --out docs/results/mapping-causes-realistic

For each seed: render the scene (iesm_agent.sim, the given profile), build the map under each
configuration of `VARIANTS` (the paper's rules, our rules before geometry cleaning, the first
cleaning without depth smoothing, without the tops, before the split-fragment link, ours), match it
against the observed footprints (evals/mapping.py) and give every unmatched seen object one cause
(evals/mapping_causes.py); then, for ours, what became of each stacked object (named right, named
wrong, unmatched by cause) beside the 2D point-wise baseline with ground-truth masks; last, every
configuration's extra instances and same-label split fragments by the association rule that kept
them apart, per category before and after the split-fragment link. Writes OUT/table.md +
OUT/summary.json + OUT/fragments.png (a few split fragments drawn).
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Callable, Optional

import numpy as np

from ...config import MappingConfig
from ...frames import FrameSet
from ...mapping.build import MapBuilder, category_vectors
from ...mapping.cells import rowcol_of
from ...sim.ground_truth import GroundTruth
from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, log_stderr, run_checked, scene_frames, study_command,
               study_main, write_table)
from ..baseline2d import PointwiseMap2D
from ..mapping import EvalContext, named_right, pairs, prediction_from_map, prediction_from_pointwise, score
from ..mapping_causes import (CAUSES, FRAGMENT_CAUSES, cause_counts, extra_instances, grid_keys, instance_keys,
                              mask_attribution, mask_objects, same_label_pairs, unmatched_causes)

#: the configurations compared: name -> (title, factory)
VARIANTS: dict[str, tuple[str, Callable[[], MappingConfig]]] = {
    "paper": ("MappingConfig.paper()", MappingConfig.paper),
    "before": ("Ours before issue 29 (MappingConfig.uncleaned())", lambda: MappingConfig.uncleaned()),
    "first-cut": ("Ours without depth smoothing (mask erosion 1 px, 3 points per cell, delta_geo_strong=0.7)",
                  lambda: MappingConfig(depth_smooth_px=0, min_cell_points=3, top_fill_max_cos=None,
                                        delta_geo_strong=0.7)),
    "no-tops": ("Ours without the tops seen at grazing incidence (top_fill_max_cos=None, delta_geo_strong=0.7)",
                lambda: MappingConfig(top_fill_max_cos=None, delta_geo_strong=0.7)),
    "no-fragment-link": ("Ours before the split-fragment link (delta_geo_strong=0.7)",
                         lambda: MappingConfig(delta_geo_strong=0.7)),
    "ours": ("Ours (MappingConfig())", MappingConfig),
}


#: what became of a stacked object on our map: named right, named wrong, or unmatched for a cause
STACKED_GROUPS = ("named right", "named wrong", *CAUSES)


def stacked_groups(ctx: EvalContext, right: dict[int, bool], causes: dict[int, str],
                   baseline_right: dict[int, bool]) -> dict[str, dict[str, int]]:
    """{group: {"objects": n, "baseline_right": n}} over the scene's stacked objects: our group
    (`right`: matched ids -> named right; `causes` of the unmatched) and how many of them the 2D
    point-wise baseline with ground-truth masks names right."""
    out = {group: {"objects": 0, "baseline_right": 0} for group in STACKED_GROUPS}
    for i in sorted(ctx.stacked):
        group = ("named right" if right[i] else "named wrong") if i in right else causes[i]
        out[group]["objects"] += 1
        out[group]["baseline_right"] += int(baseline_right.get(i, False))
    return out


#: variants whose same-label pairs are tabulated per category (the split-fragment link before / after)
FRAGMENT_VARIANTS = ("no-fragment-link", "ours")
#: split fragments drawn in OUT/fragments.png (the first of each cause, then in order)
DRAWN_FRAGMENTS = 6


def fragment_summary(scene, main: dict[int, int], labels: dict[int, str], cfg: MappingConfig) -> dict:
    """{"extras": {cause: {"same_label": n, "other_label": n}} (`extra_instances`), "pairs": {label:
    {"fragments", "different", "named_wrong"}} (`same_label_pairs`), "fragment_causes": {cause: n}}."""
    extras = {c: {"same_label": 0, "other_label": 0} for c in FRAGMENT_CAUSES}
    for e in extra_instances(scene, main, cfg):
        extras[e["cause"]]["same_label" if e["same_label"] else "other_label"] += 1
    per_label: dict[str, dict[str, int]] = {}
    causes = {c: 0 for c in FRAGMENT_CAUSES}
    for p in same_label_pairs(scene, main, labels, cfg):
        row = per_label.setdefault(p["label"], {"fragments": 0, "different": 0, "named_wrong": 0})
        if p["same_object"]:
            row["fragments"] += 1
            causes[p["cause"]] += 1
        else:
            row["different"] += 1
            row["named_wrong"] += int(p["named_wrong"])
    return {"extras": extras, "pairs": per_label, "fragment_causes": causes}


def fragment_crops(scene, main: dict[int, int], labels: dict[int, str], ctx: EvalContext, cfg: MappingConfig,
                   title: str) -> list[dict]:
    """Top-down crops of the split fragments (same label, one object) of a built map, for
    `draw_fragments`: {"title", "cause", "image" (h, w) int8: 1 ground-truth observed footprint, 2 and
    3 the two instances, 4 both}."""
    keys = instance_keys(scene)
    gflat, gid, _top = ctx.gt_cells
    out = []
    for p in same_label_pairs(scene, main, labels, cfg):
        if not p["same_object"]:
            continue
        obj = grid_keys(gflat[gid == main[p["a"]]], ctx.gt.grid)
        layers = [obj, keys[p["a"]], keys[p["b"]]]
        rc = [rowcol_of(k) for k in layers]
        r0 = min(int(r.min()) for r, _c in rc if len(r)) - 3
        c0 = min(int(c.min()) for _r, c in rc if len(c)) - 3
        h = max(int(r.max()) for r, _c in rc if len(r)) - r0 + 4
        w = max(int(c.max()) for _r, c in rc if len(c)) - c0 + 4
        image = np.zeros((h, w), np.int8)
        image[rc[0][0] - r0, rc[0][1] - c0] = 1
        image[rc[1][0] - r0, rc[1][1] - c0] = 2
        both = np.zeros((h, w), bool)
        both[rc[1][0] - r0, rc[1][1] - c0] = True
        image[rc[2][0] - r0, rc[2][1] - c0] = 3
        image[both & (image == 3)] = 4
        out.append({"title": f"{title}: {p['label']} {p['a']} / {p['b']}", "cause": p["cause"], "image": image})
    return out


def draw_fragments(crops: list[dict], path: Path) -> None:
    """OUT/fragments.png: up to DRAWN_FRAGMENTS crops (`fragment_crops`), the first of each cause first."""
    from matplotlib.colors import ListedColormap

    from ...fileio import pyplot, save_figure

    first = {}
    for k, crop in enumerate(crops):
        first.setdefault(crop["cause"], k)
    order = sorted(first.values()) + [k for k in range(len(crops)) if k not in first.values()]
    chosen = [crops[k] for k in order[:DRAWN_FRAGMENTS]]
    if not chosen:
        return
    plt = pyplot()
    fig, axes = plt.subplots(1, len(chosen), figsize=(3.2 * len(chosen), 3.4), squeeze=False)
    cmap = ListedColormap(["white", "#cccccc", "#1f77b4", "#ff7f0e", "#7b3294"])
    for ax, crop in zip(axes[0], chosen):
        ax.imshow(crop["image"], cmap=cmap, vmin=0, vmax=4, interpolation="nearest", origin="lower")
        ax.set_title(f"{crop['title']}\n{crop['cause']}", fontsize=7)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle("Split fragments (5 cm cells): grey = the object's observed footprint, blue / orange = its two "
                 "instances, purple = both", fontsize=8, y=1.1)
    save_figure(fig, path)


def study_scene(frames_dir: Path, crops: Optional[list[dict]] = None) -> dict:
    """{variant: {"n_gt", "n_pred", "n_matched", "instance_diff", "auc_match", "causes": {cause: n},
    "fragments": `fragment_summary`}, "stacked": `stacked_groups` of ours} on one frame directory;
    `crops` collects `fragment_crops` of the map before the split-fragment link."""
    frames = FrameSet.open(frames_dir)
    categories, e = category_vectors(frames)
    gt = GroundTruth.load(frames_dir)
    out: dict = {}
    shows: Optional[dict[tuple[int, int], int]] = None
    flat2d = PointwiseMap2D(frames.intrinsics, e, MappingConfig(cell_size=frames.meta.cell_size))
    for frame in frames:
        flat2d.add(frame, frame.segmentation)
    for name, (_title, make) in VARIANTS.items():
        cfg = make().model_copy(update={"cell_size": frames.meta.cell_size})
        builder = MapBuilder(frames.intrinsics, cfg)
        for frame in frames:
            builder.add(frame, frame.segmentation)
        scene = builder.finish(categories, e, scene_id=frames.meta.scene_id,
                               embedding_space=frames.meta.embedding_space, second_pass=True)
        ctx = EvalContext.create(gt, frames_dir, cfg)
        pred = prediction_from_map(scene, ctx)
        result = score(pred, ctx)
        if shows is None:
            shows = mask_objects(frames, cfg.min_mask_pixels)
        causes = unmatched_causes(pred.cells[:2], ctx.gt_cells[:2], ctx.gt_ids, set(result["matched_ids"]),
                                  scene.observations, shows)
        _went, main = mask_attribution(scene.observations, shows)
        labels = {int(o["id"]): str(o["label"]) for o in gt.objects}
        out[name] = {"n_gt": result["n_gt"], "n_pred": result["n_pred"], "n_matched": result["n_matched"],
                     "instance_diff": result["instance_diff"], "auc_match": result["auc_top"]["match"],
                     "causes": cause_counts(causes), "fragments": fragment_summary(scene, main, labels, cfg)}
        if crops is not None and name == FRAGMENT_VARIANTS[0]:
            crops += fragment_crops(scene, main, labels, ctx, cfg, frames.meta.scene_id)
        if name == "ours":
            baseline = prediction_from_pointwise(*flat2d.finish(), cfg.cell_size, ctx)
            out["stacked"] = stacked_groups(ctx, named_right(pred, ctx, pairs(pred, ctx)), causes,
                                            named_right(baseline, ctx, pairs(baseline, ctx)))
    return out


def table_markdown(per_scene: dict[str, dict], realism: str, seeds_arg: str) -> str:
    rows = list(per_scene.values())
    lines = [f"Profile `{realism}`; seeds {seeds_arg}; mean per scene over {len(rows)} simulated scenes "
             f"({', '.join(per_scene)}). Every evaluated ground-truth object (seen in at least "
             "`min_mask_pixels` pixels) that no instance matches (top-down IoU > 0.5 against the observed "
             "footprint) gets one cause (evals/mapping_causes.py; an instance is an object's own when most of "
             "its masks show that object): never segmented (no mask showing mostly it reached the map), "
             "swallowed (most of its masks went into other objects' instances), split (its masks went into "
             "two or more own instances, none covering half of it), inflated (an own instance covers half of "
             "it or more but is too large for IoU > 0.5), partial (its own instances cover under half of it).", "",
             "| configuration | seen objects | predicted | matched | " + " | ".join(CAUSES) + " | AUC match |",
             "|---|" + "---:|" * (len(CAUSES) + 4)]
    for name, (title, _make) in VARIANTS.items():
        mean = {k: float(np.mean([r[name][k] for r in rows])) for k in ("n_gt", "n_pred", "n_matched", "auc_match")}
        causes = [float(np.mean([r[name]["causes"][c] for r in rows])) for c in CAUSES]
        lines.append(f"| {title} | {mean['n_gt']:.1f} | {mean['n_pred']:.1f} | {mean['n_matched']:.1f} | "
                     + " | ".join(f"{c:.1f}" for c in causes) + f" | {mean['auc_match']:.3f} |")
    total = {g: {k: sum(r["stacked"][g][k] for r in rows) for k in ("objects", "baseline_right")}
             for g in STACKED_GROUPS}
    n = sum(t["objects"] for t in total.values())
    lines += ["", f"Stacked objects (their box footprint lies over another's by half or more), ours "
              f"(MappingConfig()), {n} over the {len(rows)} scenes: what became of each on our map, and how many of "
              "them the 2D point-wise baseline with ground-truth masks names right (top-1). Top-1 over all "
              f"stacked objects, pooled over the scenes (the mapping table averages per scene): ours {total['named right']['objects'] / max(n, 1):.3f}, baseline "
              f"{sum(t['baseline_right'] for t in total.values()) / max(n, 1):.3f}.", "",
              "| on our map | objects | named right by the baseline |", "|---|---:|---:|"]
    lines += [f"| {g} | {t['objects']} | {t['baseline_right']} |" for g, t in total.items()]
    return "\n".join(lines + fragment_tables(rows))


def fragment_tables(rows: list[dict]) -> list[str]:
    """The split-fragment section of table.md: extra instances and same-label fragment pairs by the
    association rule that kept them apart, per configuration; same-label pairs per category before
    and after the split-fragment link."""
    n = len(rows)
    lines = ["", "## Split fragments: instances of one object that association kept apart", "",
             "An object's extra instances are those beyond the heaviest of the instances whose masks mostly "
             "show it (what Inst. Diff counts); a split fragment is a pair of instances with the same label "
             "and the same object. Each is given the association rule the pair fails as built "
             "(evals/mapping_causes.py `fragment_cause`): overlap, cosine under the thresholds (phi_geo > "
             "delta_geo but not linkable); touching (cells shared or adjacent: the continuity merge's reach) with "
             "no continuity merge (the paper's rules), a cosine at most delta_sem_continuous, or shapes that do "
             "not continue each other (two compact footprints; planar ones not collinear); footprints apart; "
             "linkable as built (the pair grew after it was compared). Association has no height or label gate, "
             "so neither can keep a pair apart. Mean per scene (extra instances: same label / other label; "
             "fragment pairs: totals over the scenes).", "",
             "| configuration | extra instances | " + " | ".join(FRAGMENT_CAUSES) + " |",
             "|---|" + "---:|" * (len(FRAGMENT_CAUSES) + 1)]
    for name, (title, _make) in VARIANTS.items():
        ex = {c: [sum(r[name]["fragments"]["extras"][c][k] for r in rows) / n for k in ("same_label", "other_label")]
              for c in FRAGMENT_CAUSES}
        total = [sum(v[k] for v in ex.values()) for k in (0, 1)]
        lines.append(f"| {title} | {total[0]:.1f} / {total[1]:.1f} | "
                     + " | ".join(f"{v[0]:.1f} / {v[1]:.1f}" for v in ex.values()) + " |")
    lines += ["", "| configuration | same-label fragment pairs | " + " | ".join(FRAGMENT_CAUSES) + " |",
              "|---|" + "---:|" * (len(FRAGMENT_CAUSES) + 1)]
    for name, (title, _make) in VARIANTS.items():
        causes = {c: sum(r[name]["fragments"]["fragment_causes"][c] for r in rows) for c in FRAGMENT_CAUSES}
        lines.append(f"| {title} | {sum(causes.values())} | " + " | ".join(str(v) for v in causes.values()) + " |")
    before, after = (VARIANTS[v][0] for v in FRAGMENT_VARIANTS)
    lines += ["", f"Same-label instance pairs per category, totals over the scenes, {before} -> {after}: split "
              "fragments (one object) and pairs of different objects (of them, pairs where one instance's object is "
              "of another category: a mislabelled neighbour). Categories with a fragment or a mislabelled pair.", "",
              "| label | split fragments | different objects | of them mislabelled |", "|---|---:|---:|---:|"]
    labels = sorted({lab for r in rows for v in FRAGMENT_VARIANTS for lab in r[v]["fragments"]["pairs"]})
    for lab in labels:
        got = [[sum(r[v]["fragments"]["pairs"].get(lab, {}).get(k, 0) for r in rows) for v in FRAGMENT_VARIANTS]
               for k in ("fragments", "different", "named_wrong")]
        if any(got[0]) or any(got[2]):
            lines.append(f"| {lab} | " + " | ".join(f"{a} -> {b}" for a, b in got) + " |")
    lines += ["", "`fragments.png`: the first split fragment of each cause on the map before the split-fragment link."]
    return lines


def run_study(seeds: list[int], out: Path, *, realism: str = "realistic", seeds_arg: Optional[str] = None,
              work: Optional[Path] = None, log=print) -> dict:
    """Render (or reuse, under `work`) each seed's frames, diagnose them, write table.md and summary.json."""
    seeds_arg = seeds_arg or ",".join(map(str, seeds))
    per_scene: dict[str, dict] = {}
    crops: list[dict] = []
    with scene_frames(work) as cache:
        for seed in seeds:
            frames_dir = cache.prepare(seed, "small", False, realism)
            result = study_scene(frames_dir, crops)
            per_scene[f"sim-small-{seed}"] = result
            log(f"{realism} seed {seed}: " + "; ".join(
                f"{name} matched {result[name]['n_matched']}/{result[name]['n_gt']} {result[name]['causes']}"
                for name in VARIANTS))
    command = study_command("mapping_causes", seeds_arg, realism, out)
    write_table(out, f"Unmatched seen objects by cause ({realism} profile)", command,
                table_markdown(per_scene, realism, seeds_arg),
                {"seeds": seeds, "realism": realism, "scenes": per_scene})
    draw_fragments(crops, out / "fragments.png")
    return per_scene


def command(seeds: Seeds = "0-4", realism: Realism = "realistic",
            out: Out = Path("docs/results/mapping-causes-tuning"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, realism=realism, seeds_arg=seeds, work=work,
                                            log=log_stderr))


def main(argv: list[str] | None = None) -> int:
    return study_main("mapping_causes", __doc__, command, argv)


if __name__ == "__main__":
    sys.exit(main())
