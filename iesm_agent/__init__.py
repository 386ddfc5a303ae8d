"""iesm-agent: goal retrieval over instance-enriched 2.5D semantic maps (IESM + MTEFR).

Heavy modules are imported lazily so that `iesm` starts fast.
"""

__version__ = "0.1.0"
