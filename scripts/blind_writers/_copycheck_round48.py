"""No wording may share a run of 6 words with any caption of its map (case- and punctuation-
insensitive). For caption maps the caption text is the inner "captions" string (the raw caption
string is also scanned). Exit 1 on any shared run."""
import json
import re
import sys

from _common_round48 import ROOT, load_map

N = 6


def words(text):
    return re.findall(r"[a-z0-9]+", text.lower())


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def captions(field):
    kind, objs, _ = load_map(field)
    out = []
    for o in objs.values():
        raw = o.get("caption") or ""
        out.append(raw)
        if kind == "cap":
            m = re.search(r'"captions"\s*:\s*"(.*?)"\s*[,}]', raw, re.S)
            if m:
                out.append(m.group(1))
    return out


def main():
    rows = [json.loads(l) for l in (ROOT / "evals/blind/round48.jsonl").read_text().splitlines()]
    cache, bad = {}, 0
    for r in rows:
        if r["map"] not in cache:
            g = set()
            for c in captions(r["map"]):
                g |= grams(words(c))
            cache[r["map"]] = g
        shared = grams(words(r["query"])) & cache[r["map"]]
        if shared:
            bad += 1
            print(f"{r['id']}: shares {[' '.join(s) for s in shared]} :: {r['query']}")
    print(f"{len(rows)} wordings checked against {len(cache)} maps; {bad} share a {N}-word run")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
