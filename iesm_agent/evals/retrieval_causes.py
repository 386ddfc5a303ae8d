"""Why a retrieval answer on a built map is wrong: one cause per wrong answer, the map's side first.

A query of the retrieval study (`evals/gt_queries.py`) names a ground-truth object by its
category, and for its type a room (`r`) and a description (`d`: colour and/or material); the
answer is wrong when the picked instance is not among the accepted ones. The causes, tested in
this order (`CAUSES`):

- target not its own instance: no built instance holds the target (never reached, or went into
  other objects' instances; such queries are dropped by the study, so this stays 0 there);
- target mislabelled: no accepted instance carries a label the query's category covers
  (`kinship.covers`);
- target's room wrong: (`r` types) no accepted instance with such a label is in the named room on
  the map;
- target's caption lacks the attribute: (`d` types) no accepted instance with the label (and room)
  has a caption that names the colour family and the material the query says;
- distractor labelled as the category: the pick carries a label the category covers, but the
  object it holds is of another category (or it holds none);
- distractor's room wrong: (`r` types) the pick is in the named room on the map, its object not;
- distractor's caption carries the attribute: (`d` types) the pick's caption names what the query
  says, its object's ground truth does not (these two and the next: for a pick the category covers,
  or any pick of an `ard` query, which names no category);
- a distractor truly answers: the pick's object is of the category, in the room and with the
  description the query says (the query does not single the target out);
- query read wrongly: the reading (the gate's hints) misses the category (not for `ard`), the
  room or a said colour or material;
- other: none of the above (the map holds everything the query needs; the ranking picked another).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence

from ..colours import colour_family
from ..store.model import Instance
from .kinship import covers
from .vocab import Vocabulary, normalise, room_name

CAUSES = ("target not its own instance", "target mislabelled", "target's room wrong",
          "target's caption lacks the attribute", "distractor labelled as the category",
          "distractor's room wrong", "distractor's caption carries the attribute",
          "a distractor truly answers", "query read wrongly", "other")
#: the causes that lie in the map (labels, rooms, captions), not in the query or its reading
MAP_CAUSES = CAUSES[:7]


@dataclass(frozen=True)
class GtObject:
    """A ground-truth object as a query describes it: `label`, `room` (spoken name or None) and
    `attributes` (`Vocabulary.attributes`: "color" and/or "material" as a person says them)."""

    id: int
    label: str
    room: Optional[str]
    attributes: dict[str, str]


def gt_objects(objects: Sequence[dict], rooms: Sequence[dict], vocab: Vocabulary) -> dict[int, GtObject]:
    """Ground truth (gt/objects.json `objects` and `rooms`) -> {id: `GtObject`}."""
    names = {int(r["id"]): room_name(r.get("label")) for r in rooms}
    return {int(o["id"]): GtObject(int(o["id"]), o["label"], names.get(o.get("room")),
                                   vocab.attributes(o.get("tags") or {}, ""))
            for o in objects}


def _values(vocab: Vocabulary, text: str, kind: str) -> set[str]:
    """The lexicon's canonical `kind` ("color" / "material") values said in `text`; colours as
    their families (`colours.colour_family`)."""
    lex = vocab.lex
    found = {v for s in lex.scan([lex.lemma(t) for t in lex.tokens(normalise(text or ""))]) if s.has(kind)
             for v in s.values(kind)}
    return {colour_family(v) or v for v in found} if kind == "color" else found


def said(query: str, target: GtObject, vocab: Vocabulary) -> dict[str, set[str]]:
    """Of the target's colour and material, the values the query says ({kind: canonical values})."""
    out = {}
    for kind, value in target.attributes.items():
        values = _values(vocab, value, kind) & _values(vocab, query, kind)
        if values:
            out[kind] = values
    return out


def carries(inst: Instance, wanted: dict[str, set[str]], vocab: Vocabulary) -> bool:
    """`inst`'s caption and tags name every kind of `wanted` with one of its values."""
    text = " ".join([inst.caption, *(inst.tags.get(k, "") for k in ("color", "material"))])
    return all(_values(vocab, text, kind) & values for kind, values in wanted.items())


def truly(obj: GtObject, wanted: dict[str, set[str]], vocab: Vocabulary) -> bool:
    """The ground truth of `obj` has every kind of `wanted` with one of its values."""
    return all(_values(vocab, obj.attributes.get(kind, ""), kind) & values for kind, values in wanted.items())


def read_wrongly(qtype: str, hints: dict[str, str], category: str, room: Optional[str],
                 wanted: dict[str, set[str]], vocab: Vocabulary) -> Optional[str]:
    """What the reading (`hints`: obj, room, desc) misses of the query, None when nothing."""
    obj = hints.get("obj")
    if qtype != "ard" and not (obj and (covers(category, obj) or covers(obj, category))):
        return f"category {category!r} read as {obj!r}"
    if "r" in qtype and room_name(hints.get("room")) != room:
        return f"room {room!r} read as {hints.get('room')!r}"
    for kind, values in wanted.items():
        if not _values(vocab, hints.get("desc", ""), kind) & values:
            return f"{kind} {'/'.join(sorted(values))} read as {hints.get('desc')!r}"
    return None


def names_abstract(hints: dict[str, str], category: str) -> bool:
    """The reading of an abstract (`ard`) query names `category` (or a kind it covers, or one
    covering it) among the categories its use phrase points to (`hints["abs"]`, comma-separated)."""
    return any(part and (covers(category, part) or covers(part, category))
               for part in (p.strip() for p in hints.get("abs", "").split(",")))


def _describe(inst: Optional[Instance]) -> str:
    if inst is None:
        return "-"
    return f"#{inst.id} {inst.label} ({inst.room_label or 'no room'}): {inst.caption or 'no caption'}"


def classify(qtype: str, query: str, hints: dict[str, str], target: GtObject, target_insts: Sequence[Instance],
             accept_insts: Sequence[Instance], picked: Optional[Instance], picked_gt: Optional[GtObject],
             vocab: Vocabulary) -> tuple[str, str]:
    """(cause, detail) of one wrong answer: the query (`qtype`, text, the reading's `hints`), its
    target's ground truth and built instances, the accepted instances and the pick (`picked`
    and the ground-truth object it holds, None for none); causes as the module docstring."""
    category = vocab.spoken(target.label)
    wanted = said(query, target, vocab) if "d" in qtype else {}
    room = target.room if "r" in qtype else None
    if not target_insts:
        return CAUSES[0], f"{target.label} in no instance of its own"
    kin = [i for i in accept_insts if covers(category, i.label)]
    if not kin:
        return CAUSES[1], f"{category} labelled {', '.join(sorted({i.label for i in accept_insts}))}"
    if room is not None:
        kin = [i for i in kin if room_name(i.room_label) == room]
        if not kin:
            return CAUSES[2], f"{category} in the {room}, on the map in the " + ", ".join(
                sorted({str(i.room_label) for i in accept_insts if covers(category, i.label)}))
    if wanted and not any(carries(i, wanted, vocab) for i in kin):
        says = "; ".join(i.caption or "no caption" for i in kin)
        return CAUSES[3], f"query says {', '.join('/'.join(sorted(v)) for v in wanted.values())}; caption: {says}"
    # a pick the category covers, or any pick of an abstract query (which names no category)
    if picked is not None and (qtype == "ard" or covers(category, picked.label)):
        if qtype != "ard" and (picked_gt is None or not covers(category, picked_gt.label)):
            return CAUSES[4], f"{_describe(picked)} holds {picked_gt.label if picked_gt else 'no object'}"
        if picked_gt is None:
            return CAUSES[9], f"picked {_describe(picked)}, which holds no object"
        if room is not None and room_name(picked.room_label) == room and picked_gt.room != room:
            return CAUSES[5], f"{_describe(picked)} is in the {picked_gt.room}"
        if wanted and carries(picked, wanted, vocab) and not truly(picked_gt, wanted, vocab):
            return CAUSES[6], f"{_describe(picked)}; truly {picked_gt.attributes}"
        if (covers(category, picked_gt.label) and (room is None or picked_gt.room == room)
                and truly(picked_gt, wanted, vocab)):
            return CAUSES[7], f"{_describe(picked)}; truly {picked_gt.attributes} in the {picked_gt.room}"
    misread = read_wrongly(qtype, hints, category, room, wanted, vocab)
    if misread:
        return CAUSES[8], misread
    return CAUSES[9], f"picked {_describe(picked)}"
