#include "conditioning/condition.hpp"

#include "conditioning/sea_classification.hpp"
#include "terrain/height_block.hpp"

namespace globe::conditioning {

ConditionStats conditionGrid(DemGrid& grid, const CoarserSources* coarser,
                             const ConditionOptions& options) {
  ConditionStats stats;
  stats.samples = grid.samples.size();
  const SeaClassification classes = classifySea(grid, coarser, options.noDataIsWater);
  stats.noDataSamples = classes.noDataSamples;
  stats.seaSamples = classes.seaSamples;
  stats.voidSamples = classes.voidSamples;

  std::vector<uint8_t> isVoid(grid.samples.size(), 0), outside(grid.samples.size(), 0);
  for (size_t i = 0; i < grid.samples.size(); ++i) {
    int16_t& sample = grid.samples[i];
    switch (classes.classes[i]) {
      case SampleClass::Sea:
        if (sample != terrain::kNoDataHeight) {
          sample = terrain::encodeWater(sample);  // a measured depth (ETOPO's bathymetry) kept
        } else if (coarser != nullptr) {
          // No data under coarser water: that water, with its floor where the coarser knows it.
          const auto row = static_cast<int64_t>(i / static_cast<size_t>(grid.cols));
          const auto column = static_cast<int64_t>(i % static_cast<size_t>(grid.cols));
          const auto coarse =
              coarser->sample(grid.longitudeDegrees(column), grid.latitudeDegrees(row));
          sample = coarse && terrain::isWater(*coarse) ? *coarse : terrain::kNoDataHeight;
        }
        break;
      case SampleClass::Void:
        isVoid[i] = 1;
        break;
      case SampleClass::Outside:
        outside[i] = 1;
        break;
      case SampleClass::Land:
        break;
    }
  }
  if (stats.voidSamples > 0) stats.fill = fillVoids(grid, isVoid, coarser, options.fill);
  if (coarser != nullptr && classes.outsideSamples > 0) {
    stats.outsideSamples =
        bendCoarserToFootprint(grid, outside, *coarser, options.bendMarginDegrees);
  }
  return stats;
}

}  // namespace globe::conditioning
