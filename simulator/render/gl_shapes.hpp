#pragma once
// Solid primitives in fixed-function OpenGL, centred at the origin of the current matrix, with
// outward normals for lighting. Axes follow ODE's: cylinders and capsules along z.
namespace stride::render {

void draw_box(double sx, double sy, double sz);
void draw_cylinder(double radius, double length);
void draw_sphere(double radius);
void draw_capsule(double radius, double length);
// A square checkerboard of `extent` metres around (cx, cy) at z = 0, cells of `cell` metres.
void draw_checker_floor(double cx, double cy, double extent, double cell);

}  // namespace stride::render
