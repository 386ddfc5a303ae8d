"""Suite parsing: every bad line is an error naming file and line; --skip-invalid keeps the rest."""

from __future__ import annotations

import json

import pytest

from iesm_agent.errors import IesmError
from iesm_agent.evals.suite import SuiteQuery, load_suites, write_suite
from iesm_agent.store.fileformat import save_map
from iesm_agent.store.model import GridSpec, Instance, SceneMap


@pytest.fixture
def tiny_map(tmp_path):
    scene = SceneMap(scene_id="tiny", grid=GridSpec(cell_size=0.1, height=4, width=4),
                     instances=[Instance(id=1, label="chair"), Instance(id=2, label="table")])
    path = tmp_path / "maps" / "tiny.iesm"
    path.parent.mkdir()
    save_map(scene, path)
    return path


def _line(**fields):
    base = {"id": "q1", "map": "maps/tiny.iesm", "query": "find the chair", "type": "o",
            "target": 1, "accept": [1]}
    base.update(fields)
    return json.dumps(base)


def _write(tmp_path, lines, name="suite.jsonl"):
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return path


def test_valid_suite_resolves_map_relative_to_suite_file(tmp_path, tiny_map):
    path = _write(tmp_path, [_line(), "", _line(id="q2", target=2, accept=[])])
    suite = load_suites([path])
    assert [e.query.id for e in suite.entries] == ["q1", "q2"]
    assert suite.entries[1].line == 3
    assert suite.entries[0].map_path == tiny_map.resolve()
    assert suite.entries[1].query.accept == [2]  # the target is always accepted


@pytest.mark.parametrize("bad, message", [
    ("{\"id\": \"q9\", \"map\": ", "Expecting value|Unterminated|Expecting"),
    (_line(id="q9", map="maps/nowhere.iesm"), "unknown map 'maps/nowhere.iesm'"),
    (_line(id="q9", target=7, accept=[7]), "target 7 is not an instance"),
    (_line(id="q9", accept=[1, 99]), "accept id 99 is not an instance"),
    (json.dumps({"id": "q9", "map": "maps/tiny.iesm", "target": 1}), "query: Field required"),
    (_line(id="q9", type="a type label that is far too long"), "type: String should have at most"),
    (_line(id="q9", type="o r"), "type: String should match"),
    (_line(), "duplicate query id 'q1'"),
])
def test_bad_line_names_file_and_line(tmp_path, tiny_map, bad, message):
    path = _write(tmp_path, [_line(), bad, _line(id="q3")])
    with pytest.raises(IesmError, match=message) as info:
        load_suites([path])
    assert info.value.source == str(path)
    assert info.value.where == "line 2"
    assert str(info.value).startswith(f"{path}:line 2: ")


def test_types_are_free_short_labels_reported_after_the_paper_types(tmp_path, tiny_map):
    from iesm_agent.evals.query_types import ordered_types, type_title

    path = _write(tmp_path, [_line(type="spatial"), _line(id="q2", type="s"), _line(id="q3", type="ord")])
    assert [e.query.type for e in load_suites([path]).entries] == ["spatial", "s", "ord"]
    assert ordered_types({"spatial", "s", "ord", "o"}) == ["o", "ord", "s", "spatial"]
    assert [type_title(t) for t in ("ord", "spatial")] == ["(o,r,d)", "spatial"]


def test_skip_invalid_collects_errors_and_keeps_the_rest(tmp_path, tiny_map):
    path = _write(tmp_path, [_line(), "not json", _line(id="q2", target=5, accept=[5]), _line(id="q3", target=2)])
    suite = load_suites([path], skip_invalid=True)
    assert [e.query.id for e in suite.entries] == ["q1", "q3"]
    assert [e.where for e in suite.errors] == ["line 2", "line 3"]


def test_ids_must_be_unique_across_suites(tmp_path, tiny_map):
    first = _write(tmp_path, [_line()], "a.jsonl")
    second = _write(tmp_path, [_line()], "b.jsonl")
    with pytest.raises(IesmError, match="duplicate query id 'q1'") as info:
        load_suites([first, second])
    assert info.value.source == str(second)


def test_unreadable_suite_names_the_file(tmp_path):
    with pytest.raises(IesmError, match="cannot read suite") as info:
        load_suites([tmp_path / "missing.jsonl"])
    assert info.value.source.endswith("missing.jsonl")


def test_write_suite_round_trips(tmp_path, tiny_map):
    queries = [SuiteQuery(id="a", map="maps/tiny.iesm", query="find the table", type="o", target=2, accept=[2])]
    path = tmp_path / "out.jsonl"
    write_suite(queries, path)
    assert [e.query for e in load_suites([path]).entries] == queries
    assert list(tmp_path.glob(".out.jsonl.*")) == []  # no temporary file left behind


def test_a_broken_map_is_an_error_of_the_lines_that_use_it(tmp_path, tiny_map):
    broken = tmp_path / "maps" / "broken.iesm"
    broken.write_bytes(tiny_map.read_bytes()[:200])  # truncated archive
    path = _write(tmp_path, [_line(), _line(id="q2", map="maps/broken.iesm"),
                             _line(id="q3", map="maps/broken.iesm")])
    with pytest.raises(IesmError, match=r"suite.jsonl:line 2: .*broken.iesm: not a valid .iesm archive"):
        load_suites([path])
    suite = load_suites([path], skip_invalid=True)
    assert [e.query.id for e in suite.entries] == ["q1"]
    assert [e.where for e in suite.errors] == ["line 2", "line 3"]


@pytest.mark.parametrize("char", ["\u2028", "\u2029", "\u0085", "\x0b", "\x0c", "\x1c"])
def test_a_query_holding_a_unicode_line_separator_is_one_line(tmp_path, tiny_map, char):
    """Issue 31 (10): JSON Lines end at "\\n" only; `splitlines()` cut a query holding U+2028 or
    U+0085 (valid, unescaped, in JSON text) in two and refused the line."""
    path = tmp_path / "suite.jsonl"
    path.write_text(json.dumps({"id": "q1", "map": "maps/tiny.iesm", "query": f"the chair{char}by the door",
                                "type": "o", "target": 1, "accept": [1]}, ensure_ascii=False) + "\r\n",
                    encoding="utf-8", newline="")
    suite = load_suites([path])
    assert [e.query.query for e in suite.entries] == [f"the chair{char}by the door"]


def test_a_suite_that_is_a_fifo_or_a_device_is_refused_not_read(tmp_path):
    import os

    fifo = tmp_path / "fifo.jsonl"
    os.mkfifo(fifo)
    for path in (fifo, "/dev/zero"):
        with pytest.raises(IesmError, match="cannot read suite: not a regular file"):
            load_suites([path])


def test_eval_refuses_a_suite_path_that_is_not_utf8_in_one_line(tmp_path, capsys):
    """run.json records the suite's path: one that is not UTF-8 text cannot be written there (it
    was a PydanticSerializationError traceback); now one line, before the run directory exists."""
    import os
    from pathlib import Path

    from iesm_agent.cli import run

    folder = Path(os.fsdecode(bytes(tmp_path) + b"/e_\xff"))
    folder.mkdir()
    suite = folder / "s.jsonl"
    suite.write_text(_line(map="apartment") + "\n")
    assert run(["eval", str(suite), "-m", "keyword", "--no-cache", "-o", str(tmp_path / "run")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "not valid UTF-8" in err[0] and not (tmp_path / "run").exists()
