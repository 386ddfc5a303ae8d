"""What a query asks for: target categories, rooms, attributes and functional intent, read
with the shipped lexicon. Every provider and the candidate selection rely on this reading."""

from __future__ import annotations

from dataclasses import MISSING, dataclass, field, fields
from functools import lru_cache
from types import MappingProxyType, SimpleNamespace

from ..lexicon import ATTRIBUTE_KINDS, Lexicon, Span, load_lexicon, read_data
from .clauses import STRANDABLE, clause_final_words, clause_landmark, is_stranded, near_room
from .motion import MOTION_VERBS, strip_motion
from .parse import NOUNS, Structure, Word, normalise, parse_many, parse_request
from .text import SENTENCE_MARK, Slot, clause_breaks, lemmatise, modifier_spans, read_slots, stem

#: category values that name nothing in particular ("object", "unknown", "clutter")
_UNSPECIFIC = frozenset({"object"})
#: weight of a category named outside the target phrase when the target names no known kind ("a spot for my cup")
_THEME_WEIGHT = 0.35
#: word sequences after which the query says what the target is NOT (the first after word 0; "than" after "rather")
_EXCLUSIONS = tuple(tuple(p.split()) for p in read_data("language.json")["exclusions"])
#: words that introduce a part or feature of the target ("with the torn flap")
_PART_WORDS = frozenset({"with", "without", "has", "have", "having", "featuring", "wearing"})
#: verbs of posture, said of a thing, say where it is ("it sits on the worktop"), not what to do there
_POSTURE, _THING_SUBJECTS = frozenset({"sit", "stand", "lie", "rest", "perch"}), {"it", "which", "that", "this"}
#: words that open the request proper after a preamble ("I'm chilly, lead me towards ...")
_REQUEST_OPENERS = frozenset({"find", "show", "locate", "where", "navigate", "point", "search", "look", "visit"})
#: share of the request's function evidence a preamble's function evidence gets
_PREAMBLE_SCALE = 0.5
#: the kind of object that is the way out of a room
WAY_OUT = "door"
#: share of an affordance weight a kind gets as functional kin of the named category
_KIN_SCALE = 0.8
#: a purpose counts as the named category's own when the category is among its first three
#: typical kinds (weight 1.0, 0.98, 0.96: chair for sitting, not for reaching a high shelf)
_OWN_PURPOSE = 0.96
#: of such a purpose, only its most typical kinds (the first six) are kin
_TYPICAL = 0.9
#: prepositions that introduce the room an object is in ("the tap in the pantry")
_PLACE_PREPOSITIONS = frozenset({"in", "inside", "within"})


def _named(info: QueryInfo | SimpleNamespace) -> bool:
    """True when the query (or its draft) names a specific category as its target."""
    return any(w >= 1.0 for w in info.targets.values())


def _kind_alone(lex: Lexicon, info: QueryInfo) -> bool:
    """True when `info`'s text names kinds and nothing else: no attribute, room, modifier or place
    ("the toaster", "a cup or a jug"; not "the chrome toaster", "the cup on the sill")."""
    words = parse_request(normalise(lex.respell(info.text))).words
    return not (info.attrs or info.rooms) and all(
        w.dep in ("det", "cc", "punct", "preconj", "predet") or w.dep == "poss" and w.pos == "PRON"  # "our ladder"
        or w.pos in NOUNS and w.dep in ("ROOT", "conj", "compound", "pobj")
        or w.pos in ("NUM", "PRON", "DET") and w.dep == "ROOT"  # "one of the crates"
        or w.dep == "prep" and w.text.lower() == "of" and words[w.head].pos in ("NUM", "PRON", "DET")
        for w in words)


@dataclass(frozen=True, eq=False)
class QueryInfo:
    """What a query asks for (immutable: `analyse_query` memoises it and every caller shares it).
    Weights are in (0, 1]."""

    text: str
    targets: dict[str, float] = field(default_factory=dict)   # named categories (1.0 head, 0.35 theme)
    #: categories named beside the target (landmarks, things mentioned), 0.35; they are also
    #: themes in `targets` only when the request asks for no kind or class of its own
    landmarks: dict[str, float] = field(default_factory=dict)
    target_phrase: str | None = None                          # the head's words, as written
    generic: str | None = None                                # class noun used as target ("seating")
    rooms: dict[str, float] = field(default_factory=dict)     # canonical room -> 1.0 explicit, 0.5 implied
    room_phrase: str | None = None
    attrs: tuple[tuple[str, str], ...] = ()  # (kind, canonical value)
    extra: frozenset[str] = frozenset()                       # other content lemmas
    afford: dict[str, float] = field(default_factory=dict)    # category -> affordance weight
    kin: dict[str, float] = field(default_factory=dict)       # kinds that serve the named kind's purpose
    abstract: bool = False                                    # "something", "a place to ..."
    #: the function is said by a verb or a phrase ("to sit", "turn the heating down"), a class noun
    #: ("seating"), a cue naming the target (a perch), an abstract target ("something for
    #: storage") or the context, not only by a noun modifying the target ("the gold cover")
    purpose: bool = False
    head_words: frozenset[str] = frozenset()                  # lemmas of the target phrase
    slots: tuple[Slot, ...] = ()                              # attributes as written (surface + family)
    overlap: frozenset[str] = frozenset()                     # stems of extra and attribute words
    unknown_target: str | None = None     # target words the lexicon does not know ("the gizmo")
    unknown_room: str | None = None       # place words after "in" the lexicon does not know
    #: what the query rules out ("not the metal one", "that isn't a stool"): categories and
    #: attributes read from the words after an exclusion marker, which add nothing to the above
    excluded_targets: frozenset[str] = frozenset()
    excluded_attrs: frozenset[tuple[str, str]] = frozenset()

    def __post_init__(self) -> None:  # freezes the containers too
        for f in fields(self):
            if isinstance(value := getattr(self, f.name), dict):
                object.__setattr__(self, f.name, MappingProxyType(dict(value)))

    named = property(_named)


def _command_at(lex: Lexicon, tokens: list[str], i: int) -> int:
    """Length of the request phrase ("go to", "take me to") at `tokens[i]`; 0: none."""
    return next((len(cmd) for cmd in lex.commands if tuple(tokens[i:i + len(cmd)]) == cmd), 0)


def _add_entry(target: dict[str, float], weights: dict[str, float], scale: float) -> None:
    for concept, w in weights.items():
        target[concept] = target.get(concept, 0.0) + w * scale


class _Token(str):
    """A lexicon token that keeps its character offset in the parsed text (`at`)."""

    at: int

    def __new__(cls, token: str, at: int = -1) -> _Token:  # (a copy passes the text alone, then its `at`)
        self = super().__new__(cls, token)
        self.at = at
        return self


@dataclass(frozen=True)
class _Target:
    """Where the target phrase lies among the request's lemmas."""

    start: int  # its first word
    end: int  # one past the head
    head: Span | None  # the category span of the head noun (None: there is none)
    word: int | None = None  # the parse's word index of the head noun


def _parsed_target(structure: Structure, surface: list[_Token], spans: list[Span]) -> _Target | None:
    """The target phrase the parse names, when its head noun is a category the lexicon knows
    (not a room); None otherwise (the caller reads the phrase from the word order)."""
    index = None if structure.target is None else _surface_index(surface, structure.words[structure.target])
    if index is None:
        return None  # no target, or its word is not among the request's tokens
    phrase_start = next((i for i, t in enumerate(surface) if t.at >= structure.words[structure.phrase[0]].start), index)
    head = next((s for s in spans if s.start <= index < s.end), None)
    if head is not None and head.has("gen"):  # "which appliance", "the seating": a class, read as one
        return _Target(min(phrase_start, head.start), head.end, None, structure.target)
    if head is None or not set(head.values("cat")) - _UNSPECIFIC:
        return None  # not a kind the lexicon knows, a room, or "the thing": read from the word order
    following = {s.start: s for s in spans if s.has("cat")}
    # a compound the parse split ("the notebook pc", one space between as written): its last noun
    while head.end in following and _typed_together(surface, head.end - 1, head.end + 1):
        head = following[head.end]
    return _Target(min(phrase_start, head.start), head.end, head, structure.target)


def _typed_together(surface: list[_Token], start: int, end: int) -> bool:
    """True when the tokens `surface[start:end]` were typed one space apart, with no word dropped between."""
    return all(surface[k + 1].at == surface[k].at + len(surface[k]) + 1 for k in range(start, end - 1))


def _one_phrase(structure: Structure, tokens: list[_Token]) -> bool:
    """True when the parse hangs the words of `tokens` from one of them (a cue's words are one phrase),
    or has none of them."""
    ks = [k for k, w in enumerate(structure.words) if any(t.at <= w.start < t.at + len(t) for t in tokens)]
    return not ks or any(all(structure.dominates(h, k) for k in ks) for h in ks)


def _surface_index(surface: list[_Token], word: Word) -> int | None:
    """Index of the surface token that the parsed `word` covers, or None (dropped or absent)."""
    return next((i for i, t in enumerate(surface) if word.start <= t.at < word.start + len(word.text)), None)


def _ordered_target(lex: Lexicon, reading: _Reading, clause: set[int]) -> _Target:
    """The target phrase read from the word order when the parse names no known category: it ends at the first boundary
    word (a relative clause, landmark or room) or where a clause about a landmark begins (`clause`); its head is the
    rightmost specific category before that (not an attribute word before an abstract noun: "the glass object" is no
    drinking glass), its `word` the parse's word for that head, else the parse's target ("the thing", "something")."""
    bounds, abstract = lex.words["boundaries"], lex.words["abstract"]
    lemmas, spans = reading.lemmas, reading.spans
    inner = {i for s in spans for i in range(s.start + 1, s.end)}  # "set of towels" is one phrase
    end = min([next((i for i, t in enumerate(lemmas) if t in bounds and i not in inner), len(lemmas)), *clause])
    one = reading.structure.target  # "the big one facing the window": the phrase ends at the "one"
    if one is not None and reading.structure.words[one].text.lower() in ("one", "ones"):
        end = next((i + 1 for i, t in enumerate(reading.surface) if t.at == reading.structure.words[one].start), end)
    head = next((s for s in reversed(spans) if s.end <= end and set(s.values("cat")) - _UNSPECIFIC and not s.has("gen")
                 and not (set(lemmas[s.end:s.end + 1]) & abstract and any(k in ATTRIBUTE_KINDS for k, _ in s.kinds))),
                None)
    word = reading.structure.target if head is None else reading.structure.index_at(reading.surface[head.end - 1].at)
    return _Target(0, end, head, word)


def _outside_target(structure: Structure, surface: list[_Token], span: Span, target: _Target,
                    described: frozenset[int], place_ok: bool = False) -> bool:
    """True when the words of `span` modify a noun other than the target ("beside the tall wardrobe",
    "hang my wet coat"); a part of the target ("the jar with the green handle"), the target named again
    and a predicate ("it is white") stay the target's, and with `place_ok` so does a place phrase.
    `described` holds the offsets of attribute words ("in brown leather": a description)."""
    word = structure.index_at(surface[span.end - 1].at)  # the parse's word under the span's last token
    if word is not None and word != target.word and structure.words[word].dep in ("dobj", "nsubj", "nsubjpass") \
            and structure.words[word].pos == "NOUN":
        return True  # a thing the request mentions, not a description ("you nuke popcorn in")
    noun = None if word is None else structure.modified_noun(word)
    if noun is None or noun == target.word:
        return False
    owner = structure.words[noun]
    if owner.dep == "attr" or owner.start in described or owner.dep == "appos" and owner.head == target.word:
        return False  # "in brown leather": the material is the target's; "floor lamp, red shade": a part of it
    via = structure.words[owner.head].text.lower()
    return not (owner.dep == "pobj" and (via in _PART_WORDS or place_ok and via in _PLACE_PREPOSITIONS))


@dataclass
class _Reading:
    """The request's words as the span loop reads them, with what only says why (`preamble`) and
    the readings of what follows an exclusion marker (`ruled_out`)."""

    text: str
    structure: Structure
    surface: list[_Token]
    lemmas: list[str]
    spans: list[Span]
    preamble: list[str]
    ruled_out: list["QueryInfo"]


def _read_request(lex: Lexicon, text: str) -> _Reading:
    """Spell, parse and tokenise `text`: the request's tokens without the words that only say
    where to go or what to do ("take me to", "head over to"), with what follows an exclusion
    marker read apart and what comes before the request phrase kept as the preamble."""
    structure = parse_request(normalise(lex.respell(text)))
    corrected = structure.text  # without the vessels of a wished portion ("a jug of juice": a juice)
    start, end = structure.request
    tokens = [_Token(token, start + at) for token, at in lex.token_offsets(corrected[start:end])]
    marker = next(((i, i + len(words)) for i in range(1, len(tokens)) for words in _EXCLUSIONS
                   if tuple(tokens[i:i + len(words)]) == words and (words[0] != "than" or "rather" in tokens[:i])),
                  None)
    ruled_out = [] if structure.excluded is None else [  # "Not the green kettle: ..."
        analyse_query(" ".join(lex.tokens(corrected[slice(*structure.excluded)])[1:]))]
    if marker is not None:  # to the end of its sentence ("the blue mug, not the red. It's on the sill.")
        end = min((k for k in clause_breaks(corrected, [(t, t.at) for t in tokens], SENTENCE_MARK) if k > marker[1]),
                  default=len(tokens))
        after = marker[1] + (marker[1] < end and tokens[marker[1]] in _PLACE_PREPOSITIONS | {"on", "at"})
        ruled_out.append(analyse_query(" ".join(tokens[after:end])))  # "not in the wingback": the wingback
        tokens = tokens[:marker[0]] + tokens[end:]
    preamble = [t for a, b in structure.context for t in lex.tokens(corrected[a:b])]
    # a request phrase ("go to", "take me to", "find") after at least two words: what comes before it only says why
    start = next((i for i in range(2, len(tokens) - 1) if tokens[i] in MOTION_VERBS | _REQUEST_OPENERS
                  and tokens[i - 1] != "to" and _command_at(lex, tokens, i)), None)  # not "to get it dried"
    # ("My feet are cold, take me to a rug"); not when the parse's target is first ("A rug by the door. Head there.")
    if start is not None and (structure.target is None or structure.words[structure.target].start >= tokens[start].at):
        preamble, tokens = preamble + tokens[:start], tokens[start:]
    tokens = strip_motion(tokens)
    while n := _command_at(lex, tokens, 0):  # without the request phrases it opens with ("do show me the way to")
        tokens = tokens[n:]
    surface = [t for t in tokens if t not in lex.words["skip"]]
    lemmas = lemmatise(lex, surface)
    breaks = clause_breaks(corrected, [(t, t.at) for t in surface])
    def one_use(start: int, end: int, kinds) -> bool:  # a use's words read past a dropped word are one phrase
        return {k for k, _ in kinds} != {"cue"} or _typed_together(surface, start, end) \
            or _one_phrase(structure, surface[start:end])  # ("turn on the light"; not "gives me the time")
    # a thing's name right before a hyphened colour suffix is a colour ("light-coloured": no lamp)
    spans = [s for s in lex.scan(lemmas, breaks, one_use) if any(k in ATTRIBUTE_KINDS for k, _ in s.kinds)
             or s.end == len(lemmas) or lemmas[s.end] not in lex.words["color_suffixes"]
             or corrected[surface[s.end].at - 1] != "-"]
    # a use's word as the target noun with a colour or material ("a red leather volume") names a thing, not a use
    looks = {surface[i].at for s in spans if s.has("color") or s.has("material") for i in range(s.start, s.end)}
    if any(structure.words[k].start in looks for k in structure.children(structure.target, "amod", "compound", "nmod")):
        spans = [s for s in spans if not (s.end - s.start == 1 and {k for k, _ in s.kinds} == {"cue"}
                                          and structure.index_at(surface[s.start].at) == structure.target)]
    return _Reading(corrected, structure, surface, lemmas, spans, preamble, ruled_out)


def parse_queries(texts: list[str]) -> None:
    """Parse the requests `texts` together (`parse_many`), for `analyse_query` to find memoised."""
    lex = load_lexicon()
    parse_many([normalise(lex.respell(t)) for t in texts])


@lru_cache(maxsize=4096)
def analyse_query(text: str) -> QueryInfo:
    """Targets, rooms, attributes and functional intent of a natural-language query; words
    after an exclusion marker ("- not the metal one") only say what the target is not."""
    lex = load_lexicon()
    reading = _read_request(lex, text)
    info = SimpleNamespace(**{f.name: f.default_factory() if f.default_factory is not MISSING else f.default
                              for f in fields(QueryInfo) if f.name != "text"}, text=text)  # a mutable draft
    # kinds ruled out by name alone ("not the toaster"); "not the chrome toaster" rules out what it describes
    by_kind = [_kind_alone(lex, out) for out in reading.ruled_out]
    info.excluded_targets = frozenset(c for out, alone in zip(reading.ruled_out, by_kind) for c in (
        *(out.targets if alone else ()), *out.landmarks))
    info.excluded_attrs = frozenset(kv for out in reading.ruled_out for kv in out.attrs)
    # token positions of relative clauses about a landmark whose preposition is stranded, from the landmark's noun to
    # the preposition ("the cabinet [the printer sits on]")
    surface, categories = reading.surface, {sp.start: sp for sp in reading.spans if sp.has("cat")}
    starts = {k: clause_landmark(categories, surface, k) for k, token in enumerate(surface)
              if token in STRANDABLE and is_stranded(surface, k + 1, clause_final_words(reading.text))}
    clause = {i for k, start in starts.items() if start is not None for i in range(start, k + 1)}
    target = _parsed_target(reading.structure, surface, reading.spans) or _ordered_target(lex, reading, clause)
    info.abstract = any(t in lex.words["abstract"] for t in reading.lemmas[target.start:target.end])
    afford, attr_spans, landmark_words = _read_spans(lex, reading, target, clause, info)
    covered = {i for s in reading.spans for i in range(s.start, s.end)}
    cue_covered = {i for s in reading.spans if s.has("cue") for i in range(s.start, s.end)}
    for positions, idx in lex.gapped_cues(reading.lemmas):
        if not _one_phrase(reading.structure, [surface[k] for k in positions]):
            continue  # its words in two phrases of the parse; "turn the heating down" is one
        info.purpose = info.purpose or len(positions) > 1  # "turn the heating down": a phrase says what to do
        if not cue_covered.intersection(positions):  # a contiguous cue already read these words
            _add_entry(afford, lex.affordances[int(idx)], 0.8)
            covered.update(positions)
    words = reading.structure.words
    for k, thing in reading.structure.done_to:  # a use said of a pronoun ("scrub them") or as a result ("get it warm")
        kinds = {c for kind, c in lex.phrase(words[thing].text) if kind == "cat"}  # ("dry the shirts": clothes)
        particles = {(), *((words[p].text.lower(),) for p in reading.structure.children(k, "prt"))}  # "plug it in"
        for cue, idx in lex.cue_sequences.get(lex.lemma(words[k].text.lower()), ()):
            if cue[1:-1] in particles and cue[-1] in kinds | {lex.lemma(words[thing].text.lower())}:
                _add_entry(afford, lex.affordances[int(idx)], 0.8)
                info.purpose = True  # what the use is done to is not where to go
                info.targets = {c: w for c, w in info.targets.items() if c not in kinds}
    if reading.preamble:  # "I'm chilly - bring me to ...", "It's upstairs in the study.": why and where
        context = analyse_query(" ".join(reading.preamble))
        scale = _PREAMBLE_SCALE * (max(afford.values()) if afford else 1.0)
        for concept, weight in context.afford.items():  # never above what the request itself asks
            afford[concept] = max(afford.get(concept, 0.0), scale * weight)
        info.purpose = info.purpose or context.purpose
        if not info.rooms:
            info.rooms = dict(context.rooms)
            info.room_phrase = context.room_phrase
    top = max(afford.values(), default=1.0)
    info.afford = {c: w / top for c, w in afford.items()}
    left = reading.structure.leaving  # what the request wants out of, when it is a room ("get me out of the garage")
    left = None if left is None else _surface_index(surface, reading.structure.words[left])
    if not _named(info) and left is not None and any(s.has("room") and s.start <= left < s.end for s in reading.spans):
        info.targets[WAY_OUT] = 1.0  # "how do I leave the kitchen": the kitchen's door
        info.target_phrase = info.target_phrase or WAY_OUT
    info.kin = functional_kin(lex, [c for c, w in info.targets.items() if w >= 1.0])
    fronted_or_one = reading.structure.excluded is not None or "one" in reading.lemmas
    # a thing ruled out by what it is like or where it is gives "one" its kind; one ruled out by its kind
    # alone does not ("the glass one, not the wooden tray": a tray; "the glass one, not the tray": no tray)
    kind_of_one = reading.ruled_out[0] if fronted_or_one and by_kind and not by_kind[0] else None
    named_before = reading.structure.kind is not None  # "I need a mug; the blue ones": its kind, whatever the wish
    if kind_of_one is None and named_before:
        kind_of_one = analyse_query(reading.structure.words[reading.structure.kind].text)
    if not _named(info) and kind_of_one is not None and kind_of_one.named and (
            not info.afford or named_before or "one" in reading.lemmas):
        # "Not the tall oak wardrobe, the short pine one", "the pine one, not the oak wardrobe":
        # one of the kind the exclusion named
        info.targets.update({c: 1.0 for c, w in kind_of_one.targets.items() if w >= 1.0})
        info.target_phrase = info.target_phrase or kind_of_one.target_phrase
    _read_words(lex, reading, target, covered, attr_spans, landmark_words, info)
    info.excluded_targets -= {c for c, w in info.targets.items() if w >= 1.0}  # "not the plain blue rug:
    info.excluded_attrs -= set(info.attrs)                                     # the striped blue one"
    return QueryInfo(**vars(info))


def _read_spans(lex: Lexicon, reading: _Reading, target: _Target, clause: set[int],
                info: SimpleNamespace) -> tuple[dict[str, float], list[Span], set[str]]:
    """Fill `info` from the lexicon spans: the head's categories, rooms, attributes of the target
    and the landmarks named beside it; return (function evidence, attribute spans, landmark words)."""
    structure, surface, lemmas, head = reading.structure, reading.surface, reading.lemmas, target.head
    afford: dict[str, float] = {}
    landmark_words: set[str] = set()
    attr_spans: list[Span] = []
    described = frozenset(surface[i].at for s in reading.spans if any(k in ATTRIBUTE_KINDS for k, _ in s.kinds)
                          for i in range(s.start, s.end))
    asks_kind = head is not None or any(s.has("gen") and target.start <= s.start and s.end <= target.end
                                        for s in reading.spans)
    for s in reading.spans:
        in_target = target.start <= s.start and s.end <= target.end
        if s is head or s.has("gen") and in_target:  # a class noun's words too: a label may say it ("bucket")
            info.target_phrase = " ".join(surface[s.start:s.end])
            info.head_words = frozenset(lemmas[s.start:s.end])
            if s is head:
                info.targets.update({c: 1.0 for c in s.values("cat") if c not in _UNSPECIFIC})
                attr_spans.extend(modifier_spans(lex, lemmas, s))
                info.rooms.update({v: info.rooms.get(v, 0.5) for w in lemmas[s.start:s.end]
                                   for kind, v in lex.phrases.get((w,), ()) if kind == "room"})  # "bath towel"
            else:
                info.generic = s.values("gen")[0]
                _add_entry(afford, lex.generic[info.generic], 1.0)
                info.purpose = True
            continue
        word = structure.index_at(surface[s.start].at)  # the parse's word under the span's first token
        if word in structure.lacking and not in_target:  # "without using the hob", "with no lamp": never the target
            info.excluded_targets |= frozenset(c for c in s.values("cat") if c not in _UNSPECIFIC)
            continue
        if s.has("room") and not (in_target and s.has("cat")) and not (  # "where I want to lounge": no room
                word is not None and structure.words[word].pos == "VERB" and structure.children(word, "aux", "nsubj")):
            if _outside_target(structure, surface, s, target, described, place_ok=True) \
                    or near_room(surface, s.start, s.end, {t.start for t in reading.spans if t.has("cat")}):
                continue  # "a case for the office papers": the papers' room; "closest to the den": a landmark
            info.rooms.update({r: 1.0 for r in s.values("room")})
            first = s.start - (s.start > 0 and lemmas[s.start - 1] in lex.room_qualifiers)  # ("a principal bedroom")
            info.room_phrase = info.room_phrase or " ".join(surface[first:s.end])
            continue
        attr = [(k, v) for k, v in s.kinds if k in ATTRIBUTE_KINDS]
        if attr and not s.has("cue") and not in_target and (_outside_target(structure, surface, s, target, described) or (
                {k for k, _ in attr} == {"shape"} and word is not None and structure.words[word].dep == "pobj")):
            continue  # "where do I hang my wet coat": wet is the coat; "at the corner of the desk": a place, no shape
        info.attrs = info.attrs + tuple(kv for kv in attr if kv not in info.attrs)
        attr_spans += [s] if attr else []
        if attr and not s.has("cue"):
            continue
        posed = lemmas[s.start] in _POSTURE and word is not None and any(  # "it sits", "it plugs in and sits"
            structure.words[n].text.lower() in _THING_SUBJECTS for n in structure.children(
                {word, structure.words[word].head if structure.words[word].dep == "conj" else word}, "nsubj"))
        if s.has("cue") and s.start not in clause and not posed:
            for idx in s.values("cue"):
                _add_entry(afford, lex.affordances[int(idx)], 1.0 if s.end - s.start > 1 else 0.8)
            # a cue on a noun the parse puts under the target noun ("the grey file with a tag on the spine") describes
            # the thing, not what to do (a head noun that is a cue names a class of things: a perch to sit on)
            info.purpose = info.purpose or s.end - s.start > 1 or info.abstract or not (
                word is not None and target.word is not None and word != target.word
                and structure.words[word].pos in NOUNS and structure.dominates(target.word, word))
        if s.has("cat") and not in_target:
            named = {c: _THEME_WEIGHT for c in s.values("cat") if c not in _UNSPECIFIC}
            info.landmarks.update(named)
            if not asks_kind:  # no kind or class asked for: a thing named beside the target may be what is meant
                info.targets.update({c: info.targets.get(c, w) for c, w in named.items()})
            landmark_words.update(lemmas[s.start:s.end])  # "the lamp next to the bed": captions naming it count
        elif s.has("gen"):
            _add_entry(afford, lex.generic[s.values("gen")[0]], 0.8)
    return afford, attr_spans, landmark_words


def _read_words(lex: Lexicon, reading: _Reading, target: _Target, covered: set[int], attr_spans: list[Span],
                landmark_words: set[str], info: SimpleNamespace) -> None:
    """Fill `info`'s attribute slots, loose words and the words the lexicon does not know (a
    target or room phrase to ground in the map)."""
    surface, lemmas, bounds = reading.surface, reading.lemmas, lex.words["boundaries"]
    slots, used = read_slots(lex, lemmas, attr_spans)
    info.slots = tuple(dict.fromkeys(slots))
    stop = (lex.words["skip"] | bounds | lex.words["abstract"] | lex.words["color_suffixes"]
            | lex.words["imitation_suffixes"])
    info.extra = frozenset(t for i, t in enumerate(lemmas)
                           if i not in covered and i not in used and len(t) > 2 and t not in stop)
    words = {*info.extra, *landmark_words, *(w for slot in info.slots for w in slot.base.split())}
    info.overlap = frozenset(stem(w) for w in words if len(w) > 2)
    known = covered | used
    if not _named(info) and not info.afford:
        info.unknown_target = _unknown_run(surface, lemmas, known, stop, 0, target.end)
    place = next((i for i, t in enumerate(lemmas) if t in _PLACE_PREPOSITIONS), None)
    if place is not None and not any(w >= 1.0 for w in info.rooms.values()):
        stop_at = next((i for i in range(place + 1, len(lemmas)) if lemmas[i] in bounds), len(lemmas))
        if known.isdisjoint(range(place + 1, stop_at)):  # no word of the place phrase is a lexicon phrase
            info.unknown_room = _unknown_run(surface, lemmas, known, stop, place + 1, stop_at)


def functional_kin(lex: Lexicon, named: list[str]) -> dict[str, float]:
    """Kinds that serve the same purpose as a named category (chair -> sofa, stool, bench): the
    most typical kinds of the affordance entries whose first kinds include it, 0.8 x their weight."""
    kin: dict[str, float] = {}
    for concept, weight in ((c, w) for i in sorted({i for n in named for i in lex.purposes_of(n, _OWN_PURPOSE)})
                            for c, w in lex.affordances[i].items() if w >= _TYPICAL):
        kin[concept] = max(kin.get(concept, 0.0), _KIN_SCALE * weight)
    return kin


def _unknown_run(surface: list[_Token], lemmas: list[str], known: set[int], stop: frozenset[str],
                 start: int, end: int) -> str | None:
    """The content words of `start:end` that no lexicon phrase covers, as written; None when there are none."""
    return " ".join(surface[i] for i in range(start, end)
                    if i not in known and lemmas[i] not in stop and len(lemmas[i]) > 2 and lemmas[i].isalpha()) or None
