"""Peak memory of `iesm segment` on bad recordings (issue 31: "peak memory under 1 GB for any bad
recording"). Each named case of tests/test_fuzz_recordings.py (decompression-bomb headers, a pose
1e8 m away, /dev/zero and FIFO files, a million-line trajectory, ...) is written into a tiny valid
recording and run in a fresh process; its peak resident set (`ru_maxrss` from `wait4`), wall time
and exit status are measured. Figures: the largest peak and the slowest case; every case must end
with status 2 (refused in one line) within 60 s. Then the largest recording the readers accept
(2048 x 2048 depth, 4096 x 4096 colour, random noise) is segmented, and its peak recorded. A child's `ru_maxrss` starts from this process's
own size at the fork (Linux keeps the high-water mark across exec), so the peaks are upper bounds.

Run: python benchmarks/bench_bad_recordings.py
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "tests"))
from results_io import record  # noqa: E402
from recordings import WRITERS  # noqa: E402
from test_fuzz_recordings import (REPLICA_CASES, SEVEN_CASES, TUM_CASES, _replica_case,  # noqa: E402
                                  _seven_case, _tum_case)

LIMIT_MB = 1024
TIMEOUT_S = 60


def measure(argv: list[str]) -> tuple[int, float, float, str]:
    """(exit status, peak RSS MB, wall s, last stderr line) of `iesm argv` in a fresh process
    (killed after `TIMEOUT_S`: status -9)."""
    env = {**os.environ, "HF_HUB_OFFLINE": "1"}
    t0 = time.perf_counter()
    with tempfile.TemporaryFile() as err:
        proc = subprocess.Popen([sys.executable, "-m", "iesm_agent.cli", *argv], stdout=subprocess.DEVNULL,
                                stderr=err, env=env)
        while True:  # reaped here with wait4, which reports the child's peak RSS
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.perf_counter() - t0 > TIMEOUT_S:
                proc.kill()
            time.sleep(0.02)
        proc.returncode = os.waitstatus_to_exitcode(status)  # already reaped: Popen must not wait again
        wall = time.perf_counter() - t0
        err.seek(0)
        lines = err.read().decode("utf-8", "replace").strip().splitlines()
    return proc.returncode, usage.ru_maxrss / 1024, wall, lines[-1] if lines else ""


def at_the_bounds(d: Path) -> Path:
    """A 7-Scenes recording as large as the readers accept: two 2048 x 2048 noisy depth frames
    (MAX_FRAME_PIXELS) with 4096 x 4096 random-noise colour JPEGs (fileio.MAX_IMAGE_PIXELS)."""
    import cv2
    import numpy as np

    d.mkdir(parents=True)
    side, f = 2048, 1500.0
    (d / "camera-intrinsics.txt").write_text(f"{f} 0 {side / 2 - 0.5}\n0 {f} {side / 2 - 0.5}\n0 0 1\n")
    v = np.arange(side)[:, None] - (side / 2 - 0.5)
    depth = np.broadcast_to(np.minimum(np.where(v > 0, 1.4 * f / np.maximum(v, 1e-6), np.inf), 2.5), (side, side))
    rng = np.random.default_rng(0)
    for i in range(2):
        noisy = np.rint(depth * 1000 + rng.integers(0, 30, (side, side))).astype(np.uint16)
        (d / f"frame-{i:06d}.depth.png").write_bytes(cv2.imencode(".png", noisy)[1].tobytes())
        colour = rng.integers(0, 255, (2 * side, 2 * side, 3), dtype=np.uint8)
        (d / f"frame-{i:06d}.color.jpg").write_bytes(cv2.imencode(".jpg", colour)[1].tobytes())
        pose = np.eye(4)
        pose[0, 3] = 0.05 * i
        (d / f"frame-{i:06d}.pose.txt").write_text("\n".join(" ".join(map(str, r)) for r in pose) + "\n")
    return d


def main() -> int:
    cases = [("7scenes", name, _seven_case) for name in SEVEN_CASES]
    cases += [("replica", name, _replica_case) for name in REPLICA_CASES]
    cases += [("tum", name, _tum_case) for name in TUM_CASES]
    worst_mb, slowest_s, bad = 0.0, 0.0, []
    with tempfile.TemporaryDirectory() as tmp:
        for layout, name, damage in cases:
            src = WRITERS[layout](Path(tmp) / f"{layout}-{name}")
            damage(name, src)
            code, peak, wall, last = measure(["segment", str(src), "-o", str(Path(tmp) / f"out-{name}"),
                                              "--segmenter", "geometric"])
            print(f"{layout:8} {name:22} exit {code}  peak {peak:7.1f} MB  {wall:5.1f} s  {last[:90]}")
            worst_mb, slowest_s = max(worst_mb, peak), max(slowest_s, wall)
            if code != 2 or wall > TIMEOUT_S:
                bad.append(f"{layout}/{name}: exit {code} in {wall:.0f} s")
        src = at_the_bounds(Path(tmp) / "bounds")
        code, peak, wall, last = measure(["segment", str(src), "-o", str(Path(tmp) / "out-bounds"),
                                          "--segmenter", "geometric"])
        print(f"7scenes  {'at the bounds (accepted)':22} exit {code}  peak {peak:7.1f} MB  {wall:5.1f} s")
        bounds_mb = peak
        if code != 0:
            bad.append(f"at the bounds: exit {code} ({last[:80]})")
    note = "; ".join(bad)
    record("bad_recording_peak_mb", worst_mb, "MB", f"<= {LIMIT_MB} MB", worst_mb <= LIMIT_MB and not bad, note)
    record("bad_recording_slowest_s", slowest_s, "s", f"<= {TIMEOUT_S} s, exit 2", slowest_s <= TIMEOUT_S and not bad,
           note)
    record("largest_accepted_frame_peak_mb", bounds_mb, "MB", f"<= {LIMIT_MB} MB", bounds_mb <= LIMIT_MB,
           "segment of 2048 x 2048 depth + 4096 x 4096 colour frames")
    print(f"{len(cases)} bad recordings: peak {worst_mb:.0f} MB, slowest {slowest_s:.1f} s"
          + (f"; not refused: {note}" if bad else "; every one refused (exit 2)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
