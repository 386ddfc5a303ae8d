"""Check that no wording of round29 shares a run of 6 words with a caption of its map, that every w6 is
lower case and every w3 has no articles.   python3 scripts/copycheck.py   (exit 1 on any hit)"""
import json, re, sys
from pathlib import Path

SUITE = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round29.jsonl"
N = 6


def words(text):
    return re.findall(r"[a-z0-9]+(?:'[a-z]+)?", text.lower())


def captions(mp):
    d = json.loads((SUITE.parent / mp).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption") or "" for o in d["objects"]]
    out = []
    for v in d.values():
        c = v.get("caption") or ""
        m = re.search(r'"captions"\s*:\s*"(.*?)"', c, re.S)
        out.append(m.group(1) if m else c)
    return out


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def main():
    cache, hits = {}, 0
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    for r in rows:
        if r["map"] not in cache:
            cache[r["map"]] = set().union(*(grams(words(c)) for c in captions(r["map"])))
        shared = grams(words(r["query"])) & cache[r["map"]]
        if shared:
            hits += 1
            print(f"COPY {r['id']}: {[' '.join(g) for g in shared]}  | {r['query']}")
        if r["id"].endswith("w6") and r["query"] != r["query"].lower():
            hits += 1; print(f"CASE {r['id']}: {r['query']}")
        if r["id"].endswith("w3") and set(words(r["query"])) & {"a", "an", "the"}:
            hits += 1; print(f"ARTICLE {r['id']}: {r['query']}")
    print(f"{len(rows)} wordings checked, {hits} problems")
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main())
