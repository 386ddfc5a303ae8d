"""Fuzzing the frame-directory reader through `iesm build-map` (scene.json, intrinsics.json, pose.txt,
seg.npz) and `--cell-labels` through `iesm rooms`: exit 2, one line, no map written (issue 25)."""

from __future__ import annotations

import io
import json
import random
import shutil
import zipfile

import numpy as np
import pytest

from fuzzing import FAST, SLOW, H, W, Tally, check_cli, mutations, write_tiny_frames

from iesm_agent.embeddings import HASH_SPACE, text_vectors


@pytest.fixture(scope="module")
def base_frames(tmp_path_factory):
    return write_tiny_frames(tmp_path_factory.mktemp("frames"))


def _npz(arrays: dict[str, np.ndarray], allow_pickle: bool = False) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, arr in arrays.items():
            b = io.BytesIO()
            np.save(b, arr, allow_pickle=allow_pickle)
            zf.writestr(f"{name}.npy", b.getvalue())
    return buf.getvalue()


def _seg_mutation(rng: random.Random, emb: np.ndarray) -> tuple[str, bytes]:
    masks = np.zeros((2, H, W), bool)
    masks[0, 2:8, 3:9] = True
    scores = np.array([0.9, 0.8], np.float32)
    kind = rng.choice(["nan-emb", "nan-score", "string-mask", "shape", "truncate", "empty", "missing", "huge", "object"])
    arrays = {"masks": masks, "embeddings": emb.copy(), "scores": scores}
    if kind == "nan-emb":
        arrays["embeddings"][rng.randrange(2), rng.randrange(emb.shape[1])] = rng.choice([np.nan, np.inf])
    elif kind == "nan-score":
        arrays["scores"][0] = rng.choice([np.nan, 7.0, -1.0, np.inf])
    elif kind == "string-mask":
        arrays["masks"] = np.array([["ab"] * W] * H)[None].repeat(2, 0)
    elif kind == "shape":
        arrays["masks"] = np.zeros(rng.choice([(2, W, H), (2, H), (1, 2, H, W)]), bool)
    elif kind == "truncate":
        raw = _npz(arrays)
        return kind, raw[:rng.randrange(len(raw))]
    elif kind == "empty":
        return kind, b""
    elif kind == "missing":
        arrays.pop(rng.choice(list(arrays)))
    elif kind == "huge":  # a header declaring 10^5 masks with hardly any data behind it
        b = io.BytesIO()
        np.save(b, np.zeros((1, H, W), bool))
        header = b.getvalue().replace(b"(1, 12, 16)", b"(100000, 12, 16)")
        buf = io.BytesIO()
        with zipfile.ZipFile(buf, "w") as zf:
            zf.writestr("masks.npy", header)
            for k in ("embeddings", "scores"):
                bb = io.BytesIO()
                np.save(bb, arrays[k])
                zf.writestr(f"{k}.npy", bb.getvalue())
        return kind, buf.getvalue()
    else:
        return kind, _npz({**arrays, "scores": np.array([{"x": 1}, None], dtype=object)}, allow_pickle=True)
    return kind, _npz(arrays)


def _json_site(rng: random.Random, d):
    name = rng.choice(["scene.json", "intrinsics.json"])
    doc = json.loads((d / name).read_text())
    kind, text = next(mutations(doc, rng))
    return name, kind, text.encode("utf-8", "surrogateescape")


def _pose_text(rng: random.Random) -> tuple[str, str]:
    kind = rng.choice(["far", "nan", "short", "words", "rotation"])
    pose = np.eye(4)
    pose[:3, 3] = [0.1, 0.0, 1.2]
    if kind == "far":
        pose[0, 3] = rng.choice([1e12, -1e7, 1e300])
    elif kind == "nan":
        pose[rng.randrange(3), rng.randrange(4)] = np.nan
    elif kind == "rotation":
        pose[0, 0] = 1e9
    text = "\n".join(" ".join(f"{v:.9g}" for v in row) for row in pose)
    if kind == "short":
        text = "\n".join(text.splitlines()[:rng.randint(0, 3)])
    elif kind == "words":
        text = text.replace("0", "zero", 1)
    return kind, text


def _fuzz_frames(base, tmp_path, capsys, n, seed):
    rng = random.Random(seed)
    emb, _ = text_vectors(["chair", "table"], HASH_SPACE)
    out = tmp_path / "out.iesm"
    for i in range(n):
        d = tmp_path / f"f{i % 2}"
        if d.exists():
            shutil.rmtree(d)
        shutil.copytree(base, d)
        site = rng.choice(["json", "pose", "seg", "seg", "n_frames"])
        if site == "json":
            name, kind, raw = _json_site(rng, d)
            (d / name).write_bytes(raw)
        elif site == "pose":
            kind, text = _pose_text(rng)
            (d / "frames" / "000001.pose.txt").write_text(text)
        elif site == "seg":
            kind, raw = _seg_mutation(rng, emb)
            (d / "frames" / "000000.seg.npz").write_bytes(raw)
        else:
            meta = json.loads((d / "scene.json").read_text())
            meta["n_frames"] = rng.choice([0, -1, 3, True, 2**70, 1.5])
            kind = "n_frames"
            (d / "scene.json").write_text(json.dumps(meta))
        code = check_cli(["build-map", str(d), "-o", str(out)], capsys, outputs=(out,))
        Tally.add("frames", f"{site}/{kind}:{'refused' if code == 2 else 'accepted'}")


def _label_mutation(rng: random.Random, shape: tuple[int, int]) -> tuple[str, bytes]:
    labels = np.zeros(shape, np.int32)
    names = np.array(["kitchen", "hall"])
    kind = rng.choice(["float", "string", "shape", "index", "truncate", "empty", "missing", "object", "huge"])
    if kind == "float":
        return kind, _npz({"labels": np.full(shape, np.nan), "names": names})
    if kind == "string":
        return kind, _npz({"labels": labels.astype(str), "names": names})
    if kind == "shape":
        return kind, _npz({"labels": np.zeros((shape[0] + 1, shape[1]), np.int32), "names": names})
    if kind == "index":
        labels[0, 0] = rng.choice([5, -7, 2**31 - 1])
        return kind, _npz({"labels": labels, "names": names})
    if kind == "truncate":
        raw = _npz({"labels": labels, "names": names})
        return kind, raw[:rng.randrange(len(raw))]
    if kind == "empty":
        return kind, b""
    if kind == "missing":
        return kind, _npz({"labels": labels})
    if kind == "object":
        return kind, _npz({"labels": labels, "names": np.array([{"a": 1}], dtype=object)}, allow_pickle=True)
    b = io.BytesIO()
    np.save(b, np.zeros((1, 1), np.int32))
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as zf:
        zf.writestr("labels.npy", b.getvalue().replace(b"(1, 1)", b"(32768, 32768)"))
        nb = io.BytesIO()
        np.save(nb, names)
        zf.writestr("names.npy", nb.getvalue())
    return kind, buf.getvalue()


@pytest.fixture(scope="module")
def small_map(tmp_path_factory):
    from iesm_agent.cli import run

    d = tmp_path_factory.mktemp("map")
    src = d / "objs.json"
    src.write_text(json.dumps({"scene_id": "cl", "objects": [
        {"id": 1, "label": "chair", "center": [0.5, 0.5, 0.4], "size": [0.4, 0.4, 0.8]},
        {"id": 2, "label": "table", "center": [1.5, 1.0, 0.4], "size": [0.8, 0.6, 0.8]}]}))
    assert run(["import", str(src), "-o", str(d / "m.iesm")]) == 0
    from iesm_agent.store import load_map

    scene = load_map(d / "m.iesm")
    return d / "m.iesm", (scene.grid.height, scene.grid.width)


def _fuzz_cell_labels(small_map, tmp_path, capsys, n, seed):
    rng = random.Random(seed)
    path, shape = small_map
    bad, out = tmp_path / "labels.npz", tmp_path / "rooms.iesm"
    for _ in range(n):
        kind, raw = _label_mutation(rng, shape)
        bad.write_bytes(raw)
        code = check_cli(["rooms", str(path), "--cell-labels", str(bad), "-o", str(out)], capsys, outputs=(out,),
                         may_pass=False)
        Tally.add("cell labels", f"{kind}:{'refused' if code == 2 else 'accepted'}")


def test_the_base_frames_build(base_frames, tmp_path, capsys):
    check_cli(["build-map", str(base_frames), "-o", str(tmp_path / "ok.iesm")], capsys, may_pass=True)


def test_fuzz_frames(base_frames, tmp_path, capsys):
    _fuzz_frames(base_frames, tmp_path, capsys, FAST, seed=5)


def test_fuzz_cell_labels(small_map, tmp_path, capsys):
    _fuzz_cell_labels(small_map, tmp_path, capsys, FAST, seed=6)


@pytest.mark.slow
def test_fuzz_frames_and_cell_labels_seeded_long_run(base_frames, small_map, tmp_path, capsys):
    _fuzz_frames(base_frames, tmp_path, capsys, SLOW, seed=105)
    _fuzz_cell_labels(small_map, tmp_path, capsys, SLOW, seed=106)
