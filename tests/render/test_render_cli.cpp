// The commands that draw: `moa render`, `moa reconstruct --render`, `moa check --report`, run
// as separate processes; their pictures are decoded and looked at. Arguments: the tool's path
// and a scratch folder.
#include <sys/stat.h>

#include <cstdio>
#include <string>

#include "cli/tool_runner.hpp"
#include "meshes.hpp"
#include "render/render.hpp"

namespace {

namespace render = moa::render;

using namespace moa::test;

Tool g_moa;

std::string path(const std::string &name) { return g_moa.path(name); }
Run moa(const std::string &args) { return g_moa.run(args); }

std::string cube_file() {
  const std::string file = path("cube.off");
  write_file(file, moa::test::cube().off());
  return file;
}

std::string open_cube_file() {
  const std::string file = path("open_cube.off");
  write_file(file, moa::test::open_cube().off());
  return file;
}

void test_help(void **) {
  Run r = moa("--help");
  expect_ok(r);
  EXPECT_HAS(r.out, "moa render MESH -o IMAGE.png");
  EXPECT_HAS(r.out, "[--render IMAGE.png]");
  EXPECT_HAS(r.out, "[--report REPORT.md]");
  for (const char *args : {"render --help", "help render"}) {
    r = moa(args);
    expect_ok(r);
    for (const char *part :
         {"Usage: moa render", "--view", "--size", "--wireframe", "--highlight-defects"})
      EXPECT_HAS(r.out, part);
  }
  EXPECT_HAS(moa("reconstruct --help").out, "--render IMAGE.png");
  EXPECT_HAS(moa("check --help").out, "--report REPORT.md");
}

void test_render_cube(void **) {
  const std::string png = path("cube.png");
  std::remove(png.c_str());
  Run r =
      moa("render " + quote(cube_file()) + " -o " + quote(png) + " --view front --size 160x120");
  expect_ok(r);
  EXPECT_HAS(r.out, "12 triangles");
  EXPECT_HAS(r.out, "160x120, front view");
  const render::Image image = render::read_png(png);
  assert_int_equal(image.width, 160);
  assert_int_equal(image.height, 120);
  assert_true(moa::test::corners_are_background(image));
  assert_true(moa::test::lit_front(image.at(80, 60)));
  assert_int_equal(moa::test::count_colour(image, render::kBoundaryColour), 0);

  // The default size; every view and the wireframe work.
  r = moa("render -q " + quote(cube_file()) + " --output=" + quote(png));
  expect_ok(r);
  assert_true(r.out.empty());
  const render::Image big = render::read_png(png);
  assert_int_equal(big.width, 1024);
  assert_int_equal(big.height, 1024);
  for (const char *view : {"front", "back", "left", "right", "top", "bottom", "iso"}) {
    r = moa("render " + quote(cube_file()) + " -o " + quote(png) +
            " --size 64 --wireframe --view=" + view);
    expect_ok(r);
    const render::Image small = render::read_png(png);
    assert_true(small.width == 64 && small.height == 64);
    assert_true(moa::test::corners_are_background(small));
    assert_true(small.at(32, 32) != render::kBackground);
  }
}

void test_render_defects(void **) {
  const std::string png = path("open.png");
  Run r = moa("render " + quote(open_cube_file()) + " -o " + quote(png) +
              " --view front --size 200x200 --highlight-defects");
  expect_ok(r);
  EXPECT_HAS(r.out, "4 boundary edges");
  EXPECT_HAS(r.out, "0 defective faces");
  render::Image image = render::read_png(png);
  assert_true(moa::test::count_colour(image, render::kBoundaryColour) > 4 * 100);
  assert_true(moa::test::lit_back(image.at(100, 100)));  // the inside, through the opening
  // Without --highlight-defects the border is not drawn.
  expect_ok(moa("render " + quote(open_cube_file()) + " -o " + quote(png) +
                " --view front --size 200x200"));
  image = render::read_png(png);
  assert_int_equal(moa::test::count_colour(image, render::kBoundaryColour), 0);
}

void test_render_errors(void **) {
  const std::string cube = cube_file();
  expect_error(moa("render " + quote(cube)), 2, {"missing -o IMAGE.png"});
  expect_error(moa("render -o " + quote(path("x.png"))), 2, {"missing MESH"});
  expect_error(moa("render " + quote(cube) + " -o " + quote(path("x.png")) + " --view diagonal"), 2,
               {"--view 'diagonal'", "front|back|left|right|top|bottom|iso"});
  for (const char *size : {"0x10", "10x", "big", "20000x20000"})
    expect_error(moa("render " + quote(cube) + " -o " + quote(path("x.png")) + " --size " + size),
                 2, {"--size '" + std::string(size) + "'"});
  expect_error(moa("render " + quote(cube) + " -o " + quote(path("x.png")) + " --shiny"), 2,
               {"unknown option '--shiny'"});
  expect_error(moa("render " + quote(cube) + " -o " + quote(path("x.jpg"))), 5, {"x.jpg", "PNG"});
  expect_error(moa("render " + quote(path("missing.ply")) + " -o " + quote(path("x.png"))), 3,
               {"missing.ply"});
  expect_error(moa("render " + quote(cube) + " -o " + quote(path("no/such/dir/x.png"))), 5,
               {"x.png", "cannot write"});
}

void test_reconstruct_render(void **) {
  const std::string input = write_sphere_points(path("sphere.xyz")), mesh = path("sphere.ply"),
                    png = path("sphere.png");
  std::remove(png.c_str());
  Run r = moa("reconstruct " + quote(input) + " -o " + quote(mesh) + " --render " + quote(png));
  expect_ok(r);
  EXPECT_HAS(r.out, "rendered " + png);
  const render::Image image = render::read_png(png);
  assert_int_equal(image.width, 1024);
  assert_int_equal(image.height, 1024);
  assert_true(moa::test::corners_are_background(image));
  assert_true(moa::test::lit_front(image.at(512, 512)));  // a closed sphere, faces outward

  // A picture name that is no PNG is refused before the run: no mesh is written.
  const std::string other = path("sphere2.ply");
  std::remove(other.c_str());
  expect_error(moa("reconstruct " + quote(input) + " -o " + quote(other) + " --render " +
                   quote(path("sphere.gif"))),
               5, {"sphere.gif"});
  assert_false(exists(other));
}

void test_check_report(void **) {
  const std::string report = path("open_report.md"), chart = path("open_report_angles.png");
  std::remove(report.c_str());
  std::remove(chart.c_str());
  Run r = moa("check " + quote(open_cube_file()) + " --report " + quote(report));
  expect_ok(r);
  EXPECT_HAS(r.out, "boundary edges");  // the usual text still goes to stdout
  const std::string md = read_file(report);
  for (const char *part :
       {"# moa check: ", "open\\_cube.off", "| triangles | 10 |",
        "| closed | no: 4 boundary edges in 1 loops |", "| non-manifold edges | 0 |",
        "| self-intersecting pairs | 0", "## Output contract", "![", "(<open_report_angles.png>)",
        "| 0-5 | 0 | 0.00% |"})
    EXPECT_HAS(md, part);
  const render::Image image = render::read_png(chart);
  assert_int_equal(image.width, 640);
  assert_int_equal(image.height, 360);
  // With --json as well, and into a folder that does not exist.
  expect_ok(
      moa("check --json " + quote(cube_file()) + " --report=" + quote(path("cube_report.md"))));
  assert_true(exists(path("cube_report_angles.png")));
  expect_error(moa("check " + quote(cube_file()) + " --report " + quote(path("no/dir/r.md"))), 5,
               {"r.md: cannot write"});
  // The picture's name is taken by a folder: refused before the mesh is read.
  ::mkdir(path("blocked_angles.png").c_str(), 0755);
  expect_error(
      moa("check " + quote(path("missing.ply")) + " --report " + quote(path("blocked.md"))), 5,
      {"blocked_angles.png: cannot write"});
  assert_false(exists(path("blocked.md")));
}

}  // namespace

int main(int argc, char **argv) {
  if (!tool_from_args(argc, argv, g_moa)) return 2;
  ::mkdir(g_moa.dir.c_str(), 0755);
  const CMUnitTest tests[] = {
      cmocka_unit_test(test_help),
      cmocka_unit_test(test_render_cube),
      cmocka_unit_test(test_render_defects),
      cmocka_unit_test(test_render_errors),
      cmocka_unit_test(test_reconstruct_render),
      cmocka_unit_test(test_check_report),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
