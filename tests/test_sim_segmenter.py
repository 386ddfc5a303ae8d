"""The synthetic segmenter: each fault happens at its configured rate, masks stay faithful to the
instance ids otherwise, embeddings live in the text space, and everything is seeded."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.embeddings import HASH_SPACE, text_vectors
from iesm_agent.errors import IesmError
from iesm_agent.frames import Frame
from iesm_agent.sim.segmenter import FaultConfig, SyntheticSegmenter

LABELS = ["chair", "table", "stool", "sofa", "lamp"]


def _blocks(gap: int) -> tuple[np.ndarray, dict[int, str]]:
    """A 240 x 320 image of 12 x 16 square instances of 20 - gap pixels (ids 1..192)."""
    ids = np.zeros((240, 320), np.int32)
    labels = {}
    for k in range(12 * 16):
        r, c = divmod(k, 16)
        ids[r * 20:(r + 1) * 20 - gap, c * 20:(c + 1) * 20 - gap] = k + 1
        labels[k + 1] = LABELS[k % len(LABELS)]
    return ids, labels


def _frames(ids: np.ndarray, n: int):
    return [Frame(i, np.zeros(ids.shape + (3,), np.uint8), np.ones(ids.shape, np.float32), np.eye(4),
                  instance_ids=ids) for i in range(n)]


def _clean(**faults) -> FaultConfig:
    base = dict(miss_rate=0, split_rate=0, merge_rate=0, erode_rate=0, embedding_noise=0, confusion_rate=0)
    return FaultConfig(**{**base, **faults})


def test_no_faults_gives_exact_masks_and_label_vectors():
    ids, labels = _blocks(gap=2)
    seg = SyntheticSegmenter(labels, _clean(), space=HASH_SPACE)
    out = seg.segment(_frames(ids, 1)[0])
    assert out.masks.shape == (192, 240, 320) and out.embeddings.shape == (192, 384)
    assert np.array_equal(out.masks.sum(0), ids > 0) and out.masks.sum(0).max() == 1
    vecs, _ = text_vectors(LABELS, HASH_SPACE)
    owner = [int(np.unique(ids[m])[0]) for m in out.masks]
    expected = np.array([vecs[LABELS.index(labels[i])] for i in owner])
    assert np.allclose(out.embeddings, expected, atol=1e-6)
    assert np.all((out.scores > 0) & (out.scores <= 1))


@pytest.mark.parametrize("rate", [0.1, 0.3])
def test_miss_rate(rate):
    ids, labels = _blocks(gap=2)
    seg = SyntheticSegmenter(labels, _clean(miss_rate=rate), space=HASH_SPACE)
    kept = sum(len(seg.segment(f).masks) for f in _frames(ids, 5))
    assert 1 - kept / (5 * 192) == pytest.approx(rate, abs=0.05)


def test_split_rate_cuts_masks_into_two_disjoint_halves():
    ids, labels = _blocks(gap=2)
    seg = SyntheticSegmenter(labels, _clean(split_rate=0.4, min_area_px=40), space=HASH_SPACE)
    out, log = seg.segment_with_log(_frames(ids, 1)[0])
    assert log.split / 192 == pytest.approx(0.4, abs=0.08)
    assert len(out.masks) == 192 + log.split
    assert np.array_equal(out.masks.sum(0), ids > 0) and out.masks.sum(0).max() == 1  # halves tile the originals
    owners = [np.unique(ids[m]) for m in out.masks]
    assert all(len(o) == 1 for o in owners)


def test_merge_rate_unites_touching_instances():
    ids, labels = _blocks(gap=0)  # every block touches its neighbours
    seg = SyntheticSegmenter(labels, _clean(merge_rate=0.2), space=HASH_SPACE)
    out, log = seg.segment_with_log(_frames(ids, 1)[0])
    assert log.merged > 20 and len(out.masks) == 192 - log.merged
    assert np.array_equal(out.masks.sum(0), ids > 0)
    multi = [np.unique(ids[m]) for m in out.masks if len(np.unique(ids[m])) > 1]
    assert len(multi) >= 1


def test_erosion_shrinks_masks_inside_their_instance():
    ids, labels = _blocks(gap=2)
    seg = SyntheticSegmenter(labels, _clean(erode_rate=0.5, erode_px=2), space=HASH_SPACE)
    out, log = seg.segment_with_log(_frames(ids, 1)[0])
    areas = out.masks.sum((1, 2))
    # eroded by 2 px on every side, except along the image border (cv2.erode's default border)
    assert np.sum(areas < 18 * 18) == log.eroded and log.eroded / 192 == pytest.approx(0.5, abs=0.1)
    inner = out.masks[:, 20:-20, 20:-20].sum((1, 2)) == areas
    assert np.all((areas[inner] == 18 * 18) | (areas[inner] == 14 * 14))
    assert not np.any(out.masks & (ids == 0)[None])


def test_embedding_noise_and_confusion():
    ids, labels = _blocks(gap=2)
    vecs = dict(zip(LABELS, text_vectors(LABELS, HASH_SPACE)[0]))
    noisy = SyntheticSegmenter(labels, _clean(embedding_noise=0.5), space=HASH_SPACE).segment(_frames(ids, 1)[0])
    owner = [labels[int(np.unique(ids[m])[0])] for m in noisy.masks]
    cos = np.array([e @ vecs[o] for e, o in zip(noisy.embeddings, owner)])
    assert cos.mean() == pytest.approx(1 / np.sqrt(1 + 0.5 ** 2), abs=0.03)
    assert np.allclose(np.linalg.norm(noisy.embeddings, axis=1), 1, atol=1e-5)
    confused = SyntheticSegmenter(labels, _clean(confusion_rate=1.0, confusion_strength=0.6), space=HASH_SPACE)
    out = confused.segment(_frames(ids, 1)[0])
    stools = [e for e, m in zip(out.embeddings, out.masks) if labels[int(np.unique(ids[m])[0])] == "stool"]
    assert stools and all(e @ vecs["chair"] > e @ vecs["stool"] for e in stools)


def test_seeded_and_needs_instance_ids():
    ids, labels = _blocks(gap=0)
    cfg = FaultConfig(seed=3)
    a = SyntheticSegmenter(labels, cfg, space=HASH_SPACE).segment(_frames(ids, 2)[1])
    b = SyntheticSegmenter(labels, cfg, space=HASH_SPACE).segment(_frames(ids, 2)[1])
    assert np.array_equal(a.masks, b.masks) and np.array_equal(a.embeddings, b.embeddings)
    c = SyntheticSegmenter(labels, FaultConfig(seed=4), space=HASH_SPACE).segment(_frames(ids, 2)[1])
    assert not (a.masks.shape == c.masks.shape and np.array_equal(a.masks, c.masks))
    with pytest.raises(IesmError, match="instance ids"):
        a_frame = Frame(0, np.zeros((4, 4, 3), np.uint8), np.zeros((4, 4), np.float32), np.eye(4))
        SyntheticSegmenter(labels, cfg, space=HASH_SPACE).segment(a_frame)
    with pytest.raises(ValueError):
        FaultConfig(miss_rate=1.5)
