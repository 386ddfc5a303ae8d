"""`MapStore`: the tool surface over one `SceneMap` (see docs/internals.md).

Lexical scoring (used by `search` and `find_instances(text=...)`): the query is split into
content tokens; each is matched to the map's vocabulary exactly, by singular form, or fuzzily
(rapidfuzz ratio >= 85 for tokens of 4+ characters). Per instance and query token the hit
strength is the best of label (x1.0), tags (x0.7), alternative labels (x0.6), room (x0.6) and
caption (x0.4); tokens are weighted by inverse document frequency. The score is
0.75 * weighted mean hit + 0.25 * label coverage (share of the label's tokens the query names),
in [0, 1]. When the map has embeddings from the model `embeddings.get_encoder()` provides,
`search` adds 0.5 * max(cosine, 0).
"""

from __future__ import annotations


from pathlib import Path
from typing import Any, Optional, Union

import numpy as np
from rapidfuzz import fuzz, process, utils

from ..errors import IesmError
from ..lexicon import words
from .geometry import Boxes, describe_pair, is_under, rests_on
from .model import SceneMap
from .tools import function_schema

CANDIDATE_FIELDS = ("id", "label", "alt_labels", "room", "caption", "tags")
#: geometry an expert spec may request: box `center` [x, y, z] and `size` [dx, dy, dz] (m),
#: `z_range` [bottom, top] (m), `on` / `under`: ids of the instances it rests on / lies under
#: among those sharing its grid cells (multi-occupancy)
GEOMETRY_FIELDS = ("center", "size", "z_range", "on", "under")
VIEW_FIELDS = CANDIDATE_FIELDS + GEOMETRY_FIELDS
TOOLS = ("list_categories", "list_rooms", "find_instances", "get_instance", "instances_near",
         "instances_at", "stacked_with", "search", "relate")
STOPWORDS = frozenset(
    "a an the in on of to at by for from with and or is are be it its this that these those my your our "
    "me i you we please go find show take get where which what one there here near next some".split())
_FIELDS = {"label": 1.0, "tags": 0.7, "alt": 0.6, "room": 0.6, "caption": 0.4}
_EMBED_WEIGHT = 0.5
_UNSET = object()




def _singular(tok: str) -> str:
    if len(tok) > 4 and tok.endswith("ies"):
        return tok[:-3] + "y"
    if len(tok) > 4 and tok.endswith(("ches", "shes", "xes", "sses")):
        return tok[:-2]
    if len(tok) > 3 and tok.endswith("s") and not tok.endswith("ss"):
        return tok[:-1]
    return tok


def embedding_text(label: str, room: Optional[str], caption: str, tags: dict[str, str]) -> str:
    """The text embedded per instance (import time) so that queries can be compared to it."""
    parts = [label] + ([f"in the {room}"] if room else []) + [", ".join(tags.values()), caption]
    return ". ".join(p for p in parts if p)


class MapStore:
    """Query tools over a `SceneMap`; per-instance text and index arrays are precomputed."""

    def __init__(self, scene: SceneMap):
        self.scene = scene
        insts = scene.instances
        self._n = len(insts)
        self._ids = np.array([inst.id for inst in insts], np.int64)
        self._row = {inst.id: i for i, inst in enumerate(insts)}
        self._room_label = [inst.room_label or (self._room_name(inst.room_id)) for inst in insts]
        self._views = [{"id": inst.id, "label": inst.label, "alt_labels": list(inst.alt_labels),
                        "room": room, "caption": inst.caption, "tags": dict(inst.tags)}
                       for inst, room in zip(insts, self._room_label)]
        self._build_text_index()
        self._build_spatial_index()
        self._emb = None
        if scene.embeddings is not None and self._n:
            emb = np.asarray(scene.embeddings, np.float32)
            self._emb = emb / np.maximum(np.linalg.norm(emb, axis=1, keepdims=True), 1e-12)
        self._encoder: Any = _UNSET
        self._query_vecs: dict[str, np.ndarray] = {}
        self._token_hits: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        self._boxes: Optional[Boxes] = None
        self._geometry: dict[int, dict[str, Any]] = {}

    @classmethod
    def load(cls, path: Union[str, Path]) -> "MapStore":
        """Open a `.iesm` file."""
        from .fileformat import load_map

        return cls(load_map(path))

    # ---------------------------------------------------------------- indexes
    def _room_name(self, room_id: Optional[int]) -> Optional[str]:
        return next((r.label for r in self.scene.rooms if r.id == room_id), None) if room_id is not None else None

    def _build_text_index(self) -> None:
        """Vocabulary, per-field postings (vocab index -> instance rows) and idf."""
        field_tokens: dict[str, list[set[str]]] = {f: [] for f in _FIELDS}
        for view in self._views:
            field_tokens["label"].append(set(words(view["label"])))
            field_tokens["alt"].append(set(words(" ".join(view["alt_labels"]))))
            field_tokens["room"].append(set(words(view["room"] or "")))
            field_tokens["tags"].append(set(words(" ".join(view["tags"].values()))))
            field_tokens["caption"].append(set(words(view["caption"])))
        vocab = sorted(set().union(*(s for sets in field_tokens.values() for s in sets)))
        self._vocab = vocab
        self._vocab_index = {t: i for i, t in enumerate(vocab)}
        singular: dict[str, list[int]] = {}
        for i, t in enumerate(vocab):
            singular.setdefault(_singular(t), []).append(i)
        self._singular = singular
        self._postings: dict[str, list[np.ndarray]] = {}
        df = np.zeros(len(vocab), np.int64)
        for f, sets in field_tokens.items():
            rows: list[list[int]] = [[] for _ in vocab]
            for r, toks in enumerate(sets):
                for t in toks:
                    rows[self._vocab_index[t]].append(r)
            self._postings[f] = [np.array(x, np.int64) for x in rows]
        any_field = [set().union(*(field_tokens[f][r] for f in _FIELDS)) for r in range(self._n)]
        for toks in any_field:
            for t in toks:
                df[self._vocab_index[t]] += 1
        self._idf = np.log(1.0 + self._n / np.maximum(df, 1))
        self._label_len = np.array([max(len(s), 1) for s in field_tokens["label"]], np.float64)
        self._labels_proc = [utils.default_process(v["label"]) for v in self._views]
        alt_owner, alt_proc = [], []
        for r, view in enumerate(self._views):
            for alt in view["alt_labels"]:
                alt_owner.append(r)
                alt_proc.append(utils.default_process(alt))
        self._alt_owner, self._alt_proc = np.array(alt_owner, np.int64), alt_proc

    def _build_spatial_index(self) -> None:
        """Occupancy entries grouped by instance row (`_e_span[row]` = slice), cell centres in metres."""
        grid = self.scene.grid
        cells, ids, top = self.scene.occupancy.entries()
        by_id = np.argsort(self._ids)
        entry_row = by_id[np.searchsorted(self._ids[by_id], ids)] if len(ids) else np.zeros(0, np.int64)
        order = np.argsort(entry_row, kind="stable")
        self._e_row, self._e_cell, self._e_top = entry_row[order], cells[order], top[order]
        width = max(grid.width, 1)
        self._e_xy = np.stack([grid.origin[0] + (self._e_cell % width + 0.5) * grid.cell_size,
                               grid.origin[1] + (self._e_cell // width + 0.5) * grid.cell_size], 1)
        rows = np.arange(self._n)
        self._e_span = np.stack([np.searchsorted(self._e_row, rows, "left"),
                                 np.searchsorted(self._e_row, rows, "right")], 1)
        self._centroid_xy = np.array([inst.centroid[:2] if inst.centroid else (np.nan, np.nan)
                                      for inst in self.scene.instances], np.float64).reshape(self._n, 2)

    # ---------------------------------------------------------------- helpers
    def _check_id(self, instance_id: int) -> int:
        try:
            return self._row[int(instance_id)]
        except (KeyError, TypeError, ValueError):
            raise IesmError(f"unknown instance id {instance_id!r}", self.scene.scene_id, "instance_id") from None

    def _brief(self, row: int, **extra: Any) -> dict[str, Any]:
        inst = self.scene.instances[row]
        view = self._views[row]
        out = {"id": inst.id, "label": inst.label, "room": view["room"], "caption": inst.caption,
               "tags": dict(inst.tags)}
        if inst.mean_height is not None:
            out["mean_height"] = round(inst.mean_height, 3)
        if inst.centroid is not None:
            out["centroid"] = [round(c, 3) for c in inst.centroid]
        out.update(extra)
        return out

    def _token_match(self, tok: str) -> tuple[np.ndarray, np.ndarray]:
        """Vocabulary indices matching one query token and their strengths (0, 1]."""
        hit = self._token_hits.get(tok)
        if hit is not None:
            return hit
        idx: dict[int, float] = {}
        if tok in self._vocab_index:
            idx[self._vocab_index[tok]] = 1.0
        for i in self._singular.get(_singular(tok), ()):
            idx.setdefault(i, 0.95)
        if len(tok) >= 4:
            for _, score, i in process.extract(tok, self._vocab, scorer=fuzz.ratio, score_cutoff=85, limit=8):
                idx.setdefault(i, 0.9 * score / 100.0)
        hit = (np.fromiter(idx.keys(), np.int64, len(idx)), np.fromiter(idx.values(), np.float64, len(idx)))
        if len(self._token_hits) < 4096:
            self._token_hits[tok] = hit
        return hit

    def _lexical(self, text: str) -> np.ndarray:
        """(N,) lexical score in [0, 1] of every instance for `text` (see module docstring)."""
        qtoks = list(dict.fromkeys(t for t in words(text) if t not in STOPWORDS))
        total = np.zeros(self._n)
        weight_sum = 0.0
        coverage = np.zeros(self._n)
        for tok in qtoks:
            vidx, strength = self._token_match(tok)
            if len(vidx) == 0:
                weight_sum += float(self._idf.max(initial=1.0))  # unknown words dilute every score alike
                continue
            w = float(self._idf[vidx[np.argmax(strength)]])
            best = np.zeros(self._n)
            for f in _FIELDS:
                for v, s in zip(vidx, strength):
                    rows = self._postings[f][v]
                    if len(rows):
                        np.maximum.at(best, rows, s * _FIELDS[f])
                        if f == "label":
                            coverage[rows] += s
            total += w * best
            weight_sum += w
        if weight_sum == 0:
            return total
        return 0.75 * total / weight_sum + 0.25 * np.minimum(coverage / self._label_len, 1.0)

    def _encoder_for_map(self):
        """The embedding encoder when it matches the map's embeddings, else None (cached)."""
        if self._encoder is _UNSET:
            self._encoder = None
            if self._emb is not None and self.scene.embedding_model:
                try:  # through sys.modules, so tests can substitute the encoder module
                    from ..embeddings import get_encoder
                except ImportError:
                    return None
                try:
                    from ..embeddings import Encoder
                    declared = getattr(Encoder, "name", None)
                except ImportError:
                    declared = None
                if isinstance(declared, str) and declared != self.scene.embedding_model:
                    return None  # another model made the map's embeddings: do not load ours
                enc = get_encoder()
                if enc is not None and enc.name == self.scene.embedding_model and enc.dim == self._emb.shape[1]:
                    self._encoder = enc
        return self._encoder

    def _semantic(self, text: str) -> Optional[np.ndarray]:
        """(N,) cosine similarity of `text` to each instance, or None without a matching encoder."""
        enc = self._encoder_for_map()
        if enc is None:
            return None
        vec = self._query_vecs.get(text)
        if vec is None:
            vec = np.asarray(enc.encode([text]), np.float32)[0]
            if len(self._query_vecs) < 4096:
                self._query_vecs[text] = vec
        return self._emb @ vec

    @staticmethod
    def _ranked(scores: np.ndarray, ids: np.ndarray, limit: int) -> np.ndarray:
        """Row indices by descending score, ties by ascending id, at most `limit`."""
        order = np.lexsort((ids, -scores))
        return order[:max(int(limit), 0)]

    def _room_rows(self, room: Union[int, str]) -> np.ndarray:
        """(N,) bool: instances in the room given by id or (fuzzy) label."""
        if isinstance(room, int) or (isinstance(room, str) and room.strip().isdigit()):
            rid = int(room)
            return np.array([inst.room_id == rid for inst in self.scene.instances], bool)
        query = utils.default_process(room)
        labels = sorted({lab for lab in self._room_label if lab})
        good = {lab for lab in labels
                if max(fuzz.token_set_ratio(query, utils.default_process(lab)),
                       fuzz.WRatio(query, utils.default_process(lab))) >= 80}
        return np.array([lab in good for lab in self._room_label], bool)

    def _category_scores(self, category: str) -> np.ndarray:
        """(N,) in [0, 1]: 0.7 * max(token_set_ratio, WRatio) + 0.3 * ratio over label, 0.9x for alt labels."""
        q = [utils.default_process(category)]

        def score(choices: list[str]) -> np.ndarray:
            if not choices:
                return np.zeros(0)
            loose = np.maximum(process.cdist(q, choices, scorer=fuzz.token_set_ratio)[0],
                               process.cdist(q, choices, scorer=fuzz.WRatio)[0])
            return (0.7 * loose + 0.3 * process.cdist(q, choices, scorer=fuzz.ratio)[0]) / 100.0

        out = score(self._labels_proc).astype(np.float64)
        if len(self._alt_owner):
            np.maximum.at(out, self._alt_owner, 0.9 * score(self._alt_proc))
        return out

    # ---------------------------------------------------------------- tools
    def list_categories(self) -> dict[str, int]:
        """Object categories in the map with their instance counts."""
        counts: dict[str, int] = {}
        for inst in self.scene.instances:
            counts[inst.label] = counts.get(inst.label, 0) + 1
        return dict(sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))

    def list_rooms(self) -> list[dict]:
        """Rooms of the map with their instance counts and floor area in m^2."""
        area = {}
        if self.scene.room_map is not None:
            rm = self.scene.room_map
            ids, counts = np.unique(rm[rm >= 0], return_counts=True)
            area = dict(zip(ids.tolist(), (counts * self.scene.grid.cell_size ** 2).tolist()))
        return [{"id": r.id, "label": r.label,
                 "instances": sum(1 for inst in self.scene.instances if inst.room_id == r.id),
                 "area_m2": round(area.get(r.id, 0.0), 2)} for r in self.scene.rooms]

    def find_instances(self, category: Optional[str] = None, room: Optional[Union[int, str]] = None,
                       text: Optional[str] = None, limit: int = 20) -> list[dict]:
        """Find instances by category, room and/or descriptive text, best match first.

        Args:
            category: object category, matched fuzzily against labels and alternative labels
            room: room label (fuzzy) or room id
            text: words to match against captions, tags and labels
            limit: maximum number of results
        """
        score = np.ones(self._n)
        keep = np.ones(self._n, bool)
        parts = 0
        if category:
            cat = self._category_scores(category)
            keep &= cat >= 0.75
            score, parts = cat, 1
        if room is not None and room != "":
            keep &= self._room_rows(room)
        if text:
            lex = self._lexical(text)
            keep &= lex > 0
            score = lex if parts == 0 else (score + lex) / 2
        rows = self._ranked(np.where(keep, score, -1.0), self._ids, limit)
        return [self._brief(int(r), score=round(float(score[r]), 3)) for r in rows if keep[r]]

    def get_instance(self, instance_id: int) -> dict:
        """All stored attributes of one instance.

        Args:
            instance_id: the instance id
        """
        row = self._check_id(instance_id)
        out = self.scene.instances[row].model_dump()
        out["room"] = self._views[row]["room"]
        return out

    def instances_near(self, x: float, y: float, radius: float = 1.0, limit: int = 20) -> list[dict]:
        """Instances within `radius` metres of the point (x, y), nearest first.

        Args:
            x: world x in metres
            y: world y in metres
            radius: search radius in metres
            limit: maximum number of results
        """
        dist = np.hypot(self._centroid_xy[:, 0] - x, self._centroid_xy[:, 1] - y)
        if len(self._e_cell):
            d = np.hypot(self._e_xy[:, 0] - x, self._e_xy[:, 1] - y)
            has = self._e_span[:, 1] > self._e_span[:, 0]
            dist[has] = np.minimum.reduceat(d, self._e_span[has, 0])
        dist = np.where(np.isnan(dist), np.inf, dist)
        rows = [r for r in self._ranked(-dist, self._ids, self._n) if dist[r] <= radius][:limit]
        return [self._brief(int(r), distance=round(float(dist[r]), 3)) for r in rows]

    def instances_at(self, x: float, y: float) -> list[dict]:
        """Instances stacked in the grid cell containing (x, y), topmost first.

        Args:
            x: world x in metres
            y: world y in metres
        """
        grid, occ = self.scene.grid, self.scene.occupancy
        r, c = grid.cell_of(x, y)
        if not grid.contains(r, c):
            return []
        k = int(np.searchsorted(occ.cells, r * grid.width + c))
        if k >= len(occ.cells) or occ.cells[k] != r * grid.width + c:
            return []
        ids, tops = occ.ids[occ.indptr[k]:occ.indptr[k + 1]], occ.top[occ.indptr[k]:occ.indptr[k + 1]]
        order = np.lexsort((ids, -np.nan_to_num(tops, nan=-np.inf)))
        return [self._brief(self._row[int(ids[i])], top=None if np.isnan(tops[i]) else round(float(tops[i]), 3))
                for i in order]

    def stacked_with(self, instance_id: int) -> dict:
        """Instances sharing grid cells with this one, split into those above and below it.

        Above/below compares per-cell top heights (median over shared cells), falling back to
        mean heights; instances at exactly the same height are left out.

        Args:
            instance_id: the instance id
        """
        row = self._check_id(instance_id)
        s, e = self._e_span[row]
        mine_cells, mine_top = self._e_cell[s:e], self._e_top[s:e]
        shared = np.isin(self._e_cell, mine_cells) & (self._e_row != row)
        others, cells, tops = self._e_row[shared], self._e_cell[shared], self._e_top[shared]
        sorter = np.argsort(mine_cells)
        my_top = mine_top[sorter][np.searchsorted(mine_cells[sorter], cells)]  # my top in each shared cell
        above, below = [], []
        my_mean = self.scene.instances[row].mean_height
        for other in np.unique(others):
            sel = others == other
            diff = np.nanmedian(tops[sel] - my_top[sel]) if np.isfinite(tops[sel] - my_top[sel]).any() else np.nan
            if np.isnan(diff):
                their_mean = self.scene.instances[other].mean_height
                diff = (their_mean - my_mean) if their_mean is not None and my_mean is not None else np.nan
            if np.isnan(diff) or diff == 0:
                continue
            item = self._brief(int(other), shared_cells=int(sel.sum()), height_diff=round(float(diff), 3))
            (above if diff > 0 else below).append(item)
        above.sort(key=lambda d: (d["height_diff"], d["id"]))
        below.sort(key=lambda d: (-d["height_diff"], d["id"]))
        return {"id": int(instance_id), "above": above, "below": below}

    def search(self, text: str, limit: int = 100) -> list[tuple[int, float]]:
        """Rank instances for a free-text query (lexical, plus embeddings when available).

        Args:
            text: the query
            limit: maximum number of (instance id, score) pairs returned
        """
        scores = self.search_scores(text)
        rows = self._ranked(scores, self._ids, limit)
        return [(int(self._ids[r]), float(scores[r])) for r in rows]

    def search_scores(self, text: str) -> np.ndarray:
        """(N,) float: the `search` score of every instance, in `scene.instances` order."""
        scores = self._lexical(text)
        sem = self._semantic(text)
        if sem is not None:
            scores = scores + _EMBED_WEIGHT * np.maximum(sem, 0.0)
        return scores

    def candidate_view(self, instance_id: int, fields: tuple[str, ...] | list[str] = CANDIDATE_FIELDS) -> dict:
        """The fields of one instance an expert may see (`id` always included)."""
        unknown = [f for f in fields if f not in VIEW_FIELDS]
        if unknown:
            raise IesmError(f"unknown candidate field(s) {unknown}; known: {', '.join(VIEW_FIELDS)}",
                            None, "fields")
        row = self._check_id(instance_id)
        view = self._views[row]
        out = {"id": view["id"]}
        for f in fields:
            if f in GEOMETRY_FIELDS:
                out[f] = list(self._geometry_of(row)[f])
                continue
            value = view[f]
            out[f] = list(value) if f == "alt_labels" else dict(value) if f == "tags" else value
        return out

    # ---------------------------------------------------------------- geometry
    @property
    def boxes(self) -> Boxes:
        """Axis-aligned boxes of all instances, scene order (computed once). Footprint: the extent
        of the instance's grid cells (its centroid when it has none); top: the highest per-cell
        top (else the mean height); bottom: 2 * mean height - top, clipped to [0, top] (exact for
        imported boxes, whose mean height is the box centre)."""
        if self._boxes is None:
            half = self.scene.grid.cell_size / 2
            cen = np.array([inst.centroid or (np.nan, np.nan, np.nan) for inst in self.scene.instances],
                           np.float64).reshape(self._n, 3)
            mean = np.array([np.nan if inst.mean_height is None else inst.mean_height
                             for inst in self.scene.instances], np.float64)
            lo, hi = cen[:, :2].copy(), cen[:, :2].copy()
            top = np.full(self._n, np.nan)
            has = self._e_span[:, 1] > self._e_span[:, 0] if self._n else np.zeros(0, bool)
            if has.any():
                starts = self._e_span[has, 0]
                lo[has] = np.minimum.reduceat(self._e_xy, starts) - half
                hi[has] = np.maximum.reduceat(self._e_xy, starts) + half
                top[has] = np.fmax.reduceat(self._e_top.astype(np.float64), starts)
            mean = np.where(np.isnan(mean), cen[:, 2], mean)
            top = np.where(np.isnan(top), mean, top)
            top = np.nan_to_num(top, nan=0.0)
            bottom = np.where(np.isnan(mean), 0.0, np.clip(2 * np.nan_to_num(mean) - top, 0.0, None))
            bottom = np.minimum(bottom, top)
            lo, hi = np.nan_to_num(lo), np.nan_to_num(hi)
            self._boxes = Boxes(self._ids, np.column_stack([lo, bottom]), np.column_stack([hi, top]))
        return self._boxes

    def _shared_rows(self, row: int) -> tuple[np.ndarray, np.ndarray]:
        """(rows, shared cell counts) of the instances sharing grid cells with `row`."""
        s, e = self._e_span[row]
        shared = np.isin(self._e_cell, self._e_cell[s:e]) & (self._e_row != row)
        return np.unique(self._e_row[shared], return_counts=True)

    def _geometry_of(self, row: int) -> dict[str, Any]:
        """Geometry fields of one instance (see `GEOMETRY_FIELDS`), cached; lengths rounded to cm."""
        geo = self._geometry.get(row)
        if geo is None:
            boxes = self.boxes
            me = boxes.take([row])
            others, _ = self._shared_rows(row)
            near = boxes.take(others)
            geo = {"center": np.round(me.center[0], 2).tolist(), "size": np.round(me.size[0], 2).tolist(),
                   "z_range": np.round([me.lo[0, 2], me.hi[0, 2]], 2).tolist(),
                   "on": sorted(near.ids[rests_on(me, near)[0]].tolist()),
                   "under": sorted(near.ids[is_under(me, near)[0]].tolist())}
            self._geometry[row] = geo
        return geo

    def relate(self, a: int, b: int) -> dict:
        """Spatial relation of instance a to instance b: vertical relation (on, supports, under,
        above, below, level), centre distance and footprint gap in metres, whether they are near,
        a's compass direction from b (x east, y north), height difference and shared grid cells.

        Args:
            a: the instance id whose relation is described
            b: the reference instance id
        """
        ra, rb = self._check_id(a), self._check_id(b)
        rows, counts = self._shared_rows(ra)
        shared = int(counts[rows == rb].sum())
        return describe_pair(self.boxes.take([ra]), self.boxes.take([rb]), shared)

    def tool_specs(self) -> list[dict]:
        """JSON schemas ({"name", "description", "parameters"}) of the public tools."""
        return [function_schema(getattr(self, name), name) for name in TOOLS]

    def call_tool(self, name: str, arguments: dict[str, Any]) -> Any:
        """Run tool `name` with JSON `arguments` (for MCP / function-calling front ends)."""
        if name not in TOOLS:
            raise IesmError(f"unknown tool {name!r}; known: {', '.join(TOOLS)}", None, "name")
        try:
            return getattr(self, name)(**arguments)
        except TypeError as exc:
            raise IesmError(f"bad arguments for {name}: {exc}", None, "arguments") from exc
