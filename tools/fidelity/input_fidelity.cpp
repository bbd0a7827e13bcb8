#include "tools/fidelity/input_fidelity.hpp"

#include "tools/tiler/dem_reader.hpp"
#include "tools/tiler/source_set.hpp"

namespace globe::fidelity {

Result<std::vector<InputFidelity>> measureInputs(io::TileStore& store,
                                                 const std::vector<std::string>& inputs,
                                                 bool noDataIsSea, double edgeBandDegrees) {
  auto sources =
      tiler::openSources(inputs, {store.manifest().verticesPerSide, {}, {}, noDataIsSea});
  if (!sources) return Error{sources.error()};
  std::vector<dem::DemGrid> grids;  // as given, finest first
  for (const tiler::TilerSource& source : *sources) {
    auto grid = tiler::readDemGrid(*source.raster, source.argument);
    if (!grid) return Error{grid.error()};
    grids.push_back(std::move(*grid));
  }
  std::vector<InputFidelity> measured;
  for (size_t i = 0; i < sources->size(); ++i) {
    const tiler::TilerSource& source = (*sources)[i];
    if (source.grid.wrapsLongitude) continue;  // a whole-globe base has no edge to measure
    std::vector<const dem::DemGrid*> coarser, peers;
    for (size_t j = 0; j < sources->size(); ++j) {
      const double step = (*sources)[j].stepDegrees;
      if (j == i) continue;
      if (step > source.stepDegrees * (1 + 1e-6)) {
        coarser.push_back(&grids[j]);
      } else if (step >= source.stepDegrees * (1 - 1e-6)) {
        peers.push_back(&grids[j]);
      }
    }
    auto f = measureSourceFidelity(store, source.finestLevel, grids[i], coarser, peers,
                                   source.noDataIsWater, edgeBandDegrees);
    if (!f) return Error{f.error()};
    measured.push_back({source.argument, *f});
  }
  return measured;
}

}  // namespace globe::fidelity
