#include "core/io/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <optional>
#include <string>

#include "core/common/error.h"

namespace metrofit {
namespace {

[[noreturn]] void fileFail(const std::string& path, const std::string& what, int err) {
  std::string msg = what;
  if (err) msg += std::string(": ") + std::strerror(err);
  throw FileError(ErrorContext{path, 0, 0, {}}, msg);
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  int release() {
    const int f = fd_;
    fd_ = -1;
    return f;
  }

 private:
  int fd_;
};

}  // namespace

std::string displayPath(const std::string& path) {
  return path == "-" ? std::string("<stdin>") : path;
}

std::string readFile(const std::string& path, std::size_t maxBytes) {
  if (path.empty()) fileFail(path, "no file name given", 0);
  if (path == "-") {
    static std::mutex mutex;
    static std::optional<std::string> stdinText;
    const std::lock_guard<std::mutex> lock(mutex);
    if (!stdinText) {
      std::string out;
      char buf[1 << 16];
      for (;;) {
        const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
        if (n < 0) {
          if (errno == EINTR) continue;
          fileFail(displayPath(path), "cannot read standard input", errno);
        }
        if (n == 0) break;
        out.append(buf, static_cast<std::size_t>(n));
        if (out.size() > maxBytes)
          fileFail(displayPath(path), "input is larger than " + std::to_string(maxBytes >> 20) + " MiB", 0);
      }
      stdinText = std::move(out);
    }
    if (stdinText->size() > maxBytes)
      fileFail(displayPath(path), "input is larger than " + std::to_string(maxBytes >> 20) + " MiB", 0);
    return *stdinText;
  }
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) {
    const int err = errno;
    fileFail(path, err == ENOENT ? "cannot open file (it does not exist)" : "cannot open file",
             err == ENOENT ? 0 : err);
  }
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) fileFail(path, "cannot read file", errno);
  if (S_ISDIR(st.st_mode)) fileFail(path, "is a folder, not a file", 0);
  if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > maxBytes) {
    fileFail(path, "file is larger than " + std::to_string(maxBytes >> 20) + " MiB", 0);
  }
  std::string out;
  if (S_ISREG(st.st_mode)) out.reserve(static_cast<std::size_t>(st.st_size));
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd.get(), buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      fileFail(path, "cannot read file", errno);
    }
    if (n == 0) break;
    out.append(buf, static_cast<std::size_t>(n));
    if (out.size() > maxBytes)
      fileFail(path, "file is larger than " + std::to_string(maxBytes >> 20) + " MiB", 0);
  }
  return out;
}

void writeFileAtomic(const std::string& path, std::string_view content) {
  if (path.empty()) fileFail(path, "no output file name given", 0);
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) fileFail(path, "is a folder, not a file", 0);
    if (!S_ISREG(st.st_mode)) {
      // A device, FIFO or socket (e.g. --out /dev/null or /dev/stdout): write straight into it.
      // Renaming a temporary file over it would replace the device with a regular file.
      Fd out(::open(path.c_str(), O_WRONLY | O_CLOEXEC));
      if (out.get() < 0) fileFail(path, "cannot write", errno);
      std::size_t done = 0;
      while (done < content.size()) {
        const ssize_t n = ::write(out.get(), content.data() + done, content.size() - done);
        if (n < 0) {
          if (errno == EINTR) continue;
          fileFail(path, "cannot write", errno);
        }
        done += static_cast<std::size_t>(n);
      }
      return;
    }
  }
  const std::string folder = parentFolder(path);
  std::string tmpl = path + ".tmp-XXXXXX";
  Fd fd(::mkstemp(tmpl.data()));
  if (fd.get() < 0) {
    const int err = errno;
    fileFail(path,
             err == ENOENT ? "cannot write: the folder '" + folder + "' does not exist" : "cannot write",
             err == ENOENT ? 0 : err);
  }
  auto cleanupFail = [&](const std::string& what, int err) {
    ::unlink(tmpl.c_str());
    fileFail(path, what, err);
  };
  // mkstemp creates 0600; give the file the usual permissions (respecting the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(fd.get(), 0666 & ~mask) != 0) cleanupFail("cannot set permissions", errno);
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd.get(), content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      cleanupFail("cannot write", errno);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd.get()) != 0) cleanupFail("cannot flush to disk", errno);
  if (::close(fd.release()) != 0) cleanupFail("cannot close", errno);
  if (::rename(tmpl.c_str(), path.c_str()) != 0) cleanupFail("cannot replace the file", errno);
  // Make the rename durable.
  Fd dir(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.get() >= 0) (void)::fsync(dir.get());
}

std::string parentFolder(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string joinPath(const std::string& folder, const std::string& rel) {
  if (rel.empty()) return folder;
  if (rel.front() == '/') return rel;
  if (folder.empty() || folder == ".") return rel;
  if (folder.back() == '/') return folder + rel;
  return folder + '/' + rel;
}

}  // namespace metrofit
