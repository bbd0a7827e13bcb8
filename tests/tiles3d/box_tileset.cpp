#include "tests/tiles3d/box_tileset.hpp"

#include <cstring>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>

#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"

namespace globe::tiles3d::testing {
namespace {

void append(std::vector<std::byte>& out, const void* data, size_t size) {
  const auto* p = static_cast<const std::byte*>(data);
  out.insert(out.end(), p, p + size);
}

void appendU32(std::vector<std::byte>& out, uint32_t v) { append(out, &v, 4); }

}  // namespace

std::vector<std::byte> boxGlb(double halfEast, double halfNorth, double height) {
  std::vector<float> positions;
  for (int k = 0; k < 8; ++k) {
    positions.push_back(static_cast<float>(k & 1 ? halfEast : -halfEast));
    positions.push_back(static_cast<float>(k & 2 ? height : 0.0));
    positions.push_back(static_cast<float>(k & 4 ? halfNorth : -halfNorth));
  }
  const std::vector<uint16_t> indices = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                                         2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
  std::vector<std::byte> bin;
  append(bin, positions.data(), positions.size() * 4);
  append(bin, indices.data(), indices.size() * 2);
  while (bin.size() % 4 != 0) bin.push_back(std::byte{0});
  std::ostringstream json;
  json << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
       << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
       << R"("accessors":[{"bufferView":0,"componentType":5126,"count":8,"type":"VEC3","min":[)"
       << -halfEast << ",0," << -halfNorth << "],\"max\":[" << halfEast << "," << height << ","
       << halfNorth << R"(]},{"bufferView":1,"componentType":5123,"count":36,"type":"SCALAR"}],)"
       << R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96},)"
       << R"({"buffer":0,"byteOffset":96,"byteLength":72}],)"
       << R"("buffers":[{"byteLength":)" << bin.size() << "}]}";
  std::string text = json.str();
  while (text.size() % 4 != 0) text += ' ';
  std::vector<std::byte> glb;
  append(glb, "glTF", 4);
  appendU32(glb, 2);
  appendU32(glb, static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  appendU32(glb, static_cast<uint32_t>(text.size()));
  append(glb, "JSON", 4);
  append(glb, text.data(), text.size());
  appendU32(glb, static_cast<uint32_t>(bin.size()));
  append(glb, "BIN\0", 4);
  glb.insert(glb.end(), bin.begin(), bin.end());
  return glb;
}

glm::dmat4 eastNorthUp(double lon, double lat, double height) {
  const geo::Ellipsoid e = geo::Ellipsoid::wgs84();
  const auto at = geo::Cartographic::fromDegrees(lon, lat, height);
  const glm::dvec3 origin = geo::cartographicToEcef(e, at);
  const glm::dvec3 up = geo::geodeticSurfaceNormal(e, at);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), up));
  const glm::dvec3 north = glm::cross(up, east);
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(east, 0), m[1] = glm::dvec4(north, 0), m[2] = glm::dvec4(up, 0);
  m[3] = glm::dvec4(origin, 1);
  return m;
}

std::string transformJson(const glm::dmat4& m) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (int k = 0; k < 16; ++k) out << (k ? "," : "") << m[k / 4][k % 4];
  out << "]";
  return out.str();
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

void writeFile(const std::filesystem::path& path, const std::vector<std::byte>& bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

}  // namespace globe::tiles3d::testing
