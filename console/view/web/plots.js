// Live plots (uPlot): several plots, several curves each, a time window, pause and zoom,
// CSV/PNG export of what is shown; in a log, a click on a plot jumps the player there.

import { csvHref, download, toCsv, toPng } from "./plot_export.js";

const COLOURS = ["#2f6fd0", "#e0702a", "#2b9a4a", "#c0392b", "#8e44ad", "#16a0a8", "#a0782a", "#555"];
const uPlot = window.uPlot;
const MAX_PLOT_HZ = 20;

// Plots raster on the CPU: a GPU canvas on a software GL (SwiftShader, headless Chromium) drew the
// page at 6 frames per second with 4 plots, a CPU one at 30. uPlot asks for its contexts itself.
const getContext = HTMLCanvasElement.prototype.getContext;
HTMLCanvasElement.prototype.getContext = function (kind, opts) {
  return getContext.call(this, kind, kind === "2d" ? { willReadFrequently: true, ...opts } : opts);
};

class Plot {
  constructor(panel, id) {
    this.panel = panel;
    this.id = id;
    this.keys = [];
    this.u = null;
    this.el = document.createElement("div");
    this.el.className = "plot";
    this.el.id = `plot-${id}`;
    this.el.innerHTML = `<div class="toolbar"><span class="title">plot ${id}</span>
      <button id="plot-${id}-csv">csv</button><button id="plot-${id}-png">png</button>
      <button id="plot-${id}-remove">x</button></div><div class="curves"></div><div class="plot-body"></div>`;
    this.body = this.el.querySelector(".plot-body");
    this.el.querySelector(`#plot-${id}-csv`).onclick = () =>
      download(`plot_${id}.csv`, csvHref(this.csv()));
    this.el.querySelector(`#plot-${id}-png`).onclick = () => download(`plot_${id}.png`, this.png());
    this.el.querySelector(`#plot-${id}-remove`).onclick = () => panel.removePlot(this);
    this.el.addEventListener("mousedown", () => panel.setActive(this));
    this.el.addEventListener("dragover", (ev) => {
      ev.preventDefault();
      this.el.classList.add("drop");
    });
    this.el.addEventListener("dragleave", () => this.el.classList.remove("drop"));
    this.el.addEventListener("drop", (ev) => {
      ev.preventDefault();
      this.el.classList.remove("drop");
      const key = ev.dataTransfer.getData("text/plain");
      if (key) this.addCurve(key);
    });
    new ResizeObserver(() => this.resize()).observe(this.body);
  }

  owner() {
    return `plot-${this.id}`;
  }

  addCurve(key) {
    if (this.keys.includes(key) || !this.panel.store.add(key, this.owner())) return;
    this.keys.push(key);
    this.rebuild();
  }

  removeCurve(key) {
    this.keys = this.keys.filter((k) => k !== key);
    this.panel.store.remove(key, this.owner());
    this.rebuild();
  }

  dropKey(key) {
    if (!this.keys.includes(key)) return;
    this.keys = this.keys.filter((k) => k !== key);
    this.rebuild();
  }

  curveChips() {
    const box = this.el.querySelector(".curves");
    box.textContent = "";
    this.keys.forEach((k, i) => {
      const b = document.createElement("button");
      b.className = "curve-x";
      b.style.color = COLOURS[i % COLOURS.length];
      b.textContent = `${k.replace(/^(representation|module):/, "")} x`;
      b.title = `remove ${k}`;
      b.dataset.key = k;
      b.onclick = () => this.removeCurve(k);
      box.appendChild(b);
    });
  }

  rebuild() {
    this.el.dataset.keys = this.keys.join(" ");
    this.curveChips();
    if (this.u) this.u.destroy();
    const opts = {
      width: Math.max(this.body.clientWidth, 200),
      height: 180,
      scales: { x: { time: false } },
      series: [{ label: "t" }, ...this.keys.map((k, i) => ({ label: k.replace(/^representation:/, ""), stroke: COLOURS[i % COLOURS.length], width: 1.5 }))],
      cursor: { drag: { x: true, y: false } },
      legend: { show: true },
      hooks: { draw: [(u) => this.drawCursor(u)] },
    };
    this.u = new uPlot(opts, this.data(), this.body);
    // A click, not the end of a drag-zoom, jumps the log player.
    this.u.over.addEventListener("mousedown", (ev) => (this.downAt = [ev.clientX, ev.clientY]));
    this.u.over.addEventListener("click", (ev) => {
      const [x, y] = this.downAt || [ev.clientX, ev.clientY];
      if (Math.hypot(ev.clientX - x, ev.clientY - y) < 4) this.onClick();
    });
  }

  resize() {
    if (this.u) this.u.setSize({ width: Math.max(this.body.clientWidth, 200), height: 180 });
  }

  // The rows in the time window: the last `window` seconds, or around the log frame shown.
  data() {
    const st = this.panel.store;
    const n = st.t.length;
    if (n === 0) return [[], ...this.keys.map(() => [])];
    const w = this.panel.window;
    const centre = this.panel.cursorT;
    const t0 = centre === null ? st.t[n - 1] - w : centre - w / 2;
    const t1 = centre === null ? Infinity : centre + w / 2;
    const i0 = st.indexAtOrAfter(t0);
    const i1 = t1 === Infinity ? n : st.indexAtOrAfter(t1 + 1e-9);
    return st.slice(this.keys, i0, i1);
  }

  update() {
    if (this.u && this.keys.length) this.u.setData(this.data());
  }

  // A vertical line at the log frame shown.
  drawCursor(u) {
    const t = this.panel.cursorT;
    if (t === null) return;
    const x = u.valToPos(t, "x", true);
    const ctx = u.ctx;
    ctx.save();
    ctx.strokeStyle = "#c0392b";
    ctx.beginPath();
    ctx.moveTo(x, u.bbox.top);
    ctx.lineTo(x, u.bbox.top + u.bbox.height);
    ctx.stroke();
    ctx.restore();
  }

  onClick() {
    if (!this.u || this.u.cursor.idx === null || this.u.cursor.idx === undefined) return;
    const t = this.u.data[0][this.u.cursor.idx];
    if (t !== undefined) this.panel.onPointClick(t);
  }

  // What is shown: the data inside the x scale's current range (zoom included).
  shown() {
    const d = this.u ? this.u.data : [[]];
    const sx = this.u ? this.u.scales.x : { min: -Infinity, max: Infinity };
    return { data: d, xmin: sx.min ?? -Infinity, xmax: sx.max ?? Infinity };
  }

  csv() {
    const s = this.shown();
    return toCsv(this.keys, s.data, s.xmin, s.xmax);
  }

  png() {
    return toPng(this.u, this.keys, this.keys.map((_, i) => COLOURS[i % COLOURS.length]));
  }

  destroy() {
    for (const k of this.keys) this.panel.store.remove(k, this.owner());
    if (this.u) this.u.destroy();
    this.el.remove();
  }
}

export class PlotPanel {
  constructor(store, container) {
    this.store = store;
    this.container = container;
    this.plots = [];
    this.nextId = 1;
    this.active = null;
    this.window = 10;
    this.paused = false;
    this.cursorT = null; // the log frame's time in mode log
    this.drawnVersion = -1;
    this.drawnAt = -Infinity;
    this.onPointClick = () => {};
  }

  addPlot() {
    const p = new Plot(this, this.nextId++);
    this.container.appendChild(p.el);
    this.plots.push(p);
    p.rebuild();
    this.setActive(p);
    return p;
  }

  removePlot(p) {
    p.destroy();
    this.plots = this.plots.filter((q) => q !== p);
    if (this.active === p) this.setActive(this.plots[this.plots.length - 1] || null);
  }

  setActive(p) {
    for (const q of this.plots) q.el.classList.toggle("active", q === p);
    this.active = p;
  }

  // "+plot" from the tree: onto the active plot, or a new one.
  plotKey(key) {
    (this.active || this.addPlot()).addCurve(key);
  }

  // A key the bridge refused leaves every plot.
  forget(key) {
    for (const p of this.plots) p.dropKey(key);
  }

  setWindow(s) {
    if (s > 0) this.window = s;
    this.drawnVersion = -1;
  }

  setPaused(on) {
    this.paused = on;
    this.drawnVersion = -1;
  }

  setCursor(t) {
    this.cursorT = t;
    this.drawnVersion = -1;
  }

  // Called every animation frame: redraws when there is anything new and plots are not paused,
  // at most MAX_PLOT_HZ (a plot read by eye needs no more; the 3D view gets the time).
  draw(now = performance.now()) {
    if (this.paused || this.drawnVersion === this.store.version || now - this.drawnAt < 1000 / MAX_PLOT_HZ) return;
    this.drawnVersion = this.store.version;
    this.drawnAt = now;
    for (const p of this.plots) p.update();
  }
}
