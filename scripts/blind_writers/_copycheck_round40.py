"""Flag any wording of round40 that shares a run of N (default 6) words with a caption of its map."""
import json, re, sys
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"
N = int(sys.argv[1]) if len(sys.argv) > 1 else 6


def words(text):
    return re.findall(r"[a-z0-9']+", text.lower())


def grams(ws, n):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}


def captions(mp):
    data = json.loads((BLIND / mp).resolve().read_text())
    if isinstance(data, dict) and "objects" in data:
        return [o.get("caption", "") or "" for o in data["objects"]]
    out = []
    for v in data.values():
        try:
            out.append(json.loads(v["caption"]).get("captions", ""))
        except Exception:
            out.append(v["caption"])
    return out


def main():
    cache, hits, n = {}, 0, 0
    for line in (BLIND / "round40.jsonl").read_text().splitlines():
        row = json.loads(line)
        if row["map"] not in cache:
            g = set()
            for c in captions(row["map"]):
                g |= grams(words(c), N)
            cache[row["map"]] = g
        n += 1
        shared = grams(words(row["query"]), N) & cache[row["map"]]
        if shared:
            hits += 1
            print(row["id"], "|", row["query"], "|", [" ".join(s) for s in shared])
    print(f"{n} wordings checked, {hits} share a {N}-word run with a caption")
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main())
