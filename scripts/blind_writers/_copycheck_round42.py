"""No wording may share a run of 6 words with a caption of its map. python3 copycheck.py"""
import json, re, sys
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"
N = 6


def words(t):
    return re.findall(r"[a-z0-9]+", t.lower())


def captions(path):
    d = json.loads(path.read_text())
    out = []
    if isinstance(d, dict) and "objects" in d:
        out = [o.get("caption", "") or "" for o in d["objects"]]
    else:
        for v in d.values():
            c = v.get("caption", "") or ""
            out.append(c)  # raw string (contains the inner JSON with the captions text)
            m = re.search(r'"captions"\s*:\s*"(.*?)"', c, re.S)
            if m:
                out.append(m.group(1))
    return out


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def main():
    suite = BLIND / "round42.jsonl"
    cache, bad, n = {}, 0, 0
    for line in suite.read_text().splitlines():
        r = json.loads(line)
        if r["map"] not in cache:
            p = BLIND / r["map"]
            cache[r["map"]] = set().union(*[grams(words(c)) for c in captions(p)]) if p.is_file() else set()
        hit = grams(words(r["query"])) & cache[r["map"]]
        n += 1
        if hit:
            bad += 1
            print(r["id"], r["query"], "->", [" ".join(h) for h in hit])
    print(f"{n} wordings checked, {bad} share a {N}-word run with a caption of their map")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
