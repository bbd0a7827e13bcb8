// globe-source-fidelity: how a pyramid draws each of the inputs it was tiled from, as a Markdown
// table (tools/fidelity/source_fidelity.hpp says what each column measures).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io/tile_store.hpp"
#include "tools/fidelity/source_fidelity.hpp"
#include "tools/tiler/dem_reader.hpp"
#include "tools/tiler/source_set.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Measures how a pyramid draws each of its inputs at the input's finest level",
               "globe-source-fidelity"};
  std::string pyramid;
  std::vector<std::string> inputs;
  double bandDegrees = 0.1;
  app.add_option("PYRAMID", pyramid, "pyramid directory")->required();
  app.add_option("INPUT", inputs, "the inputs it was tiled from, as given to globe-tiler")
      ->required();
  app.add_option("--band", bandDegrees, "width of the edge band, degrees")->capture_default_str();
  bool noDataIsSea = false;
  app.add_flag("--no-data-is-sea", noDataIsSea, "as given to globe-tiler");
  CLI11_PARSE(app, argc, argv);

  auto store = globe::io::TileStore::open(pyramid);
  if (!store) {
    std::fprintf(stderr, "globe-source-fidelity: %s\n", store.error().c_str());
    return 1;
  }
  auto sources = globe::tiler::openSources(
      inputs, {(*store)->manifest().verticesPerSide, {}, {}, noDataIsSea});
  if (!sources) {
    std::fprintf(stderr, "globe-source-fidelity: %s\n", sources.error().c_str());
    return 1;
  }
  std::vector<globe::dem::DemGrid> grids;  // as given, finest first
  for (const globe::tiler::TilerSource& source : *sources) {
    auto grid = globe::tiler::readDemGrid(*source.raster, source.argument);
    if (!grid) {
      std::fprintf(stderr, "globe-source-fidelity: %s\n", grid.error().c_str());
      return 1;
    }
    grids.push_back(std::move(*grid));
  }
  std::printf(
      "| source | level | inside: p95 / max |drawn − source| (m) | 0.1° edge band: p95 / max (m) "
      "| steps across its edge: worst (m) / source p99.9 (m) | over 1.5× the local step | vertices "
      "over no "
      "data drawn as sea over land |\n|---|---|---|---|---|---|---|\n");
  for (size_t i = 0; i < sources->size(); ++i) {
    const globe::tiler::TilerSource& source = (*sources)[i];
    std::vector<const globe::dem::DemGrid*> coarser, peers;
    for (size_t j = 0; j < sources->size(); ++j) {
      if (j == i) continue;
      const double step = (*sources)[j].stepDegrees;
      if (step > source.stepDegrees * (1 + 1e-6)) {
        coarser.push_back(&grids[j]);
      } else if (step >= source.stepDegrees * (1 - 1e-6)) {
        peers.push_back(&grids[j]);
      }
    }
    if (source.grid.wrapsLongitude) continue;  // a whole-globe base has no edge to measure
    auto measured = globe::fidelity::measureSourceFidelity(
        **store, source.finestLevel, grids[i], coarser, peers, source.noDataIsWater, bandDegrees);
    if (!measured) {
      std::fprintf(stderr, "globe-source-fidelity: %s\n", measured.error().c_str());
      return 1;
    }
    const globe::fidelity::SourceFidelity& f = *measured;
    const std::string sea = f.noDataIsWater ? "its no data is its sea (GTOPO30's ocean mask)"
                                            : std::to_string(f.noDataDrawnAsSeaOverLand) + " of " +
                                                  std::to_string(f.noDataVertices);
    std::printf("| %s | %u | %.1f / %.1f | %.1f / %.1f | %.1f / %.1f | %llu of %llu | %s |\n",
                std::filesystem::path(source.argument).filename().c_str(), f.level,
                f.inside.p95Meters, f.inside.maxMeters, f.edgeBand.p95Meters, f.edgeBand.maxMeters,
                f.worstStepAcrossMeters, f.sourceP999StepMeters,
                static_cast<unsigned long long>(f.stepsOverLocalBound),
                static_cast<unsigned long long>(f.edgePairs), sea.c_str());
  }
  return 0;
}
