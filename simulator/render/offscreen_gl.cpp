#include "simulator/render/offscreen_gl.hpp"

#include <GL/gl.h>

#include "robot/core/error.hpp"

namespace stride::render {

OffscreenGl::OffscreenGl(int width, int height)
    : width_(width), height_(height), buffer_(static_cast<size_t>(width) * height * 4) {
  context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context_) throw Error("renderer: OSMesa could not create an offscreen OpenGL context");
  make_current();
}

OffscreenGl::~OffscreenGl() {
  OSMesaDestroyContext(context_);
}

void OffscreenGl::make_current() {
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw Error("renderer: OSMesa could not bind a " + std::to_string(width_) + "x" +
                std::to_string(height_) + " image");
  OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 at the top, as image files store it
}

RgbaImage OffscreenGl::read() {
  glFinish();
  RgbaImage out;
  out.width = width_;
  out.height = height_;
  out.rgba = buffer_;
  return out;
}

}  // namespace stride::render
