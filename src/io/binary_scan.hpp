// Endian-aware loads and stores of plain numbers in byte buffers.
#pragma once

#include <algorithm>
#include <cstring>
#include <string>

namespace moa::io::detail {

constexpr bool host_is_little_endian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

template <class T>
T load(const unsigned char *bytes, bool big_endian) {
  unsigned char copy[sizeof(T)];
  std::memcpy(copy, bytes, sizeof(T));
  if (big_endian == host_is_little_endian) std::reverse(copy, copy + sizeof(T));
  T value;
  std::memcpy(&value, copy, sizeof(T));
  return value;
}

template <class T>
void append_little_endian(std::string &out, T value) {
  unsigned char copy[sizeof(T)];
  std::memcpy(copy, &value, sizeof(T));
  if (!host_is_little_endian) std::reverse(copy, copy + sizeof(T));
  out.append(reinterpret_cast<const char *>(copy), sizeof(T));
}

}  // namespace moa::io::detail
