"""Lexical analysis of queries, raw instance labels and candidate records (cached)."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from functools import lru_cache

from ...lexicon import ATTRIBUTE_KINDS, Lexicon, Span, load_lexicon

#: category values that name nothing in particular ("object", "unknown", "clutter")
_UNSPECIFIC = frozenset({"object"})
#: weight of a category named outside the target phrase ("... to put my cup on")
_THEME_WEIGHT = 0.35
_SECONDARY_WEIGHT = 0.6
#: weight of a category only an alternative label names (the first; each later one 0.05 less)
_ALT_WEIGHT = 0.6


@dataclass(frozen=True)
class Slot:
    """One described attribute as written: `surface` keeps the words ("pale blue gray",
    "leather like", "mesh"), `base` drops shade words ("blue gray"), `values` are the canonical
    families ({"blue", "gray"}; empty for a colour the lexicon does not know, e.g. "ash colored")."""

    kind: str
    surface: str
    base: str
    values: frozenset[str]


@dataclass
class QueryInfo:
    """What a query asks for. Weights are in (0, 1]."""

    text: str
    targets: dict[str, float] = field(default_factory=dict)   # named categories (1.0 head, 0.35 theme)
    target_phrase: str | None = None                          # the head's words, as written
    generic: str | None = None                                # class noun used as target ("seating")
    rooms: dict[str, float] = field(default_factory=dict)     # canonical room -> 1.0 explicit, 0.5 implied
    room_phrase: str | None = None
    attrs: list[tuple[str, str]] = field(default_factory=list)  # (kind, canonical value)
    extra: frozenset[str] = frozenset()                       # other content lemmas
    afford: dict[str, float] = field(default_factory=dict)    # category -> affordance weight
    abstract: bool = False                                    # "something", "a place to ..."
    head_words: frozenset[str] = frozenset()                  # lemmas of the target phrase
    slots: tuple[Slot, ...] = ()                              # attributes as written (surface + family)
    overlap: frozenset[str] = frozenset()                     # stems of extra and attribute words
    memo: dict = field(default_factory=dict, repr=False, compare=False)  # scorer's per-query cache

    @property
    def named(self) -> bool:
        """True when the query names a specific category as its target."""
        return any(w >= 1.0 for w in self.targets.values())


@dataclass(frozen=True)
class Record:
    """A candidate's lexical profile, built from whatever fields it has."""

    concepts: tuple[tuple[str, float], ...]  # (category, weight), best first
    room: str | None
    attrs: frozenset[tuple[str, str]]
    words: frozenset[str]        # lemmas of label, caption and tags
    label_words: frozenset[str]  # lemmas of the label
    text: str                    # label and caption, for sentence embeddings
    slots: tuple[Slot, ...] = ()  # attributes as written in label, caption and tags
    stems: frozenset[str] = frozenset()  # word stems of label, caption and tags


def _strip_command(lex: Lexicon, tokens: list[str]) -> list[str]:
    changed = True
    while changed and tokens:
        changed = False
        for cmd in lex.commands:
            if tuple(tokens[:len(cmd)]) == cmd and len(tokens) > len(cmd):
                tokens = tokens[len(cmd):]
                changed = True
                break
    return tokens


def _add_entry(target: dict[str, float], weights: dict[str, float], scale: float) -> None:
    for concept, w in weights.items():
        target[concept] = target.get(concept, 0.0) + w * scale


@lru_cache(maxsize=4096)
def analyse_query(text: str) -> QueryInfo:
    """Targets, rooms, attributes and functional intent of a natural-language query."""
    lex = load_lexicon()
    skip, bounds = lex.words["skip"], lex.words["boundaries"]
    surface = [t for t in _strip_command(lex, lex.tokens(text)) if t not in skip]
    lemmas = [lex.lemma(t) for t in surface]
    spans = lex.scan(lemmas)
    info = QueryInfo(text=text)

    # the target noun phrase ends at the first boundary word (relative clause, landmark, room)
    inner = {i for s in spans for i in range(s.start + 1, s.end)}  # "set of towels" is one phrase
    end = next((i for i, t in enumerate(lemmas) if t in bounds and i > 0 and i not in inner), len(lemmas))
    if lemmas and lemmas[0] in bounds:
        end = 0
    covered: set[int] = set()
    for s in spans:
        covered.update(range(s.start, s.end))
    head = _head_span(spans, end, lemmas, lex.words["abstract"])
    if head is not None and _after_abstract_clause(lex, lemmas, covered, head.start):
        end, head = head.start, None  # "something (that) gives light": light is what it does
    info.abstract = any(t in lex.words["abstract"] for t in lemmas[:max(end, 1)])
    afford: dict[str, float] = {}
    landmark_words: set[str] = set()
    attr_spans: list[Span] = []
    cue_covered: set[int] = set()
    for s in spans:
        if s.has("cue"):
            cue_covered.update(range(s.start, s.end))

    for s in spans:
        in_target = s.end <= end
        if s is head:
            info.targets.update({c: 1.0 for c in s.values("cat") if c not in _UNSPECIFIC})
            info.target_phrase = " ".join(surface[s.start:s.end])
            info.head_words = frozenset(lemmas[s.start:s.end])
            attr_spans.extend(_modifier_spans(lex, lemmas, s))
            _implied_rooms(lex, lemmas[s.start:s.end], info)
            continue
        if s.has("gen") and in_target:
            info.generic = s.values("gen")[0]
            info.target_phrase = " ".join(surface[s.start:s.end])
            _add_entry(afford, lex.generic[info.generic], 1.0)
            continue
        if s.has("room") and not (in_target and s.has("cat")):
            for r in s.values("room"):
                info.rooms[r] = 1.0
            info.room_phrase = info.room_phrase or " ".join(surface[s.start:s.end])
            continue
        attr = [(k, v) for k, v in s.kinds if k in ATTRIBUTE_KINDS]
        info.attrs.extend(kv for kv in attr if kv not in info.attrs)
        if attr:
            attr_spans.append(s)
        if attr and not s.has("cue"):
            continue
        if s.has("cue"):
            scale = 1.0 if s.end - s.start > 1 else 0.8
            for idx in s.values("cue"):
                _add_entry(afford, lex.affordances[int(idx)], scale)
        if s.has("cat") and not in_target:
            for c in s.values("cat"):
                if c not in _UNSPECIFIC:
                    info.targets.setdefault(c, _THEME_WEIGHT)
            # a landmark ("the lamp next to the bed"): captions that mention it are evidence
            landmark_words.update(lemmas[s.start:s.end])
        elif s.has("gen"):
            _add_entry(afford, lex.generic[s.values("gen")[0]], 0.8)

    for positions, idx in lex.gapped_cues(lemmas):
        if not cue_covered.intersection(positions):  # a contiguous cue already read these words
            _add_entry(afford, lex.affordances[int(idx)], 0.8)
            covered.update(positions)
    if afford:
        top = max(afford.values())
        info.afford = {c: w / top for c, w in afford.items()}
    slots, used = _slots(lex, lemmas, attr_spans)
    info.slots = tuple(dict.fromkeys(slots))
    stop = skip | bounds | lex.words["abstract"] | lex.words["color_suffixes"] | lex.words["imitation_suffixes"]
    info.extra = frozenset(t for i, t in enumerate(lemmas)
                           if i not in covered and i not in used and len(t) > 2 and t not in stop and not t.isdigit())
    words = set(info.extra) | landmark_words
    for slot in info.slots:
        words.update(slot.base.split())
    info.overlap = frozenset(stem(w) for w in words if len(w) > 2)
    return info


def _word_stems(lex: Lexicon, lemmas: list[str]) -> set[str]:
    """Stems of words and of the parts of hyphenated words; imitation words read as "like"."""
    out: set[str] = set()
    imitation = lex.words["imitation_suffixes"]
    for w in lemmas:
        for part in (w, *w.split("-")) if "-" in w else (w,):
            if part in imitation:
                part = "like"
            if len(part) > 2:
                out.add(stem(part))
    return out


def stem(word: str) -> str:
    """Crude suffix stripping for word overlap: striped/stripes/stripe -> strip, frosted -> frost."""
    w = word
    if len(w) > 5 and w.endswith("ing"):
        w = w[:-3]
    elif len(w) > 4 and w.endswith(("ed", "es")):
        w = w[:-2]
    elif len(w) > 3 and w.endswith("s") and not w.endswith("ss"):
        w = w[:-1]
    if len(w) > 4 and w.endswith("y"):
        w = w[:-1]
    if len(w) > 3 and w.endswith("e"):
        w = w[:-1]
    if len(w) > 3 and w[-1] == w[-2]:
        w = w[:-1]
    return w


def _norm_surface(lex: Lexicon, words: list[str]) -> tuple[str, str]:
    """(surface, base) of an attribute's words: hyphens and colour suffixes dropped, imitation
    words ("look", "faux", "like") folded into one trailing "like", shades dropped from base."""
    parts = [p for w in words for p in w.split("-") if p]
    imitation = any(p in lex.words["imitation_suffixes"] for p in parts)
    core = [p for p in parts if p not in lex.words["imitation_suffixes"] and p not in lex.words["color_suffixes"]]
    base = [p for p in core if p not in lex.shades] or core
    tail = ["like"] if imitation else []
    return " ".join(core + tail), " ".join(base + tail)


def _modifier_spans(lex: Lexicon, lemmas: list[str], span: Span) -> list[Span]:
    """Attribute words inside a multi-word category phrase, as one-word spans: a modifier there
    is also a description ("mesh chair": mesh; "small table": small)."""
    out = []
    for k in range(span.start, span.end) if span.end - span.start > 1 else ():
        kinds = tuple(kv for kv in lex.phrases.get((lemmas[k],), ()) if kv[0] in ATTRIBUTE_KINDS)
        if kinds:
            out.append(Span(k, k + 1, kinds))
    return out


def _slots(lex: Lexicon, lemmas: list[str], attr_spans: list[Span]) -> tuple[list[Slot], set[int]]:
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
        start, end = group[0].start, group[-1].end
        while end < len(lemmas) and lemmas[end] in suffixes:
            end += 1
        used.update(range(start, end))
        kinds = {k for s in group for k, _ in s.kinds if k in ATTRIBUTE_KINDS}
        for kind in sorted(kinds):
            values = frozenset(v for s in group for k, v in s.kinds if k == kind)
            words = lemmas[start:end] if kind == "color" or len(group) == 1 else lemmas[group[0].start:group[0].end]
            surface, base = _norm_surface(lex, words)
            slots.append(Slot(kind, surface, base, values))
    for i in range(len(lemmas) - 1):
        if (lemmas[i + 1] in lex.words["color_suffixes"] and i not in span_idx and i not in used
                and lemmas[i].isalpha() and len(lemmas[i]) > 2 and lemmas[i] not in lex.shades):
            slots.append(Slot("color", lemmas[i], lemmas[i], frozenset()))
            used.update((i, i + 1))
    return slots, used


def _head_span(spans: list[Span], end: int, lemmas: list[str], abstract: frozenset[str]) -> Span | None:
    """Rightmost specific category span inside the target phrase. A word that is also an
    attribute and stands before an abstract noun modifies it ("the glass object": glass is the
    material, not a drinking glass)."""
    head = None
    for s in spans:
        if s.end > end:
            break
        cats = [c for c in s.values("cat") if c not in _UNSPECIFIC]
        modifier = (any(k in ATTRIBUTE_KINDS for k, _ in s.kinds) and s.end < len(lemmas)
                    and lemmas[s.end] in abstract)
        if cats and not s.has("gen") and not modifier:
            head = s
    return head


def _after_abstract_clause(lex: Lexicon, lemmas: list[str], covered: set[int], start: int) -> bool:
    """An abstract noun comes before `start` with an unknown (verb-like) word in between."""
    marks = [i for i in range(start) if lemmas[i] in lex.words["abstract"]]
    return bool(marks) and any(i not in covered for i in range(marks[0] + 1, start))


def _implied_rooms(lex: Lexicon, words: list[str], info: QueryInfo) -> None:
    for w in words:
        for kind, value in lex.phrases.get((w,), ()):
            if kind == "room":
                info.rooms.setdefault(value, 0.5)


@lru_cache(maxsize=65536)
def label_concepts(label: str) -> tuple[tuple[str, float], ...]:
    """Categories a raw map label denotes, with weights: 'cabinet kitchen' -> cabinet,
    'stand/small table' -> stand and side table, 'set of towels' -> towel, 'mirror frame' -> mirror 1.0 + frame."""
    lex = load_lexicon()
    out: dict[str, float] = {}
    whole = [v for k, v in lex.phrase(label) if k == "cat"]
    for c in whole:
        out[c] = 1.0
    for part in label.replace("\\", "/").split("/"):
        for concept, w in _part_concepts(lex, part).items():
            out[concept] = max(out.get(concept, 0.0), w)
    return tuple(sorted(out.items(), key=lambda kv: (-kv[1], kv[0])))


def _part_concepts(lex: Lexicon, part: str) -> dict[str, float]:
    words = [lex.lemma(t) for t in lex.tokens(part) if t not in lex.words["skip"]]
    words = [w for w in words if w not in lex.words["ignore"]]
    if not words:
        return {}
    # "set of towels" -> towels; "box of paper" -> box (+ paper); "bowl with sweets" -> bowl
    for joiner in ("of", "with", "for", "on", "in", "and"):
        if joiner in words[1:-1]:
            i = words.index(joiner)
            left, right = words[:i], words[i + 1:]
            if joiner == "of" and left[-1] in lex.words["collective_strict"]:
                return _phrase_concepts(lex, right)
            if joiner == "of" and left[-1] in lex.words["weak_heads"]:
                return _phrase_concepts(lex, right)
            main = _phrase_concepts(lex, left)
            for c, w in _phrase_concepts(lex, right).items():
                main.setdefault(c, w * _SECONDARY_WEIGHT)
            return main or _phrase_concepts(lex, right)
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
    out: dict[str, float] = {}
    for s in spans:
        for c in s.values("cat"):
            w = 1.0 if s is head else _SECONDARY_WEIGHT
            out[c] = max(out.get(c, 0.0), w)
    return out


def _text_attrs(lex: Lexicon, text: str) -> tuple[set[tuple[str, str]], set[str]]:
    lemmas = [lex.lemma(t) for t in lex.tokens(text)]
    attrs = {(k, v) for s in lex.scan(lemmas) for k, v in s.kinds if k in ATTRIBUTE_KINDS}
    return attrs, set(lemmas)


@lru_cache(maxsize=65536)
def _caption_profile(text: str) -> tuple[frozenset[tuple[str, str]], frozenset[str]]:
    attrs, words = _text_attrs(load_lexicon(), text)
    return frozenset(attrs), frozenset(words)


_CHUNK = re.compile(r"[,;:.()/|!?]+")


@lru_cache(maxsize=65536)
def text_slots(text: str) -> tuple[tuple[Slot, ...], frozenset[str]]:
    """Attribute slots and word stems of a caption, tag value or label. Punctuation separates
    ("white, red" is two colours); words next to each other may form a compound ("blue-gray")."""
    lex = load_lexicon()
    slots: list[Slot] = []
    stems: set[str] = set()
    for chunk in _CHUNK.split(text):
        lemmas = [lex.lemma(t) for t in lex.tokens(chunk)]
        if not lemmas:
            continue
        stems.update(_word_stems(lex, lemmas))
        spans: list[Span] = []
        for sp in lex.scan(lemmas):
            if any(k in ATTRIBUTE_KINDS for k, _ in sp.kinds):
                spans.append(sp)
            else:
                spans.extend(_modifier_spans(lex, lemmas, sp))
        slots.extend(_slots(lex, lemmas, spans)[0])
    return tuple(dict.fromkeys(slots)), frozenset(stems)


@lru_cache(maxsize=4096)
def room_of(text: str) -> str | None:
    """Canonical room type of a room label such as 'Living Room 2' or 'office1'."""
    lex = load_lexicon()
    lemmas = [lex.lemma(t.rstrip("0123456789")) for t in lex.tokens(text)]
    for s in lex.scan([t for t in lemmas if t]):
        rooms = s.values("room")
        if rooms:
            return rooms[0]
    return text.strip().lower() or None


@lru_cache(maxsize=65536)
def candidate_from_line(line: str) -> tuple[int, Record] | None:
    """(id, profile) of one fenced candidate line (JSON object with id, label, alt_labels,
    room, caption, tags; all but id optional); None if the line is unusable."""
    try:
        data = json.loads(line)
    except ValueError:
        return None
    if not isinstance(data, dict):
        return None
    ident = data.get("id")
    if isinstance(ident, str) and ident.strip().lstrip("-").isdigit():
        ident = int(ident)
    if not isinstance(ident, int) or isinstance(ident, bool):
        return None
    return ident, _record(data)


def _record(data: dict) -> Record:
    label = _as_text(data.get("label"))
    concepts = dict(label_concepts(label)) if label else {}
    label_words = set(_caption_profile(label)[1]) if label else set()
    alts = data.get("alt_labels")
    # alternative labels are the mapper's runner-up guesses: weak evidence, best first
    for rank, alt in enumerate(alts[:6] if isinstance(alts, list) else []):
        for c, w in label_concepts(_as_text(alt)):
            concepts.setdefault(c, (_ALT_WEIGHT - 0.05 * rank) * w)
    room = room_of(_as_text(data.get("room"))) if data.get("room") else None
    caption = _as_text(data.get("caption"))
    text_parts = [label, caption]
    tags = data.get("tags")
    if isinstance(tags, dict):
        text_parts += [_as_text(v) for v in tags.values()]
    attrs: set[tuple[str, str]] = set()
    words: set[str] = set()
    slots: dict[Slot, None] = {}
    stems: set[str] = set()
    for part in text_parts:
        if part:
            a, w = _caption_profile(part)
            attrs |= a
            words |= w
            sl, st = text_slots(part)
            slots.update(dict.fromkeys(sl))
            stems |= st
    return Record(concepts=tuple(sorted(concepts.items(), key=lambda kv: (-kv[1], kv[0]))), room=room,
                  attrs=frozenset(attrs), words=frozenset(words), label_words=frozenset(label_words),
                  text=". ".join(p for p in (label, caption) if p), slots=tuple(slots), stems=frozenset(stems))


def _as_text(value) -> str:
    if value is None:
        return ""
    if isinstance(value, (list, tuple)):
        return ", ".join(_as_text(v) for v in value)
    return str(value)
