// Switchable overlays on the 3D view: CoM and its ground projection, ZMP reference, measured CoP,
// support polygon, contact forces as arrows, planned footsteps.

const THREE = window.THREE;
const LIFT = 0.003; // above the ground so the overlays are not hidden in it
const NEWTON_TO_M = 0.004; // arrow length per newton
const FOOT = [0.16, 0.08]; // a NAO sole, for the footsteps' outlines
const SIDE = { left: 0x5c8feb, right: 0xed854d }; // the robot's side colours (scene_builder.js)
const TRAIL = 150; // ZMP reference points kept (1.5 s of 10 ms frames at most)
const TRAIL_JUMP = 0.3; // m: a reference moving further in one frame starts a new trail (reset, mv)

function disc(colour, r) {
  const m = new THREE.Mesh(new THREE.CircleBufferGeometry(r, 24),
    new THREE.MeshBasicMaterial({ color: colour, depthTest: false, transparent: true, opacity: 0.9 }));
  m.renderOrder = 10;
  return m;
}

function lineMaterial(colour) {
  return new THREE.LineBasicMaterial({ color: colour, depthTest: false });
}

function loop(points, material) {
  const g = new THREE.BufferGeometry().setFromPoints(points.map((p) => new THREE.Vector3(p[0], p[1], LIFT)));
  const l = new THREE.LineLoop(g, material);
  l.renderOrder = 10;
  return l;
}

export class Overlays {
  constructor(scene) {
    this.root = new THREE.Group();
    scene.add(this.root);
    this.on = { com: true, zmp: true, cop: true, support: true, contacts: false, footsteps: false };
    this.dynamic = new THREE.Group(); // rebuilt each frame: polygons, arrows, footsteps
    this.root.add(this.dynamic);
    this.com = new THREE.Mesh(new THREE.SphereBufferGeometry(0.015, 16, 10),
      new THREE.MeshBasicMaterial({ color: 0x111111, depthTest: false }));
    this.com.renderOrder = 11;
    this.comGround = disc(0x111111, 0.012);
    this.comLine = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]),
      lineMaterial(0x333333));
    this.zmp = disc(0xd02020, 0.014);
    this.cop = disc(0x20a040, 0.011);
    this.root.add(this.com, this.comGround, this.comLine, this.zmp, this.cop);
    this.supportMat = lineMaterial(0x1060c0);
    this.stepMat = { left: lineMaterial(SIDE.left), right: lineMaterial(SIDE.right) };
    this.trail = []; // recent ZMP reference points, oldest first
    this.trailLine = new THREE.Line(new THREE.BufferGeometry(), lineMaterial(0xd02020));
    this.trailLine.renderOrder = 10;
    this.root.add(this.trailLine);
    this.soleGeometry = new THREE.PlaneBufferGeometry(FOOT[0], FOOT[1]); // shared by the soles
    this.soleMat = {};
    for (const side of ["left", "right"])
      this.soleMat[side] = new THREE.MeshBasicMaterial({ color: SIDE[side], transparent: true, opacity: 0.35, depthTest: false });
    this.steps = []; // the footsteps drawn now: [x, y, yaw, side], for tests and tooltips
    this.last = null;
  }

  set(name, on) {
    this.on[name] = on;
    if (this.last) this.update(this.last);
  }

  update(frame) {
    this.last = frame;
    const r = (frame.robots || [])[0] || {};
    this.place(this.com, r.com && this.on.com, r.com);
    this.place(this.comGround, r.com && this.on.com, r.com && [r.com[0], r.com[1], LIFT]);
    this.comLine.visible = !!(r.com && this.on.com);
    if (this.comLine.visible) {
      this.comLine.geometry.setFromPoints([new THREE.Vector3(r.com[0], r.com[1], r.com[2]),
        new THREE.Vector3(r.com[0], r.com[1], LIFT)]);
    }
    this.place(this.zmp, r.zmp_ref && this.on.zmp, r.zmp_ref && [r.zmp_ref[0], r.zmp_ref[1], LIFT * 2]);
    this.updateTrail(r.zmp_ref, frame.seq);
    this.place(this.cop, r.cop && this.on.cop, r.cop && [r.cop[0], r.cop[1], LIFT * 3]);
    this.rebuildDynamic(r);
  }

  // The ZMP reference's recent path, one point per frame message (a repeated frame adds none).
  updateTrail(zmp, seq) {
    if (!zmp) this.trail = [];
    else if (seq !== this.trailSeq) {
      const last = this.trail[this.trail.length - 1];
      if (last && Math.hypot(zmp[0] - last[0], zmp[1] - last[1]) > TRAIL_JUMP) this.trail = [];
      this.trail.push([zmp[0], zmp[1]]);
      if (this.trail.length > TRAIL) this.trail.shift();
    }
    this.trailSeq = seq;
    this.trailLine.visible = this.on.zmp && this.trail.length > 1;
    if (this.trailLine.visible)
      this.trailLine.geometry.setFromPoints(this.trail.map((p) => new THREE.Vector3(p[0], p[1], LIFT * 2)));
  }

  place(obj, visible, p) {
    obj.visible = !!visible;
    if (visible) obj.position.set(p[0], p[1], p[2]);
  }

  rebuildDynamic(r) {
    for (const c of [...this.dynamic.children]) {
      this.dynamic.remove(c);
      if (c.isLineLoop) c.geometry.dispose(); // arrows share three's geometry: not theirs to free
    }
    if (this.on.support && r.support && r.support.length > 2) this.dynamic.add(loop(r.support, this.supportMat));
    if (this.on.contacts)
      for (const c of r.contacts || []) {
        const f = new THREE.Vector3(c[3], c[4], c[5]);
        const len = f.length() * NEWTON_TO_M;
        if (len < 1e-4) continue;
        const a = new THREE.ArrowHelper(f.normalize(), new THREE.Vector3(c[0], c[1], c[2]), len, 0xe0a000,
          Math.min(0.03, len * 0.3), Math.min(0.015, len * 0.15));
        a.traverse((o) => { o.renderOrder = 12; if (o.material) o.material.depthTest = false; });
        this.dynamic.add(a);
      }
    this.steps = this.on.footsteps ? r.footsteps || [] : [];
    for (const s of this.steps) {
      const [x, y, yaw, side] = s, c = Math.cos(yaw), sn = Math.sin(yaw);
      const corners = [[1, 1], [-1, 1], [-1, -1], [1, -1]].map(([u, v]) => {
        const dx = (u * FOOT[0]) / 2, dy = (v * FOOT[1]) / 2;
        return [x + c * dx - sn * dy, y + sn * dx + c * dy];
      });
      const key = side === "right" ? "right" : "left";
      const outline = loop(corners, this.stepMat[key]);
      outline.userData = { footstep: s };
      const sole = new THREE.Mesh(this.soleGeometry, this.soleMat[key]);
      sole.position.set(x, y, LIFT);
      sole.rotation.z = yaw;
      sole.renderOrder = 9;
      this.dynamic.add(sole, outline);
    }
  }
}
