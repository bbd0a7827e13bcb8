// "Go to" in `globe view` and `--go-to` on view and snapshot: a typed position in any common
// form (places/coordinates.hpp) or a place's name from the bundled gazetteer (GeoNames, Natural
// Earth and the bundled data's landmarks: places/gazetteer.hpp), the best match taken.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "camera/camera_pose.hpp"
#include "camera/saved_views.hpp"
#include "core/result.hpp"

namespace globe::app {

struct GoToTarget {
  std::string name;  // the place's name (", country"), or the position as typed back
  double latitudeDegrees = 0;
  double longitudeDegrees = 0;
};

// "35.36, 138.73", "138.73 35.36", "35°21'38\"N 138°43'39\"E", or a place name ("mount FUJI",
// "Zurich", "Paris, US"). Errors start "go to:" and say what was wrong.
Result<GoToTarget> parseGoTo(std::string_view text);
// Where `--go-to` puts the camera: as the window's go-to lands, ~15 km from the place looking at
// it 35 degrees down, from the south (north up); its height is above the terrain.
camera::CameraPose goToPose(const GoToTarget& target);
// The view saved under `name` (V in the window; camera/saved_views.hpp), or an error listing
// the saved names.
Result<camera::SavedView> savedViewNamed(const std::string& name);
// The best few places for what is typed so far, for the window's suggestions ("Name, CC").
std::vector<std::string> goToSuggestions(std::string_view text, size_t count);

}  // namespace globe::app
