// Mouse tools on the 3D view of a local simulation: orbit (the camera), push (drag from a body:
// `push <link> fx fy fz 0.1`, force = drag x N/m) and move (drag on the ground: `mv x y z yaw`).

const THREE = window.THREE;
const $ = (id) => document.getElementById(id);
const PUSH_SECONDS = 0.1;

export class Picking {
  constructor(view, consolePane) {
    this.view = view;
    this.consolePane = consolePane;
    this.tool = "orbit";
    this.drag = null;
    this.line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]),
      new THREE.LineBasicMaterial({ color: 0xd02020, depthTest: false }));
    this.line.renderOrder = 20;
    this.line.visible = false;
    view.scene.add(this.line);
    for (const t of ["orbit", "push", "move"]) $(`tool-${t}`).onclick = () => this.setTool(t);
    const c = view.canvas;
    c.addEventListener("pointerdown", (ev) => this.down(ev));
    c.addEventListener("pointermove", (ev) => this.move(ev));
    c.addEventListener("pointerup", (ev) => this.up(ev));
  }

  setTool(t) {
    this.tool = t;
    this.view.controls.enabled = t === "orbit";
    for (const n of ["orbit", "push", "move"]) $(`tool-${n}`).classList.toggle("on", n === t);
  }

  down(ev) {
    if (this.tool === "orbit" || ev.button !== 0) return;
    let start, body = null;
    if (this.tool === "push") {
      const hit = this.view.pickBody(ev.clientX, ev.clientY);
      if (!hit) return;
      body = hit.body;
      start = hit.point;
    } else {
      start = this.view.pickPlane(ev.clientX, ev.clientY, 0);
      if (!start) return;
    }
    this.drag = { body, start, end: start.clone() };
    this.view.canvas.setPointerCapture(ev.pointerId);
    this.showLine();
  }

  move(ev) {
    if (!this.drag) return;
    const p = this.view.pickPlane(ev.clientX, ev.clientY, this.drag.start.z);
    if (p) this.drag.end = p;
    this.showLine();
  }

  up() {
    const d = this.drag;
    this.drag = null;
    this.line.visible = false;
    this.view.dirty = true;
    if (!d) return;
    const dx = d.end.x - d.start.x, dy = d.end.y - d.start.y;
    if (this.tool === "push") {
      const k = Math.max(1, +$("push-force").value || 200);
      const link = d.body.split("/").pop(); // push names the selected robot's link
      this.consolePane.run(`push ${link} ${(dx * k).toFixed(1)} ${(dy * k).toFixed(1)} 0 ${PUSH_SECONDS}`);
    } else {
      const torso = this.view.robots[0] && this.view.robots[0].links[0];
      const z = torso ? torso.position.z : 0.33;
      const moved = Math.hypot(dx, dy) > 0.02;
      const yaw = moved ? Math.atan2(dy, dx) : null;
      const f = (v) => v.toFixed(3);
      this.consolePane.run(`mv ${f(d.start.x)} ${f(d.start.y)} ${f(z)}${yaw === null ? "" : ` ${f(yaw)}`}`);
    }
  }

  showLine() {
    const d = this.drag;
    this.line.geometry.setFromPoints([d.start, d.end]);
    this.line.visible = true;
    this.view.dirty = true;
  }
}
