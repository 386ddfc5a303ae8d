"""`iesm rooms` (room segmentation, per-instance rooms, obstacle map) and `iesm path` (plan a path
to an instance)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer

from ..errors import IesmError
from ..fileio import read_npz


#: largest --robot-radius (m)
MAX_ROBOT_RADIUS = 10.0


def _parse_xy(text: str) -> tuple[float, float]:
    try:
        x, y = (float(v) for v in text.split(","))
    except ValueError:
        raise IesmError(f"expected X,Y in metres, got {text!r}", None, "--start") from None
    if not all(map(lambda v: abs(v) < 1e6, (x, y))):  # False for nan
        raise IesmError(f"expected finite X,Y in metres, got {text!r}", None, "--start")
    return x, y


def _load_cell_labels(path: Path, shape: tuple[int, int]):
    """Per-cell labels from an .npz with `labels` (H, W) int and `names` (L,) str."""
    import numpy as np

    from ..rooms import CellLabels

    def check(name: str, found: tuple[int, ...], dtype) -> None:  # before the array is read
        if name == "labels" and (found != shape or dtype.kind not in "iu"):
            raise IesmError(f"labels must be integer {shape} (the map grid), got {dtype} {found}", path)
        if name == "names" and (len(found) != 1 or found[0] > 100_000):
            raise IesmError(f"names must be a list of at most 100,000 strings, got shape {found}", path)

    data = read_npz(path, ("labels", "names"), kinds={"labels": "iu", "names": "U"}, check=check)
    labels, names = data["labels"], [str(n) for n in data["names"]]
    if labels.max(initial=-1) >= len(names) or labels.min(initial=-1) < -1:
        raise IesmError(f"label indices must be -1 or below {len(names)} (the number of names)", path)
    return CellLabels(labels.astype(np.int32), names)


def register(app: typer.Typer) -> None:
    @app.command("rooms")
    def rooms_cmd(
        map_path: Path = typer.Argument(..., metavar="MAP", help="a built .iesm map (iesm build-map)"),
        output: Path = typer.Option(..., "-o", "--output", help="the .iesm file to write (may be MAP)"),
        frames: Optional[Path] = typer.Option(None, "--frames",
                                              help="frame directory the map was built from (labels: --room-labels)"),
        room_labels: Optional[str] = typer.Option(
            None, "--room-labels", metavar="sim|clip",
            help="with --frames: 'sim' simulated CLIP-like labels from the simulator's ground truth (default), "
                 "'clip' CLIP frame features against room embeddings (iesm segment --segmenter sam-clip)"),
        cell_labels: Optional[Path] = typer.Option(None, "--cell-labels",
                                                   help=".npz with per-cell labels (H, W) and names (real data)"),
        split: bool = typer.Option(True, "--split/--no-split", help="contextual split of open-plan space"),
        seed: int = typer.Option(0, "--seed", min=0, max=2**32 - 1, help="seed of the simulated labels"),
    ) -> None:
        """Segment rooms; store rooms, room map, each instance's room and the obstacle map."""
        from ..nav import with_obstacles
        from ..rooms import RoomConfig, segment_rooms
        from ..store import save_map
        from ..store.refs import open_map

        if (frames is None) == (cell_labels is None):
            raise IesmError("give exactly one of --frames DIR or --cell-labels FILE.npz", None, "rooms")
        if room_labels not in (None, "sim", "clip"):
            raise IesmError(f"expected sim or clip, got {room_labels!r}", None, "--room-labels")
        if room_labels is not None and frames is None:
            raise IesmError("--room-labels chooses how --frames DIR is read; give --frames DIR", None,
                            "--room-labels")
        if not output.parent.resolve().is_dir():
            raise IesmError("output directory does not exist", output)
        clip = None
        if frames is not None and room_labels == "clip":
            from ..rooms.clip_labels import ClipFrameLabels

            clip = ClipFrameLabels(frames)  # checks the directory before the map is read
        scene = open_map(map_path)
        if clip is not None:
            labels = clip.cell_labels(scene.grid)
        elif frames is not None:
            from ..sim.room_labels import ViewpointLabels

            labels = ViewpointLabels(frames, seed=seed).cell_labels(scene.grid)
        else:
            labels = _load_cell_labels(cell_labels, (scene.grid.height, scene.grid.width))
        result = with_obstacles(segment_rooms(scene, labels, RoomConfig(split=split)))
        size = save_map(result, output)
        rooms = ", ".join(f"{r.label} ({int((result.room_map == r.id).sum() * scene.grid.cell_size ** 2)} m2)"
                          for r in result.rooms)
        typer.echo(f"wrote {output} ({size} bytes): {len(result.rooms)} rooms: {rooms or '-'}; "
                   f"{int(result.obstacles.sum())} obstacle cells; {result.meta['room_segmentation']}")

    @app.command("path")
    def path_cmd(
        map_path: Path = typer.Argument(..., metavar="MAP", help="a .iesm map, a JSON map or a shipped map name"),
        to: int = typer.Option(..., "--to", help="goal instance id"),
        start: str = typer.Option(..., "--start", help="start X,Y in metres"),
        png: Optional[Path] = typer.Option(None, "--png", help="draw the path into this PNG"),
        robot_radius: float = typer.Option(0.2, "--robot-radius", help="obstacle inflation, metres"),
        as_json: bool = typer.Option(False, "--json", help="print the result as JSON"),
    ) -> None:
        """Plan a path to an instance: length in metres, reachable or not (exit 1 when not)."""
        from ..nav import PlanningGrid
        from ..nav import ObstacleConfig
        from ..store.refs import open_map

        xy = _parse_xy(start)
        if png is not None and not png.parent.resolve().is_dir():
            raise IesmError("output directory does not exist", png)
        if not 0 <= robot_radius <= MAX_ROBOT_RADIUS:  # also refuses nan
            raise IesmError(f"expected a radius from 0 to {MAX_ROBOT_RADIUS:g} m, got {robot_radius}", None,
                            "--robot-radius")
        planning = PlanningGrid(open_map(map_path), ObstacleConfig(robot_radius=robot_radius))
        result = planning.plan(to, xy)
        if result.status == "unknown_instance":
            raise IesmError(result.message, map_path, "--to")
        if png is not None:
            from ..nav.render import render_path

            render_path(planning, result, png)
        if as_json:
            typer.echo(json.dumps(result.model_dump(mode="json"), indent=2))
        elif result.reachable:
            typer.echo(f"reachable: {result.length_m:.2f} m to instance {to} in {len(result.waypoints) - 1} "
                       f"straight legs; stops {result.goal_distance_m:.2f} m from it")
        else:
            typer.echo(f"not reachable ({result.status}): {result.message}")
        if not as_json:
            typer.echo(f"walls: {result.walls}")
        if not result.reachable:
            raise typer.Exit(1)
