"""`iesm segment`: read a recording in any supported layout (or our own frame directory), check
and gravity-align it, run a segmenter once (serially or on Ray Data) and write our frame directory
with masks and embeddings, so that `iesm build-map` needs no model."""

from __future__ import annotations

import shutil
import time
from pathlib import Path
from typing import Optional

import typer

from ..errors import IesmError
from ..fileio import read_text, utf8_text
from .outputs import check_frame_output


#: most names a --categories or --rooms file may list
MAX_NAMES = 10_000


def _lines(path: Path | None) -> list[str] | None:
    if path is None:
        return None
    names = [line.strip() for line in read_text(path, max_bytes=1024 * 1024, max_lines=MAX_NAMES).split("\n")
             if line.strip()]
    if not names:
        raise IesmError("no names in the file (one per line)", path)
    return names


def _sim_segmenter(frames):
    """The simulator's segmenter for a frame directory written by `iesm sim` (needs gt/ and inst.png)."""
    from ..sim.ground_truth import GroundTruth
    from ..sim.segmenter import SyntheticSegmenter

    gt = GroundTruth.load(frames.directory)
    return SyntheticSegmenter({int(o["id"]): str(o["label"]) for o in gt.objects}, space=frames.meta.embedding_space)


def register(app: typer.Typer) -> None:
    @app.command("segment")
    def segment_cmd(
        source: Path = typer.Argument(..., help="a recording (7-Scenes/3DMatch, Replica, ScanNet, TUM) or our frame directory"),
        output: Optional[Path] = typer.Option(None, "-o", "--output",
                                              help="frame directory to write (default for our layout: in place)"),
        segmenter: str = typer.Option("geometric", "--segmenter", help="geometric, sam-clip or sim"),
        layout: Optional[str] = typer.Option(None, "--layout", help="ours, 7scenes, 3dmatch, replica, scannet, tum (default: detected)"),
        depth_scale: Optional[float] = typer.Option(None, "--depth-scale", help="raw depth units per metre (default: the format's)"),
        skip_bad: bool = typer.Option(False, "--skip-bad-frames", help="skip (and count) frames with a missing file or a bad pose"),
        no_align: bool = typer.Option(False, "--no-align", help="keep the recording's world (no gravity alignment)"),
        every: int = typer.Option(1, "--every", min=1, help="use every N-th frame"),
        use_ray: bool = typer.Option(False, "--ray", help="run the segmenter on Ray Data (local, or RAY_ADDRESS)"),
        workers: Optional[int] = typer.Option(None, "--workers", min=1, help="Ray actors (default: GPUs, else CPUs)"),
        categories_file: Optional[Path] = typer.Option(None, "--categories", help="category names, one per line (sam-clip)"),
        rooms_file: Optional[Path] = typer.Option(None, "--rooms", help="room names, one per line (sam-clip)"),
        sam_checkpoint: Optional[str] = typer.Option(None, "--sam-checkpoint", help="SAM .pth checkpoint"),
        sam_model: str = typer.Option("vit_h", "--sam-model", help="vit_h, vit_l, vit_b (tiny: tests)"),
        clip_model: str = typer.Option("ViT-B-32", "--clip-model", help="open_clip architecture"),
        clip_pretrained: Optional[str] = typer.Option(None, "--clip-pretrained", help="open_clip checkpoint path or cached tag"),
        clip_config: Optional[str] = typer.Option(None, "--clip-config", help="open_clip model config JSON to register"),
        device: Optional[str] = typer.Option(None, "--device", help="cpu or cuda (default: cuda when available)"),
        points_per_side: int = typer.Option(32, "--points-per-side", min=1, help="SAM point grid"),
        random_weights: bool = typer.Option(False, "--random-weights", help="sam-clip without checkpoints (tests only)"),
        force: bool = typer.Option(False, "--force", help="replace a non-empty -o that is a frame directory of ours"),
    ) -> None:
        """Run perception once: masks + embeddings in our frame layout, from any supported recording."""
        from ..frames import FrameSet, matching_layouts, open_recording
        from ..fileio import staged_directory
        from ..frames.convert import import_recording
        from ..segment import SEGMENTERS, SegmenterSpec
        from ..segment.run import segment_frame_set
        from .progress import progress_bar

        if segmenter not in SEGMENTERS:
            raise IesmError(f"unknown segmenter {segmenter!r} (choose from {', '.join(SEGMENTERS)})", None, "--segmenter")
        if use_ray and segmenter == "sim":
            raise IesmError("the simulator's segmenter runs serially (drop --ray)", None, "--ray")
        spec = SegmenterSpec(name=segmenter, sam_checkpoint=sam_checkpoint, sam_model=sam_model, clip_model=clip_model,
                             clip_pretrained=clip_pretrained, clip_config=clip_config, device=device,
                             points_per_side=points_per_side, random_weights=random_weights,
                             **({"pred_iou_thresh": 0.0, "stability_score_thresh": 0.0} if random_weights else {}))
        categories, rooms = _lines(categories_file), _lines(rooms_file)
        found = matching_layouts(source)
        if not found and layout is None:
            from ..frames.detect import EXPECTED

            raise IesmError(f"no frames found ({EXPECTED})", source)
        kind = layout or found[0]
        if layout is None and len(found) > 1:
            typer.echo(f"iesm: warning: {source} looks like {' and '.join(found)}: read as {kind} "
                       f"(--layout chooses)", err=True)
        if kind != "ours" and output is not None:
            check_frame_output(output, force, "segment", source)
        backend = "ray" if use_ray else "serial"
        timings: dict[str, float] = {}

        def run_segmenter(frames: FrameSet, seg_dir: Path):
            with progress_bar("segment") as progress:
                task = progress.add_task(f"segment ({segmenter}, {backend})", total=len(frames))
                seg = _sim_segmenter(frames) if segmenter == "sim" else None
                return segment_frame_set(frames, seg_dir, spec=spec, segmenter=seg, backend=backend, workers=workers,
                                         categories=categories, rooms=rooms, on_frame=lambda _i: progress.advance(task))

        if kind == "ours":
            if output is not None and output.resolve() != source.resolve():
                raise IesmError("our own frame directory is segmented in place (drop -o)", output)
            frames = FrameSet.open(source)
            stage = source / ".iesm-segment-tmp"
            shutil.rmtree(stage, ignore_errors=True)
            try:
                report = run_segmenter(frames, stage)
                for path in sorted(stage.glob("*.seg.npz")):
                    path.replace(source / "frames" / path.name)
            finally:
                shutil.rmtree(stage, ignore_errors=True)
            out_dir, lines = source, []
        else:
            if output is None:
                raise IesmError(f"{source} is a {kind} recording: give -o OUT for the frame directory to write", None,
                                "-o")
            recording = open_recording(source, kind, depth_scale)
            recording.refs = recording.refs[::every]
            with staged_directory(output) as stage:
                t0 = time.perf_counter()
                with progress_bar("read") as progress:
                    task = progress.add_task(f"read {kind}", total=len(recording))
                    imported = import_recording(recording, stage, scene_id=utf8_text(output.name),
                                                embedding_space="none",
                                                categories=[], skip_bad=skip_bad, align=not no_align,
                                                on_frame=lambda _f: progress.advance(task))
                timings["read + check + align + write"] = (time.perf_counter() - t0) / imported.n_frames
                frames = FrameSet.open(stage)
                report = run_segmenter(frames, stage / "frames")
            out_dir, lines = output, imported.lines()
        timings[f"segment ({segmenter}, {backend})"] = report.seconds / max(report.n_frames, 1)
        k = frames.intrinsics
        for line in lines:
            typer.echo(line)
        for line in report.notes:
            typer.echo(line)
        typer.echo(f"wrote {out_dir}: {report.n_frames} frames ({k.width} x {k.height}), {report.n_masks} masks "
                   f"({report.n_masks / max(report.n_frames, 1):.1f} per frame), embedding space {report.space}")
        typer.echo("time per frame: " + ", ".join(f"{name} {1000 * s:.0f} ms" for name, s in timings.items()))
