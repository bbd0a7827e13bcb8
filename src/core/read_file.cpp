// readFileBounded: stat, then read to the end, stopping one chunk past the limit.
#include "core/read_file.hpp"

#include <algorithm>
#include <fstream>

namespace globe {

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
  const auto tooLarge = [&] {
    return makeError(file.string() + ": larger than the " + sizeText(maxBytes) + " allowed");
  };
  if (!error && bytes > maxBytes) return tooLarge();
  std::ifstream in(file, std::ios::binary);
  if (!in) return makeError(file.string() + ": cannot be opened");
  std::string text;
  text.reserve(error ? 0 : static_cast<size_t>(std::min(bytes, maxBytes)));
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {  // to the end: it may have grown
    text.append(chunk, static_cast<size_t>(in.gcount()));
    if (text.size() > maxBytes) return tooLarge();
  }
  if (in.bad()) return makeError(file.string() + ": read failed");
  return text;
}

}  // namespace globe
