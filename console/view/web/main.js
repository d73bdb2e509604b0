// Wires the page's parts to the bridge connection and runs the draw loop.

import { tokenFromFragment } from "./auth.js";
import { Connection, bridgeUrl } from "./connection.js";
import { ConsolePane } from "./console_pane.js";
import { DataTree } from "./data_tree.js";
import { DebugList } from "./debug_list.js";
import { LogPlayer } from "./log_player.js";
import { LogSampler } from "./log_sampler.js";
import { ModuleGraph } from "./module_graph.js";
import { Overlays } from "./overlays.js";
import { Picking } from "./picking.js";
import { PlotPanel } from "./plots.js";
import { RenderScale } from "./render_scale.js";
import { SampleStore } from "./sample_store.js";
import { SceneView } from "./scene_view.js";
import { Banner, StatusBar } from "./status_bar.js";
import { Watches } from "./watches.js";

const $ = (id) => document.getElementById(id);

const conn = new Connection(bridgeUrl(window.location), tokenFromFragment(window.location.hash));
const consolePane = new ConsolePane(conn, $("console-in"), $("console-out"));
const status = new StatusBar(consolePane);
const banner = new Banner();
const view = new SceneView($("scene-canvas"));
const renderScale = new RenderScale(view);
const overlays = new Overlays(view.scene);
const picking = new Picking(view, consolePane);
const store = new SampleStore(conn);
const plots = new PlotPanel(store, $("plots"));
const watches = new Watches($("watches"), store, conn);
const tree = new DataTree({ container: $("tree"), filter: $("tree-filter"), conn, consolePane, watches, plots });
let treeAskedAt = 0;
let treeRetries = 0;
const refreshTree = () => {
  treeAskedAt = performance.now();
  conn.send({ op: "tree" });
};
const graph = new ModuleGraph($("module-graph"), $("module-detail"), $("providers"), consolePane, refreshTree);
const debugList = new DebugList($("debug-list"), consolePane);
const player = new LogPlayer(conn);
const logSampler = new LogSampler(conn, store, (t) => {
  plots.setCursor(t);
  status.setLogTime(t);
});

// Test and bench hooks: what the page received and drew.
const hooks = {
  hello: null, scene: null, frame: null, tree: null,
  framesReceived: 0,
  rafTicks: 0,
  latencies: [], // ms from the bridge stepping a frame to the page drawing it
  drawn: [], // [frame seq, Date.now()] of each draw that showed a new frame
  view, conn, consolePane, store, plots, tree, player, picking, overlays, logSampler, renderScale,
  robotScreenBox: (i) => view.robotScreenBox(i),
};
window.strideView = hooks;

let latestWall = null;
const fallen = new Set(); // robots whose fall the banner has shown
let lastShown = ""; // frame/log frame the tree's values were last fetched for
conn.onState((s) => status.setConnection(s));
// Nothing is sent before hello: a bridge asking for a token closes on any other first message.
conn.on("hello", (m) => {
  hooks.hello = m;
  status.setHello(m);
  player.setHello(m);
  store.mode = m.mode;
  store.sendWatch(); // after a reconnect, the bridge forgot the list
  sendTimes();
  refreshTree();
});
conn.on("scene", (m) => {
  if (hooks.scene) refreshTree(); // a load or reset: modules and providers may differ
  hooks.scene = m;
  view.setScene(m);
});
// Samples are kept from every frame message; what is drawn only from the last one before each
// animation frame (messages may come faster than the page draws).
let pendingFrame = null;
let shownSeq = null; // the seq of the frame the next draw shows
function showFrame(m) {
  shownSeq = m.seq;
  view.setFrame(m);
  overlays.update(m);
  status.setFrame(m);
  player.setFrame(m);
  graph.setTimes(m.times);
}
conn.on("frame", (m) => {
  hooks.frame = m;
  hooks.framesReceived++;
  pendingFrame = m;
  store.addFrame(m);
  const rows = m.samples && m.samples.rows;
  if (m.log_frame !== null && m.log_frame !== undefined && rows && rows.length) plots.setCursor(rows[rows.length - 1][0]);
  logSampler.onFrame(m);
  if (typeof m.wall === "number") latestWall = m.wall;
  const shown = `${m.frame}/${m.log_frame}`;
  if (!m.running && shown !== lastShown) tree.refetchVisible(); // a step or a log frame
  lastShown = shown;
  // Before the first control frame the blackboard is empty: ask again once there is one.
  const empty = !hooks.tree || !(hooks.tree.representations || []).length;
  if (empty && m.frame > 0 && treeRetries < 3 && performance.now() - treeAskedAt > 1000) {
    treeRetries++; // a scene without a controller never has a tree: do not ask forever
    refreshTree();
  }
  for (const r of m.robots || []) {
    if (r.fell && !fallen.has(r.name)) banner.show("fall", `${r.name} fell at ${m.t.toFixed(2)} s`);
    if (r.fell) fallen.add(r.name);
    else fallen.delete(r.name); // up again (a reset): the next fall shows
  }
});
conn.on("tree", (m) => {
  hooks.tree = m;
  tree.setTree(m);
  graph.setTree(m);
  debugList.setTree(m);
});
conn.on("event", (m) => {
  if (m.kind !== "info") banner.show(m.kind, m.text);
  if (m.kind === "override_swapped") refreshTree();
  consolePane.print(`[${m.kind}] ${m.text}`, m.kind === "info" ? "con-out" : "con-err");
});
conn.on("status", (m) => status.setStatus(m));
conn.on("error", (m) => {
  const key = store.rejectFrom(m.error);
  if (key) {
    plots.forget(key);
    watches.remove(key);
  }
  consolePane.print(m.error, "con-err");
});
store.onError = (e) => consolePane.print(e, "con-err");

// In a log, a click on a plot shows the log frame nearest that time.
plots.onPointClick = (t) => {
  const i = Math.min(store.indexAtOrAfter(t), store.t.length - 1);
  const k = store.logFrame[i];
  if (k !== null && k !== undefined) player.goto(k);
  else if (hooks.hello && hooks.hello.mode === "log") player.goto(Math.round(t / (hooks.hello.period || 0.01)));
};

for (const name of ["follow", "front", "side", "top"]) {
  $(`view-${name}`).onclick = () => {
    view.setView(name);
    if (name === "follow") {
      $("follow-toggle").checked = true;
      view.setFollowing(true);
    }
  };
}
$("follow-toggle").onchange = (ev) => view.setFollowing(ev.target.checked);
for (const name of ["com", "zmp", "cop", "support", "contacts", "footsteps"]) {
  const box = $(`ov-${name}`);
  overlays.set(name, box.checked);
  box.onchange = () => {
    overlays.set(name, box.checked);
    view.dirty = true;
  };
}
$("plot-add").onclick = () => plots.addPlot();
$("plot-window").onchange = (ev) => plots.setWindow(+ev.target.value);
$("plot-pause").onclick = () => {
  plots.setPaused(!plots.paused);
  $("plot-pause").classList.toggle("on", plots.paused);
};
$("tree-refresh").onclick = refreshTree;
// Module times cost a robot's loop a copy every frame: asked for only while the graph shows.
function sendTimes() {
  conn.send({ op: "times", on: !$("panel-modules").hidden });
}
for (const tab of document.querySelectorAll(".tabs button")) {
  tab.onclick = () => {
    for (const t of document.querySelectorAll(".tabs button")) {
      t.classList.toggle("on", t === tab);
      $(t.dataset.panel).hidden = t !== tab;
    }
    sendTimes();
  };
}

view.afterDraw.push(() => {
  if (shownSeq !== null) hooks.drawn.push([shownSeq, Date.now()]);
  if (hooks.drawn.length > 5000) hooks.drawn.splice(0, 1000);
  shownSeq = null;
  if (latestWall === null) return;
  hooks.latencies.push(Date.now() - latestWall);
  if (hooks.latencies.length > 5000) hooks.latencies.splice(0, 1000);
  latestWall = null;
});
setInterval(() => {
  tree.refresh(store);
  watches.refresh();
}, 200);

// Time spent drawing, per part (ms, summed): where a slow page's time goes.
hooks.drawMs = { view: 0, plots: 0 };
function tick() {
  hooks.rafTicks++;
  const t0 = performance.now();
  if (pendingFrame) showFrame(pendingFrame);
  pendingFrame = null;
  renderScale.tick(view.draw());
  const t1 = performance.now();
  plots.draw();
  hooks.drawMs.view += t1 - t0;
  hooks.drawMs.plots += performance.now() - t1;
  requestAnimationFrame(tick);
}
requestAnimationFrame(tick);
conn.open();
