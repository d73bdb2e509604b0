// The module graph: modules in layers by dependency (a module sits below the providers of what it
// requires), edges provider -> consumer, each module's time per frame; and the providers table,
// whose selects run `mr <Rep> <Module>`.

const SVG = "http://www.w3.org/2000/svg";
const BOX_W = 128, BOX_H = 40, OFF_H = 17, GAP_X = 12, GAP_Y = 26;

// Time per frame, in the unit that reads: 0.38 us, 12.5 us, 0.41 ms.
function formatMs(ms) {
  if (typeof ms !== "number") return "";
  return ms >= 0.1 ? `${ms.toFixed(2)} ms` : `${(ms * 1000).toFixed(ms >= 0.01 ? 0 : 2)} \u00b5s`;
}

function svg(tag, attrs, parent) {
  const el = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
  if (parent) parent.appendChild(el);
  return el;
}

// Layer of each active module: 0 for those needing nothing provided, else 1 + their providers' max.
function layers(modules, providerOf) {
  const layer = new Map();
  const visiting = new Set();
  const depth = (m) => {
    if (layer.has(m.name)) return layer.get(m.name);
    if (visiting.has(m.name)) return 0; // a cycle: the bridge reports it; draw it flat
    visiting.add(m.name);
    let d = 0;
    for (const rep of m.requires || []) {
      const p = modules.find((x) => x.name === providerOf.get(rep));
      if (p && p !== m) d = Math.max(d, depth(p) + 1);
    }
    visiting.delete(m.name);
    layer.set(m.name, d);
    return d;
  };
  for (const m of modules) depth(m);
  return layer;
}

export class ModuleGraph {
  constructor(svgEl, detail, table, consolePane, refreshTree) {
    this.svg = svgEl;
    this.detail = detail;
    this.table = table;
    this.consolePane = consolePane;
    this.refreshTree = refreshTree;
    this.msEls = new Map();
  }

  setTree(msg) {
    this.graphKnown = msg.graph !== false; // an older robot does not say what modules require
    const providerOf = new Map((msg.representations || []).map((r) => [r.name, r.provider]));
    const active = new Set(providerOf.values());
    const mods = msg.modules || [];
    const on = mods.filter((m) => active.has(m.name)); // the rest provide nothing: not running
    const off = mods.filter((m) => !on.includes(m));
    this.providerOf = providerOf;
    if (!this.graphKnown) this.detail.textContent = "this robot's debug server does not say what modules require: no edges";
    this.draw(on, off, providerOf);
    this.providers(msg.representations || []);
  }

  // Positions: a row per layer (wrapping when wide), then the modules not running, smaller.
  place(on, off, providerOf) {
    const perRow = Math.max(1, Math.floor((this.svg.clientWidth || 420) / (BOX_W + GAP_X)));
    const layer = layers(on, providerOf);
    const pos = new Map();
    let y = 4;
    const rowsOf = (mods, h, gap) => {
      for (let i = 0; i < mods.length; i += perRow) {
        mods.slice(i, i + perRow).forEach((m, c) => pos.set(m.name, { x: 4 + c * (BOX_W + GAP_X), y, h }));
        y += h + gap;
      }
    };
    const maxLayer = Math.max(-1, ...layer.values());
    for (let l = 0; l <= maxLayer; l++) rowsOf(on.filter((m) => layer.get(m.name) === l), BOX_H, GAP_Y);
    rowsOf(off, OFF_H, 4);
    return { pos, height: y + 4 };
  }

  draw(on, off, providerOf) {
    this.svg.textContent = "";
    this.msEls.clear();
    const { pos, height } = this.place(on, off, providerOf);
    this.svg.setAttribute("height", height);
    const marker = svg("marker", { id: "edge-head", viewBox: "0 0 6 6", refX: 6, refY: 3, markerWidth: 6, markerHeight: 6, orient: "auto" },
      svg("defs", {}, this.svg));
    svg("path", { d: "M0,0 L6,3 L0,6 z", class: "edge-head" }, marker);
    for (const m of on)
      for (const rep of m.requires || []) {
        const from = pos.get(providerOf.get(rep)), to = pos.get(m.name);
        if (!from || !to || from === to) continue;
        const x1 = from.x + BOX_W / 2, y1 = from.y + from.h, x2 = to.x + BOX_W / 2, y2 = to.y;
        const e = svg("path", { class: "edge", "marker-end": "url(#edge-head)", d: `M${x1},${y1} C${x1},${y1 + 18} ${x2},${y2 - 18} ${x2},${y2}` }, this.svg);
        Object.assign(e.dataset, { from: providerOf.get(rep), to: m.name, rep });
        svg("title", {}, e).textContent = `${providerOf.get(rep)} -> ${rep} -> ${m.name}`;
      }
    for (const m of [...on, ...off]) this.box(m, pos.get(m.name), on.includes(m));
  }

  // A module's box: its name, what it provides and its time per frame (running ones).
  box(m, p, running) {
    const g = svg("g", { class: running ? "module" : "module inactive", transform: `translate(${p.x},${p.y})` }, this.svg);
    g.dataset.module = m.name;
    svg("rect", { width: BOX_W, height: p.h, rx: 4 }, g);
    const cut = (t, n) => (t.length > n ? `${t.slice(0, n - 1)}.` : t);
    svg("text", { x: 4, y: 12 }, g).textContent = cut(m.name, 22);
    if (running) {
      svg("text", { x: 4, y: 23, class: "module-provides" }, g).textContent = cut(`> ${(m.provides || []).join(", ")}`, 24);
      const ms = svg("text", { x: 4, y: 35, class: "module-ms" }, g);
      ms.textContent = formatMs(m.ms);
      this.msEls.set(m.name, ms);
    }
    const detail = `${m.name}${running ? "" : " (not running)"}\nrequires: ${this.requiresText(m)}\n` +
      `provides: ${(m.provides || []).join(", ") || "-"}`;
    svg("title", {}, g).textContent = detail;
    g.addEventListener("click", () => {
      this.detail.textContent = detail;
      for (const e of this.svg.querySelectorAll("path.edge"))
        e.classList.toggle("hl", e.dataset.from === m.name || e.dataset.to === m.name);
    });
  }

  // What a module requires, each with the module providing it now (the active provider).
  requiresText(m) {
    if (!Array.isArray(m.requires)) return this.graphKnown ? "?" : "? (the robot does not say)";
    const from = (rep) => (this.providerOf.get(rep) ? ` <- ${this.providerOf.get(rep)}` : " (built in)");
    return m.requires.map((rep) => rep + from(rep)).join(", ") || "-";
  }

  providers(reps) {
    this.table.textContent = "";
    for (const r of reps) {
      const tr = this.table.insertRow();
      tr.insertCell().textContent = r.name;
      if (!r.provider && !(r.available || []).length) {
        tr.insertCell().textContent = "(built in)"; // the runtime's own: nothing to choose
        continue;
      }
      const sel = document.createElement("select");
      sel.className = "provider-select";
      sel.dataset.rep = r.name;
      for (const name of r.available && r.available.length ? r.available : [r.provider]) {
        const o = new Option(name, name, false, name === r.provider);
        sel.add(o);
      }
      sel.add(new Option("(default)", "default"));
      sel.onchange = async () => {
        await this.consolePane.run(`mr ${r.name} ${sel.value}`);
        this.refreshTree();
      };
      tr.insertCell().appendChild(sel);
    }
  }

  // ms per frame from frame.times.
  setTimes(times) {
    for (const [name, ms] of Object.entries(times || {})) {
      const el = this.msEls.get(name);
      if (el) el.textContent = formatMs(ms);
    }
  }
}
