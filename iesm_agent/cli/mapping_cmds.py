"""`iesm build-map` (instance-level 2.5D map from RGB-D frames) and `iesm eval-map` (its
metrics against simulator ground truth)."""

from __future__ import annotations

import json
from pathlib import Path

import typer

from ..errors import IesmError


def register(app: typer.Typer) -> None:
    @app.command("build-map")
    def build_map_cmd(
        frames_dir: Path = typer.Argument(..., help="frame directory (scene.json, intrinsics.json, frames/)"),
        output: Path = typer.Option(..., "-o", "--output", help="the .iesm file to write"),
        no_second_pass: bool = typer.Option(False, "--no-second-pass",
                                            help="skip the second association-fusion pass (ablation)"),
        cell_size: float = typer.Option(None, "--cell-size", help="grid cell in metres (default: scene.json's)"),
    ) -> None:
        """Build an instance-level 2.5D map from RGB-D frames with masks and embeddings."""
        from ..config import MappingConfig
        from ..frames import FrameSet
        from ..mapping.build import build_map
        from ..store import save_map
        from .progress import progress_bar

        if not output.parent.resolve().is_dir():
            raise IesmError("output directory does not exist", output)
        if cell_size is not None and not cell_size > 0:
            raise IesmError(f"cell size must be > 0, got {cell_size}", None, "--cell-size")
        frames = FrameSet.open(frames_dir)
        if len(frames) == 0:
            raise IesmError("the frame set has no frames (n_frames is 0)", frames_dir / "scene.json", "n_frames")
        cfg = MappingConfig() if cell_size is None else MappingConfig(cell_size=cell_size)
        with progress_bar("build-map") as progress:
            task = progress.add_task("build-map", total=len(frames))
            scene = build_map(frames, cfg, second_pass=not no_second_pass,
                              on_frame=lambda _i: progress.advance(task))
        size = save_map(scene, output)  # temp file + rename: nothing half-written on failure
        m = scene.meta
        typer.echo(f"wrote {output} ({size} bytes): {len(scene.instances)} instances from {m['frames']} frames "
                   f"({m['instances_first_pass']} before the second pass, {m['second_pass_merges']} merged); "
                   f"grid {scene.grid.height}x{scene.grid.width} @ {scene.grid.cell_size} m; "
                   f"{scene.occupancy.multi_occupancy_cells} multi-occupancy cells")

    @app.command("eval-map")
    def eval_map_cmd(
        map_path: Path = typer.Argument(..., help="a .iesm map built from the frames in --gt"),
        gt_dir: Path = typer.Option(..., "--gt", help="frame directory with gt/ (simulator ground truth)"),
        as_json: bool = typer.Option(False, "--json", help="print JSON"),
    ) -> None:
        """Mapping metrics (paper Sec. 4.1): AUC^top, Instance Diff, top-down Acc/mAcc/mIoU/F-mIoU, small objects."""
        from ..sim.ground_truth import GroundTruth
        from ..evals.mapping import evaluate_map
        from ..store import open_map

        scene = open_map(map_path)
        result = evaluate_map(scene, GroundTruth.load(gt_dir), gt_dir)
        if as_json:
            typer.echo(json.dumps(result, indent=2, ensure_ascii=False))
            return
        typer.echo(format_result(result))


def format_result(r: dict) -> str:
    """Plain-text summary of `evaluate_map` output."""
    a, s, t = r["auc_top"], r["small"], r["topdown"]
    lines = [f"instances: {r['n_pred']} predicted, {r['n_gt']} ground truth, {r['n_matched']} matched "
             f"(IoU > 0.5); Instance Diff {r['instance_diff']}",
             f"AUC^top  pred {a['pred']:.3f}  gt {a['gt']:.3f}  match {a['match']:.3f}  (top-1 match {a['top1_match']:.3f})",
             f"top-down Acc {t['acc']:.3f}  mAcc {t['macc']:.3f}  mIoU {t['miou']:.3f}  F-mIoU {t['fmiou']:.3f}",
             f"small objects ({', '.join(s['categories']) or '-'}): AUC^top pred {s['auc_top']['pred']:.3f}  "
             f"gt {s['auc_top']['gt']:.3f}  match {s['auc_top']['match']:.3f}; Instance Diff {s['instance_diff']}",
             f"stacked objects ({r['stacked']['n_gt']}): top-1 of matched {r['stacked']['top1_match']:.3f}, "
             f"of all {r['stacked']['top1_gt']:.3f}"]
    lines += [f"{key}: {json.dumps(value)}" for key, value in r.items()
              if key not in ("auc_top", "small", "topdown", "stacked", "n_pred", "n_gt", "n_matched", "instance_diff")]
    return "\n".join(lines)
