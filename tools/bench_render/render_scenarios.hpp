// The measured scenarios of globe-bench-render, run in one process for one llvmpipe thread count:
// steady frames on a complete view, and the frames from a jump until the view is complete.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::bench {

struct ScenarioOptions {
  std::filesystem::path pyramid;
  std::filesystem::path shaderDirectory;  // empty: the default shaders
  int widthPixels = 1280, heightPixels = 720;
  int frames = 50;
  double maximumScreenSpaceErrorPixels = 2.0;  // the viewer's default
};

// One table row. Steady views fill the per-frame fields; the jump fills wall time and frames.
struct ScenarioRow {
  std::string name;
  int frames = 0;
  double medianMs = 0, p90Ms = 0, minMs = 0;  // update + draw + glFinish
  double medianDrawMs = 0;                    // draw + glFinish
  double medianUpdateMs = 0;                  // selection, load polling, uploads
  double medianCpuMs = 0;  // CPU time of every thread (llvmpipe's too): steadier under load
  double wallMs = 0;       // the jump: from the new pose to the complete view
  uint32_t tilesDrawn = 0, drawCalls = 0;
  uint64_t triangles = 0, gpuBytes = 0;
  uint64_t tileLoads = 0;  // loads it took to complete this view (steady rows: the row before)
};

// Creates the OSMesa context (LP_NUM_THREADS must already be set) and runs, in order: the whole
// globe complete from a cold start, its steady frames, the jump to the oblique Fuji view, that
// view's steady frames, and the jump again from a cold cache paced as `globe view` paces it.
Result<std::vector<ScenarioRow>> runScenarios(const ScenarioOptions& options,
                                              std::string& rendererName);

// Tab-separated, one row a line, for the parent process to read back.
std::string formatRow(const ScenarioRow& row);
bool parseRow(const std::string& line, ScenarioRow& row);

}  // namespace globe::bench
