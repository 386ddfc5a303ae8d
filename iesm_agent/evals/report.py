"""Run outputs: `summary.json`, `report.md` (paper Table 4 style O-SR table, ranking and cost,
paired significance) and a PNG bar chart of O-SR by type per variant."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from ..errors import IesmError
from ..fileio import pyplot, save_figure, write_text
from .query_types import ordered_types, type_title

PLOT = "osr_by_type.png"


def _pct(value) -> str:
    return "-" if value is None else f"{100 * value:.1f}"


def render_markdown(summary: dict, plot: str | None) -> str:
    methods, types = summary["methods"], summary["types"]
    lines = ["# Evaluation report", ""]
    run = summary.get("run", {})
    if run:
        lines += [f"Provider `{run.get('provider')}`, suites {', '.join(f'`{s}`' for s in run.get('suites', []))}, "
                  f"{run.get('queries')} queries x {len(methods)} variants.", ""]
    lines += ["## Object retrieval success rate (O-SR, %) by query type", "",
              "| Method | " + " | ".join(type_title(t) for t in types) + " | type mean | overall |",
              "|---|" + "---:|" * (len(types) + 2)]
    for name, m in methods.items():
        cells = [_pct(m["by_type"][t]["osr"]) if t in m["by_type"] else "-" for t in types]
        lines.append(f"| {name} | " + " | ".join(cells)
                     + f" | {_pct(m['overall']['osr_type_mean'])} | {_pct(m['overall']['osr'])} |")
    lines += ["", "Queries per type: " + ", ".join(
        f"{type_title(t)} {next(iter(methods.values()))['by_type'][t]['n']}" for t in types), ""]
    if plot:
        lines += [f"![O-SR by query type]({plot})", ""]
    lines += ["## Ranking and cost", "",
              "| Method | n | MRR | top-3 (%) | latency p50 (ms) | latency mean (ms) | prompt tokens "
              "| of those cached by the server | completion tokens | cache hits | queries with failures "
              "| candidates cut | candidate recall (%) |",
              "|---|" + "---:|" * 12]
    for name, m in methods.items():
        o = m["overall"]
        lines.append(f"| {name} | {o['n']} | {o['mrr']:.3f} | {_pct(o['top3'])} | {o['latency_ms_p50']:.1f} "
                     f"| {o['latency_ms_mean']:.1f} | {o.get('prompt_tokens', 0)} | {o.get('cached_tokens', 0)} "
                     f"| {o.get('completion_tokens', 0)} | {o['cache_hits']} "
                     f"| {o['queries_with_failures']} | {o.get('candidates_cut', 0)} | {_pct(o['candidate_recall'])} |")
    if any(m["overall"].get("nsr") is not None for m in methods.values()):
        lines += ["", "## Navigation success given correct retrieval (N-SR, %)", "",
                  "| Method | " + " | ".join(type_title(t) for t in types) + " | overall |",
                  "|---|" + "---:|" * (len(types) + 1)]
        for name, m in methods.items():
            cells = [_pct(m["by_type"].get(t, {}).get("nsr")) for t in types]
            lines.append(f"| {name} | " + " | ".join(cells) + f" | {_pct(m['overall']['nsr'])} |")
    if summary["significance"]:
        lines += ["", "## Paired significance (exact McNemar, two-sided)", "",
                  "`A only` / `B only`: queries only that variant got right.", "",
                  "| A | B | type | n | A only | B only | p |", "|---|---|---|---:|---:|---:|---:|"]
        for t in summary["significance"]:
            title = type_title(t["type"])
            lines.append(f"| {t['a']} | {t['b']} | {title} | {t['n']} | {t['a_only']} | {t['b_only']} | {t['p']:.4f} |")
    lines += _paraphrase_lines(methods)
    invalid = summary.get("invalid_lines", [])
    if invalid:
        lines += ["", f"## Skipped suite lines ({len(invalid)})", ""] + [f"- {e}" for e in invalid]
    return "\n".join(lines) + "\n"


def _paraphrase_lines(methods: dict) -> list[str]:
    """The paraphrase-consistency section (empty when no method has groups): shares per method,
    overall and per query type, then each method's worst groups with their wordings and picks."""
    grouped = {name: m["groups"] for name, m in methods.items() if "groups" in m}
    if not grouped:
        return []
    first = next(iter(grouped.values()))
    types = ordered_types({t for g in grouped.values() for t in g["by_type"]})
    lines = ["", "## Paraphrase consistency (%)", "",
             f"{first['overall']['n']} groups of two or more wordings ({first['overall']['wordings']} lines). "
             "All correct: every wording answered correctly; same pick: every wording picked the same instance. "
             "Per type: all correct / same pick.", "",
             "| Method | O-SR | all correct | same pick | " + " | ".join(type_title(t) for t in types) + " |",
             "|---|" + "---:|" * (3 + len(types))]
    for name, g in grouped.items():
        cells = [f"{_pct(g['by_type'][t]['all_correct'])} / {_pct(g['by_type'][t]['consistent_pick'])}"
                 if t in g["by_type"] else "-" for t in types]
        lines.append(f"| {name} | {_pct(methods[name]['overall']['osr'])} | {_pct(g['overall']['all_correct'])} "
                     f"| {_pct(g['overall']['consistent_pick'])} | " + " | ".join(cells) + " |")
    for name, g in grouped.items():
        if not g["worst"]:
            continue
        lines += ["", f"### Worst groups: {name}", ""]
        for w in g["worst"]:
            lines.append(f"- `{w['group']}` {type_title(w['type'])}: {w['correct']}/{w['n']} correct")
            lines += [f"  - {'ok ' if r['correct'] else 'MISS'} `{r['id']}` {r['query']!r} -> {r['predicted']}"
                      for r in w["wordings"]]
    return lines


def plot_osr(summary: dict, path: Path) -> bool:
    """Grouped bar chart of O-SR by type per variant; False when matplotlib is missing."""
    try:
        plt = pyplot()
    except IesmError:
        return False
    methods, types = summary["methods"], summary["types"]
    width = 0.8 / max(len(methods), 1)
    fig, ax = plt.subplots(figsize=(2.8 + 1.3 * len(types), 3.2), dpi=80)
    for k, (name, m) in enumerate(methods.items()):
        values = [100 * m["by_type"].get(t, {}).get("osr", 0.0) for t in types]
        ax.bar([i + (k - (len(methods) - 1) / 2) * width for i in range(len(types))], values, width, label=name)
    ax.set_xticks(range(len(types)), [type_title(t) for t in types])
    ax.set_ylabel("O-SR (%)")
    ax.set_ylim(0, 100)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    fig.tight_layout()
    save_figure(fig, path, dpi=80, tight=False)
    return True


def write_outputs(run_dir: Path, summary: dict) -> None:
    """summary.json, report.md, the plot and report.html (from the files of `run_dir`) into `run_dir`."""
    from .html import REPORT, write_report  # the page reads the run back from its files

    plotted = bool(summary["types"]) and plot_osr(summary, run_dir / PLOT)
    write_text(run_dir / "summary.json", json.dumps(summary, indent=2) + "\n")
    write_text(run_dir / "report.md", render_markdown(summary, PLOT if plotted else None))
    try:  # the run's results stand without the page: a page that cannot be written is a warning
        write_report([run_dir], run_dir / REPORT)
    except IesmError as exc:
        print(f"iesm: warning: {REPORT} not written: {exc}", file=sys.stderr)
