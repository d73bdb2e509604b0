#include "simulator/render/world_renderer.hpp"

#include <GL/gl.h>
#include <ode/ode.h>

#include <set>

#include "robot/core/error.hpp"
#include "robot/model/robot_model.hpp"
#include "simulator/render/body_side.hpp"
#include "simulator/render/gl_shapes.hpp"
#include "simulator/render/offscreen_gl.hpp"
#include "simulator/world/geom_info.hpp"
#include "simulator/world/ode/ode_world.hpp"

namespace stride::render {
namespace {

// The link a robot geom belongs to (robot bodies carry their model::Link).
const model::Link* link_of(dGeomID g) {
  dBodyID b = dGeomGetBody(g);
  return b ? static_cast<const model::Link*>(dBodyGetData(b)) : nullptr;
}

// Left side blue, right side orange, the rest light grey: a walk reads at a glance.
Eigen::Vector3d side_colour(BodySide side) {
  switch (side) {
    case BodySide::Left:
      return {0.36, 0.56, 0.92};
    case BodySide::Right:
      return {0.93, 0.52, 0.30};
    case BodySide::Centre:
      break;
  }
  return {0.86, 0.86, 0.88};
}

void set_colour(dGeomID g, const sim::GeomInfo* info) {
  if (!info || info->robot < 0) {
    glColor3d(0.62, 0.55, 0.47);  // static environment
    return;
  }
  const model::Link* link = link_of(g);
  Eigen::Vector3d c = side_colour(link ? side_of_link(link->name) : BodySide::Centre);
  // Neighbouring links alternate in shade so the chain reads in a still picture.
  c *= info->link % 2 == 0 ? 1.0 : 0.86;
  if (info->robot != 0) c = 0.5 * c + Eigen::Vector3d(0.2, 0.35, 0.2);  // other robots greener
  glColor3d(c.x(), c.y(), c.z());
}

void load_pose(dGeomID g) {
  const dReal* p = dGeomGetPosition(g);
  const dReal* r = dGeomGetRotation(g);  // row-major 3x4
  const double m[16] = {r[0], r[4], r[8],  0, r[1], r[5], r[9], 0,
                        r[2], r[6], r[10], 0, p[0], p[1], p[2], 1};
  glMultMatrixd(m);
}

void draw_geom(dGeomID g, const CameraView& view) {
  const int cls = dGeomGetClass(g);
  if (cls == dPlaneClass) {
    dVector4 plane;
    dGeomPlaneGetParams(g, plane);
    if (plane[2] < 0.999) return;  // only level ground is drawn
    glPushMatrix();
    glTranslated(0, 0, plane[3]);
    draw_checker_floor(view.target.x(), view.target.y(), 12.0, 0.25);
    glPopMatrix();
    return;
  }
  set_colour(g, static_cast<const sim::GeomInfo*>(dGeomGetData(g)));
  glPushMatrix();
  load_pose(g);
  switch (cls) {
    case dBoxClass: {
      dVector3 s;
      dGeomBoxGetLengths(g, s);
      draw_box(s[0], s[1], s[2]);
      break;
    }
    case dCylinderClass: {
      dReal r, l;
      dGeomCylinderGetParams(g, &r, &l);
      draw_cylinder(r, l);
      break;
    }
    case dCapsuleClass: {
      dReal r, l;
      dGeomCapsuleGetParams(g, &r, &l);
      draw_capsule(r, l);
      break;
    }
    case dSphereClass:
      draw_sphere(dGeomSphereGetRadius(g));
      break;
    default:
      break;  // no other shapes are built from scenes
  }
  glPopMatrix();
}

void draw_space(dSpaceID space, const CameraView& view) {
  const int n = dSpaceGetNumGeoms(space);
  for (int i = 0; i < n; ++i) draw_geom(dSpaceGetGeom(space, i), view);
}

// Every hinge of the robots as a dot in its side's darker colour, drawn over the bodies (the
// joints sit inside the links' shapes).
void draw_joints(dSpaceID robots) {
  std::set<dJointID> seen;
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  const int n = dSpaceGetNumGeoms(robots);
  for (int i = 0; i < n; ++i) {
    dBodyID b = dGeomGetBody(dSpaceGetGeom(robots, i));
    if (!b) continue;
    for (int k = 0; k < dBodyGetNumJoints(b); ++k) {
      dJointID j = dBodyGetJoint(b, k);
      if (dJointGetType(j) != dJointTypeHinge || !seen.insert(j).second) continue;
      dBodyID child = dJointGetBody(j, 1) ? dJointGetBody(j, 1) : dJointGetBody(j, 0);
      const auto* link = static_cast<const model::Link*>(dBodyGetData(child));
      const Eigen::Vector3d c =
          0.45 * side_colour(link ? side_of_link(link->name) : BodySide::Centre);
      dVector3 anchor;
      dJointGetHingeAnchor(j, anchor);
      glColor3d(c.x(), c.y(), c.z());
      glPushMatrix();
      glTranslated(anchor[0], anchor[1], anchor[2]);
      draw_sphere(0.009);
      glPopMatrix();
    }
  }
  glEnable(GL_LIGHTING);
  glEnable(GL_DEPTH_TEST);
}

void set_lights(const std::vector<sim::SceneLight>& lights) {
  static const std::vector<sim::SceneLight> fallback = {sim::SceneLight{}};
  const auto& use = lights.empty() ? fallback : lights;
  const float ambient[4] = {0.35f, 0.35f, 0.35f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  for (size_t i = 0; i < use.size() && i < 8; ++i) {
    const GLenum id = GL_LIGHT0 + static_cast<GLenum>(i);
    const Eigen::Vector3d towards = -use[i].direction.normalized();
    const float pos[4] = {static_cast<float>(towards.x()), static_cast<float>(towards.y()),
                          static_cast<float>(towards.z()), 0};  // w = 0: directional
    const auto k = static_cast<float>(use[i].intensity);
    const float diffuse[4] = {k, k, k, 1};
    const float none[4] = {0, 0, 0, 1};
    glEnable(id);
    glLightfv(id, GL_POSITION, pos);
    glLightfv(id, GL_DIFFUSE, diffuse);
    glLightfv(id, GL_AMBIENT, none);
  }
}

}  // namespace

WorldRenderer::WorldRenderer() = default;
WorldRenderer::~WorldRenderer() = default;

RgbaImage WorldRenderer::render(const sim::PhysicsWorld& world, const CameraView& view,
                                const std::vector<sim::SceneLight>& lights) {
  if (!gl_ || gl_->width() != view.width || gl_->height() != view.height)
    gl_ = std::make_unique<OffscreenGl>(view.width, view.height);
  gl_->make_current();
  glViewport(0, 0, view.width, view.height);
  glClearColor(0.62f, 0.74f, 0.86f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  const Eigen::Matrix4d projection = projection_matrix(view);
  glLoadMatrixd(projection.data());
  glMatrixMode(GL_MODELVIEW);
  const Eigen::Matrix4d camera = view_matrix(view);
  glLoadMatrixd(camera.data());
  set_lights(lights);  // after the view matrix: light directions are in the world frame

  const auto* ode = dynamic_cast<const sim::OdeWorld*>(&world);
  if (!ode)
    throw Error(std::string("render: the ") + world.engine_name() +
                " engine's world is not drawn (only the ode engine's is)");
  draw_space(ode->static_space(), view);
  draw_space(ode->robot_space(), view);
  draw_joints(ode->robot_space());
  return gl_->read();
}

}  // namespace stride::render
