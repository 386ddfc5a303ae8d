"""What raw map labels, room labels and candidate records denote: 'cabinet kitchen' ->
cabinet, 'Living Room 2' -> living room, a fenced candidate line -> its lexical profile."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import lru_cache

from ..lexicon import ATTRIBUTE_KINDS, Lexicon, load_lexicon
from .text import Slot, modifier_spans, read_slots, word_stems

_SECONDARY_WEIGHT = 0.6
#: weight of a category only an alternative label names (the first; each later one 0.05 less)
_ALT_WEIGHT = 0.6


@dataclass(frozen=True)
class Record:
    """A candidate's lexical profile, built from whatever fields it has."""

    concepts: tuple[tuple[str, float], ...]  # (category, weight), best first
    label: str                   # the raw label as given
    room: str | None
    attrs: frozenset[tuple[str, str]]
    words: frozenset[str]        # lemmas of label, caption and tags
    label_words: frozenset[str]  # lemmas of the label
    text: str                    # label and caption, for sentence embeddings
    slots: tuple[Slot, ...] = ()  # attributes as written in label, caption and tags
    stems: frozenset[str] = frozenset()  # word stems of label, caption and tags
    room_words: frozenset[str] = frozenset()  # lemmas of the room's own name ("master bedroom 2")


@lru_cache(maxsize=65536)
def label_concepts(label: str) -> tuple[tuple[str, float], ...]:
    """Categories a raw map label denotes, with weights: 'cabinet kitchen' -> cabinet,
    'stand/small table' -> stand and side table, 'set of towels' -> towel, 'mirror frame' -> mirror 1.0 + frame."""
    lex = load_lexicon()
    out = {v: 1.0 for k, v in lex.phrase(label) if k == "cat"}  # the whole label as one phrase
    for part in label.split("/"):
        for concept, w in _part_concepts(lex, part).items():
            out[concept] = max(out.get(concept, 0.0), w)
    return tuple(sorted(out.items(), key=lambda kv: (-kv[1], kv[0])))


def _part_concepts(lex: Lexicon, part: str) -> dict[str, float]:
    words = [lex.lemma(t) for t in lex.tokens(part) if t not in lex.words["skip"]]
    words = [w for w in words if w not in lex.words["ignore"]]
    # "set of towels" -> towels; "box of paper" -> box (+ paper); "bowl with sweets" -> bowl
    for joiner in ("of", "with", "for"):
        if joiner in words[1:-1]:
            i = words.index(joiner, 1)  # "of cups of tea": the joiner between two words
            left, right = words[:i], words[i + 1:]
            if joiner == "of" and left[-1] in lex.words["collective_strict"] | lex.words["weak_heads"]:
                return _phrase_concepts(lex, right)
            main = _phrase_concepts(lex, left)
            return main | {c: w * _SECONDARY_WEIGHT for c, w in _phrase_concepts(lex, right).items() if c not in main}
    return _phrase_concepts(lex, words)


def _phrase_concepts(lex: Lexicon, words: list[str]) -> dict[str, float]:
    whole = [v for k, v in lex.phrases.get(tuple(words), ()) if k == "cat"]
    if whole:
        return {c: 1.0 for c in whole}
    # drop room modifiers ("cabinet kitchen", "bath sink") when something else remains
    core = [w for w in words if w not in lex.words["room_modifiers"]] or words
    spans = [s for s in lex.scan(core) if s.has("cat")]
    if not spans:
        return {}
    head = spans[-1]
    if len(spans) > 1 and core[head.start] in lex.words["weak_heads"] and head.end - head.start == 1:
        head = spans[-2]  # "mirror frame" -> mirror
    return {c: 1.0 if c in head.values("cat") else _SECONDARY_WEIGHT for s in spans for c in s.values("cat")}


@lru_cache(maxsize=65536)
def text_slots(text: str) -> tuple[tuple[Slot, ...], frozenset[str]]:
    """Attribute slots and word stems of a caption, tag value or label. Punctuation separates
    ("white, red" is two colours); words next to each other may form a compound ("blue-gray")."""
    lex = load_lexicon()
    slots: list[Slot] = []
    stems: set[str] = set()
    for chunk in re.split(r"[,;:.()/|!?]+", text):
        lemmas = [lex.lemma(t) for t in lex.tokens(chunk)]
        stems.update(word_stems(lex, lemmas))
        spans = [found for sp in lex.scan(lemmas, fits=_not_measured(lemmas)) for found in (
            [sp] if any(k in ATTRIBUTE_KINDS for k, _ in sp.kinds) else modifier_spans(lex, lemmas, sp))]
        slots.extend(read_slots(lex, lemmas, spans)[0])
    return tuple(dict.fromkeys(slots)), frozenset(stems)


#: length units a caption states a dimension in ("about 1.3 m tall", "25 cm wide")
_UNITS = frozenset({"m", "cm", "mm", "metre", "meter", "centimetre", "centimeter", "ft", "foot", "inch"})


def _not_measured(lemmas: list[str]):
    """A `Lexicon.scan` filter: a size word after a number and a unit gives a dimension, not a
    size ("1.3 m tall" says how tall, not that it is tall)."""
    def fits(start: int, end: int, kinds: tuple[tuple[str, str], ...]) -> bool:
        return not (start >= 2 and lemmas[start - 1] in _UNITS and lemmas[start - 2].isdigit()
                    and all(k == "size" for k, _ in kinds))
    return fits


@lru_cache(maxsize=4096)
def room_of(text: str) -> str | None:
    """Canonical room type of a room label such as 'Living Room 2' or 'office1'."""
    lex = load_lexicon()
    lemmas = [lex.lemma(t.rstrip("0123456789")) for t in lex.tokens(text)]
    return next((s.values("room")[0] for s in lex.scan([t for t in lemmas if t]) if s.values("room")),
                text.strip().lower() or None)


@lru_cache(maxsize=65536)
def candidate_from_line(line: str) -> tuple[int, Record] | None:
    """(id, profile) of one fenced candidate line (JSON object with id, label, alt_labels,
    room, caption, tags; all but id optional); None if the line is unusable."""
    try:
        data = json.loads(line)
    except ValueError:
        return None
    ident = data.get("id") if isinstance(data, dict) else None
    if isinstance(ident, str) and ident.strip().lstrip("-").isdigit():
        ident = int(ident)
    if not isinstance(ident, int) or isinstance(ident, bool):
        return None
    label, caption, room = (_as_text(data.get(k)) for k in ("label", "caption", "room"))
    concepts = dict(label_concepts(label))
    alts = data.get("alt_labels")
    # alternative labels are the mapper's runner-up guesses: weak evidence, best first
    for rank, alt in enumerate(alts[:6] if isinstance(alts, list) else []):
        for c, w in label_concepts(_as_text(alt)):
            concepts.setdefault(c, (_ALT_WEIGHT - 0.05 * rank) * w)
    lex = load_lexicon()
    tags = data.get("tags")
    parts = [label, caption] + ([_as_text(v) for v in tags.values()] if isinstance(tags, dict) else [])
    lemmas, slots = [[lex.lemma(t) for t in lex.tokens(p)] for p in parts], [text_slots(p) for p in parts]
    attrs = [frozenset({(k, v) for s in lex.scan(ls, fits=_not_measured(ls)) for k, v in s.kinds
                        if k in ATTRIBUTE_KINDS}) for ls in lemmas]
    return ident, Record(concepts=tuple(sorted(concepts.items(), key=lambda kv: (-kv[1], kv[0]))), label=label,
                         room=room_of(room), attrs=frozenset().union(*attrs), label_words=frozenset(lemmas[0]),
                         words=frozenset().union(*map(frozenset, lemmas)),
                         text=". ".join(p for p in (label, caption) if p),
                         slots=tuple(dict.fromkeys(s for found, _ in slots for s in found)),
                         stems=frozenset().union(*(st for _, st in slots)),
                         room_words=frozenset(lex.lemma(t) for t in lex.tokens(room) if t.isalpha()))


def _as_text(value) -> str:
    if isinstance(value, (list, tuple)):
        return ", ".join(_as_text(v) for v in value)
    return "" if value is None else str(value)
