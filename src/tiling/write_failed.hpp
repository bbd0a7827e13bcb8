// The error a tiler returns when writing its output failed: its writes are atomic and resumable,
// so it says that nothing half-written was left and that the same command resumes.
#pragma once

#include <string>

#include "core/result.hpp"

namespace globe::tiling {

inline Error writeFailed(const std::string& error) {
  return makeError(error +
                   " (nothing half-written was left; once fixed, the same command resumes)");
}

}  // namespace globe::tiling
