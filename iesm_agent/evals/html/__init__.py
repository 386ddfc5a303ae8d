"""Self-contained HTML pages of results: the eval report (`iesm eval` writes `report.html`,
`iesm report RUN_DIR [RUN_DIR_B]` rebuilds it) and the map viewer (`iesm view MAP`).

One file each, no network: inline CSS and JavaScript from `assets/`, data embedded as escaped
JSON, maps as inline SVG. `shapes` traces a map into vector outlines, `run_data` reads run
directories, `report_page` and `map_page` write the markup, `page` the shell.
"""

from __future__ import annotations

from pathlib import Path

from .page import write_page

REPORT = "report.html"


def write_report(run_dirs: list[str | Path], out: str | Path) -> int:
    """Write the report of one run (or two compared) to `out`; returns its size in bytes."""
    from .report_page import report_html
    from .run_data import MAX_PAGE_BYTES, report_data

    return write_page(out, report_html(report_data(run_dirs)), MAX_PAGE_BYTES)


def write_map_view(map_ref: str | Path, out: str | Path) -> int:
    """Write the viewer of the map `map_ref` (a file or shipped name) to `out`; returns its size."""
    from ...store.refs import open_map
    from .map_page import MAX_MAP_PAGE_BYTES, map_html

    return write_page(out, map_html(open_map(map_ref), str(map_ref)), MAX_MAP_PAGE_BYTES)
