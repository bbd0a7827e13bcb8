// Parsing and formatting of GTOPO30 .HDR text, with strict validation of every size it implies.
#include "rasters/gtopo30_header.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "core/ascii_case.hpp"

namespace globe::rasters {
namespace {

constexpr int64_t kMaxDimension = 10'000'000;
constexpr int64_t kMaxRasterBytes = int64_t{1} << 40;

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
  return s;
}

// KEY -> value (rest of the line); later lines win, as in GDAL's EHdr driver.
std::map<std::string, std::string> splitKeys(std::string_view text) {
  std::map<std::string, std::string> keys;
  while (!text.empty()) {
    size_t end = text.find('\n');
    std::string_view line = trim(text.substr(0, end));
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    if (line.empty() || line.front() == '#') continue;
    size_t split = 0;
    while (split < line.size() && !isSpace(line[split])) ++split;
    keys[core::asciiUpper(line.substr(0, split))] = std::string(trim(line.substr(split)));
  }
  return keys;
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& file) : keys_(splitKeys(text)), file_(file) {}

  bool empty() const { return keys_.empty(); }
  Error error(const std::string& message) const { return makeError(file_ + ": " + message); }
  Error bad(const std::string& key, const std::string& value, const std::string& why) const {
    return error(key + " is " + (value.empty() ? "empty" : value) + "; " + why);
  }
  const std::string* find(const std::string& key) const {
    auto it = keys_.find(key);
    return it == keys_.end() ? nullptr : &it->second;
  }

  // Integer key; `fallback` when absent, error when absent without one.
  Result<int64_t> integer(const std::string& key, std::optional<int64_t> fallback) const {
    const std::string* value = find(key);
    if (!value) {
      if (fallback) return *fallback;
      return error("missing " + key);
    }
    std::string_view digits = *value;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    int64_t parsed = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), parsed);
    if (ec == std::errc::result_out_of_range) return bad(key, *value, "out of range");
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
      return bad(key, *value, "expected an integer");
    }
    return parsed;
  }

  Result<double> number(const std::string& key) const {
    const std::string* value = find(key);
    if (!value) return error("missing " + key);
    std::string_view digits = *value;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double parsed = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), parsed);
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
      return bad(key, *value, "expected a number");
    }
    if (!std::isfinite(parsed)) return bad(key, *value, "must be finite");
    return parsed;
  }

 private:
  std::map<std::string, std::string> keys_;
  const std::string& file_;
};

std::string formatDouble(double value) {
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, end) : std::string("nan");
}

}  // namespace

Result<Gtopo30Header> parseGtopo30Header(std::string_view text,
                                         const std::string& fileNameForMessages) {
  const Parser p(text, fileNameForMessages);
  if (p.empty()) return p.error("header is empty (no KEY VALUE lines)");
  Gtopo30Header h;

  if (const std::string* v = p.find("BYTEORDER")) {
    const std::string order = core::asciiUpper(*v);
    if (order == "M" || order == "MSBFIRST") {
      h.byteOrder = 'M';
    } else if (order == "I" || order == "LSBFIRST") {
      h.byteOrder = 'I';
    } else {
      return p.bad("BYTEORDER", *v, "expected M (big-endian) or I (little-endian)");
    }
  }
  if (const std::string* v = p.find("LAYOUT")) {
    if (core::asciiUpper(*v) != "BIL") return p.bad("LAYOUT", *v, "only BIL is supported");
  }

  auto bands = p.integer("NBANDS", 1);
  if (!bands) return Error{bands.error()};
  if (*bands != 1) {
    return p.bad("NBANDS", std::to_string(*bands), "only single-band GTOPO30 is supported");
  }
  auto bits = p.integer("NBITS", 16);
  if (!bits) return Error{bits.error()};
  if (*bits != 16) {
    return p.bad("NBITS", std::to_string(*bits), "only 16-bit GTOPO30 is supported");
  }
  h.bands = *bands;
  h.bitsPerSample = *bits;

  auto rows = p.integer("NROWS", std::nullopt);
  if (!rows) return Error{rows.error()};
  auto cols = p.integer("NCOLS", std::nullopt);
  if (!cols) return Error{cols.error()};
  const std::string range = "must be between 1 and " + std::to_string(kMaxDimension);
  if (*rows < 1 || *rows > kMaxDimension) return p.bad("NROWS", std::to_string(*rows), range);
  if (*cols < 1 || *cols > kMaxDimension) return p.bad("NCOLS", std::to_string(*cols), range);
  h.rows = *rows;
  h.cols = *cols;

  auto bandRow = p.integer("BANDROWBYTES", h.cols * 2);
  if (!bandRow) return Error{bandRow.error()};
  if (*bandRow != h.cols * 2) {
    return p.bad("BANDROWBYTES", std::to_string(*bandRow),
                 "expected NCOLS*2 = " + std::to_string(h.cols * 2));
  }
  auto totalRow = p.integer("TOTALROWBYTES", h.cols * 2);
  if (!totalRow) return Error{totalRow.error()};
  if (*totalRow < *bandRow) {
    return p.bad("TOTALROWBYTES", std::to_string(*totalRow),
                 "smaller than BANDROWBYTES " + std::to_string(*bandRow));
  }
  // Division, not multiplication, so that absurd values cannot overflow.
  if (*totalRow > kMaxRasterBytes / h.rows) {
    return p.error("NROWS " + std::to_string(h.rows) + " x TOTALROWBYTES " +
                   std::to_string(*totalRow) + " is more than 2^40 bytes");
  }
  auto gap = p.integer("BANDGAPBYTES", 0);
  if (!gap) return Error{gap.error()};
  if (*gap < 0 || *gap > kMaxRasterBytes) {
    return p.bad("BANDGAPBYTES", std::to_string(*gap), "must be between 0 and 2^40");
  }
  // EHdr's leading-offset key: a GTOPO30 reader that ignored it would read shifted samples.
  auto skip = p.integer("SKIPBYTES", 0);
  if (!skip) return Error{skip.error()};
  if (*skip != 0) return p.bad("SKIPBYTES", std::to_string(*skip), "only 0 is supported");
  h.bandRowBytes = *bandRow;
  h.totalRowBytes = *totalRow;
  h.bandGapBytes = *gap;

  if (p.find("NODATA")) {
    auto noData = p.number("NODATA");
    if (!noData) return Error{noData.error()};
    if (*noData != std::trunc(*noData) || *noData < std::numeric_limits<int32_t>::min() ||
        *noData > std::numeric_limits<int32_t>::max()) {
      return p.bad("NODATA", *p.find("NODATA"), "expected a 32-bit integer");
    }
    h.noData = static_cast<int32_t>(*noData);
  }

  for (auto [key, target] : {std::pair{"XDIM", &h.xDimDegrees}, {"YDIM", &h.yDimDegrees}}) {
    auto value = p.number(key);
    if (!value) return Error{value.error()};
    if (*value <= 0) return p.bad(key, *p.find(key), "must be > 0");
    *target = *value;
  }
  for (auto [key, target] : {std::pair{"ULXMAP", &h.ulxMapDegrees}, {"ULYMAP", &h.ulyMapDegrees}}) {
    auto value = p.number(key);
    if (!value) return Error{value.error()};
    *target = *value;
  }
  return h;
}

std::string formatGtopo30Header(const Gtopo30Header& h) {
  std::string out;
  auto line = [&](std::string_view key, const std::string& value) {
    out += key;
    out.append(key.size() < 15 ? 15 - key.size() : 1, ' ');
    out += value;
    out += '\n';
  };
  line("BYTEORDER", std::string(1, h.byteOrder));
  line("LAYOUT", h.layout);
  line("NROWS", std::to_string(h.rows));
  line("NCOLS", std::to_string(h.cols));
  line("NBANDS", std::to_string(h.bands));
  line("NBITS", std::to_string(h.bitsPerSample));
  line("BANDROWBYTES", std::to_string(h.bandRowBytes));
  line("TOTALROWBYTES", std::to_string(h.totalRowBytes));
  line("BANDGAPBYTES", std::to_string(h.bandGapBytes));
  line("NODATA", std::to_string(h.noData));
  line("ULXMAP", formatDouble(h.ulxMapDegrees));
  line("ULYMAP", formatDouble(h.ulyMapDegrees));
  line("XDIM", formatDouble(h.xDimDegrees));
  line("YDIM", formatDouble(h.yDimDegrees));
  // GDAL's EHdr driver reads 16-bit data as unsigned unless NODATA is negative.
  if (h.noData >= 0) line("PIXELTYPE", "SIGNEDINT");
  return out;
}

}  // namespace globe::rasters
