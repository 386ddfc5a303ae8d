"""`iesm sim`: generate a seeded synthetic apartment and write its RGB-D frames + ground truth."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from ..errors import IesmError
from ..fileio import staged_directory
from .outputs import check_frame_output
from .progress import progress_bar


def _load_faults(path: Optional[Path], seed: int):
    from pydantic import ValidationError

    from ..sim import FaultConfig

    if path is None:
        return FaultConfig(seed=seed)
    from ..fileio import load_json, validation_message

    data = load_json(path, max_bytes=1024 * 1024)
    if not isinstance(data, dict):
        raise IesmError("a fault config is a JSON object", path)
    try:
        return FaultConfig.model_validate({"seed": seed, **data})
    except ValidationError as exc:
        message, field = validation_message(exc)
        raise IesmError(message, path, field) from None


def register(app: typer.Typer) -> None:
    @app.command("sim")
    def sim_cmd(
        out: Path = typer.Option(..., "--out", help="frame directory to create"),
        seed: int = typer.Option(0, "--seed", min=0, max=2**32 - 1, help="scene seed (same seed, same scene)"),
        size: str = typer.Option("small", "--size", help="small (a flat, ~75 instances) | hm3d (30 m x 30 m, ~330 instances)"),
        open_plan: bool = typer.Option(False, "--open-plan", help="two public rooms share no wall"),
        faults: Optional[Path] = typer.Option(None, "--faults", help="JSON segmenter fault config (FaultConfig)"),
        realism: str = typer.Option("realistic", "--realism",
                                    help="realistic (sensor noise, lighting, mask and embedding errors) | easy "
                                         "(exact depth, flat shading, near-exact masks: for unit tests)"),
        force: bool = typer.Option(False, "--force", help="replace a non-empty existing DIR"),
    ) -> None:
        """Generate a synthetic apartment: RGB-D frames, poses, masks + embeddings, ground truth."""
        from ..sim import generate_scene, render_frames
        from ..sim.catalog import PROGRAMS
        from ..sim.realism import get_profile

        if size not in PROGRAMS:
            raise IesmError(f"unknown --size {size!r} (choose from {', '.join(PROGRAMS)})")
        profile = get_profile(realism)
        check_frame_output(out, force, "sim")
        config = _load_faults(faults, seed)
        world = generate_scene(seed, size, open_plan)
        with staged_directory(out) as stage, progress_bar("rendering") as bar:  # a killed run's stage goes next run
            task = bar.add_task("frames", total=len(world.poses))
            summary = render_frames(world, stage, config, progress=lambda i: bar.advance(task), realism=profile)
        opened = ", ".join(" + ".join(p) for p in summary["open_plan"]) or "none"
        print(f"scene {summary['scene_id']}: {summary['rooms']} rooms, {summary['instances']} instances "
              f"({summary['structural']} walls/doors/windows, {summary['stacked']} stacked), "
              f"{summary['frames']} frames; {summary['seen']} instances seen; open plan: {opened}")
        print(f"embedding space: {summary['embedding_space']}; realism: {summary['realism']}")
        print(f"wrote {out}/ (scene.json, intrinsics.json, frames/, gt/)")
