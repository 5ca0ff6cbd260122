// The body of a binary PLY file, little or big endian. Every element count is compared with
// the bytes left before anything is reserved, so a lying header costs no memory.
#include <algorithm>

#include "binary_scan.hpp"
#include "errors.hpp"
#include "ply_reader.hpp"

namespace moa::io::detail {
namespace {

double load_double(const unsigned char *p, PlyType type, bool big) {
  switch (type) {
    case PlyType::Int8: return load<int8_t>(p, big);
    case PlyType::UInt8: return load<uint8_t>(p, big);
    case PlyType::Int16: return load<int16_t>(p, big);
    case PlyType::UInt16: return load<uint16_t>(p, big);
    case PlyType::Int32: return load<int32_t>(p, big);
    case PlyType::UInt32: return load<uint32_t>(p, big);
    case PlyType::Float32: return load<float>(p, big);
    case PlyType::Float64: return load<double>(p, big);
  }
  return 0;
}

int64_t load_integer(const unsigned char *p, PlyType type, bool big) {
  switch (type) {
    case PlyType::Int8: return load<int8_t>(p, big);
    case PlyType::UInt8: return load<uint8_t>(p, big);
    case PlyType::Int16: return load<int16_t>(p, big);
    case PlyType::UInt16: return load<uint16_t>(p, big);
    case PlyType::Int32: return load<int32_t>(p, big);
    case PlyType::UInt32: return load<uint32_t>(p, big);
    default: return 0;  // the header parser admits only integer count and index types
  }
}

struct Body {
  const Source &source;
  const unsigned char *bytes;
  size_t size;
  size_t pos;
  bool big;

  size_t left() const { return size - pos; }
};

// Checks the count against the bytes left: exactly for fixed-size items, as a lower bound
// for items with lists.
void check_room(const Body &body, const PlyElement &element) {
  const size_t item = element.min_binary_size();
  if (element.count <= body.left() / item) return;
  const std::string promised = std::to_string(element.count) + " " + plural(element.name);
  if (!element.has_lists()) {
    const size_t fit = body.left() / item;
    fail_at_byte(body.source.path, body.pos + fit * item,
                 "file ends after " + std::to_string(fit) + " of " + promised);
  }
  fail_at_byte(body.source.path, body.pos,
               "the header promises " + promised + " of at least " +
                   counted(item, "byte", "bytes") + " each, but only " +
                   counted(body.left(), "byte is", "bytes are") + " left");
}

void read_element(Body &body, const PlyElement &element, const std::vector<PlyRole> &roles,
                  uint64_t vertex_count, MeshData &mesh) {
  const std::string &path = body.source.path;
  double xyz[3] = {0, 0, 0};
  const bool vertices = std::find(roles.begin(), roles.end(), PlyRole::X) != roles.end();
  for (uint64_t i = 0; i < element.count; ++i) {
    const size_t start = body.pos;
    const auto truncated = [&] {
      fail_at_byte(path, start,
                   "file ends after " + std::to_string(i) + " of " +
                       std::to_string(element.count) + " " + plural(element.name));
    };
    for (size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty &property = element.properties[p];
      const size_t value_size = ply_type_size(property.type);
      if (!property.is_list) {
        if (body.left() < value_size) truncated();
        if (roles[p] != PlyRole::Skip)
          xyz[static_cast<int>(roles[p])] = load_double(body.bytes + body.pos, property.type,
                                                        body.big);
        body.pos += value_size;
        continue;
      }
      const size_t count_size = ply_type_size(property.count_type);
      if (body.left() < count_size) truncated();
      const int64_t length = load_integer(body.bytes + body.pos, property.count_type, body.big);
      if (length < 0)
        fail_at_byte(path, body.pos, "negative list length " + std::to_string(length));
      body.pos += count_size;
      if (body.left() / value_size < static_cast<uint64_t>(length)) truncated();
      if (roles[p] == PlyRole::FaceIndices) {
        if (length < 3)
          fail_at_byte(path, start, "a face needs at least 3 vertices, this one has " +
                                        std::to_string(length));
        uint32_t first = 0, previous = 0;
        for (int64_t k = 0; k < length; ++k, body.pos += value_size) {
          const int64_t index = load_integer(body.bytes + body.pos, property.type, body.big);
          if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
            fail_at_byte(path, body.pos,
                         "vertex index " + std::to_string(index) + " is out of range (" +
                             std::to_string(vertex_count) + " vertices)");
          const auto current = static_cast<uint32_t>(index);
          if (k == 0) first = current;
          if (k >= 2) mesh.triangles.insert(mesh.triangles.end(), {first, previous, current});
          previous = current;
        }
      } else {
        body.pos += static_cast<size_t>(length) * value_size;
      }
    }
    if (vertices) mesh.xyz.insert(mesh.xyz.end(), xyz, xyz + 3);
  }
}

}  // namespace

void read_ply_binary(const Source &source, const PlyHeader &header, const PlyPlan &plan,
                     MeshData &mesh) {
  Body body{source, reinterpret_cast<const unsigned char *>(source.data.data()),
            source.data.size(), header.body_offset,
            header.encoding == PlyEncoding::BinaryBigEndian};
  const uint64_t vertex_count = header.elements[plan.vertex_element].count;
  for (size_t e = 0; e <= plan.last_element; ++e) {
    const PlyElement &element = header.elements[e];
    const size_t item = element.min_binary_size();
    if (item == 0) continue;  // no properties: nothing stored
    check_room(body, element);
    if (e == plan.vertex_element) {
      mesh.xyz.reserve(mesh.xyz.size() + 3 * element.count);
    } else if (static_cast<long>(e) == plan.face_element) {
      // Sized for triangles, and never beyond what the bytes left can hold.
      mesh.triangles.reserve(mesh.triangles.size() +
                             3 * std::min<uint64_t>(element.count, body.left() / (item + 3)));
    } else if (!element.has_lists()) {
      body.pos += element.count * item;  // skipped whole
      continue;
    }
    read_element(body, element, plan.roles[e], vertex_count, mesh);
  }
}

}  // namespace moa::io::detail
