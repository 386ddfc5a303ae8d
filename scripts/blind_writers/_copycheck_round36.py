"""No wording of round 36 may share a run of 6 words with any caption of its map."""
import json, re, sys
from pathlib import Path

SUITE = Path(__file__).resolve().parent.parent / "evals" / "blind" / "round36.jsonl"
N = 6


def words(text):
    return re.findall(r"[a-z0-9']+", text.lower().replace("-", " "))


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def captions(path):
    d = json.loads(path.read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") for o in d["objects"]]
    out = []
    for v in d.values():
        out.append(v["caption"])  # the whole stored caption text (incl. its JSON wrapper)
    return out


def main():
    cache, bad, n = {}, 0, 0
    for line in SUITE.read_text().splitlines():
        row = json.loads(line)
        path = (SUITE.parent / row["map"]).resolve()
        if row["map"] not in cache:
            cg = set()
            for c in captions(path):
                cg |= grams(words(c))
            cache[row["map"]] = cg
        n += 1
        hit = grams(words(row["query"])) & cache[row["map"]]
        if hit:
            bad += 1
            print(row["id"], "shares", [" ".join(h) for h in hit])
    print(f"{n} wordings checked, {bad} share a {N}-word run with a caption")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
