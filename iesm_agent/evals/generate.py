"""Synthetic query suites of the paper's five types (Sec. 4.3, Appendix C).

Targets are sampled (seeded) from instances of the most frequent categories of each map. Queries
come from templates with lexical variants (command verbs, description forms, room phrases) or,
with a model, from `prompts/gen_queries.j2`, validated the same way and replaced by the
template query after `RETRIES` rejected retries. `accept` follows the paper's relaxations.
"""

from __future__ import annotations

import asyncio
import os
import random
import re
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional, Sequence

from ..errors import IesmError
from ..providers.base import ChatOptions, Model
from ..store.model import Instance, SceneMap
from ..store.refs import resolve_map_path
from .kinship import covers
from .suite import MapRegistry, SuiteQuery, write_suite
from .vocab import Vocabulary, room_name

TYPES: tuple[str, ...] = ("o", "or", "od", "ord", "ard")
#: spatial referring expressions (beyond the paper), accept sets from geometry: evals/spatial_queries.py
SPATIAL = "s"
TOP_CATEGORIES = 30
STRUCTURAL = {"wall", "floor", "ceiling", "doorway", "door frame", "unknown", "misc", "other", "object",
              "background", "stuff", "thing", "item"}
RETRIES = 3
TYPE_RULES = {
    "o": "Name only the object category. No room, colour or material.",
    "or": "Name the object category and the room it is in. No colour or material.",
    "od": "Name the object category and the given description (colour and/or material). No room.",
    "ord": "Name the object category, the room and the given description.",
    "ard": "Do not name the category, any synonym or a more general category; refer to the object by "
           "what it is used for (e.g. 'something to sit on'), plus the room and the given description.",
}
_VERBS = ("Find the {np}", "Go to the {np}", "Navigate to the {np}", "Take me to the {np}",
          "Where is the {np}?", "I need the {np}", "Can you find the {np}?", "Head to the {np}",
          "Show me the {np}", "I'm looking for the {np}", "Could you take me to the {np}?")
_ABSTRACT_VERBS = ("Find {np}", "Take me to {np}", "Navigate to {np}", "I need {np}", "Go to {np}",
                   "Where can I find {np}?", "Show me {np}", "I'm looking for {np}")
_THINGS = ("object", "thing")
#: draws of template wordings per wanted paraphrase before a target is given up
_DRAWS = 8
_PREFIX = re.compile(r"^[A-Za-z0-9_.\-]{1,40}$")
_ROOM_FORMS = ("in the {room}", "in the {room} area")


def parse_types(text: str) -> list[str]:
    types = [t.strip() for t in text.split(",") if t.strip()]
    unknown = [t for t in types if t not in (*TYPES, SPATIAL)]
    if unknown or not types:
        raise IesmError(f"unknown query type(s) {unknown or text!r}; known: {', '.join((*TYPES, SPATIAL))}",
                        "--types")
    return list(dict.fromkeys(types))


@dataclass
class Target:
    """What a query may say about one instance."""

    inst: Instance
    category: str
    room: Optional[str]
    attributes: dict[str, str]  # kind (color, material) -> value
    uses: list[str]             # what it is for, after "for" ("sitting on", "heating up leftovers")


@dataclass
class GenerationResult:
    queries: list[SuiteQuery] = field(default_factory=list)
    counts: Counter = field(default_factory=Counter)        # (map, type) -> written
    shortfalls: dict = field(default_factory=dict)          # (map, type) -> how many short of per_type
    rejected: int = 0                                       # model queries that failed validation
    fallbacks: int = 0                                      # model gave up, template query used

    def report_lines(self) -> list[str]:
        lines = [f"{m}: ({t}) {n} queries" + (f", {self.shortfalls[m, t]} short: too few answerable targets"
                                               if self.shortfalls.get((m, t)) else "")
                 for (m, t), n in self.counts.items()]
        lines.append(f"{len(self.queries)} queries written")
        if self.rejected or self.fallbacks:
            lines.append(f"model queries rejected: {self.rejected}, template fallbacks: {self.fallbacks}")
        return lines


def top_categories(scene: SceneMap, vocab: Vocabulary, k: int = TOP_CATEGORIES) -> list[str]:
    """The `k` most frequent categories (labels as people say them, `Vocabulary.spoken`),
    structural/unhelpful ones left out (ties by name)."""
    counts = Counter(vocab.spoken(i.label) for i in scene.instances)
    ranked = sorted((c for c in counts if c and c not in STRUCTURAL), key=lambda c: (-counts[c], c))
    return ranked[:k]


def _target(inst: Instance, vocab: Vocabulary) -> Target:
    category = vocab.spoken(inst.label)
    attributes = vocab.attributes(inst.tags, inst.caption)
    if set(attributes.get("material", "").split()) & set(category.split()):
        del attributes["material"]  # "paper" made of paper says nothing
    return Target(inst=inst, category=category, room=room_name(inst.room_label),
                  attributes=attributes, uses=vocab.uses_of(inst.label))


def answerable(t: Target, qtype: str) -> bool:
    need_room, need_desc = "r" in qtype, "d" in qtype
    return ((not need_room or t.room is not None) and (not need_desc or bool(t.attributes))
            and (qtype != "ard" or bool(t.uses)))


def _kin(t: Target, o: Target) -> bool:
    """`o` answers to `t`'s category name (`kinship.covers`: a desk chair counts for "the chair")."""
    return o.category == t.category or covers(t.category, o.inst.label)


def accept_ids(t: Target, qtype: str, others: Sequence[Target]) -> list[int]:
    """Paper relaxations: (o) any instance answering to the category name, (o,r) any such
    instance in the named room; otherwise the target alone."""
    if qtype == "o":
        return sorted(o.inst.id for o in others if _kin(t, o))
    if qtype == "or":
        return sorted(o.inst.id for o in others if _kin(t, o) and o.room == t.room)
    return [t.inst.id]


def _describe(t: Target, qtype: str, others: Sequence[Target], rng: random.Random) -> dict[str, str]:
    """The attribute subset that leaves the fewest look-alikes (instances answering to the
    category name, in the same room for room types), smallest subset first."""
    scope = [o for o in others if o.inst.id != t.inst.id and _kin(t, o)
             and ("r" not in qtype or o.room == t.room)]
    kinds = sorted(t.attributes)
    subsets = [[k] for k in kinds] + ([kinds] if len(kinds) > 1 else [])
    clashes = [sum(all(o.attributes.get(k) == t.attributes[k] for k in s) for o in scope) for s in subsets]
    best = min(clashes)
    choice = rng.choice([s for s, c in zip(subsets, clashes, strict=True) if c == best])
    return {k: t.attributes[k] for k in choice}


def template_query(t: Target, qtype: str, others: Sequence[Target], vocab: Vocabulary, rng: random.Random,
                   desc: Optional[dict[str, str]] = None) -> str:
    """A query of `qtype` for `t` from the templates (command verb, description form, room phrase);
    `desc` fixes the attributes said (else chosen by `_describe`)."""
    room = rng.choice(_ROOM_FORMS).format(room=t.room) if "r" in qtype else ""
    if desc is None:
        desc = _describe(t, qtype, others, rng) if "d" in qtype else {}
    adjectives = [vocab.adjective(k, v) for k, v in sorted(desc.items())]
    if qtype == "ard":  # "something gray for lounging on in the living room", ...
        use, said = rng.choice(t.uses), " ".join(adjectives)
        form = rng.randrange(3)
        if form == 0:
            np = f"something {' and '.join(adjectives)} for {use} {room}"
        elif form == 1:
            np = f"the {said} {rng.choice(_THINGS)} used for {use} {room}"
        else:
            np = f"something {room} for {use}, the {said} one"
        room = ""
        template = rng.choice(_ABSTRACT_VERBS)
    else:
        if desc and rng.random() < 0.5 and "material" in desc:
            np = " ".join([*(vocab.adjective(k, v) for k, v in desc.items() if k != "material"), t.category,
                           f"made of {desc['material']}"])
        else:
            np = " ".join([*adjectives, t.category])
        template = rng.choice(_VERBS)
    return template.format(np=" ".join(f"{np} {room}".split()))


def wordings(t: Target, qtype: str, others: Sequence[Target], vocab: Vocabulary, rng: random.Random,
             k: int = 1) -> list[str]:
    """`k` distinct valid template wordings of one intent (the same target and description),
    [] when `_DRAWS * k` draws give fewer."""
    desc = _describe(t, qtype, others, rng) if "d" in qtype else {}
    out: list[str] = []
    for _ in range(_DRAWS * k):
        text = template_query(t, qtype, others, vocab, rng, desc)
        if validate(text, t, qtype, vocab, out) is None:
            out.append(text)
            if len(out) == k:
                return out
    return []


def validate(text: str, t: Target, qtype: str, vocab: Vocabulary, others: Sequence[str] = ()) -> Optional[str]:
    """Why `text` is not a valid query of `qtype` for `t`, or not a new wording beside `others`
    (None when it is valid)."""
    if not text or len(text) > 300:
        return "empty or longer than 300 characters"
    if text.strip().lower() in {o.strip().lower() for o in others}:
        return "repeats another wording of the same request"
    named = vocab.names_category(text, t.inst.label, tuple(t.inst.alt_labels))
    if qtype == "ard" and named:
        return f"names the category ({named!r})"
    if qtype != "ard" and not named:
        return "does not name the category"
    return None


async def _model_query(model: Model, library, t: Target, qtype: str, fallback: str, vocab: Vocabulary,
                       seed: int, result: GenerationResult, written: Sequence[str] = ()) -> str:
    """The model's query for `t`, a new wording beside `written` (the intent's earlier wordings);
    `fallback` after `RETRIES` rejected retries."""
    from ..providers.jsonreply import JsonReplyError, parse_json_reply

    rejected = ""
    desc = ", ".join(f"{k}: {v}" for k, v in sorted(t.attributes.items())) or None
    for attempt in range(1 + RETRIES):
        messages = library.render(
            "gen_queries.j2", query_type=qtype, type_rule=TYPE_RULES[qtype], category=t.category,
            room=t.room if "r" in qtype else None, description=desc if "d" in qtype else None,
            caption=t.inst.caption if "d" in qtype else "", tags=t.inst.tags if "d" in qtype else {},
            forbidden=sorted(vocab.forbidden(t.inst.label, tuple(t.inst.alt_labels))) if qtype == "ard" else [],
            attempt=attempt, rejected=rejected, written=list(written))
        try:
            reply = await model.acomplete(messages, ChatOptions(temperature=0.7, seed=seed + attempt))
            text = str(parse_json_reply(reply.text).get("query", "")).strip()
        except (IesmError, JsonReplyError) as exc:
            text, problem = "", str(exc)
        else:
            problem = validate(text, t, qtype, vocab, written)
        if problem is None:
            return text
        result.rejected += 1
        rejected = text or problem
    result.fallbacks += 1
    return fallback


async def _rewrite(model: Model, library, jobs: list[tuple[Target, list[str]]], qtype: str, vocab: Vocabulary,
                   seed: int, result: GenerationResult) -> list[tuple[Target, list[str]]]:
    """The model's wordings for each (target, template wordings) job, one after another within a
    job (each sees the earlier ones), at most 8 calls at a time; a fallback template wording that
    repeats a model wording is replaced by an unused template wording."""
    sem = asyncio.Semaphore(8)

    async def write(k: int, t: Target, templates: list[str]) -> list[str]:
        texts: list[str] = []
        for j, fallback in enumerate(templates):
            async with sem:
                text = await _model_query(model, library, t, qtype, fallback, vocab,
                                          seed * 1000 + k * 100 + j, result, texts)
            if text in texts:
                text = next(w for w in templates if w not in texts)
            texts.append(text)
        return texts

    return list(zip([t for t, _ in jobs],
                    await asyncio.gather(*(write(k, t, texts) for k, (t, texts) in enumerate(jobs))), strict=True))


def _map_ref(given: str, path: Path, out: Path) -> str:
    """How the suite names the map: a shipped name as given, else a path relative to the suite."""
    if not Path(given).is_file():
        return given
    return Path(os.path.relpath(path, out.resolve().parent)).as_posix()


def _append(result: GenerationResult, ref: str, base: str, qtype: str, target: int, texts: Sequence[str],
            accept: Sequence[int]) -> None:
    """One suite line per wording: a lone wording has id `base`; several form the group `base`
    with ids `base-0`, `base-1`, ..."""
    for j, text in enumerate(texts):
        grouped = len(texts) > 1
        result.queries.append(SuiteQuery(id=f"{base}-{j}" if grouped else base, map=ref, query=text, type=qtype,
                                         target=target, accept=list(accept), group=base if grouped else None))


def _add_spatial(result: GenerationResult, scene: SceneMap, ref: str, targets: list[Target],
                 pool: list[Target], per_type: int, rng: random.Random, paraphrases: int, prefix: str) -> None:
    """Append up to `per_type` type-`s` intents of one map to `result`, `paraphrases` wordings each."""
    from ..store.mapstore import MapStore
    from .spatial_queries import spatial_queries

    by_id = {t.inst.id: t.category for t in targets}
    order = [t.inst.id for t in pool]
    rng.shuffle(order)
    found = spatial_queries(MapStore(scene), [by_id[i.id] for i in scene.instances], order, per_type, rng,
                            wordings=paraphrases)
    for k, (ident, q) in enumerate(found):
        _append(result, ref, f"{prefix}{scene.scene_id}-{SPATIAL}-{k:03d}", SPATIAL, ident, q.texts, q.accept)
    result.counts[ref, SPATIAL] = len(found)
    result.shortfalls[ref, SPATIAL] = per_type - len(found)


def check_options(per_type: int, paraphrases: int, prefix: str) -> None:
    """One-line errors for generation options out of range."""
    if per_type < 1:
        raise IesmError("--per-type must be at least 1", "--per-type")
    if not 1 <= paraphrases <= 20:
        raise IesmError(f"--paraphrases must be between 1 and 20, got {paraphrases}", "--paraphrases")
    if prefix and not _PREFIX.match(prefix):
        raise IesmError(f"--id-prefix must be 1-40 letters, digits or '_.-', got {prefix!r}", "--id-prefix")


async def generate_suite(maps: Sequence[str], out: str | Path, types: Sequence[str] = TYPES, *,
                         per_type: int = 10, seed: int = 0, model: Model | None = None,
                         vocab: Vocabulary | None = None, paraphrases: int = 1,
                         id_prefix: str = "") -> GenerationResult:
    """Write a suite of `per_type` intents per type and map to `out` (atomically). With
    `paraphrases` K > 1 each intent gets K distinct wordings sharing a `group` (a target whose
    templates give fewer is skipped); `id_prefix` starts every id and group (suites from two seeds
    evaluated together)."""
    check_options(per_type, paraphrases, id_prefix)
    out = Path(out)
    vocab = vocab or Vocabulary.load()
    library = None
    if model is not None:
        from ..prompting import PromptLibrary

        library = PromptLibrary()
    registry, result = MapRegistry(), GenerationResult()
    for given in maps:
        path = resolve_map_path(given)
        scene = registry.get(path)
        ref = _map_ref(given, path, out)
        keep = set(top_categories(scene, vocab))
        targets = [_target(i, vocab) for i in sorted(scene.instances, key=lambda i: i.id)]
        pool = [t for t in targets if t.category in keep]
        for qtype in types:
            rng = random.Random(f"{seed}|{scene.scene_id}|{qtype}")
            if qtype == SPATIAL:  # template queries only: a rewrite could change the relation
                _add_spatial(result, scene, ref, targets, pool, per_type, rng, paraphrases, id_prefix)
                continue
            eligible = [t for t in pool if answerable(t, qtype)]
            rng.shuffle(eligible)
            jobs: list[tuple[Target, list[str]]] = []
            for t in eligible:
                if len(jobs) == per_type:
                    break
                texts = wordings(t, qtype, targets, vocab, rng, paraphrases)
                if texts:
                    jobs.append((t, texts))
            if model is not None:
                jobs = await _rewrite(model, library, jobs, qtype, vocab, seed, result)
            for k, (t, texts) in enumerate(jobs):
                _append(result, ref, f"{id_prefix}{scene.scene_id}-{qtype}-{k:03d}", qtype, t.inst.id, texts,
                        accept_ids(t, qtype, targets))
            result.counts[ref, qtype] = len(jobs)
            result.shortfalls[ref, qtype] = per_type - len(jobs)
    write_suite(result.queries, out)
    return result
