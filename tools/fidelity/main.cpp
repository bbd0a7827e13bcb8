// globe-source-fidelity: how a pyramid draws each of the inputs it was tiled from, as a Markdown
// table (tools/fidelity/source_fidelity.hpp says what each column measures).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "streaming/tile_store.hpp"
#include "tools/fidelity/input_fidelity.hpp"

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

  auto store = globe::streaming::TileStore::open(pyramid);
  if (!store) {
    std::fprintf(stderr, "globe-source-fidelity: %s\n", store.error().c_str());
    return 1;
  }
  auto measured = globe::fidelity::measureInputs(**store, inputs, noDataIsSea, bandDegrees);
  if (!measured) {
    std::fprintf(stderr, "globe-source-fidelity: %s\n", measured.error().c_str());
    return 1;
  }
  std::printf(
      "| source | level | inside: p95 / max |drawn − source| (m) | 0.1° edge band: p95 / max (m) "
      "| steps across its edge: worst (m) / source p99.9 (m) | over 1.5× the local step | vertices "
      "over no "
      "data drawn as sea over land |\n|---|---|---|---|---|---|---|\n");
  for (const globe::fidelity::InputFidelity& input : *measured) {
    const globe::fidelity::SourceFidelity& f = input.fidelity;
    const std::string sea = f.noDataIsWater ? "its no data is its sea (GTOPO30's ocean mask)"
                                            : std::to_string(f.noDataDrawnAsSeaOverLand) + " of " +
                                                  std::to_string(f.noDataVertices);
    std::printf("| %s | %u | %.1f / %.1f | %.1f / %.1f | %.1f / %.1f | %llu of %llu | %s |\n",
                std::filesystem::path(input.argument).filename().c_str(), f.level,
                f.inside.p95Meters, f.inside.maxMeters, f.edgeBand.p95Meters, f.edgeBand.maxMeters,
                f.worstStepAcrossMeters, f.sourceP999StepMeters,
                static_cast<unsigned long long>(f.stepsOverLocalBound),
                static_cast<unsigned long long>(f.edgePairs), sea.c_str());
  }
  return 0;
}
