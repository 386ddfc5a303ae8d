"""The page shell shared by the report and the map viewer: one self-contained HTML file with the
shipped CSS and JavaScript inlined (`assets/`, package data) and the data embedded as JSON.

Everything that comes from a run or a map (queries, captions, labels, replies) is untrusted
text: markup escapes it with `html.escape`, and `embed_json` writes JSON that cannot end its
`<script>` element or open a comment (`<`, `>`, `&` and the JavaScript line separators become
`\\uXXXX` escapes; `JSON.parse` restores them). The scripts put data into the page with
`textContent` and attributes only, never as markup.
"""

from __future__ import annotations

import json
from html import escape
from pathlib import Path

from ...errors import IesmError
from ...fileio import utf8_text, write_text

ASSETS = Path(__file__).with_name("assets")

_JSON_ESCAPES = {ord("<"): "\\u003c", ord(">"): "\\u003e", ord("&"): "\\u0026",
                 0x2028: "\\u2028", 0x2029: "\\u2029"}


def embed_json(data) -> str:
    """`data` as JSON safe inside `<script type="application/json">` (no `</script>`, no `<!--`)."""
    return json.dumps(data, ensure_ascii=False, separators=(",", ":"), allow_nan=False).translate(_JSON_ESCAPES)


def asset(name: str) -> str:
    """The text of a shipped asset (CSS or JavaScript)."""
    try:
        return (ASSETS / name).read_text(encoding="utf-8")
    except OSError as exc:
        raise IesmError(f"missing page asset (broken installation?): {exc}", ASSETS / name) from exc


def page(title: str, body: str, data, scripts: list[str], kind: str) -> str:
    """A whole HTML document: `body` (markup, already escaped), `data` embedded as JSON in
    `<script id="data">`, then the inline `scripts` (asset names) run at the end of the body."""
    code = "\n".join(asset(s) for s in scripts)
    if "</script" in code.lower():
        raise IesmError("a page script contains '</script'", ASSETS)
    return ("<!DOCTYPE html>\n"
            f'<html lang="en"><head><meta charset="utf-8">'
            '<meta name="viewport" content="width=device-width, initial-scale=1">'
            "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
            "style-src 'unsafe-inline'; script-src 'unsafe-inline'; img-src data:\">"
            f"<title>{escape(title)}</title><style>{asset('style.css')}</style></head>"
            f'<body data-page="{kind}">{body}'
            f'<script type="application/json" id="data">{embed_json(data)}</script>'
            f"<script>{code}</script></body></html>\n")


def write_page(path: str | Path, html: str, limit: int) -> int:
    """Write `html` atomically; refuse a page over `limit` bytes (the stated bound). Returns its size.
    Text that is not valid UTF-8 (a path's undecodable bytes) is written as U+FFFD."""
    html = utf8_text(html)
    size = len(html.encode("utf-8"))
    if size > limit:
        raise IesmError(f"the page would be {size / 1e6:.1f} MB, over the {limit / 1e6:.0f} MB bound", path)
    write_text(path, html)
    return size
