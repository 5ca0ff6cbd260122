// PNG files through libpng's simplified API; the files are opened here so that a failure can
// name its cause (errno), which libpng's own messages do not.
#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "render/render.hpp"

namespace moa::render {
namespace {

std::string system_error(const std::string &path, const char *what) {
  return path + ": " + what + ": " + std::strerror(errno);
}

// Frees what libpng holds for a png_image whatever way we leave.
struct ImageGuard {
  png_image &image;
  ~ImageGuard() { png_image_free(&image); }
};

}  // namespace

void write_png(const std::string &path, const Image &image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != 3 * size_t(image.width) * size_t(image.height))
    throw RenderError(path + ": cannot write an empty or malformed image");
  std::FILE *file = std::fopen(path.c_str(), "wb");
  if (!file) throw RenderError(system_error(path, "cannot write"));
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = PNG_FORMAT_RGB;
  const bool encoded =
      png_image_write_to_stdio(&png, file, 0, image.rgb.data(), 3 * image.width, nullptr) != 0;
  const std::string message = png.message;
  png_image_free(&png);
  errno = 0;
  const bool flushed = std::fflush(file) == 0 && !std::ferror(file);
  const int saved = errno;
  const bool closed = std::fclose(file) == 0;
  if (!encoded || !flushed || !closed) {
    std::remove(path.c_str());  // no half-written picture left behind
    errno = saved;
    if (!encoded) throw RenderError(path + ": cannot write: " + message);
    throw RenderError(system_error(path, "cannot write"));
  }
}

Image read_png(const std::string &path) {
  std::FILE *file = std::fopen(path.c_str(), "rb");
  if (!file) throw RenderError(system_error(path, "cannot read"));
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  ImageGuard guard{png};
  Image out;
  bool ok = png_image_begin_read_from_stdio(&png, file) != 0;
  if (ok && (png.width > png_uint_32(kMaxSide) || png.height > png_uint_32(kMaxSide))) {
    std::fclose(file);
    throw RenderError(path + ": image larger than " + std::to_string(kMaxSide) + " pixels a side");
  }
  if (ok) {
    png.format = PNG_FORMAT_RGB;
    out.width = int(png.width);
    out.height = int(png.height);
    out.rgb.resize(PNG_IMAGE_SIZE(png));
    ok = png_image_finish_read(&png, nullptr, out.rgb.data(), 0, nullptr) != 0;
  }
  const std::string message = png.message;
  std::fclose(file);
  if (!ok) throw RenderError(path + ": not a readable PNG: " + message);
  return out;
}

}  // namespace moa::render
