// Wires the page's parts to the bridge connection and runs the draw loop.

import { Connection, bridgeUrl } from "./connection.js";
import { ConsolePane } from "./console_pane.js";
import { SceneView } from "./scene_view.js";
import { Banner, StatusBar } from "./status_bar.js";

const $ = (id) => document.getElementById(id);

const conn = new Connection(bridgeUrl(window.location));
const consolePane = new ConsolePane(conn, $("console-in"), $("console-out"));
const status = new StatusBar(consolePane);
const banner = new Banner();
const view = new SceneView($("scene-canvas"));

// Test and bench hooks: what the page received and drew.
const hooks = {
  hello: null,
  scene: null,
  frame: null,
  framesReceived: 0,
  rafTicks: 0,
  latencies: [], // ms from the bridge stepping a frame to the page drawing it
  view,
  conn,
  consolePane,
  robotScreenBox: (i) => view.robotScreenBox(i),
};
window.strideView = hooks;

let latestWall = null;
conn.onState((s) => {
  status.setConnection(s);
  if (s === "connected") conn.send({ op: "tree" });
});
conn.on("hello", (m) => {
  hooks.hello = m;
  status.setHello(m);
});
conn.on("scene", (m) => {
  hooks.scene = m;
  view.setScene(m);
});
conn.on("frame", (m) => {
  hooks.frame = m;
  hooks.framesReceived++;
  view.setFrame(m);
  status.setFrame(m);
  if (typeof m.wall === "number") latestWall = m.wall;
  for (const r of m.robots || []) if (r.fell) banner.show("fall", `${r.name} fell at ${m.t.toFixed(2)} s`);
});
conn.on("event", (m) => {
  if (m.kind !== "info") banner.show(m.kind, m.text);
  consolePane.print(`[${m.kind}] ${m.text}`, m.kind === "info" ? "con-out" : "con-err");
});
conn.on("status", (m) => status.setDropped(m.dropped));
conn.on("error", (m) => consolePane.print(m.error, "con-err"));

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

view.afterDraw.push(() => {
  if (latestWall === null) return;
  hooks.latencies.push(Date.now() - latestWall);
  if (hooks.latencies.length > 5000) hooks.latencies.splice(0, 1000);
  latestWall = null;
});

function tick() {
  hooks.rafTicks++;
  view.draw();
  requestAnimationFrame(tick);
}
requestAnimationFrame(tick);
conn.open();
