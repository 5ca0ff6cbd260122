// plot_histogram: bars, a percent axis and numbers drawn with a 3x5 pixel font, so that the
// chart needs no font library.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render/render.hpp"

namespace moa::render {
namespace {

constexpr Rgb kBar{90, 130, 190};
constexpr Rgb kAxis{60, 60, 60};
constexpr Rgb kGrid{225, 225, 225};
constexpr Rgb kText{40, 40, 40};
constexpr int kFontScale = 2;  // each font pixel is 2x2 image pixels

// Rows of 3 bits, top first; the leftmost pixel is the highest bit.
struct Glyph {
  char c;
  uint8_t rows[5];
};
constexpr Glyph kGlyphs[] = {{'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}},
                             {'3', {7, 1, 7, 1, 7}}, {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}},
                             {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}}, {'8', {7, 5, 7, 5, 7}},
                             {'9', {7, 5, 7, 1, 7}}, {'%', {5, 1, 2, 4, 5}}, {'.', {0, 0, 0, 0, 2}},
                             {'-', {0, 0, 7, 0, 0}}};

void fill_rect(Image &image, int x0, int y0, int x1, int y1, Rgb c) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) image.set(x, y, c);
}

int text_width(const std::string &text) { return int(text.size()) * 4 * kFontScale - kFontScale; }

// Draws text with its top-left corner at (x, y); unknown characters are blanks.
void draw_text(Image &image, int x, int y, const std::string &text) {
  for (char ch : text) {
    for (const Glyph &g : kGlyphs) {
      if (g.c != ch) continue;
      for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 3; ++col)
          if (g.rows[row] & (4 >> col))
            fill_rect(image, x + col * kFontScale, y + row * kFontScale, x + (col + 1) * kFontScale,
                      y + (row + 1) * kFontScale, kText);
    }
    x += 4 * kFontScale;
  }
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A round step for the percent axis so that it has at most five intervals.
double percent_step(double top_percent) {
  for (double step : {1.0, 2.0, 5.0, 10.0, 20.0, 25.0, 50.0})
    if (top_percent <= 5 * step) return step;
  return 100;
}

}  // namespace

Image plot_histogram(const std::vector<size_t> &counts, double first_edge, double edge_step,
                     int width, int height) {
  if (width < 120 || height < 80 || width > kMaxSide || height > kMaxSide)
    throw RenderError("histogram size out of range");
  Image image(width, height, kBackground);
  const int left = 56, right = width - 16, top = 16, bottom = height - 36;
  size_t total = 0, most = 0;
  for (size_t n : counts) total += n, most = std::max(most, n);
  const double top_share = total ? 100.0 * double(most) / double(total) : 0;
  const double step = percent_step(std::max(top_share, 1.0));
  const double axis_top = step * std::max(1.0, std::ceil(top_share / step));

  // Grid lines and labels of the percent axis.
  const int plot_height = bottom - top;
  for (int i = 0; i * step <= axis_top + 1e-9; ++i) {
    const int y = bottom - int(std::lround(i * step / axis_top * plot_height));
    fill_rect(image, left, y, right, y + 1, kGrid);
    const std::string label = number(i * step) + "%";
    draw_text(image, left - 8 - text_width(label), y - 5 * kFontScale / 2, label);
  }

  // Bars, a two-pixel gap between neighbours.
  const size_t bins = std::max<size_t>(counts.size(), 1);
  const double bar_width = double(right - left) / double(bins);
  for (size_t b = 0; b < counts.size(); ++b) {
    const double share = total ? 100.0 * double(counts[b]) / double(total) : 0;
    const int h = int(std::lround(share / axis_top * plot_height));
    const int x0 = left + int(std::lround(b * bar_width)) + 1;
    const int x1 = left + int(std::lround((b + 1) * bar_width)) - 1;
    fill_rect(image, x0, bottom - h, x1, bottom, kBar);
  }

  // Axes, then the bin edges below the horizontal one (every other when crowded).
  fill_rect(image, left - 1, top, left, bottom + 1, kAxis);
  fill_rect(image, left - 1, bottom, right, bottom + 1, kAxis);
  const int every = bar_width < 28 ? 2 : 1;
  for (size_t e = 0; e <= counts.size(); e += every) {
    const int x = left + int(std::lround(e * bar_width));
    fill_rect(image, x, bottom, x + 1, bottom + 5, kAxis);
    const std::string label = number(first_edge + double(e) * edge_step);
    draw_text(image, x - text_width(label) / 2, bottom + 9, label);
  }
  return image;
}

}  // namespace moa::render
