"""Relative clauses whose preposition has no object of its own ("the cabinet the printer sits on", "the sink with the
mirror above it", "the one the calendar hangs over"): the noun inside the clause is the landmark, the noun before it the
target, and the relation points from the landmark to the target. Shared by the query reading (`query`: where the target
phrase ends) and the spatial reading (`spatial`: which noun is the landmark and which way the relation goes)."""

from __future__ import annotations

import re
from functools import lru_cache
from collections.abc import Collection

from ..lexicon import Span, read_data

#: pronouns that stand for the target inside its own relative clause ("... with a lamp next to it")
BACK_REFERENCES = frozenset({"it", "them", "itself", "themselves"})
#: prepositions a relative clause can leave at its end ("the shelf the vase stands on")
STRANDABLE = frozenset(read_data("language.json")["strandable"])
#: nouns standing for an unnamed target ("the one by the door", "the thing on the shelf")
TARGET_PRONOUNS = frozenset({"one", "ones", "thing", "things", "something", "object", "item", "stuff", "whatever"})
#: nouns inside multi-word relations ("on top of", "to the left of", "next to", "close to")
RELATION_NOUNS = frozenset({"top", "bottom", "side", "left", "right", "front", "back", "next", "close", "near"})
#: the relation seen from the target: the printer is on the cabinet, so the cabinet is what the
#: printer rests on ("with"); the clock is above the window, so the window is below the clock
INVERSE_RELATION = {"on": "with", "under": "above", "below": "above", "above": "below", "near": "near",
                    "left": "right", "right": "left", "front": "behind", "behind": "front", "opposite": "opposite"}

#: words between a clause's noun and its preposition that are not verb forms ("is", "has been", "right above", "hung")
AUXILIARIES = frozenset(read_data("language.json")["auxiliaries"])
_CLAUSE_END = re.compile(r"([\w'-]+)\s*(?:[.,;:!?()]|\s[-\u2013\u2014]\s|$)")
#: words of nearness after which a room is a place the target is near, not the room it is in
NEARNESS = frozenset(read_data("language.json")["nearness"])


def near_room(words: list[str], start: int, end: int, named: Collection[int]) -> bool:
    """True when the room named by `words[start:end]` follows a word of nearness, past "to" or "from" ("the stool
    closest to the garage", "far from the study"), or names a side ("on the study side"; not a kind named from `end`,
    one of the starts in `named`: "the study side table"): a place to be near, not the target's room."""
    k = start - 1
    while k >= 0 and words[k] in ("to", "from"):
        k -= 1
    return k >= 0 and words[k] in NEARNESS or words[end:end + 1] == ["side"] and end not in named


@lru_cache(maxsize=4096)  # (asked at every stranded preposition and relation cue of a reading)
def clause_final_words(text: str) -> frozenset[str]:
    """Lowercase words that end a clause of `text` (followed by punctuation, a dash or the end)."""
    return frozenset(m.group(1).lower() for m in _CLAUSE_END.finditer(text))


def is_stranded(toks: list[str], end: int, finals: frozenset[str]) -> bool:
    """True when the preposition ending at `toks[end - 1]` has no object: the clause ends there or a
    pronoun for the target follows ("on it", "to the left of it")."""
    if toks[end - 1] in ("left", "right", "front"):
        if end >= len(toks) or toks[end] != "of":  # a side word is a noun then ("the lamp on the right")
            return False
        end += 1  # "to the left of it"
    return end >= len(toks) or toks[end] in BACK_REFERENCES or toks[end - 1] in finals


def clause_landmark(categories: dict[int, Span], toks: list[str], cue_start: int) -> int | None:
    """Start of the category phrase a stranded preposition at `toks[cue_start]` relates to: the last one before it,
    past verb forms only (auxiliaries, "sits", "mounted"), when a target comes before that phrase (another category
    phrase, or "the one"). `categories` maps token starts to spans."""
    while cue_start > 0 and (toks[cue_start - 1] in STRANDABLE or toks[cue_start - 1] in RELATION_NOUNS):
        cue_start -= 1  # the relation's first word: "on top of", "to the left of", "next to"
    before = sorted(s for s, span in categories.items() if span.end <= cue_start)
    last = before[-1] if before else None
    if last is None or not all(
            w in AUXILIARIES or w.endswith(("ed", "ing")) or (w.endswith("s") and not w.endswith("ss"))
            for w in toks[categories[last].end:cue_start]):
        return None  # "the cushion with the pattern on it": the clause's noun is another word
    return last if len(before) > 1 or TARGET_PRONOUNS.intersection(toks[:last]) else None
