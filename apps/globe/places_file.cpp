#include "apps/globe/places_file.hpp"

#include <cstdlib>
#include <map>
#include <mutex>
#include <system_error>

namespace globe::app {

std::filesystem::path defaultPlacesFile() {
  if (const char* env = std::getenv("GLOBE_PLACES"); env != nullptr && *env != '\0') return env;
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed =
        exe.parent_path().parent_path() / "share/globe/places.tsv.gz";
    if (std::filesystem::is_regular_file(installed, error)) return installed;
  }
  return GLOBE_SOURCE_PLACES;
}

Result<const places::Gazetteer*> loadPlaces(const std::filesystem::path& file) {
  static std::mutex mutex;
  static std::map<std::filesystem::path, places::Gazetteer> loaded;
  const std::filesystem::path path = file.empty() ? defaultPlacesFile() : file;
  std::lock_guard lock(mutex);
  if (auto it = loaded.find(path); it != loaded.end()) return &it->second;
  auto gazetteer = places::Gazetteer::load(path);
  if (!gazetteer) return Error{gazetteer.error()};
  return &loaded.emplace(path, std::move(*gazetteer)).first->second;
}

}  // namespace globe::app
