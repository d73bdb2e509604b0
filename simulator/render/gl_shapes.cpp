#include "simulator/render/gl_shapes.hpp"

#include <cmath>
#include <initializer_list>
#include <numbers>

#include <GL/gl.h>

namespace stride::render {
namespace {
constexpr int kSegments = 24;  // around a cylinder or sphere: smooth enough at snapshot sizes

void sphere_cap(double radius, double z_offset, bool upper) {
  constexpr int rings = kSegments / 4;
  for (int i = 0; i < rings; ++i) {
    const double a0 = std::numbers::pi / 2 * i / rings, a1 = std::numbers::pi / 2 * (i + 1) / rings;
    const double s = upper ? 1.0 : -1.0;
    glBegin(GL_QUAD_STRIP);
    for (int k = 0; k <= kSegments; ++k) {
      const double phi = 2 * std::numbers::pi * k / kSegments;
      for (double a : {a0, a1}) {
        const double nx = std::cos(a) * std::cos(phi), ny = std::cos(a) * std::sin(phi),
                     nz = s * std::sin(a);
        glNormal3d(nx, ny, nz);
        glVertex3d(radius * nx, radius * ny, z_offset + radius * nz);
      }
    }
    glEnd();
  }
}

void tube(double radius, double length) {
  glBegin(GL_QUAD_STRIP);
  for (int k = 0; k <= kSegments; ++k) {
    const double phi = 2 * std::numbers::pi * k / kSegments;
    const double c = std::cos(phi), s = std::sin(phi);
    glNormal3d(c, s, 0);
    glVertex3d(radius * c, radius * s, length / 2);
    glVertex3d(radius * c, radius * s, -length / 2);
  }
  glEnd();
}
}  // namespace

void draw_box(double sx, double sy, double sz) {
  const double x = sx / 2, y = sy / 2, z = sz / 2;
  glBegin(GL_QUADS);
  glNormal3d(1, 0, 0);
  glVertex3d(x, -y, -z), glVertex3d(x, y, -z), glVertex3d(x, y, z), glVertex3d(x, -y, z);
  glNormal3d(-1, 0, 0);
  glVertex3d(-x, -y, -z), glVertex3d(-x, -y, z), glVertex3d(-x, y, z), glVertex3d(-x, y, -z);
  glNormal3d(0, 1, 0);
  glVertex3d(-x, y, -z), glVertex3d(-x, y, z), glVertex3d(x, y, z), glVertex3d(x, y, -z);
  glNormal3d(0, -1, 0);
  glVertex3d(-x, -y, -z), glVertex3d(x, -y, -z), glVertex3d(x, -y, z), glVertex3d(-x, -y, z);
  glNormal3d(0, 0, 1);
  glVertex3d(-x, -y, z), glVertex3d(x, -y, z), glVertex3d(x, y, z), glVertex3d(-x, y, z);
  glNormal3d(0, 0, -1);
  glVertex3d(-x, -y, -z), glVertex3d(-x, y, -z), glVertex3d(x, y, -z), glVertex3d(x, -y, -z);
  glEnd();
}

void draw_cylinder(double radius, double length) {
  tube(radius, length);
  for (double s : {1.0, -1.0}) {
    glBegin(GL_TRIANGLE_FAN);
    glNormal3d(0, 0, s);
    glVertex3d(0, 0, s * length / 2);
    for (int k = 0; k <= kSegments; ++k) {
      const double phi = s * 2 * std::numbers::pi * k / kSegments;
      glVertex3d(radius * std::cos(phi), radius * std::sin(phi), s * length / 2);
    }
    glEnd();
  }
}

void draw_sphere(double radius) {
  sphere_cap(radius, 0, true);
  sphere_cap(radius, 0, false);
}

void draw_capsule(double radius, double length) {
  tube(radius, length);
  sphere_cap(radius, length / 2, true);
  sphere_cap(radius, -length / 2, false);
}

void draw_checker_floor(double cx, double cy, double extent, double cell) {
  const int n = static_cast<int>(std::ceil(extent / cell / 2));
  const int i0 = static_cast<int>(std::floor(cx / cell)),
            j0 = static_cast<int>(std::floor(cy / cell));
  glBegin(GL_QUADS);
  glNormal3d(0, 0, 1);
  for (int i = i0 - n; i <= i0 + n; ++i)
    for (int j = j0 - n; j <= j0 + n; ++j) {
      const bool dark = ((i + j) % 2 + 2) % 2 == 1;
      if (dark)
        glColor3d(0.55, 0.58, 0.56);
      else
        glColor3d(0.78, 0.78, 0.74);
      const double x = i * cell, y = j * cell;
      glVertex3d(x, y, 0), glVertex3d(x + cell, y, 0), glVertex3d(x + cell, y + cell, 0),
          glVertex3d(x, y + cell, 0);
    }
  glEnd();
}

}  // namespace stride::render
