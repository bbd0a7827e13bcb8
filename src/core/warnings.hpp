// Where a library's warnings go. Libraries never print: the program passes a sink that prints
// them (or shows them in its window), a test one that collects them; with no sink they are dropped.
#pragma once

#include <functional>
#include <string>

namespace globe::core {

// One warning, without the program's name in front: "imagery L3 X5 Y2: bad tile; drawing a
// coarser tile there".
using WarningSink = std::function<void(const std::string& warning)>;

inline void warn(const WarningSink& sink, const std::string& warning) {
  if (sink) sink(warning);
}

}  // namespace globe::core
