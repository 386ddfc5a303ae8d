"""The English parser's products on numpy's BLAS held to one thread (`iesm_agent.blas`): every layer
of the loaded pipeline multiplies with numpy, and it reads requests as spaCy's shipped pipeline
(blis) does (all suite texts: `scripts/check_parse_batching.py --blis`)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from iesm_agent import blas
from iesm_agent.understanding import parse

REPO = Path(__file__).resolve().parents[1]


def _tokens(doc) -> list[tuple]:
    return [(t.text, t.idx, t.head.i, t.dep_, t.pos_, t.tag_, t.lemma_, t.is_sent_start) for t in doc]


def test_the_reading_pipeline_multiplies_with_numpy_in_one_thread():
    nlp = parse._pipeline()
    if not blas.one_blas_thread():
        pytest.skip("numpy's BLAS here is no OpenBLAS with a thread setter: thinc keeps blis")
    layers = [layer for _, c in nlp.pipeline if getattr(c, "model", None) is not None for layer in c.model.walk()]
    assert layers and all(layer.ops.name == "numpy" and layer.ops.use_blis is False for layer in layers)
    threadpoolctl = pytest.importorskip("threadpoolctl")
    numpy_blas = [i for i in threadpoolctl.threadpool_info() if "numpy.libs" in i["filepath"]]
    assert numpy_blas and all(i["num_threads"] == 1 for i in numpy_blas)


def test_it_parses_as_the_shipped_pipeline():
    import spacy

    lines = [
        json.loads(line)["query"]
        for name in ("spatial_suite.jsonl", "apartment_human_suite.jsonl")
        for line in (REPO / "evals" / name).read_text().splitlines()
        if line.strip()
    ]
    texts = [parse.normalise(t) for t in dict.fromkeys(lines)][:60]
    shipped = spacy.load(parse.PIPELINE, exclude=["ner"])
    nlp = parse._pipeline()
    assert [_tokens(d) for d in nlp.pipe(texts)] == [_tokens(shipped(t)) for t in texts]
    assert [_tokens(nlp(t)) for t in texts[:10]] == [_tokens(d) for d in shipped.pipe(texts[:10])]
