// readCameraPath: picks the camera path reader by the file's extension.
#include "io/camera_path_file.hpp"

#include <algorithm>
#include <cctype>

namespace globe::io {

Result<CameraPathFile> readCameraPath(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".json") return readCameraPathJson(path);
  if (extension == ".kml") return readKmlTour(path);
  return makeError(path.string() + ": unknown camera path format '" + extension +
                   "' (expected a .json path or a .kml tour)");
}

}  // namespace globe::io
