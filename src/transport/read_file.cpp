// readFileBounded: the reasons a user's file cannot be read, named first, then the project's one
// bounded reader (readWholeFile: no wait on a FIFO, the size checked on the open file).
#include "transport/read_file.hpp"

#include "transport/atomic_file.hpp"

namespace globe::transport {

namespace {

std::string sizeText(std::uintmax_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

Result<std::string> readFileBounded(const std::filesystem::path& file, std::uintmax_t maxBytes) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    return makeError(file.string() + ": " +
                     (std::filesystem::exists(file, error) ? "not a regular file" : "no such file"));
  }
  const std::uintmax_t bytes = std::filesystem::file_size(file, error);
  if (!error && bytes > maxBytes) {
    return makeError(file.string() + ": larger than the " + sizeText(maxBytes) + " allowed");
  }
  auto read = readWholeFile(file, maxBytes);
  if (!read) return Error{read.error()};
  return std::string(reinterpret_cast<const char*>(read->data()), read->size());
}

}  // namespace globe::transport
