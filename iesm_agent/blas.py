"""The English parser's matrix products on numpy's BLAS, in one thread.

thinc multiplies with blis, whose wheel has no kernels for AMD's Zen 3 and later (family 19h): there
it selects its generic ones (`BLIS_ARCH_DEBUG=1` prints "selecting sub-configuration 'generic'"),
about a third of the speed of numpy's OpenBLAS on one thread for the parser's products (a batch of
40 queries: 280 x 288 by 288 x 288). `load_pipeline` loads a spaCy pipeline with every layer on
thinc's `NumpyOps(use_blis=False)`, whose products are numpy's, when numpy's OpenBLAS can be held
to one thread (`one_blas_thread`): with two, its threads spin between the products, which cost the
server more CPU than blis did. The parser's transition steps keep blis (spaCy calls it from C).
Every suite text reads the same either way (`scripts/check_parse_batching.py --blis`).
"""

from __future__ import annotations

import ctypes
from functools import lru_cache
from pathlib import Path

#: OpenBLAS's setter of its thread count: numpy's wheels (scipy-openblas, 64-bit integers), older
#: wheels, a system OpenBLAS
_SETTERS = ("scipy_openblas_set_num_threads64_", "openblas_set_num_threads64_", "openblas_set_num_threads")


@lru_cache(maxsize=1)
def one_blas_thread() -> bool:
    """Hold numpy's OpenBLAS (the one its wheel ships, in `numpy.libs`) to one thread in this
    process; False when there is none with a thread setter loaded (another BLAS, a system numpy,
    no /proc). A matrix product gives the same values on any number of threads (each entry is one
    thread's); only its CPU changes."""
    import numpy

    shipped = Path(numpy.__file__).resolve().parent.with_name("numpy.libs")
    try:
        maps = Path("/proc/self/maps").read_text()
    except OSError:
        return False
    # (address, permissions, offset, device, inode, path): the OpenBLAS libraries loaded
    loaded = dict.fromkeys(Path(line.split(None, 5)[5]) for line in maps.splitlines() if "openblas" in line)
    for path in (p for p in loaded if p.parent == shipped):
        try:
            library = ctypes.CDLL(str(path))
        except OSError:
            continue
        for name in _SETTERS:
            setter = getattr(library, name, None)
            if setter is not None:
                setter(1)
                return True
    return False


def load_pipeline(name: str, **options):
    """`spacy.load(name, **options)`, its layers' matrix products on numpy's BLAS when it runs in
    one thread (else on blis, as shipped)."""
    import spacy

    nlp = spacy.load(name, **options)
    if one_blas_thread():
        from thinc.api import Model, NumpyOps

        ops = NumpyOps(use_blis=False)
        for _, component in nlp.pipeline:
            model = getattr(component, "model", None)  # (the rule-based components have none)
            for layer in model.walk() if isinstance(model, Model) else ():
                layer.ops = ops
    return nlp
