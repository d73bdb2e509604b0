// The 3D view: renderer, camera with orbit/pan/zoom, named views, follow-the-robot, link poses.

import { applyPose, buildGround, buildScene } from "./scene_builder.js";

const THREE = window.THREE;
THREE.Object3D.DefaultUp.set(0, 0, 1); // the world is z up

// Eye offsets from the framed point, as simulator/render/views.cpp.
const VIEWS = {
  follow: [0.8, -0.65, 0.35],
  front: [1.0, 0.0, 0.05],
  side: [0.0, -1.0, 0.05],
  top: [0.0, -0.001, 1.3],
};

export class SceneView {
  constructor(canvas) {
    this.canvas = canvas;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(new THREE.Color(0.62, 0.74, 0.86));
    this.scene = new THREE.Scene();
    this.scene.add(new THREE.AmbientLight(0xffffff, 0.35));
    const sun = new THREE.DirectionalLight(0xffffff, 0.8);
    sun.position.set(0.4, -0.3, 1.0); // towards the light: the renderer's default light reversed
    this.scene.add(sun);
    this.ground = buildGround();
    this.scene.add(this.ground);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    this.controls = new THREE.OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
    this.controls.addEventListener("change", () => (this.dirty = true));
    this.world = null;
    this.robots = [];
    this.following = true;
    this.dirty = true;
    this.draws = 0;
    this.afterDraw = [];
    this.setView("follow");
    new ResizeObserver(() => this.resize()).observe(canvas.parentElement);
    this.resize();
  }

  resize() {
    const el = this.canvas.parentElement;
    const w = Math.max(el.clientWidth, 50);
    const h = Math.max(el.clientHeight, 50);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.dirty = true;
  }

  setScene(msg) {
    if (this.world) this.scene.remove(this.world);
    const built = buildScene(msg);
    this.world = built.root;
    this.robots = built.robots;
    this.scene.add(this.world);
    this.dirty = true;
  }

  setFrame(frame) {
    for (const fr of frame.robots || []) {
      const robot = this.robots.find((r) => r.name === fr.name);
      if (!robot || !fr.links) continue;
      fr.links.forEach((pose, i) => {
        if (pose && robot.links[i]) {
          applyPose(robot.links[i], pose);
          robot.links[i].visible = true;
        } else if (robot.links[i]) robot.links[i].visible = false;
      });
    }
    if (this.following) this.followRobot();
    this.dirty = true;
  }

  // The point views frame: the first robot's first link (torso) at mid-height of a NAO.
  framedPoint() {
    const link = this.robots[0] && this.robots[0].links[0];
    if (!link) return new THREE.Vector3(0, 0, 0.25);
    return new THREE.Vector3(link.position.x, link.position.y, 0.25);
  }

  followRobot() {
    const target = this.framedPoint();
    const delta = target.clone().sub(this.controls.target);
    if (delta.lengthSq() === 0) return;
    this.controls.target.add(delta);
    this.camera.position.add(delta);
    this.controls.update();
  }

  setView(name) {
    const offset = VIEWS[name];
    if (!offset) return false;
    const target = this.framedPoint();
    this.controls.target.copy(target);
    this.camera.position.set(target.x + offset[0], target.y + offset[1], target.z + offset[2]);
    this.controls.update();
    this.following = name === "follow" ? true : this.following;
    this.dirty = true;
    return true;
  }

  setFollowing(on) {
    this.following = on;
    if (on) this.followRobot();
  }

  // Draws if anything changed since the last draw; returns whether it drew.
  draw() {
    if (!this.dirty) return false;
    this.dirty = false;
    this.renderer.render(this.scene, this.camera);
    this.draws++;
    for (const fn of this.afterDraw) fn();
    return true;
  }

  // Normalised device coordinates of a client point on the canvas.
  ndc(clientX, clientY) {
    const r = this.canvas.getBoundingClientRect();
    return new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
  }

  // The robot body under a client point: {body, point} or null.
  pickBody(clientX, clientY) {
    const ray = new THREE.Raycaster();
    ray.setFromCamera(this.ndc(clientX, clientY), this.camera);
    const meshes = this.robots.flatMap((r) => r.links);
    const hit = ray.intersectObjects(meshes, true)[0];
    return hit ? { body: hit.object.userData.body, point: hit.point } : null;
  }

  // Where a client point's ray meets the horizontal plane at height z.
  pickPlane(clientX, clientY, z = 0) {
    const ray = new THREE.Raycaster();
    ray.setFromCamera(this.ndc(clientX, clientY), this.camera);
    const plane = new THREE.Plane(new THREE.Vector3(0, 0, 1), -z);
    const p = new THREE.Vector3();
    return ray.ray.intersectPlane(plane, p) ? p : null;
  }

  // A robot's bounding box on the canvas in CSS pixels (for tests and screenshots).
  robotScreenBox(index = 0) {
    const robot = this.robots[index];
    if (!robot) return null;
    const box = new THREE.Box3().setFromObject(robot.group);
    if (box.isEmpty()) return null;
    const r = this.canvas.getBoundingClientRect();
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let i = 0; i < 8; i++) {
      const v = new THREE.Vector3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
        i & 4 ? box.max.z : box.min.z).project(this.camera);
      const x = ((v.x + 1) / 2) * r.width, y = ((1 - v.y) / 2) * r.height;
      x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
    }
    return { x0, y0, x1, y1, left: r.left, top: r.top };
  }
}
