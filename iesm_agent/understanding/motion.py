"""Verbs of motion and their particles: the grammar that tells "head over to the sofa" (where to
go: the sofa is the target) from "the picture over the sofa" (a relation). Shared by the query
reading (`query`) and the spatial reading (`spatial`)."""

from __future__ import annotations

from ..lexicon import read_data

#: verbs of motion: a particle or preposition right after one (optionally after its object: "take
#: me over to") says where to go, not where the target is ("head over to", "stop by", "pull up to")
MOTION_VERBS = frozenset(read_data("language.json")["motion_verbs"])
#: verbs of posture that chain after a motion verb ("go stand next to", "come sit by"): verbs there,
#: never the category nouns they spell ("stand") nor the function asked for ("sit")
POSTURE_VERBS = frozenset({"stand", "sit", "wait", "park", "stay", "hover", "look", "hang", "settle"})
#: words a motion verb used as a verb follows (or it starts the query): "can you nip over",
#: "please swing by"; after anything else it is a noun ("rest my head on")
VERB_OPENERS = frozenset(read_data("language.json")["verb_openers"])
#: words between a motion verb and its particle ("take me over to", "make your way over to")
MOTION_OBJECTS = frozenset(read_data("language.json")["motion_objects"])
#: particles of motion: "over to", "up to", "round to", "across to", "by" after a motion verb
PARTICLES = frozenset(read_data("language.json")["particles"])
#: particles that name a path, never a place: followed by "to" they always mean motion ("over to",
#: "round to"), unlike "next to" or "close to"
PATH_PARTICLES = frozenset(read_data("language.json")["path_particles"])
#: what follows a particle when the phrase names a destination
DESTINATION_PREPS = frozenset({"to", "towards", "toward", "into", "onto", "until", "till"})


def _verb_before(toks: list[str], i: int) -> int:
    """Index of the motion verb that governs position `i` (skipping its object and a posture
    verb: "take me over", "go sit by"), or -1."""
    j = i - 1
    while j >= 0 and (toks[j] in MOTION_OBJECTS or toks[j] in POSTURE_VERBS) and i - j <= 3:
        j -= 1
    opened = j == 0 or j > 0 and (toks[j - 1] in VERB_OPENERS or toks[j - 1] in MOTION_VERBS)
    return j if j >= 0 and toks[j] in MOTION_VERBS and opened else -1


def is_destination(toks: list[str], i: int, n: int) -> bool:
    """True when toks[i:i+n] is a particle or preposition of motion: right after a verb of motion
    (and its object), or a path particle followed by a destination preposition ("over to the sofa")."""
    return (toks[i] in PATH_PARTICLES and i + n < len(toks) and toks[i + n] in DESTINATION_PREPS
            or _verb_before(toks, i) >= 0 and toks[i] in PARTICLES | DESTINATION_PREPS)


def strip_motion(toks: list[str]) -> list[str]:
    """`toks` without the motion phrases that only say where to go: a motion verb with its object,
    a chained posture verb, its particle and destination preposition ("make your way across to")."""
    drop: set[int] = set()
    for i in range(len(toks)):
        if i not in drop and is_destination(toks, i, 1):
            start = _verb_before(toks, i)
            end = next((k for k in range(i + 1, len(toks)) if toks[k] not in DESTINATION_PREPS), len(toks))
            drop.update(range(start if start >= 0 else i, end))
    return [t for k, t in enumerate(toks) if k not in drop]
