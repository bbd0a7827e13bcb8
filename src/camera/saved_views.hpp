// Views a user saves by name and comes back to: kept in $XDG_CONFIG_HOME/globe/views.json (else
// ~/.config/globe/views.json), and exchanged with Google Earth as KML: each a Placemark with a
// <Camera>; read back from <Camera> or <LookAt> (a point seen from a range, heading and tilt).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "camera/camera_pose.hpp"
#include "core/result.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::camera {

struct SavedView {
  std::string name;
  CameraPose pose;
  // The pose's height is above the terrain (a KML view relativeToGround or clampToGround).
  bool heightAboveTerrain = false;
};

std::filesystem::path userViewsFile();

// The views in a file; none when the file does not exist. Errors name the file.
Result<std::vector<SavedView>> readSavedViews(const std::filesystem::path& file);
// Written to a temporary name, then renamed.
Result<void> writeSavedViews(const std::filesystem::path& file,
                             const std::vector<SavedView>& views);
// `view` added, replacing one of the same name.
void putSavedView(std::vector<SavedView>& views, const SavedView& view);
// The view of that name (case ignored), or null.
const SavedView* findSavedView(const std::vector<SavedView>& views, const std::string& name);

std::string savedViewsToKml(const std::vector<SavedView>& views);
// Every Placemark (or Document) with a <Camera> or <LookAt>, named by its <name>. Errors name
// the file and line.
Result<std::vector<SavedView>> savedViewsFromKml(const std::filesystem::path& file,
                                                 const geo::Ellipsoid& ellipsoid);
// Where a KML LookAt puts the camera: `range` metres from the point, looking at it along
// `heading` (degrees from north) and `tilt` (degrees from straight down).
CameraPose lookAtPose(double longitudeDegrees, double latitudeDegrees, double altitudeMeters,
                      double headingDegrees, double tiltDegrees, double rangeMeters,
                      const geo::Ellipsoid& ellipsoid);

}  // namespace globe::camera
