// The map viewer: hover or click an instance for its label, room, caption and tags; a search
// box over labels, rooms, captions and tags dims the rest and lists the hits. #q=TEXT and
// #id=N in the URL set the search and the selected instance on load.
(function () {
  const instances = new Map(DATA.instances.map((i) => [String(i.id), i]));
  const svg = document.querySelector("svg.map");
  const info = document.getElementById("info");
  const input = document.getElementById("q");
  const hits = document.getElementById("hits");
  const results = document.getElementById("results");
  const paths = Array.from(svg.querySelectorAll("path.inst"));
  let pinned = null;

  function show(id) {
    const inst = instances.get(String(id));
    if (!inst) return;
    const tags = Object.entries(inst.tags || {});
    info.replaceChildren(
      el("h2", {}, `#${inst.id} ${inst.label}`),
      el("dl", {},
        el("dt", {}, "room"), el("dd", {}, inst.room || "none"),
        el("dt", {}, "caption"), el("dd", {}, inst.caption || "none"),
        el("dt", {}, "tags"), el("dd", {}, tags.length ? tags.map(([k, v]) => `${k}: ${v}`).join("; ") : "none")));
    for (const p of paths) p.classList.toggle("selected", p.dataset.id === String(id));
    document.body.dataset.selected = String(id);
  }

  function pick(id) {
    pinned = String(id);
    show(id);
    const params = hashParams();
    params.set("id", pinned);
    setHash(params);
  }

  svg.addEventListener("mouseover", (e) => {
    const p = e.target.closest("path.inst");
    if (p && pinned === null) show(p.dataset.id);
  });
  svg.addEventListener("click", (e) => {
    const p = e.target.closest("path.inst");
    if (p) pick(p.dataset.id);
  });

  function matches(inst, text) {
    const hay = [inst.label, inst.room || "", inst.caption || "", ...Object.values(inst.tags || {})].join(" ").toLowerCase();
    return hay.includes(text);
  }

  function search(text) {
    text = text.trim().toLowerCase();
    const found = text ? DATA.instances.filter((i) => matches(i, text)) : [];
    const ids = new Set(found.map((i) => String(i.id)));
    for (const p of paths) p.classList.toggle("dim", text !== "" && !ids.has(p.dataset.id));
    svg.classList.toggle("searching", text !== "");
    hits.textContent = text ? `${found.length} of ${DATA.instances.length} instances match` : "";
    document.body.dataset.hits = text ? String(found.length) : "";
    results.replaceChildren(...found.slice(0, 50).map((i) =>
      el("li", {}, el("button", {type: "button", "data-id": i.id}, `#${i.id} ${i.label}` + (i.room ? ` (${i.room})` : "")))));
    const params = hashParams();
    if (text) params.set("q", text); else params.delete("q");
    setHash(params);
  }

  results.addEventListener("click", (e) => {
    const b = e.target.closest("button[data-id]");
    if (b) pick(b.dataset.id);
  });
  input.addEventListener("input", () => search(input.value));

  function load() {
    const params = hashParams();
    input.value = params.get("q") || "";
    search(input.value);
    if (params.get("id")) pick(params.get("id"));
  }
  window.addEventListener("hashchange", load);
  load();
  document.body.dataset.ready = String(Math.round(performance.now()));
})();
