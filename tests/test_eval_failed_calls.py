"""Failed model calls where scripts look: counted in the eval summary, a non-zero exit unless
allowed (--max-failed-calls), asked again by --resume; `iesm ask` against a dead endpoint is
one line and exit 2. Real loopback HTTP server, no mocks."""

from __future__ import annotations

import asyncio
import json
import os
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from iesm_agent.cli import app
from iesm_agent.evals.generate import generate_suite
from iesm_agent.evals.journal import read_journal
from loopback import Fault, LoopbackServer
from iesm_agent.providers.offline import OfflineModel


@pytest.fixture(scope="module")
def suite(tmp_path_factory):
    path = tmp_path_factory.mktemp("failed") / "suite.jsonl"
    asyncio.run(generate_suite(["apartment"], path, per_type=1, seed=3))
    return path


@pytest.fixture
def quiet(monkeypatch, tmp_path):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    monkeypatch.setenv("IESM_CACHE_DIR", str(tmp_path / "cache"))


def test_failed_calls_are_counted_fail_the_run_and_are_retried_on_resume(tmp_path, suite, quiet):
    queries = [json.loads(line)["query"] for line in suite.read_text().splitlines() if line.strip()]
    unlucky = queries[1]
    healthy = {"on": False}

    def faults(index, body):  # 404 is not retried: every call of one query fails at once
        return None if healthy["on"] or unlucky not in json.dumps(body) else Fault.http(404)

    out = tmp_path / "run"
    args = ["eval", str(suite), "-m", "spr", "-p", "openai-compat:m", "-o", str(out), "--no-cache"]
    runner = CliRunner()
    with LoopbackServer(OfflineModel(use_embeddings=False), faults=faults) as server:
        failed = runner.invoke(app, args + ["--base-url", server.base_url])
        summary = json.loads((out / "summary.json").read_text())
        allowed = runner.invoke(app, args + ["--base-url", server.base_url, "--resume",
                                             "--max-failed-calls", "1"])
        healthy["on"] = True
        sent_before = server.request_count
        resumed = runner.invoke(app, args + ["--base-url", server.base_url, "--resume"])
    assert failed.exit_code == 1, failed.output
    assert "1 model call(s) failed in 1 result(s) (allowed: 0)" in failed.output
    assert summary["run"]["failed_calls"] == 1 and summary["run"]["queries_with_failed_calls"] == 1
    assert allowed.exit_code == 0, allowed.output  # retried, failed again, but allowed
    assert resumed.exit_code == 0, resumed.output
    assert server.request_count - sent_before == 1  # only the failed query was asked again
    final = json.loads((out / "summary.json").read_text())
    assert final["run"]["failed_calls"] == 0 and final["run"]["results"] == len(queries)
    records = read_journal(out / "results.jsonl")
    assert len(records) == len(queries) + 2  # the two failed attempts stay in the journal
    assert [r.failed_calls for r in records if r.query == unlucky] == [1, 1, 0]


def test_ask_against_a_dead_endpoint_is_one_line_and_exit_2(tmp_path):
    with LoopbackServer(OfflineModel(use_embeddings=False)) as server:
        url = server.base_url
    env = {**os.environ, "IESM_EMBEDDINGS": "0", "IESM_CACHE_DIR": str(tmp_path)}
    proc = subprocess.run([sys.executable, "-c", "from iesm_agent.cli import main; main()", "ask", "apartment",
                           "somewhere to sleep", "-p", "openai-compat:x", "--base-url", url],
                          capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("iesm: error: openai-compat:x: all 5 model calls failed")
    assert "is the server running" in lines[0] and "Traceback" not in proc.stderr
