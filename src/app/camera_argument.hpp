// Parses --camera LON,LAT,HEIGHT[,HEADING,PITCH,ROLL] (degrees and metres) with clear errors.
#pragma once

#include <string>

#include "camera/camera_pose.hpp"
#include "geo/result.hpp"

namespace globe::app {

// Heading 0 = north, pitch −90 = straight down (the default), roll 0.
Result<camera::CameraPose> parseCameraArgument(const std::string& text);

// "WxH" → width and height in pixels (1..16384 each).
Result<std::pair<int, int>> parseSizeArgument(const std::string& text);

}  // namespace globe::app
