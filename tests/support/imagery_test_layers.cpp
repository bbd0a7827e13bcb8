#include "tests/support/imagery_test_layers.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "tests/support/tiler_test_fixture.hpp"

namespace globe::testing {

std::filesystem::path bundledData(const std::string& relativePath) {
  return std::filesystem::path(GLOBE_SOURCE_DIR) / relativePath;
}

const std::filesystem::path& imageryLayer(const std::string& name, const std::string& arguments) {
  static std::map<std::string, std::filesystem::path> layers;
  if (auto it = layers.find(name); it != layers.end()) return it->second;
  const auto dir = freshTempDir("layer-" + name) / "layer";
  const std::string command = std::string(GLOBE_TILER_EXE) + " imagery -q -o " + dir.string() +
                              " " + arguments + " > /dev/null";
  if (std::system(command.c_str()) != 0) ADD_FAILURE() << "failed: " << command;
  return layers.emplace(name, dir).first->second;
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
    const auto out = freshTempDir("layer-coast") / "layer";
    std::string command = std::string(GLOBE_TILER_EXE) + " water-mask -q -o " + out.string();
    for (const char* file :
         {"gshhg-l-land", "gshhg-f-suruga-bay", "gshhg-f-the-wash", "gshhg-f-chesapeake-bay",
          "gshhg-f-gibraltar", "gshhg-f-san-francisco-bay"}) {
      command += " " + bundledData(std::string("data/coast/") + file + ".fgb").string();
    }
    if (std::system((command + " > /dev/null").c_str()) != 0)
      ADD_FAILURE() << "failed: " << command;
    return out;
  }();
  return dir;
}

const std::filesystem::path& zionPyramid() {
  static const std::filesystem::path dir =
      tilePyramid("zion-pyramid", {bundledData("data/dem/ETOPO20.DEM").string(),
                                   bundledData("data/dem/zion-srtm3.tif").string()});
  return dir;
}

}  // namespace globe::testing
