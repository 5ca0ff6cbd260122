#include "file_access.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "errors.hpp"

namespace moa::io::detail {
namespace {

std::string describe_errno(int err) {
  // strerror's "Not a directory" would puzzle someone who named a file, not a directory.
  if (err == ENOTDIR) return "a parent in the path is not a directory";
  return std::strerror(err);
}

class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor &) = delete;
  FileDescriptor &operator=(const FileDescriptor &) = delete;
  int get() const { return fd_; }
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_;
};

}  // namespace

std::string read_whole_file(const std::string &path) {
  // stat first: opening a FIFO for reading would block.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail(path, "cannot open: " + describe_errno(errno));
  if (S_ISDIR(st.st_mode)) fail(path, "is a directory, not a file");
  if (!S_ISREG(st.st_mode)) fail(path, "is not a regular file");

  FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) fail(path, "cannot open: " + describe_errno(errno));
  if (::fstat(fd.get(), &st) != 0) fail(path, "cannot read: " + describe_errno(errno));

  std::string data(static_cast<size_t>(st.st_size), '\0');
  size_t used = 0;
  for (;;) {
    if (used == data.size()) data.resize(data.size() + 65536);  // the file grew meanwhile
    const ssize_t n = ::read(fd.get(), &data[used], data.size() - used);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(path, "cannot read: " + describe_errno(errno));
    }
    if (n == 0) break;
    used += static_cast<size_t>(n);
  }
  data.resize(used);
  return data;
}

void write_whole_file(const std::string &path, const std::string &bytes) {
  FileDescriptor fd(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666));
  if (fd.get() < 0) fail(path, "cannot write: " + describe_errno(errno));
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(path, "cannot write: " + describe_errno(errno));
    }
    done += static_cast<size_t>(n);
  }
  // close reports delayed write errors (NFS, full disks).
  if (::close(fd.release()) != 0) fail(path, "cannot write: " + describe_errno(errno));
}

}  // namespace moa::io::detail
