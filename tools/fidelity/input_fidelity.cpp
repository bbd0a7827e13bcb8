#include "tools/fidelity/input_fidelity.hpp"

#include "tiling/dem_reader.hpp"
#include "tiling/source_set.hpp"

namespace globe::fidelity {

Result<std::vector<InputFidelity>> measureInputs(streaming::TileStore& store,
                                                 const std::vector<std::string>& inputs,
                                                 bool noDataIsSea, double edgeBandDegrees) {
  auto sources =
      tiling::openSources(inputs, {store.manifest().verticesPerSide, {}, {}, noDataIsSea});
  if (!sources) return Error{sources.error()};
  std::vector<conditioning::DemGrid> grids;  // as given, finest first
  for (tiling::TilerSource& source : *sources) {
    // openSources closed it once it had the grid: read it whole, then close it again.
    if (auto opened = tiling::openRaster(source); !opened) return Error{opened.error()};
    auto grid = tiling::readDemGrid(*source.raster, source.argument);
    if (!grid) return Error{grid.error()};
    grids.push_back(std::move(*grid));
    source.raster.reset();
  }
  std::vector<InputFidelity> measured;
  for (size_t i = 0; i < sources->size(); ++i) {
    const tiling::TilerSource& source = (*sources)[i];
    if (source.grid.wrapsLongitude) continue;  // a whole-globe base has no edge to measure
    std::vector<const conditioning::DemGrid*> coarser, peers;
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
