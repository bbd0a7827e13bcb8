// An owned GDALDatasetH: closed when it goes out of scope.
#pragma once

#include <gdal.h>

#include <memory>

namespace globe::imagery_tiling {

struct GdalDatasetCloser {
  void operator()(void* dataset) const { GDALClose(dataset); }
};
using GdalDataset = std::unique_ptr<void, GdalDatasetCloser>;

}  // namespace globe::imagery_tiling
