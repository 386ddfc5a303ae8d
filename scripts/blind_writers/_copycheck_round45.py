"""No wording may share a run of 6 words with a caption of its map."""
import json, re, sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import _build_round45 as emit

N = 6


def words(s):
    return re.findall(r"[a-z0-9]+(?:['-][a-z0-9]+)*", s.lower())


def captions(mkey):
    d = json.loads((emit.ROOT / "evals" / "blind" / emit.MAPS[mkey]).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") or "" for o in d["objects"]]
    out = []
    for v in d.values():
        c = v.get("caption", "") or ""
        m = re.search(r'"captions"\s*:\s*"((?:[^"\\]|\\.)*)"', c)
        out.append(m.group(1) if m else c)
    return out


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def main():
    bad = 0
    cache = {}
    for num, mkey, typ, target, accept, spec, qs in emit.G:
        if mkey not in cache:
            cache[mkey] = set().union(*(grams(words(c)) for c in captions(mkey)))
        for k, q in enumerate(qs, 1):
            hit = grams(words(q)) & cache[mkey]
            if hit:
                bad += 1
                print(f"g{num:02d} w{k}: shares {[' '.join(h) for h in hit]}")
    print("copycheck.py:", "PASS" if not bad else f"{bad} wordings share a {N}-word run")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
