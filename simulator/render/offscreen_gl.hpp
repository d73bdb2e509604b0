#pragma once
// An OpenGL context that draws into memory (OSMesa): no display, no GPU, same pixels everywhere.
#include <vector>

#include <GL/osmesa.h>

#include "simulator/render/image.hpp"

namespace stride::render {

class OffscreenGl {
 public:
  OffscreenGl(int width, int height);  // throws stride::Error if no context can be made
  ~OffscreenGl();
  OffscreenGl(const OffscreenGl&) = delete;
  OffscreenGl& operator=(const OffscreenGl&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  void make_current();
  RgbaImage read();  // waits for drawing to finish; rows top to bottom

 private:
  int width_, height_;
  std::vector<unsigned char> buffer_;
  OSMesaContext context_ = nullptr;
};

}  // namespace stride::render
