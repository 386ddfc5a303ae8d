"""`iesm caption`: captions, tags and rooms for every instance of a map built from frames."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer

from ..errors import IesmError

#: built-in providers that accept `vision=True` (plugins decide for themselves)
_VISION_FLAG = ("openai", "ollama", "openai-compat")


def _captioner(provider: str, base_url: Optional[str], cache: bool, concurrency: int):
    from ..captioning import OfflineCaptioner, VisionCaptioner

    if provider == "offline":
        return OfflineCaptioner()
    from ..providers import get_model

    opts = {"vision": True} if provider.partition(":")[0] in _VISION_FLAG else {}
    model = get_model(provider, base_url=base_url, cache=True if cache else None,
                      concurrency=concurrency, **opts)
    return VisionCaptioner(model, concurrency=concurrency)


def register(app: typer.Typer) -> None:
    @app.command("caption")
    def caption_cmd(
        map_path: Path = typer.Argument(..., metavar="MAP", help="a .iesm map built from frames (iesm build-map)"),
        frames: Optional[Path] = typer.Option(None, "--frames", help="the frame directory the map was built from"),
        output: Optional[Path] = typer.Option(None, "-o", "--output", help="the .iesm file to write (default: MAP)"),
        provider: str = typer.Option("offline", "--provider", "-p",
                                     help="offline (pixels and geometry, no model) or a vision model spec, "
                                          "e.g. openai:gpt-4o-mini, ollama:llama3.2-vision"),
        keyframes: int = typer.Option(3, "--keyframes", "-k", help="at most this many keyframes per instance"),
        base_url: Optional[str] = typer.Option(None, "--base-url", help="OpenAI-compatible endpoint URL"),
        cache: bool = typer.Option(True, "--cache/--no-cache", help="cache model replies on disk"),
        concurrency: int = typer.Option(4, "--concurrency", help="instances captioned at once (vision models)"),
        strip: bool = typer.Option(False, "--strip", help="remove captions and caption tags instead "
                                                         "(labels-only ablation; no frames needed)"),
    ) -> None:
        """Caption every instance (keyframe crops -> captioner -> caption + tags) and write the map."""
        from ..captioning import caption_map, strip_captions
        from ..store import open_map, resolve_map_path, save_map
        from .progress import progress_bar

        output = output or map_path
        if not output.parent.resolve().is_dir():
            raise IesmError("output directory does not exist", output)
        if keyframes < 1:
            raise IesmError(f"must be >= 1, got {keyframes}", None, "--keyframes")
        if concurrency < 1:
            raise IesmError(f"must be >= 1, got {concurrency}", None, "--concurrency")
        scene = open_map(resolve_map_path(map_path))
        if strip:
            size = save_map(strip_captions(scene), output)
            typer.echo(f"wrote {output} ({size} bytes): captions of {len(scene.instances)} instances removed")
            return
        if frames is None:
            raise IesmError("give the frame directory the map was built from", None, "--frames")
        captioner = _captioner(provider, base_url, cache, concurrency)
        with progress_bar("caption") as bar:
            tasks: dict[str, int] = {}

            def progress(stage: str, done: int, total: int) -> None:
                if stage not in tasks:
                    tasks[stage] = bar.add_task(stage, total=total)
                bar.update(tasks[stage], completed=done, total=total)

            captioned = caption_map(scene, frames, captioner, keyframes=keyframes, progress=progress)
        size = save_map(captioned, output)
        failures = json.loads(captioned.meta["caption_failures"])
        coloured = sum("color" in i.tags for i in captioned.instances)
        typer.echo(f"wrote {output} ({size} bytes): {len(captioned.instances)} instances captioned by "
                   f"{captioner.name}, {coloured} with a colour, {len(failures)} fell back to the offline "
                   "captioner" + (f" (e.g. instance {next(iter(failures))}: {next(iter(failures.values()))})"
                                  if failures else ""))
