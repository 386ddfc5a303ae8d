"""The offline model's spatial-relation expert (`prompts/spatial.j2`) and its gate weighting.

It reads a referring expression ("the cup on the kitchen table", "the chair closest to the
window", "the shorter of the two vases", "facing the sofa, the lamp on the right") into a
target kind, colour/material words and relations to landmark categories, then scores the
candidates of the target kind from the geometry fenced in the prompt (`center`, `size`,
`z_range`, `on`, `under`), with landmarks found by category among the candidates and the
reference objects; a landmark to be near or far from whose kind the map lacks is read as the map
label its name misspells or is nearest to ("the archway" where the map has a "door"). A relation
whose landmark the map lacks even so is left unread and the others rank; no relation, no target,
or none left to rank by: an empty ranking.
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from ...lexicon import load_lexicon
from ...store import geometry as geo
from ...understanding import Slot, analyse_query, candidate_from_line, label_concepts, label_kinds, map_word, room_of
from ...understanding.spatial import COMPASS, SIZE_EXTREMES, Relation, parse_query
from .looks import colour_nearness, own_colours
from .prompt import Prompt

#: words in an expert's gate description that make the gate score it by the query's relations
GATE_MARKER = "spatial relations"
#: gate score of the other experts when the query picks its target by a relation
_OTHERS_CAP = 1


# -- ranking ---------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class _Scene:
    """The geometry the prompt shows: boxes of candidates and references, labels, rooms
    (shared by the prompts that show the same lines: never modified)."""

    boxes: geo.Boxes
    concepts: list[tuple[tuple[str, float], ...]]
    attrs: list[frozenset]
    rooms: list[str | None]        # canonical room types ("kids room" and "bedroom": bedroom)
    room_names: list[str | None]   # the rooms as the map names them: one room's objects
    on: list[frozenset[int]]
    under: list[frozenset[int]]
    is_candidate: np.ndarray
    labels: list[str]
    label_words: list[frozenset[str]]
    words: list[frozenset[str]]    # lemmas of each line's label, caption, tags and room
    parts: list[frozenset[str]]    # categories each line's caption names ("with a green seat cushion")
    colours: list[tuple[Slot, ...]]  # the colours each line's label, caption and tags say


@dataclass(frozen=True)
class _Line:
    """One fenced instance line as the scene reads it: its id, box corners (None: no usable
    geometry) and what its label, tags, caption and room say."""

    id: int
    box: tuple[np.ndarray, np.ndarray] | None
    concepts: tuple[tuple[str, float], ...]
    attrs: frozenset
    room: str | None
    room_name: str | None
    on: frozenset[int]
    under: frozenset[int]
    label: str
    label_words: frozenset[str]
    words: frozenset[str]
    parts: frozenset[str]
    colours: tuple[Slot, ...]


@lru_cache(maxsize=65536)
def _read_line(line: str) -> _Line | None:
    """`line` read (None: not an instance with a centre). Memoised by its text: the queries on a
    map show the same instance lines again and again (1.2 ms per prompt when read afresh)."""
    try:
        data = json.loads(line)
    except ValueError:
        return None
    if not (isinstance(data, dict) and isinstance(data.get("id"), int) and "center" in data):
        return None
    lex = load_lexicon()
    boxes = geo.Boxes.from_views([data])

    def ids(value) -> frozenset[int]:
        return frozenset(x for x in value if isinstance(x, int)) if isinstance(value, list) else frozenset()

    record = candidate_from_line(json.dumps({"id": data["id"], "label": data.get("label"), "tags": data.get("tags"),
                                             "caption": data.get("caption")}))
    return _Line(id=data["id"], box=(boxes.lo[0], boxes.hi[0]) if len(boxes) else None,
                 concepts=label_concepts(str(data.get("label") or "")),
                 attrs=record[1].attrs if record else frozenset(),
                 room=room_of(str(data["room"])) if data.get("room") else None,
                 room_name=str(data["room"]) if data.get("room") else None,
                 on=ids(data.get("on")), under=ids(data.get("under")), label=str(data.get("label") or ""),
                 label_words=record[1].label_words if record else frozenset(),
                 words=record[1].words | record[1].room_words if record else frozenset(),
                 parts=frozenset(v for sp in lex.scan([lex.lemma(t) for t in lex.tokens(str(data.get("caption") or ""))])
                                 for k, v in sp.kinds if k == "cat"),
                 colours=tuple(s for s in record[1].slots if s.kind == "color") if record else ())


def _read_scene(prompt: Prompt) -> _Scene:
    """Candidates then references with geometry, each id once (the first line wins)."""
    return _scene_of(tuple(prompt.candidate_lines), tuple(prompt.reference_lines))


@lru_cache(maxsize=64)
def _scene_of(candidate_lines: tuple[str, ...], reference_lines: tuple[str, ...]) -> _Scene:
    """`_read_scene` memoised by the lines: the spatial prompts on one map show the same lines
    from query to query (`read_prompt` gives the same tuples for the same blocks)."""
    by_id: dict[int, tuple[_Line, bool]] = {}
    for lines, is_cand in ((candidate_lines, True), (reference_lines, False)):
        for line in lines:
            read = _read_line(line)
            if read is not None:
                by_id.setdefault(read.id, (read, is_cand))
    keep = [(r, c) for r, c in by_id.values() if r.box is not None]
    boxes = geo.Boxes(np.array([r.id for r, _ in keep], np.int64),
                      np.array([r.box[0] for r, _ in keep], np.float64).reshape(-1, 3),
                      np.array([r.box[1] for r, _ in keep], np.float64).reshape(-1, 3))
    return _Scene(boxes=boxes, concepts=[r.concepts for r, _ in keep], attrs=[r.attrs for r, _ in keep],
                  rooms=[r.room for r, _ in keep], room_names=[r.room_name for r, _ in keep],
                  on=[r.on for r, _ in keep], under=[r.under for r, _ in keep],
                  is_candidate=np.array([c for _, c in keep], bool), labels=[r.label for r, _ in keep],
                  label_words=[r.label_words for r, _ in keep],
                  words=[r.words for r, _ in keep], parts=[r.parts for r, _ in keep],
                  colours=[r.colours for r, _ in keep])


@lru_cache(maxsize=512)
def _of_kind(scene: _Scene, cats: tuple[str, ...], attrs: tuple[tuple[str, str], ...],
             landmark: bool = False, by_text: bool = False, names: str = "") -> np.ndarray:
    """(N,) bool, read-only: instances of one of `cats` (or of a more general kind when none is:
    "kitchen table" finds a "table"; a landmark's, the one whose caption or room says "kitchen",
    if any; with `by_text`, a landmark of no related kind at all is the one whose text names it: an
    "oven" in "a gas cooker with an oven below", a point to be near or far from; not a thing to be on
    or with, which a caption's passing "floor" or "handle" is not; nor any kind, the one whose text says the
    landmark's `names`: a "boiler" labelled "tank"), narrowed to those matching `attrs` best when any
    matches.
    Memoised by the scene and what is asked: the queries on one map name the same target and
    landmark kinds again and again (about 50 us per scene of 100 instances)."""
    lex = load_lexicon()
    fit = _fit_to(scene, cats)
    kind = fit >= 0.9 if (fit >= 0.9).any() else fit >= 0.6 if cats else np.ones(len(fit), bool)
    if landmark and cats and not (fit >= 0.9).any():
        said = np.array([any(_words(q) <= words for q in cats) for words in scene.words], bool)
        if (kind & said).any():
            kind = kind & said
        elif by_text and not kind.any():
            kind = said | np.array([bool(names) and _words(names) <= words for words in scene.words], bool)
    rooms = {v for k, v in attrs if k == "room"}  # a landmark's room ("the kitchen table"), when one is there
    in_room = kind & np.array([r in rooms for r in scene.rooms], bool) if rooms else kind
    kind = in_room if in_room.any() or not cats else kind  # no category: a room's objects ("nearest the den")
    attrs = tuple((k, v) for k, v in attrs if k not in ("size", "room"))  # sizes compare instances: see "extreme"
    if attrs and kind.any():
        fit = np.array([min(max((lex.attr_sim(k, v, vv) for kk, vv in a if kk == k), default=0.0) for k, v in attrs)
                        for a in scene.attrs])
        best = float(fit[kind].max())
        if best >= 0.5:  # the best-matching colour or material only: "grey" is not "white"
            kind = kind & (fit >= best - 1e-9)
    kind.flags.writeable = False
    return kind


def _fit_to(scene: _Scene, cats: tuple[str, ...]) -> np.ndarray:
    """(N,) per instance of `scene`, the best weight x fit of its label's categories to one of
    `cats` (`concept_sim` or `_member`, the higher; 0 for a label without categories): each of the
    scene's distinct categories compared with each kind once (`_fits_to`), not once per instance."""
    pairs = _concept_pairs(scene)
    if pairs is None:  # a weight not above 0 (the max below starts from 0): per instance
        lex = load_lexicon()
        return np.array([max((w * max(lex.concept_sim(q, c), _member(lex, q, c)) for c, w in concepts for q in cats),
                             default=0.0) for concepts in scene.concepts])
    rows, index, weights = pairs
    fit = np.zeros(len(scene.concepts))
    for q in cats:
        np.maximum.at(fit, rows, weights * _fits_to(scene, q)[index])
    return fit


@lru_cache(maxsize=64)
def _concept_pairs(scene: _Scene) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """(row, index into `_scene_concepts`, weight) of each category of each instance's label;
    None when a weight is not above 0."""
    distinct = {c: k for k, c in enumerate(_scene_concepts(scene))}
    pairs = [(row, distinct[c], w) for row, concepts in enumerate(scene.concepts) for c, w in concepts]
    if not all(w > 0.0 for _, _, w in pairs):
        return None
    return (np.array([p[0] for p in pairs], np.int64), np.array([p[1] for p in pairs], np.int64),
            np.array([p[2] for p in pairs], np.float64))


@lru_cache(maxsize=64)
def _scene_concepts(scene: _Scene) -> tuple[str, ...]:
    """The distinct categories of the scene's labels, in order of first appearance."""
    return tuple(dict.fromkeys(c for concepts in scene.concepts for c, _ in concepts))


@lru_cache(maxsize=4096)
def _fits_to(scene: _Scene, kind: str) -> np.ndarray:
    """(C,) read-only: how well each of the scene's distinct categories answers `kind`."""
    lex = load_lexicon()
    fits = np.array([max(lex.concept_sim(kind, c), _member(lex, kind, c)) for c in _scene_concepts(scene)],
                    dtype=np.float64)
    fits.flags.writeable = False
    return fits


@lru_cache(maxsize=1024)
def _words(phrase: str) -> frozenset[str]:
    """Lemmas of the words of `phrase`."""
    lex = load_lexicon()
    return frozenset(lex.lemma(t) for t in lex.tokens(phrase))


def _member(lex, word: str, label: str) -> float:
    """How well `label` answers a class noun (`word` a generic of the lexicon: "seat", "storage"):
    a member kind (weight >= 0.8 there) as well as a subkind answers its kind (0.9), a kind the
    class only touches (a bed as a seat) by its weight; 0 when `word` is no class noun."""
    weight = lex.generic.get(word, {}).get(label, 0.0)
    return 0.9 if weight >= 0.8 else weight


#: what saying the target's name literally is worth against a relation's score (each in 0-1):
#: half a relation's range, so a relation one candidate meets and the other does not still
#: decides, and on a ranked relation ("closest") so does a lead of more than half the range
_LITERAL_NAME = 0.5
#: what the target's colour is worth, ranked over the targets: as much as its literal name, for the same reason
_LOOK = 0.5


def _named_most_literally(scene: _Scene, rows: np.ndarray, head: frozenset[str],
                          relations: list[Relation]) -> np.ndarray:
    """(len(rows),) bool: the rows whose labels say the request's name for the target most
    literally: most of the head noun's words, then fewest words neither the head nor a landmark
    the target is placed by uses (a "bed lamp" placed by the bed says nothing extra; all False
    when every row says it alike). The kind set holds more specific kinds too (an "office chair"
    is a chair), but a map that labels some objects "chair" and others "office chair" tells
    them apart by name, and so does a request that says only "chair"."""
    said = head | {w for rel in relations if not rel.negated for mark in rel.landmarks for c in mark for w in c.split()}
    keys = [(len(head & scene.label_words[r]), -len(scene.label_words[r] - said)) for r in rows]
    best = max(keys, default=None)
    literal = np.array([k == best for k in keys], bool)
    return literal if not literal.all() else np.zeros(len(rows), bool)


def _not_named_in_part(scene: _Scene, rows: np.ndarray, head: frozenset[str]) -> np.ndarray:
    """(len(rows),) bool: False for a row whose label is part of another row's label that the
    request says in full ("file cabinet" asked: not the plain "cabinet"s)."""
    said_in_full = [scene.label_words[r] for r in rows if scene.label_words[r] <= head]
    return np.array([not any(scene.label_words[r] < full for full in said_in_full) for r in rows], bool)


def _extent(scene: _Scene, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """xy (lo, hi) of the objects in the rooms of `rows`, each room as the map names it (two
    bedrooms are two rooms; all objects when rooms are unknown)."""
    rooms = {scene.room_names[r] for r in rows}
    same = np.array([room in rooms for room in scene.room_names], bool) if None not in rooms \
        else np.ones(len(scene.room_names), bool)
    return scene.boxes.lo[same, :2].min(axis=0), scene.boxes.hi[same, :2].max(axis=0)


def _end_of(scene: _Scene, rows: np.ndarray, end: str) -> geo.Boxes:
    """One box per landmark row: the last 0.3 m of its length at its "head" (the end nearer a wall:
    a wall the prompt shows, else the edge of the objects of its room) or its "foot" (the other end); ids -1."""
    boxes = scene.boxes.take(rows)
    walls = scene.boxes.take(np.array(["wall" in words for words in scene.label_words], bool))
    room_lo, room_hi = _extent(scene, rows) if not len(walls) else (None, None)  # (only without walls)
    lo, hi = boxes.lo.copy(), boxes.hi.copy()
    for k in range(len(rows)):
        axis = int(np.argmax(hi[k, :2] - lo[k, :2]))  # along its length
        depth = min(0.3, hi[k, axis] - lo[k, axis])
        ends = [geo.Boxes(np.array([-1]), lo[k:k + 1].copy(), hi[k:k + 1].copy()) for _ in range(2)]
        ends[0].hi[0, axis] = lo[k, axis] + depth  # the low end
        ends[1].lo[0, axis] = hi[k, axis] - depth  # the high end
        to_wall = [float(geo.xy_gap(e, walls).min()) for e in ends] if len(walls) else \
            [lo[k, axis] - room_lo[axis], room_hi[axis] - hi[k, axis]]
        head = int(to_wall[1] < to_wall[0])
        chosen = ends[head if end == "head" else 1 - head]
        lo[k], hi[k] = chosen.lo[0], chosen.hi[0]
    return geo.Boxes(np.full(len(rows), -1), lo, hi)


def _rank_score(values: np.ndarray) -> np.ndarray:
    """Higher value -> score near 1; ties share a score (dense ranks over distinct values)."""
    if len(values) < 2:
        return np.ones(len(values))
    ranks = np.unique(np.round(-values, 3), return_inverse=True)[1]
    return 1.0 - ranks / max(ranks.max(), 1)


@dataclass(frozen=True)
class _Viewpoint:
    """Rows of the scene the viewer looks at (`facing`) and stands or sits at (`at`); either may
    be empty."""

    facing: np.ndarray
    at: np.ndarray


def _nearest(scene: _Scene, rows: np.ndarray, xy: np.ndarray) -> int:
    """The row of `rows` whose centre is nearest to the point `xy`."""
    return int(rows[np.argmin(np.hypot(*(scene.boxes.center[rows, :2] - xy).T))])


def _view(scene: _Scene, targets: np.ndarray, view: _Viewpoint) -> tuple[np.ndarray, np.ndarray]:
    """(viewer xy, unit view direction): from where the viewer is (the middle of the targets'
    room, or the landmark they are at, nearest to the targets) towards the landmark they face,
    else towards the targets; from a landmark whose own footprint holds the targets' middle (the
    cushions on the sofa one sits on), into the room."""
    lo, hi = _extent(scene, targets)
    middle = (lo + hi) / 2
    tc = scene.boxes.center[targets, :2].mean(axis=0)
    at = _nearest(scene, view.at, tc) if len(view.at) else None
    viewer = middle if at is None else scene.boxes.center[at, :2]
    if len(view.facing):
        look = scene.boxes.center[_nearest(scene, view.facing, tc), :2] - viewer
    elif at is not None and np.all((scene.boxes.lo[at, :2] <= tc) & (tc <= scene.boxes.hi[at, :2])):
        look = middle - viewer
    else:
        look = tc - viewer
    norm = float(np.hypot(*look))
    return viewer, (look / norm if norm > 1e-6 else np.array([0.0, 1.0]))


#: relations of contact, met or not by the geometry; a candidate that meets one scores at least _MET
_CONTACT = ("on", "in", "under", "above", "below", "with")
_MET = 0.7


def _landmarks(scene: _Scene, rel: Relation, cats: tuple[str, ...], attrs: tuple[tuple[str, str], ...],
               names: str) -> np.ndarray:
    """(N,) bool: the scene's instances that are one landmark of `rel` (`_of_kind`; the words said
    matter only for a relation of no contact: one memo entry per kind otherwise)."""
    by_text = rel.kind not in _CONTACT
    return _of_kind(scene, cats, attrs, landmark=True, by_text=by_text, names=names if by_text else "")


def _map_kinds(scene: _Scene, phrase: str, encoder: Callable[[], Any] | None) -> tuple[str, ...]:
    """The categories of the scene's label that `phrase` misspells or is nearest to (`map_word`);
    none when no label is sure."""
    labels = sorted({label for label in scene.labels if label})
    if not phrase or not labels:
        return ()
    return label_kinds(map_word(phrase, labels, encoder() if encoder is not None else None))


def _relations_on_map(scene: _Scene, relations: list[Relation], encoder: Callable[[], Any] | None) -> list[Relation]:
    """`relations`, each landmark kind the scene lacks read as the scene label its name misspells
    or is nearest to (`_map_kinds`: "the archway" where the map has a "door"), for a point to be
    near or far from; not for a thing to be on or with, which a caption's part may be ("the chair
    with a cup holder"); a landmark no label is sure of stays as said."""
    out = []
    for rel in relations:
        marks = [_map_kinds(scene, names, encoder)
                 if cats and rel.kind not in _CONTACT and not _landmarks(scene, rel, cats, attrs, names).any()
                 else () for cats, attrs, names in zip(rel.landmarks, rel.landmark_attrs, rel.landmark_names)]
        out.append(rel if not any(marks) else dataclasses.replace(
            rel, landmarks=[found or cats for found, cats in zip(marks, rel.landmarks)]))
    return out


def _relation_scores(rel: Relation, scene: _Scene, targets: np.ndarray, view: _Viewpoint) -> np.ndarray | None:
    """(len(targets),) scores in [0, 1]; None when a landmark is missing from the map."""
    boxes = scene.boxes
    tb = boxes.take(targets)
    marks, mark_rows = [], []  # the landmarks' boxes and the scene rows they come from (none for a room)
    for cats, attrs, names in zip(rel.landmarks, rel.landmark_attrs, rel.landmark_names):
        rows = np.flatnonzero(_landmarks(scene, rel, cats, attrs, names))
        if not len(rows):
            return None
        if rel.landmark_where in ("foot", "head"):
            marks.append(_end_of(scene, rows, rel.landmark_where))
            mark_rows.append(rows)
            continue
        if rel.landmark_where:
            where = _relation_scores(Relation(rel.landmark_where), scene, rows, view)
            rows = rows[where >= where.max() - 1e-9]
        if not cats:  # a room ("the stool nearest the garage"): one box around the objects shown in it
            room = boxes.take(rows)
            lo, hi = room.lo.min(axis=0, keepdims=True), room.hi.max(axis=0, keepdims=True)
            marks.append(geo.Boxes(np.array([-1]), lo, hi))
            mark_rows.append(rows[:0])
            continue
        for size in (v for k, v in attrs if k == "size" and v in SIZE_EXTREMES):
            extreme = _relation_scores(Relation("extreme", value=SIZE_EXTREMES[size]), scene, rows, view)
            rows = rows[extreme >= extreme.max() - 1e-9]  # "the small lamp": the smaller of them
        marks.append(boxes.take(rows))
        mark_rows.append(rows)
    kind = rel.kind
    if rel.value == "group" and kind in ("closest", "farthest"):  # the others of its kind (none: it alone)
        if len(targets) < 2:
            return np.ones(len(targets))
        gap = geo.xy_gap(tb, tb) + 0.25 * geo.center_distance(tb, tb)  # (T, T) m
        np.fill_diagonal(gap, np.nan)  # apart from them: its nearest fellow is far; amid them: near them all
        return _rank_score(np.nanmin(gap, axis=1) if kind == "farthest" else -np.nanmean(gap, axis=1))
    if not marks and (kind in _CONTACT or kind in ("near", "closest", "farthest", "between", "opposite")):
        return None  # the query's landmark could not be read: no guess
    if kind in _CONTACT:
        lm = marks[0]
        if kind in ("on", "in"):  # "in": on one of its shelves, or on its top
            hit = geo.rests_on(tb, lm) | np.array([[int(i) in scene.on[t] for i in lm.ids] for t in targets])
            if kind == "in":
                hit |= geo.is_within(tb, lm)
        elif kind == "under":
            hit = geo.is_under(tb, lm) | np.array([[int(i) in scene.under[t] for i in lm.ids] for t in targets])
        elif kind == "above":
            hit = geo.is_above(tb, lm)
        elif kind == "below":
            hit = geo.is_above(lm, tb).T
        else:  # "a nightstand with a clock (on it)": the landmark rests on the target, or is
            # part of it as its caption says ("the seat with a green cushion")
            cats, attrs = rel.landmarks[0], {(k, v) for k, v in rel.landmark_attrs[0] if k != "room"}
            own = np.array([bool(scene.parts[t] & set(cats)) and attrs <= scene.attrs[t] for t in targets], bool)
            hit = geo.rests_on(lm, tb).T | own[:, None]
        close = np.exp(-geo.center_distance(tb, lm))
        near = np.exp(-geo.xy_gap(tb, lm) / geo.NEAR_GAP)
        # satisfied: _MET + up to 0.3 for the closest landmark; otherwise a little for being near
        return np.where(hit, _MET + 0.3 * close, (0.5 if kind == "with" else 0.15) * near).max(axis=1)
    if kind in ("near", "closest", "farthest"):
        lm = marks[0]
        gap = geo.xy_gap(tb, lm) + 0.25 * geo.center_distance(tb, lm)
        gap = np.where(tb.ids[:, None] == lm.ids[None, :], np.inf, gap).min(axis=1)
        if kind == "near":  # a "bed curtain" is by the bed whatever the geometry says; a chair is
            # not by a chair for its name alone: the label must say more than the landmark's name
            named_after = np.array([any(set(c.split()) < scene.label_words[t] for c in rel.landmarks[0])
                                    for t in targets], bool)
            return np.where(named_after, 1.0, np.exp(-gap / geo.NEAR_GAP))
        # compared among the targets in the landmark's room when it holds two or more besides the landmark:
        # "the stool farthest from the sink" is one of the sink's room's, not the farthest stool of the home
        # (landmarks in several rooms, as a home's two sinks: no one room)
        rooms = {scene.room_names[r] for r in mark_rows[0]}
        shared = np.array([scene.room_names[t] in rooms for t in targets], bool) & ~np.isin(targets, mark_rows[0])
        among = shared if len(rooms) == 1 and None not in rooms and shared.sum() >= 2 else np.ones(len(targets), bool)
        scores = np.zeros(len(targets))
        scores[among] = _rank_score(-gap[among] if kind == "closest" else gap[among])
        return scores
    if kind == "between":
        if len(marks) < 2:
            marks.append(marks[0])
        return _rank_score(-geo.segment_distance(tb, marks[0], marks[1]))
    if kind == "middle" and rel.value == "group":  # the middle one of the target's kind: of a row or a stack
        return _rank_score(-np.linalg.norm(tb.center - tb.center.mean(axis=0), axis=1))
    if kind == "middle" and marks:
        return _rank_score(-geo.center_distance(tb, marks[0]).min(axis=1))
    if kind in ("corner", "middle", "wall"):
        lo, hi = _extent(scene, targets)
        c = tb.center[:, :2]
        if kind == "middle":
            return _rank_score(-np.hypot(*(c - (lo + hi) / 2).T))
        edge = np.minimum(tb.lo[:, :2] - lo, hi - tb.hi[:, :2])  # (T, 2) distance to the x / y walls
        return _rank_score(-(edge.max(axis=1) if kind == "corner" else edge.min(axis=1)))
    if kind == "opposite":
        if len(marks) == 2:  # across M from R: near R reflected through M
            goal = 2 * marks[0].center[:, None, :2] - marks[1].center[None, :, :2]
            goal = goal.reshape(-1, 2)
        else:  # opposite M: across M from the middle of the room
            lo, hi = _extent(scene, targets)
            goal = 2 * marks[0].center[:, :2] - (lo + hi) / 2
        dist = np.hypot(*(tb.center[:, None, :2] - goal[None]).transpose(2, 0, 1)).min(axis=1)
        return _rank_score(-dist)
    if kind == "extreme":
        size = tb.size
        value = {"large": size.prod(axis=1), "small": -size.prod(axis=1), "tall": size[:, 2],
                 "short": -size[:, 2], "high": tb.hi[:, 2] + tb.lo[:, 2], "low": -(tb.hi[:, 2] + tb.lo[:, 2]),
                 "wide": size[:, :2].max(axis=1)}[rel.value]
        return _rank_score(value)
    viewer, look = _view(scene, targets, view)
    left = np.array([-look[1], look[0]])
    if kind in ("left", "right", "front", "behind") or kind in COMPASS:
        axis = np.array(COMPASS[kind]) if kind in COMPASS else \
            {"left": left, "right": -left, "front": -look, "behind": look}[kind]
        if not marks:
            return _rank_score(tb.center[:, :2] @ axis)
        lm = marks[0]
        apart = tb.center[:, None, :2] - lm.center[None, :, :2]  # (T, L, 2)
        offset = apart @ axis  # (T, L) along the side
        dist = geo.center_distance(tb, lm)
        ok = (offset > 0.05) & (tb.ids[:, None] != lm.ids[None, :])
        if kind in COMPASS:  # the nearer and the more squarely that way ("the north-west corner of the desk")
            along = offset / np.maximum(np.linalg.norm(apart, axis=2), 1e-6)
            return np.where(ok, (1.0 + along) / 2.0 / (1.0 + dist), 0.0).max(axis=1)
        return np.where(ok, 1.0 / (1.0 + dist), 0.0).max(axis=1)
    # ordinal: order along the side (or by distance to the landmark), pick the n-th
    if rel.value == "landmark" and marks:
        key = geo.center_distance(tb, marks[0]).min(axis=1)
    else:
        key = -(tb.center[:, :2] @ (left if rel.value == "left" else -left))
    order = np.argsort(key, kind="stable")
    pick = rel.order - 1 if rel.order > 0 else len(order) - 1
    if pick >= len(order):
        return np.zeros(len(order))
    place = np.empty(len(order), np.int64)
    place[order] = np.arange(len(order))
    return 1.0 / (1.0 + np.abs(place - pick))


def rank(prompt: Prompt, encoder: Callable[[], Any] | None = None) -> dict:
    """Top-kappa candidate ids of the target kind by how well they satisfy the relations
    (`encoder`: loads the sentence encoder that reads a kind the map lacks, or None); no ranking
    (an abstention with its reason) when there is nothing for the relations to tell apart."""
    def abstain(reason: str) -> dict:
        return {"ranked_instance_ids": [], "abstain": reason}

    sq = parse_query(prompt.query)
    if not sq.relations:
        return abstain("the query states no spatial relation, comparison, order or viewpoint")
    if sq.unknown_target:
        return abstain("the target is a word I do not know")
    scene = _read_scene(prompt)
    if not len(scene.boxes):
        return abstain("no candidates")
    if sq.target and np.count_nonzero(_of_kind(scene, sq.target, ()) & scene.is_candidate) == 1:
        # where the one candidate of its kind stands tells it from nothing: the kind's reading is the
        # object expert's to weigh, not a relation's weight to impose (a misread kind would win)
        return abstain("one candidate of the target kind: nothing for a relation to tell apart")
    reading = analyse_query(prompt.query)
    relations = _relations_on_map(scene, sq.relations, encoder)  # (may load the encoder: after the abstentions)
    if sq.target:
        # the target's appearance wherever the request gives it (before a participle: "the olive
        # lacquered stool"; in a later sentence: "... the teal one, I think"), not only in the relation's clause
        attrs = tuple(dict.fromkeys(sq.attrs + reading.attrs))
        kind = _of_kind(scene, sq.target, attrs)
    else:  # "the one on the left": anything that is not a landmark
        marks = [c for r in relations for c in r.landmarks] + [c for c in (sq.facing, sq.viewer_at) if c]
        kind = ~np.any([_of_kind(scene, c, ()) for c in marks], axis=0) if marks else np.ones(len(scene.boxes), bool)
    targets = np.flatnonzero(kind & scene.is_candidate)
    named_rooms = {r for r, w in reading.rooms.items() if w >= 1.0} or set(reading.rooms)
    in_room = np.array([scene.rooms[t] in named_rooms for t in targets], bool)
    if in_room.any():  # "... in the attic", else "the kitchen chair ...": that room's instances
        targets = targets[in_room]
    said = (reading.room_phrase or "").lower()
    if said:  # the room the map calls so, not another of its type (a studio is an office too); else the rooms
        # whose names hold the words said, as the room expert reads them ("the principal bedroom": the master one)
        names = [(scene.room_names[t] or "").lower() for t in targets]
        as_named = np.array([name == said for name in names], bool)
        if not as_named.any():
            lex = load_lexicon()
            asked, held = lex.room_name_words(said), {name: lex.room_name_words(name) for name in set(names)}
            as_named = np.array([asked <= held[name] for name in names], bool)
        if as_named.any():
            targets = targets[as_named]
    if not len(targets):
        return abstain("no candidate of the target kind")
    view = _Viewpoint(*(np.flatnonzero(_of_kind(scene, cats, ())) if cats else np.zeros(0, np.int64)
                        for cats in (sq.facing, sq.viewer_at)))
    if sq.target and reading.head_words:
        targets = targets[_not_named_in_part(scene, targets, reading.head_words)]
        # a map that names one kind two ways ("recycling bin", "trash can") tells them apart by the name said;
        # so does a name of several words ("file cabinet"); one word that is also a class's ("chair" of an
        # "armchair", "machine") only breaks near ties (below)
        said_in_full = np.array([reading.head_words <= scene.label_words[t] for t in targets], bool)
        if said_in_full.any() and (len(reading.head_words) > 1 or len(
                {scene.concepts[t][0][0] if scene.concepts[t] else None for t in targets}) == 1):  # one kind
            targets = targets[said_in_full]
        total = _LITERAL_NAME * _named_most_literally(scene, targets, reading.head_words, relations)
    else:
        total = np.zeros(len(targets))
    if sq.modifiers and any(c in load_lexicon().generic for c in sq.target):
        # a class noun says little: "the bar seat" is likelier the seat whose own words say "bar"
        total += _LITERAL_NAME * np.array([sq.modifiers <= scene.words[t] for t in targets], bool)
    own = own_colours(reading)
    for asked in (s for s in reading.slots if s.kind == "color" and s.values & own):
        # the target's colour: those of its family first, then by how near theirs looks (a scan's means are dull)
        look = [max((1.0 if asked.values & seen.values else colour_nearness(asked, seen) for seen in scene.colours[t]),
                    default=0.0) for t in targets]
        total += _LOOK * _rank_score(np.array(look))
    placed = np.ones(len(targets), bool)  # the targets that meet every contact relation stated
    comparisons = [rel for rel in relations if rel.kind == "extreme" and not rel.negated]
    stated = [rel for rel in relations if not (rel.kind == "extreme" and not rel.negated)]
    scored = [(rel, _relation_scores(rel, scene, targets, view)) for rel in stated]
    scored = [(rel, scores) for rel, scores in scored if scores is not None]  # a landmark the map lacks: unread
    if not scored and not comparisons:
        return abstain("a landmark the map lacks")  # no relation left to guess by
    for rel, scores in scored:
        total += 1.0 - scores if rel.negated else scores
        if rel.kind in _CONTACT and not rel.negated:
            placed &= scores >= _MET
    among = placed if placed.any() else np.ones(len(targets), bool)
    for rel in comparisons:  # "the smaller of the boxes on the bench": compared among those on it
        total[among] += _relation_scores(rel, scene, targets[among], view)
    order = np.lexsort((scene.boxes.ids[targets], -np.round(total, 9)))
    return {"ranked_instance_ids": [int(scene.boxes.ids[targets[k]]) for k in order[:prompt.kappa]]}


# -- gate ------------------------------------------------------------------------------------
def weigh(prompt: Prompt, reply: dict) -> dict:
    """Adjust a gate reply for experts whose description declares spatial relations: 4 when the
    query names the target's kind and states a relation, comparison, order or viewpoint (then
    every other expert at most `_OTHERS_CAP`, since a category, room or colour alone cannot pick
    among same-kind objects), 2 beside the others when the kind is not named, else 0 (also for a
    size word alone where the captions of the kind speak of size)."""
    spatial = [e["name"] for e in prompt.experts if GATE_MARKER in str(e.get("gate_description", "")).lower()]
    if not spatial:
        return reply
    sq = parse_query(prompt.query)
    scores, hints = dict(reply.get("scores", {})), dict(reply.get("hints", {}))
    named = sq.named
    # a size word alone ("the little wardrobe") is the description's when captions of that kind speak
    # of size; the boxes decide it only where no words do (an object list's measured captions)
    relations = bool(sq.relations) and not (all(r.said for r in sq.relations) and _sizes_in_words(prompt, sq.target))
    if relations and named:
        scores = {name: min(int(s), _OTHERS_CAP) for name, s in scores.items()}
    for name in spatial:
        # with the target's kind unnamed ("what I dry my hands with, by the sink") the kind is
        # evidence as strong as the relation: the spatial expert then shares the decision
        scores[name] = (4 if named else 2) if relations else 0
        hints[name] = sq.words
    return {"scores": scores, "hints": hints}


def _sizes_in_words(prompt: Prompt, target: tuple[str, ...]) -> bool:
    """True when a candidate of one of the `target` kinds has a size word in its label, caption or tags."""
    lex = load_lexicon()
    for line in prompt.candidate_lines:
        one = candidate_from_line(line)
        if one is not None and any(s.kind == "size" for s in one[1].slots) and any(
                lex.concept_sim(t, c) >= 0.9 for t in target for c, w in one[1].concepts if w >= 1.0):
            return True
    return False
