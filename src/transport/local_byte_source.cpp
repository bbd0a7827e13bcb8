// ByteSource over a local directory: pread on descriptors kept open by the stores' pack sets.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "transport/byte_source.hpp"
#include "transport/file_reads.hpp"

namespace globe::transport {
namespace {

class LocalFile final : public ByteFile {
 public:
  LocalFile(int fd, uint64_t sizeBytes, std::string path)
      : fd_(fd), sizeBytes_(sizeBytes), path_(std::move(path)) {}
  ~LocalFile() override { ::close(fd_); }
  LocalFile(const LocalFile&) = delete;
  LocalFile& operator=(const LocalFile&) = delete;

  uint64_t sizeBytes() const override { return sizeBytes_; }
  Result<void> read(std::span<std::byte> out, uint64_t offset) const override {
    return preadFully(fd_, out.data(), out.size(), offset, path_);
  }
  const std::string& location() const override { return path_; }

 private:
  int fd_;
  uint64_t sizeBytes_;
  std::string path_;
};

class LocalByteSource final : public ByteSource {
 public:
  explicit LocalByteSource(std::filesystem::path dir)
      : dir_(std::move(dir)), text_(dir_.string()) {}

  Result<std::optional<std::vector<std::byte>>> readWhole(const std::string& name,
                                                          size_t maxBytes) override {
    const std::filesystem::path path = dir_ / name;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return std::optional<std::vector<std::byte>>();
    auto opened = open(name, maxBytes + 1);
    if (!opened) return Error{opened.error()};
    if (opened->head.size() > maxBytes) {
      return makeError(path.string() + ": larger than " + std::to_string(maxBytes) + " bytes");
    }
    return std::optional<std::vector<std::byte>>(std::move(opened->head));
  }

  Result<OpenedFile> open(const std::string& name, size_t headBytes) override {
    const std::string path = (dir_ / name).string();
    // O_NONBLOCK: a FIFO in a pack's place must not block the viewer; it is refused below.
    FdCloser file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
    if (file.fd < 0) return makeError(path + ": cannot open: " + std::strerror(errno));
    struct stat info {};
    if (::fstat(file.fd, &info) != 0)
      return makeError(path + ": cannot stat: " + std::strerror(errno));
    if (!S_ISREG(info.st_mode)) return makeError(path + ": not a regular file");
    const auto sizeBytes = static_cast<uint64_t>(info.st_size);
    OpenedFile opened;
    opened.head.resize(static_cast<size_t>(std::min<uint64_t>(headBytes, sizeBytes)));
    if (auto read = preadFully(file.fd, opened.head.data(), opened.head.size(), 0, path); !read) {
      return Error{read.error()};
    }
    opened.file = std::make_shared<const LocalFile>(file.fd, sizeBytes, path);
    file.fd = -1;
    return opened;
  }

  std::string locationOf(const std::string& name) const override { return (dir_ / name).string(); }
  const std::string& location() const override { return text_; }

 private:
  std::filesystem::path dir_;
  std::string text_;
};

}  // namespace

std::shared_ptr<ByteSource> localByteSource(const std::filesystem::path& dir) {
  return std::make_shared<LocalByteSource>(dir);
}

}  // namespace globe::transport
