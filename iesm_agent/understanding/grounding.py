"""Words the lexicon does not know, grounded in the map: a target or room phrase that matches
no lexicon entry ("the gizmo", "in the scullery") is read as the map label or room it misspells,
else mapped with the sentence encoder to the nearest label or room among the candidates."""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Any

import numpy as np

from .labels import label_concepts
from .text import stem
from ..lexicon import load_lexicon
from .query import QueryInfo, functional_kin

#: cosine similarity (all-MiniLM-L6-v2) a map label or room must reach to stand for an unknown
#: phrase, and its lead over the runner-up (single words embed loosely: "washroom" is as near to
#: "bedroom" as to "living room", so a near tie grounds nothing)
MIN_SIMILARITY = 0.45
MIN_MARGIN = 0.05
_CACHE_SIZE = 4096
_grounded: dict[tuple, QueryInfo] = {}


def ground_query(info: QueryInfo, rooms: Sequence[str], labels: Sequence[str], encoder: Any) -> QueryInfo:
    """`info` with its unknown target phrase read as the map label it misspells, else as the
    categories of the nearest of `labels` (`_nearest`), and its unknown room phrase likewise as one
    of `rooms` (the strings the candidates carry); `info` itself when nothing is near enough."""
    if not (info.unknown_target or info.unknown_room):
        return info
    rooms, labels = tuple(sorted(set(rooms))), tuple(sorted(set(labels)))
    key = (info.text, rooms, labels, getattr(encoder, "name", None))
    if (hit := _grounded.get(key)) is not None:
        return hit
    targets, found_rooms, overlap = dict(info.targets), dict(info.rooms), info.overlap
    if info.unknown_target:
        label = _misspelt_label(info.unknown_target, labels)
        if label is not None:  # its words count as the query's, whatever the lexicon makes of them
            overlap = overlap | {stem(w) for w in load_lexicon().tokens(label) if len(w) > 2}
        else:
            label = _nearest(encoder, info.unknown_target, labels)
        targets.update({c: 1.0 for c in label_kinds(label)})
    if info.unknown_room and (room := map_word(info.unknown_room, rooms, encoder)) is not None:
        found_rooms[room] = 1.0
    named, placed = (targets, overlap) != (info.targets, info.overlap), found_rooms != info.rooms
    grounded = info if not (named or placed) else dataclasses.replace(
        info, targets=targets, rooms=found_rooms, overlap=overlap,
        kin=functional_kin(load_lexicon(), [c for c, w in targets.items() if w >= 1.0]),
        target_phrase=info.target_phrase or (info.unknown_target if named else None),
        room_phrase=info.room_phrase or (info.unknown_room if placed else None))
    if len(_grounded) >= _CACHE_SIZE:
        _grounded.clear()
    _grounded[key] = grounded
    return grounded


def map_word(phrase: str, options: Sequence[str], encoder: Any) -> str | None:
    """The one of `options` (map labels or rooms) `phrase` misspells, else the nearest by the
    encoder (`_nearest`); None when neither is sure."""
    return _misspelt_label(phrase, options) or _nearest(encoder, phrase, options)


def label_kinds(label: str | None) -> tuple[str, ...]:
    """The categories a map label stands for most (none for None)."""
    concepts = label_concepts(label) if label is not None else ()
    return tuple(c for c, w in concepts if w >= concepts[0][1])


def _misspelt_label(phrase: str, options: Sequence[str]) -> str | None:
    """The one option holding a word that a word of `phrase` misspells ("the gizmoo" and a map
    label "gizmo": one letter doubled), by the lexicon's spelling rules; None otherwise."""
    lex = load_lexicon()
    words = {w: option for option in options for w in lex.tokens(option) if w.isalpha() and len(w) >= 4}
    known = frozenset(words)
    found = {words[fixed] for token in lex.tokens(phrase) if token.isalpha() and len(token) >= 4
             and (fixed := lex.closest(token, known)) != token}
    return found.pop() if len(found) == 1 else None


def _nearest(encoder: Any, phrase: str, options: Sequence[str]) -> str | None:
    """The option nearest to `phrase` by cosine; None without an encoder or options, or when the
    best is below MIN_SIMILARITY or within MIN_MARGIN of the runner-up."""
    if encoder is None or not options:
        return None
    known, asked = (np.asarray(encoder.encode(list(texts)), np.float32) for texts in (options, [phrase]))
    sims = known @ asked[0]  # cosines: the encoder's vectors are of unit length (and memoised)
    order = np.argsort(-sims)
    best = float(sims[order[0]])
    runner_up = float(sims[order[1]]) if len(order) > 1 else -1.0
    return options[int(order[0])] if best >= MIN_SIMILARITY and best - runner_up >= MIN_MARGIN else None
