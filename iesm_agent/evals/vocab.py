"""The words query generation needs, from the shipped lexicon: what names a category (so an
abstract query can avoid it, judged with the same lemmatiser the offline model reads with),
what an object is used for (`purposes`), and colours/materials for descriptions."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Optional

from ..lexicon import Lexicon, load_lexicon
from .purposes import purposes_of

_SPACES = re.compile(r"[\s_\-]+")
_ROOM_NUMBER = re.compile(r"\s*\d+$")
_MATERIAL_ADJECTIVES = {"wood": "wooden", "wool": "woollen", "gold": "golden"}
_PARTS = re.compile(r"\s*(?:,|\band\b)\s*")
#: at most this many words of a kind in a description ("black and white", one material)
_MOST = {"color": 2, "material": 1}


def normalise(text: str) -> str:
    """Lower case, `_`/`-` as spaces, single spaces."""
    return _SPACES.sub(" ", text.lower()).strip()


def room_name(label: Optional[str]) -> Optional[str]:
    """A room label as a query says it: `Office_2` -> `office`; None stays None."""
    if not label:
        return None
    return _ROOM_NUMBER.sub("", normalise(label)) or None


@dataclass
class Vocabulary:
    lex: Lexicon

    @classmethod
    def load(cls) -> "Vocabulary":
        return cls(load_lexicon())

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
        """What `label` is for, as phrases that follow "for" ("sitting on", "heating up leftovers"):
        `purposes.PURPOSES` of its category or of a more general one."""
        category = self.canonical(label)
        return purposes_of([category, *sorted(self.lex.ancestors.get(category, ()))])

    def attributes(self, tags: dict[str, str], caption: str) -> dict[str, str]:
        """Colour and material of an instance as a person says them: its tags, else the first the
        lexicon finds in its caption; only the parts the lexicon reads as that kind ("light colored",
        "high gloss material" dropped), at most two colours and one material, no material word
        already said by the colour ("dark wood")."""
        spans = self.lex.scan(self._lemmas(caption))
        out: dict[str, str] = {}
        for kind in ("color", "material"):
            value = tags.get(kind) or (tags.get("colour") if kind == "color" else None)
            if not value:
                value = next((s.values(kind)[0] for s in spans if s.has(kind)), None)
            said = set(out.get("color", "").split())
            parts = [p for p in dict.fromkeys(_PARTS.split(normalise(value or ""))) if p
                     and any(s.has(kind) for s in self.lex.scan(self._lemmas(p))) and not set(p.split()) & said]
            if parts:
                out[kind] = " and ".join(parts[:_MOST[kind]])
        return out

    @staticmethod
    def adjective(kind: str, value: str) -> str:
        return _MATERIAL_ADJECTIVES.get(value, value) if kind == "material" else value
