// The data tree: every representation and module parameter from the `tree` message's type
// descriptions; values shown on demand, watched as text, "+plot"/dragged into plots, edited in place.

import { splitKey } from "./keys.js";

const MAX_FLAT = 300; // rows a filter shows at most
const MAX_FETCH = 40; // values fetched when a node opens
const MAX_ITEMS = 256; // array elements listed

// The children of a typed node: struct fields, array items.
function children(node) {
  const t = node.type;
  if (!t) return [];
  if (t.kind === "struct")
    return (t.fields || []).map((f) => ({ name: f.name, key: `${node.key}.${f.name}`, type: f.type }));
  if (t.kind === "array") {
    // Named elements (joints) are keyed by name, as the console takes them: position[LKneePitch].
    const names = t.names || [];
    const n = Math.min(MAX_ITEMS, names.length || t.size || 0); // a list (size null) shows whole
    return Array.from({ length: n }, (_, i) => {
      const id = names[i] || String(i);
      return { name: names[i] || `[${i}]`, key: `${node.key}[${id}]`, type: t.item };
    });
  }
  return [];
}

function typeLabel(t) {
  if (!t) return "";
  if (t.kind === "number") return t.unit ? t.unit : "";
  if (t.kind === "array") return `[${t.size ?? ""}]`;
  if (t.kind === "enum") return (t.names || []).join("|");
  return t.kind === "struct" ? "" : t.kind;
}

// A value as get printed it; numbers to 6 digits on screen, the whole text in the tooltip.
function showValue(el, text) {
  const n = Number(text);
  el.textContent = text !== "" && Number.isFinite(n) ? String(+n.toPrecision(6)) : text;
  el.title = `${text} (click to edit)`;
}

const isLeaf = (t) => t && t.kind !== "struct" && t.kind !== "array";

export class DataTree {
  constructor({ container, filter, conn, consolePane, watches, plots }) {
    this.container = container;
    this.conn = conn;
    this.consolePane = consolePane;
    this.watches = watches;
    this.plots = plots;
    this.roots = [];
    this.valueEls = new Map(); // key -> value spans on screen
    filter.addEventListener("input", () => this.render(filter.value.trim()));
    this.filterEl = filter;
  }

  setTree(msg) {
    const reps = (msg.representations || []).map((r) => ({
      name: r.name, key: `representation:${r.name}`, type: r.fields, note: r.provider ? `(${r.provider})` : "",
    }));
    const mods = (msg.modules || []).filter((m) => m.params).map((m) => ({
      name: m.name, key: `module:${m.name}`, type: m.params, note: "",
    }));
    const debug = (msg.debug || []).map((d) => ({ name: d.name, key: `debug:${d.name}`, type: null, note: d.state }));
    this.roots = [
      { name: "representations", group: true, kids: reps },
      { name: "module parameters", group: true, kids: mods },
      { name: "debug requests", group: true, kids: debug },
    ];
    this.render(this.filterEl.value.trim());
  }

  render(filter) {
    this.container.textContent = "";
    this.valueEls.clear();
    if (filter) return this.renderFlat(filter.toLowerCase());
    for (const g of this.roots) this.container.appendChild(this.groupEl(g));
  }

  groupEl(g) {
    const el = document.createElement("div");
    el.className = "tree-group";
    const head = document.createElement("div");
    head.className = "tree-row";
    head.innerHTML = `<span class="tree-toggle">+</span><b>${g.name}</b> <span class="tree-type">${g.kids.length}</span>`;
    el.appendChild(head);
    const box = document.createElement("div");
    box.className = "tree-node";
    box.hidden = true;
    el.appendChild(box);
    head.onclick = () => {
      box.hidden = !box.hidden;
      head.firstChild.textContent = box.hidden ? "+" : "-";
      if (!box.hidden && !box.childElementCount) for (const k of g.kids) box.appendChild(this.nodeEl(k));
    };
    return el;
  }

  // Every node under the roots whose key contains the filter, as a flat list.
  renderFlat(filter) {
    const out = [];
    const visit = (node, depth) => {
      if (out.length >= MAX_FLAT || depth > 6) return;
      if (node.key.toLowerCase().includes(filter)) out.push(node);
      for (const c of children(node)) visit(c, depth + 1);
    };
    for (const g of this.roots) for (const k of g.kids) visit(k, 0);
    for (const n of out) this.container.appendChild(this.nodeEl(n, true));
    this.fetchValues(out);
  }

  nodeEl(node, flat = false) {
    const el = document.createElement("div");
    el.className = "tree-node";
    el.dataset.key = node.key;
    el.appendChild(this.rowEl(node, flat));
    const kids = children(node);
    if (kids.length && !flat) {
      const box = document.createElement("div");
      box.hidden = true;
      el.appendChild(box);
      const toggle = el.querySelector(".tree-toggle");
      toggle.textContent = "+";
      toggle.onclick = () => {
        box.hidden = !box.hidden;
        toggle.textContent = box.hidden ? "+" : "-";
        if (!box.hidden && !box.childElementCount) {
          for (const k of kids) box.appendChild(this.nodeEl(k));
          this.fetchValues(kids);
        }
      };
    }
    return el;
  }

  rowEl(node, flat) {
    const row = document.createElement("div");
    row.className = "tree-row";
    const number = node.type && node.type.kind === "number";
    row.innerHTML = `<span class="tree-toggle"></span><span class="tree-name"></span>
      <span class="tree-type"></span><span class="tree-value"></span>`;
    const name = row.querySelector(".tree-name");
    // A filtered row shows its whole key, cut at the front when long (the end names the field).
    name.textContent = flat ? `\u200e${node.key.replace(/^(representation|module):/, "")}\u200e` : `${node.name} ${node.note || ""}`;
    name.classList.toggle("flat", flat);
    name.title = node.key;
    row.querySelector(".tree-type").textContent = typeLabel(node.type);
    const value = row.querySelector(".tree-value");
    if (number) {
      name.draggable = true;
      name.addEventListener("dragstart", (ev) => ev.dataTransfer.setData("text/plain", node.key));
    }
    if (isLeaf(node.type)) {
      this.valueEls.set(node.key, value);
      value.textContent = ".";
      value.title = "click to edit";
      value.onclick = () => this.edit(node, row, value);
    }
    const watch = document.createElement("button");
    watch.className = "tree-watch";
    watch.textContent = "watch";
    watch.onclick = () => this.watches.add(node.key, number);
    row.appendChild(watch);
    if (number) {
      const plot = document.createElement("button");
      plot.className = "tree-plot";
      plot.textContent = "+plot";
      plot.onclick = () => this.plots.plotKey(node.key);
      row.appendChild(plot);
    }
    return row;
  }

  // Values on screen again (after a step, a log frame): at most every 250 ms, the last call
  // always served (a scrub ends on the frame it shows).
  refetchVisible() {
    if (this.refetchTimer) return;
    const wait = Math.max(0, 250 - (performance.now() - (this.refetchedAt || -1e9)));
    this.refetchTimer = setTimeout(() => {
      this.refetchTimer = null;
      this.refetchedAt = performance.now();
      this.fetchValues([...this.valueEls.keys()].map((key) => ({ key, type: { kind: "number" } })));
    }, wait);
  }

  async fetchValues(nodes) {
    for (const n of nodes.filter((n) => isLeaf(n.type)).slice(0, MAX_FETCH)) {
      const v = await this.conn.get(n.key);
      const el = this.valueEls.get(n.key);
      if (el && !el.querySelector("input")) showValue(el, v.error ? "?" : (v.text || "").trim());
    }
  }

  // Edit in place: the value's text in an input; Enter sends `set`, Escape gives up.
  async edit(node, row, value) {
    if (value.querySelector("input")) return;
    const { top, field } = splitKey(node.key);
    if (!field || !/^(representation|module):/.test(top)) return;
    const got = await this.conn.get(node.key);
    const input = document.createElement("input");
    input.className = "tree-edit";
    input.value = got.error ? "" : (got.text || "").trim();
    value.textContent = "";
    value.appendChild(input);
    input.focus();
    input.select();
    input.onkeydown = async (ev) => {
      if (ev.key === "Escape") return showValue(value, got.error ? "?" : (got.text || "").trim());
      if (ev.key !== "Enter") return;
      const reply = await this.consolePane.run(`set ${top} ${field}=${input.value.trim()}`);
      row.parentElement.querySelectorAll(":scope > .tree-error").forEach((e) => e.remove());
      if (!reply.ok) {
        const err = document.createElement("div");
        err.className = "tree-error";
        err.textContent = reply.error || "set failed";
        row.after(err);
      }
      const now = await this.conn.get(node.key);
      value.textContent = "";
      showValue(value, now.error ? "?" : (now.text || "").trim());
    };
  }

  // Numbers the store has (watched) show their latest value.
  refresh(store) {
    for (const [key, el] of this.valueEls) {
      if (el.querySelector("input")) continue;
      const v = store.latest(key);
      if (v !== null) el.textContent = String(+v.toPrecision(6));
    }
  }
}
