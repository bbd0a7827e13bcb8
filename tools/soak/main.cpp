// globe-soak: `globe play`'s per-frame pipeline (path sampling, the collision controller against
// the rendering tile array, tile selection, the streaming loader under its byte budget) run for
// up to millions of frames over a looped path, without drawing, reporting the camera's drift
// between loops, the process's memory and the loader and cache counters.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/globe/camera_argument.hpp"
#include "apps/globe/stderr_warnings.hpp"
#include "geo/ellipsoid.hpp"
#include "terrain/height_block.hpp"
#include "tools/soak/playback_soak.hpp"
#include "transport/network_settings.hpp"

namespace {

double mebibytes(size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

void print(const globe::soak::SoakCheckpoint& c) {
  std::printf(
      "frames %lld  wall %.1f s (%.3f ms/frame)  drift %.3g m %.3g rad (%lld frames differ)  "
      "VmRSS %.1f MiB  VmHWM %.1f MiB  VmRSS after loop 1 %.1f MiB, max since %.1f MiB  "
      "cache %.2f / %.2f MiB (peak %.2f, %zu blocks, %llu loads, %llu evictions)  "
      "loader: %llu requested %llu completed %llu cancelled  gpu %u tiles %.1f MiB  "
      "collision frames %lld  min clearance %.3f m\n",
      static_cast<long long>(c.frames), c.wallSeconds,
      1000.0 * c.wallSeconds / static_cast<double>(c.frames), c.maximumDriftMeters,
      c.maximumDriftRadians, static_cast<long long>(c.framesDrifted), mebibytes(c.residentBytes),
      mebibytes(c.peakResidentBytes), mebibytes(c.residentAfterFirstLoopBytes),
      mebibytes(c.maximumResidentAfterFirstLoopBytes), mebibytes(c.cache.residentBytes),
      mebibytes(c.cacheBudgetBytes), mebibytes(c.cache.peakResidentBytes), c.cache.entries,
      static_cast<unsigned long long>(c.cache.loads),
      static_cast<unsigned long long>(c.cache.evictions),
      static_cast<unsigned long long>(c.loader.requested),
      static_cast<unsigned long long>(c.loader.completed),
      static_cast<unsigned long long>(c.loader.cancelled), c.gpuTiles,
      mebibytes(static_cast<size_t>(c.gpuBytes)), static_cast<long long>(c.collisionFrames),
      c.minimumClearanceMeters);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "globe-soak: globe play's per-frame step (path, collision controller, tile selection, "
      "streaming under the byte budget) over a looped path for many frames, without drawing "
      "(10^6 drawn frames would take hours on llvmpipe): reports the drift between loops, "
      "VmRSS/VmHWM and the loader and cache counters at 10^4, 10^5, 10^6 frames and the end",
      "globe-soak"};
  globe::soak::SoakOptions options;
  std::string pyramid, path, globeName = "wgs84", fpsText = "30", sizeText = "1280x720",
                             cacheText = "256";
  long long frames = options.frames;
  app.add_option("PYRAMID", pyramid, "pyramid directory made by globe-tiler")->required();
  app.add_option("PATH", path, "camera path (.json or .kml tour), played in a loop")->required();
  app.add_option("--frames", frames, "frames to run")->capture_default_str();
  app.add_option("--fps", fpsText, "frames per second of path time (0..1000]")
      ->capture_default_str();
  app.add_option("--size", sizeText, "WxH the tiles are selected for")->capture_default_str();
  app.add_option("--cache-mib", cacheText,
                 "the loader's block cache budget, MiB (below one view's working set, ~0.5 MiB "
                 "on the demo path, views thrash and the run stops at the view timeout)")
      ->capture_default_str();
  app.add_option("--gpu-tiles", options.scene.gpuTileBudget,
                 "tile meshes counted as resident (bookkept: the soak opens no GL context)")
      ->capture_default_str();
  app.add_option("--globe", globeName, "wgs84 | sphere")->capture_default_str();
  bool seaFloor = false;
  app.add_flag("--sea-floor", seaFloor,
               "the sea floor (bathymetry) is the ground where the pyramid has it, as globe play "
               "--sea-floor; default: the water surface at 0 m");
  CLI11_PARSE(app, argc, argv);

  const auto globeModel = globe::geo::parseGlobeModel(globeName);
  const auto fps = globe::app::parseNumberArgument("--fps", fpsText, 0, 1000, true);
  const auto size = globe::app::parseSizeArgument(sizeText);
  const auto cache = globe::app::parseNumberArgument("--cache-mib", cacheText, 0.01, 1e6);
  if (!globeModel || !fps || !size || !cache || frames < 1 || options.scene.gpuTileBudget < 1) {
    std::fprintf(stderr, "globe-soak: %s\n",
                 !globeModel  ? "--globe must be wgs84 or sphere"
                 : !fps       ? fps.error().c_str()
                 : !size      ? size.error().c_str()
                 : !cache     ? cache.error().c_str()
                 : frames < 1 ? "--frames must be at least 1"
                              : "--gpu-tiles must be at least 1");
    return 2;
  }
  options.pyramid = pyramid;
  options.pathFile = path;
  options.frames = frames;
  options.framesPerSecond = *fps;
  options.widthPixels = size->first;
  options.heightPixels = size->second;
  options.scene.globeModel = *globeModel;
  options.scene.sea =
      seaFloor ? globe::terrain::SeaSurface::SeaFloor : globe::terrain::SeaSurface::Water;
  options.scene.cacheBudgetBytes = static_cast<size_t>(*cache * 1024 * 1024);
  // The scene's warnings (a damaged pack, drawn coarser) as `globe play` prints them; a pyramid's
  // URL is read as `globe play` reads one by default.
  options.scene.warnings = globe::app::stderrWarnings();
  options.scene.network = std::make_shared<globe::transport::Network>(
      globe::transport::NetworkSettings{}, options.scene.warnings);
  options.checkpoints = {10'000, 100'000, 1'000'000};
  const auto report = globe::soak::runSoak(options, print);
  if (!report) {
    std::fprintf(stderr, "globe-soak: %s\n", report.error().c_str());
    return 1;
  }
  std::printf("frames per loop: %lld\n", static_cast<long long>(report->framesPerLoop));
  const globe::soak::SoakCheckpoint& last = report->checkpoints.back();
  return last.framesDrifted == 0 ? 0 : 3;
}
