// Three.js objects from a `scene` message: statics, tiles and each robot's links with their shapes.
// Colours as the offscreen renderer (simulator/render/world_renderer.cpp): left blue, right orange.

const THREE = window.THREE;

export const SIDE_COLOURS = {
  left: [0.36, 0.56, 0.92],
  right: [0.93, 0.52, 0.3],
  centre: [0.86, 0.86, 0.88],
};
const STATIC_COLOUR = [0.62, 0.55, 0.47];

// [x,y,z,qw,qx,qy,qz] onto an Object3D.
export function applyPose(obj, p) {
  obj.position.set(p[0], p[1], p[2]);
  obj.quaternion.set(p[4], p[5], p[6], p[3]);
}

function shapeGeometry(s) {
  switch (s.shape) {
    case "box":
      return new THREE.BoxBufferGeometry(s.size[0], s.size[1], s.size[2]);
    case "sphere":
      return new THREE.SphereBufferGeometry(s.radius, 20, 14);
    case "cylinder":
    case "capsule": {
      // Three's cylinders lie along y, the protocol's along z.
      const g = new THREE.CylinderBufferGeometry(s.radius, s.radius, s.length, 20);
      g.rotateX(Math.PI / 2);
      return g;
    }
    default:
      return null;
  }
}

// One shape as a mesh (a capsule as its cylinder and two end spheres) in its parent's frame.
function shapeObject(s, material) {
  const geom = shapeGeometry(s);
  if (!geom) return null;
  const group = new THREE.Group();
  group.add(new THREE.Mesh(geom, material));
  if (s.shape === "capsule") {
    for (const z of [-s.length / 2, s.length / 2]) {
      const cap = new THREE.Mesh(new THREE.SphereBufferGeometry(s.radius, 16, 10), material);
      cap.position.z = z;
      group.add(cap);
    }
  }
  if (s.pose) applyPose(group, s.pose);
  return group;
}

function material(rgb) {
  return new THREE.MeshLambertMaterial({ color: new THREE.Color(rgb[0], rgb[1], rgb[2]) });
}

// Neighbouring links alternate in shade; robots after the first are greener.
function linkColour(side, linkIndex, robotIndex) {
  let c = (SIDE_COLOURS[side] || SIDE_COLOURS.centre).map((v) => v * (linkIndex % 2 === 0 ? 1 : 0.86));
  if (robotIndex > 0) c = [0.5 * c[0] + 0.2, 0.5 * c[1] + 0.35, 0.5 * c[2] + 0.2];
  return c;
}

function buildRobot(robot, robotIndex) {
  const group = new THREE.Group();
  group.name = robot.name;
  const links = robot.links.map((link, i) => {
    const obj = new THREE.Group();
    obj.name = link.name;
    obj.userData = { body: `${robot.name}/${link.name}`, robot: robot.name, side: link.side };
    const mat = material(linkColour(link.side, i, robotIndex));
    for (const s of link.shapes || []) {
      const mesh = shapeObject(s, mat);
      if (mesh) obj.add(mesh);
    }
    obj.traverse((o) => (o.userData.body = obj.userData.body));
    group.add(obj);
    return obj;
  });
  return { name: robot.name, group, links };
}

function buildStatics(msg) {
  const group = new THREE.Group();
  const mat = material(STATIC_COLOUR);
  const tileMat = material([0.7, 0.64, 0.55]);
  for (const s of msg.statics || []) {
    const obj = shapeObject(s, mat);
    if (obj) group.add(obj);
  }
  for (const t of msg.tiles || []) {
    const obj = shapeObject({ ...t, shape: "box" }, tileMat);
    if (obj) group.add(obj);
  }
  return group;
}

// A checker floor like the renderer's (0.25 m cells), 24 m across.
export function buildGround() {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const ctx = canvas.getContext("2d");
  const light = "rgb(199,199,189)";
  const dark = "rgb(140,148,143)";
  for (let i = 0; i < 2; i++)
    for (let j = 0; j < 2; j++) {
      ctx.fillStyle = (i + j) % 2 ? dark : light;
      ctx.fillRect(i * 32, j * 32, 32, 32);
    }
  const tex = new THREE.CanvasTexture(canvas);
  tex.wrapS = tex.wrapT = THREE.RepeatWrapping;
  tex.magFilter = THREE.NearestFilter;
  tex.repeat.set(48, 48);
  const mesh = new THREE.Mesh(
    new THREE.PlaneBufferGeometry(24, 24),
    new THREE.MeshLambertMaterial({ map: tex }),
  );
  mesh.name = "ground";
  return mesh;
}

// Everything a scene message describes, as one group plus the robots' link objects.
export function buildScene(msg) {
  const root = new THREE.Group();
  root.add(buildStatics(msg));
  const robots = (msg.robots || []).map((r, i) => buildRobot(r, i));
  for (const r of robots) root.add(r.group);
  return { root, robots };
}
