// A per-test scratch folder for the hand-made overlay files, and lookups into a read document.
#pragma once

#include <cpl_conv.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "overlays/overlay_model.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::overlays {

inline const std::filesystem::path kInterop =
    std::filesystem::path(GLOBE_SOURCE_DIR) / "tests/data/interop";

class ScratchFolder {
 public:
  ScratchFolder() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("globe-overlays-" + std::to_string(::getpid()) + "-" + test->test_suite_name() + "-" +
             test->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

  std::filesystem::path write(const std::string& name, std::string_view text) const {
    const auto file = path_ / name;
    std::ofstream(file, std::ios::binary)
        .write(text.data(), static_cast<std::streamsize>(text.size()));
    return file;
  }

 private:
  std::filesystem::path path_;
};

// Writes a zip (GDAL's zip writer) holding these (name, bytes) entries, in order.
inline void writeZip(const std::filesystem::path& file,
                     const std::vector<std::pair<std::string, std::string>>& entries) {
  void* zip = CPLCreateZip(file.c_str(), nullptr);
  ASSERT_NE(zip, nullptr);
  for (const auto& [name, bytes] : entries) {
    ASSERT_EQ(CPLCreateFileInZip(zip, name.c_str(), nullptr), CE_None);
    ASSERT_EQ(CPLWriteFileInZip(zip, bytes.data(), static_cast<int>(bytes.size())), CE_None);
    ASSERT_EQ(CPLCloseFileInZip(zip), CE_None);
  }
  ASSERT_EQ(CPLCloseZip(zip), CE_None);
}

// The placemark with this name (and folder, when given), or nullptr.
inline const Placemark* findPlacemark(const OverlayDocument& document, std::string_view name,
                                      std::string_view folderPath = "*") {
  for (const Placemark& p : document.placemarks) {
    if (p.name == name && (folderPath == "*" || p.folderPath == folderPath)) return &p;
  }
  return nullptr;
}

// A KML document around these features.
inline std::string kml(std::string_view features) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<kml xmlns=\"http://www.opengis.net/kml/2.2\" "
         "xmlns:gx=\"http://www.google.com/kml/ext/2.2\">\n<Document>\n" +
         std::string(features) + "\n</Document>\n</kml>\n";
}

}  // namespace globe::overlays
