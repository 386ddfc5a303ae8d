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

import contextlib
import hashlib
import json
import sys
import tempfile
from pathlib import Path
from typing import Annotated, Callable, Iterator, Optional

import typer

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


def seeds_note(seeds_arg: str, untuned: str = "not used for tuning") -> str:
    """How a table's seeds stand to tuning: `untuned`, or a warning when any is a tuning seed
    (a run with --allow-tuning-seeds)."""
    tuned = sorted(set(parse_seeds(seeds_arg)) & TUNING_SEEDS)
    return f"tuning seeds {tuned} among them: not a held-out figure" if tuned else untuned


def check_profile(realism: str) -> None:
    """Refuse a realism profile the simulator does not have (--realism)."""
    from ...sim.realism import PROFILES

    if realism not in PROFILES:
        raise IesmError(f"no realism profile {realism!r}; choose from {', '.join(PROFILES)}", None, "--realism")


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


#: the options every study takes (each study's command function declares them with its defaults)
Seeds = Annotated[str, typer.Option(help="seeds as 10-14 or 10,12 (0-4 are tuning seeds: refused)")]
Realism = Annotated[str, typer.Option(help="the simulator's realism profile: easy or realistic")]
Out = Annotated[Path, typer.Option(help="folder for table.md and summary.json")]
Work = Annotated[Optional[Path], typer.Option(help="keep (and reuse) rendered scenes and maps here")]
AllowTuningSeeds = Annotated[bool, typer.Option("--allow-tuning-seeds", help="for tuning runs; never for reported tables")]


def study_command(module: str, seeds_arg: str, realism: str, out: Path, *extra: str) -> str:
    """The exact command that rebuilds a study's table (written at the top of table.md), with
    --allow-tuning-seeds when the seeds include tuning seeds (the command refuses them otherwise)."""
    tuning = ["--allow-tuning-seeds"] if set(parse_seeds(seeds_arg)) & TUNING_SEEDS else []
    return " ".join([f"python -m iesm_agent.evals.studies.{module} --seeds {seeds_arg} --realism {realism}",
                     *tuning, *extra, f"--out {out.as_posix()}"])


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


def run_checked(seeds_arg: str, realism: str, allow_tuning: bool, out: Path,
                run: Callable[[list[int]], object]) -> None:
    """The body of a study's command: seeds and profile checked before any work, `run(seeds)`,
    then OUT/table.md printed; a user error (`IesmError`) is one line on stderr and exit status 2."""
    try:
        seeds = parse_seeds(seeds_arg)
        check_seeds(seeds, allow_tuning)
        check_profile(realism)
        run(seeds)
    except IesmError as exc:
        print(f"iesm: error: {exc}", file=sys.stderr)
        raise typer.Exit(2) from None
    table = out / "table.md"
    if table.is_file():
        print(table.read_text(encoding="utf-8"))


def study_main(module: str, doc: str, command: Callable[..., None], argv: list[str] | None = None) -> int:
    """Run the typer command function `command` as `python -m iesm_agent.evals.studies.<module>`
    (help from the first paragraph of `doc`) on `argv` (default: the process's arguments) and
    return its exit status (2 for a usage error, as typer reports it)."""
    app = typer.Typer(add_completion=False, pretty_exceptions_enable=False)
    app.command(help=doc.strip().split("\n\n")[0])(command)
    try:
        app(args=argv, prog_name=f"python -m iesm_agent.evals.studies.{module}")
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else int(exc.code is not None)
    return 0


def log_stderr(line: str) -> None:
    """Progress lines of a study, on stderr."""
    print(line, file=sys.stderr, flush=True)
