// Helpers shared by the io tests: a scratch directory for fixture files, and checks that
// report an unexpected or missing IoError with its message.
#pragma once

#include <csetjmp>  // cmocka needs these four before its header
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <fstream>  // before cmocka.h, whose fail() macro breaks std::ios::fail
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "io/io.hpp"

extern "C" {  // cmocka 1.1 does not declare its functions extern "C" itself
#include <cmocka.h>
}

namespace io_test {

// The group's scratch directory, made by setup_temp_dir and removed by remove_temp_dir
// (usable as cmocka group setup and teardown).
extern std::string temp_dir;
int setup_temp_dir(void **state);
int remove_temp_dir(void **state);

// temp_dir + "/" + name.
std::string temp_path(const std::string &name);
// Writes a fixture file into the scratch directory and returns its path.
std::string write_fixture(const std::string &name, const std::string &bytes);

// Reads that must succeed; an IoError fails the test with its message.
std::vector<double> points_of(const std::string &path, const char *file, int line);
moa::io::MeshData mesh_of(const std::string &path, const char *file, int line);

// Fails the test unless `action` throws IoError whose message holds every fragment.
void expect_io_error(const std::function<void()> &action,
                     std::initializer_list<std::string> fragments, const char *file, int line);

// Bitwise equality, so that -0 differs from 0 and a NaN equals itself.
bool same_bits(double a, double b);

}  // namespace io_test

#define READ_POINTS(path) io_test::points_of((path), __FILE__, __LINE__)
#define READ_MESH(path) io_test::mesh_of((path), __FILE__, __LINE__)
#define EXPECT_IO_ERROR(statement, ...) \
  io_test::expect_io_error([&] { statement; }, {__VA_ARGS__}, __FILE__, __LINE__)
