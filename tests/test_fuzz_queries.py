"""Fuzzing what arrives with a query: suite lines (`iesm eval`), model replies (a bad reply never
breaks a run) and MCP tool arguments (a one-line IesmError, never a crash) (issue 25)."""

from __future__ import annotations

import asyncio
import json
import random

import pytest

from fuzzing import FAST, SLOW, WRONG_TYPES, Tally, check_cli, mutations

from iesm_agent.errors import IesmError

MAP = {"scene_id": "fq", "objects": [
    {"id": 1, "label": "chair", "center": [0.5, 0.5, 0.4], "size": [0.4, 0.4, 0.8], "room": "kitchen"},
    {"id": 2, "label": "table", "center": [1.5, 1.0, 0.4], "size": [0.8, 0.6, 0.8], "room": "kitchen"}]}
LINE = {"id": "q1", "map": "map.json", "query": "the chair", "type": "o", "target": 1, "accept": [1],
        "start": [1.0, 1.0], "group": "g"}


@pytest.fixture()
def quiet(monkeypatch, tmp_path):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    monkeypatch.setenv("IESM_CACHE_DIR", str(tmp_path / "cache"))


def _fuzz_suites(tmp_path, capsys, n, seed):
    (tmp_path / "map.json").write_text(json.dumps(MAP))
    suite, run_dir = tmp_path / "s.jsonl", tmp_path / "run"
    second = json.dumps({**LINE, "id": "q2", "query": "the table", "target": 2, "accept": []})

    def write(text: str) -> None:
        suite.write_text(text.replace("\n", " ") + "\n" + second + "\n", encoding="utf-8", errors="surrogateescape")

    return _counted("suite", LINE, write, ["eval", str(suite), "-o", str(run_dir), "-m", "keyword", "--no-cache"],
                    capsys, n, seed, run_dir)


def _counted(reader, doc, write, argv, capsys, n, seed, out):
    gen = mutations(doc, random.Random(seed))
    for _ in range(n):
        kind, text = next(gen)
        write(text)
        code = check_cli(argv, capsys, outputs=(out,), may_pass=kind != "nesting")
        Tally.add(reader, f"{kind}:{'refused' if code == 2 else 'accepted'}")


REPLY = {"ranked_instance_ids": [3, 1], "scores": {"obj": 4, "desc": 2}, "hints": {"obj": "a chair"},
         "object": "chair", "room": None}


def _fuzz_replies(store, n, seed):
    from iesm_agent.providers import FunctionModel
    from iesm_agent.retrieval import Retriever

    rng = random.Random(seed)
    gen = mutations(REPLY, rng)
    replies: list[str] = []

    def answer(messages, options):
        return replies[-1]

    for method in ("mtefr", "spr", "keyword"):
        retriever = Retriever(store, provider=FunctionModel(answer), method=method, cache=False)
        for _ in range(n // 3 + 1):
            kind, text = next(gen)
            replies.append(text if rng.random() < 0.7 else f"Sure! ```json\n{text}\n``` hope that helps")
            res = retriever.ask("the red chair in the kitchen")  # never raises on model misbehaviour
            assert res.ranking is not None
            Tally.add("model replies", f"{kind}:{'failure recorded' if res.failures else 'answered'}")


def _arguments(rng: random.Random, tool: str) -> dict:
    numbers = [float("nan"), float("inf"), -float("inf"), 1e308, -1e308, 2**70, -2**70, True, None, "1", [], {}]
    pick = lambda: rng.choice(numbers + [json.loads(w) for w in WRONG_TYPES] + [0, 1, 0.5, "x" * 3000])  # noqa: E731
    base = {"find_goal": {"query": "the chair"}, "plan_path": {"instance_id": 1, "start": [0.5, 0.5]},
            "get_instance": {"instance_id": 1}, "instances_near": {"x": 0.5, "y": 0.5, "radius": 1.0},
            "instances_at": {"x": 0.5, "y": 0.5}, "find_instances": {"category": "chair", "limit": 5},
            "stacked_with": {"instance_id": 1}}.get(tool, {})
    args = dict(base)
    for _ in range(rng.randint(1, 3)):
        key = rng.choice(list(args) + ["map", "bogus"]) if args else rng.choice(["map", "bogus"])
        args[key] = [pick(), pick()] if key == "start" and rng.random() < 0.7 else pick()
    return args


def _fuzz_mcp(store, n, seed):
    from iesm_agent.server import MapService

    rng = random.Random(seed)
    service = MapService({"fq": store}, providers=("offline",))
    names = [t.__name__ for t in service.tools()]

    async def go():
        for _ in range(n):
            tool = rng.choice(names)
            try:
                await service.call_tool(tool, _arguments(rng, tool))
                Tally.add("MCP arguments", "accepted")
            except IesmError as exc:
                assert "\n" not in str(exc), str(exc)
                Tally.add("MCP arguments", "refused")
        await service.aclose()

    asyncio.run(go())


@pytest.fixture(scope="module")
def small_store(tmp_path_factory):
    from iesm_agent.store import MapStore
    from iesm_agent.store.refs import open_map

    path = tmp_path_factory.mktemp("fq") / "map.json"
    path.write_text(json.dumps(MAP))
    return MapStore(open_map(path))


def test_fuzz_suite_lines(tmp_path, capsys, quiet):
    _fuzz_suites(tmp_path, capsys, FAST, seed=7)


def test_fuzz_model_replies(small_store, quiet):
    _fuzz_replies(small_store, FAST, seed=8)


def test_fuzz_mcp_arguments(small_store, quiet):
    _fuzz_mcp(small_store, FAST * 2, seed=9)


@pytest.mark.slow
def test_fuzz_query_inputs_seeded_long_run(tmp_path, capsys, quiet, small_store):
    _fuzz_suites(tmp_path, capsys, SLOW, seed=107)
    _fuzz_replies(small_store, SLOW, seed=108)
    _fuzz_mcp(small_store, SLOW, seed=109)
