"""Issue 25, "what a 1,011-case attack found": each finding as a test, in the issue's order. Every
one of them failed before the fix (traceback, exit 1, silent acceptance or a leftover file)."""

from __future__ import annotations

import asyncio
import io
import json
import os
import sqlite3
import time
import warnings
import zipfile

import numpy as np
import pytest

from fuzzing import DEEP, check_cli, write_tiny_frames

from iesm_agent.cli import run
from iesm_agent.errors import IesmError

OBJECTS = {"scene_id": "h", "objects": [
    {"id": 1, "label": "chair", "center": [0.5, 0.5, 0.4], "size": [0.4, 0.4, 0.8], "room": "kitchen"},
    {"id": 2, "label": "table", "center": [1.5, 1.0, 0.4], "size": [0.8, 0.6, 0.8], "room": "kitchen"}]}
LINE = {"id": "q1", "map": "map.json", "query": "the chair", "target": 1}


@pytest.fixture()
def env(monkeypatch, tmp_path):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    monkeypatch.setenv("IESM_CACHE_DIR", str(tmp_path / "cache"))
    (tmp_path / "map.json").write_text(json.dumps(OBJECTS))
    return tmp_path


def refused(argv, capsys, *outputs, contains: str = "") -> str:
    check_cli(list(map(str, argv)), capsys, outputs=tuple(outputs), may_pass=False)
    return ""


def error_line(argv, capsys) -> str:
    assert run(list(map(str, argv))) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("iesm: error: ") and "Traceback" not in err, err
    return err


# ---------------------------------------------------------------------- usage errors: one line, exit 2
@pytest.mark.parametrize("argv", [["no-such-command"], ["ask", "apartment"], ["ask", "apartment", "x", "--bogus-flag"],
                                  ["path", "apartment", "--to", "x", "--start", "1,1"]])
def test_usage_errors_are_one_line_and_exit_2(argv, capsys):
    err = error_line(argv, capsys)
    assert "usage: iesm" in err


def test_bare_iesm_prints_help_and_exits_2(capsys):
    assert run([]) == 2
    assert "Usage" in capsys.readouterr().out


# ------------------------------------------------------------------- deep JSON: bounded in every reader
def test_deep_object_list(env, capsys):
    (env / "deep.json").write_text('{"scene_id": "x", "objects": ' + "[" * DEEP + "]" * DEEP + "}")
    assert "nested" in error_line(["import", env / "deep.json", "-o", env / "o.iesm"], capsys)
    assert not (env / "o.iesm").exists()


def test_deep_inner_caption_imports_as_unrecovered(env, capsys):
    doc = {"3": {"category": "chair", "caption": "[" * DEEP}}
    (env / "scene_d_caption.json").write_text(json.dumps(doc))
    assert run(["import", str(env / "scene_d_caption.json"), "-o", str(env / "o.iesm")]) == 0


def test_deep_suite_line(env, capsys):
    (env / "s.jsonl").write_text("[" * DEEP + "\n")
    err = error_line(["eval", env / "s.jsonl", "-o", env / "run", "-m", "keyword", "--no-cache"], capsys)
    assert "line 1" in err and "nested" in err and not (env / "run").exists()


def test_deep_iesm_manifest(tmp_path, capsys, apartment_path):
    with zipfile.ZipFile(apartment_path) as zf:
        members = {n: zf.read(n) for n in zf.namelist()}
    members["manifest.json"] = b"[" * DEEP
    bad = tmp_path / "deep.iesm"
    with zipfile.ZipFile(bad, "w") as zf:
        for name, data in members.items():
            zf.writestr(name, data)
    assert "nested" in error_line(["info", bad], capsys)


def test_the_depth_bound_is_exact_with_or_without_the_full_scan():
    """load_json skips the bracket scan when the text has no more opening brackets than the bound
    allows: the refusal starts exactly one level past the bound, and brackets inside strings (which
    make the count exceed the bound) still do not count."""
    from iesm_agent.fileio import json_depth, load_json

    bound = 8
    assert load_json("[" * bound + "]" * bound, max_depth=bound) is not None
    with pytest.raises(IesmError, match="nested 9 levels deep"):
        load_json("[" * (bound + 1) + "]" * (bound + 1), max_depth=bound)
    in_strings = json.dumps({"a": ["[{" * 20, {"b": "{" * 30}]})
    assert load_json(in_strings, max_depth=3) == json.loads(in_strings)
    with pytest.raises(IesmError, match="nested 4 levels deep"):
        load_json(json.dumps([[[["[" * 20]]]]), max_depth=3)  # 4 lists; 24 brackets counted
    rng = np.random.default_rng(0)
    for _ in range(500):  # random bracket soups: refused for depth exactly when the full scan says so
        text = "".join(rng.choice(list('[]{}"x,'), size=int(rng.integers(1, 30))))
        try:
            load_json(text, max_depth=4)
        except IesmError as exc:
            assert ("levels deep" in str(exc)) == (json_depth(text.encode()) > 4), (text, str(exc))
        else:
            assert json_depth(text.encode()) <= 4, text


def test_deep_sim_faults(tmp_path, capsys):
    (tmp_path / "f.json").write_text("{\"miss_rate\": " + "[" * DEEP)
    assert "nested" in error_line(["sim", "--out", tmp_path / "s", "--faults", tmp_path / "f.json"], capsys)
    assert not (tmp_path / "s").exists()


def test_a_deeply_nested_model_reply_does_not_break_an_eval(env):
    from iesm_agent.evals.runner import make_config, make_variants, run_eval
    from iesm_agent.providers import FunctionModel

    (env / "s.jsonl").write_text(json.dumps(LINE) + "\n")
    reply = '{"ranked_instance_ids": ' + "[" * DEEP + "]" * DEEP + "}"
    config = make_config([env / "s.jsonl"], make_variants(["mtefr", "spr"], []), "offline")
    outcome = asyncio.run(run_eval(config, env / "run", model=FunctionModel(lambda m, o: reply)))
    assert outcome.new == 2 and all(r.failures for r in outcome.records)


# ---------------------------------------------------------------------- corrupt .npz: one line
@pytest.mark.parametrize("damage", ["empty", "truncated"])
def test_corrupt_seg_npz(tmp_path, capsys, damage):
    d = write_tiny_frames(tmp_path / "f")
    seg = d / "frames" / "000000.seg.npz"
    seg.write_bytes(b"" if damage == "empty" else seg.read_bytes()[:100])
    assert "seg.npz" in error_line(["build-map", d, "-o", tmp_path / "m.iesm"], capsys)
    assert not (tmp_path / "m.iesm").exists()


def test_corrupt_gt_cells_npz(tmp_path):
    from iesm_agent.sim.ground_truth import GroundTruth
    from iesm_agent.store.model import GridSpec, InstanceGrid

    GroundTruth("g", [], [], GridSpec(cell_size=0.1, height=2, width=2), np.full((2, 2), -1, np.int32),
                np.zeros((2, 2), bool), InstanceGrid.empty()).save(tmp_path)
    cells = tmp_path / "gt" / "cells.npz"
    cells.write_bytes(cells.read_bytes()[:50])
    with pytest.raises(IesmError, match="cells.npz") as info:
        GroundTruth.load(tmp_path)
    assert "\n" not in str(info.value)


def _small_map(env):
    assert run(["import", str(env / "map.json"), "-o", str(env / "m.iesm")]) == 0
    return env / "m.iesm"


def test_corrupt_cell_labels(env, capsys):
    m = _small_map(env)
    (env / "l.npz").write_bytes(b"PK\x03\x04garbage")
    error_line(["rooms", m, "--cell-labels", env / "l.npz", "-o", env / "r.iesm"], capsys)
    assert not (env / "r.iesm").exists()


# ---------------------------------------------------------------------- size caps, the limit named
def test_a_pose_translation_of_1e12_is_refused(tmp_path, capsys):
    d = write_tiny_frames(tmp_path / "f")
    pose = np.eye(4)
    pose[0, 3] = 1e12
    (d / "frames" / "000001.pose.txt").write_text("\n".join(" ".join(map(str, r)) for r in pose))
    assert "10000 m" in error_line(["build-map", d, "-o", tmp_path / "m.iesm"], capsys)


def _with_manifest(src, dst, patch, replace=None):
    with zipfile.ZipFile(src) as zf:
        members = {n: zf.read(n) for n in zf.namelist()}
    manifest = json.loads(members["manifest.json"])
    patch(manifest)
    members["manifest.json"] = json.dumps(manifest).encode()
    members.update(replace or {})
    with zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in members.items():
            zf.writestr(name, data)


def test_a_manifest_declaring_a_1e6_grid_is_refused_naming_the_limit(tmp_path, capsys, apartment_path):
    def patch(m):
        m["grid"]["height"] = m["grid"]["width"] = 10**6

    _with_manifest(apartment_path, tmp_path / "big.iesm", patch)
    for command in (["info"], ["render", "-o", str(tmp_path / "x.png")]):
        assert "25,000,000" in error_line([command[0], tmp_path / "big.iesm", *command[1:]], capsys)


def test_a_small_iesm_whose_room_map_inflates_is_refused_before_reading(tmp_path, capsys, apartment_path):
    side = 32768
    buf = io.BytesIO()
    np.save(buf, np.zeros((1, 1), np.int32))
    header = buf.getvalue().replace(b"(1, 1)", f"({side}, {side})".encode())

    def patch(m):
        m["grid"]["height"] = m["grid"]["width"] = side
        for e in m["arrays"]:
            if e["name"] == "room_map":
                e["shape"] = [side, side]

    _with_manifest(apartment_path, tmp_path / "bomb.iesm", patch, {"room_map.npy": header})
    started = time.perf_counter()
    error_line(["info", tmp_path / "bomb.iesm"], capsys)
    assert time.perf_counter() - started < 2.0


# ---------------------------------------------------------------------- the cache turns itself off
def _cache(tmp_path):
    from iesm_agent.providers import FunctionModel
    from iesm_agent.providers.cache import CachedModel

    return CachedModel(FunctionModel(lambda m, o: '{"a": 1}'), tmp_path / "c")


def _ask(model, text="x"):
    from iesm_agent.providers.base import Message

    return asyncio.run(model.acomplete([Message(role="user", content=text)]))


def test_a_damaged_cache_settings_table_turns_the_cache_off_with_one_warning(tmp_path):
    from iesm_agent.providers.cache import CacheWarning

    _ask(_cache(tmp_path))
    with sqlite3.connect(tmp_path / "c" / "cache.db") as con:
        con.execute("UPDATE Settings SET value = 'bogus' WHERE key = 'eviction_policy'")
    model = _cache(tmp_path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        replies = [_ask(model, f"q{i}").text for i in range(3)]
    assert replies == ['{"a": 1}'] * 3
    assert [w.category for w in caught] == [CacheWarning] and model.disabled_reason


def test_a_locked_cache_costs_about_a_second_not_a_minute(tmp_path):
    _ask(_cache(tmp_path))
    con = sqlite3.connect(tmp_path / "c" / "cache.db")
    con.execute("BEGIN EXCLUSIVE")
    try:
        model = _cache(tmp_path)
        started = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for i in range(5):
                assert _ask(model, f"q{i}").text == '{"a": 1}'
        assert time.perf_counter() - started < 5.0 and "locked" in model.disabled_reason
    finally:
        con.close()


# ---------------------------------------------------------------------- non-finite and huge numbers
@pytest.mark.parametrize("field, value", [("start", [float("nan"), float("nan")]), ("start", [1e308, 1e308]),
                                          ("target", 2**70), ("target", True), ("accept", [1, 2**70])])
def test_bad_numbers_in_a_suite_line(env, capsys, field, value):
    (env / "s.jsonl").write_text(json.dumps({**LINE, field: value}) + "\n")
    err = error_line(["eval", env / "s.jsonl", "-o", env / "run", "-m", "keyword", "--no-cache"], capsys)
    assert field in err and not (env / "run").exists()


@pytest.mark.parametrize("radius", ["nan", "inf", "-1", "1e308"])
def test_robot_radius_must_be_finite_and_in_range(capsys, radius):
    assert "--robot-radius" in error_line(["path", "apartment", "--to", "1", "--start", "1,1", "--robot-radius", radius],
                                          capsys)


@pytest.mark.parametrize("argv", [["sim", "--seed", "-1"], ["sim", "--seed", str(2**70)], ["rooms", "x", "--seed", "-1"]])
def test_seeds_must_be_in_range(tmp_path, capsys, argv):
    error_line([*argv, "--out" if argv[0] == "sim" else "-o", tmp_path / "o"], capsys)


@pytest.mark.parametrize("start", [[float("nan"), 1.0], [1e308, 1e308], [float("inf"), 0]])
def test_plan_path_start_over_the_tool_surface(apartment_store, start):
    from iesm_agent.server import MapService

    service = MapService({"apartment": apartment_store})
    with pytest.raises(IesmError, match="start") as info:
        asyncio.run(service.call_tool("plan_path", {"instance_id": 1, "start": start}))
    assert "\n" not in str(info.value)


def test_plan_path_start_over_mcp_is_a_tool_error(apartment_store):
    from mcp.server.mcpserver.exceptions import ToolError

    from iesm_agent.server import MapService
    from iesm_agent.server.app import build_server

    server = build_server(MapService({"apartment": apartment_store}))
    with pytest.raises(ToolError, match="finite"):
        asyncio.run(server.call_tool("plan_path", {"instance_id": 1, "start": [float("nan"), 1.0]}))


# ---------------------------------------------------------------------- bad data no longer accepted silently
def _seg(d, **arrays):
    seg = d / "frames" / "000000.seg.npz"
    with np.load(seg) as z:
        data = {k: z[k] for k in ("masks", "embeddings", "scores")}
    data.update(arrays)
    np.savez_compressed(seg, **data)


@pytest.mark.parametrize("what", ["nan-embeddings", "nan-scores", "string-masks"])
def test_bad_segmentations_are_refused(tmp_path, capsys, what):
    d = write_tiny_frames(tmp_path / "f")
    with np.load(d / "frames" / "000000.seg.npz") as z:
        emb, scores = z["embeddings"].copy(), z["scores"].copy()
    if what == "nan-embeddings":
        emb[0, 0] = np.nan
        _seg(d, embeddings=emb)
    elif what == "nan-scores":
        scores[1] = np.nan
        _seg(d, scores=scores)
    else:
        _seg(d, masks=np.full((2, 12, 16), "yes"))
    error_line(["build-map", d, "-o", tmp_path / "m.iesm"], capsys)
    assert not (tmp_path / "m.iesm").exists()


def test_n_frames_zero_is_refused(tmp_path, capsys):
    d = write_tiny_frames(tmp_path / "f")
    meta = json.loads((d / "scene.json").read_text())
    (d / "scene.json").write_text(json.dumps({**meta, "n_frames": 0}))
    assert "n_frames" in error_line(["build-map", d, "-o", tmp_path / "m.iesm"], capsys)


@pytest.mark.parametrize("field, value", [("mean_height", float("nan")), ("id", True), ("id", 2**70)])
def test_bad_instance_fields_in_a_manifest(tmp_path, capsys, apartment_path, field, value):
    def patch(m):
        m["instances"][0][field] = value

    _with_manifest(apartment_path, tmp_path / "bad.iesm", patch)
    assert field in error_line(["info", tmp_path / "bad.iesm"], capsys)


def test_true_as_an_object_id_is_refused(env, capsys):
    doc = json.loads(json.dumps(OBJECTS))
    doc["objects"][0]["id"] = True
    (env / "t.json").write_text(json.dumps(doc))
    assert "boolean" in error_line(["import", env / "t.json", "-o", env / "o.iesm"], capsys)


def test_an_empty_suite_is_an_error(env, capsys):
    (env / "s.jsonl").write_text("\n")
    assert "no query" in error_line(["eval", env / "s.jsonl", "-o", env / "run", "-m", "keyword"], capsys)
    assert not (env / "run").exists()


@pytest.mark.parametrize("spec", ["osr=nan", "osr=inf", "mrr=-0.1", "top3=2"])
def test_fail_under_values_must_be_in_0_1(env, capsys, spec):
    (env / "s.jsonl").write_text(json.dumps(LINE) + "\n")
    assert "--fail-under" in error_line(["eval", env / "s.jsonl", "-o", env / "run", "--fail-under", spec], capsys)


# ---------------------------------------------------------------------- off-contract exits
def test_a_corrupt_run_json_is_one_line(env, capsys):
    (env / "s.jsonl").write_text(json.dumps(LINE) + "\n")
    argv = ["eval", env / "s.jsonl", "-o", env / "run", "-m", "keyword", "--no-cache"]
    assert run(list(map(str, argv))) == 0
    capsys.readouterr()
    (env / "run" / "run.json").write_text(json.dumps({"suites": 3}))
    assert "run.json" in error_line([*argv, "--resume"], capsys)


def test_a_bad_indptr_is_one_line(tmp_path, capsys, apartment_path):
    buf = io.BytesIO()
    np.save(buf, np.array([[0, 1], [2, 3]], np.int64))
    _with_manifest(apartment_path, tmp_path / "i.iesm", lambda m: None, {"occupancy.indptr.npy": buf.getvalue()})
    error_line(["info", tmp_path / "i.iesm"], capsys)


def test_an_unknown_method_leaves_no_run_directory(env, capsys):
    (env / "s.jsonl").write_text(json.dumps(LINE) + "\n")
    assert "bogus" in error_line(["eval", env / "s.jsonl", "-o", env / "run", "-m", "bogus"], capsys)
    assert not (env / "run").exists()
    assert run(["eval", str(env / "s.jsonl"), "-o", str(env / "run"), "-m", "keyword", "--no-cache"]) == 0


def test_stale_temp_files_of_a_killed_writer_are_cleaned_on_the_next_run(env, capsys):
    dead = 2**22 + 12345  # beyond the default pid_max: no such process
    stale_file = env / f".m.iesm.iesm-tmp.{dead}.abc.iesm"
    stale_dir = env / f".m.iesm.iesm-tmp.{dead}.xyz"
    live = env / f".m.iesm.iesm-tmp.{os.getpid() - 0}.keep.iesm"  # ours, in progress: kept
    stale_file.write_bytes(b"half")
    stale_dir.mkdir()
    (stale_dir / "frames").mkdir()
    other = env / ".m.iesm.backup"  # not our naming: kept
    other.write_text("x")
    live.write_text("x")
    _small_map(env)
    assert not stale_file.exists() and not stale_dir.exists() and other.exists() and live.exists()


# ---------------------------------------------------------------------- templates cannot run code
def test_a_template_cannot_run_code(tmp_path):
    from iesm_agent.prompting import PromptLibrary

    (tmp_path / "evil.j2").write_text("{% block user %}{{ cycler.__init__.__globals__.os.popen('echo pwned').read() }}"
                                      "{% endblock %}")
    with pytest.raises(IesmError, match="unsafe") as info:
        PromptLibrary([tmp_path]).render("evil.j2")
    assert "\n" not in str(info.value)


def _plain_render(env, name, variables):
    template = env.get_template(name)
    context = template.new_context(variables)
    return [text for role in ("system", "user") if role in template.blocks
            and (text := "".join(template.blocks[role](context)).strip())]


def _context_for(env, name, candidates):
    """Variables that render template `name`: each undefined name gets the first of a few
    generic values (a candidate list, one candidate, a string, a number) the template accepts."""
    import re

    import jinja2

    variables: dict = {"query": "the red chair in the kitchen", "kappa": 2}
    for _ in range(40):
        try:
            _plain_render(env, name, variables)
            return variables
        except jinja2.UndefinedError as exc:
            missing = re.search(r"'(\w+)' is undefined", str(exc))
            if missing is None or missing.group(1) in variables:
                return None
            variables[missing.group(1)] = candidates
        except (TypeError, AttributeError, jinja2.TemplateError):
            last = list(variables)[-1]
            options = [candidates, candidates[0], "text", 2]
            index = next((i for i, o in enumerate(options) if o is variables[last] or o == variables[last]), 3)
            if index == 3:
                return None
            variables[last] = options[index + 1]
    return None


def test_shipped_templates_render_byte_identical_in_the_sandbox(lib):
    """Each shipped template rendered by the sandboxed library and by a plain Jinja environment
    with the same settings (the library before the sandbox) gives the same messages."""
    import jinja2

    from iesm_agent.prompting import fence, fence_lines
    from iesm_agent.resources import resource_dir

    plain = jinja2.Environment(loader=lib._env.loader, undefined=jinja2.StrictUndefined, trim_blocks=True,
                               lstrip_blocks=True)  # the library's settings, without the sandbox
    plain.filters.update(lib._env.filters)
    plain.globals.update(lib._env.globals)
    assert plain.filters["fence"] is fence and plain.filters["fence_lines"] is fence_lines
    candidates = [{"id": 3, "label": "chair", "room": "kitchen", "caption": "a <red> chair", "tags": {"color": "red"},
                   "alt_labels": ["seat"], "center": [1, 2, 0.4], "size": [0.5, 0.5, 0.9], "z_range": [0, 0.9],
                   "on": [], "under": [7], "name": "obj", "gate_description": "objects", "text": "a red chair",
                   "type": "o"}]
    names = sorted(p.name for p in resource_dir("prompts").glob("*.j2"))
    rendered = []
    for name in names:
        variables = _context_for(plain, name, candidates)
        if variables is None:
            continue
        assert [m.content for m in lib.render(name, **variables)] == _plain_render(plain, name, variables), name
        rendered.append(name)
    # the retrieval templates at least (the caption and query-writing ones take structured
    # contexts this generic filler does not build; the caption pipeline tests render them)
    assert {"expert.j2", "gate.j2", "keyword.j2", "spatial.j2", "spr.j2"} <= set(rendered), rendered


# ---------------------------------------------------------------------- serving
def test_serve_refuses_a_public_bind_without_a_token(capsys, monkeypatch):
    monkeypatch.delenv("IESM_TOKEN", raising=False)
    err = error_line(["serve", "apartment", "--http", "0.0.0.0:0"], capsys)
    assert "--insecure-no-token" in err


def test_exposure_rule():
    from iesm_agent.server.app import check_exposure, is_loopback

    assert is_loopback("127.0.0.1") and is_loopback("::1") and is_loopback("LOCALHOST") and is_loopback("127.8.0.1")
    assert not is_loopback("0.0.0.0") and not is_loopback("::") and not is_loopback("192.168.1.5")
    check_exposure("0.0.0.0", "secret", False)
    check_exposure("0.0.0.0", None, True)
    with pytest.raises(IesmError):
        check_exposure("::", None, False)


def _headers_seen(host: bytes, origin: bytes | None = None) -> tuple[int | None, dict]:
    """(status the wrapper answered itself or None, headers it passed on) for one request."""
    from iesm_agent.server.app import checked_host_headers

    seen, sent = {}, []

    async def app(scope, receive, send):
        seen.update(dict(scope["headers"]))

    async def send(message):
        sent.append(message)

    headers = [(b"host", host), (b"x-other", b"KeepCase")] + ([(b"origin", origin)] if origin else [])
    asyncio.run(checked_host_headers(app)({"type": "http", "headers": headers}, None, send))
    return (sent[0]["status"] if sent else None), seen


def test_host_is_compared_case_insensitively():
    from mcp.server.transport_security import TransportSecurityMiddleware

    from iesm_agent.server.app import transport_security

    status, seen = _headers_seen(b"LOCALHOST:8000", b"HTTP://LocalHost:8000")
    assert status is None
    assert seen == {b"host": b"localhost:8000", b"origin": b"http://localhost:8000", b"x-other": b"KeepCase"}
    check = TransportSecurityMiddleware(transport_security("127.0.0.1", 8000))
    assert check._validate_host(seen[b"host"].decode()) and check._validate_origin(seen[b"origin"].decode())


@pytest.mark.parametrize("host, ok", [
    ("localhost:8000", True), ("127.0.0.1:8000", True), ("[::1]:8000", True), ("localhost", True),
    ("localhost:1@evil.example", False), ("127.0.0.1:8000.evil.example", False), ("localhost:8001", False),
    ("localhost:", False), ("localhost:8000:1", False), ("evil.example:8000", False), ("localhost.evil:8000", False),
])
def test_host_is_compared_as_host_and_port_exactly(host, ok):
    """Issue 31 (11): anything after `localhost:` passed; now the name and the port served."""
    from mcp.server.transport_security import TransportSecurityMiddleware

    from iesm_agent.server.app import transport_security

    assert TransportSecurityMiddleware(transport_security("127.0.0.1", 8000))._validate_host(host) is ok


@pytest.mark.parametrize("origin, ok", [
    ("http://localhost", True), ("https://127.0.0.1", True), ("http://localhost:8000", True),
    ("http://localhost:3000", True), ("http://[::1]:8000", True),
    ("http://localhost:1@evil.example", False), ("http://localhost:8000.evil.example", False),
    ("http://evil.example", False), ("http://localhost.evil.example", False), ("ftp://localhost", False),
])
def test_origin_is_a_loopback_name_with_or_without_a_numeric_port(origin, ok):
    """Issue 31 (11): `Origin: http://localhost` without a port was refused; a port that is not a
    number is refused by the wrapper before the SDK's `host:*` pattern sees it."""
    from mcp.server.transport_security import TransportSecurityMiddleware

    from iesm_agent.server.app import transport_security

    status, seen = _headers_seen(b"localhost:8000", origin.encode())
    passed = status is None and TransportSecurityMiddleware(
        transport_security("127.0.0.1", 8000))._validate_origin(seen[b"origin"].decode())
    assert passed is ok
    if not ok and status is not None:
        assert status == 403


# ---------------------------------------------------------------------- sim --force
def test_sim_force_only_replaces_a_frame_directory(tmp_path, capsys):
    victim = tmp_path / "home"
    victim.mkdir()
    (victim / "thesis.tex").write_text("precious")
    (victim / "src").mkdir()
    assert "not deleting" in error_line(["sim", "--out", victim, "--force"], capsys)
    assert (victim / "thesis.tex").read_text() == "precious"


def test_sim_force_accepts_a_frame_directory_of_ours(tmp_path):
    from iesm_agent.cli.outputs import looks_like_frames as _looks_like_frames

    d = write_tiny_frames(tmp_path / "f")
    assert _looks_like_frames(d)
    (d / "notes").mkdir()
    assert not _looks_like_frames(d)


def test_an_allowed_host_may_name_its_own_port():
    """`--allowed-host proxy.example:8443` (a name with the port a proxy sends) is compared as
    given, and a plain name takes the port served."""
    from mcp.server.transport_security import TransportSecurityMiddleware

    from iesm_agent.server.app import transport_security

    check = TransportSecurityMiddleware(transport_security("127.0.0.1", 8000, ("proxy.example:8443", "lab.example")))
    assert check._validate_host("proxy.example:8443") and check._validate_host("lab.example:8000")
    assert check._validate_host("lab.example") and check._validate_host("[::1]:8000")
    assert not check._validate_host("proxy.example:8000") and not check._validate_host("lab.example:8443")


def test_the_sandbox_gives_each_template_the_library_globals_as_one_dict(lib):
    """`prompting._sandbox`: a template's globals are one dict (Jinja's `ChainMap` is iterated in
    Python on every render) holding the library's globals; the environment is still the sandbox."""
    from jinja2.sandbox import SandboxedEnvironment

    from iesm_agent import contract

    template = lib._env.get_template("expert.j2")
    assert isinstance(lib._env, SandboxedEnvironment) and type(template.globals) is dict
    assert template.globals["task_line"] is contract.task_line and template.globals["range"] is lib._env.globals["range"]
