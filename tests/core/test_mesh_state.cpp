// The mesh's per-vertex records (src/core/mesh_state.hpp), which start as untouched zero pages
// (src/core/zeroed_array.hpp): all zero bytes must read as an unused vertex, before any face
// reaches it and after its last face is removed.
#include <cstdint>
#include <utility>

#include "core/mesh_state.hpp"
#include "core/zeroed_array.hpp"

// cmocka last: its macros clash with names in the standard headers.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

namespace {

struct Record {
  uint32_t a, b;
  double c;
};

void zeroed_array_starts_zero_and_moves(void **) {
  moa::ZeroedArray<Record> records(1u << 20);  // 16 MB, pages untouched until written
  assert_int_equal(records.size(), 1u << 20);
  for (std::size_t i = 0; i < records.size(); i += 4093) {
    assert_int_equal(records[i].a, 0);
    assert_int_equal(records[i].b, 0);
    assert_true(records[i].c == 0.0);
  }
  records[12345] = {7, 8, 9.5};
  moa::ZeroedArray<Record> moved(std::move(records));
  assert_int_equal(records.size(), 0);
  assert_int_equal(moved.size(), 1u << 20);
  assert_int_equal(moved[12345].b, 8);
  moa::ZeroedArray<Record> empty;
  assert_int_equal(empty.size(), 0);
  empty = std::move(moved);
  assert_true(empty[12345].c == 9.5);
  assert_int_equal(empty[12346].a, 0);
}

// Vertex 0 and face 0 are where stale list ends would point: an unused vertex must show no
// faces, and edges at it none, although face 0 has vertex 0 as a corner.
void unused_vertices_have_no_faces(void **) {
  moa::MeshState mesh(6);
  uint32_t fs[2];
  assert_int_equal(mesh.add({0, 1, 2}), 0);
  assert_int_equal(mesh.edge_faces(3, 0, fs), 0);
  assert_int_equal(mesh.edge_faces(0, 3, fs), 0);
  assert_true(mesh.faces_at(3).empty());
  assert_false(mesh.is_used(3));
  assert_int_equal(mesh.fan_count(3), 0);
  assert_int_equal(mesh.edge_faces(0, 1, fs), 1);
  assert_int_equal(fs[0], 0);
  // Vertex 3 gains a face and loses it again: unused once more, its edges free.
  const uint32_t f = mesh.add({2, 1, 3});
  assert_int_equal(mesh.edge_faces(1, 3, fs), 1);
  assert_int_equal(fs[0], f);
  mesh.remove(f);
  assert_false(mesh.is_used(3));
  assert_true(mesh.faces_at(3).empty());
  assert_int_equal(mesh.edge_faces(1, 3, fs), 0);
  assert_int_equal(mesh.edge_faces(3, 1, fs), 0);
  assert_int_equal(mesh.edge_faces(1, 2, fs), 1);  // face 0 alone again
  assert_int_equal(fs[0], 0);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(zeroed_array_starts_zero_and_moves),
      cmocka_unit_test(unused_vertices_have_no_faces),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
