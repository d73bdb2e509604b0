#pragma once
// Text drawn into a rendered picture (time and status lines over a movie frame): a built-in 5x7
// pixel font, no font files. Letters print as capitals; characters without a glyph print as '?'.
#include <string>
#include <string_view>
#include <vector>

#include "simulator/render/image.hpp"

namespace stride::render {

struct TextStyle {
  int scale = 2;  // pixels per font pixel
  unsigned char colour[3] = {255, 255, 255};
  unsigned char backing[4] = {0, 0, 0, 150};  // box behind the lines; alpha 0: none
};

// Draws one line with its top-left corner at (x, y); clipped to the image.
void draw_text(RgbaImage& image, int x, int y, std::string_view text, const TextStyle& style);

// Lines stacked at the top-left corner on a shared translucent box; at a smaller scale than
// `style` asks where the widest line would not fit the picture.
void draw_overlay(RgbaImage& image, const std::vector<std::string>& lines,
                  const TextStyle& style = {});

// Width in pixels of `text` at `style` (for layout and tests).
int text_width(std::string_view text, const TextStyle& style);

}  // namespace stride::render
