// A set of indices (faces, points) that a search fills and then forgets: a bit per index,
// cleared through the list of those set, since a search touches tens of indices and a cloud
// holds millions (a stamp per index cost 4 bytes each).
#pragma once

#include <cstdint>
#include <vector>

namespace moa {

class IndexMarks {
 public:
  bool has(uint32_t i) const {
    return (i >> 6) < bits_.size() && ((bits_[i >> 6] >> (i & 63)) & 1u) != 0;
  }
  void set(uint32_t i) {
    if ((i >> 6) >= bits_.size()) bits_.resize((i >> 6) + 1 + bits_.size() / 2, 0);
    bits_[i >> 6] |= uint64_t(1) << (i & 63);
    set_.push_back(i);
  }
  void clear() {
    for (uint32_t i : set_) bits_[i >> 6] &= ~(uint64_t(1) << (i & 63));
    set_.clear();
  }
  void release() {
    std::vector<uint64_t>().swap(bits_);
    std::vector<uint32_t>().swap(set_);
  }
  std::size_t memory_bytes() const { return bits_.capacity() * 8 + set_.capacity() * 4; }

 private:
  std::vector<uint64_t> bits_;
  std::vector<uint32_t> set_;
};

}  // namespace moa
