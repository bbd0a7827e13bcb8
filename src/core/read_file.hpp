// A whole file read into memory with a limit on its size: the one way the programs read a text
// or small binary file they were given (suites, shaders, logs, earlier exports' documents).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/result.hpp"

namespace globe {

// The file's bytes, or an error naming it: not a regular file, larger than maxBytes (checked
// before reading, and again on what was read, for a file that grows meanwhile), or unreadable.
Result<std::string> readFileBounded(const std::filesystem::path& file, std::uintmax_t maxBytes);

}  // namespace globe
