"""No wording may share a run of 6 words with any caption of its map. Run: python3 copycheck.py"""
import json, re, sys
from pathlib import Path

SUITE = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round38.jsonl"
N = 6
words = lambda s: re.findall(r"[a-z0-9]+", s.lower())


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def captions(mp):
    p = (SUITE.parent / mp).resolve()
    if not p.is_file():
        p = SUITE.parent / mp
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") or "" for o in d["objects"]]
    return [v.get("caption", "") for v in d.values()]  # raw caption text incl. the embedded captions field


def main():
    cache, bad = {}, 0
    for line in SUITE.read_text().splitlines():
        r = json.loads(line)
        if r["map"] not in cache:
            g = set()
            for c in captions(r["map"]):
                g |= grams(words(c))
            cache[r["map"]] = g
        shared = grams(words(r["query"])) & cache[r["map"]]
        if shared:
            bad += 1
            print("COPY", r["id"], r["query"], "::", [" ".join(s) for s in shared])
    print(f"{bad} wordings share a {N}-word run with a caption")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
