#include "simulator/render/text_overlay.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace stride::render {
namespace {

constexpr int kGlyphW = 5, kGlyphH = 7, kAdvance = 6, kLineGap = 3, kMargin = 4;

struct Glyph {
  char c;
  std::array<const char*, kGlyphH> rows;  // '#' lit
};

// Our own 5x7 shapes, drawn for legibility at small sizes.
constexpr Glyph kGlyphs[] = {
    {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"####.", "....#", "....#", ".###.", "....#", "....#", "####."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'B', {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."}},
    {'C', {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."}},
    {'D', {"###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."}},
    {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
    {'F', {"#####", "#....", "#....", "####.", "#....", "#....", "#...."}},
    {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"}},
    {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'I', {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'J', {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."}},
    {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
    {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
    {'M', {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"}},
    {'N', {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"}},
    {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
    {'Q', {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"}},
    {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
    {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
    {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'V', {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."}},
    {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
    {'Y', {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."}},
    {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
    {':', {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
    {'=', {".....", ".....", "#####", ".....", "#####", ".....", "....."}},
    {'/', {"....#", "....#", "...#.", "..#..", ".#...", "#....", "#...."}},
    {'%', {"##..#", "##..#", "...#.", "..#..", ".#...", "#..##", "#..##"}},
    {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
    {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
    {'[', {".###.", ".#...", ".#...", ".#...", ".#...", ".#...", ".###."}},
    {']', {".###.", "...#.", "...#.", "...#.", "...#.", "...#.", ".###."}},
    {'_', {".....", ".....", ".....", ".....", ".....", ".....", "#####"}},
    {'|', {"..#..", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'?', {".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."}},
};

const Glyph& glyph(char c) {
  const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kGlyphs)
    if (g.c == up) return g;
  return kGlyphs[std::size(kGlyphs) - 1];  // '?'
}

void blend(RgbaImage& image, int x, int y, const unsigned char* rgb, int alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::uint8_t* p = image.rgba.data() + (static_cast<std::size_t>(y) * image.width + x) * 4;
  for (int k = 0; k < 3; ++k)
    p[k] = static_cast<std::uint8_t>((rgb[k] * alpha + p[k] * (255 - alpha)) / 255);
}

}  // namespace

int text_width(std::string_view text, const TextStyle& style) {
  return text.empty() ? 0 : static_cast<int>(text.size() * kAdvance - 1) * style.scale;
}

void draw_text(RgbaImage& image, int x, int y, std::string_view text, const TextStyle& style) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const Glyph& g = glyph(text[i]);
    const int left = x + static_cast<int>(i) * kAdvance * style.scale;
    for (int row = 0; row < kGlyphH; ++row)
      for (int col = 0; col < kGlyphW; ++col) {
        if (g.rows[row][col] != '#') continue;
        for (int dy = 0; dy < style.scale; ++dy)
          for (int dx = 0; dx < style.scale; ++dx)
            blend(image, left + col * style.scale + dx, y + row * style.scale + dy, style.colour,
                  255);
      }
  }
}

void draw_overlay(RgbaImage& image, const std::vector<std::string>& lines,
                  const TextStyle& requested) {
  if (lines.empty()) return;
  // A line wider than the picture (a long robot name, a fall, three-digit steps) is drawn smaller
  // rather than cut off at the edge.
  TextStyle style = requested;
  int width = 0;
  for (;;) {
    width = 0;
    for (const auto& l : lines) width = std::max(width, text_width(l, style));
    if (style.scale <= 1 || width + 4 * kMargin <= image.width) break;
    --style.scale;
  }
  const int line_h = (kGlyphH + kLineGap) * style.scale;
  const int box_w = width + 4 * kMargin;  // text starts 2 margins in
  const int box_h = static_cast<int>(lines.size()) * line_h + 2 * kMargin;
  if (style.backing[3] > 0)
    for (int y = 0; y < box_h; ++y)
      for (int x = 0; x < box_w; ++x) blend(image, x, y, style.backing, style.backing[3]);
  for (std::size_t i = 0; i < lines.size(); ++i)
    draw_text(image, 2 * kMargin,
              kMargin + kLineGap * style.scale / 2 + static_cast<int>(i) * line_h, lines[i], style);
}

}  // namespace stride::render
