"""Reading a referring expression for the spatial expert: the target kind, its colour, material
and size words, the relations (on, under, above, below, next to, closest, farthest, between, corner,
middle, wall, left/right/front/behind, extremes, ordinals) with their landmark categories, and the
viewpoint ("facing the wardrobe"). Lexicon-driven, from the shared query understanding."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

from ..lexicon import ATTRIBUTE_KINDS, load_lexicon, read_data
from .clauses import (AUXILIARIES, BACK_REFERENCES, INVERSE_RELATION, TARGET_PRONOUNS, clause_final_words, clause_landmark,
                      is_stranded, near_room)
from .motion import MOTION_VERBS, POSTURE_VERBS, is_destination
from .parse import NAMING, NOUNS, STAND_INS, Word, normalise, parse_request
from .query import QueryInfo, analyse_query
from .text import SENTENCE_MARK, clause_breaks, lemmatise

#: relation cues (word sequences) by the relation they name, from the lexicon's language file
_CUES: dict[tuple[str, ...], str] = {  # as read: without the words the reader skips ("on [its] own")
    tuple(w for w in cue.split() if w not in read_data("language.json")["skip"]): kind
    for kind, cues in read_data("language.json")["relation_cues"].items() for cue in cues}
#: compass directions on the map's plan (x east, y north, as the store's `relate` tool says them):
#: sides with an axis of their own, whoever looks ("the north side of the desk", "the west crate")
COMPASS = {"north": (0.0, 1.0), "south": (0.0, -1.0), "east": (1.0, 0.0), "west": (-1.0, 0.0)}
COMPASS.update({f"{a}-{b}": (COMPASS[b][0] / 2 ** 0.5, COMPASS[a][1] / 2 ** 0.5)
                for a in ("north", "south") for b in ("east", "west")})
_CUES.update({cue: kind for kind in COMPASS for cue in (tuple(kind.split("-")), (kind.replace("-", ""),),
                                                         (kind.replace("-", "") + "ern",))})
#: comparative and superlative words by the extreme they rank on
_EXTREMES = {word: value for value, words in read_data("language.json")["extremes"].items() for word in words}
#: nouns that place the target in height when they modify a noun ("the top drawer") or are the
#: object of "on" or "at" with no "of" ("the one on top")
_HEIGHT_NOUNS = {"top": "high", "bottom": "low"}
_ORDINALS = {word: int(n) for n, words in read_data("language.json")["ordinals"].items() for word in words}
#: relations a side or middle word names, also made superlative ("rightmost")
_SIDES = frozenset({"left", "right", "front", "middle"})
#: possessives that make a thing the speaker's ("my tablet"): no target when the parse names none
_SPEAKERS = frozenset({"my", "our"})
#: words that negate the relation that follows ("not on the table", "isn't in the corner")
_NEGATIONS = {"not", "isn't", "aren't", "isnt", "never", "nowhere"}
#: relations that need a landmark after the cue (the others are read before this set is used)
_LANDMARK_KINDS = {"on", "under", "below", "above", "near", "between", "with"}
#: forms of "stand": a place it takes is the viewer's, said of no one or of the listener
_STANDING = frozenset({"stand", "stands", "standing", "stood"})
#: words before "end" that say which end of a thing's length it is ("the bottom end of the cot": its foot)
_WHICH_END = {"foot": "foot", "feet": "foot", "bottom": "foot", "head": "head", "top": "head"}
#: parts of a thing that a viewer there faces ("at the foot of the cot", "in front of the benches")
_FACING_PARTS = frozenset({"foot", "end", "bottom", "front"})
#: forms of "sit": a place it takes is the viewer's when said of the speaker or the listener, or
#: when it opens the sentence ("Sitting on the settee, ..."; not "the jug sitting on the dresser")
_SITTING = frozenset({"sit", "sits", "sitting", "sat", "seated"})
#: anyone at all, whose place is a viewpoint ("for somebody sat on it"), and the words
#: that make a clause of sitting or standing a condition of the view ("when seated on the settee")
_ANYONE = frozenset({"someone", "somebody", "anyone", "anybody", "person"})
_PEOPLE = _ANYONE | {"i", "you", "u", "ur", "we"}  # whoever may sit or look: anyone, the speaker, the listener
_WHEN = frozenset({"when", "while", "if", "as", "once", "whenever"})
#: forms of "be" and of placing, after which a phrase of being alone says where the thing is ("it's on its own")
_BEING = AUXILIARIES | {"s", "placed", "located"}
#: the subjects of a relative clause that stand for the noun it hangs on ("the bench that is facing ...")
_RELATIVE_PRONOUNS = frozenset({"that", "which", "who"})
#: verbs whose side word says which way the target is turned, not where it is ("facing left")
_TURNED = frozenset({"face", "faces", "facing", "faced", "turned", "turns", "pointing", "points", "pointed", "angled"})
#: verbs after which "at" names what is looked at, not what the target is by
_LOOKING = frozenset({"look", "looking", "looks", "stare", "staring", "point", "pointing", "glance", "facing"})
#: forms of "be" that place a person ("while I'm on the settee"), and of "watch" that say what one faces
_BE = frozenset({"am", "'m", "m", "is", "'s", "are", "'re", "re", "was", "were", "be"})
_WATCHING = frozenset({"watch", "watches", "watching", "watched"})
#: verbs of seeing after which "from" says where the viewer is
_SEEING = frozenset({"seen", "viewed", "looked", "watching"}) | _LOOKING
#: attribute kinds read before a target or landmark noun ("the red chair", "the small lamp")
_LANDMARK_ATTRS = ("color", "material", "size")
SIZE_EXTREMES = {"small": "small", "large": "large", "tall": "tall", "short": "short"}
#: "on" after these verbs states a use, not a place ("where can I work on my computer")
_USE_VERBS = frozenset(read_data("language.json")["use_verbs"])


@dataclass(eq=False)  # one statement of one request, told apart by identity (`_Reader.taken`)
class Relation:
    """One relation the request states of its target."""

    kind: str  # a `_CUES` value, "extreme", "ordinal" or "in" (on a part of the landmark: "the cupboard's top shelf")
    landmarks: list[tuple[str, ...]] = field(default_factory=list)  # one tuple of canonical categories per landmark
    landmark_attrs: list[tuple[tuple[str, str], ...]] = field(default_factory=list)
    #: the words that name each landmark as said ("gas boiler"; none for a stand-in or a room): a map whose labels
    #: lack the landmark's kinds may still name it so in a caption
    landmark_names: list[str] = field(default_factory=list)
    #: extreme: large/small/tall/short/high/low/wide; ordinal: side or "landmark"; middle: "group" for the middle one of
    #: the target's kind, else the room's middle or a landmark's; closest/farthest: "group" for the others of its kind
    value: str = ""
    order: int = 0  # ordinal: 1-based, -1 = last
    landmark_where: str = ""  # "corner" / "middle" / "wall" / a side: which of its instances; "foot" / "head": its end
    negated: bool = False     # "the bowl that is not on the shelf"
    said: bool = False        # extreme: read from a size word on the target ("the little wardrobe"), not "smallest"


@dataclass
class SpatialQuery:
    """A referring expression: its target, the relations stated of it and where it is seen from."""

    target: tuple[str, ...] = ()  # the target's categories (empty: unnamed)
    attrs: tuple[tuple[str, str], ...] = ()  # its colour, material and size words
    relations: list[Relation] = field(default_factory=list)
    facing: tuple[str, ...] = ()  # the viewpoint landmark ("facing the wardrobe")
    viewer_at: tuple[str, ...] = ()  # where the viewer is ("viewed from the settee", "if I sit on the ottoman")
    unknown_target: bool = False  # the target is a noun the lexicon does not know ("the unicorn")
    named: bool = False           # the target kind is named ("the lamp"), not inferred from a function
    modifiers: frozenset[str] = frozenset()  # lemmas of nouns naming the target before it ("the bar seat")

    @property
    def words(self) -> str:
        return " ".join(r.kind if r.kind not in ("extreme", "ordinal") else r.value or r.kind for r in self.relations)


def _side_words(kept: list[tuple[str, int]], text: str) -> list[tuple[str, int]]:
    """(token, offset) pairs of `text` with a side or middle word made superlative ("rightmost",
    "left-most", "middlemost") read as that word."""
    out: list[tuple[str, int]] = []
    for token, at in kept:
        if token == "most" and out and text[at - 1:at] == "-" and _CUES.get((out[-1][0],)) in _SIDES:
            continue
        out.append((token[:-4] if token.endswith("most") and _CUES.get((token[:-4],)) in _SIDES else token, at))
    return out


class _Reader:
    """One pass over a query's tokens: cues become relations, the category phrases after them their landmarks."""

    def __init__(self, text: str):
        self.text = text
        lex = self.lex = load_lexicon()
        self.corrected = corrected = normalise(lex.respell(text))
        self.structure = parse_request(corrected)
        kept = _side_words([(t, at) for t, at in lex.token_offsets(corrected) if t not in lex.words["skip"]
                            or t == "one"], corrected)
        self.toks = toks = [t for t, _ in kept]
        self.offsets = [at for _, at in kept]
        self.words = [self.structure.index_at(at) for _, at in kept]  # each token's parsed word
        self.lemmas = lemmas = lemmatise(lex, toks)
        spans = lex.scan(lemmas, clause_breaks(corrected, kept))
        self.sentence_starts = clause_breaks(corrected, kept, SENTENCE_MARK)
        self.cat_at = {s.start: s for s in spans if s.has("cat") and not (  # "toilet": category and room
            s.end - s.start == 1 and (  # one word that is a verb here: posture after motion ("go sit")
                toks[s.start] in POSTURE_VERBS and s.start > 0 and toks[s.start - 1] in MOTION_VERBS
                # or a participle ("the plant standing by the tv"), not the noun of its lemma
                or toks[s.start].endswith("ing") and lemmas[s.start] != toks[s.start]))}
        self.attr_at = {s.end: s for s in spans if any(k in _LANDMARK_ATTRS for k, _ in s.kinds)}
        self.attr_words = {self.words[i] for s in self.attr_at.values() for i in range(s.start, s.end)}
        rooms = [s for s in spans if s.has("room") and not s.has("cat")]
        self.room_at = {s.end: tuple(("room", r) for r in s.values("room")) for s in rooms}
        #: rooms a target is said to be near ("closest to the den", "the den side"): start -> end
        self.near_rooms = {s.start: s.end for s in rooms if near_room(toks, s.start, s.end, self.cat_at)}
        #: token positions right after a colour, material or shape word ("glass [top]")
        self.part_described = {s.end for s in spans if any(k in ATTRIBUTE_KINDS and k != "size" for k, _ in s.kinds)}
        self.out = SpatialQuery()
        self.last_landmark_end = -1
        self.taken: dict[Relation, list[int]] = {}  # relation -> starts of its landmark spans
        self.pending_ordinal: Relation | None = None
        self.cue_word: int | None = None  # the parsed word of the relation cue being read
        #: start of a category span -> the parsed words of its tokens (`span_words`), the categories it names (`kinds`)
        self.span_words = {j: set(self.words[s.start:s.end]) for j, s in self.cat_at.items()}
        self.kinds = {j: tuple(s.values("cat")) for j, s in self.cat_at.items()}
        #: parsed word -> start of the category span holding its first token (`.get`: None when none holds it)
        self.span_of = {word: next((s for s, span in self.cat_at.items() if span.start <= i < span.end), None)
                        for i, word in reversed(list(enumerate(self.words))) if word is not None}
        #: start of the category span of the target noun the parse names, else of the first span naming what
        #: the shared reading found as the target (None: neither)
        self.target_at = self.span_of.get(self.structure.target)
        if self.target_at is None:
            named = {c for c, w in analyse_query(text).targets.items() if w >= 1.0}
            self.target_at = next((j for j in sorted(self.cat_at) if named.intersection(self.kinds[j])), None)
        self.used: set[int] = set() if self.target_at is None else {self.target_at}  # starts of the spans taken
        self.parts: set[int] = set()  # starts of the landmark spans that name a part of another landmark

    def word(self, i: int) -> Word:
        """The parsed word of token `i` (a blank one for a token outside the parse)."""
        k = self.words[i]
        return self.structure.words[k] if k is not None else Word("", -1, -1, "", "")

    def lower(self, k: int | None) -> str:
        """The lowercase text of the parsed word `k` ("" for None)."""
        return self.structure.words[k].text.lower() if k is not None else ""

    def cue_object(self) -> set[int] | None:
        """Parsed words the current cue governs ("the far side of [the piano]": through the noun the cue modifies;
        not a compound before it: "nearer" taken for a noun); None when they hold no noun or pronoun (or no cue)."""
        st, cue = self.structure, self.noun_of(self.cue_word)
        below = {k for k in range(len(st.words)) if k != cue and st.dominates(cue, k)
                 and (k > self.cue_word or st.words[k].dep != "compound")}
        return below if any(st.words[k].pos in ("NOUN", "PROPN", "PRON") for k in below) else None

    def points_back(self, word: int) -> bool:
        """True when the parsed `word` stands for the target: a pronoun ("its left", "behind it")
        or the target's kind named again ("to the left of the piano", said of the piano)."""
        st, j, at = self.structure, self.span_of.get(word), self.target_at
        if self.lower(word) in BACK_REFERENCES | {"its"}:
            return True
        if j is None or at is None:
            return False
        if j == at:  # "there is a rug under this table", said of the table
            return any(self.lower(d) == "this" for d in st.children(word, "det"))
        return self.kinds[j] == self.kinds[at]

    def of_the_group(self, k: int) -> bool:
        """True when the parsed word `k` stands for the others of the target's kind: a pronoun, a
        number or "the others" ("between them", "between the remaining two", "the middle of the three")."""
        return self.structure.words[k].pos in ("NUM", "PRON") or self.lower(k) in STAND_INS | {"others", "rest"}

    def placed_alone(self, i: int) -> bool:
        """True when the phrase of being alone at token `i` ("on its own", "by itself") is said of a thing where
        it is (on a noun, or a verb of being, standing or sitting), not of a person ("eat on my own") or a doing
        ("they will not dry on their own")."""
        st, owner = self.structure, self.words[i]
        if any(self.lower(k) not in ("its", "their") for k in st.children(self.cue_word, "poss")):
            return False
        head = st.words[st.words[owner].head]
        return head.pos in NOUNS or head.text.lower().lstrip("'") in _STANDING | _SITTING | _BEING

    def noun_of(self, k: int | None) -> int | None:
        """The noun the parsed word `k` modifies, through compounds ("the left-hand [side]"), or `k`."""
        st = self.structure
        while k is not None and st.words[k].dep in ("amod", "compound") and st.words[st.words[k].head].pos in NOUNS:
            k = st.words[k].head
        return k

    def side_of(self) -> bool:
        """True when the side word's noun has an "of": a landmark's side ("the right side of the piano")."""
        k, st = self.noun_of(self.cue_word), self.structure
        of, owner = st.of_phrase(k), self.span_of.get(k)  # "the left stool of the three stools": not a landmark
        return of is not None and (owner is None or not any(
            self.kinds.get(j) == self.kinds[owner] for j in map(self.span_of.get, st.children(of, "pobj"))))

    def located_by_pronoun(self, kind: str) -> bool:
        """Read the relation of `kind` seen from the target when the cue places another thing relative to it, its object
        only pointing back ("there is a hamper [to its left]", "a fruit bowl sits on the sideboard", said of the
        sideboard): the noun the phrase hangs on, or the subject or object of its verb; False when there is none."""
        below, st = self.cue_object(), self.structure
        if kind not in INVERSE_RELATION or below is None or not any(self.points_back(k) for k in below) \
                or any(self.span_of.get(k) is not None and not self.points_back(k) for k in below):
            return False
        k = st.words[self.cue_word].head
        while st.words[k].pos in ("ADP", "ADV") and st.words[k].head != k:
            k = st.words[k].head  # "to [its left]": the phrase's own head
        if st.words[k].pos not in ("NOUN", "PROPN"):
            k = next((c for c in st.children(k, "attr", "nsubj", "dobj") if self.span_of.get(c) is not None), None)
        j = self.span_of.get(k)
        return j is not None and j not in self.used and not self.points_back(k) and self.seen_from_target(kind, j)

    def attrs_before(self, start: int) -> tuple[tuple[str, str], ...]:
        """Attributes of the noun at `start`, read leftwards ("the green upper shelf", "cream-coloured",
        "the grey conference chair": past a noun that modifies it)."""
        found, end = [], start
        passed = _EXTREMES.keys() | self.lex.words["color_suffixes"]  # "the tallest", "cream-coloured"
        while end in self.attr_at or end > 0 and (self.toks[end - 1] in passed or self.word(end - 1).dep == "compound"):
            s = self.attr_at.get(end)  # an attribute ending here, else a word passed over
            found += [(k, v) for k, v in s.kinds if k in _LANDMARK_ATTRS] if s else []
            end = s.start if s else end - 1
        return tuple(found)

    def next_cat(self, pos: int) -> int | None:
        """Start of the first free category span from `pos` within what the current cue governs, before
        an exclusion ("with a chipped rim, not the teapot"); of those, the one that heads the cue's object
        ("on the piano [bench]": not the piano)."""
        below = self.cue_object()  # None: the parse gives the cue no noun, any span may serve
        end = next((k for k in range(pos, len(self.toks)) if self.toks[k] in _NEGATIONS), len(self.lemmas))
        found = [j for j in range(pos, end) if j in self.cat_at and j not in self.used
                 and (below is None or below & self.span_words[j])]
        objects = self.cue_objects() if below is not None else set()
        return next((j for j in found if objects & self.span_words[j]), found[0] if found else None)

    def cue_objects(self) -> set[int]:
        """Parsed words that are the current cue's own objects: its noun objects, those of its
        prepositions ("nearest [to] the fireplace", "the far side [of] the piano") and their conjuncts."""
        st = self.structure
        owners = {self.cue_word, self.noun_of(self.cue_word)}
        owners |= set(st.children(owners, "prep"))
        objects = set(st.children(owners, "pobj", "dobj", "conj", "attr", "npadvmod"))  # ("on the piano [bench]")
        return objects | set(st.children(objects, "conj"))

    def turned_to(self, k: int | None) -> bool:
        """True when the parsed side word `k` is what a verb of turning takes, directly or through
        "to" or "towards" ("facing left", "turned towards the right"; not "facing the crate on the right")."""
        head = self.structure.words[k].head if k is not None else None
        if self.lower(head) in ("to", "towards", "toward"):
            head = self.structure.words[head].head
        return self.lower(head) in _TURNED

    def on_a_plan(self, i: int) -> bool:
        """True when the height word at `i` comes before a side ("the top left corner", "the upper
        right one"): a place on a plan seen from above, not a height."""
        return _EXTREMES.get(self.toks[i], _HEIGHT_NOUNS.get(self.toks[i])) in ("high", "low") \
            and _CUES.get(tuple(self.toks[i + 1:i + 2])) in _SIDES

    def height_word(self, i: int) -> bool:
        """True when token `i` is "top" or "bottom" saying where the target sits in height (not on a plan): a modifier
        of the target's noun ("the bottom drawer") or the object of "on"/"at" with no "of" said of the target ("the cup
        on top"); or "high" or "low" beside "up" or "down" ("the mug up high", "the one low down")."""
        if self.toks[i] in ("high", "low"):
            return bool({"up", "down"} & set(self.toks[max(i - 1, 0):i] + self.toks[i + 1:i + 2]))
        if self.toks[i] not in _HEIGHT_NOUNS or self.words[i] is None or self.on_a_plan(i):
            return False
        st, k, word = self.structure, self.words[i], self.word(i)
        if st.children(k, "amod", "compound") or i in self.part_described:
            return False  # the top itself described ("a glass top table"): a part, not a height
        if word.dep in ("amod", "compound"):  # of the target's noun ("the bottom shelf") or of a part (`parts`)
            return self.target_at is not None and self.span_of.get(word.head) in (self.target_at, *self.parts)
        if word.dep != "pobj" or self.lower(word.head) not in ("on", "at") or st.of_phrase(k) is not None:
            return False
        owner = st.words[word.head].head  # said of the target ("the cup that sits on top"), not
        if st.words[owner].pos in ("VERB", "AUX"):  # of a thing on it ("a radio resting on top")
            subject = next(iter(st.children(owner, "nsubj")), None)
            owner = st.words[owner].head if st.words[owner].dep in ("acl", "relcl") else subject
        return self.said_of_target(owner)

    def said_of_target(self, k: int | None) -> bool:
        """True when the parsed word `k` is the target's noun or points back to it (`points_back`)."""
        return k is not None and (self.span_of.get(k) == self.target_at or self.points_back(k))

    def antecedent(self, objects: set[int]) -> int | None:
        """Start of the category span that a pronoun the cue takes stands for when the cue places the
        target itself ("There's a bookcase in the hall. The vase on top of [it]"): the last one named
        in an earlier sentence, not the target; else None."""
        st = self.structure
        said = [st.words[k].start for k in objects if self.lower(k) in BACK_REFERENCES]
        top = self.cue_word
        while top is not None and st.words[top].pos in ("ADP", "ADV") and st.words[top].head != top:
            top = st.words[top].head  # the word the cue's phrase hangs on
        if not said or top is None or st.target is None or not (  # the cue in the target's phrase, or on the
                st.dominates(st.target, self.cue_word) or st.dominates(top, st.target)):  # verb that takes it
            return None
        opened = max((self.offsets[i] for i in self.sentence_starts if self.offsets[i] <= said[0]), default=-1)
        before = [j for j in self.cat_at if self.offsets[j] < opened and j != self.target_at]
        named = [j for j in before if self.word(self.cat_at[j].end - 1).dep in NAMING]  # not "the west wall" it is by
        return max(named or before, default=None)

    def landmark(self, rel: Relation, pos: int) -> bool:
        """Take the next free category phrase from `pos` as a landmark of `rel`; a "one" the cue
        takes stands for another of the target's kind ("the mug beside the chipped one")."""
        st, objects = self.structure, self.cue_objects()
        objects |= set(st.children(objects, "appos"))  # the apposition the parser hangs "one" on ("the metal [one]"),
        bare = {k for k in objects if k in self.attr_words or st.words[k].pos != "NOUN"}
        objects |= set(st.children(bare, "nummod"))  # or the number ("next to blue [one]", not "one chair")
        one = next((i for i in range(pos, len(self.toks)) if self.toks[i] in ("one", "ones")
                    and self.words[i] in objects), None)
        if one is not None and self.target_at is not None and not set(self.toks[pos:one]) & _NEGATIONS \
                and st.of_phrase(self.words[one]) is None:  # "one of the plates": the plates
            at, end, kinds = one, one + 1, self.kinds[self.target_at]
        elif self.place_for_use(rel, pos):
            return True
        else:
            at = self.next_cat(pos)
            at = self.antecedent(objects) if at is None else at
            if at is None:
                return self.room_landmark(rel, pos)
            self.used.add(at)
            rel.negated = rel.negated or self.words[at] in st.lacking  # "with no lamp on it"
            # a part named with a free whole, not the target ("on the top shelf [of the bookcase]"): in the whole
            of = st.of_phrase(self.words[self.cat_at[at].end - 1])
            whole = next((j for j in map(self.span_of.get, st.children(of, "pobj")) if j is not None), None)
            if whole is not None and whole not in self.used and whole != self.target_at:
                self.parts.add(at)
                at, rel.kind = whole, "in" if rel.kind == "on" else rel.kind
                self.used.add(at)
            self.taken.setdefault(rel, []).append(at)
            end, kinds = self.cat_at[at].end, self.kinds[at]
            if rel.kind == "on" and self.toks[end:end + 1] == ["side"] and end not in self.cat_at:
                rel.kind = "closest"  # "on the radiator side (of the desk)": the side nearest the radiator
            of = st.words[noun].head if (noun := self.noun_of(self.words[at])) is not None else None
            if self.lower(of) == "of":  # "near the foot of the (narrow) cot": that end of it
                rel.landmark_where = self.which_end(st.words[of].head)
        attrs = self.attrs_before(at) + self.room_at.get(at, ())  # with the room before it ("the living room bookcase")
        return self.add_landmark(rel, kinds, attrs, end, "" if at == one else " ".join(self.toks[at:end]))

    def add_landmark(self, rel: Relation, kinds: tuple[str, ...], attrs: tuple, end: int, names: str = "") -> bool:
        """Add to `rel` a landmark of the categories `kinds` (none: a room's objects) described by `attrs` and
        named `names`, its phrase ending before token `end`; True."""
        rel.landmarks.append(kinds)
        rel.landmark_attrs.append(attrs)
        rel.landmark_names.append(names)
        self.last_landmark_end = end
        return True

    def place_for_use(self, rel: Relation, pos: int) -> bool:
        """A place said by what a person does there ("the clock above where I work"): the kinds that serve it, as
        the landmark of `rel`; False when no "where" clause with a pronoun subject and no thing named is at `pos`."""
        st, where = self.structure, self.word(pos) if pos < len(self.toks) else None
        if where is None or self.toks[pos] != "where" or not any(
                st.words[k].pos == "PRON" for k in st.children(where.head, "nsubj")):
            return False
        clause = [j for j in range(pos + 1, len(self.toks)) if self.words[j] is not None
                  and st.dominates(where.head, self.words[j])]
        use = analyse_query(" ".join(self.toks[j] for j in clause))
        kinds = tuple(c for c, w in use.afford.items() if w >= 1.0)
        return bool(kinds) and not use.named and self.add_landmark(rel, kinds, (), clause[-1] + 1)

    def room_landmark(self, rel: Relation, pos: int) -> bool:
        """A room said right after a word of nearness ("the stool closest to the garage") as the
        landmark of a relation of nearness: no category, the room's objects (`landmark_attrs`)."""
        end = next((e for s, e in self.near_rooms.items() if pos <= s <= pos + 1), None)  # where the room's name ends
        return end is not None and rel.kind in ("near", "closest", "farthest") \
            and self.add_landmark(rel, (), self.room_at[end], end)

    def named_side(self, i: int) -> int:
        """The position after the category or room phrase at `i`; a phrase other than the target's that
        names a side ("the radiator side one", "on the porch side") is a landmark the target is closest to."""
        span = self.cat_at.get(i)
        end = span.end if span is not None else self.near_rooms[i]
        if self.toks[end:end + 1] != ["side"] or end in self.cat_at or i == self.target_at or i in self.used:
            return end
        rel, self.cue_word = Relation("closest"), None  # (no cue: the phrase at `i` is the landmark)
        self.out.relations.append(rel)
        return end + (self.landmark(rel, i) if span is not None else self.room_landmark(rel, i))

    def read(self) -> SpatialQuery:
        """The relations of the query, then its target."""
        i, negated = 0, set()  # indices of relations that follow a negation word
        toks, out = self.toks, self.out
        while i < len(self.lemmas):
            if i in self.sentence_starts or i and self.words[i - 1] is None and self.words[i] is not None:
                negated = {k for k in negated if k < len(out.relations)}  # past "Not the kettle:", "Not that one."
            if toks[i] in _NEGATIONS:
                negated.add(len(out.relations))
                i += 1
            elif i in self.cat_at or i in self.near_rooms:  # never a cue ("first aid kit", "corner shelf")
                i = self.named_side(i)
            elif (toks[i] in _EXTREMES and not self.on_a_plan(i)) or self.height_word(i):
                value = _EXTREMES.get(toks[i]) or _HEIGHT_NOUNS.get(toks[i], toks[i])  # ("high", "low": themselves)
                out.relations.append(Relation("extreme", value=value))
                i += 1
            elif toks[i] in _ORDINALS:
                self.pending_ordinal = Relation("ordinal", order=_ORDINALS[toks[i]], value="left")
                out.relations.append(self.pending_ordinal)
                i += 1
            else:
                i = self.cue(i)
        for rel in (out.relations[k] for k in negated if k < len(out.relations)):
            rel.negated = True
        self.seated_viewer()
        return self.target()

    def seated_viewer(self) -> None:
        """Where a person said to sit (or to be) is, when no cue placed the viewer: the seat the sitting or
        being takes ("while I'm on the settee"), no longer a place of the target; else the seat a side of the
        target is told from ("the speaker left of the daybed when you sit"). And what the viewer watches, when
        nothing is faced ("as I sit watching the television")."""
        st, out, seats = self.structure, self.out, self.lex.generic.get("seat", {})

        def placed(k: int) -> bool:  # a person sits or is there: not a thing ("the pot sitting on the desk")
            subjects = st.children(k, "nsubj", "nsubjpass")
            if subjects:
                return all(self.lower(n) in _PEOPLE for n in subjects) and self.lower(k) in _SITTING | _BE
            said_of = st.words[k].head if st.words[k].dep in ("acl", "amod", "relcl") else None  # ("anybody seated")
            return self.lower(k) in _SITTING and (said_of is None or self.lower(said_of) in _PEOPLE)

        def placed_by(rel: Relation) -> int | None:  # the verb the relation's landmark phrase hangs on
            noun = self.noun_of(self.words[self.taken[rel][0]]) if self.taken.get(rel) else None
            prep = st.words[noun].head if noun is not None and st.words[noun].dep == "pobj" else None
            return st.words[prep].head if prep is not None else None

        def to_a_seat(rel: Relation) -> bool:  # its one landmark is a thing to sit on (a bed too)
            return len(rel.landmarks) == 1 and any(seats.get(c, 0.0) >= 0.5 for c in rel.landmarks[0])

        held = None if out.viewer_at else next((r for r in out.relations if r.kind in ("on", "in", "near") and to_a_seat(r)
                                                 and (k := placed_by(r)) is not None and placed(k)), None)
        if held is not None:
            out.viewer_at = held.landmarks[0]
            out.relations.remove(held)
        elif not out.viewer_at and any(self.lower(k) in _SITTING and placed(k) for k in range(len(st.words))):
            told = next((r for r in out.relations if r.kind in ("left", "right") and to_a_seat(r)), None)
            out.viewer_at = told.landmarks[0] if told is not None else ()
        if out.viewer_at and not out.facing:  # (the lexicon reads watching a screen as a use: its noun read alone)
            watched = {o for k, w in enumerate(st.words) if w.text.lower() in _WATCHING for o in st.children(k, "dobj")}
            out.facing = next((tuple(span.values("cat")) for i, k in enumerate(self.words) if k in watched
                               for span in self.lex.scan(self.lemmas[i:i + 1]) if span.has("cat")), ())

    def cue(self, i: int) -> int:
        """Read the relation cue at `i` (if any); the position after it."""
        toks = self.toks
        cue = max(((c, k) for c, k in _CUES.items() if c[0] == toks[i] and tuple(toks[i:i + len(c)]) == c),
                  key=lambda ck: len(ck[0]), default=None)  # the longest cue here (the first of equals)
        if cue is None:
            return i + 1
        words, kind = cue
        end = i + len(words)
        self.cue_word = self.words[end - 1]
        stranded = kind in INVERSE_RELATION and is_stranded(toks, end, clause_final_words(self.text))
        if (self.word(end - 1).dep == "prt" and not stranded  # "switch on the lamp": a particle of the verb
                # (but "pick the one across [from] the sofa": a cue's last word with its object is a cue)
                or self.word(end - 1).dep == "agent" and not any(  # "watched by somebody", "painted by my aunt": who did it
                    self.span_of.get(k) is not None or self.lower(k) in ("one", "ones")  # (not "framed by the ones")
                    for k in self.structure.children(self.cue_word, "pobj"))
                or kind in ("left", "right") and self.turned_to(self.cue_word)  # "facing left": turned
                or words == ("face",) and self.word(i).pos != "VERB"  # "the clock face": a noun
                or words == ("at",) and not self.beside(self.words[i])):
            return end
        if kind != "facing" and self.viewer_place():  # "when standing by the door, ...": where the viewer is
            self.viewer_landmark(Relation(kind), end)  # its noun is no target
            return end
        if is_destination(toks, i, len(words)) or stranded and self.inverse(i, kind):
            return end  # "head over to", "stop by": where to go; or a relative clause read (`inverse`)
        return self.relation(end, words, kind)

    def inverse(self, i: int, kind: str) -> bool:
        """A relative clause's stranded preposition ("the cabinet the printer sits on"): its noun is
        the landmark, the relation seen from the target; False when the clause has no such noun."""
        j = clause_landmark(self.cat_at, self.toks, i)
        owner = next((r for r in self.out.relations if j in self.taken.get(r, ())), None)
        if j is None or (j in self.used and (owner is None or owner.kind != "with")):
            return False
        if owner is not None:  # "with a lamp next to it": one fact, the clause says which way
            self.out.relations.remove(owner)
            self.used.discard(j)
        return self.seen_from_target(kind, j)

    def seen_from_target(self, kind: str, j: int) -> bool:
        """Add the relation of `kind` seen from the target (`INVERSE_RELATION`), to the category span
        at `j` as its landmark (which comes before the cue, or is what the cue places); True."""
        rel = Relation(INVERSE_RELATION[kind])
        self.cue_word = None
        self.landmark(rel, j)
        self.out.relations.append(rel)
        return True

    def relation(self, i: int, words: tuple[str, ...], kind: str) -> int:
        """Read the relation of `kind` whose cue `words` ends before `i`; the position after it."""
        toks, out, st, cue = self.toks, self.out, self.structure, self.word(i - 1)  # (the cue's last word)
        nxt = toks[i] if i < len(toks) else ""
        before = i - len(words) - 1  # the word before the cue
        side_noun = (nxt in ("left", "right") or _CUES.get((nxt,)) in COMPASS) \
            and self.span_of.get(self.noun_of(self.words[i])) is None
        if kind == "on" and (side_noun or (before >= 0 and toks[before] in _USE_VERBS)):
            return i  # "on the left": the side word is the relation; "to sit on": a use, not a place
        if kind == "with" and cue.pos in ("VERB", "AUX"):  # a verb of having ("the desk that holds a lamp")
            return self.had(i, nxt) if cue.pos == "VERB" else i
        if kind != "facing" and any(st.words[k].pos == "PRON" for k in st.children(self.cue_word, "nsubj")):
            return i  # "the mug I left there": a cue with a pronoun subject
        if kind in ("on", "wall") and nxt in ("wall", "walls"):
            out.relations.append(Relation("wall"))
            return i + 1
        if kind == "from":
            return self.ordinal_from(i, nxt)
        if kind == "alone":  # "the desk on its own", "the lone stool": apart from the others of its kind
            if cue.dep in ("amod", "compound") and cue.head != st.target:  # "on its own shelf", "by the lone fern"
                return self.landmark_relation(i, _CUES[words[:1]], nxt) if len(words) > 1 else i
            if len(words) == 1 or self.placed_alone(i - len(words)):
                out.relations.append(Relation("farthest", value="group"))
            return i
        if words == ("without",) and (not st.children(self.cue_word, "pobj") or cue.head != st.target
                                      and st.words[cue.head].pos not in ("VERB", "AUX")):
            return i  # "without opening my laptop": not done; "the mirror over the sink without the soap": the sink's
        if kind == "facing":
            return self.facing(i)
        if kind == "corner" and before >= 0 and _CUES.get((toks[before],)) in COMPASS:
            return i  # "the south-east corner of the workbench": a side of it, which the compass word says
        if kind in ("corner", "middle") and nxt == "of":
            return self.place_of(i, kind)
        if kind == "right" and nxt != "of" and i < len(toks) and self.cue_word is not None and (
                self.word(i).pos == "ADP" and cue.dep != "pobj"
                or cue.dep == "advmod" and self.word(i).dep != "pobj" and cue.head == self.words[i]):
            return i  # "right under the basin", "right alongside it": an intensifier, not a side
        if kind in ("corner", "middle", "wall") and before >= 0 and self.last_landmark_end == before \
                and toks[before] in ("in", "at"):
            out.relations[-1].landmark_where = kind  # "near the fern in the corner": the plant's place
            return i
        if kind == "middle":  # "the middle one", "it sits at the centre": of the target's kind, unless it is
            if not self.says_which_landmark(kind):  # the landmark's ("by the middle window")
                out.relations.append(Relation(kind, value="group"))
            return i
        return self.landmark_relation(i, kind, nxt)

    def had(self, i: int, nxt: str) -> int:
        """A verb of having whose cue ends before `i` said of the target (its relative clause or participle, or the
        target as subject): a "with" relation to what it has; not said of the speaker ("I have a spare key") or of
        another thing, nor when a phrase in its clause points back ("it has a lamp to its left": that phrase says
        where, `located_by_pronoun`). The position after it."""
        st, cue = self.structure, self.word(i - 1)
        holder = cue.head if cue.dep in ("relcl", "acl") else next(iter(st.children(self.cue_word, "nsubj")), None)
        if self.target_at is None or not self.said_of_target(holder):
            return i
        if any(k > self.cue_word and st.dominates(self.cue_word, k) and self.lower(k) in BACK_REFERENCES | {"its"}
               for k in range(len(st.words))):
            return i
        return self.landmark_relation(i, "with", nxt)

    def facing(self, i: int) -> int:
        """The viewpoint of a cue ending before `i` ("facing the wardrobe"). When the parse's target lies in a
        viewpoint clause a comma or colon closes ("facing the window, the shelf on the left"), the target is the
        first free category after that mark that no preposition or verb takes; with none ("facing the
        stools, the one on the left"), of the clause noun's kind."""
        at, st = self.target_at, self.structure
        if self.turned_target():  # "it is facing the desk", "the bench that is facing the piano": near what it faces
            found = len(self.out.relations)
            i = self.landmark_relation(i, "near", self.toks[i] if i < len(self.toks) else "")
            if len(self.out.relations) > found and st.children(self.cue_word, "neg"):
                self.out.relations[-1].negated = True  # "the window that is not facing the tables"
            return i
        ends = [k for k in (self.corrected.find(c, self.offsets[i - 1]) for c in ",:;") if k >= 0]
        end = -1 if at is None or at < i or not ends else min(ends)  # where the clause ends
        if end >= 0 and self.offsets[at] < end:
            after = next((j for j in sorted(self.cat_at) if j not in self.used and self.offsets[j] > end
                          and self.words[j] is not None
                          and st.words[self.noun_of(self.words[j])].dep not in ("pobj", "dobj")), None)
            if after is not None:
                self.out.facing, self.target_at = self.kinds[at], after
                self.used.add(after)
        elif (j := self.next_cat(i)) is not None:
            self.used.add(j)
            self.out.facing = self.kinds[j]
        return i

    def turned_target(self) -> bool:
        """True when the facing cue says which way the target is turned: its subject is the target or points
        back to it ("it is facing ..."), or it is a relative clause on the target with no subject of its own
        but the relative pronoun ("the bench that is facing ...") or a participle on it in a request that says
        no side; not the viewer's ("when you face ...", "the left stool, facing the window": where one looks from)."""
        st = self.structure
        if self.cue_word is None or self.target_at is None:
            return False
        cue, subject = st.words[self.cue_word], next(iter(st.children(self.cue_word, "nsubj")), None)
        if cue.dep == "relcl" and (subject is None or self.lower(subject) in _RELATIVE_PRONOUNS) or (
                cue.dep == "acl" and not self.sided()):  # "the bench facing the sofa"; not "the left one facing ..."
            subject = cue.head
        return self.said_of_target(subject)

    def sided(self) -> bool:
        """True when the request says a side ("left", "right"), which needs a viewpoint to be read from."""
        return any(_CUES.get((token,)) in ("left", "right") for token in self.toks)

    def viewer_place(self) -> bool:
        """True when the cue word places the one who looks, not the target: it hangs on "stand"
        said of no one or of the listener ("when standing by the door", "if you stand by the oven"),
        on "sit" so said in a condition ("when seated on the settee"), or on either said of anyone."""
        st, k = self.structure, self.cue_word
        if k is not None and st.words[k].dep == "pobj":
            k = st.words[k].head  # "at [the centre] of the hall": through its preposition
        if k is not None and st.words[k].pos == "ADP":
            k = st.words[k].head
        verb = self.lower(k)
        if verb not in _STANDING | _SITTING:
            return False
        subjects, word = st.children(k, "nsubj", "nsubjpass"), st.words[k]
        if word.dep == "acl" and self.lower(word.head) in _ANYONE:  # "for a person sat on the daybed"
            return True
        when = any(self.lower(n) in _WHEN for n in st.children(k, "advmod", "mark"))  # "when seated on the settee"
        return all(self.lower(n) in _ANYONE | {"you", "i", "we"} for n in subjects) and (bool(subjects) or (
            word.dep in ("advcl", "ROOT") and (verb in _STANDING or when or self.opens_clause(k))))

    def opens_clause(self, k: int) -> bool:
        """True when the parsed word `k` opens the request or a clause after punctuation."""
        return k == 0 or self.structure.words[k - 1].text in (",", ".", ";", ":")

    def place_of(self, i: int, kind: str) -> int:
        """"the middle of X", "the corner of X": relative to the object X; the middle one of the
        target's own kind ("of the three vases", "of the three"); the room's middle or corner when X is no object
        (a room named after "of" is read for itself, so a clause on it keeps its own relation)."""
        rel, objects, st = Relation(kind), self.cue_objects(), self.structure
        objects |= {o for k in objects if self.span_of.get(k) is None for p in st.children(k, "prep")
                    if self.lower(p) == "of" for o in st.children(p, "pobj")}  # "a row of vases"
        if kind == "middle" and any(self.points_back(k) or self.of_the_group(k) for k in objects):
            rel.value = "group"
        elif any(self.span_of.get(k) is not None for k in objects):
            self.landmark(rel, i)
        self.out.relations.append(rel)
        return i

    def says_which_landmark(self, kind: str) -> bool:
        """True when the cue word is on a landmark's noun, not the target's ("on the left bench",
        "by the middle window"): it says which of the landmark's instances (`landmark_where`)."""
        noun = self.noun_of(self.cue_word)
        owner = self.span_of.get(noun)
        if owner is None or owner == self.target_at or self.target_at is None or self.points_back(noun):
            return False  # on the target's own noun or its kind named again ("facing the vases, the left vase")
        described = next((r for r in self.out.relations if owner in self.taken.get(r, ())), None)
        if described is not None and not described.landmark_where:
            described.landmark_where = kind
        return True

    def viewer_landmark(self, rel: Relation, pos: int) -> None:
        """Take the landmark at `pos` as where the viewer is ("viewed from the settee") when the cue
        takes it; at its front, foot or end, as what the viewer faces ("standing at the cot's foot")."""
        objects = self.cue_objects()
        if any(self.lower(k) in BACK_REFERENCES for k in objects):  # "sat on it": the thing just named
            named = next((r.landmarks[0] for r in reversed(self.out.relations) if r.landmarks), None)
            if named is not None and not self.out.facing and not self.out.viewer_at:
                self.out.viewer_at = named
            return
        if not self.landmark(rel, pos) or self.out.facing:
            return
        j = self.taken[rel][-1]
        part = any(self.lower(k) in _FACING_PARTS for k in objects | {self.cue_word})
        if part or objects & self.span_words[j]:  # an object the cue takes (not "at the centre of the hall, ...")
            setattr(self.out, "facing" if part else "viewer_at", self.kinds[j])

    def ordinal_from(self, i: int, nxt: str) -> int:
        """"from" after an ordinal ("the second from the left", "third from the door"); with no
        ordinal, after a verb of seeing or opening a clause, where the viewer is ("seen from the
        settee", "From the pantry arch, ..."; not "a pipe runs from the boiler to the sink")."""
        if self.pending_ordinal is None:
            st, k = self.structure, self.cue_word
            if k is not None and (self.lower(st.words[k].head) in _SEEING or self.opens_clause(k)):
                self.viewer_landmark(Relation("from"), i)
        elif nxt in ("left", "right"):
            self.pending_ordinal.value = nxt
            return i + 1
        elif self.landmark(self.pending_ordinal, i):
            self.pending_ordinal.value = "landmark"
        return i

    def which_end(self, k: int | None) -> str:
        """The end of a thing's length the parsed noun `k` names: "foot" or "head" ("the foot of", and "the
        foot end", "the bottom end" of it: its foot; "the top end": its head); "" for none (nor for an end
        told by no such word: "the end of the bench", "the near end")."""
        noun = self.lower(k)
        if noun in ("foot", "head"):
            return noun
        said = [self.lower(c) for c in self.structure.children(k, "amod", "compound")]
        return _WHICH_END.get(said[0], "") if noun == "end" and len(said) == 1 else ""

    def beside(self, at: int | None) -> bool:
        """True when "at" places the target by a thing ("the chair at the desk"): its object is a
        category itself, or the foot or head of one ("at the head of the cot", "at the bottom end of the cot":
        that end, `landmark`), not another part of one ("at one end of the workbench") or a place looked at."""
        st = self.structure
        return at is not None and self.lower(st.words[at].head) not in _LOOKING and any(
            self.span_of.get(k) is not None or self.which_end(k) and any(
                self.span_of.get(g) is not None for g in st.children(st.of_phrase(k), "pobj"))
            for k in st.children(at, "pobj"))

    def landmark_relation(self, i: int, kind: str, nxt: str) -> int:
        """Sides, opposites, nearest/farthest and the relations that need a landmark after them."""
        toks, rel, st = self.toks, Relation(kind), self.structure
        if kind in ("left", "right", "front", "behind") or kind in COMPASS:
            if not self.side_of() and self.says_which_landmark(kind) or self.located_by_pronoun(kind):
                return i
            if nxt == "of" or self.side_of() or (kind == "behind" and self.structure.children(self.cue_word, "pobj")):
                self.landmark(rel, i)  # "left of my bed", "behind a sofa"
        elif kind == "opposite":  # "across the desk from the grey stool": two landmarks, else one
            frm = next((j for j in range(i, len(toks)) if toks[j] == "from"), None)
            if self.landmark(rel, i) and frm is not None:
                self.cue_word = self.words[frm]
                i = self.last_landmark_end if self.landmark(rel, frm) else i
        elif kind in ("closest", "farthest"):
            anchor = next((j for j in range(i, len(toks)) if toks[j] in ("to", "from")), None)
            if (anchor is None or not self.landmark(rel, anchor)) and not self.landmark(rel, i) and any(
                    st.words[k].pos == "NUM" or self.lower(k) in ("others", "rest", "ones")
                    for k in self.cue_objects()):
                rel.value = "group"  # "furthest from the other two": from the others of its kind
        elif kind == "between" and any(self.of_the_group(k) for k in self.cue_objects()):
            rel = Relation("middle", value="group")  # "the bookcase in between them": the middle one of its kind
        elif self.located_by_pronoun(kind):
            return i
        elif kind in _LANDMARK_KINDS:  # "with a cracked top", "silver on its frame": a part of the target
            j = self.next_cat(i)
            if j is not None and set(self.lemmas[j:self.cat_at[j].end]) <= self.lex.words["weak_heads"]:
                self.used.add(j)
                return i
            if not self.landmark(rel, i):
                return i  # "the one on top", "over there", a landmark we cannot read: nothing to relate to
            if kind == "between":
                self.landmark(rel, i)
        self.out.relations.append(rel)
        return i

    def target(self) -> SpatialQuery:
        """The target is the first category left, unless it only says what the target is for
        ("the cloth for the glasses"): then there is no named target."""
        toks, out, taken, info = self.toks, self.out, self.taken, analyse_query(self.text)
        target = self.target_at if self.target_at is not None else next(
            (j for j in sorted(self.cat_at) if j not in self.used and self.words[j] is not None
             and self.words[j] not in self.structure.lacking  # nor what the request rules out
             # nor a thing of the speaker's ("my tablet is flat", "our old rug")
             and not any(self.lower(p) in _SPEAKERS for p in self.structure.children(self.words[j], "poss"))
             and not set(self.kinds[j]) <= info.excluded_targets), None)
        if target is not None and target > 0 and toks[target - 1] == "for":
            target = None
        if target is None and not info.unknown_target and not TARGET_PRONOUNS & set(toks) and out.relations:
            # a relation needs a target and a distinct landmark: when the only thing named was read as
            # a landmark ("the nearest sofa", "next to the bed"), it is the target, and no relation is left
            first = next((r for r in out.relations if taken.get(r)), None)
            if first is not None:
                target = taken[first][0]
                out.relations = [r for r in out.relations if r is not first]
                if not any(taken.get(r) for r in out.relations):
                    out.relations = [r for r in out.relations if r.kind in ("extreme", "ordinal")]
        # a relation to a landmark the request does not name ("the nearest sofa") says nothing
        out.relations = [r for r in out.relations
                         if r.landmarks or r.value or r.kind not in _LANDMARK_KINDS | {"closest", "farthest", "opposite"}]
        if target is not None:
            out.named = True
            out.target = self.kinds[target]
            out.relations = [r for r in out.relations if not (r.kind == "with" and r.landmarks and all(
                set(mark) & set(out.target) for mark in r.landmarks))]  # "the couch with a sofa bed": a part of it
            one = next((i for i, k in enumerate(self.words) if k is not None and k == self.structure.target), None)
            if one is not None and self.words[target] is None:  # its kind named only in the part ruled out: read the
                one = next((k for k in range(one, len(toks)) if toks[k] == "one"), one)  # kept "one", not "oak" of "the short oak one"
            # "Not the red mug, the blue one", "the blue one, not the red mug": blue
            stand_in = one is not None and self.toks[one] == "one" and (
                self.words[target] is None or _NEGATIONS.intersection(toks[one:target]))
            out.attrs = self.attrs_before(one if stand_in else target)
            start = target  # the lemmas of the nouns that modify it from its left ("the bar seat": bar)
            while start > 0 and self.word(start - 1).dep == "compound":
                start -= 1
            out.modifiers = frozenset(self.lemmas[k] for k in range(start, target)
                                      if not any(s.start <= k < s.end for s in self.attr_at.values()))
        elif info.afford:  # "the seat nearest the radio", "something to brighten the hallway": what serves
            out.target = tuple(c for c, w in info.afford.items() if w >= 1.0)
        elif info.unknown_target:
            out.unknown_target = True
        # a size word on the target ranks within the relation ("the small vase on the dresser"), or on its own
        sizes = [SIZE_EXTREMES[v] for k, v in out.attrs if k == "size" and v in SIZE_EXTREMES]
        if sizes and not any(r.kind == "extreme" for r in out.relations) and (
                out.relations or self.size_alone(out, info, target)):
            out.relations += [Relation("extreme", value=v, said=True) for v in sizes]
        return out

    def size_alone(self, out: SpatialQuery, info: QueryInfo, target: int | None) -> bool:
        """A size word compares the target with the others of its kind when it is all a definite request
        says of a kind named by its own noun ("the little wardrobe"); not when it is one detail of a
        description ("the short green vase") or says what kind of thing will do ("a tall stool")."""
        return (out.named and not self.lex.generic.keys() & set(out.target) and all(s.kind == "size" for s in info.slots)
                and any(w.head == self.words[target] and w.dep == "det" and w.text.lower() in ("the", "this", "that")
                        for w in self.structure.words))


@lru_cache(maxsize=4096)
def parse_query(text: str) -> SpatialQuery:
    """The spatial reading of `text` (no relations when it states none). Memoised and shared by
    retrieval's choice of experts, the gate and the spatial expert: no caller may change it."""
    return _Reader(text).read()
