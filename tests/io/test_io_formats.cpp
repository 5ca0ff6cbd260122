// Reading the variants each format comes in: hand-written fixtures with comments, extra
// columns and properties, other elements, polygons, both endiannesses, CRLF line ends.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "io_test_support.hpp"

using moa::io::MeshData;

namespace {

void assert_doubles(const std::vector<double> &actual, std::vector<double> expected) {
  assert_int_equal(actual.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i)
    if (!io_test::same_bits(actual[i], expected[i]) &&
        !(std::isnan(actual[i]) && std::isnan(expected[i])))
      fail_msg("value %zu: expected %.17g, read %.17g", i, expected[i], actual[i]);
}

void assert_indices(const std::vector<uint32_t> &actual, std::vector<uint32_t> expected) {
  assert_int_equal(actual.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) assert_int_equal(actual[i], expected[i]);
}

// Appends a number in the given byte order.
template <class T>
void put(std::string &out, T value, bool big_endian) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const bool host_little = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
  if (big_endian == host_little) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

void xyz_variants(void **) {
  const std::string text =
      "\xEF\xBB\xBF# scanner output\r\n"
      "\r\n"
      "1 2 3 0 0 1 red\r\n"        // extra columns, even non-numeric ones, are ignored
      "\t+4.5\t-5e-1  6E2 # a comment after the data\n"
      "   \n"
      "nan inf -inf\n"
      "1e400 -1e400 1e-400\n"  // out of range: overflow to infinity, underflow to zero
      "7 8 9";  // no final newline
  const std::string path = io_test::write_fixture("variants.xyz", text);
  assert_doubles(READ_POINTS(path), {1, 2, 3, 4.5, -0.5, 600, NAN, INFINITY, -INFINITY, INFINITY,
                                     -INFINITY, 0, 7, 8, 9});
}

void xyz_pts_count_line(void **) {
  const std::string path = io_test::write_fixture("scan.pts", "2\n1 2 3 40 255 0 0\n4 5 6 41 0 255 0\n");
  assert_doubles(READ_POINTS(path), {1, 2, 3, 4, 5, 6});
  // Several scans in one file, each after its own count.
  const std::string scans =
      io_test::write_fixture("scans.pts", "2\n1 2 3 40\n4 5 6 41\n1\n7 8 9 42\n");
  assert_doubles(READ_POINTS(scans), {1, 2, 3, 4, 5, 6, 7, 8, 9});
}

// Spreadsheet and CloudCompare exports: commas or semicolons between the columns, with or
// without spaces around them; the first line of numbers decides which.
void xyz_comma_and_semicolon_columns(void **) {
  const std::string csv = io_test::write_fixture(
      "export.csv", "1.5,2,3,255,0,0\r\n 4 , -5e-1 ,6E2,,\n# a comment\n7,8,9\n");
  assert_doubles(READ_POINTS(csv), {1.5, 2, 3, 4, -0.5, 600, 7, 8, 9});
  const std::string semicolons = io_test::write_fixture("export.txt", "1;2;3\n4; 5; 6; 0.25\n");
  assert_doubles(READ_POINTS(semicolons), {1, 2, 3, 4, 5, 6});
  // Tabs stay whitespace: no comma or semicolon on the first line of numbers.
  const std::string tabs = io_test::write_fixture("tabs.xyz", "1\t2\t3\n4\t5\t6\n");
  assert_doubles(READ_POINTS(tabs), {1, 2, 3, 4, 5, 6});
}

// A first line of column names is skipped; where it names x, y and z (any case, quoted or
// not, CloudCompare's "//" before the first), those columns are read.
void xyz_header_names_columns(void **) {
  struct Case {
    const char *name, *text;
    std::vector<double> expected;
  };
  const Case cases[] = {
      {"cloudcompare.txt", "//X,Y,Z,R,G,B\n1,2,3,255,0,0\n4,5,6,0,0,255\n", {1, 2, 3, 4, 5, 6}},
      {"normals_first.xyz", "nx ny nz x y z\n0 0 1 4 5 6\n", {4, 5, 6}},
      {"quoted.csv", "\"Intensity\";\"Z\";\"Y\";\"X\"\n9;3;2;1\n", {1, 2, 3}},
      {"unnamed.xyz", "# made by hand\neast north up\n1 2 3\n", {1, 2, 3}},
      {"header_spaces_data_commas.csv", "x y z\n1,2,3\n", {1, 2, 3}},
  };
  for (const Case &c : cases)
    assert_doubles(READ_POINTS(io_test::write_fixture(c.name, c.text)), c.expected);
}

void ply_ascii_with_other_elements(void **) {
  const std::string text =
      "ply\r\n"
      "format ascii 1.0\r\n"
      "comment an element before the vertices, with a list\r\n"
      "obj_info made by hand\r\n"
      "element material 2\r\n"
      "property list uchar float coefficients\r\n"
      "property int id\r\n"
      "element vertex 5\r\n"
      "property short x\r\n"  // any numeric type will do
      "property float nx\r\n"
      "property list uint8 int32 neighbours\r\n"
      "property double y\r\n"
      "property uchar red\r\n"
      "property float64 z\r\n"
      "element face 2\r\n"
      "property uchar flags\r\n"
      "property list uchar uint vertex_index\r\n"
      "element edge 1\r\n"
      "property int vertex1\r\n"
      "property int vertex2\r\n"
      "end_header\r\n"
      "3 0.5 1 2.5 7\r\n"
      "0 8\r\n"
      "0 0 2 1 2 0.25 255 -1e-3\r\n"
      "10 0 0 0.5 0 0.75\r\n"
      "\r\n"  // blank lines between items are tolerated
      "20 0 1 4 1 0 1\r\n"
      "30 0 0 1.5 0 2\r\n"
      "-40 0 0 -2.5 0 3\r\n"
      "0 4 0 1 2 3\r\n"  // a quad: two triangles
      "1 3 2 3 4\r\n"
      "0 1\r\n";
  const std::string path = io_test::write_fixture("ascii.ply", text);
  const MeshData mesh = READ_MESH(path);
  assert_doubles(mesh.xyz, {0, 0.25, -1e-3, 10, 0.5, 0.75, 20, 1, 1, 30, 1.5, 2, -40, -2.5, 3});
  assert_indices(mesh.triangles, {0, 1, 2, 0, 2, 3, 2, 3, 4});
  assert_doubles(READ_POINTS(path), mesh.xyz);
}

// The same layout in either byte order: an element before the vertices, vertex lists,
// properties of every size, a quad face.
std::string binary_ply(bool big) {
  std::string out = std::string("ply\nformat ") +
                    (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\n"
                    "element camera 1\n"
                    "property list ushort int16 params\n"
                    "property double focal\n"
                    "element vertex 4\n"
                    "property float x\n"
                    "property uchar red\n"
                    "property double y\n"
                    "property list uchar float extra\n"
                    "property int z\n"
                    "element face 2\n"
                    "property int flags\n"
                    "property list uchar uint vertex_indices\n"
                    "property list int ushort other\n"
                    "end_header\n";
  put<uint16_t>(out, 2, big);
  put<int16_t>(out, -1, big);
  put<int16_t>(out, 5, big);
  put<double>(out, 35.0, big);
  const float x[4] = {0.5f, -1.25f, 3e-5f, 1e30f};
  const double y[4] = {0.1, -0.2, 1e-300, 7};
  const int32_t z[4] = {-3, 0, 2000000000, 4};
  for (int v = 0; v < 4; ++v) {
    put<float>(out, x[v], big);
    put<uint8_t>(out, 200, big);
    put<double>(out, y[v], big);
    put<uint8_t>(out, static_cast<uint8_t>(v), big);  // v extra floats
    for (int k = 0; k < v; ++k) put<float>(out, 1.5f, big);
    put<int32_t>(out, z[v], big);
  }
  put<int32_t>(out, 9, big);
  put<uint8_t>(out, 4, big);
  for (uint32_t i : {0u, 1u, 2u, 3u}) put<uint32_t>(out, i, big);
  put<int32_t>(out, 1, big);
  put<uint16_t>(out, 7, big);
  put<int32_t>(out, 9, big);
  put<uint8_t>(out, 3, big);
  for (uint32_t i : {3u, 2u, 1u}) put<uint32_t>(out, i, big);
  put<int32_t>(out, 0, big);
  return out;
}

void ply_binary_both_endians(void **) {
  for (bool big : {false, true}) {
    const std::string path = io_test::write_fixture(big ? "big.ply" : "little.ply", binary_ply(big));
    const MeshData mesh = READ_MESH(path);
    assert_doubles(mesh.xyz, {0.5, 0.1, -3, -1.25, -0.2, 0, double(3e-5f), 1e-300, 2000000000,
                              double(1e30f), 7, 4});
    assert_indices(mesh.triangles, {0, 1, 2, 0, 2, 3, 3, 2, 1});
    assert_doubles(READ_POINTS(path), mesh.xyz);
  }
}

void off_variants(void **) {
  struct Case {
    const char *name, *text;
  } cases[] = {
      {"plain.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"},
      {"same_line.off", "OFF 4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"},
      {"comments.off",
       "# made by hand\nOFF # keyword\n\n# counts next, no edge count\n4 2\n0 0 0 # origin\n"
       "1 0 0\n\n1 1 0\n0 1 0\n# faces\n3 0 1 2\n3 0 2 3\n"},
      {"crlf.off", "OFF\r\n4 2 0\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n3 0 1 2\r\n3 0 2 3"},
      {"headerless.off", "4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"},
      {"quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 255 0 0\n"},
      {"colour.off",
       "COFF\n4 2 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n1 1 0 0 0 255 255\n"
       "0 1 0 9 9 9 255\n3 0 1 2 0.5 0.5 0.5\n3 0 2 3\n"},
      {"normals.off",
       "NOFF\n4 2 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n3 0 2 3\n"},
      {"dimension.off", "nOFF\n3\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"},
      {"textured.off",
       "STCNOFF\n4 2 0\n0 0 0 0 0 1 1 0 0 1 0 0\n1 0 0 0 0 1 1 0 0 1 1 0\n"
       "1 1 0 0 0 1 1 0 0 1 1 1\n0 1 0 0 0 1 1 0 0 1 0 1\n3 0 1 2\n3 0 2 3\n"},
  };
  for (const Case &c : cases) {
    const std::string path = io_test::write_fixture(c.name, c.text);
    const MeshData mesh = READ_MESH(path);
    assert_doubles(mesh.xyz, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    assert_indices(mesh.triangles, {0, 1, 2, 0, 2, 3});
    assert_doubles(READ_POINTS(path), mesh.xyz);
  }
}

void obj_variants(void **) {
  const std::string text =
      "# exported\nmtllib scene.mtl\no square\n"
      "v 0 0 0\nv 1 0 0 1.0\nv 1 1 0 0.5 0.5 0.5\n"
      "vt 0 0\nvt 1 0\nvn 0 0 1\ng group\nusemtl red\ns off\n"
      "f 1/1/1 2/2/1 3/1/1\n"
      "v 0 1 0\n"
      "f -4//1 -2//1 -1//1\n"  // relative: vertices 1 3 4
      "f 1/1 2/2 3/1 4/2\n"    // a quad
      "l 1 2\n";
  const std::string path = io_test::write_fixture("variants.obj", text);
  const MeshData mesh = READ_MESH(path);
  assert_doubles(mesh.xyz, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  assert_indices(mesh.triangles, {0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3});
  assert_doubles(READ_POINTS(path), mesh.xyz);
}

void stl_ascii(void **) {
  const std::string text =
      "solid square made by hand\n"
      "  facet normal 0 0 1\n    outer loop\n"
      "      vertex 0 0 0\n      vertex 1 0 0\n      vertex 1 1 0\n"
      "    endloop\n  endfacet\n"
      "  facet normal 0 0 1\n    outer loop\n"
      "      vertex -0 0 0\n      vertex 1 1 0\n      vertex 0 1 -0\n"  // -0 is 0
      "    endloop\n  endfacet\n"
      "endsolid square made by hand\n";
  const std::string path = io_test::write_fixture("square.stl", text);
  const MeshData mesh = READ_MESH(path);
  assert_doubles(mesh.xyz, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  assert_indices(mesh.triangles, {0, 1, 2, 0, 2, 3});
  assert_doubles(READ_POINTS(path), mesh.xyz);
}

// Some writers start a binary STL's header with "solid"; the size tells it apart.
void stl_binary_starting_with_solid(void **) {
  std::string out = "solid but binary";
  out.resize(80, ' ');
  put<uint32_t>(out, 1, false);
  for (float v : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put<float>(out, v, false);
  put<uint16_t>(out, 0, false);
  const std::string path = io_test::write_fixture("solid_binary.stl", out);
  const MeshData mesh = READ_MESH(path);
  assert_doubles(mesh.xyz, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  assert_indices(mesh.triangles, {0, 1, 2});
}

// A PLY with vertices only is a mesh without triangles, not an error.
void ply_without_faces(void **) {
  const std::string path =
      io_test::write_fixture("cloud.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                          "property float x\nproperty float y\nproperty float z\n"
                                          "end_header\n1 2 3\n");
  const MeshData mesh = READ_MESH(path);
  assert_doubles(mesh.xyz, {1, 2, 3});
  assert_int_equal(mesh.triangles.size(), 0);
}

// Coordinates named in upper case; lower case wins where a file has both.
void ply_upper_case_coordinates(void **) {
  const std::string upper = io_test::write_fixture(
      "upper.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty double X\n"
                   "property double Y\nproperty double Z\nend_header\n1 2 3\n");
  assert_doubles(READ_POINTS(upper), {1, 2, 3});
  const std::string both = io_test::write_fixture(
      "both.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float X\nproperty float x\n"
                  "property float y\nproperty float z\nend_header\n9 1 2 3\n");
  assert_doubles(READ_POINTS(both), {1, 2, 3});
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(xyz_variants),
      cmocka_unit_test(xyz_pts_count_line),
      cmocka_unit_test(xyz_comma_and_semicolon_columns),
      cmocka_unit_test(xyz_header_names_columns),
      cmocka_unit_test(ply_ascii_with_other_elements),
      cmocka_unit_test(ply_binary_both_endians),
      cmocka_unit_test(off_variants),
      cmocka_unit_test(obj_variants),
      cmocka_unit_test(stl_ascii),
      cmocka_unit_test(stl_binary_starting_with_solid),
      cmocka_unit_test(ply_without_faces),
      cmocka_unit_test(ply_upper_case_coordinates),
  };
  return cmocka_run_group_tests(tests, io_test::setup_temp_dir, io_test::remove_temp_dir);
}
