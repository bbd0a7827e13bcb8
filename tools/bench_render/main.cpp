// globe-bench-render: headless (OSMesa, llvmpipe) frame times of the viewer at 1280x720 on the
// bundled pyramid, per llvmpipe thread count (a table printer, not a timed test).
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "render_scenarios.hpp"
#include "shader_variants.hpp"
#include "tests/support/build_paths.hpp"
#include "tiling/tiler.hpp"

namespace {

using namespace globe;

std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The 1-minute load average: frame times are wall clock, on cores other work may share.
std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string first;
  in >> first;
  return first.empty() ? "?" : first;
}

int runChild(const bench::ScenarioOptions& options) {
  std::string rendererName;
  auto rows = bench::runScenarios(options, rendererName);
  if (!rows) {
    std::fprintf(stderr, "globe-bench-render: %s\n", rows.error().c_str());
    return 1;
  }
  std::printf("renderer\t%s\n", rendererName.c_str());
  for (const auto& row : *rows) std::printf("row\t%s\n", bench::formatRow(row).c_str());
  return 0;
}

struct ChildResult {
  std::string rendererName;
  std::vector<bench::ScenarioRow> rows;
};

// Runs this program again with LP_NUM_THREADS set: llvmpipe reads it once per process.
Result<ChildResult> runInChild(const std::string& self, const std::string& arguments,
                               const std::string& threads) {
  const std::string command =
      (threads.empty() ? std::string() : "LP_NUM_THREADS=" + shellQuote(threads) + " ") +
      shellQuote(self) + " --child " + arguments;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return makeError("cannot run " + command);
  ChildResult result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) {
    std::string line = buffer.data();
    if (!line.empty() && line.back() == '\n') line.pop_back();
    if (line.rfind("renderer\t", 0) == 0) result.rendererName = line.substr(9);
    bench::ScenarioRow row;
    if (line.rfind("row\t", 0) == 0 && bench::parseRow(line.substr(4), row)) {
      result.rows.push_back(row);
    }
  }
  const int status = ::pclose(pipe);
  if (status != 0) return makeError("the run with LP_NUM_THREADS=" + threads + " failed");
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Frame times of the terrain renderer, headless at 1280x720, on a pyramid."};
  std::string pyramid, threadList = "2,1", sizeText = "1280x720";
  int frames = 50;
  bool child = false, noFragDepth = false;
  std::string shaderDirectory;
  bench::ScenarioOptions options;
  app.add_option("--pyramid", pyramid,
                 "pyramid directory (default: tile the bundled data/dem into a temp dir)");
  app.add_option("--frames", frames, "frames timed per steady view")->capture_default_str();
  app.add_option("--size", sizeText, "WxH pixels")->capture_default_str();
  app.add_option("--sse", options.maximumScreenSpaceErrorPixels,
                 "maximum screen-space error in pixels (a what-if: the viewer uses 2)")
      ->capture_default_str();
  app.add_option("--lp-threads", threadList, "llvmpipe thread counts to compare, comma-separated")
      ->capture_default_str();
  app.add_flag("--no-frag-depth", noFragDepth,
               "also time shaders without the gl_FragDepth write (wrong image; its cost)");
  app.add_flag("--child", child, "internal: run the scenarios here, print rows")->group("");
  app.add_option("--shader-dir", shaderDirectory, "internal: shader directory")->group("");
  CLI11_PARSE(app, argc, argv);

  if (std::sscanf(sizeText.c_str(), "%dx%d", &options.widthPixels, &options.heightPixels) != 2) {
    std::fprintf(stderr, "globe-bench-render: --size must be WxH\n");
    return 2;
  }
  options.frames = frames;
  options.shaderDirectory = shaderDirectory;
  if (child) {
    options.pyramid = pyramid;
    return runChild(options);
  }

  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("globe-bench-render-" + std::to_string(::getpid()));
  std::filesystem::remove_all(scratch);
  if (pyramid.empty()) {
    const std::string dem = std::string(GLOBE_SOURCE_DIR) + "/data/dem/";
    tiling::TilerOptions tilerOptions;
    tilerOptions.inputs = {dem + "ETOPO20.DEM", dem + "W002N52.DEM", dem + "E138N35_FUJI.DEM"};
    tilerOptions.outputDir = scratch / "pyramid";
    if (auto report = tiling::runTiler(tilerOptions); !report) {
      std::fprintf(stderr, "globe-bench-render: %s\n", report.error().c_str());
      return 1;
    }
    pyramid = tilerOptions.outputDir.string();
  }

  struct Variant {
    std::string label, shaderArgument;
  };
  std::vector<Variant> variants{{"", ""}};
  if (noFragDepth) {
    auto directory = bench::shadersWithoutFragDepth(scratch);
    if (!directory) {
      std::fprintf(stderr, "globe-bench-render: %s\n", directory.error().c_str());
      return 1;
    }
    variants.push_back({" (no gl_FragDepth)", " --shader-dir " + shellQuote(directory->string())});
  }
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::string common = "--pyramid " + shellQuote(pyramid) + " --frames " +
                             std::to_string(frames) + " --size " + shellQuote(sizeText) +
                             " --sse " + std::to_string(options.maximumScreenSpaceErrorPixels);

  std::printf(
      "| LP threads | scenario | frames | ms/frame median | p90 | min | draw+glFinish median | "
      "update median | CPU ms/frame median | wall ms | tiles drawn | draw calls | triangles | tile "
      "loads | "
      "GPU MiB |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  const std::string loadBefore = loadAverage();
  std::string rendererName;
  int status = 0;
  std::stringstream threads(threadList);
  for (std::string count; std::getline(threads, count, ',');) {
    for (const Variant& variant : variants) {
      auto result = runInChild(self, common + variant.shaderArgument, count);
      if (!result) {
        std::fprintf(stderr, "globe-bench-render: %s\n", result.error().c_str());
        status = 1;
        continue;
      }
      rendererName = result->rendererName;
      for (const auto& r : result->rows) {
        const bool steady = r.wallMs == 0;
        char cells[512];
        if (steady) {
          std::snprintf(cells, sizeof cells, "%d | %.1f | %.1f | %.1f | %.1f | %.2f | %.1f | – ",
                        r.frames, r.medianMs, r.p90Ms, r.minMs, r.medianDrawMs, r.medianUpdateMs,
                        r.medianCpuMs);
        } else {
          std::snprintf(cells, sizeof cells, "%d | – | – | – | – | – | – | %.0f", r.frames,
                        r.wallMs);
        }
        std::printf("| %s | %s%s | %s | %u | %u | %llu | %llu | %.1f |\n", count.c_str(),
                    r.name.c_str(), variant.label.c_str(), cells, r.tilesDrawn, r.drawCalls,
                    static_cast<unsigned long long>(r.triangles),
                    static_cast<unsigned long long>(r.tileLoads),
                    static_cast<double>(r.gpuBytes) / (1 << 20));
      }
      std::fflush(stdout);
    }
  }
  std::printf("\n%dx%d, renderer: %s, %u cores, load average %s before, %s after; pyramid: %s\n",
              options.widthPixels, options.heightPixels, rendererName.c_str(),
              std::thread::hardware_concurrency(), loadBefore.c_str(), loadAverage().c_str(),
              pyramid.c_str());
  std::filesystem::remove_all(scratch);
  return status;
}
