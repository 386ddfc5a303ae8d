"""`iesm eval` end to end: --fail-under exit codes, and a real run killed with SIGKILL and
resumed over a loopback chat-completions server (the response cache on)."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time

import pytest
from typer.testing import CliRunner

from iesm_agent.cli import app
from iesm_agent.errors import IesmError
from iesm_agent.evals.generate import generate_suite
from iesm_agent.evals.journal import read_journal


@pytest.fixture(scope="module")
def suite(tmp_path_factory):
    import asyncio

    path = tmp_path_factory.mktemp("cli") / "suite.jsonl"
    asyncio.run(generate_suite(["apartment"], path, per_type=3, seed=2))
    return path


@pytest.fixture
def no_embeddings(monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")


def test_fail_under_sets_the_exit_status(tmp_path, suite, no_embeddings):
    runner = CliRunner()
    ok = runner.invoke(app, ["eval", str(suite), "-m", "spr,keyword", "-o", str(tmp_path / "a"),
                             "--fail-under", "osr=0.0"])
    assert ok.exit_code == 0, ok.output
    summary = json.loads((tmp_path / "a" / "summary.json").read_text())
    keyword_osr = summary["methods"]["keyword"]["overall"]["osr"]
    assert 0 < keyword_osr < 1

    bad = runner.invoke(app, ["eval", str(suite), "-m", "spr,keyword", "-o", str(tmp_path / "b"),
                              "--fail-under", f"osr={keyword_osr + 0.01:.4f}"])
    assert bad.exit_code == 1
    assert f"fail-under: keyword: osr {keyword_osr:.3f} <" in bad.output
    assert (tmp_path / "b" / "report.md").exists()  # outputs are written before failing


def test_bad_fail_under_and_existing_run_dir_are_user_errors(tmp_path, suite, no_embeddings):
    result = CliRunner().invoke(app, ["eval", str(suite), "-o", str(tmp_path / "r"), "--fail-under", "speed=3"])
    assert isinstance(result.exception, IesmError) and "expected METRIC=VALUE" in str(result.exception)
    (tmp_path / "r").mkdir()
    (tmp_path / "r" / "results.jsonl").write_text("")
    result = CliRunner().invoke(app, ["eval", str(suite), "-m", "keyword", "-o", str(tmp_path / "r")])
    assert isinstance(result.exception, IesmError) and "run directory is not empty" in str(result.exception)


def _eval(suite, run, server, *extra):
    return [sys.executable, "-m", "iesm_agent.cli", "eval", str(suite), "-m", "spr,keyword",
            "--provider", "openai-compat:offline", "--base-url", server.base_url, "-o", str(run),
            "--concurrency", "2", *extra]


def _settled_request_count(server, quiet_s=0.5):
    """The server's request count once no request of the killed client is still arriving (a
    request it sent just before the kill can reach a handler thread after the kill)."""
    count = -1
    while count != server.request_count:
        count = server.request_count
        time.sleep(quiet_s)
    return count


@pytest.mark.slow
def test_killed_run_resumes_to_the_same_results(tmp_path, suite):
    from loopback import LoopbackServer
    from iesm_agent.providers.offline import OfflineModel

    env = {**os.environ, "IESM_CACHE_DIR": str(tmp_path / "cache"), "IESM_EMBEDDINGS": "0"}
    total = 2 * len(suite.read_text().splitlines())
    with LoopbackServer(OfflineModel(use_embeddings=False), delay_s=0.15) as server:
        clean = tmp_path / "clean"
        subprocess.run(_eval(suite, clean, server, "--no-cache"), env=env, check=True, capture_output=True)

        run = tmp_path / "run"
        proc = subprocess.Popen(_eval(suite, run, server), env=env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        journal = run / "results.jsonl"
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not (journal.exists() and journal.read_text().count("\n") >= 5):
            time.sleep(0.01)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        before = len(read_journal(journal))
        assert 5 <= before < total, "the kill should land mid-run"

        requests = _settled_request_count(server)
        resumed = subprocess.run(_eval(suite, run, server, "--resume"), env=env, capture_output=True, text=True)
        assert resumed.returncode == 0, resumed.stderr
        new = read_journal(journal)[before:]
        # every resumed pair made one call: a cache hit (answered before the kill) or a request
        assert server.request_count - requests == len(new) - sum(r.cache_hits for r in new)

    final, reference = read_journal(journal), read_journal(clean / "results.jsonl")
    keys = [r.key for r in final]
    assert len(keys) == len(set(keys)) == total
    assert {r.key: r.predicted for r in final} == {r.key: r.predicted for r in reference}
    ours, theirs = (json.loads((d / "summary.json").read_text())["methods"] for d in (run, clean))
    for variant in ("spr", "keyword"):
        assert ours[variant]["by_type"] == theirs[variant]["by_type"]
        assert ours[variant]["overall"]["n"] == total // 2


def test_resume_refuses_a_different_configuration(tmp_path, suite, no_embeddings):
    runner = CliRunner()
    run = tmp_path / "run"
    assert runner.invoke(app, ["eval", str(suite), "-m", "keyword", "-o", str(run)]).exit_code == 0
    result = runner.invoke(app, ["eval", str(suite), "-m", "spr", "-o", str(run), "--resume"])
    assert "refusing to resume" in str(result.exception) and "variants" in str(result.exception)
