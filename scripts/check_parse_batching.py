"""Check that the English parser reads every suite text the same in `nlp.pipe` batches (as
`iesm serve` parses the queries waiting together) as one sentence at a time: every token's text,
offset, head, dependency, part of speech, tag, lemma and sentence start, for batches of the given
sizes in random compositions. Prints the texts that differ; exit 1 if any does. `--blis`: also
one at a time with thinc's products on blis, as spaCy ships it, against the reading's pipeline
(numpy's BLAS where `blas.one_blas_thread` holds it to one thread).

Run from the repository root: .venv/bin/python scripts/check_parse_batching.py [--blis] [SIZE ...]
(default sizes 2 7 40 64; the referring corpus in ../shared/data/referring_dev when present).
"""

from __future__ import annotations

import json
import random
import sys
from pathlib import Path

from iesm_agent.lexicon import load_lexicon
from iesm_agent.understanding import parse

REPO = Path(__file__).resolve().parents[1]
REFERRING = REPO.parent / "shared" / "data" / "referring_dev"


def suite_queries() -> list[str]:
    """Every query of the shipped suites, the blind rounds and the referring corpus as written, each once, in order."""
    paths = [*sorted((REPO / "evals").glob("*.jsonl")), *sorted((REPO / "evals" / "blind").glob("round*.jsonl")),
             *(REFERRING / f"{stem}.jsonl" for stem in ("scanrefer_dev", "nr3d_dev"))]
    texts = [json.loads(line).get("query") for path in paths if path.is_file()
             for line in path.read_text().splitlines() if line.strip()]
    return list(dict.fromkeys(t for t in texts if t))


def suite_texts() -> list[str]:
    """`suite_queries`, spelt and normalised as the reading parses them, each once."""
    lex = load_lexicon()
    return list(dict.fromkeys(parse.normalise(lex.respell(t)) for t in suite_queries()))


def tokens(doc) -> list[tuple]:
    return [(t.text, t.idx, t.head.i, t.dep_, t.pos_, t.tag_, t.lemma_, t.is_sent_start) for t in doc]


def main() -> None:
    sizes = [int(a) for a in sys.argv[1:] if a != "--blis"] or [2, 7, 40, 64]
    texts = suite_texts()
    nlp = parse._pipeline()
    alone = [tokens(nlp(t)) for t in texts]
    differ = 0
    if "--blis" in sys.argv:
        import spacy

        shipped = spacy.load(parse.PIPELINE, exclude=["ner"])
        changed = [t for t, read in zip(texts, alone) if tokens(shipped(t)) != read]
        print(f"on blis: {len(changed)} of {len(texts)} texts parsed differently", *changed[:5], sep="\n  ")
        differ += len(changed)
    for size in sizes:
        order = list(range(len(texts)))
        random.Random(size).shuffle(order)
        changed = []
        for i in range(0, len(order), size):
            chunk = order[i:i + size]
            for k, doc in zip(chunk, nlp.pipe([texts[k] for k in chunk], batch_size=size)):
                if tokens(doc) != alone[k]:
                    changed.append(texts[k])
        print(f"batches of {size}: {len(changed)} of {len(texts)} texts parsed differently", *changed[:5], sep="\n  ")
        differ += len(changed)
    sys.exit(1 if differ else 0)


if __name__ == "__main__":
    main()
