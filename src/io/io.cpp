// The public entry points: pick the format, check the content against it, dispatch.
#include "io/io.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

#include "errors.hpp"
#include "file_access.hpp"
#include "formats.hpp"
#include "sniff.hpp"

namespace moa::io {
namespace {

using detail::fail;

// The mesh as a writer needs it: whole triples and indices that exist.
void validate(const std::string &path, const std::vector<double> &xyz,
              const std::vector<uint32_t> &triangles) {
  if (xyz.size() % 3 != 0)
    fail(path, "cannot write: " + std::to_string(xyz.size()) +
                   " coordinates are not a whole number of x y z triples");
  if (triangles.size() % 3 != 0)
    fail(path, "cannot write: " + std::to_string(triangles.size()) +
                   " triangle indices are not a whole number of triangles");
  const size_t vertices = xyz.size() / 3;
  for (size_t i = 0; i < triangles.size(); ++i)
    if (triangles[i] >= vertices)
      fail(path, "cannot write: triangle " + std::to_string(i / 3) + " refers to vertex " +
                     std::to_string(triangles[i]) + " but there are " +
                     std::to_string(vertices) + " vertices");
}

}  // namespace

const char *format_name(Format format) {
  switch (format) {
    case Format::Xyz: return "XYZ";
    case Format::Ply: return "PLY";
    case Format::Off: return "OFF";
    case Format::Obj: return "OBJ";
    case Format::Stl: return "STL";
  }
  return "unknown";
}

namespace {

constexpr const char *kExtensions = ".xyz .txt .pts .csv .ply .off .obj .stl";

// The extension of a path's file name, lower case; fails when there is none.
std::string extension_of(const std::string &path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    fail(path, std::string("no file extension to tell the format (") + kExtensions + ")");
  std::string extension = path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

Format format_from_path(const std::string &path) {
  const std::string extension = extension_of(path);
  if (extension == "xyz" || extension == "txt" || extension == "pts" || extension == "csv")
    return Format::Xyz;
  if (extension == "ply") return Format::Ply;
  if (extension == "off") return Format::Off;
  if (extension == "obj") return Format::Obj;
  if (extension == "stl") return Format::Stl;
  fail(path, "unknown extension " + detail::quoted(path.substr(path.find_last_of('.'))) +
                 " (expected " + kExtensions + ")");
}

std::vector<double> read_points(const std::string &path) {
  // Read before looking at the extension so that a directory or a missing file says so.
  const std::string data = detail::read_whole_file(path);
  const Format format = format_from_path(path);
  const detail::Source source{path, data, detail::check_content(path, data, format)};
  MeshData mesh;
  switch (format) {
    case Format::Xyz: detail::read_xyz(source, mesh.xyz); break;
    case Format::Ply: detail::read_ply(source, mesh, false); break;
    case Format::Off: detail::read_off(source, mesh, false); break;
    case Format::Obj: detail::read_obj(source, mesh, false); break;
    case Format::Stl: detail::read_stl(source, mesh); break;
  }
  return std::move(mesh.xyz);
}

MeshData read_mesh(const std::string &path) {
  const std::string data = detail::read_whole_file(path);
  const Format format = format_from_path(path);
  const detail::Source source{path, data, detail::check_content(path, data, format)};
  MeshData mesh;
  switch (format) {
    case Format::Xyz: fail(path, "an XYZ file holds points, not a mesh");
    case Format::Ply: detail::read_ply(source, mesh, true); break;
    case Format::Off: detail::read_off(source, mesh, true); break;
    case Format::Obj: detail::read_obj(source, mesh, true); break;
    case Format::Stl: detail::read_stl(source, mesh); break;
  }
  return mesh;
}

void write_mesh(const std::string &path, const MeshData &mesh, bool ascii) {
  const Format format = format_from_path(path);
  validate(path, mesh.xyz, mesh.triangles);
  std::string out;
  switch (format) {
    case Format::Xyz: fail(path, "cannot write a mesh as XYZ, which holds only points");
    case Format::Ply: detail::write_ply(out, mesh.xyz, &mesh.triangles, ascii); break;
    case Format::Off: detail::write_off(out, mesh.xyz, mesh.triangles); break;
    case Format::Obj: detail::write_obj(out, mesh.xyz, mesh.triangles); break;
    case Format::Stl:
      if (mesh.triangles.size() / 3 > std::numeric_limits<uint32_t>::max())
        fail(path, "cannot write: binary STL holds at most 2^32 - 1 triangles");
      detail::write_stl(out, mesh.xyz, mesh.triangles);
      break;
  }
  detail::write_whole_file(path, out);
}

void write_points(const std::string &path, const std::vector<double> &xyz, bool ascii) {
  const Format format = format_from_path(path);
  static const std::vector<uint32_t> no_triangles;
  validate(path, xyz, no_triangles);
  std::string out;
  switch (format) {
    case Format::Xyz:  // a .csv gets commas, so that spreadsheets split its columns
      detail::write_xyz(out, xyz, extension_of(path) == "csv" ? ',' : ' ');
      break;
    case Format::Ply: detail::write_ply(out, xyz, nullptr, ascii); break;
    case Format::Off: detail::write_off(out, xyz, no_triangles); break;
    case Format::Obj: detail::write_obj(out, xyz, no_triangles); break;
    case Format::Stl: fail(path, "cannot write points as STL, which holds only triangles");
  }
  detail::write_whole_file(path, out);
}

}  // namespace moa::io
