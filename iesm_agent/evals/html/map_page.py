"""The map viewer page (`iesm view`): the instance map as one inline SVG (instances coloured by
category, rooms outlined, stacked cells hatched), a legend, a search box over labels and
captions, and an info panel (`assets/map.js`: hover or click an instance, or pick a result)."""

from __future__ import annotations

from html import escape

from ...store.model import SceneMap
from .page import page
from .shapes import MAX_SIDE, map_layers, svg_markup

#: the largest map page written (bytes)
MAX_MAP_PAGE_BYTES = 16_000_000


def map_html(scene: SceneMap, source: str) -> str:
    """The whole viewer page of `scene` (`source`: how the map was named, shown in the header)."""
    layers = map_layers(scene)
    legend = "".join(f'<li><span class="swatch" style="background:{e["colour"]}" aria-hidden="true"></span>'
                     f'{escape(e["label"])}</li>' for e in layers["legend"][:20])
    others = len(layers["legend"]) - 20
    if others > 0:
        legend += f'<li><span class="swatch other" aria-hidden="true"></span>{others} more categories</li>'
    legend += '<li><span class="swatch stacked-swatch" aria-hidden="true"></span>stacked cells</li>'
    g = scene.grid
    coarse = (f", drawn at {layers['cell']:.3g} m cells (at most {MAX_SIDE} a side)"
              if layers["coarsened"] > 1 else "")
    body = (
        f'<main class="viewer"><header><h1>Map {escape(scene.scene_id)}</h1>'
        f'<p><code>{escape(source)}</code>: {len(scene.instances)} instances, {len(scene.rooms)} rooms, '
        f'{layers["stacked_cells"]} stacked cells; grid {g.height} x {g.width} at {g.cell_size:.3g} m{coarse}. '
        'Self-contained page (no network).</p></header>'
        '<div class="viewer-split"><div class="map-pane">'
        f'{svg_markup(layers, f"instance map of {scene.scene_id}")}</div>'
        '<div class="side"><form id="search" role="search" aria-label="Search instances" onsubmit="return false">'
        '<label>Search labels and captions <input id="q" type="search" autocomplete="off"></label></form>'
        '<p id="hits" role="status" aria-live="polite"></p><ul id="results" class="results"></ul>'
        '<section id="info" role="region" aria-label="Instance details" aria-live="polite" tabindex="-1">'
        '<p class="note">Hover or click an instance (or search) to see its label, room, caption and tags.</p>'
        f'</section><h2>Legend</h2><ul class="legend">{legend}</ul></div></div></main>')
    data = {"scene": scene.scene_id, "instances": [
        {k: i[k] for k in ("id", "label", "room", "caption", "tags", "colour")} for i in layers["instances"]]}
    return page(f"Map {scene.scene_id}", body, data, ["common.js", "map.js"], "map")
