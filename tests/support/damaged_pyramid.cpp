#include "tests/support/damaged_pyramid.hpp"

#include <fstream>
#include <string>

#include "tests/support/tiler_test_fixture.hpp"

namespace globe::testing {

namespace fs = std::filesystem;

fs::path damagedPyramid(const fs::path& dir) {
  const fs::path copy = dir / "damaged";
  fs::copy(bundledPyramid(), copy, fs::copy_options::recursive);
  for (const auto& entry : fs::recursive_directory_iterator(copy)) {
    if (entry.path().extension() != ".pack") continue;
    const std::string level = entry.path().parent_path().filename().string();  // "L12"
    if (std::stoi(level.substr(1)) < 8) continue;
    std::fstream file(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
    const auto size = static_cast<std::streamoff>(fs::file_size(entry.path()));
    for (std::streamoff at = size / 3; at + 8 < size; at += 97) {
      file.seekg(at);
      const char byte = static_cast<char>(file.get() ^ 0xff);
      file.seekp(at);
      file.put(byte);
    }
  }
  return copy;
}

}  // namespace globe::testing
