#include "apps/globe/process_memory.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace globe::app {

std::optional<ProcessMemory> readProcessMemory() {
  std::ifstream status("/proc/self/status");
  if (!status) return std::nullopt;
  ProcessMemory memory;
  bool rss = false, hwm = false;
  for (std::string line; std::getline(status, line);) {
    // "VmRSS:	  123456 kB"
    const bool isRss = line.rfind("VmRSS:", 0) == 0, isHwm = line.rfind("VmHWM:", 0) == 0;
    if (!isRss && !isHwm) continue;
    std::istringstream fields(line.substr(6));
    size_t kibibytes = 0;
    std::string unit;
    if (!(fields >> kibibytes >> unit) || unit != "kB") return std::nullopt;
    (isRss ? memory.residentBytes : memory.peakResidentBytes) = kibibytes * 1024;
    (isRss ? rss : hwm) = true;
  }
  if (!rss || !hwm) return std::nullopt;
  return memory;
}

}  // namespace globe::app
