// Point and mesh files: the readers and writers used by the `moa` tool, the tests and the
// benchmarks. Not part of the library's ABI.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace moa::io {

// A malformed, truncated or unreadable file. what() names the file and, where it applies, the
// line (text formats) or byte offset (binary formats) and what was wrong there.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Format { Xyz, Ply, Off, Obj, Stl };

struct MeshData {
  std::vector<double> xyz;          // x y z per vertex
  std::vector<uint32_t> triangles;  // 3 indices per triangle (polygons are fan-triangulated)
};

// The format named by a path's extension (case-insensitive: .xyz .txt .pts .csv for XYZ, .ply
// .off .obj .stl). Throws IoError for an unknown extension.
Format format_from_path(const std::string &path);

// "XYZ", "PLY", "OFF", "OBJ" or "STL", for messages.
const char *format_name(Format format);

// Reads the points of a file: XYZ (columns separated by whitespace, commas or semicolons; a
// first line of column names may say where x, y and z are; extra columns and '#' comments
// ignored), PLY (ASCII, binary little and big endian; float or double x y z; other properties
// and elements ignored), and the vertices of OFF and OBJ. The content decides the format where
// it can (a PLY or OFF header is recognised whatever the extension); a file whose content
// contradicts its extension is an error naming both.
std::vector<double> read_points(const std::string &path);

// Reads a triangle mesh (OFF, PLY, OBJ, binary or ASCII STL; polygons fan-triangulated).
MeshData read_mesh(const std::string &path);

// Writes a mesh in the format of the path's extension: PLY (binary little endian unless ascii),
// OFF, OBJ, binary STL. Throws IoError when the file cannot be written, and (before creating
// it) for an extension without faces (.xyz) or a mesh whose indices or sizes are invalid.
void write_mesh(const std::string &path, const MeshData &mesh, bool ascii = false);

// Writes points (x y z each) in the format of the path's extension: XYZ (comma-separated for
// .csv), PLY (binary little endian unless ascii; vertices only), OFF (no faces), OBJ. STL
// cannot hold points: IoError.
void write_points(const std::string &path, const std::vector<double> &xyz, bool ascii = false);

}  // namespace moa::io
