#include "apps/globe-tiler/shard_argument.hpp"

#include <charconv>
#include <string_view>

namespace globe::tiler_app {

Result<ShardSpec> parseShardSpec(const std::string& text) {
  const size_t slash = text.find('/');
  ShardSpec spec;
  auto number = [](std::string_view s, uint32_t& out) {
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), out);
    return error == std::errc() && end == s.data() + s.size() && !s.empty();
  };
  if (slash == std::string::npos || !number(std::string_view(text).substr(0, slash), spec.index) ||
      !number(std::string_view(text).substr(slash + 1), spec.count) || spec.count == 0 ||
      spec.index >= spec.count) {
    return makeError("--shard '" + text + "': expected K/N with 0 <= K < N (e.g. 0/8)");
  }
  return spec;
}

}  // namespace globe::tiler_app
