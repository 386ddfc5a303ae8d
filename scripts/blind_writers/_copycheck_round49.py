"""No wording may share a run of 6 words with any caption of its map. Also checks the style rules
(w1 imperative, w2 'Could ...?', w3 no articles, w5 two sentences 'This is/These are', w6 lower case)."""
import json, re, sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SUITE_DIR = ROOT / "evals/blind"
N = 6


def words(t): return re.findall(r"[a-z0-9]+(?:['-][a-z0-9]+)*", t.lower())


def captions(mp):
    d = json.loads((SUITE_DIR / mp).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") or "" for o in d["objects"]]
    out = []
    for v in d.values():
        c = v.get("caption", "")
        try:
            c = json.loads(c).get("captions", c) + " " + c
        except Exception:
            pass
        out.append(c)
    return out


def grams(ws): return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def main():
    cache, bad, style = {}, [], []
    for line in (SUITE_DIR / "round49.jsonl").read_text().splitlines():
        r = json.loads(line)
        if r["map"] not in cache:
            cache[r["map"]] = set().union(*(grams(words(c)) for c in captions(r["map"])))
        hit = grams(words(r["query"])) & cache[r["map"]]
        if hit:
            bad.append(f"{r['id']}: shares {[' '.join(h) for h in hit]}")
        q, w = r["query"], r["id"][-2:]
        if w == "w1" and not re.match(r"(Go|Take|Bring|Lead|Show)\b", q): style.append(f"{r['id']} w1 not imperative")
        if w == "w2" and not (q.startswith("Could") and q.endswith("?")): style.append(f"{r['id']} w2 not polite question")
        if w == "w3" and (re.search(r"\b(a|an|the)\b", q.lower()) or len(q.split()) > 6): style.append(f"{r['id']} w3 not telegraphic")
        if w == "w5" and not (re.match(r"(This is|These are)", q) and len(re.findall(r"[.!?](\s|$)", q)) == 2): style.append(f"{r['id']} w5 not two sentences")
        if w == "w6" and q != q.lower(): style.append(f"{r['id']} w6 not lower case")
    for x in bad + style:
        print(x)
    print("copycheck: OK" if not (bad or style) else f"copycheck: {len(bad)} copy hits, {len(style)} style issues")
    return 1 if bad or style else 0


if __name__ == "__main__":
    sys.exit(main())
