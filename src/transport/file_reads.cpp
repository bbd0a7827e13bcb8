#include "transport/file_reads.hpp"

#include <cerrno>
#include <cstring>
#include <string>

namespace globe::transport {

Result<void> preadFully(int fd, std::byte* out, size_t bytes, uint64_t offset,
                        const std::filesystem::path& path) {
  size_t done = 0;
  while (done < bytes) {
    const ssize_t n = ::pread(fd, out + done, bytes - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      return makeError(
          path.string() + ": read failed at byte " + std::to_string(offset + done) +
          (n < 0 ? std::string(": ") + std::strerror(errno) : ": unexpected end of file"));
    }
    done += static_cast<size_t>(n);
  }
  return {};
}

}  // namespace globe::transport
