// A whole file read into memory with a limit on its size, as text: the one way the programs read a
// text or small binary file they were given (suites, shaders, logs, earlier exports' documents).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/result.hpp"

namespace globe::transport {

// The file's bytes, or an error naming it: no such file, not a regular file, larger than maxBytes
// (all said before reading), then whatever readWholeFile (atomic_file.hpp) finds reading it.
Result<std::string> readFileBounded(const std::filesystem::path& file, std::uintmax_t maxBytes);

}  // namespace globe::transport
