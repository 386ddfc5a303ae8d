"""Report any wording in a suite that shares a run of N (default 6) consecutive words with a caption
of its own map; also print the longest shared run per line when --verbose.

    python3 scripts/copycheck.py evals/blind/round60.jsonl [--n 6] [--verbose]
"""
import argparse
import json
import re
from pathlib import Path

SUITE_DIR = Path(__file__).resolve().parents[2] / "evals" / "blind"
STORE = Path(__file__).resolve().parents[2] / "map_store"


def words(text):
    return re.findall(r"[a-z0-9]+", text.lower())


def map_path(name):
    p = (SUITE_DIR / name).resolve()
    if not p.is_file() and "/" not in name:
        p = STORE / f"{name}.json"
    return p


def captions(path):
    data = json.loads(path.read_text(encoding="utf-8"))
    out = []
    if isinstance(data, dict) and "objects" in data:
        for o in data["objects"]:
            if o.get("caption"):
                out.append(o["caption"])
    else:
        for v in data.values():
            raw = v.get("caption", "")
            out.append(raw)  # the raw string (covers the captions text inside it too)
            m = re.search(r'"captions"\s*:\s*"(.*?)"', raw, re.S)
            if m:
                out.append(m.group(1))
    return out


def longest_run(q, caps):
    qw = words(q)
    best = 0
    for c in caps:
        cw = words(c)
        # longest common substring over word sequences
        prev = [0] * (len(cw) + 1)
        for i in range(1, len(qw) + 1):
            cur = [0] * (len(cw) + 1)
            for j in range(1, len(cw) + 1):
                if qw[i - 1] == cw[j - 1]:
                    cur[j] = prev[j - 1] + 1
                    best = max(best, cur[j])
            prev = cur
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("suite", type=Path)
    ap.add_argument("--n", type=int, default=6)
    ap.add_argument("--verbose", action="store_true")
    a = ap.parse_args()
    cache = {}
    bad = 0
    hist = {}
    for line in a.suite.read_text(encoding="utf-8").splitlines():
        r = json.loads(line)
        if r["map"] not in cache:
            cache[r["map"]] = captions(map_path(r["map"]))
        run = longest_run(r["query"], cache[r["map"]])
        hist[run] = hist.get(run, 0) + 1
        if run >= a.n:
            bad += 1
            print(f"COPY {r['id']}: {run}-word run shared with a caption: {r['query']}")
        elif a.verbose:
            print(f"{r['id']}: longest shared run {run}")
    print(f"longest-shared-run histogram {dict(sorted(hist.items()))}; {bad} lines with a run >= {a.n}")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
