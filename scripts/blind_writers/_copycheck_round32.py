"""No wording may share a run of 6 words with a caption of its map.

    python3 scripts/copycheck.py [N]   (N = run length, default 6; also lists the longest shared run)
"""
import json, re, sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from show import cap_fields  # noqa: E402

SUITE = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round32.jsonl"
N = int(sys.argv[1]) if len(sys.argv) > 1 else 6


def words(text):
    return re.findall(r"[a-z0-9']+", text.lower().replace("'s", ""))


def captions(map_path):
    data = json.loads(map_path.read_text(encoding="utf-8"))
    if "objects" in data:
        return [o.get("caption") or "" for o in data["objects"]]
    return [cap_fields(v)["captions"] for v in data.values()]


cache, bad, longest = {}, 0, []
for line in SUITE.read_text(encoding="utf-8").splitlines():
    row = json.loads(line)
    if row["map"] not in cache:
        caps = captions((SUITE.parent / row["map"]).resolve())
        grams = {}
        for c in caps:
            w = words(c)
            for k in range(1, len(w) + 1):
                for i in range(len(w) - k + 1):
                    grams.setdefault(k, set()).add(tuple(w[i:i + k]))
        cache[row["map"]] = grams
    grams, w = cache[row["map"]], words(row["query"])
    best = 0
    for k in range(1, len(w) + 1):
        if any(tuple(w[i:i + k]) in grams.get(k, ()) for i in range(len(w) - k + 1)):
            best = k
        else:
            break
    longest.append((best, row["id"], row["query"]))
    if best >= N:
        bad += 1
        print(f"COPY {row['id']}: shares a {best}-word run with a caption: {row['query']}")
longest.sort(reverse=True)
print("longest shared runs:", [(b, i) for b, i, _ in longest[:5]])
print("copycheck.py:", f"FAIL ({bad})" if bad else f"no wording shares a {N}-word run with a caption of its map")
sys.exit(1 if bad else 0)
