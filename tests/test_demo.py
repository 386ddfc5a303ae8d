"""`make demo` end to end (the project's main job), in a fresh process on a temporary directory."""

import json
import os
import subprocess
import sys

import pytest

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.mark.slow
def test_demo_runs_the_whole_system_and_draws_its_pictures(tmp_path):
    env = {**os.environ, "IESM_DEMO_DIR": str(tmp_path), "HF_HUB_OFFLINE": "1"}
    proc = subprocess.run([sys.executable, "-m", "iesm_agent.demo"], env=env, capture_output=True, text=True,
                          timeout=280)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    for picture in ("instance_map.png", "room_map.png", "path.png", "results.png"):
        data = (tmp_path / picture).read_bytes()
        assert data[:8] == PNG and len(data) > 10_000, picture
    summary = json.loads((tmp_path / "eval" / "summary.json").read_text())
    assert {"mtefr", "mtefr-uniform", "spr", "keyword"} <= set(summary["methods"])
    assert set(summary["types"]) >= {"o", "or", "od", "ord", "ard", "s"}
    assert "N-SR" in (tmp_path / "eval" / "report.md").read_text()
    for step in ("iesm sim", "iesm build-map", "iesm rooms", "iesm caption", "iesm eval-map", "iesm path"):
        assert f"$ {step}" in proc.stdout
