// The renderer on meshes made here: what the pixels show (background, lit sides, borders,
// defects, wireframe, views), PNG files, the histogram plot, and the defect lists behind
// --highlight-defects (which must agree with moa check's counts). Argument: a scratch folder.
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "cli/cmocka_cxx.hpp"
#include "meshes.hpp"
#include "quality/defects.hpp"
#include "quality/quality.hpp"
#include "render/render.hpp"

namespace {

using moa::test::Mesh;
namespace render = moa::render;

std::string g_dir;

render::Image draw(const Mesh &m, render::View view, int w, int h, bool wireframe = false,
                   const render::Highlights *highlights = nullptr) {
  render::Options o;
  o.view = view;
  o.width = w;
  o.height = h;
  o.wireframe = wireframe;
  return render::render_mesh(m.xyz.data(), m.vertices(), m.tri.data(), m.faces(), o, highlights);
}

render::Highlights highlights_of(const Mesh &m) {
  moa::MeshDefects d = moa::find_mesh_defects(m.xyz.data(), m.vertices(), m.tri.data(), m.faces());
  render::Highlights h;
  h.boundary_edges = d.boundary_edges;
  h.defective_faces = d.defective_faces;
  return h;
}

void test_closed_cube(void **) {
  const render::Image image = draw(moa::test::cube(), render::View::Front, 128, 96);
  assert_int_equal(image.width, 128);
  assert_int_equal(image.height, 96);
  assert_true(moa::test::corners_are_background(image));
  assert_true(moa::test::lit_front(image.at(64, 48)));
  // The +z side faces the camera squarely: evenly lit.
  assert_true(image.at(50, 40) == image.at(78, 56));
  const render::Highlights h = highlights_of(moa::test::cube());
  assert_true(h.boundary_edges.empty() && h.defective_faces.empty());
  assert_int_equal(
      moa::test::count_colour(draw(moa::test::cube(), render::View::Iso, 96, 96, false, &h),
                              render::kBoundaryColour),
      0);
}

void test_open_cube_shows_its_border(void **) {
  const Mesh open = moa::test::open_cube();
  const render::Highlights h = highlights_of(open);
  assert_int_equal(h.boundary_edges.size(), 4);
  const render::Image plain = draw(open, render::View::Front, 160, 160);
  const render::Image marked = draw(open, render::View::Front, 160, 160, false, &h);
  // Through the opening the inside of the -z side shows: its back.
  assert_true(moa::test::lit_back(plain.at(80, 80)));
  assert_true(moa::test::lit_back(marked.at(80, 80)));
  assert_true(moa::test::corners_are_background(marked));
  assert_int_equal(moa::test::count_colour(plain, render::kBoundaryColour), 0);
  // Four edges along the picture's sides, each some hundred pixels long and 3 wide.
  assert_true(moa::test::count_colour(marked, render::kBoundaryColour) > 4 * 100);
  // The border runs around the opening: look along the middle row from the left.
  int first = -1;
  for (int x = 0; x < 160 && first < 0; ++x)
    if (marked.at(x, 80) == render::kBoundaryColour) first = x;
  assert_true(first > 0 && first < 20);
}

void test_defective_faces(void **) {
  // Two triangles crossing each other, apart from a clean third one.
  Mesh m;
  m.vertex(-1, 0, -1), m.vertex(1, 0, -1), m.vertex(0, 0, 1);
  m.vertex(0, -1, -0.5), m.vertex(0, 1, -0.5), m.vertex(0, 0, 0.5);
  m.vertex(3, 0, 0), m.vertex(4, 0, 0), m.vertex(3, 1, 0);
  m.face(0, 1, 2), m.face(3, 4, 5), m.face(6, 7, 8);
  const moa::MeshDefects d =
      moa::find_mesh_defects(m.xyz.data(), m.vertices(), m.tri.data(), m.faces());
  assert_int_equal(d.intersecting_pairs.size(), 1);
  assert_int_equal(d.defective_faces.size(), 2);
  render::Highlights h = highlights_of(m);
  h.boundary_edges.clear();  // every edge here is one: keep the picture to the defects
  const render::Image image = draw(m, render::View::Iso, 200, 200, false, &h);
  assert_true(moa::test::count_colour(image, render::kDefectColour) > 50);  // the outlines
  size_t purple = 0;  // shaded faces in the defect colour: red and blue well above green
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const render::Rgb c = image.at(x, y);
      purple += c != render::kDefectColour && c.r > c.g + 40 && c.b > c.g + 40;
    }
  assert_true(purple > 100);
}

void test_wireframe(void **) {
  const Mesh cube = moa::test::cube();
  const render::Image plain = draw(cube, render::View::Front, 120, 120);
  const render::Image wire = draw(cube, render::View::Front, 120, 120, true);
  // The diagonal of the +z side runs through the centre.
  assert_true(moa::test::brightness(wire.at(59, 60)) + 150 <
              moa::test::brightness(plain.at(59, 60)));
  assert_true(wire.at(30, 60) == plain.at(30, 60));  // away from every edge
  assert_true(moa::test::corners_are_background(wire));
}

void test_views(void **) {
  // A right triangle in the z = 0 plane, its right angle at the origin, normal +z.
  Mesh t;
  t.vertex(0, 0, 0), t.vertex(1, 0, 0), t.vertex(0, 1, 0);
  t.face(0, 1, 2);
  render::Image front = draw(t, render::View::Front, 100, 100);
  assert_true(moa::test::lit_front(front.at(27, 73)));  // lower left
  assert_true(front.at(73, 27) == render::kBackground);
  render::Image back = draw(t, render::View::Back, 100, 100);  // mirrored, other side
  assert_true(moa::test::lit_back(back.at(73, 73)));
  assert_true(back.at(27, 27) == render::kBackground);
  // The same in the y = 0 plane seen from the top: x to the right, -z up.
  Mesh flat;
  flat.vertex(0, 0, 0), flat.vertex(1, 0, 0), flat.vertex(0, 0, 1);
  flat.face(0, 2, 1);  // normal +y
  render::Image top = draw(flat, render::View::Top, 100, 100);
  assert_true(moa::test::lit_front(top.at(27, 27)));
  assert_true(top.at(73, 73) == render::kBackground);
  render::Image bottom = draw(flat, render::View::Bottom, 100, 100);
  assert_true(moa::test::lit_back(bottom.at(27, 73)));
  // Every view of the cube shows it in the middle.
  for (const char *name : {"front", "back", "left", "right", "top", "bottom", "iso"}) {
    render::View view;
    assert_true(render::view_from_name(name, view));
    assert_string_equal(render::view_name(view), name);
    const render::Image image = draw(moa::test::cube(), view, 64, 64);
    assert_true(moa::test::corners_are_background(image));
    assert_true(image.at(32, 32) != render::kBackground);
  }
}

void test_degenerate_input(void **) {
  render::Options o;
  o.width = 32;
  o.height = 16;
  const render::Image empty = render::render_mesh(nullptr, 0, nullptr, 0, o);
  assert_int_equal(moa::test::count_colour(empty, render::kBackground), 32 * 16);
  // Out-of-range indices, repeated indices and non-finite corners are left out.
  Mesh m = moa::test::cube();
  m.vertex(NAN, 0, 0);
  m.face(0, 1, 99), m.face(0, 0, 1), m.face(0, 1, 8);
  const render::Image image = draw(m, render::View::Front, 64, 64);
  assert_true(moa::test::lit_front(image.at(32, 32)));
  o.width = render::kMaxSide + 1;
  bool thrown = false;
  try {
    render::render_mesh(m.xyz.data(), m.vertices(), m.tri.data(), m.faces(), o);
  } catch (const render::RenderError &) {
    thrown = true;
  }
  assert_true(thrown);
}

void test_png_files(void **) {
  const render::Image image = draw(moa::test::cube(), render::View::Iso, 77, 55);
  const std::string path = g_dir + "/cube.png";
  render::write_png(path, image);
  const render::Image back = render::read_png(path);
  assert_int_equal(back.width, 77);
  assert_int_equal(back.height, 55);
  assert_true(back.rgb == image.rgb);
  std::FILE *f = std::fopen((g_dir + "/not.png").c_str(), "w");
  std::fputs("not a picture\n", f);
  std::fclose(f);
  for (const std::string &bad : {g_dir + "/not.png", g_dir + "/missing.png"}) {
    try {
      render::read_png(bad);
      fail_msg("%s was read", bad.c_str());
    } catch (const render::RenderError &e) {
      assert_true(std::string(e.what()).find(bad) == 0);
    }
  }
  try {
    render::write_png(g_dir + "/no/such/dir/x.png", image);
    fail_msg("wrote into a missing folder");
  } catch (const render::RenderError &e) {
    assert_true(std::string(e.what()).find("x.png: cannot write") != std::string::npos);
  }
}

void test_parsing(void **) {
  int w = 0, h = 0;
  assert_true(render::parse_size("1024x768", w, h) && w == 1024 && h == 768);
  assert_true(render::parse_size("300", w, h) && w == 300 && h == 300);
  assert_true(render::parse_size("8192X1", w, h) && w == 8192 && h == 1);
  for (const char *bad :
       {"", "x", "0x5", "5x0", "8193x2", "12x", "x12", "axb", "-4x4", "4x4x4", "1e3"})
    assert_false(render::parse_size(bad, w, h));
  render::View view;
  assert_false(render::view_from_name("diagonal", view));
  assert_true(render::has_png_extension("a.png") && render::has_png_extension("/x/B.PNG"));
  assert_false(render::has_png_extension("a.jpg") || render::has_png_extension("png") ||
               render::has_png_extension("a.png.txt"));
}

void test_histogram_plot(void **) {
  const std::vector<size_t> counts = {0, 5, 20, 40, 10, 0, 0, 0, 0, 0, 0, 1};
  const render::Image chart = render::plot_histogram(counts, 0, 5);
  assert_int_equal(chart.width, 640);
  assert_int_equal(chart.height, 360);
  // The height of each bar: blue pixels in the column through its middle.
  const double bar = (640.0 - 16 - 56) / double(counts.size());
  std::vector<int> height;
  for (size_t b = 0; b < counts.size(); ++b) {
    const int x = 56 + int((double(b) + 0.5) * bar);
    int n = 0;
    for (int y = 0; y < chart.height; ++y) {
      const render::Rgb c = chart.at(x, y);
      n += c.b > c.r + 50;
    }
    height.push_back(n);
  }
  assert_int_equal(height[0], 0);
  assert_true(height[3] > height[2] && height[2] > height[4] && height[4] > height[1]);
  assert_true(height[1] > height[11] && height[11] > 0);
  const std::string path = g_dir + "/chart.png";
  render::write_png(path, chart);
  assert_true(render::read_png(path).rgb == chart.rgb);
}

// The lists' sizes are moa check's counts, also past the 1000 pairs check lists.
void expect_same_counts(const Mesh &m) {
  const moa::MeshReport r = moa::analyze_mesh(m.xyz.data(), m.vertices(), m.tri.data(), m.faces());
  const moa::MeshDefects d =
      moa::find_mesh_defects(m.xyz.data(), m.vertices(), m.tri.data(), m.faces());
  assert_int_equal(d.boundary_edges.size(), r.boundary_edges);
  assert_int_equal(d.non_manifold_edges.size(), r.non_manifold_edges);
  assert_int_equal(d.non_manifold_vertices.size(), r.non_manifold_vertices);
  assert_int_equal(d.intersecting_pairs.size(), r.self_intersecting_pairs);
  assert_true(d.intersections_tested);
  const moa::MeshDefects quick =
      moa::find_mesh_defects(m.xyz.data(), m.vertices(), m.tri.data(), m.faces(), false);
  assert_true(quick.boundary_edges == d.boundary_edges);
  assert_true(quick.intersecting_pairs.empty() && !quick.intersections_tested);
}

void test_defect_lists(void **) {
  expect_same_counts(moa::test::cube());
  expect_same_counts(moa::test::open_cube());
  Mesh bowtie;  // two triangles sharing one vertex only: a non-manifold vertex
  bowtie.vertex(0, 0, 0), bowtie.vertex(1, 0, 0), bowtie.vertex(1, 1, 0);
  bowtie.vertex(-1, 0, 0), bowtie.vertex(-1, -1, 0);
  bowtie.face(0, 1, 2), bowtie.face(0, 3, 4);
  expect_same_counts(bowtie);
  const moa::MeshDefects b = moa::find_mesh_defects(bowtie.xyz.data(), 5, bowtie.tri.data(), 2);
  assert_true(b.non_manifold_vertices == std::vector<uint32_t>{0});
  assert_int_equal(b.defective_faces.size(), 2);
  Mesh fin = moa::test::cube();  // a third face on the edge 0-1
  fin.vertex(0, -3, -3);
  fin.face(0, 1, 8);
  expect_same_counts(fin);
  const moa::MeshDefects f = moa::find_mesh_defects(fin.xyz.data(), 9, fin.tri.data(), 13);
  assert_int_equal(f.non_manifold_edges.size(), 1);
  assert_true(f.non_manifold_edges[0] == std::make_pair(0u, 1u));
  assert_int_equal(f.defective_faces.size(), 3);
  // 40 planes x = i crossing 40 planes y = j: 1600 intersecting pairs.
  Mesh grid;
  for (int i = 0; i < 40; ++i) {
    const uint32_t v = uint32_t(grid.vertices());
    grid.vertex(i, -10, -10), grid.vertex(i, 200, -10), grid.vertex(i, -10, 200);
    grid.face(v, v + 1, v + 2);
    grid.vertex(-10, i, -10), grid.vertex(200, i, -10), grid.vertex(-10, i, 200);
    grid.face(v + 3, v + 4, v + 5);
  }
  expect_same_counts(grid);
  const moa::MeshDefects g =
      moa::find_mesh_defects(grid.xyz.data(), grid.vertices(), grid.tri.data(), grid.faces());
  assert_int_equal(g.intersecting_pairs.size(), 1600);
  assert_int_equal(g.defective_faces.size(), 80);
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCRATCH_DIR\n", argv[0]);
    return 2;
  }
  g_dir = argv[1];
  ::mkdir(g_dir.c_str(), 0755);
  const CMUnitTest tests[] = {
      cmocka_unit_test(test_closed_cube),     cmocka_unit_test(test_open_cube_shows_its_border),
      cmocka_unit_test(test_defective_faces), cmocka_unit_test(test_wireframe),
      cmocka_unit_test(test_views),           cmocka_unit_test(test_degenerate_input),
      cmocka_unit_test(test_png_files),       cmocka_unit_test(test_parsing),
      cmocka_unit_test(test_histogram_plot),  cmocka_unit_test(test_defect_lists),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
