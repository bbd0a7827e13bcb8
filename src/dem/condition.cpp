#include "dem/condition.hpp"

#include "dem/sea_classification.hpp"
#include "terrain/height_block.hpp"

namespace globe::dem {

ConditionStats conditionGrid(DemGrid& grid, const CoarserSources* coarser,
                             const ConditionOptions& options) {
  ConditionStats stats;
  stats.samples = grid.samples.size();
  const SeaClassification classes = classifySea(grid, coarser);
  stats.noDataSamples = classes.noDataSamples;
  stats.seaSamples = classes.seaSamples;
  stats.voidSamples = classes.voidSamples;

  std::vector<uint8_t> isVoid(grid.samples.size(), 0);
  for (size_t i = 0; i < grid.samples.size(); ++i) {
    int16_t& sample = grid.samples[i];
    switch (classes.classes[i]) {
      case SampleClass::Sea:
        // Sea keeps GTOPO30's no data; a measured depth (ETOPO's bathymetry) is kept with it.
        sample = sample == terrain::kNoDataHeight ? terrain::kNoDataHeight
                                                  : terrain::encodeWater(sample);
        break;
      case SampleClass::Void:
        isVoid[i] = 1;
        break;
      case SampleClass::Land:
        break;
    }
  }
  if (stats.voidSamples > 0) stats.fill = fillVoids(grid, isVoid, coarser, options.fill);
  if (coarser != nullptr && options.blendMarginDegrees > 0) {
    const CoverageTest noOther = [](double, double) { return false; };
    stats.blendedSamples = blendIntoCoarser(
        grid, *coarser, options.sameOrFinerCovers ? options.sameOrFinerCovers : noOther,
        options.blendMarginDegrees);
  }
  return stats;
}

}  // namespace globe::dem
