"""Shared by the fuzz tests (tests/test_fuzz_*.py): seeded malformed variants of a valid input, and
the one assertion every reader must pass (exit 2, one `iesm: error:` line, no traceback, nothing
left behind). Cases run in-process through `iesm_agent.cli.run`, so hundreds take seconds.

`FUZZ_CASES` (environment) scales the slow runs; the fast runs use a few dozen cases per reader."""

from __future__ import annotations

import json
import os
import random
from pathlib import Path
from typing import Any, Callable, Iterator

from iesm_agent.cli import run

#: cases per reader: fast (default run) and slow (`-m slow`)
FAST = 40
SLOW = int(os.environ.get("FUZZ_CASES", "400"))

DEEP = 100_000  # nesting that broke the recursive JSON parser
BAD_NUMBERS = ["NaN", "Infinity", "-Infinity", "1e308", "-1e308", str(2**70), "1e12", "-1"]
WRONG_TYPES = ["true", "false", "null", '"x"', "[]", "{}", '[1, "a", null]', '{"a": {}}']


def _paths(value: Any, prefix: tuple = ()) -> Iterator[tuple]:
    """Every path (tuple of keys / indices) into a JSON value, the root included."""
    yield prefix
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _paths(v, prefix + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from _paths(v, prefix + (i,))


_MARK = "\u0000FUZZ\u0000"


def _replace_at(doc: Any, path: tuple, raw: str) -> str:
    """JSON text of `doc` with the value at `path` replaced by raw JSON-ish text `raw`."""
    doc = json.loads(json.dumps(doc))
    if not path:
        return raw
    node = doc
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = _MARK
    return json.dumps(doc).replace(json.dumps(_MARK), raw)


def mutations(doc: Any, rng: random.Random) -> Iterator[tuple[str, str]]:
    """Endless (kind, text) malformed variants of JSON document `doc`: deep nesting, truncation,
    non-finite and huge numbers, wrong types, garbage bytes."""
    text = json.dumps(doc)
    paths = list(_paths(doc))
    numbers = [p for p in paths if _get(doc, p).__class__ in (int, float)] or paths
    while True:
        kind = rng.choice(["nesting", "truncation", "number", "type", "garbage"])
        if kind == "nesting":
            depth = rng.choice([DEEP, 5000, 200, 65])
            opener = rng.choice(["[", "{\"a\": "])
            closer = "]" if opener == "[" else "}"
            yield kind, _replace_at(doc, rng.choice(paths), opener * depth + "1" + closer * depth * rng.randint(0, 1))
        elif kind == "truncation":
            yield kind, text[:rng.randrange(0, max(len(text) - 1, 1))]
        elif kind == "number":
            yield kind, _replace_at(doc, rng.choice(numbers), rng.choice(BAD_NUMBERS))
        elif kind == "type":
            yield kind, _replace_at(doc, rng.choice(paths), rng.choice(WRONG_TYPES))
        else:
            raw = bytearray(text.encode())
            for _ in range(rng.randint(1, 8)):
                raw[rng.randrange(len(raw))] = rng.randrange(256)
            yield kind, raw.decode("latin-1")


def _get(doc: Any, path: tuple) -> Any:
    for key in path:
        doc = doc[key]
    return doc


def check_cli(argv: list[str], capsys, *, outputs: tuple[Path, ...] = (), may_pass: bool = True) -> int:
    """Run `argv`; it must exit 0 (when `may_pass`: the mutation left the input valid) or exit 2
    with exactly one `iesm: error:` line on stderr, no traceback and none of `outputs` (nor a
    temporary file beside them) left behind. Any other exception fails the test. Returns the code."""
    code = run(argv)
    out, err = capsys.readouterr()
    assert code in ((0, 2) if may_pass else (2,)), f"{argv}: exit {code}\n{err[-2000:]}"
    if code == 2:
        lines = err.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("iesm: error: "), f"{argv}: {err[-2000:]}"
        assert "Traceback" not in err
        for path in outputs:
            assert not path.exists(), f"{path} left behind after a refused input"
    for path in outputs:
        assert not list(path.parent.glob(f".{path.name}.iesm-tmp.*")), "temporary file left behind"
    if code == 0:
        for path in outputs:
            if path.is_file():
                path.unlink()
            elif path.is_dir():
                import shutil

                shutil.rmtree(path)
    return code


class Tally:
    """Counts per reader and outcome, printed at the end of the run (`-s` shows them)."""

    counts: dict[str, dict[str, int]] = {}

    @classmethod
    def add(cls, reader: str, outcome: str) -> None:
        cls.counts.setdefault(reader, {}).setdefault(outcome, 0)
        cls.counts[reader][outcome] += 1


def fuzz_json(reader: str, doc: Any, write: Callable[[str], None], argv: list[str], capsys, n: int, seed: int,
              outputs: tuple[Path, ...] = ()) -> dict[str, int]:
    """`n` seeded mutations of `doc`, each written with `write(text)` and checked with `argv`."""
    rng = random.Random(seed)
    gen = mutations(doc, rng)
    outcomes = {"refused": 0, "accepted": 0}
    for _ in range(n):
        kind, text = next(gen)
        write(text)
        code = check_cli(argv, capsys, outputs=outputs, may_pass=kind not in ("nesting",))
        outcomes["refused" if code == 2 else "accepted"] += 1
        Tally.add(reader, f"{kind}:{'refused' if code == 2 else 'accepted'}")
    return outcomes


H, W = 12, 16  # tiny frames


def write_tiny_frames(d: Path, n: int = 2) -> Path:
    """`n` tiny valid frames with hash-space embeddings in `d` (build-map accepts them)."""
    import numpy as np

    from iesm_agent.embeddings import HASH_SPACE, text_vectors
    from iesm_agent.frames import Frame, Intrinsics, SceneMeta, Segmentation, write_frame, write_frame_set

    emb, _ = text_vectors(["chair", "table"], HASH_SPACE)
    write_frame_set(d, SceneMeta(scene_id="fz", n_frames=n, embedding_space=HASH_SPACE, categories=["chair", "table"]),
                    Intrinsics(width=W, height=H, fx=80.0, fy=80.0, cx=7.5, cy=5.5))  # 2.5 cm a pixel at 2 m: 4 per cell
    for i in range(n):
        masks = np.zeros((2, H, W), bool)
        masks[0, 2:8, 3:9] = True
        masks[1, 7:, 8:] = True
        pose = np.eye(4)
        pose[:3, 3] = [0.1 * i, 0.0, 1.2]
        write_frame(d, Frame(index=i, rgb=np.full((H, W, 3), 120, np.uint8), depth=np.full((H, W), 2.0, np.float32),
                             pose=pose, segmentation=Segmentation(masks, emb, np.array([0.9, 0.8], np.float32))))
    return d
