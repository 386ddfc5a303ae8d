"""Peak memory of `iesm segment` on bad recordings (issue 31: "peak memory under 1 GB for any bad
recording"). Each named case of tests/test_fuzz_recordings.py (decompression-bomb headers, a pose
1e8 m away, /dev/zero and FIFO files, a million-line trajectory, ...) is written into a tiny valid
recording and run in a fresh process; its peak resident set (`ru_maxrss` from `wait4`), wall time
and exit status are measured. Figures: the largest peak and the slowest case; every case must end
with status 2 (refused in one line) within 60 s. A child's `ru_maxrss` starts from this process's
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
    note = "; ".join(bad)
    record("bad_recording_peak_mb", worst_mb, "MB", f"<= {LIMIT_MB} MB", worst_mb <= LIMIT_MB and not bad, note)
    record("bad_recording_slowest_s", slowest_s, "s", f"<= {TIMEOUT_S} s, exit 2", slowest_s <= TIMEOUT_S and not bad,
           note)
    print(f"{len(cases)} bad recordings: peak {worst_mb:.0f} MB, slowest {slowest_s:.1f} s"
          + (f"; not refused: {note}" if bad else "; every one refused (exit 2)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
