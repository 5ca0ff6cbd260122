// STL lists each triangle's corners by value; equal positions become one indexed vertex.
#pragma once

#include <cstdint>
#include <cstring>
#include <unordered_map>

#include "io/io.hpp"

namespace moa::io::detail {

class VertexMerger {
 public:
  VertexMerger(MeshData &mesh, size_t expected_corners) : mesh_(mesh) {
    index_.reserve(expected_corners / 4);  // a closed mesh has about half as many vertices
  }

  // The index of the vertex at (x, y, z), added when new. -0 and +0 are the same position.
  uint32_t add(double x, double y, double z) {
    const Key key{bits(x), bits(y), bits(z)};
    const auto next = static_cast<uint32_t>(mesh_.xyz.size() / 3);
    const auto [it, inserted] = index_.try_emplace(key, next);
    if (inserted) mesh_.xyz.insert(mesh_.xyz.end(), {x + 0.0, y + 0.0, z + 0.0});
    return it->second;
  }

 private:
  struct Key {
    uint64_t x, y, z;
    bool operator==(const Key &o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct Hash {
    size_t operator()(const Key &k) const {
      uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
      h = (h ^ (h >> 29) ^ k.y) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 32) ^ k.z) * 0x94D049BB133111EBull;
      return static_cast<size_t>(h ^ (h >> 31));
    }
  };
  static uint64_t bits(double v) {
    v += 0.0;  // turns -0 into +0
    uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }

  MeshData &mesh_;
  std::unordered_map<Key, uint32_t, Hash> index_;
};

}  // namespace moa::io::detail
