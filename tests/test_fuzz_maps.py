"""Fuzzing the map readers through `iesm import` / `iesm info`: object lists, the paper's caption
format (with inner caption JSON), PLY files and `.iesm` archives. Every malformed input is exit 2
with one `iesm: error:` line and no output file (issue 25)."""

from __future__ import annotations

import io
import json
import random
import struct
import zipfile

import numpy as np
import pytest

from fuzzing import FAST, SLOW, Tally, check_cli, fuzz_json

OBJECTS = {"scene_id": "fuzz", "rooms": [{"id": 1, "label": "kitchen", "polygon": [[0, 0], [4, 0], [4, 3], [0, 3]]}],
           "objects": [{"id": 1, "label": "chair", "center": [1.0, 1.0, 0.45], "size": [0.5, 0.5, 0.9],
                        "room": 1, "tags": {"color": "red"}, "color_rgb": [200, 10, 10]},
                       {"id": 2, "label": "table", "center": [2.0, 1.5, 0.4], "size": [1.2, 0.8, 0.8],
                        "alt_labels": ["desk"], "caption": "a wooden table"}]}
CAPTIONS = {"3": {"category": "chair", "room_cat": "kitchen", "room_id": 1, "top5_categories": ["chair", "stool"],
                  "caption": json.dumps({"color": "red", "material": "wood", "captions": "a red chair"})},
            "7": {"category": "table", "room_cat": None, "caption": "{\"captions\": \"a table\",}"}}


def _ply(rows: list[tuple[float, float, float, int]], count: int | None = None) -> bytes:
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(rows) if count is None else count}\n"
              "property float x\nproperty float y\nproperty float z\nproperty int instance_id\nend_header\n")
    return header.encode() + b"".join(struct.pack("<fffi", *r) for r in rows)


PLY_ROWS = [(1, 1, 10, 3), (2, 1, 12, 3), (5, 4, 8, 7), (6, 4, 8, 99)]


def _fuzz_objects(tmp_path, capsys, n, seed):
    src, out = tmp_path / "objs.json", tmp_path / "out.iesm"
    return fuzz_json("object list", OBJECTS, lambda t: src.write_text(t, encoding="utf-8", errors="surrogateescape"),
                     ["import", str(src), "-o", str(out)], capsys, n, seed, outputs=(out,))


def _fuzz_captions(tmp_path, capsys, n, seed):
    src, out = tmp_path / "scene_f_caption.json", tmp_path / "out.iesm"
    (tmp_path / "scene_f_ours_map_with_id.ply").write_bytes(_ply(PLY_ROWS))
    # the inner caption (a string holding JSON) is fuzzed too: the caption of "3" is a mutation site
    return fuzz_json("paper format", CAPTIONS, lambda t: src.write_text(t, encoding="utf-8", errors="surrogateescape"),
                     ["import", str(src), "-o", str(out)], capsys, n, seed, outputs=(out,))


def _ply_mutations(rng: random.Random):
    while True:
        kind = rng.choice(["count", "coords", "truncate", "header", "huge"])
        rows = [tuple(r) for r in PLY_ROWS]
        if kind == "count":
            yield kind, _ply(rows, rng.choice([0, 3, 5, 10**9, 2**40]))
        elif kind == "coords":
            i = rng.randrange(len(rows))
            value = rng.choice([float("nan"), float("inf"), -1.0, 1e30, 3e38, -3e38])
            rows[i] = tuple(value if k == rng.randrange(3) else v for k, v in enumerate(rows[i]))
            yield kind, _ply(rows)
        elif kind == "truncate":
            raw = _ply(rows)
            yield kind, raw[:rng.randrange(len(raw))]
        elif kind == "header":
            raw = _ply(rows).replace(b"property float z", rng.choice([b"property list uchar int z", b"property quad z",
                                                                      b"", b"property float z extra"]))
            yield kind, raw.replace(b"binary_little_endian", rng.choice([b"binary_little_endian", b"ascii"]))
        else:  # a grid of 1e6 x 1e6 cells from two far corners
            rows.append((1e6, 1e6, 1.0, 3))
            yield kind, _ply(rows)


def _fuzz_ply(tmp_path, capsys, n, seed):
    src, ply, out = tmp_path / "scene_f_caption.json", tmp_path / "f.ply", tmp_path / "out.iesm"
    src.write_text(json.dumps(CAPTIONS), encoding="utf-8")
    gen = _ply_mutations(random.Random(seed))
    for _ in range(n):
        kind, raw = next(gen)
        ply.write_bytes(raw)
        code = check_cli(["import", str(src), "--ply", str(ply), "-o", str(out)], capsys, outputs=(out,))
        Tally.add("PLY", f"{kind}:{'refused' if code == 2 else 'accepted'}")


def _archive(members: dict[str, bytes]) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in members.items():
            zf.writestr(name, data)
    return buf.getvalue()


def _npy(arr: np.ndarray) -> bytes:
    buf = io.BytesIO()
    np.save(buf, arr, allow_pickle=True)
    return buf.getvalue()


def _iesm_mutations(base: bytes, rng: random.Random):
    with zipfile.ZipFile(io.BytesIO(base)) as zf:
        members = {n: zf.read(n) for n in zf.namelist()}
    manifest = json.loads(members["manifest.json"])
    gen = __import__("fuzzing").mutations(manifest, rng)
    while True:
        kind = rng.choice(["manifest", "manifest", "truncate", "flip", "member", "bomb", "grid"])
        m = dict(members)
        if kind == "manifest":
            sub, text = next(gen)
            m["manifest.json"] = text.encode("utf-8", "surrogateescape")
            kind = f"manifest-{sub}"
        elif kind == "truncate":
            yield kind, base[:rng.randrange(len(base))]
            continue
        elif kind == "flip":
            raw = bytearray(base)
            for _ in range(rng.randint(1, 16)):
                raw[rng.randrange(len(raw))] = rng.randrange(256)
            yield kind, bytes(raw)
            continue
        elif kind == "member":
            name = rng.choice([n for n in m if n.endswith(".npy")])
            m[name] = rng.choice([b"", _npy(np.array([{"a": 1}], dtype=object)), _npy(np.array(["x", "y"])),
                                  _npy(np.zeros((3, 3, 3))), m[name][:20], b"\x93NUMPY\x01\x00\xff\xff{"])
        elif kind == "bomb":  # a room map declared (and stored) far larger than its grid
            entry = next((e for e in manifest["arrays"] if e["name"] == "room_map"), None)
            big = rng.choice([(4096, 4096), (32768, 32768)])
            bad = json.loads(json.dumps(manifest))
            for e in bad["arrays"]:
                if e is not None and e["name"] == "room_map":
                    e["shape"] = list(big)
            if entry is not None:
                header = _npy(np.zeros((1, 1), np.int8))  # header claims 1x1; rewritten below
                hdr = header.replace(b"(1, 1)", str(big).encode())
                m[entry["member"]] = hdr  # no data: the header alone must be refused
            m["manifest.json"] = json.dumps(bad).encode()
        else:  # a manifest declaring a 1e6 x 1e6 grid
            bad = json.loads(json.dumps(manifest))
            bad["grid"]["height"] = bad["grid"]["width"] = rng.choice([10**6, 2**31, 32768])
            m["manifest.json"] = json.dumps(bad).encode()
        yield kind, _archive(m)


def _fuzz_iesm(tmp_path, capsys, n, seed, apartment_path):
    base = apartment_path.read_bytes()
    bad = tmp_path / "bad.iesm"
    gen = _iesm_mutations(base, random.Random(seed))
    for _ in range(n):
        kind, raw = next(gen)
        bad.write_bytes(raw)
        code = check_cli(["info", str(bad)], capsys)
        Tally.add(".iesm", f"{kind.split('-')[0]}:{'refused' if code == 2 else 'accepted'}")


def test_fuzz_object_lists(tmp_path, capsys):
    _fuzz_objects(tmp_path, capsys, FAST, seed=1)


def test_fuzz_paper_caption_format(tmp_path, capsys):
    _fuzz_captions(tmp_path, capsys, FAST, seed=2)


def test_fuzz_ply(tmp_path, capsys):
    _fuzz_ply(tmp_path, capsys, FAST, seed=3)


def test_fuzz_iesm_archives(tmp_path, capsys, apartment_path):
    _fuzz_iesm(tmp_path, capsys, FAST, seed=4, apartment_path=apartment_path)


@pytest.mark.slow
def test_fuzz_map_readers_seeded_long_run(tmp_path, capsys, apartment_path):
    for k, fuzz in enumerate((_fuzz_objects, _fuzz_captions, _fuzz_ply)):
        d = tmp_path / str(k)
        d.mkdir()
        fuzz(d, capsys, SLOW, seed=100 + k)
    _fuzz_iesm(tmp_path, capsys, SLOW, seed=103, apartment_path=apartment_path)
