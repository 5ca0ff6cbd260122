#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "io_test_support.hpp"

namespace io_test {

std::string temp_dir;

int setup_temp_dir(void **) {
  const char *base = std::getenv("TMPDIR");
  std::string pattern = std::string(base && *base ? base : "/tmp") + "/moa_io_test_XXXXXX";
  if (!mkdtemp(&pattern[0])) {
    std::perror("mkdtemp");
    return -1;
  }
  temp_dir = pattern;
  return 0;
}

namespace {

// Removes a tree; fixtures include subdirectories and files made unreadable.
void remove_tree(const std::string &path) {
  struct stat st {};
  if (lstat(path.c_str(), &st) != 0) return;
  if (S_ISDIR(st.st_mode)) {
    chmod(path.c_str(), 0700);
    if (DIR *dir = opendir(path.c_str())) {
      while (const dirent *entry = readdir(dir)) {
        const std::string name = entry->d_name;
        if (name != "." && name != "..") remove_tree(path + "/" + name);
      }
      closedir(dir);
    }
    rmdir(path.c_str());
  } else {
    unlink(path.c_str());
  }
}

}  // namespace

int remove_temp_dir(void **) {
  if (!temp_dir.empty()) remove_tree(temp_dir);
  temp_dir.clear();
  return 0;
}

std::string temp_path(const std::string &name) { return temp_dir + "/" + name; }

std::string write_fixture(const std::string &name, const std::string &bytes) {
  const std::string path = temp_path(name);
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    print_error("cannot write fixture %s\n", path.c_str());
    _fail(__FILE__, __LINE__);
  }
  return path;
}

std::vector<double> points_of(const std::string &path, const char *file, int line) {
  std::string error;
  try {
    return moa::io::read_points(path);
  } catch (const std::exception &e) {
    error = e.what();
  }
  print_error("read_points failed: %s\n", error.c_str());
  _fail(file, line);
  return {};
}

moa::io::MeshData mesh_of(const std::string &path, const char *file, int line) {
  std::string error;
  try {
    return moa::io::read_mesh(path);
  } catch (const std::exception &e) {
    error = e.what();
  }
  print_error("read_mesh failed: %s\n", error.c_str());
  _fail(file, line);
  return {};
}

void expect_io_error(const std::function<void()> &action,
                     std::initializer_list<std::string> fragments, const char *file, int line) {
  std::string message, problem;
  // cmocka's failure is a longjmp: decide inside the try, fail outside it.
  try {
    action();
    problem = "no exception thrown";
  } catch (const moa::io::IoError &e) {
    message = e.what();
  } catch (const std::exception &e) {
    problem = std::string("an exception other than IoError: ") + e.what();
  }
  if (problem.empty())
    for (const std::string &fragment : fragments)
      if (message.find(fragment) == std::string::npos) {
        problem = "the message \"" + message + "\" lacks \"" + fragment + "\"";
        break;
      }
  if (problem.empty()) return;
  print_error("expected an IoError: %s\n", problem.c_str());
  _fail(file, line);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace io_test
