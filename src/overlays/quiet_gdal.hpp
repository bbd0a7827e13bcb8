// GDAL reports through CPLError, which prints by default: a library stays quiet, and says what
// went wrong in its own errors (CPLGetLastErrorMsg still has the message).
#pragma once

#include <cpl_error.h>

namespace globe::overlays {

struct QuietGdal {
  QuietGdal() { CPLPushErrorHandler(CPLQuietErrorHandler); }
  ~QuietGdal() { CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
};

}  // namespace globe::overlays
