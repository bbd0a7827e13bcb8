// readCameraPath: picks the camera path reader by the file's extension.
#include "camera/camera_path_file.hpp"

#include "core/ascii_case.hpp"

namespace globe::camera {

Result<CameraPathFile> readCameraPath(const std::filesystem::path& path) {
  const std::string extension = core::asciiLower(path.extension().string());
  if (extension == ".json") return readCameraPathJson(path);
  if (extension == ".kml") return readKmlTour(path);
  return makeError(path.string() + ": unknown camera path format '" + extension +
                   "' (expected a .json path or a .kml tour)");
}

}  // namespace globe::camera
