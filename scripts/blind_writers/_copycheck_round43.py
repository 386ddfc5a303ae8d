"""No wording of round43 may share a run of 6 words with a caption of its map.
    python3 scripts/copycheck.py"""
import json, re, sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SUITE = ROOT / "evals" / "blind" / "round43.jsonl"
N = 6


def words(text):
    return re.findall(r"[a-z0-9]+(?:'[a-z]+)?", text.lower())


def grams(text):
    w = words(text)
    return {tuple(w[i:i + N]) for i in range(len(w) - N + 1)}


def captions(mp):
    data = json.loads((SUITE.parent / mp).resolve().read_text())
    out = []
    if isinstance(data, dict) and "objects" in data:
        out = [o.get("caption", "") or "" for o in data["objects"]]
    else:
        for v in data.values():
            c = v.get("caption", "")
            out.append(c)  # the raw caption string (JSON text) holds the caption sentence itself
    return out


def main():
    cache, bad = {}, 0
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    for r in rows:
        if r["map"] not in cache:
            g = set()
            for c in captions(r["map"]):
                g |= grams(c)
            cache[r["map"]] = g
        shared = grams(r["query"]) & cache[r["map"]]
        if shared:
            bad += 1
            print(r["id"], r["query"], "->", [" ".join(s) for s in shared])
    print(f"{len(rows)} wordings checked, {bad} share a {N}-word run with a caption of their map")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
