// The per-format readers and writers behind io.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/io.hpp"
#include "sniff.hpp"

namespace moa::io::detail {

struct Source {
  const std::string &path;  // for messages
  std::string_view data;    // the whole file
  Content content;          // what sniff_content found
};

// Readers append to their output. want_faces false reads only the vertices (and may stop
// before the faces, which are then not checked).
void read_xyz(const Source &source, std::vector<double> &xyz);
void read_ply(const Source &source, MeshData &mesh, bool want_faces);
void read_off(const Source &source, MeshData &mesh, bool want_faces);
void read_obj(const Source &source, MeshData &mesh, bool want_faces);
void read_stl(const Source &source, MeshData &mesh);  // vertices merged where equal
void read_stl_ascii(const Source &source, MeshData &mesh);
void read_stl_binary(const Source &source, MeshData &mesh);

// Writers append a whole file to out; the mesh is already validated.
using Triangles = std::vector<uint32_t>;
// Columns separated by `separator`: a space, or a comma for .csv.
void write_xyz(std::string &out, const std::vector<double> &xyz, char separator);
void write_ply(std::string &out, const std::vector<double> &xyz, const Triangles *triangles,
               bool ascii);
void write_off(std::string &out, const std::vector<double> &xyz, const Triangles &triangles);
void write_obj(std::string &out, const std::vector<double> &xyz, const Triangles &triangles);
void write_stl(std::string &out, const std::vector<double> &xyz, const Triangles &triangles);

}  // namespace moa::io::detail
