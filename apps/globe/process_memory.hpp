// This process's resident memory as Linux reports it (/proc/self/status), for the soak tool.
#pragma once

#include <cstddef>
#include <optional>

namespace globe::app {

struct ProcessMemory {
  size_t residentBytes = 0;      // VmRSS: resident now
  size_t peakResidentBytes = 0;  // VmHWM: the high-water mark since the process started
};

// nullopt where /proc/self/status cannot be read or lacks the fields (not Linux).
std::optional<ProcessMemory> readProcessMemory();

}  // namespace globe::app
