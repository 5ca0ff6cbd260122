// A fixed-size array of plain records that starts as all zero bytes, taken from the system as
// untouched pages: a page costs memory only once something is written to it. Each part of
// Algorithm 1's parallel pass keeps per-vertex records indexed like the whole cloud, and writes
// about a tenth of their pages (its own points, spread through the Morton order); in a
// std::vector, which writes every element, each part running at once paid for all of them.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <new>
#include <type_traits>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#define MOA_ZEROED_BY_MMAP 1
#endif

namespace moa {

template <class T>
class ZeroedArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "all zero bytes must be a valid T, and nothing to destroy");

 public:
  ZeroedArray() = default;
  explicit ZeroedArray(std::size_t count) : size_(count) {
    if (count == 0) return;
    if (count > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_alloc();
#ifdef MOA_ZEROED_BY_MMAP
    void *p = ::mmap(nullptr, count * sizeof(T), PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
#else
    void *p = std::calloc(count, sizeof(T));
    if (!p) throw std::bad_alloc();
#endif
    data_ = static_cast<T *>(p);
  }
  ~ZeroedArray() { release(); }
  ZeroedArray(const ZeroedArray &) = delete;
  ZeroedArray &operator=(const ZeroedArray &) = delete;
  ZeroedArray(ZeroedArray &&other) noexcept : data_(other.data_), size_(other.size_) {
    other.data_ = nullptr;
    other.size_ = 0;
  }
  ZeroedArray &operator=(ZeroedArray &&other) noexcept {
    if (this != &other) {
      release();
      data_ = other.data_;
      size_ = other.size_;
      other.data_ = nullptr;
      other.size_ = 0;
    }
    return *this;
  }

  T &operator[](std::size_t i) { return data_[i]; }
  const T &operator[](std::size_t i) const { return data_[i]; }
  std::size_t size() const { return size_; }

 private:
  void release() {
    if (!data_) return;
#ifdef MOA_ZEROED_BY_MMAP
    ::munmap(data_, size_ * sizeof(T));
#else
    std::free(data_);
#endif
    data_ = nullptr;
  }

  T *data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace moa
