// The publish tests' points and `globe query` output: lon,lat lines in, lon,lat,level,height
// lines out.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace globe::publish::testing {

struct Point {
  double lon, lat;
};

inline std::filesystem::path writePoints(const std::filesystem::path& path,
                                         const std::vector<Point>& points) {
  std::ofstream out(path);
  out.precision(17);
  for (const Point& p : points) out << p.lon << "," << p.lat << "\n";
  return path;
}

// The heights of lon,lat,level,height lines, in order.
inline std::vector<double> heightsOf(const std::string& output) {
  std::vector<double> heights;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    double lon = 0, lat = 0, h = 0;
    int level = 0;
    if (std::sscanf(line.c_str(), "%lf,%lf,%d,%lf", &lon, &lat, &level, &h) == 4) {
      heights.push_back(h);
    }
  }
  return heights;
}

}  // namespace globe::publish::testing
