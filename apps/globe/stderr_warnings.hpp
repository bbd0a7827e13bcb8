// How `globe` (and the tools that run its frame) shows library warnings: "globe: WARNING" on
// stderr, each as it comes.
#pragma once

#include "core/warnings.hpp"

namespace globe::app {

core::WarningSink stderrWarnings();

}  // namespace globe::app
