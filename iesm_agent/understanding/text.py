"""Attribute slots and word stems: how described attributes are read, the same way in queries
and in instance labels, captions and tags."""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..lexicon import ATTRIBUTE_KINDS, Lexicon, Span

_CLAUSE_MARK = re.compile(r"[.,;:!?()]")
SENTENCE_MARK = re.compile(r"[.!?:;]")
#: (length a word must exceed, suffix) that `stem` cuts, the first that fits
_SUFFIXES = ((5, "ing"), (4, "ed"), (4, "es"), (3, "s"))


@dataclass(frozen=True)
class Slot:
    """One described attribute as written: `surface` keeps the words ("pale blue gray",
    "leather like", "mesh"), `base` drops shade words ("blue gray"), `values` are the canonical
    families ({"blue", "gray"}; empty for a colour the lexicon does not know, e.g. "ash colored")."""

    kind: str
    surface: str
    base: str
    values: frozenset[str]


def lemmatise(lex: Lexicon, tokens: list[str]) -> list[str]:
    """Lemmas of a query's tokens; a present participle after a noun and before a preposition keeps
    its form ("the lamp standing on the desk": a verb, so never the category "lamp stand"); a
    gerund after a preposition is read as its verb ("for resting on" -> rest)."""
    bounds = lex.words["boundaries"]
    return [token if token.endswith("ing") and 0 < i < len(tokens) - 1 and tokens[i + 1] in bounds
            and tokens[i - 1] not in bounds else lex.lemma(token) for i, token in enumerate(tokens)]


def word_stems(lex: Lexicon, lemmas: list[str]) -> set[str]:
    """Stems of words and of the parts of hyphenated words; imitation words read as "like"."""
    imitation = lex.words["imitation_suffixes"]
    return {stem("like" if part in imitation else part) for w in lemmas for part in (w, *w.split("-"))
            if part in imitation or len(part) > 2}


def stem(word: str) -> str:
    """Crude suffix stripping for word overlap: striped/stripes/stripe -> strip, frosted -> frost."""
    w = next((word[:-len(end)] for longer, end in _SUFFIXES
              if len(word) > longer and word.endswith(end) and not word.endswith("ss")), word)
    for longer, last in ((4, "y"), (3, "e"), (3, "")):  # a last "y", an "e", a doubled letter ("")
        if len(w) > longer and w[-1] == (last or w[-2]):
            w = w[:-1]
    return w


def modifier_spans(lex: Lexicon, lemmas: list[str], span: Span) -> list[Span]:
    """Attribute words inside a multi-word category phrase, as one-word spans: a modifier there
    is also a description ("mesh chair": mesh; "small table": small)."""
    return [Span(k, k + 1, kinds) for k in (range(span.start, span.end) if span.end - span.start > 1 else ())
            if (kinds := tuple(kv for kv in lex.phrases.get((lemmas[k],), ()) if kv[0] in ATTRIBUTE_KINDS))]


def read_slots(lex: Lexicon, lemmas: list[str], attr_spans: list[Span]) -> tuple[list[Slot], set[int]]:
    """Attribute slots from attribute spans over one run of adjacent words: adjacent colour spans
    form one compound colour ("golden brown", "blue gray"); an unknown word before a colour suffix
    is a colour ("ash-colored"); a suffix after a span joins it ("leather look")."""
    slots: list[Slot] = []
    used: set[int] = set()
    suffixes = lex.words["color_suffixes"] | lex.words["imitation_suffixes"]
    groups: list[list[Span]] = []
    for s in attr_spans:
        if groups and s.start == groups[-1][-1].end and s.has("color") and groups[-1][-1].has("color"):
            groups[-1].append(s)
        else:
            groups.append([s])
    span_idx = {i for s in attr_spans for i in range(s.start, s.end)}
    for group in groups:
        start = group[0].start
        end = next((k for k in range(group[-1].end, len(lemmas)) if lemmas[k] not in suffixes), len(lemmas))
        used.update(range(start, end))
        for kind in sorted({k for s in group for k, _ in s.kinds if k in ATTRIBUTE_KINDS}):
            values = frozenset(v for s in group for k, v in s.kinds if k == kind)
            words = lemmas[start:end] if kind == "color" or len(group) == 1 else lemmas[group[0].start:group[0].end]
            # hyphens and colour suffixes dropped, imitation words ("look", "faux", "like") folded into a last "like"
            parts = [p for w in words for p in w.split("-") if p]
            core = [p for p in parts if p not in suffixes]
            tail = ["like"] if any(p in lex.words["imitation_suffixes"] for p in parts) else []
            base = [p for p in core if p not in lex.shades] or core  # shades dropped
            slots.append(Slot(kind, " ".join(core + tail), " ".join(base + tail), values))
    for i in range(len(lemmas) - 1):
        if (lemmas[i + 1] in lex.words["color_suffixes"] and i not in span_idx and i not in used
                and lemmas[i].isalpha() and len(lemmas[i]) > 2 and lemmas[i] not in lex.shades):
            slots.append(Slot("color", lemmas[i], lemmas[i], frozenset()))
            used.update((i, i + 1))
    return slots, used


def clause_breaks(text: str, tokens: list[tuple[str, int]], marks: re.Pattern = _CLAUSE_MARK) -> frozenset[int]:
    """Indices of the `tokens` ((token, character offset in `text`) pairs) that punctuation separates
    from the token before them: where a lexicon phrase may not continue ("the piano. The stool").
    With `marks` `SENTENCE_MARK`: the tokens that open a new sentence."""
    return frozenset(k for k in range(1, len(tokens))
                     if marks.search(text, tokens[k - 1][1] + len(tokens[k - 1][0]), tokens[k][1]))
