"""Shared query understanding: what a query asks for and what map labels, rooms and candidate records denote (lexicon
first, sentence embeddings for words the lexicon does not know). Used by every provider's prompts as well as by
candidate selection; depends only on the lexicon and the encoder."""

from .grounding import ground_query, label_kinds, map_word
from .labels import Record, candidate_from_line, label_concepts, room_of, text_slots
from .query import QueryInfo, analyse_query, parse_queries
from .text import Slot, stem

__all__ = ["QueryInfo", "Record", "Slot", "analyse_query", "candidate_from_line", "ground_query",
           "label_concepts", "label_kinds", "map_word", "parse_queries", "room_of", "stem", "text_slots"]
