"""`.iesm` round trip, compact on-disk dtypes, versioning and validation errors."""

from __future__ import annotations

import json
import zipfile

import numpy as np
import pytest

from iesm_agent.errors import MapFormatError
from iesm_agent.store import GridSpec, Instance, InstanceGrid, Room, SceneMap, load_map, save_map
from iesm_agent.store.model import SCHEMA_VERSION


def make_scene(rng: np.random.Generator, n: int = 12, h: int = 40, w: int = 50, dim: int = 16) -> SceneMap:
    ids = np.arange(100, 100 + n)
    cells = rng.integers(0, h * w, 400)
    entry_ids = rng.choice(ids, 400)
    top = rng.uniform(0, 2, 400).astype(np.float32)
    top[::7] = np.nan
    occ = InstanceGrid.from_entries(cells, entry_ids, top)
    rooms = [Room(id=1, label="küche", polygon=[(0, 0), (1, 0), (1, 1)]), Room(id=2, label="bedroom")]
    instances = [Instance(id=int(i), label=f"chair {k}", room_id=1 if k % 2 else None,
                          room_label="küche" if k % 2 else None,
                          caption=f"a 红色 chair ✓ #{k} with \"quotes\"", tags={"color": "red", "材料": "wood"},
                          alt_labels=["seat"], mean_height=0.1 * k, frames=[k, k + 1],
                          centroid=(0.1 * k, 0.2, 0.3), footprint_cells=k) for k, i in enumerate(ids)]
    room_map = rng.integers(-1, 3, (h, w)).astype(np.int32)
    return SceneMap(scene_id="t1", source="test", grid=GridSpec(cell_size=0.05, origin=(-1.0, 2.5), height=h, width=w),
                    instances=instances, rooms=rooms, occupancy=occ, room_map=room_map,
                    obstacles=rng.random((h, w)) > 0.5, embeddings=rng.normal(size=(n, dim)).astype(np.float32),
                    embedding_model="fake-model", meta={"k": "v"})


def test_round_trip_is_lossless(tmp_path):
    scene = make_scene(np.random.default_rng(0))
    assert scene.occupancy.multi_occupancy_cells > 0
    assert np.isnan(scene.occupancy.top).any()
    path = tmp_path / "m.iesm"
    size = save_map(scene, path)
    assert size == path.stat().st_size
    loaded = load_map(path)
    assert loaded == scene
    for name in ("cells", "indptr", "ids", "top"):
        a, b = getattr(scene.occupancy, name), getattr(loaded.occupancy, name)
        assert a.dtype == b.dtype and np.array_equal(a, b, equal_nan=True)
    for name in ("room_map", "obstacles", "embeddings"):
        assert getattr(loaded, name).dtype == getattr(scene, name).dtype
        assert np.array_equal(getattr(loaded, name), getattr(scene, name))
    assert loaded.instances[3].caption == scene.instances[3].caption
    assert list(tmp_path.iterdir()) == [path]  # no temp file left behind


def test_equality_detects_a_changed_value(tmp_path):
    scene = make_scene(np.random.default_rng(1))
    save_map(scene, tmp_path / "m.iesm")
    loaded = load_map(tmp_path / "m.iesm")
    loaded.room_map[0, 0] = 7
    assert loaded != scene


def test_disk_dtypes_are_compact(tmp_path):
    scene = make_scene(np.random.default_rng(2))
    save_map(scene, tmp_path / "m.iesm")
    with zipfile.ZipFile(tmp_path / "m.iesm") as zf:
        arrays = {a["name"]: a for a in json.loads(zf.read("manifest.json"))["arrays"]}
        assert zf.getinfo("room_map.npy").compress_type == zipfile.ZIP_DEFLATED
    assert arrays["occupancy.cells"]["encoding"] == "delta"
    assert np.dtype(arrays["occupancy.cells"]["disk_dtype"]).itemsize <= 2
    assert np.dtype(arrays["occupancy.indptr"]["disk_dtype"]).itemsize == 1
    assert np.dtype(arrays["occupancy.ids"]["disk_dtype"]).itemsize == 1
    assert np.dtype(arrays["room_map"]["disk_dtype"]) == np.int8
    assert arrays["room_map"]["dtype"] == np.dtype(np.int32).str


def test_float16_embeddings_on_request(tmp_path):
    scene = make_scene(np.random.default_rng(3), dim=64)
    full = save_map(scene, tmp_path / "a.iesm")
    half = save_map(scene, tmp_path / "b.iesm", embeddings_dtype="float16")
    assert half < full
    loaded = load_map(tmp_path / "b.iesm")
    assert loaded.embeddings.dtype == np.float32
    assert np.allclose(loaded.embeddings, scene.embeddings, atol=2e-3)


def test_empty_map_round_trip(tmp_path):
    scene = SceneMap(scene_id="empty", grid=GridSpec(cell_size=0.1, height=0, width=0), instances=[])
    save_map(scene, tmp_path / "e.iesm")
    assert load_map(tmp_path / "e.iesm") == scene


def _rewrite(src, dst, *, manifest=None, drop=None, replace=None):
    with zipfile.ZipFile(src) as zin, zipfile.ZipFile(dst, "w") as zout:
        for item in zin.infolist():
            if item.filename == drop:
                continue
            data = zin.read(item.filename)
            if item.filename == "manifest.json" and manifest is not None:
                data = manifest(json.loads(data)) if callable(manifest) else manifest
                data = data if isinstance(data, bytes) else json.dumps(data).encode()
            if replace and item.filename in replace:
                data = replace[item.filename]
            zout.writestr(item, data)


@pytest.fixture
def saved(tmp_path):
    path = tmp_path / "ok.iesm"
    save_map(make_scene(np.random.default_rng(4)), path)
    return path


def _expect(path, *fragments):
    with pytest.raises(MapFormatError) as info:
        load_map(path)
    text = str(info.value)
    assert str(path) in text
    for fragment in fragments:
        assert fragment in text, text


def test_newer_schema_rejected(saved, tmp_path):
    bad = tmp_path / "new.iesm"
    _rewrite(saved, bad, manifest=lambda m: {**m, "schema_version": SCHEMA_VERSION + 1})
    _expect(bad, "schema_version", "newer")


def test_truncated_file(saved, tmp_path):
    bad = tmp_path / "trunc.iesm"
    bad.write_bytes(saved.read_bytes()[: saved.stat().st_size // 2])
    _expect(bad, "truncated or corrupted")


def test_corrupted_member(saved, tmp_path):
    data = bytearray(saved.read_bytes())
    with zipfile.ZipFile(saved) as zf:
        info = zf.getinfo("embeddings.npy")
    start = info.header_offset + 30 + len(info.filename) + 20
    data[start:start + 40] = bytes(40)
    bad = tmp_path / "corrupt.iesm"
    bad.write_bytes(bytes(data))
    _expect(bad)


def test_missing_member(saved, tmp_path):
    bad = tmp_path / "missing.iesm"
    _rewrite(saved, bad, drop="room_map.npy")
    _expect(bad, "room_map.npy", "missing")


def test_bad_manifest_json(saved, tmp_path):
    bad = tmp_path / "json.iesm"
    _rewrite(saved, bad, manifest=b"{not json")
    _expect(bad, "manifest.json", "invalid JSON")


def test_validation_error_names_the_field(saved, tmp_path):
    def drop_label(m):
        del m["instances"][2]["label"]
        return m

    bad = tmp_path / "field.iesm"
    _rewrite(saved, bad, manifest=drop_label)
    _expect(bad, "instances.2.label")


def test_shape_mismatch_names_the_member(saved, tmp_path):
    bad = tmp_path / "shape.iesm"
    import io

    buf = io.BytesIO()
    np.save(buf, np.zeros((3, 3), np.int8))
    _rewrite(saved, bad, replace={"room_map.npy": buf.getvalue()})
    _expect(bad, "room_map.npy")


def test_pickled_member_is_refused(saved, tmp_path):
    import io

    buf = io.BytesIO()
    np.save(buf, np.array([{"a": 1}], dtype=object), allow_pickle=True)
    bad = tmp_path / "pickle.iesm"
    _rewrite(saved, bad, replace={"embeddings.npy": buf.getvalue()})
    _expect(bad, "embeddings.npy", "allow_pickle=False")


@pytest.mark.parametrize("key, value", [("dtype", "|O"), ("dtype", "<U3"), ("disk_dtype", "zzz"), ("dtype", "<c8")])
def test_unsupported_array_dtype_names_the_field(saved, tmp_path, key, value):
    def patch(m):
        m["arrays"][0][key] = value
        return m

    bad = tmp_path / "dtype.iesm"
    _rewrite(saved, bad, manifest=patch)
    _expect(bad, f"arrays[0].{key}", "unsupported array dtype")


def test_out_of_range_delta_base_is_refused(saved, tmp_path):
    def patch(m):
        next(e for e in m["arrays"] if e["name"] == "occupancy.cells")["base"] = 2 ** 70
        return m

    bad = tmp_path / "base.iesm"
    _rewrite(saved, bad, manifest=patch)
    _expect(bad, "occupancy.cells.npy", "unreadable array")


def test_not_a_file(tmp_path):
    _expect(tmp_path / "nope.iesm", "no such map file")


def test_random_corruption_is_always_a_clear_error(tmp_path, apartment_path):
    """Flipped bytes anywhere (headers, offsets, compressed data) and truncation: a map loads or
    raises MapFormatError, never another exception."""
    import random

    from iesm_agent.errors import MapFormatError

    data = apartment_path.read_bytes()
    rng = random.Random(7)
    outcomes = {"loaded": 0, "refused": 0}
    for i in range(600):
        corrupted = bytearray(data)
        for _ in range(rng.randint(1, 12)):
            corrupted[rng.randrange(len(corrupted))] = rng.randrange(256)
        if i % 5 == 0:
            corrupted = corrupted[:rng.randrange(len(corrupted))]
        path = tmp_path / "c.iesm"
        path.write_bytes(bytes(corrupted))
        try:
            load_map(path)
            outcomes["loaded"] += 1
        except MapFormatError as exc:
            assert str(path) in str(exc)
            outcomes["refused"] += 1
    assert outcomes["refused"] > 500
