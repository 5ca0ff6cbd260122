// The small parts of the render interface: view names, image sizes, file names.
#include <cctype>
#include <cstdlib>
#include <cstring>

#include "render/render.hpp"

namespace moa::render {
namespace {

struct ViewName {
  View view;
  const char *name;
};

constexpr ViewName kViews[] = {
    {View::Front, "front"}, {View::Back, "back"},     {View::Left, "left"}, {View::Right, "right"},
    {View::Top, "top"},     {View::Bottom, "bottom"}, {View::Iso, "iso"}};

// A whole number in [1, kMaxSide] from text[begin, end), digits only.
bool parse_side(const std::string &text, size_t begin, size_t end, int &side) {
  if (begin >= end || end - begin > 5) return false;
  int value = 0;
  for (size_t i = begin; i < end; ++i) {
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) return false;
    value = value * 10 + (text[i] - '0');
  }
  if (value < 1 || value > kMaxSide) return false;
  side = value;
  return true;
}

}  // namespace

Image::Image(int w, int h, Rgb fill) : width(w), height(h), rgb(3 * size_t(w) * size_t(h)) {
  for (size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = fill.r;
    rgb[i + 1] = fill.g;
    rgb[i + 2] = fill.b;
  }
}

bool view_from_name(const std::string &name, View &view) {
  for (const ViewName &v : kViews)
    if (name == v.name) {
      view = v.view;
      return true;
    }
  return false;
}

const char *view_name(View view) {
  for (const ViewName &v : kViews)
    if (view == v.view) return v.name;
  return "?";
}

const char *view_names() { return "front|back|left|right|top|bottom|iso"; }

bool parse_size(const std::string &text, int &width, int &height) {
  const size_t x = text.find_first_of("xX");
  if (x == std::string::npos) {
    if (!parse_side(text, 0, text.size(), width)) return false;
    height = width;
    return true;
  }
  int w = 0, h = 0;
  if (!parse_side(text, 0, x, w) || !parse_side(text, x + 1, text.size(), h)) return false;
  width = w;
  height = h;
  return true;
}

bool has_png_extension(const std::string &path) {
  if (path.size() < 4) return false;
  const std::string tail = path.substr(path.size() - 4);
  return tail[0] == '.' && std::tolower(static_cast<unsigned char>(tail[1])) == 'p' &&
         std::tolower(static_cast<unsigned char>(tail[2])) == 'n' &&
         std::tolower(static_cast<unsigned char>(tail[3])) == 'g';
}

}  // namespace moa::render
