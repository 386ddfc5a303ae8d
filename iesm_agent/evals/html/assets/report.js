// The report: filters over the query rows (method, type, right/wrong, changed between two
// methods or runs, text) and one query opened with its evidence and its map. The state is in
// the URL hash: #variant=..&type=..&result=right|wrong&a=..&b=..&changed=result|a-only|b-only|pick
// &text=..&q=QUERY_ID&qv=METHOD (q opens that query).
(function () {
  const records = DATA.records;
  const rows = Array.from(document.querySelectorAll("#rows tbody tr"));
  const detail = document.getElementById("detail");
  const count = document.getElementById("count");
  const form = document.getElementById("filters");
  const FIELDS = ["variant", "type", "result", "a", "b", "changed", "text"];
  const control = Object.fromEntries(FIELDS.map((f) => [f, document.getElementById("f-" + f)]));
  const byVariant = {};
  records.forEach((r) => { (byVariant[r.variant] = byVariant[r.variant] || {})[r.id] = r; });
  let opened = null;

  function state() {
    const s = Object.fromEntries(FIELDS.map((f) => [f, control[f].value]));
    if (s.changed && (!s.a || !s.b)) {  // a comparison needs two methods: default to the first two
      s.a = s.a || DATA.variants[0] || "";
      s.b = s.b || DATA.variants.find((v) => v !== s.a) || "";
      control.a.value = s.a;
      control.b.value = s.b;
    }
    return s;
  }

  function changed(r, s) {
    if (r.variant !== s.a && r.variant !== s.b) return false;
    const ra = (byVariant[s.a] || {})[r.id], rb = (byVariant[s.b] || {})[r.id];
    if (!ra || !rb) return false;
    if (s.changed === "result") return ra.correct !== rb.correct;
    if (s.changed === "a-only") return ra.correct && !rb.correct;
    if (s.changed === "b-only") return rb.correct && !ra.correct;
    return ra.predicted !== rb.predicted;
  }

  function matches(r, s) {
    if (s.variant && r.variant !== s.variant) return false;
    if (s.type && (r.type || "-") !== s.type) return false;
    if (s.result === "right" && !r.correct) return false;
    if (s.result === "wrong" && r.correct) return false;
    if (s.text) {
      const t = s.text.toLowerCase();
      if (!r.query.toLowerCase().includes(t) && !r.id.toLowerCase().includes(t)) return false;
    }
    if (s.changed && s.a && s.b && s.a !== s.b && !changed(r, s)) return false;
    return true;
  }

  function apply() {
    const s = state();
    let shown = 0;
    for (const tr of rows) {
      const ok = matches(records[+tr.dataset.key], s);
      tr.hidden = !ok;
      shown += ok;
    }
    count.textContent = `${shown} of ${rows.length} rows`;
    document.body.dataset.visibleRows = String(shown);
    const params = hashParams();
    for (const f of FIELDS) { if (s[f]) params.set(f, s[f]); else params.delete(f); }
    setHash(params);
  }

  // ---- one query opened
  function nameOf(r, id) {
    const m = DATA.maps[r.map_key];
    const inst = m && m.instances[String(id)];
    if (inst) return inst[0] + (inst[1] ? ` (${inst[1]})` : "");
    return r.names[String(id)] || "?";
  }

  function idItem(r, id) {
    const accepted = r.accept.includes(id), chosen = id === r.predicted;
    return el("li", {class: (accepted ? "accepted" : "") + (chosen ? " predicted" : "")},
      `#${id} ${nameOf(r, id)}`,
      accepted ? el("span", {class: "tag ok"}, "accepted") : null,
      chosen ? el("span", {class: "tag chosen"}, "chosen") : null);
  }

  function gateTable(r) {
    const experts = Array.from(new Set([...Object.keys(r.gate), ...Object.keys(r.abstained)]));
    if (!experts.length) return el("p", {class: "note"}, "No gate (a single-pass or keyword method).");
    return el("table", {class: "gate"}, el("caption", {}, "Gate weights"),
      el("thead", {}, el("tr", {}, ["expert", "weight (%)", "", "hint"].map((h) => el("th", {scope: "col"}, h)))),
      el("tbody", {}, experts.map((e) => {
        const abst = e in r.abstained;
        const w = abst ? r.abstained[e] : r.gate[e];
        return el("tr", {class: abst ? "abstained" : ""},
          el("th", {scope: "row"}, e + (e === r.deciding_expert ? " (decided)" : "")),
          el("td", {class: "num"}, pct(w)),
          el("td", {class: "barcell"}, el("span", {class: "bar", style: `width:${Math.round(100 * (w || 0))}%`, "aria-hidden": "true"})),
          el("td", {}, abst ? "abstained: weight given to the others" : (r.hints[e] || "")));
      })));
  }

  function expertLists(r) {
    const names = Object.keys(r.experts);
    if (!names.length) return el("p", {class: "note"}, "No expert rankings.");
    return el("div", {class: "experts"}, names.map((e) => el("div", {class: "expert"},
      el("h4", {}, e, e === r.deciding_expert ? el("span", {class: "tag chosen"}, "decided") : null),
      r.experts[e].length ? el("ol", {}, r.experts[e].map((id) => idItem(r, id)))
        : el("p", {class: "note"}, e in r.abstained ? "abstained" : "no ranking"))));
  }

  function fusedTable(r) {
    const ids = Object.keys(r.scores).map(Number);
    if (!ids.length) return el("p", {class: "note"}, "Nothing scored.");
    const f = (x) => (x === undefined ? "-" : Number(x).toFixed(3));
    return el("table", {class: "fused"}, el("caption", {}, "Fused ranking: U (fused), S (sum), P (peak)"),
      el("thead", {}, el("tr", {}, ["#", "instance", "U", "S", "P", ""].map((h) => el("th", {scope: "col"}, h)))),
      el("tbody", {}, ids.map((id, k) => el("tr", {class: id === r.predicted ? "predicted" : ""},
        el("td", {class: "num"}, k + 1), el("td", {}, `#${id} ${nameOf(r, id)}`),
        el("td", {class: "num"}, f(r.scores[id])), el("td", {class: "num"}, f(r.sum_scores[id])),
        el("td", {class: "num"}, f(r.peak_scores[id])),
        el("td", {}, r.accept.includes(id) ? el("span", {class: "tag ok"}, "accepted") : "")))));
  }

  function kept_text(i) {
    return i === null || i === undefined ? "(left out: the page's prompt budget was spent)" : DATA.texts[i];
  }

  function callsSection(r) {
    if (!r.calls.length) return null;
    const table = el("table", {class: "calls"}, el("caption", {}, "Model calls"),
      el("thead", {}, el("tr", {}, ["call", "template", "template hash", "ms", "prompt tokens",
        "of those from the server's cache", "completion tokens (bound)", "cached", "error"]
        .map((h) => el("th", {scope: "col"}, h)))),
      el("tbody", {}, r.calls.map((c) => el("tr", {class: c.error ? "failed" : ""},
        el("td", {}, c.name), el("td", {}, c.template), el("td", {}, el("code", {}, c.template_hash)),
        el("td", {class: "num"}, Math.round(c.latency_ms)), el("td", {class: "num"}, c.prompt_tokens),
        el("td", {class: "num"}, c.cached_tokens ?? 0),
        el("td", {class: "num"}, `${c.completion_tokens}${c.max_tokens ? ` (${c.max_tokens})` : ""}`),
        el("td", {}, c.cached ? "yes" : ""),
        el("td", {}, [c.error || "", ...(c.notes || []).map((n) => el("div", {class: "note"}, n))])))));
    const kept = r.calls.filter((c) => c.messages);
    const prompts = kept.map((c) => el("details", {class: "prompt"}, el("summary", {}, `${c.name}: prompt and reply`),
      c.messages.map((m) => [el("h5", {}, m.role), el("pre", {}, kept_text(m.content))]),
      el("h5", {}, "reply"), el("pre", {}, kept_text(c.reply))));
    return el("section", {}, el("h3", {}, "Calls"), table,
      kept.length ? prompts : el("p", {class: "note"}, "Prompts and replies were not kept (iesm eval --keep-prompts keeps them)."));
  }

  function mapFigure(r) {
    const tpl = document.getElementById("map-" + r.map_key);
    const m = DATA.maps[r.map_key];
    if (!tpl || !m) return el("p", {class: "note"}, "The map of this query is not in the page.");
    const svg = tpl.content.firstElementChild.cloneNode(true);
    const accept = new Set(r.accept.map(String));
    for (const p of svg.querySelectorAll("path.inst")) {
      if (accept.has(p.dataset.id)) p.classList.add("accepted");
      if (p.dataset.id === String(r.predicted)) p.classList.add("predicted");
    }
    const overlay = svg.querySelector("g.overlay");
    const at = (x, y) => [(x - m.origin[0]) / m.cell, m.height - (y - m.origin[1]) / m.cell];
    const radius = Math.max(m.width, m.height) / 45;
    const ring = (id, cls) => {
      const inst = m.instances[String(id)];
      if (inst && inst[2]) overlay.append(svgEl("circle", {cx: inst[2][0], cy: inst[2][1], r: radius, class: cls}));
    };
    r.accept.forEach((id) => ring(id, "ring accepted"));
    if (r.predicted !== null) ring(r.predicted, "ring predicted");
    if (r.nav_path && r.nav_path.length > 1) {
      overlay.append(svgEl("polyline", {class: "path", points: r.nav_path.map(([x, y]) => at(x, y).join(",")).join(" ")}));
    }
    if (r.start) {
      const [x, y] = at(r.start[0], r.start[1]);
      overlay.append(svgEl("circle", {cx: x, cy: y, r: radius / 2, class: "start"}));
    }
    svg.setAttribute("aria-label", `map ${m.scene}: accepted ${r.accept.join(", ")}; prediction ${r.predicted}`);
    return el("figure", {class: "query-map"}, svg, el("figcaption", {},
      el("span", {class: "key accepted"}, "accepted"), el("span", {class: "key predicted"}, "prediction"),
      r.start ? el("span", {class: "key start"}, "robot start and path") : null));
  }

  function render(r) {
    const chosen = r.predicted === null ? "nothing" : `#${r.predicted} ${nameOf(r, r.predicted)}`;
    const facts = [["method", r.variant], ["type", r.type || "-"], ["prediction", chosen],
      ["result", r.correct ? "right" : "wrong"], ["accepted", r.accept.map((id) => `#${id} ${nameOf(r, id)}`).join("; ")],
      ["rank of first accepted", r.rank === null ? "not ranked" : r.rank],
      ["deciding expert", r.deciding_expert || "-"], ["lambda / kappa", `${r.lam === null ? "-" : r.lam.toFixed(2)} / ${r.kappa ?? "-"}`],
      ["latency", `${Math.round(r.latency_ms)} ms`],
      ["tokens", `${r.prompt_tokens ?? 0} prompt (${r.cached_tokens ?? 0} from the server's cache), `
        + `${r.completion_tokens ?? 0} completion`],
      ["candidates", `${(r.candidates_cut ?? 0)} instances cut before the model`]];
    if (r.start) {
      facts.push(["navigation", (r.nav_success === null ? "not judged" : r.nav_success ? "reached" : "failed")
        + (r.path_length_m !== null ? `, path ${r.path_length_m.toFixed(2)} m` : "")]);
    }
    const problems = [...r.failures.map((f) => el("li", {class: "failure"}, f)),
      ...r.notes.map((n) => el("li", {class: "note"}, n))];
    return [
      el("h3", {id: "detail-title"}, `${r.id}: ${r.variant}`),
      el("p", {class: "query-text"}, r.query),
      el("dl", {class: "facts"}, facts.map(([k, v]) => [el("dt", {}, k), el("dd", {}, String(v))])),
      problems.length ? el("section", {}, el("h4", {}, "Failures, fallbacks and notes"), el("ul", {}, problems)) : null,
      mapFigure(r),
      el("section", {}, el("h4", {}, "Gate"), gateTable(r)),
      el("section", {class: "experts-section"}, el("h4", {}, "Experts' top picks"), expertLists(r)),
      el("section", {}, el("h4", {}, "Fusion"), fusedTable(r)),
      callsSection(r),
    ];
  }

  function open(i, focus) {
    const r = records[i];
    if (!r) return;
    opened = i;
    detail.replaceChildren(...render(r).filter(Boolean));
    for (const tr of rows) {
      const on = +tr.dataset.key === i;
      tr.classList.toggle("open", on);
      if (on) tr.setAttribute("aria-current", "true"); else tr.removeAttribute("aria-current");
    }
    document.body.dataset.open = `${r.variant} ${r.id}`;
    const params = hashParams();
    params.set("q", r.id);
    params.set("qv", r.variant);
    setHash(params);
    if (focus) detail.focus();
  }

  // ---- events
  form.addEventListener("change", apply);
  form.addEventListener("input", apply);
  form.addEventListener("reset", () => setTimeout(apply, 0));
  const tbody = document.querySelector("#rows tbody");
  tbody.addEventListener("click", (e) => {
    const tr = e.target.closest("tr");
    if (tr) open(+tr.dataset.key, false);
  });
  tbody.addEventListener("keydown", (e) => {
    const tr = e.target.closest("tr");
    if (!tr) return;
    if (e.key === "Enter" || e.key === " ") { e.preventDefault(); open(+tr.dataset.key, false); return; }
    if (e.key !== "ArrowDown" && e.key !== "ArrowUp") return;
    e.preventDefault();
    const visible = rows.filter((row) => !row.hidden);
    const next = visible[visible.indexOf(tr) + (e.key === "ArrowDown" ? 1 : -1)];
    if (next) next.focus();
  });

  function load() {
    const params = hashParams();
    for (const f of FIELDS) control[f].value = params.get(f) || "";
    apply();
    const q = params.get("q");
    if (q !== null) {
      const v = params.get("qv");
      const i = records.findIndex((r) => r.id === q && (!v || r.variant === v));
      if (i >= 0) {
        open(i, false);
        document.getElementById("queries").scrollIntoView();  // a link to a query shows it
      }
    }
  }
  window.addEventListener("hashchange", () => { if (location.hash.includes("=")) load(); });
  load();
  document.body.dataset.ready = String(Math.round(performance.now()));
})();
