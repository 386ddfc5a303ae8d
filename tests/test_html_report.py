"""The HTML report (`iesm eval` / `iesm report`) and the map viewer (`iesm view`).

Two modes. Headless Chromium, when installed (`make test` installs Debian's `chromium` when it
can; `IESM_CHROMIUM` names another binary, `IESM_CHROMIUM=none` acts as if there were none),
opens the pages of the demo run, writes a
screenshot of each and checks the DOM after the scripts ran: rows present, filters from the URL
hash change the row count, an opened query shows its experts and map, hostile text stays text.
Without a browser those tests are skipped (the reason says so) and the static checks still run:
the page structure and the embedded data read with `html.parser`.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

from iesm_agent.cli import run
from iesm_agent.errors import IesmError
from iesm_agent.evals.html.page import embed_json, write_page
from iesm_agent.evals.html.run_data import wilson
from iesm_agent.evals.html.shapes import outline_path
from iesm_agent.evals.journal import read_journal

HOSTILE = '</script><script>alert("x")</script><!-- & \u2028'
PNG = b"\x89PNG\r\n\x1a\n"
VOID = {"meta", "input", "br", "img", "hr", "link", "col", "area", "base", "embed", "source", "track", "wbr"}


# ---------------------------------------------------------------- a small DOM from html.parser
class Node:
    def __init__(self, tag: str, attrs: dict, parent: "Node | None"):
        self.tag, self.attrs, self.parent, self.children = tag, attrs, parent, []

    def text(self) -> str:
        return "".join(c if isinstance(c, str) else c.text() for c in self.children)

    def all(self, tag: str | None = None, **attrs) -> list["Node"]:
        """Descendants with `tag` whose attributes contain `attrs` (`cls` matches one class)."""
        out = []
        for c in self.children:
            if isinstance(c, str):
                continue
            classes = c.attrs.get("class", "").split()
            if ((tag is None or c.tag == tag) and ("cls" not in attrs or attrs["cls"] in classes)
                    and all(c.attrs.get(k) == v for k, v in attrs.items() if k != "cls")):
                out.append(c)
            out += c.all(tag, **attrs)
        return out

    def one(self, tag: str | None = None, **attrs) -> "Node":
        found = self.all(tag, **attrs)
        assert found, f"no <{tag} {attrs}>"
        return found[0]


class Tree(HTMLParser):
    def __init__(self, html: str):
        super().__init__(convert_charrefs=True)
        self.root = self.here = Node("#document", {}, None)
        self.feed(html)
        self.close()

    def handle_starttag(self, tag, attrs):
        node = Node(tag, {k: v or "" for k, v in attrs}, self.here)
        self.here.children.append(node)
        if tag not in VOID:
            self.here = node

    def handle_startendtag(self, tag, attrs):
        self.here.children.append(Node(tag, {k: v or "" for k, v in attrs}, self.here))

    def handle_endtag(self, tag):
        node = self.here
        while node is not None and node.tag != tag:
            node = node.parent
        if node is not None and node.parent is not None:
            self.here = node.parent

    def handle_data(self, data):
        self.here.children.append(data)


def dom(html: str) -> Node:
    return Tree(html).root


def page_data(root: Node) -> dict:
    return json.loads(root.one("script", id="data").text())


# ---------------------------------------------------------------- fixtures
def _hostile_map(path: Path) -> Path:
    objects = [
        {"id": 1, "label": "chair", "center": [1.0, 1.0, 0.45], "size": [0.5, 0.5, 0.9], "room": "kitchen",
         "caption": f"a red chair {HOSTILE}", "tags": {"color": "red", "note": HOSTILE}},
        {"id": 2, "label": "chair", "center": [3.0, 1.0, 0.45], "size": [0.5, 0.5, 0.9], "room": "office",
         "caption": "a blue office chair", "tags": {"color": "blue"}},
        {"id": 3, "label": "table", "center": [1.0, 2.5, 0.4], "size": [1.2, 0.8, 0.8], "room": "kitchen",
         "caption": "a wooden kitchen table"},
        {"id": 4, "label": "cup", "center": [1.0, 2.5, 0.85], "size": [0.1, 0.1, 0.1], "room": "kitchen",
         "caption": "a white cup on the table"},
        {"id": 5, "label": "sofa", "center": [3.2, 3.0, 0.4], "size": [1.8, 0.8, 0.8], "room": "office",
         "caption": "a grey sofa"},
    ]
    rooms = [{"id": 1, "label": "kitchen", "polygon": [[0, 0], [2, 0], [2, 4], [0, 4]]},
             {"id": 2, "label": "office", "polygon": [[2, 0], [4.5, 0], [4.5, 4], [2, 4]]}]
    path.write_text(json.dumps({"scene_id": "hostile", "rooms": rooms, "objects": objects}))
    return path


@pytest.fixture(scope="module")
def hostile(tmp_path_factory):
    """A tiny map whose caption and tags hold markup, a suite whose query does, and two runs:
    A (mtefr, keyword; prompts kept) and B (mtefr, spr; not kept)."""
    base = tmp_path_factory.mktemp("hostile")
    map_path = _hostile_map(base / "hostile.json")
    lines = [{"id": "q-red", "map": map_path.name, "query": "the red chair in the kitchen", "type": "ord",
              "target": 1, "accept": [1]},
             {"id": "q-blue", "map": map_path.name, "query": "the blue chair", "type": "od", "target": 2, "accept": [2]},
             {"id": "q-cup", "map": map_path.name, "query": "a cup", "type": "o", "target": 4, "accept": [4]},
             {"id": "q-evil", "map": map_path.name, "query": f"the sofa {HOSTILE}", "type": "o", "target": 5,
              "accept": [5]}]
    suite = base / "suite.jsonl"
    suite.write_text("".join(json.dumps(line) + "\n" for line in lines))
    run_a, run_b = base / "a", base / "b"
    assert run(["eval", str(suite), "-m", "mtefr,keyword", "--keep-prompts", "--no-cache", "-o", str(run_a)]) == 0
    assert run(["eval", str(suite), "-m", "mtefr,spr", "--no-cache", "-o", str(run_b)]) == 0
    return {"map": map_path, "suite": suite, "a": run_a, "b": run_b}


def find_browser() -> str | None:
    named = os.environ.get("IESM_CHROMIUM")  # "none": as if no browser were installed
    if named:
        return None if named == "none" else shutil.which(named)
    return next((p for p in map(shutil.which, ("chromium", "chromium-browser", "google-chrome")) if p), None)


BROWSER = find_browser()
needs_browser = pytest.mark.skipif(
    BROWSER is None, reason="no Chromium: ran the static checks only (html.parser on the written pages); "
                            "`apt-get install chromium` or IESM_CHROMIUM=... for the browser checks")


def chromium(tmp_path: Path, url: str, screenshot: Path | None = None) -> str:
    """The DOM after the page's scripts ran (or a screenshot), from headless Chromium."""
    args = [BROWSER, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
            f"--user-data-dir={tmp_path / 'chromium-profile'}", "--window-size=1366,2000",
            "--virtual-time-budget=5000"]
    args += [f"--screenshot={screenshot}", url] if screenshot else ["--dump-dom", url]
    proc = subprocess.run(args, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    return proc.stdout


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    """`make demo` in a fresh process: its eval run with report.html and its map.html."""
    out = tmp_path_factory.mktemp("demo")
    env = {**os.environ, "IESM_DEMO_DIR": str(out), "HF_HUB_OFFLINE": "1"}
    proc = subprocess.run([sys.executable, "-m", "iesm_agent.demo"], env=env, capture_output=True, text=True,
                          timeout=280)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return out


# ---------------------------------------------------------------- units
def test_wilson_interval_matches_known_values():
    lo, hi = wilson(0, 10)
    assert lo == 0.0 and hi == pytest.approx(0.2775, abs=1e-4)
    lo, hi = wilson(5, 10)
    assert (lo, hi) == (pytest.approx(0.2366, abs=1e-4), pytest.approx(0.7634, abs=1e-4))
    assert wilson(0, 0) == (0.0, 1.0)


def _loops(d: str) -> list[list[tuple[float, float]]]:
    """Vertices of each loop of a path made of M/H/V/Z commands."""
    import re

    loops, x, y = [], 0.0, 0.0
    for cmd, a, b in re.findall(r"([MHVZ])([-\d.]*)\s?([-\d.]*)", d):
        if cmd == "M":
            x, y = float(a), float(b)
            loops.append([(x, y)])
        elif cmd == "H":
            x = float(a)
            loops[-1].append((x, y))
        elif cmd == "V":
            y = float(a)
            loops[-1].append((x, y))
    return loops


def _signed_area(loop) -> float:
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(loop, loop[1:] + loop[:1])) / 2


@pytest.mark.parametrize("cells", [
    [(0, 0)],
    [(r, c) for r in range(3) for c in range(3) if (r, c) != (1, 1)],  # a ring: outer loop and a hole
    [(0, 0), (1, 1)],  # touching at one corner
    [(0, 0), (0, 1), (1, 1), (2, 1), (2, 2), (0, 3)],
])
def test_outlines_enclose_exactly_the_cells(cells):
    import numpy as np

    mask = np.zeros((3, 4), bool)
    for r, c in cells:
        mask[r, c] = True
    loops = _loops(outline_path(mask))
    assert abs(sum(_signed_area(loop) for loop in loops)) == len(cells)  # holes run the other way round
    corners = {p for loop in loops for p in loop}
    assert all(0 <= x <= 4 and 0 <= y <= 3 for x, y in corners)


def test_embedded_json_cannot_end_its_script_and_round_trips():
    data = {"caption": HOSTILE, "nested": [HOSTILE, {"k": "<!--"}]}
    text = embed_json(data)
    assert "<" not in text and ">" not in text and "&" not in text and "\u2028" not in text
    assert json.loads(text) == data


def test_a_page_over_its_bound_is_refused(tmp_path):
    with pytest.raises(IesmError, match="over the"):
        write_page(tmp_path / "big.html", "x" * 2000, limit=1000)
    assert not (tmp_path / "big.html").exists()


# ---------------------------------------------------------------- run records and run.json
def test_records_keep_the_evidence_and_prompts_only_when_asked(hostile):
    kept = {r.key: r for r in read_journal(hostile["a"] / "results.jsonl")}
    plain = {r.key: r for r in read_journal(hostile["b"] / "results.jsonl")}
    red = kept["q-red", "mtefr"]
    assert red.accept == [1] and set(red.gate) and set(red.experts) and red.scores
    assert set(red.gate) | set(red.abstained) >= set(red.experts)
    assert red.calls and all(c.template_hash and c.messages and c.reply for c in red.calls)
    from iesm_agent.prompting import fence

    assert any(fence(f"the sofa {HOSTILE}") in m["content"] for c in kept["q-evil", "mtefr"].calls
               for m in c.messages)  # the rendered prompt, as the model saw it
    assert all(c.messages is None and c.reply == "" and c.template_hash for c in plain["q-red", "mtefr"].calls)
    config = json.loads((hostile["a"] / "run.json").read_text())
    from iesm_agent.prompting import PromptLibrary

    assert config["prompt_hashes"]["mtefr"]["gate.j2"] == PromptLibrary().source_hash("gate.j2")
    assert set(config["prompt_hashes"]) == {"mtefr", "keyword"}


# ---------------------------------------------------------------- static checks (always)
def test_report_page_structure_and_embedded_data(hostile):
    html = (hostile["a"] / "report.html").read_text(encoding="utf-8")
    root = dom(html)
    scripts = root.all("script")
    assert len(scripts) == 2 and scripts[0].attrs == {"type": "application/json", "id": "data"}
    assert html.lower().count("</script") == 2  # the hostile query and caption never close a script
    assert not root.all("link") and not [n for n in root.all() if "src" in n.attrs]  # nothing fetched
    assert "default-src 'none'" in root.one("meta", **{"http-equiv": "Content-Security-Policy"}).attrs["content"]
    data = page_data(root)
    records = {r.key: r for r in read_journal(hostile["a"] / "results.jsonl")}
    assert len(data["records"]) == len(records) == 8
    rows = root.one("table", id="rows").one("tbody").all("tr")
    assert len(rows) == 8 and all(tr.attrs["tabindex"] == "0" for tr in rows)
    assert sum(tr.attrs["data-correct"] == "0" for tr in rows) == sum(not r.correct for r in records.values())
    evil = [tr for tr in rows if tr.attrs["data-qid"] == "q-evil"]
    assert len(evil) == 2 and HOSTILE in evil[0].text()  # shown as text
    assert all(th.attrs.get("scope") == "col" for table in root.all("table") for th in table.one("thead").all("th"))
    metrics = root.one("table", cls="metrics")
    assert [th.text() for th in metrics.one("tbody").all("th")] == ["mtefr", "keyword"]
    assert "n\xa02" in metrics.text()  # per-type n
    assert {t["id"] for t in data["types"]} == {"o", "od", "ord"}
    red = next(r for r in data["records"] if r["id"] == "q-red" and r["variant"] == "mtefr")
    assert red["experts"] and red["gate"] and red["map_key"] in data["maps"]
    assert root.all("template", id=f"map-{red['map_key']}")
    assert any("alert(" in t for t in data["texts"])  # kept prompts, stored once each
    caption_in_map = data["maps"][red["map_key"]]["instances"]["1"]
    assert caption_in_map[0] == "chair"


def test_comparing_two_runs_prefixes_variants_and_tests_them_pairwise(hostile, tmp_path):
    out = tmp_path / "ab.html"
    assert run(["report", str(hostile["a"]), str(hostile["b"]), "-o", str(out)]) == 0
    data = page_data(dom(out.read_text(encoding="utf-8")))
    assert data["variants"] == ["A:mtefr", "A:keyword", "B:mtefr", "B:spr"]
    cross = [t for t in data["significance"] if t["a"] == "A:mtefr" and t["b"] == "B:mtefr"]
    assert {t["type"] for t in cross} == {"overall", "o", "od", "ord"}
    assert cross[0]["n"] == 4 and cross[0]["a_only"] == cross[0]["b_only"] == 0  # same method, same answers


def test_map_viewer_structure(hostile, tmp_path):
    out = tmp_path / "map.html"
    assert run(["view", str(hostile["map"]), "-o", str(out)]) == 0
    html = out.read_text(encoding="utf-8")
    root = dom(html)
    assert len(root.all("script")) == 2 and html.lower().count("</script") == 2
    svg = root.one("svg", cls="map")
    paths = svg.all("path", cls="inst")
    assert sorted(int(p.attrs["data-id"]) for p in paths) == [1, 2, 3, 4, 5]
    assert {p.one("title").text() for p in paths} >= {"#1 chair (kitchen)", "#5 sofa (office)"}
    assert len(svg.all("path", cls="room")) == 2 and svg.all("path", cls="stacked")  # the cup on the table
    data = page_data(root)
    assert next(i for i in data["instances"] if i["id"] == 1)["caption"].endswith(HOSTILE)
    assert root.one("input", id="q").attrs["type"] == "search"


def test_bad_input_is_one_line_and_exit_2(tmp_path, capsys, hostile):
    (tmp_path / "empty").mkdir()
    cases = [["report", str(tmp_path / "missing")], ["report", str(tmp_path / "empty")],
             ["report", str(hostile["a"]), str(hostile["b"]), str(hostile["a"])],
             ["view", str(tmp_path / "nomap.iesm"), "-o", str(tmp_path / "m.html")]]
    for argv in cases:
        assert run(argv) == 2, argv
        err = capsys.readouterr().err
        assert err.startswith("iesm: error: ") and err.count("\n") == 1, err
    assert not (tmp_path / "m.html").exists()


# ---------------------------------------------------------------- in a real browser
def _visible_rows(root: Node) -> list[Node]:
    return [tr for tr in root.one("table", id="rows").one("tbody").all("tr") if "hidden" not in tr.attrs]


@needs_browser
@pytest.mark.slow
def test_report_in_chromium(demo, tmp_path):
    report = demo / "eval" / "report.html"
    url = report.resolve().as_uri()
    shot = tmp_path / "report.png"
    chromium(tmp_path, url + "#result=wrong", screenshot=shot)
    assert shot.read_bytes()[:8] == PNG and shot.stat().st_size > 20_000
    records = list({r.key: r for r in read_journal(demo / "eval" / "results.jsonl")}.values())

    root = dom(chromium(tmp_path, url))
    body = root.one("body")
    assert body.attrs.get("data-ready") and body.attrs["data-visible-rows"] == str(len(records))
    assert len(_visible_rows(root)) == len(records)

    root = dom(chromium(tmp_path, url + "#result=wrong"))
    wrong = sum(not r.correct for r in records)
    assert 0 < wrong < len(records) and len(_visible_rows(root)) == wrong
    assert root.one("p", id="count").text() == f"{wrong} of {len(records)} rows"

    root = dom(chromium(tmp_path, url + "#variant=mtefr&type=s"))
    assert len(_visible_rows(root)) == sum(r.variant == "mtefr" and r.type == "s" for r in records) > 0

    by = {(r.variant, r.id): r for r in records}
    flips = [q for (v, q) in by if v == "mtefr" and ("keyword", q) in by and by[v, q].correct != by["keyword", q].correct]
    root = dom(chromium(tmp_path, url + "#a=mtefr&b=keyword&changed=result"))
    shown = _visible_rows(root)
    assert flips and len(shown) == 2 * len(flips)
    assert {tr.attrs["data-qid"] for tr in shown} == set(flips)

    opened = next(r for r in records if r.variant == "mtefr" and len(r.experts) >= 2 and r.nav_path)
    root = dom(chromium(tmp_path, url + f"#q={opened.id}&qv=mtefr"))
    detail = root.one("aside", id="detail")
    assert root.one("body").attrs["data-open"] == f"mtefr {opened.id}"
    assert {h.text().removesuffix("decided") for h in detail.all("h4") if h.parent.attrs.get("class") == "expert"} \
        == set(opened.experts)
    assert detail.one("table", cls="gate") and detail.one("table", cls="fused")
    svg = detail.one("svg", cls="map")
    assert {int(p.attrs["data-id"]) for p in svg.all("path", cls="accepted")} == set(opened.accept)
    assert svg.all("polyline", cls="path") and svg.all("circle", cls="start")
    assert detail.all("details", cls="prompt")  # the demo keeps prompts
    print(f"\nreport screenshot: {shot} ({shot.stat().st_size} bytes); page {report.stat().st_size} bytes")


@needs_browser
@pytest.mark.slow
def test_map_viewer_in_chromium(demo, tmp_path):
    page = demo / "map.html"
    url = page.resolve().as_uri()
    shot = tmp_path / "map.png"
    chromium(tmp_path, url + "#q=chair", screenshot=shot)
    assert shot.read_bytes()[:8] == PNG and shot.stat().st_size > 20_000
    instances = page_data(dom(page.read_text(encoding="utf-8")))["instances"]

    def hit(i):
        return "chair" in " ".join([i["label"], i["room"] or "", i["caption"], *i["tags"].values()]).lower()

    root = dom(chromium(tmp_path, url + "#q=chair"))
    expected = sum(map(hit, instances))
    assert root.one("body").attrs["data-hits"] == str(expected) and expected > 0
    hits = {i["id"] for i in instances if hit(i)}
    paths = root.one("svg", cls="map").all("path", cls="inst")
    dimmed = {int(p.attrs["data-id"]) for p in paths if "dim" in p.attrs["class"].split()}
    assert dimmed and not dimmed & hits and {int(p.attrs["data-id"]) for p in paths} - dimmed <= hits
    target = next(i for i in instances if i["caption"])
    root = dom(chromium(tmp_path, url + f"#id={target['id']}"))
    info = root.one("section", id="info")
    assert target["label"] in info.text() and target["caption"] in info.text()
    print(f"\nmap screenshot: {shot} ({shot.stat().st_size} bytes); page {page.stat().st_size} bytes")


@needs_browser
def test_hostile_text_stays_text_in_chromium(hostile, tmp_path):
    url = (hostile["a"] / "report.html").resolve().as_uri()
    root = dom(chromium(tmp_path, url + "#q=q-evil&qv=mtefr"))
    assert len(root.all("script")) == 2 and root.one("body").attrs.get("data-ready")
    detail = root.one("aside", id="detail")
    assert HOSTILE in detail.one("p", cls="query-text").text()
    view = tmp_path / "map.html"
    assert run(["view", str(hostile["map"]), "-o", str(view)]) == 0
    root = dom(chromium(tmp_path, view.resolve().as_uri() + "#id=1"))
    assert len(root.all("script")) == 2
    assert HOSTILE in root.one("section", id="info").text()


def test_eval_writes_its_results_when_the_page_is_over_its_bound(hostile, tmp_path, monkeypatch, capsys):
    import iesm_agent.evals.html.run_data as run_data

    monkeypatch.setattr(run_data, "MAX_PAGE_BYTES", 1000)
    out = tmp_path / "run"
    assert run(["eval", str(hostile["suite"]), "-m", "keyword", "-o", str(out)]) == 0
    err = capsys.readouterr().err
    assert "iesm: warning: report.html not written" in err and "over the" in err
    assert (out / "report.md").exists() and (out / "summary.json").exists() and not (out / "report.html").exists()
