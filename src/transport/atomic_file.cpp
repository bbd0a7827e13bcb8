// Atomic whole-file writes (temporary + fsync + rename) and capped whole-file reads, over POSIX
// I/O.
#include "transport/atomic_file.hpp"
#include "transport/io_error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <string>
#include <system_error>

namespace globe::transport {
namespace {

// Closes the descriptor on every path out of a function.
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  // Closes now so the caller sees close()'s error (NFS reports write errors there).
  int closeNow() {
    int rc = ::close(fd_);
    fd_ = -1;
    return rc;
  }

 private:
  int fd_;
};

std::atomic<uint64_t> tempCounter{0};

// Names the writer among machines sharing a file system: every pod of a Kubernetes Job may run
// the tiler as the same pid, and two shards may both write tiling-plan.json at once.
const std::string& hostTag() {
  static const std::string tag = [] {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) return std::string("host");
    std::string text(name);
    for (char& c : text) {
      if (c == '/' || c == '.') c = '_';
    }
    return text.empty() ? std::string("host") : text;
  }();
  return tag;
}

}  // namespace

void removeAtomicTemporaries(const std::filesystem::path& dir) {
  std::error_code error;
  for (auto it = std::filesystem::recursive_directory_iterator(dir, error);
       !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
    std::error_code typeError;
    if (it->is_regular_file(typeError) &&
        it->path().filename().string().find(".tmp-") != std::string::npos) {
      std::filesystem::remove(it->path(), typeError);
    }
  }
}

Result<void> writeFileAtomically(const std::filesystem::path& path,
                                 std::span<const std::byte> bytes) {
  const std::filesystem::path temp = path.string() + ".tmp-" + hostTag() + "-" +
                                     std::to_string(::getpid()) + "-" +
                                     std::to_string(++tempCounter);
  Fd fd(::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
  if (fd.get() < 0) {  // named as the caller gave it: the temporary name is ours, not theirs
    const int err = errno;
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
    std::error_code missing;
    if (err == ENOENT && !std::filesystem::is_directory(folder, missing)) {
      return makeError(path.string() + ": cannot write: its folder " + folder.string() +
                       " does not exist");
    }
    return ioError(path, "cannot create", err);
  }

  auto fail = [&](std::string_view what, int err) -> Result<void> {
    ::unlink(temp.c_str());
    return ioError(path, what, err);
  };
  const std::byte* data = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(fd.get(), data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail("write failed", errno);
    }
    // POSIX allows 0 only for an empty write; looping on it would never end.
    if (n == 0) return fail("write failed", EIO);
    data += n;
    left -= static_cast<size_t>(n);
  }
  if (::fsync(fd.get()) != 0) return fail("fsync failed", errno);
  if (fd.closeNow() != 0) return fail("close failed", errno);
  if (::rename(temp.c_str(), path.c_str()) != 0) return fail("rename failed", errno);

  // Persist the rename itself; failure here does not make the file wrong, so it is not an error.
  std::filesystem::path dir = path.parent_path();
  if (dir.empty()) dir = ".";
  Fd dirFd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dirFd.get() >= 0) ::fsync(dirFd.get());
  return {};
}

Result<void> writeFileAtomically(const std::filesystem::path& path, std::string_view text) {
  return writeFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

Result<std::vector<std::byte>> readWholeFile(const std::filesystem::path& path, uint64_t maxBytes) {
  // O_NONBLOCK: opening a FIFO without a writer would wait forever; it is refused below.
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
  if (fd.get() < 0) return ioError(path, "cannot open", errno);
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) return ioError(path, "cannot stat", errno);
  if (!S_ISREG(st.st_mode)) return makeError(path.string() + ": not a regular file");
  const auto size = static_cast<uint64_t>(st.st_size);
  if (size > maxBytes) {
    return makeError(path.string() + ": file is " + std::to_string(size) +
                     " bytes, more than the " + std::to_string(maxBytes) + " allowed");
  }
  std::vector<std::byte> bytes(size);
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::read(fd.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return ioError(path, "read failed", errno);
    }
    if (n == 0) break;  // shrank while reading
    done += static_cast<size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace globe::transport
