// The module graph: modules in layers by dependency (a module sits below the providers of what it
// requires), edges provider -> consumer, each module's time per frame; and the providers table,
// whose selects run `mr <Rep> <Module>`.

const SVG = "http://www.w3.org/2000/svg";
const BOX_W = 128, BOX_H = 30, GAP_X = 12, GAP_Y = 26;

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
    const providerOf = new Map((msg.representations || []).map((r) => [r.name, r.provider]));
    const active = new Set(providerOf.values());
    const mods = msg.modules || [];
    const on = mods.filter((m) => active.has(m.name) || !(m.provides || []).length);
    const off = mods.filter((m) => !on.includes(m));
    this.draw(on, off, providerOf);
    this.providers(msg.representations || []);
  }

  // Positions: a row per layer (wrapping when wide), then the inactive modules last.
  place(on, off, providerOf) {
    const perRow = Math.max(1, Math.floor((this.svg.clientWidth || 420) / (BOX_W + GAP_X)));
    const layer = layers(on, providerOf);
    const rows = [];
    const maxLayer = Math.max(-1, ...layer.values());
    for (let l = 0; l <= maxLayer; l++) {
      const inLayer = on.filter((m) => layer.get(m.name) === l);
      for (let i = 0; i < inLayer.length; i += perRow) rows.push(inLayer.slice(i, i + perRow));
    }
    for (let i = 0; i < off.length; i += perRow) rows.push(off.slice(i, i + perRow));
    const pos = new Map();
    rows.forEach((row, r) =>
      row.forEach((m, c) => pos.set(m.name, { x: 4 + c * (BOX_W + GAP_X), y: 4 + r * (BOX_H + GAP_Y) })));
    return { pos, height: 8 + rows.length * (BOX_H + GAP_Y) };
  }

  draw(on, off, providerOf) {
    this.svg.textContent = "";
    this.msEls.clear();
    const { pos, height } = this.place(on, off, providerOf);
    this.svg.setAttribute("height", height);
    for (const m of on)
      for (const rep of m.requires || []) {
        const from = pos.get(providerOf.get(rep)), to = pos.get(m.name);
        if (!from || !to || from === to) continue;
        const x1 = from.x + BOX_W / 2, y1 = from.y + BOX_H, x2 = to.x + BOX_W / 2, y2 = to.y;
        const e = svg("path", { class: "edge", d: `M${x1},${y1} C${x1},${y1 + 18} ${x2},${y2 - 18} ${x2},${y2}` }, this.svg);
        svg("title", {}, e).textContent = rep;
      }
    for (const m of [...on, ...off]) {
      const p = pos.get(m.name);
      const g = svg("g", { class: on.includes(m) ? "module" : "module inactive", transform: `translate(${p.x},${p.y})` }, this.svg);
      g.dataset.module = m.name;
      svg("rect", { width: BOX_W, height: BOX_H, rx: 4 }, g);
      svg("text", { x: 4, y: 12 }, g).textContent = m.name.length > 22 ? `${m.name.slice(0, 21)}.` : m.name;
      const ms = svg("text", { x: 4, y: 25, class: "module-ms" }, g);
      ms.textContent = m.ms != null ? `${m.ms.toFixed(3)} ms` : "";
      this.msEls.set(m.name, ms);
      const detail = `${m.name}${on.includes(m) ? "" : " (not running)"}\nrequires: ${(m.requires || []).join(", ") || "-"}\n` +
        `provides: ${(m.provides || []).join(", ") || "-"}`;
      svg("title", {}, g).textContent = detail;
      g.addEventListener("click", () => (this.detail.textContent = detail));
    }
  }

  providers(reps) {
    this.table.textContent = "";
    for (const r of reps) {
      const tr = this.table.insertRow();
      tr.insertCell().textContent = r.name;
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
      if (el && typeof ms === "number") el.textContent = `${ms.toFixed(3)} ms`;
    }
  }
}
