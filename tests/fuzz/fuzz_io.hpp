// The reader fuzz targets: the input is the whole content of a file with one format's
// extension. It is read the way io.cpp reads files (content check, then the format's reader),
// but from memory, so that no file system call slows the fuzzer down. Every input must either
// read or throw IoError naming the file; a read must give whole triples and valid indices, the
// same vertices as points and as a mesh, and survive a binary PLY round trip bit for bit.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>

#include "io/formats.hpp"
#include "io/io.hpp"
#include "io/sniff.hpp"

namespace moa::fuzz {

[[noreturn]] inline void violated(const char *what, const std::string &detail = {}) {
  std::fprintf(stderr, "fuzz: %s%s%s\n", what, detail.empty() ? "" : ": ", detail.c_str());
  std::fflush(stderr);
  std::abort();
}

// Runs read(); true if it returned, false if it threw a well-formed IoError. Any other
// exception is a bug: the readers promise IoError for every bad file.
template <class Read>
bool attempt(const std::string &path, Read read) {
  try {
    read();
    return true;
  } catch (const io::IoError &e) {
    const std::string message = e.what();
    if (message.compare(0, path.size() + 1, path + ":") != 0)
      violated("an IoError message does not start with the path", message);
    if (message.size() <= path.size() + 2) violated("an IoError with no message", message);
    return false;
  } catch (const std::exception &e) {
    violated("an exception other than IoError", e.what());
  }
}

inline void check_shape(const io::MeshData &mesh, const char *what) {
  if (mesh.xyz.size() % 3 != 0) violated(what, "coordinates are not whole triples");
  if (mesh.triangles.size() % 3 != 0) violated(what, "indices are not whole triangles");
  const std::size_t vertices = mesh.xyz.size() / 3;
  for (std::uint32_t index : mesh.triangles)
    if (index >= vertices)
      violated(what, "index " + std::to_string(index) + " of " + std::to_string(vertices));
}

inline bool same_bits(const std::vector<double> &a, const std::vector<double> &b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// The mesh written as binary PLY and read back is the same mesh, bit for bit (NaN included).
inline void check_round_trip(const io::MeshData &mesh) {
  std::string bytes;
  io::detail::write_ply(bytes, mesh.xyz, &mesh.triangles, false);
  const std::string path = "roundtrip.ply";
  io::MeshData back;
  try {
    const io::detail::Source source{path, bytes, io::detail::check_content(path, bytes,
                                                                          io::Format::Ply)};
    io::detail::read_ply(source, back, true);
  } catch (const std::exception &e) {
    violated("a written PLY does not read back", e.what());
  }
  if (!same_bits(back.xyz, mesh.xyz) || back.triangles != mesh.triangles)
    violated("a written PLY reads back different");
}

// Reads data as a file of `format`, as points and (except XYZ) as a mesh.
inline void read_both_ways(io::Format format, const std::uint8_t *data, std::size_t size) {
  static const char *const extension[] = {"xyz", "ply", "off", "obj", "stl"};
  const std::string path = std::string("fuzz.") + extension[static_cast<int>(format)];
  const std::string_view bytes(reinterpret_cast<const char *>(data), size);
  namespace d = io::detail;

  io::MeshData points;
  const bool points_read = attempt(path, [&] {
    const d::Source source{path, bytes, d::check_content(path, bytes, format)};
    switch (format) {
      case io::Format::Xyz: d::read_xyz(source, points.xyz); break;
      case io::Format::Ply: d::read_ply(source, points, false); break;
      case io::Format::Off: d::read_off(source, points, false); break;
      case io::Format::Obj: d::read_obj(source, points, false); break;
      case io::Format::Stl: d::read_stl(source, points); break;
    }
  });
  if (points_read) check_shape(points, "points");
  if (format == io::Format::Xyz) return;

  io::MeshData mesh;
  const bool mesh_read = attempt(path, [&] {
    const d::Source source{path, bytes, d::check_content(path, bytes, format)};
    switch (format) {
      case io::Format::Ply: d::read_ply(source, mesh, true); break;
      case io::Format::Off: d::read_off(source, mesh, true); break;
      case io::Format::Obj: d::read_obj(source, mesh, true); break;
      default: d::read_stl(source, mesh); break;
    }
  });
  if (!mesh_read) return;
  check_shape(mesh, "mesh");
  // Reading points checks less than reading a mesh, never more, and finds the same vertices.
  if (!points_read) violated("a file reads as a mesh but not as points");
  if (!same_bits(points.xyz, mesh.xyz)) violated("points and mesh vertices differ");
  check_round_trip(mesh);
}

}  // namespace moa::fuzz
