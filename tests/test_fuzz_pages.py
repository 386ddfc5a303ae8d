"""Hostile run directories through `iesm report` (issue 31: 1, 8). A run is something people send
each other: every string and every number field of its files (results.jsonl, run.json,
summary.json) is set to markup that would run a script. The page either refuses the run in one
line (exit 2: a number field that is not a number, NaN / Infinity, a wrong type) or escapes every
value: the written page holds no element or attribute from the payload, and headless Chromium
(when installed: `make browser`), after the page's own scripts ran and a query was opened, shows
no sign of the payload having run."""

from __future__ import annotations

import json
import shutil
from html import escape
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import quote

import pytest

from fuzzing import FAST, SLOW, Tally, check_cli, mutations
from test_html_report import BROWSER, _hostile_map, chromium, needs_browser

from iesm_agent.cli import run

#: markup that marks <html> when any part of it runs (an event handler or a script element)
PAYLOAD = ('"><img src=x onerror="document.documentElement.setAttribute(\'data-pwned\',\'img\')">'
           "<script>document.documentElement.setAttribute('data-pwned','script')</script>"
           "<svg onload=\"document.documentElement.setAttribute('data-pwned','svg')\"></svg>'-->")
#: the page's own scripts (the embedded data and the inline code) and event-handler attributes
OWN_SCRIPTS = 2
OWN_HANDLERS = {("form", "onsubmit", "return false")}  # the map viewer's search box


class Tags(HTMLParser):
    """Every start tag of a page with its attributes."""

    def __init__(self, html: str):
        super().__init__(convert_charrefs=True)
        self.tags: list[tuple[str, dict]] = []
        self.feed(html)

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))


def assert_inert(html: str) -> None:
    """The page holds no element and no event-handler attribute from the payload."""
    tags = Tags(html).tags
    assert sum(t == "script" for t, _ in tags) == OWN_SCRIPTS
    assert not [t for t, _ in tags if t == "img"]
    assert not [(t, k, v) for t, a in tags for k, v in a.items() if k.startswith("on") and (t, k, v) not in OWN_HANDLERS]
    assert not [(t, a) for t, a in tags if "data-pwned" in a]


@pytest.fixture(scope="module")
def clean_run(tmp_path_factory):
    base = tmp_path_factory.mktemp("pages")
    map_path = _hostile_map(base / "m.json")
    lines = [{"id": "q-red", "map": map_path.name, "query": "the red chair in the kitchen", "type": "ord",
              "target": 1, "accept": [1]},
             {"id": "q-cup", "map": map_path.name, "query": "a cup", "type": "o", "target": 4, "accept": [4]}]
    suite = base / "suite.jsonl"
    suite.write_text("".join(json.dumps(line) + "\n" for line in lines))
    out = base / "run"
    assert run(["eval", str(suite), "-m", "mtefr,keyword", "--keep-prompts", "--no-cache", "-o", str(out)]) == 0
    return out


def report_or_refusal(run_dir: Path, capsys) -> str | None:
    """`iesm report RUN_DIR`: the page written (exit 0), or None for a one-line refusal (exit 2,
    no page left)."""
    page = run_dir / "report.html"
    code = run(["report", str(run_dir)])
    err = capsys.readouterr().err
    assert code in (0, 2), err
    if code == 2:
        lines = err.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("iesm: error: ") and "Traceback" not in err, err
        assert not page.exists()
        return None
    return page.read_text()


def _leaves(value, path=()):
    """(path, value) of every string and number leaf of a JSON value (dict keys left as they are)."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _leaves(v, path + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from _leaves(v, path + (i,))
    elif isinstance(value, (str, int, float)) and not isinstance(value, bool):
        yield path, value


def _set(doc, path, value):
    node = doc
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value


def _copy_run(src: Path, dst: Path) -> Path:
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(src, dst)
    (dst / "report.html").unlink(missing_ok=True)
    return dst


def _records(run_dir: Path) -> list[dict]:
    return [json.loads(line) for line in (run_dir / "results.jsonl").read_text().split("\n") if line]


def _write_records(run_dir: Path, records: list[dict]) -> None:
    (run_dir / "results.jsonl").write_text("".join(json.dumps(r) + "\n" for r in records))


def _every_string_a_payload(run_dir: Path) -> None:
    """Every string leaf of the run's files becomes the payload (numbered where the run needs
    distinct values: ids and variant names keep their pairing)."""
    names: dict[str, str] = {}

    def hostile(text: str) -> str:
        return names.setdefault(text, f"{PAYLOAD}{len(names)}")

    records = _records(run_dir)
    for record in records:
        for path, value in list(_leaves(record)):
            if isinstance(value, str):
                _set(record, path, hostile(value) if path != ("map",) else value)  # the map stays findable
    _write_records(run_dir, records)
    for name in ("run.json", "summary.json"):
        doc = json.loads((run_dir / name).read_text())
        for path, value in list(_leaves(doc)):
            if isinstance(value, str) and path[:1] != ("suites",):
                _set(doc, path, hostile(value))
        (run_dir / name).write_text(json.dumps(doc))


def test_every_string_field_a_payload_stays_text(clean_run, tmp_path, capsys):
    run_dir = _copy_run(clean_run, tmp_path / "run")
    _every_string_a_payload(run_dir)
    assert run(["report", str(run_dir)]) == 0, capsys.readouterr().err
    html = (run_dir / "report.html").read_text()
    assert_inert(html)
    assert PAYLOAD[:20] not in html  # escaped wherever it is shown


@pytest.mark.parametrize("field", ["queries", "wall_s"])
def test_the_header_facts_of_the_issue_are_refused_or_escaped(field, clean_run, tmp_path, capsys):
    """Issue 31 (1): `run.queries` / `run.wall_s` reached the header unescaped."""
    run_dir = _copy_run(clean_run, tmp_path / "run")
    summary = json.loads((run_dir / "summary.json").read_text())
    summary["run"][field] = PAYLOAD
    (run_dir / "summary.json").write_text(json.dumps(summary))
    html = report_or_refusal(run_dir, capsys)
    if html is not None:
        assert_inert(html)


def test_every_number_field_a_payload_is_refused_or_escaped(clean_run, tmp_path, capsys):
    """Each number of results.jsonl, run.json and summary.json set to the payload, one at a time."""
    cases = refused = 0
    for name in ("results.jsonl", "run.json", "summary.json"):
        docs = _records(clean_run) if name == "results.jsonl" else [json.loads((clean_run / name).read_text())]
        paths = [(i, p) for i, d in enumerate(docs) for p, v in _leaves(d) if not isinstance(v, str)]
        for i, path in paths[:: max(1, len(paths) // 60)]:  # at most ~60 fields per file
            run_dir = _copy_run(clean_run, tmp_path / "run")
            mutated = json.loads(json.dumps(docs))
            _set(mutated[i], path, PAYLOAD)
            if name == "results.jsonl":
                _write_records(run_dir, mutated)
            else:
                (run_dir / name).write_text(json.dumps(mutated[0]))
            html = report_or_refusal(run_dir, capsys)
            cases += 1
            if html is None:
                refused += 1
            else:
                assert_inert(html)
    assert cases >= 30 and refused >= 1


@pytest.mark.parametrize("name, text", [
    ("results.jsonl", "NaN"), ("results.jsonl", "Infinity"), ("run.json", "NaN"), ("summary.json", "-Infinity")])
def test_nan_and_infinity_in_run_files_are_one_line(name, text, clean_run, tmp_path, capsys):
    run_dir = _copy_run(clean_run, tmp_path / "run")
    path = run_dir / name
    if name == "results.jsonl":
        lines = [line for line in path.read_text().split("\n") if line]
        record = json.loads(lines[0])
        record["latency_ms"] = "@@"
        lines[0] = json.dumps(record).replace('"@@"', text)
        path.write_text("\n".join(lines) + "\n")
    elif name == "run.json":
        path.write_text(json.dumps({**json.loads(path.read_text()), "provider": "@@"}).replace('"@@"', text))
    else:
        doc = json.loads(path.read_text())
        doc["run"]["wall_s"] = "@@"
        path.write_text(json.dumps(doc).replace('"@@"', text))
    check_cli(["report", str(run_dir)], capsys, outputs=(run_dir / "report.html",), may_pass=False)


@pytest.mark.parametrize("change", [
    {"suites": "x"}, {"suites": [1, 2]}, {"variants": "mtefr"}, {"variants": [{"name": 3}]}, {"variants": [7]},
    {"prompt_hashes": []}, {"prompt_hashes": {"mtefr": "x"}}, {"provider": {"a": 1}}])
def test_wrong_types_in_run_json_are_one_line(change, clean_run, tmp_path, capsys):
    run_dir = _copy_run(clean_run, tmp_path / "run")
    path = run_dir / "run.json"
    path.write_text(json.dumps({**json.loads(path.read_text()), **change}))
    check_cli(["report", str(run_dir)], capsys, outputs=(run_dir / "report.html",), may_pass=False)


def test_bad_out_is_one_line(clean_run, tmp_path, capsys):
    for argv in (["report", str(clean_run), "-o", str(tmp_path)],
                 ["report", str(clean_run), "-o", str(tmp_path / "missing" / "r.html")],
                 ["view", str(tmp_path.parent), "-o", str(tmp_path / "v.html")],
                 ["view", "apartment", "-o", str(tmp_path)],
                 ["view", "apartment", "-o", str(tmp_path / "missing" / "v.html")],
                 ["import", str(_hostile_map(tmp_path / "m.json")), "-o", str(tmp_path)],
                 ["import", str(tmp_path / "m.json"), "-o", str(tmp_path / "missing" / "m.iesm")]):
        check_cli(argv, capsys, may_pass=False)


@needs_browser
def test_every_string_field_a_payload_runs_nothing_in_chromium(clean_run, tmp_path, capsys):
    assert BROWSER
    run_dir = _copy_run(clean_run, tmp_path / "run")
    _every_string_a_payload(run_dir)
    assert run(["report", str(run_dir)]) == 0, capsys.readouterr().err
    record = _records(run_dir)[0]
    url = (run_dir / "report.html").resolve().as_uri()
    for fragment in ("", f"#q={quote(record['id'])}&qv={quote(record['variant'])}", "#result=wrong"):
        dom = chromium(tmp_path, url + fragment)
        html_tag = next(a for t, a in Tags(dom).tags if t == "html")
        assert "data-pwned" not in html_tag, (fragment, html_tag)
        assert_inert(dom)


def _hostile_scene(path: Path) -> Path:
    """A map whose every string field (scene id, labels, rooms, captions, tag names and values) is
    the payload."""
    p = lambda n: f"{PAYLOAD}{n}"  # noqa: E731
    objects = [{"id": i, "label": p(f"l{i % 2}"), "center": [1.0 + i, 1.0, 0.45], "size": [0.5, 0.5, 0.9],
                "room": p(f"r{i % 2}"), "caption": p(f"c{i}"), "tags": {p("k"): p(f"v{i}")}} for i in (1, 2, 3)]
    rooms = [{"id": 1, "label": p("r0"), "polygon": [[0, 0], [2.5, 0], [2.5, 3], [0, 3]]},
             {"id": 2, "label": p("r1"), "polygon": [[2.5, 0], [5, 0], [5, 3], [2.5, 3]]}]
    path.write_text(json.dumps({"scene_id": p("scene"), "rooms": rooms, "objects": objects}))
    return path


def test_map_viewer_of_a_hostile_map_is_inert(tmp_path, capsys):
    scene = _hostile_scene(tmp_path / "m.json")
    page = tmp_path / "map.html"
    assert run(["view", str(scene), "-o", str(page)]) == 0, capsys.readouterr().err
    html = page.read_text()
    assert_inert(html)
    assert html.count(escape(PAYLOAD[:40])) >= 3  # shown, as text: id, labels, rooms
    if BROWSER:
        for fragment in ("", "#id=1", "#q=" + quote(PAYLOAD[:12])):
            dom = chromium(tmp_path, page.resolve().as_uri() + fragment)
            assert "data-pwned" not in next(a for t, a in Tags(dom).tags if t == "html"), fragment
            assert_inert(dom)


def _fuzz_run_files(clean_run: Path, tmp_path: Path, capsys, n: int, seed: int) -> None:
    """`n` seeded malformed variants (fuzzing.mutations: deep nesting, truncation, bad numbers,
    wrong types, garbage bytes) of one of the run's files at a time: each report is refused in one
    line or written inert."""
    import random

    rng = random.Random(seed)
    docs = {"run.json": json.loads((clean_run / "run.json").read_text()),
            "summary.json": json.loads((clean_run / "summary.json").read_text()),
            "results.jsonl": _records(clean_run)[0]}
    streams = {name: mutations(doc, random.Random(rng.random())) for name, doc in docs.items()}
    for _ in range(n):
        name = rng.choice(sorted(docs))
        kind, text = next(streams[name])
        run_dir = _copy_run(clean_run, tmp_path / "run")
        if name == "results.jsonl":
            rest = [json.dumps(r) for r in _records(clean_run)[1:]]
            (run_dir / name).write_text("\n".join([text.replace("\n", " "), *rest]) + "\n", encoding="utf-8",
                                        errors="surrogateescape")
        else:
            (run_dir / name).write_text(text, encoding="utf-8", errors="surrogateescape")
        html = report_or_refusal(run_dir, capsys)
        if html is not None:
            assert_inert(html)
        Tally.add(f"report {name}", f"{kind}:{'accepted' if html is not None else 'refused'}")


def test_fuzz_run_files(clean_run, tmp_path, capsys):
    _fuzz_run_files(clean_run, tmp_path, capsys, FAST, 3101)


@pytest.mark.slow
def test_fuzz_run_files_seeded_long_run(clean_run, tmp_path, capsys):
    _fuzz_run_files(clean_run, tmp_path, capsys, SLOW // 2, 3102)
