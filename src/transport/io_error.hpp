// A failed system call on a file as an Error: the path, what was being done, and errno's text.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "core/result.hpp"

namespace globe::transport {

inline Error ioError(const std::filesystem::path& path, std::string_view what, int err) {
  return makeError(path.string() + ": " + std::string(what) + ": " +
                   std::generic_category().message(err));
}

}  // namespace globe::transport
