"""The report page's markup: run facts, the method x query type table (O-SR with n and 95 %
Wilson intervals), paired significance, paraphrase groups, and every query in a filterable table
(rows rendered here, so the page reads without scripts; `assets/report.js` filters the rows and
opens one query with its evidence and its map)."""

from __future__ import annotations

from html import escape

from .page import page
from .shapes import svg_markup


def _text(value) -> str:
    """Any value from a run file as page text: `str` of it, escaped (numbers too: a run directory
    is something people send each other, and a field's type is not the page's to trust)."""
    return escape(str(value))


def _pct(x) -> str:
    return "-" if x is None else f"{100 * x:.1f}"


def _osr_cell(cell: dict) -> str:
    if not cell["n"]:
        return '<td class="num">-</td>'
    return (f'<td class="num" data-n="{_text(cell["n"])}"><span class="osr">{_pct(cell["osr"])}</span>'
            f'<span class="ci">{_pct(cell["lo"])}&ndash;{_pct(cell["hi"])}</span>'
            f'<span class="n">n&nbsp;{_text(cell["n"])}</span></td>')


def metrics_section(data: dict) -> str:
    types = data["types"]
    head = "".join(f'<th scope="col">{escape(t["title"])}</th>' for t in types)
    rows = []
    for m in data["metrics"]:
        cells = "".join(_osr_cell(m["types"][t["id"]]) for t in types)
        rows.append(f'<tr><th scope="row">{escape(m["variant"])}</th>{cells}{_osr_cell(m["overall"])}'
                    f'<td class="num">{m["mrr"]:.3f}</td><td class="num">{_pct(m["top3"])}</td>'
                    f'<td class="num">{_pct(m["nsr"])}</td><td class="num">{_text(m["failures"])}</td></tr>')
    return ('<section id="metrics" aria-labelledby="h-metrics"><h2 id="h-metrics">Success by query type</h2>'
            '<p class="note">O-SR (%) with its 95 % Wilson interval and the number of queries n; MRR and '
            'top-3 over all queries; N-SR (%) over correct retrievals whose trial was judged.</p>'
            '<div class="scroll"><table class="metrics"><caption>O-SR (%) per method and query type</caption>'
            f'<thead><tr><th scope="col">Method</th>{head}<th scope="col">overall</th><th scope="col">MRR</th>'
            '<th scope="col">top-3</th><th scope="col">N-SR</th><th scope="col">queries with failures</th>'
            f'</tr></thead><tbody>{"".join(rows)}</tbody></table></div></section>')


def significance_section(data: dict) -> str:
    tests = data["significance"]
    if not tests:
        return ""
    titles = {t["id"]: t["title"] for t in data["types"]}
    rows = "".join(
        f'<tr class="{"sig" if t["p"] < 0.05 else ""}"><td>{escape(t["a"])}</td><td>{escape(t["b"])}</td>'
        f'<td>{escape(titles.get(t["type"], t["type"]))}</td><td class="num">{_text(t["n"])}</td>'
        f'<td class="num">{_text(t["a_only"])}</td><td class="num">{_text(t["b_only"])}</td><td class="num">{t["p"]:.4f}</td></tr>'
        for t in tests)
    return ('<section id="significance" aria-labelledby="h-sig"><h2 id="h-sig">Paired significance</h2>'
            '<p class="note">Exact two-sided McNemar test on per-query correctness; A only / B only: queries only '
            'that method got right. Rows with p &lt; 0.05 are marked.</p>'
            f'<details{" open" if len(tests) <= 30 else ""}><summary>'
            f'{len(tests)} tests</summary><div class="scroll"><table><caption>Paired tests</caption><thead><tr>'
            '<th scope="col">A</th><th scope="col">B</th><th scope="col">type</th><th scope="col">n</th>'
            '<th scope="col">A only</th><th scope="col">B only</th><th scope="col">p</th></tr></thead>'
            f'<tbody>{rows}</tbody></table></div></details></section>')


def groups_section(data: dict) -> str:
    grouped = [m for m in data["metrics"] if m.get("groups")]
    if not grouped:
        return ""
    rows = "".join(
        f'<tr><th scope="row">{escape(m["variant"])}</th><td class="num">{_text(m["groups"]["overall"]["n"])}</td>'
        f'<td class="num">{_pct(m["groups"]["overall"]["all_correct"])}</td>'
        f'<td class="num">{_pct(m["groups"]["overall"]["consistent_pick"])}</td>'
        f'<td>{escape(", ".join(w["group"] for w in m["groups"].get("worst", [])[:5]))}</td></tr>' for m in grouped)
    return ('<section id="groups" aria-labelledby="h-groups"><h2 id="h-groups">Paraphrase consistency</h2>'
            '<p class="note">Groups of two or more wordings of one intent: all correct = every wording answered '
            'correctly; same pick = every wording picked the same instance (%).</p><div class="scroll"><table>'
            '<caption>Paraphrase groups per method</caption><thead><tr><th scope="col">Method</th>'
            '<th scope="col">groups</th><th scope="col">all correct</th><th scope="col">same pick</th>'
            f'<th scope="col">worst groups</th></tr></thead><tbody>{rows}</tbody></table></div></section>')


def _options(values: list[tuple[str, str]], first: str | None) -> str:
    out = [f'<option value="">{escape(first)}</option>'] if first is not None else []
    return "".join(out + [f'<option value="{escape(v)}">{escape(t)}</option>' for v, t in values])


def _row(i: int, r: dict, titles: dict[str, str]) -> str:
    pred = r["predicted"]
    shown = "nothing" if pred is None else f"#{pred} {r['names'].get(str(pred), '')}".strip()
    mark = "right" if r["correct"] else "wrong"
    return (f'<tr tabindex="0" data-key="{_text(i)}" data-variant="{escape(r["variant"])}" data-type="{escape(r["type"] or "-")}" '
            f'data-correct="{int(r["correct"])}" data-qid="{escape(r["id"])}">'
            f'<td>{escape(r["id"])}</td><td>{escape(r["variant"])}</td>'
            f'<td>{escape(titles.get(r["type"] or "-", r["type"] or "-"))}</td>'
            f'<td class="query">{escape(r["query"])}</td><td>{escape(shown)}</td>'
            f'<td class="{mark}"><span aria-hidden="true">{"&#10003;" if r["correct"] else "&#10007;"}</span> {mark}</td>'
            f'<td class="num">{_text(r["rank"]) if r["rank"] is not None else "-"}</td>'
            f'<td class="num">{len(r["failures"]) or ""}</td></tr>')


def queries_section(data: dict) -> str:
    variants = [(v, v) for v in data["variants"]]
    types = [(t["id"], t["title"]) for t in data["types"]]
    titles = dict(types)
    rows = "".join(_row(i, r, titles) for i, r in enumerate(data["records"]))
    left_out = data["limits"]["rows_left_out"]
    note = (f'<p class="warn">{left_out} more rows are not in this page (at most {data["limits"]["rows"]} '
            "rows); see results.jsonl.</p>") if left_out else ""
    return (
        '<section id="queries" aria-labelledby="h-queries"><h2 id="h-queries">Queries</h2>'
        '<form id="filters" class="filters" role="search" aria-label="Filter the queries">'
        f'<label>Method <select id="f-variant" name="variant">{_options(variants, "all")}</select></label>'
        f'<label>Type <select id="f-type" name="type">{_options(types, "all")}</select></label>'
        '<label>Result <select id="f-result" name="result"><option value="">all</option>'
        '<option value="right">right</option><option value="wrong">wrong</option></select></label>'
        '<fieldset><legend>Changed between</legend>'
        f'<label>A <select id="f-a" name="a">{_options(variants, "-")}</select></label>'
        f'<label>B <select id="f-b" name="b">{_options(variants, "-")}</select></label>'
        '<label>what <select id="f-changed" name="changed"><option value="">-</option>'
        '<option value="result">right / wrong differs</option><option value="a-only">only A right</option>'
        '<option value="b-only">only B right</option><option value="pick">prediction differs</option>'
        '</select></label></fieldset>'
        '<label>Text <input id="f-text" name="text" type="search" placeholder="query or id"></label>'
        '<button type="reset">Clear</button></form>'
        f'<p id="count" role="status" aria-live="polite">{len(data["records"])} rows</p>{note}'
        '<div class="split"><div class="scroll rows"><table id="rows"><caption>Every query under every method '
        '(Enter or click opens one; arrow keys move)</caption><thead><tr><th scope="col">id</th>'
        '<th scope="col">method</th><th scope="col">type</th><th scope="col">query</th><th scope="col">prediction</th>'
        '<th scope="col">result</th><th scope="col">rank</th><th scope="col">failures</th></tr></thead>'
        f'<tbody>{rows}</tbody></table></div>'
        '<aside id="detail" role="region" aria-label="Query details" aria-live="polite" tabindex="-1">'
        '<p class="note">Open a query to see the gate weights, each expert\'s ranking, the fused scores, '
        'the model calls and the map.</p></aside></div></section>')


def header(data: dict) -> str:
    parts = []
    for run in data["runs"]:
        label = f"Run {run['label']}: " if run["label"] else ""
        suites = ", ".join(run["suites"])
        hashes = "".join(f'<li>{escape(v)}: ' + ", ".join(f"{escape(t)} <code>{escape(h)}</code>"
                                                         for t, h in sorted(hs.items())) + "</li>"
                         for v, hs in run["prompt_hashes"].items())
        facts = run["facts"]
        parts.append(f'<p>{escape(label)}<code>{escape(run["directory"])}</code>: provider '
                     f'<code>{escape(str(run["provider"]))}</code>, suites <code>{escape(suites)}</code>'
                     + (f', {_text(facts.get("queries"))} queries, wall {_text(facts.get("wall_s"))} s' if facts else "")
                     + "</p>"
                     + (f"<details><summary>prompt templates by content hash</summary><ul>{hashes}</ul></details>"
                        if hashes else ""))
    limits = data["limits"]
    bound = (f'Self-contained page (no network). Bounded: at most {limits["rows"]} rows, kept prompts and replies '
             f'cut to {limits["message_chars"]} characters each and {limits["prompt_budget"] // 1_000_000} M '
             f'characters in all, maps at most 400 cells a side; the page is refused over '
             f'{limits["page_bytes"] // 1_000_000} MB.')
    if limits["prompts_left_out"]:
        bound += " The prompt budget ran out: later queries show no prompts."
    missing = "".join(f"<li>{escape(k)}: {escape(v)}</li>" for k, v in data["missing_maps"].items())
    return ('<header><h1>Evaluation report</h1>' + "".join(parts)
            + (f'<div class="warn">Maps not drawn:<ul>{missing}</ul></div>' if missing else "")
            + f'<p class="note">{bound}</p><nav aria-label="Sections"><a href="#metrics">Success</a> '
            + ('<a href="#significance">Significance</a> ' if data["significance"] else "")
            + ('<a href="#groups">Paraphrases</a> ' if any(m.get("groups") for m in data["metrics"]) else "")
            + '<a href="#queries">Queries</a></nav></header>')


def report_html(data: dict) -> str:
    """The whole report page for `run_data.report_data(...)`."""
    templates = "".join(f'<template id="map-{key}">{svg_markup(layers, "map " + layers["scene"])}</template>'
                        for key, layers in data["maps"].items())
    # the page's JSON needs no outlines: the templates hold them
    maps = {key: {"scene": m["scene"], "origin": m["origin"], "cell": m["cell"], "height": m["height"],
                  "width": m["width"], "instances": {str(i["id"]): [i["label"], i["room"], i["at"]] for i in m["instances"]}}
            for key, m in data["maps"].items()}
    body = ("<main>" + header(data) + metrics_section(data) + significance_section(data) + groups_section(data)
            + queries_section(data) + "</main>" + templates)
    return page("Evaluation report", body, {**data, "maps": maps}, ["common.js", "report.js"], "report")
