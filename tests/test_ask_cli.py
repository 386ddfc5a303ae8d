"""`iesm ask` end to end in a subprocess: shipped map by name, offline model, JSON and human output."""

import json
import subprocess
import sys

import pytest

CLI = [sys.executable, "-c", "from iesm_agent.cli import main; main()"]


def iesm(*args, env=None):
    return subprocess.run(CLI + list(args), capture_output=True, text=True, timeout=120, env=env)


@pytest.fixture(scope="module")
def env(tmp_path_factory):
    import os

    return {**os.environ, "HF_HUB_OFFLINE": "1", "IESM_EMBEDDINGS": "0",
            "IESM_CACHE_DIR": str(tmp_path_factory.mktemp("cache"))}


def test_ask_json_on_the_shipped_map(apartment_store, env):
    out = iesm("ask", "apartment", "please take me to the refrigerator", "--json", env=env)
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    target = next(i.id for i in apartment_store.scene.instances if i.label == "refrigerator")
    for key in ("instance_id", "label", "room", "ranking", "gate", "experts", "scores", "latency_ms", "failures"):
        assert key in data
    assert data["instance_id"] == target and (data["label"], data["room"]) == ("refrigerator", "kitchen")
    assert set(data["gate"]) == {"obj", "room", "desc", "abs"}  # no spatial relation: spatial not asked
    assert abs(sum(data["gate"].values()) - 1) < 1e-9
    assert str(target) in data["scores"] and data["ranking"][0] == target
    assert data["failures"] == [] and len(data["calls"]) == 5  # gate, four experts
    assert any(n.startswith("spatial: not asked") for n in data["notes"])


def test_ask_human_output_with_explain_and_options(apartment_path, env):
    out = iesm("ask", str(apartment_path), "the fridge", "--method", "experts:obj,room", "--kappa", "3",
               "--explain", env=env)
    assert out.returncode == 0, out.stderr
    assert "refrigerator" in out.stdout and "gate weights:" in out.stdout
    assert "obj expert:" in out.stdout and "deciding expert:" in out.stdout
    assert "desc" not in out.stdout.split("gate weights:")[1].splitlines()[0]
    assert out.stdout.count("obj expert:") == 1  # the explanation is not repeated


@pytest.mark.parametrize("args, message", [
    (["no-such-map", "a chair"], "iesm: error: unknown map 'no-such-map': no file"),
    (["apartment", "a chair", "--method", "magic"], "unknown retrieval method 'magic'"),
    (["apartment", "a chair", "--method", "experts:obj,colour"], "unknown expert(s) ['colour']"),
    (["apartment", "a chair", "--kappa", "0"], "retrieval.kappa"),
    (["apartment", "a chair", "--max-candidates", "0"], "retrieval.max_candidates"),
    (["apartment", "a chair", "--max-concurrency", "0"], "--max-concurrency: must be >= 1"),
    (["apartment", "a chair", "--deadline", "0"], "retrieval.deadline_s"),
    (["apartment", "the sofa \udcff"], "the query is not valid text"),  # a byte not UTF-8 in argv
])
def test_ask_errors_are_one_line(monkeypatch, capsys, args, message):
    from iesm_agent.cli import main

    monkeypatch.setattr(sys, "argv", ["iesm", "ask", *args])
    with pytest.raises(SystemExit) as exit_info:
        main()
    err = capsys.readouterr().err
    assert exit_info.value.code == 2 and message in err and err.count("\n") == 1


def test_an_empty_query_is_refused_in_one_line(capsys):
    from iesm_agent.cli import run

    assert run(["ask", "apartment", "   "]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["iesm: error: query: the query is empty"]


def test_a_query_without_a_word_is_refused_in_one_line(capsys):
    from iesm_agent.cli import run

    assert run(["ask", "apartment", "\U0001F600 ?!"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["iesm: error: query: the query has no word (no letter or digit)"]
