// Every way a file can be wrong: each must be an IoError naming the file and, where it
// applies, the line or byte offset and what is wrong there. Never a crash or bad_alloc.
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>

#include "io_test_support.hpp"

using moa::io::read_mesh;
using moa::io::read_points;

namespace {

std::string fixture(const std::string &name, const std::string &text) {
  return io_test::write_fixture(name, text);
}

template <class T>
void put(std::string &out, T value) {  // little endian on the hosts we build for
  out.append(reinterpret_cast<const char *>(&value), sizeof(T));
}

const char *const xyz_header = "ply\nformat binary_little_endian 1.0\nelement vertex ";

void malformed_numbers(void **) {
  const std::string xyz = fixture("bad.xyz", "1 2 3\n# fine\n4 5 abc\n");
  EXPECT_IO_ERROR(read_points(xyz), "bad.xyz: line 3: 'abc' is not a number");
  for (const char *bad : {"1.2.3", "1e", "0x10", "--1", "1e5x", "."}) {
    const std::string path = fixture("bad_number.xyz", std::string("1 2 ") + bad + "\n");
    EXPECT_IO_ERROR(read_points(path), "bad_number.xyz: line 1:", std::string("'") + bad + "'");
  }
  // A comma makes the columns comma-separated: "1,5" is not split into two coordinates.
  EXPECT_IO_ERROR(read_points(fixture("bad_number.xyz", "1 2 1,5\n")), "line 1:", "'1 2 1'",
                  "decimals must be written with '.'");
  const std::string few = fixture("few.xyz", "1 2 3\n4 5\n");
  EXPECT_IO_ERROR(read_points(few), "few.xyz: line 2:", "at least 3 numbers", "found 2");
  // A lone number is a count line only in a file that starts with one (.pts).
  EXPECT_IO_ERROR(read_points(fixture("lone.xyz", "1 2 3\n4\n")), "lone.xyz: line 2:",
                  "at least 3 numbers", "found 1");
  const std::string off = fixture("bad.off", "OFF\n3 1 0\n0 0 0\n1 O 0\n0 1 0\n3 0 1 2\n");
  EXPECT_IO_ERROR(read_points(off), "bad.off: line 4: 'O' is not a number");
  const std::string obj = fixture("bad.obj", "v 0 0 0\nv 1 0 zero\n");
  EXPECT_IO_ERROR(read_points(obj), "bad.obj: line 2: 'zero' is not a number");
  const std::string ply = fixture("bad.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                                  "property float y\nproperty float z\nproperty uchar red\n"
                                  "end_header\n1 2 3 4\n1 2 3 red\n");
  EXPECT_IO_ERROR(read_points(ply), "bad.ply: line 10: 'red' is not a number", "'red'");
  const std::string stl = fixture("bad.stl", "solid s\nfacet normal 0 0 1\nouter loop\n"
                                             "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 nan0\n");
  EXPECT_IO_ERROR(read_mesh(stl), "bad.stl: line 6: 'nan0' is not a number");
}

// Delimited columns fail as clearly as whitespace ones: decimal commas are never split into
// two coordinates, an empty field never shifts the columns after it.
void delimited_column_errors(void **) {
  EXPECT_IO_ERROR(read_points(fixture("decimal_commas.csv", "1,5;2,25;3,0\n")),
                  "decimal_commas.csv: line 1: '1,5' is not a number", "separated by ';'",
                  "decimals must be written with '.'");
  EXPECT_IO_ERROR(read_points(fixture("decimal_spaces.xyz", "1,5 2,25 3,0\n")),
                  "decimal_spaces.xyz: line 1: '5 2' is not a number", "separated by ','");
  EXPECT_IO_ERROR(read_points(fixture("empty_field.csv", "1,2,3\n4,,6\n")),
                  "empty_field.csv: line 2: column 2 is empty");
  EXPECT_IO_ERROR(read_points(fixture("short_row.csv", "1,2,3\n4,5\n")),
                  "short_row.csv: line 2:", "at least 3 numbers", "found 2");
  EXPECT_IO_ERROR(read_points(fixture("named_short.csv", "id,r,x,y,z\n1,0,2,3,4\n2,0,5,6\n")),
                  "named_short.csv: line 3:", "at least 5 columns", "columns 3, 4 and 5",
                  "found 4");
  // Only the first line may be a header.
  EXPECT_IO_ERROR(read_points(fixture("two_headers.xyz", "x y z\nu v w\n1 2 3\n")),
                  "two_headers.xyz: line 2: 'u' is not a number");
  EXPECT_IO_ERROR(read_points(fixture("header_only.csv", "x,y,z\n")), "header_only.csv:",
                  "holds no points");
}

void ply_item_shape(void **) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                             "property float y\nproperty float z\nelement face 2\n"
                             "property list uchar int vertex_indices\nend_header\n";
  EXPECT_IO_ERROR(read_points(fixture("short.ply", header + "1 2 3\n1 2\n3 0 1 1\n")),
                  "short.ply: line 11:", "before property 'z'");
  EXPECT_IO_ERROR(read_points(fixture("long.ply", header + "1 2 3\n1 2 3 4\n3 0 1 1\n")),
                  "long.ply: line 11:", "unexpected '4'");
  EXPECT_IO_ERROR(read_mesh(fixture("range.ply", header + "1 2 3\n1 2 3\n3 0 1 2\n")),
                  "range.ply: line 12:", "vertex index 2 is out of range (2 vertices)");
  EXPECT_IO_ERROR(read_mesh(fixture("negative.ply", header + "1 2 3\n1 2 3\n3 0 1 -1\n")),
                  "negative.ply: line 12:", "vertex index -1");
  EXPECT_IO_ERROR(read_mesh(fixture("two.ply", header + "1 2 3\n1 2 3\n2 0 1\n")),
                  "two.ply: line 12:", "at least 3 vertices");
  // Small enough a shortfall to pass the header check: the reader finds where it ends.
  EXPECT_IO_ERROR(read_mesh(fixture("cut.ply", header + "1 2 3\n1 2 3\n3 0 1 1\n")),
                  "cut.ply: line 12:", "file ends after 1 of 2 faces");
}

void ply_header_errors(void **) {
  const std::string v = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n";
  struct Case {
    const char *text, *message;
  } cases[] = {
      {"ply\nformat ascii 1.0\nelement vertex 1\n", "no end_header"},
      {"ply\nformat utf8 1.0\nend_header\n", "line 2: unknown PLY format 'utf8'"},
      {"ply\nformat ascii 1.0\nproperty float x\nend_header\n", "line 3: a property before"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\nend_header\n",
       "line 4: unknown property type 'half'"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n",
       "line 4: 'float' is not an integer type"},
      {"ply\nformat ascii 1.0\nelement vertex many\nend_header\n",
       "line 3: 'many' is not a valid element count"},
      {"ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\nend_header\n",
       "line 3: '99999999999999999999999' is not a valid element count"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "end_header\n1 2\n",
       "line 3: the vertex element has no 'z' property"},
      {"ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\n"
       "end_header\n",
       "no vertex element"},
      {"ply\nformat ascii 1.0\nbogus line\nend_header\n", "line 3: unknown PLY header keyword"},
      {"ply\nelement vertex 0\nend_header\n", "no format line"},
  };
  for (const Case &c : cases)
    EXPECT_IO_ERROR(read_points(fixture("header.ply", c.text)), "header.ply: ", c.message);
  const std::string no_indices = fixture(
      "faces.ply", "ply\nformat ascii 1.0\n" + v + "element face 1\nproperty list uchar int "
                   "corners\nend_header\n0 0 0\n3 0 0 0\n");
  EXPECT_IO_ERROR(read_mesh(no_indices), "faces.ply: line 7: the face element has no vertex_indices");
}

// A binary PLY cut short: the offset is where the first incomplete item starts.
void truncated_binary_ply(void **) {
  std::string header = std::string(xyz_header) +
                       "100\nproperty double x\nproperty double y\nproperty double z\n"
                       "element face 5\nproperty list uchar int vertex_indices\nend_header\n";
  std::string body;
  for (int i = 0; i < 300; ++i) put<double>(body, i);
  const std::string cut = header + body.substr(0, 12 * 24 + 10);  // 12 vertices and a bit
  const std::string at = "byte " + std::to_string(header.size() + 12 * 24) + ": ";
  EXPECT_IO_ERROR(read_points(fixture("cut.ply", cut)), "cut.ply: " + at,
                  "file ends after 12 of 100 vertices");

  // Faces have lists: cut inside the third face.
  std::string faces;
  for (int f = 0; f < 5; ++f) {
    put<uint8_t>(faces, 3);
    for (int k = 0; k < 3; ++k) put<int32_t>(faces, k);
  }
  const std::string whole = header + body + faces;
  assert_int_equal(READ_MESH(fixture("whole.ply", whole)).triangles.size(), 15);
  const size_t third = header.size() + body.size() + 2 * 13;
  EXPECT_IO_ERROR(read_mesh(fixture("cut_faces.ply", whole.substr(0, third + 7))),
                  "cut_faces.ply: byte " + std::to_string(third) + ": ",
                  "file ends after 2 of 5 faces");
  // Indices are checked where they are.
  std::string bad = whole;
  bad[third + 1 + 4] = 100;  // the low byte of the third face's second index
  EXPECT_IO_ERROR(read_mesh(fixture("bad_index.ply", bad)),
                  "bad_index.ply: byte " + std::to_string(third + 5) + ": ",
                  "vertex index 100 is out of range (100 vertices)");
}

// Headers that promise far more than the file holds fail before any allocation.
void lying_headers(void **) {
  const std::string xyz_props = "property float x\nproperty float y\nproperty float z\n";
  const std::string binary = std::string(xyz_header) + "1000000000000\n" + xyz_props +
                             "end_header\n" + std::string(40, '\0');
  EXPECT_IO_ERROR(read_points(fixture("huge.ply", binary)), "huge.ply: byte ",
                  "file ends after 3 of 1000000000000 vertices");
  const std::string biggest = std::string(xyz_header) + "18446744073709551615\n" + xyz_props +
                              "end_header\n" + std::string(40, '\0');
  EXPECT_IO_ERROR(read_points(fixture("biggest.ply", biggest)), "biggest.ply: byte ",
                  "of 18446744073709551615 vertices");
  const std::string faces = std::string(xyz_header) + "1\n" + xyz_props +
                            "element face 1000000000000\nproperty list uchar int vertex_indices\n"
                            "end_header\n" + std::string(12 + 40, '\0');
  EXPECT_IO_ERROR(read_mesh(fixture("huge_faces.ply", faces)), "huge_faces.ply: byte ",
                  "promises 1000000000000 faces");
  const std::string ascii = "ply\nformat ascii 1.0\nelement vertex 1000000000000\n" + xyz_props +
                            "end_header\n1 2 3\n";
  EXPECT_IO_ERROR(read_points(fixture("huge_ascii.ply", ascii)), "huge_ascii.ply: line 3: ",
                  "promises 1000000000000 vertices");
  EXPECT_IO_ERROR(read_mesh(fixture("huge.off", "OFF\n1000000000000 1 0\n0 0 0\n3 0 0 0\n")),
                  "huge.off: line 2: ", "promises 1000000000000 vertices");
  EXPECT_IO_ERROR(read_mesh(fixture("huge_faces.off", "OFF\n3 1000000000000 0\n0 0 0\n")),
                  "huge_faces.off: line 2: ", "1000000000000 faces");
  std::string stl(80, ' ');
  put<uint32_t>(stl, 1000000000);
  stl += std::string(60, '\0');
  EXPECT_IO_ERROR(read_mesh(fixture("huge.stl", stl)), "huge.stl: byte 134: ",
                  "file ends after 1 of 1000000000 triangles");
}

void text_truncation_and_indices(void **) {
  const std::string two = "0.000000 0.000000 0.000000\n1.000000 0.000000 0.000000\n";
  EXPECT_IO_ERROR(read_points(fixture("cut.off", "OFF\n4 1 0\n" + two)),
                  "cut.off: line 4: file ends after 2 of 4 vertices");
  EXPECT_IO_ERROR(read_mesh(fixture("cut_faces.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")),
                  "cut_faces.off: line 6: file ends after 1 of 2 faces");
  const std::string tri = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_IO_ERROR(read_mesh(fixture("range.off", tri + "3 0 1 3\n")),
                  "range.off: line 6: vertex index 3 is out of range (3 vertices)");
  EXPECT_IO_ERROR(read_mesh(fixture("two.off", tri + "2 0 1\n")), "two.off: line 6:",
                  "at least 3 vertices");
  EXPECT_IO_ERROR(read_mesh(fixture("few.off", tri + "3 0 1\n")), "few.off: line 6:",
                  "lists 2 of its 3 vertices");
  EXPECT_IO_ERROR(read_mesh(fixture("neg.off", tri + "3 0 1 -2\n")), "neg.off: line 6:",
                  "'-2' is not a vertex index");
  EXPECT_IO_ERROR(read_mesh(fixture("counts.off", "OFF\n3 x 0\n")),
                  "counts.off: line 2: 'x' is not a valid face count");
  EXPECT_IO_ERROR(read_mesh(fixture("no_counts.off", "OFF\n# nothing else\n")), "no_counts.off",
                  "before the vertex count");
  EXPECT_IO_ERROR(read_mesh(fixture("four.off", "4OFF\n1 0 0\n0 0 0 1\n")), "four.off: line 1:",
                  "not supported");
  EXPECT_IO_ERROR(read_mesh(fixture("binary.off", "OFF BINARY\n")), "binary.off: line 1:",
                  "binary OFF");
  EXPECT_IO_ERROR(read_mesh(fixture("word.off", "MESH\n3 1 0\n")), "word.off: line 1:",
                  "expected the OFF keyword", "'MESH'");

  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_IO_ERROR(read_mesh(fixture("zero.obj", v + "f 0 1 2\n")), "zero.obj: line 4:",
                  "vertex index 0");
  EXPECT_IO_ERROR(read_mesh(fixture("range.obj", v + "f 1 2 3\nf 1 2 4\nf 1 2 3\n")),
                  "range.obj: line 5: vertex index 4 is out of range (3 vertices)");
  EXPECT_IO_ERROR(read_mesh(fixture("relative.obj", v + "f -1 -2 -4\n")), "relative.obj: line 4:",
                  "relative vertex index -4");
  EXPECT_IO_ERROR(read_mesh(fixture("corner.obj", v + "f 1 2 x/1\n")), "corner.obj: line 4:",
                  "'x/1' is not a face corner");
  EXPECT_IO_ERROR(read_mesh(fixture("short.obj", "v 1 2\n")), "short.obj: line 1:", "found 2");

  const std::string facet = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n";
  EXPECT_IO_ERROR(read_mesh(fixture("open.stl", facet + "vertex 1 0 0\n")), "open.stl: line 5:",
                  "file ends inside the facet begun at line 3");
  EXPECT_IO_ERROR(read_mesh(fixture("two.stl", facet + "vertex 1 0 0\nendloop\n")),
                  "two.stl: line 6:", "at least 3 vertices");
  EXPECT_IO_ERROR(read_mesh(fixture("stray.stl", "solid s\nvertex 0 0 0\n")), "stray.stl: line 2:",
                  "'vertex' outside");
  EXPECT_IO_ERROR(read_mesh(fixture("word.stl", facet + "vertice 1 0 0\n")), "word.stl: line 5:",
                  "unexpected 'vertice'");
  EXPECT_IO_ERROR(read_mesh(fixture("tiny.stl", std::string(50, '\x01'))), "tiny.stl: byte 50:",
                  "84-byte header");
}

void wrong_format_behind_extension(void **) {
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_IO_ERROR(read_points(fixture("off.ply", off)), "off.ply:", "extension says PLY",
                  "an OFF file");
  std::string binary_ply = std::string(xyz_header) +
                           "1\nproperty double x\nproperty double y\nproperty double z\n"
                           "end_header\n";
  for (int i = 0; i < 3; ++i) put<double>(binary_ply, 0.5);
  EXPECT_IO_ERROR(read_points(fixture("ply.xyz", binary_ply)), "ply.xyz:",
                  "extension says XYZ", "a PLY file");
  EXPECT_IO_ERROR(read_mesh(fixture("ply.off", binary_ply)), "ply.off:", "extension says OFF",
                  "a PLY file");
  EXPECT_IO_ERROR(read_mesh(fixture("ply.obj", binary_ply)), "ply.obj:", "OBJ", "a PLY file");
  EXPECT_IO_ERROR(read_mesh(fixture("ply.stl", binary_ply)), "ply.stl:", "STL", "a PLY file");
  EXPECT_IO_ERROR(read_points(fixture("xyz.ply", "1 2 3\n")), "xyz.ply:", "extension says PLY",
                  "numbers (XYZ)");
  EXPECT_IO_ERROR(read_points(fixture("text.ply", "hello\n")), "text.ply:", "not a PLY file");
  EXPECT_IO_ERROR(read_points(fixture("xyz.obj", "1 2 3\n")), "xyz.obj:", "extension says OBJ",
                  "numbers (XYZ)");
  EXPECT_IO_ERROR(read_points(fixture("obj.xyz", "v 1 2 3\n")), "obj.xyz:", "extension says XYZ",
                  "an OBJ file");
  EXPECT_IO_ERROR(read_points(fixture("off.xyz", off)), "off.xyz:", "XYZ", "an OFF file");
  EXPECT_IO_ERROR(read_points(fixture("stl.off", "solid x\nendsolid x\n")), "stl.off:", "OFF",
                  "ASCII STL");
  std::string binary_stl(80, 'x');
  put<uint32_t>(binary_stl, 1);
  binary_stl += std::string(50, '\0');
  EXPECT_IO_ERROR(read_points(fixture("stl.xyz", binary_stl)), "stl.xyz:", "XYZ",
                  "binary STL");
  EXPECT_IO_ERROR(read_points(fixture("junk.xyz", std::string("\x01\x02\0\x03 1 2 3\n", 11))),
                  "junk.xyz:", "XYZ", "binary data");
  EXPECT_IO_ERROR(read_mesh(fixture("points.xyz", "1 2 3\n")), "points.xyz:", "not a mesh");
}

void paths(void **) {
  EXPECT_IO_ERROR(read_points(fixture("cloud.vtk", "1 2 3\n")), "cloud.vtk:",
                  "unknown extension '.vtk'");
  EXPECT_IO_ERROR(read_points(fixture("cloud", "1 2 3\n")), "cloud:", "no file extension");
  EXPECT_IO_ERROR(read_points(io_test::temp_dir), io_test::temp_dir + ":", "is a directory");
  const std::string dir_ply = io_test::temp_path("dir.ply");
  mkdir(dir_ply.c_str(), 0700);
  EXPECT_IO_ERROR(read_mesh(dir_ply), "dir.ply:", "is a directory");
  const std::string missing = io_test::temp_path("missing.ply");
  EXPECT_IO_ERROR(read_points(missing), missing + ":", "No such file");
  // A path through a regular file cannot be opened, even by root.
  const std::string file = fixture("file.xyz", "1 2 3\n");
  EXPECT_IO_ERROR(read_points(file + "/child.xyz"), file + "/child.xyz:", "not a directory");
  EXPECT_IO_ERROR(read_points("/dev/null.xyz"), "/dev/null.xyz:", "No such file");
  const std::string locked = fixture("locked.xyz", "1 2 3\n");
  chmod(locked.c_str(), 0);
  if (geteuid() != 0)  // root reads regardless of permissions
    EXPECT_IO_ERROR(read_points(locked), "locked.xyz:", "Permission denied");
}

void empty_files(void **) {
  for (const char *name : {"empty.xyz", "empty.ply", "empty.off", "empty.obj", "empty.stl"})
    EXPECT_IO_ERROR(read_mesh(fixture(name, "")), std::string(name) + ": the file is empty");
  for (const char *name : {"empty.xyz", "empty.ply", "empty.off", "empty.obj", "empty.stl"})
    EXPECT_IO_ERROR(read_points(fixture(name, "")), std::string(name) + ": the file is empty");
  EXPECT_IO_ERROR(read_points(fixture("blank.xyz", "\n  \n# only a comment\n")), "blank.xyz:",
                  "holds no points");
  EXPECT_IO_ERROR(read_points(fixture("blank.off", "\n# only a comment\n")), "blank.off:",
                  "no OFF header");
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(malformed_numbers),
      cmocka_unit_test(delimited_column_errors),
      cmocka_unit_test(ply_item_shape),
      cmocka_unit_test(ply_header_errors),
      cmocka_unit_test(truncated_binary_ply),
      cmocka_unit_test(lying_headers),
      cmocka_unit_test(text_truncation_and_indices),
      cmocka_unit_test(wrong_format_behind_extension),
      cmocka_unit_test(paths),
      cmocka_unit_test(empty_files),
  };
  return cmocka_run_group_tests(tests, io_test::setup_temp_dir, io_test::remove_temp_dir);
}
