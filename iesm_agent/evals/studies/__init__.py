"""Studies: one command per results table, each writing OUT/table.md (the table with the exact
command, profile and seeds) and OUT/summary.json (per-seed rows and means) under docs/results/.

    python -m iesm_agent.evals.studies.mapping --seeds 10-14 --realism realistic --out docs/results/mapping-realistic
    python -m iesm_agent.evals.studies.rooms --seeds 10-14 --realism realistic --out docs/results/rooms-realistic
    python -m iesm_agent.evals.studies.captions --seeds 10-14 --realism realistic --out docs/results/captions-realistic
    python -m iesm_agent.evals.studies.calibration --seeds 10-14 --realism realistic --out docs/results/calibration-realistic
    python -m iesm_agent.evals.studies.retrieval --seeds 10-12 --realism realistic --out docs/results/retrieval-realistic
    python -m iesm_agent.evals.studies.storage --seeds 10-12 --realism realistic --out docs/results/storage-realistic

Seeds 0-4 are tuning seeds (the mapping thresholds, the room split and the realism profile were
set on them); reported tables use seeds 10 and up (`check_seeds`).
"""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import json
import sys
import tempfile
from pathlib import Path
from typing import Callable, Iterator, Optional

from ...errors import IesmError

#: seeds the thresholds and the realism profile were tuned on; never in a reported table
TUNING_SEEDS = frozenset(range(0, 5))


def parse_seeds(text: str) -> list[int]:
    """"0-4" or "0,2,5" -> seeds."""
    try:
        seeds: list[int] = []
        for part in text.split(","):
            lo, _, hi = part.partition("-")
            seeds += list(range(int(lo), int(hi or lo) + 1))
    except ValueError:
        raise IesmError(f"expected seeds like 0-4 or 0,2,5, got {text!r}", None, "--seeds") from None
    return seeds


def check_seeds(seeds: list[int], allow_tuning: bool) -> None:
    """Refuse tuning seeds in a reported table unless `allow_tuning` (--allow-tuning-seeds)."""
    bad = sorted(set(seeds) & TUNING_SEEDS)
    if bad and not allow_tuning:
        raise IesmError(f"seeds {bad} were used for tuning; report other seeds (or pass --allow-tuning-seeds)",
                        None, "--seeds")


def profile_arg(text: str) -> str:
    """argparse type of --realism."""
    from ...sim.realism import PROFILES

    if text not in PROFILES:
        raise argparse.ArgumentTypeError(f"choose from {', '.join(PROFILES)}")
    return text


class SceneCache:
    """Rendered scenes under `root`, one directory per (size, open plan, realism, seed), made once."""

    def __init__(self, root: Path):
        self.root = root

    def prepare(self, seed: int, size: str, open_plan: bool, realism: str, space: Optional[str] = None) -> Path:
        from ...sim import generate_scene, render_frames

        frames = self.root / f"{size}-{'open' if open_plan else 'walled'}-{realism}-{seed}"
        if not (frames / "gt" / "sim.json").is_file():
            render_frames(generate_scene(seed, size, open_plan), frames, space=space, realism=realism)
        return frames

    def built(self, frames: Path) -> Path:
        """The map `iesm build-map` makes of `frames` (cached beside it)."""
        from ...frames import FrameSet
        from ...mapping.build import build_map
        from ...store import save_map

        path = frames.with_suffix(".iesm")
        if not path.is_file():
            save_map(build_map(FrameSet.open(frames)), path)
        return path


def source_fingerprint() -> str:
    """12 hex digits of a hash over the package's Python sources: scenes, maps and runs cached
    under one fingerprint were made by the code that has it."""
    package = Path(__file__).resolve().parents[2]
    digest = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        digest.update(str(path.relative_to(package)).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:12]


@contextlib.contextmanager
def scene_frames(work: Optional[Path]) -> Iterator[SceneCache]:
    """A `SceneCache` in `work/code-<source fingerprint>` (kept: a later run of the same code reuses
    it, a run after a code change starts afresh) or in a temporary directory (removed afterwards)."""
    if work is not None:
        root = work / f"code-{source_fingerprint()}"
        root.mkdir(parents=True, exist_ok=True)
        yield SceneCache(root)
        return
    with tempfile.TemporaryDirectory() as tmp:
        yield SceneCache(Path(tmp))


def write_table(out: Path, title: str, command: str, body: str, summary: dict) -> None:
    """OUT/table.md (title, command, body) and OUT/summary.json (`summary` + the command)."""
    from ...fileio import write_text

    out.mkdir(parents=True, exist_ok=True)
    write_text(out / "summary.json", json.dumps({"command": command, **summary}, indent=1) + "\n")
    write_text(out / "table.md", f"# {title}\n\nCommand: `{command}`\n\n{body.rstrip()}\n")


def common_args(parser: argparse.ArgumentParser, default_seeds: str, default_out: str) -> None:
    """--seeds, --realism, --out, --work, --allow-tuning-seeds."""
    parser.add_argument("--seeds", default=default_seeds)
    parser.add_argument("--realism", type=profile_arg, default="realistic")
    parser.add_argument("--out", type=Path, default=Path(default_out))
    parser.add_argument("--work", type=Path, default=None, help="keep (and reuse) rendered scenes and maps here")
    parser.add_argument("--allow-tuning-seeds", action="store_true", help="for tuning runs; never for reported tables")


def study_command(module: str, seeds_arg: str, realism: str, out: Path, *extra: str) -> str:
    """The exact command that rebuilds a study's table (written at the top of table.md)."""
    return " ".join([f"python -m iesm_agent.evals.studies.{module} --seeds {seeds_arg} --realism {realism}",
                     *extra, f"--out {out.as_posix()}"])


def scene_rows(seeds: list[int], score: Callable[[int], dict], describe: Callable[[dict], str],
               label: str) -> tuple[list[dict], list[str]]:
    """({"seed": s, **score(s)} per seed, skipped): a seed whose scene the simulator or mapper cannot
    make (`IesmError`) is reported in `skipped`, not fatal. Progress (`describe(row)`) on stderr."""
    rows: list[dict] = []
    skipped: list[str] = []
    for seed in seeds:
        try:
            rows.append({"seed": seed, **score(seed)})
        except IesmError as exc:
            skipped.append(f"{label} seed {seed}: {exc}".strip())
            log_stderr(f"skipped {skipped[-1]}")
            continue
        log_stderr(f"{label} seed {seed}: {describe(rows[-1])}".strip())
    return rows, skipped


def study_main(module: str, doc: str, default_seeds: str, default_out: str,
               run: Callable[[argparse.Namespace, list[int]], object], argv: list[str] | None = None,
               extra_args: Callable[[argparse.ArgumentParser], None] | None = None) -> int:
    """The command line of study `module`: the common arguments (plus `extra_args`), seeds parsed
    and checked, `run(args, seeds)`, then OUT/table.md printed; a user error is one line, exit 2."""
    parser = argparse.ArgumentParser(prog=f"python -m iesm_agent.evals.studies.{module}",
                                     description=doc.strip().split("\n\n")[0])
    common_args(parser, default_seeds, default_out)
    if extra_args is not None:
        extra_args(parser)
    args = parser.parse_args(argv)
    try:
        seeds = parse_seeds(args.seeds)
        check_seeds(seeds, args.allow_tuning_seeds)
        run(args, seeds)
    except IesmError as exc:
        print(f"iesm: error: {exc}", file=sys.stderr)
        return 2
    table = args.out / "table.md"
    if table.is_file():
        print(table.read_text(encoding="utf-8"))
    return 0


def log_stderr(line: str) -> None:
    """Progress lines of a study, on stderr."""
    print(line, file=sys.stderr, flush=True)
