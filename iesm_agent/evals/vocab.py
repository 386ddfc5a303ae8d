"""The words query generation needs, from the shipped lexicon: what names a category (so an
abstract query can avoid it, judged with the same lemmatiser the offline model reads with),
what an object is used for (affordance cues), and colours/materials for descriptions."""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass
from typing import Optional

from ..lexicon import Lexicon, load_lexicon, read_data

_SPACES = re.compile(r"[\s_\-]+")
_ROOM_NUMBER = re.compile(r"\s*\d+$")
_VOWELS = set("aeiou")
_MATERIAL_ADJECTIVES = {"wood": "wooden", "wool": "woollen", "gold": "golden"}


def normalise(text: str) -> str:
    """Lower case, `_`/`-` as spaces, single spaces."""
    return _SPACES.sub(" ", text.lower()).strip()


def room_name(label: Optional[str]) -> Optional[str]:
    """A room label as a query says it: `Office_2` -> `office`; None stays None."""
    if not label:
        return None
    return _ROOM_NUMBER.sub("", normalise(label)) or None


def gerund(phrase: str) -> str:
    """`sit` -> `sitting`, `store clothes` -> `storing clothes`, `lie down` -> `lying down`."""
    first, _, rest = phrase.partition(" ")
    if first.endswith("ing"):
        word = first
    elif first.endswith("ie"):
        word = first[:-2] + "ying"
    elif first.endswith("e") and not first.endswith("ee") and len(first) > 2:
        word = first[:-1] + "ing"
    elif (len(first) in (3, 4) and first[-1] not in _VOWELS | set("wxy") and first[-2] in _VOWELS
          and first[-3] not in _VOWELS):
        word = first + first[-1] + "ing"
    else:
        word = first + "ing"
    return f"{word} {rest}".strip()


@dataclass
class Vocabulary:
    lex: Lexicon
    uses: dict[str, list[str]]  # canonical category -> "for ..." phrases, one per affordance entry

    @classmethod
    def load(cls) -> "Vocabulary":
        lex = load_lexicon()
        entries = read_data("affordances.json")["entries"]
        groups = read_data("categories.json")["groups"]
        # a cue's first word is a noun when category names start with it ("coffee table") and no
        # other cue uses it as a verb taking an object ("wash hand")
        nouns = {normalise(s).split(" ")[0] for c, syns in groups.items() for s in (c, *syns)}
        verbs = Counter(normalise(c).split(" ")[0] for e in entries for c in e["cues"] if " " in c.strip())
        uses: dict[str, list[str]] = {}
        for entry in entries:
            cue = normalise(entry["cues"][0])
            first = cue.split(" ")[0]
            noun = first in nouns and verbs[first] == (1 if " " in cue else 0)
            for category in entry["core"]:
                uses.setdefault(category, []).append(cue if noun else gerund(cue))
        return cls(lex, uses)

    def _lemmas(self, text: str) -> list[str]:
        return [self.lex.lemma(t) for t in self.lex.tokens(normalise(text))]

    def spoken(self, label: str) -> str:
        """How a person names an instance with raw map label `label`: of '/'-alternatives the first
        the lexicon knows as a category ('window /outside' -> 'window'), and a trailing room word
        moved to the front ('cabinet kitchen' -> 'kitchen cabinet')."""
        parts = [p.strip() for p in normalise(label).split("/") if p.strip()]
        known = [p for p in parts if any(k == "cat" for k, _ in self.lex.phrase(p))]
        words = (known or parts or [normalise(label)])[0].split(" ")
        if len(words) > 1 and any(k == "room" for k, _ in self.lex.phrase(words[-1])):
            words = [words[-1], *words[:-1]]
        return " ".join(words)

    def canonical(self, label: str) -> str:
        cats = [v for k, v in self.lex.phrase(normalise(label)) if k == "cat"]
        return cats[0] if cats else normalise(label)

    def forbidden(self, label: str, alt_labels: tuple[str, ...] = ()) -> set[str]:
        """What an abstract query for `label` must not say: the label and alternative labels and
        their head nouns, the category's synonyms and its more general categories."""
        names = {normalise(label), self.spoken(label), *map(normalise, alt_labels)}
        cats = {self.canonical(n) for n in names}
        cats |= {a for c in cats for a in self.lex.ancestors.get(c, ())}
        surfaces = {" ".join(key) for key, kinds in self.lex.phrases.items()
                    if any(k == "cat" and v in cats for k, v in kinds)}
        return names | cats | surfaces | {t.rsplit(" ", 1)[-1] for t in names | cats}

    def names_category(self, text: str, label: str, alt_labels: tuple[str, ...] = ()) -> Optional[str]:
        """The forbidden term that `text` says (compared as lemmas, so plurals and verb forms
        count), else None."""
        lemmas = self._lemmas(text)
        for term in sorted(self.forbidden(label, alt_labels), key=lambda t: (-len(t), t)):
            key = self._lemmas(term)
            if key and any(lemmas[i:i + len(key)] == key for i in range(len(lemmas) - len(key) + 1)):
                return term
        return None

    def uses_of(self, label: str) -> list[str]:
        """What `label` is used for, as "something for ..." phrases ("sitting", "storing clothes")."""
        return list(dict.fromkeys(self.uses.get(self.canonical(label), [])))

    def attributes(self, tags: dict[str, str], caption: str) -> dict[str, str]:
        """Colour and material of an instance: its tags, else the first the lexicon finds in its caption."""
        spans = self.lex.scan(self._lemmas(caption))
        out = {}
        for kind in ("color", "material"):
            value = tags.get(kind) or (tags.get("colour") if kind == "color" else None)
            if not value:
                value = next((s.values(kind)[0] for s in spans if s.has(kind)), None)
            if value:
                out[kind] = " and ".join(p for p in map(normalise, value.split(",")) if p)
        return out

    @staticmethod
    def adjective(kind: str, value: str) -> str:
        return _MATERIAL_ADJECTIVES.get(value, value) if kind == "material" else value
