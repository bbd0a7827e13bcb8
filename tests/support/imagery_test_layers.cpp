#include "tests/support/imagery_test_layers.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "tests/support/build_paths.hpp"
#include "tests/support/shared_fixture.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::testing {

std::filesystem::path bundledData(const std::string& relativePath) {
  return std::filesystem::path(GLOBE_SOURCE_DIR) / relativePath;
}

namespace {

// Runs `globe-tiler ARGUMENTS -q -o DIR`; a failure is a test failure.
bool runTilerInto(const std::filesystem::path& dir, const std::string& arguments) {
  const std::string command =
      std::string(GLOBE_TILER_EXE) + " " + arguments + " -q -o " + dir.string() + " > /dev/null";
  const bool ok = std::system(command.c_str()) == 0;
  if (!ok) ADD_FAILURE() << "failed: " << command;
  return ok;
}

// A layer made by `globe-tiler ARGUMENTS` once per CTest run (sharedFixture).
std::filesystem::path sharedTilerOutput(const std::string& name, const std::string& arguments) {
  return sharedFixture(name + " " + arguments, [&](const std::filesystem::path& dir) {
    return runTilerInto(dir, arguments);
  });
}

}  // namespace

const std::filesystem::path& imageryLayer(const std::string& name, const std::string& arguments) {
  static std::map<std::string, std::filesystem::path> layers;
  if (auto it = layers.find(name); it != layers.end()) return it->second;
  return layers.emplace(name, sharedTilerOutput("layer-" + name, "imagery " + arguments))
      .first->second;
}

const std::filesystem::path& blueMarbleLayer() {
  return imageryLayer(
      "blue-marble",
      "--bounds -180,-90,180,90 " +
          bundledData("data/imagery/world.topo.bathy.200412.3x5400x2700.jpg").string());
}

const std::filesystem::path& zionLayer() {
  return imageryLayer("zion", bundledData("data/imagery/zion-landsat8-rgb.tif").string());
}

const std::filesystem::path& coastMask() {
  static const std::filesystem::path dir = [] {
    std::string arguments = "water-mask";
    for (const char* file :
         {"gshhg-l-land", "gshhg-f-suruga-bay", "gshhg-f-the-wash", "gshhg-f-chesapeake-bay",
          "gshhg-f-gibraltar", "gshhg-f-san-francisco-bay"}) {
      arguments += " " + bundledData(std::string("data/coast/") + file + ".fgb").string();
    }
    return sharedTilerOutput("layer-coast", arguments);
  }();
  return dir;
}

const std::filesystem::path& zionPyramid() {
  static const std::filesystem::path dir =
      sharedPyramid("zion-pyramid", {bundledData("data/dem/ETOPO20.DEM").string(),
                                     bundledData("data/dem/zion-srtm3.tif").string()});
  return dir;
}

}  // namespace globe::testing
