// `globe play`'s log.csv read back as rows of named fields, for the playback tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace globe::app::test {

using LogRow = std::map<std::string, std::string>;

inline std::vector<LogRow> readLog(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> names;
  std::vector<LogRow> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    if (names.empty()) {
      names = fields;
      continue;
    }
    LogRow row;
    for (size_t i = 0; i < names.size() && i < fields.size(); ++i) row[names[i]] = fields[i];
    rows.push_back(row);
  }
  return rows;
}

inline double number(const LogRow& row, const std::string& name) { return std::stod(row.at(name)); }

}  // namespace globe::app::test
