// Parses the command line's numbers: --camera LON,LAT,HEIGHT[,HEADING,PITCH,ROLL] (degrees and
// metres), --size WxH and single numbers (--fps, --sse), each refused with a message naming it.
#pragma once

#include <string>
#include <string_view>

#include "camera/camera_pose.hpp"
#include "core/result.hpp"

namespace globe::app {

// Heading 0 = north, pitch −90 = straight down (the default), roll 0. Every field must be a
// finite number ("nan", "inf", "1e999" and empty fields are refused).
Result<camera::CameraPose> parseCameraArgument(const std::string& text);

// "WxH" → width and height in pixels (1..16384 each).
Result<std::pair<int, int>> parseSizeArgument(const std::string& text);

// A finite number in [minimum, maximum] ((minimum, maximum] when minimumExcluded); errors read
// "--fps 'nan': not a finite number", "--fps '0': must be in (0, 1000]".
Result<double> parseNumberArgument(std::string_view option, const std::string& text, double minimum,
                                   double maximum, bool minimumExcluded = false);

}  // namespace globe::app
