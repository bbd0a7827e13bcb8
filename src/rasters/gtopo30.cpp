// GTOPO30 file pairs: locating .DEM/.HDR, size-checked row access with pread, whole-raster I/O.
#include "rasters/gtopo30.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "core/ascii_case.hpp"
#include "transport/atomic_file.hpp"

namespace globe::rasters {
namespace fs = std::filesystem;
namespace {

constexpr uint64_t kMaxHeaderBytes = 1 << 20;
constexpr char kHostByteOrder = std::endian::native == std::endian::big ? 'M' : 'I';

bool isRegularFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// dir/(base + ext) for the first ext (lower case) that exists, the extension matched in any case.
std::optional<fs::path> findWithExtension(const fs::path& dir, const std::string& base,
                                          std::initializer_list<std::string_view> lowerExts) {
  for (std::string_view ext : lowerExts) {
    for (const std::string& e : {core::asciiUpper(ext), std::string(ext)}) {
      if (fs::path p = dir / (base + e); isRegularFile(p)) return p;
    }
  }
  // Mixed case (".Dem") needs a directory scan.
  std::error_code ec;
  for (std::string_view ext : lowerExts) {
    for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end;
         it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.size() == base.size() + ext.size() && name.compare(0, base.size(), base) == 0 &&
          core::asciiLower(name.substr(base.size())) == ext && isRegularFile(dir / name)) {
        return dir / name;
      }
    }
  }
  return std::nullopt;
}

Error errnoError(const fs::path& path, std::string_view what, int err) {
  return makeError(path.string() + ": " + std::string(what) + ": " +
                   std::generic_category().message(err));
}

}  // namespace

Result<Gtopo30Paths> findGtopo30Files(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    return makeError(path.string() + ": is a directory, not a GTOPO30 .DEM or .HDR file");
  }
  const fs::path dir = path.parent_path();
  const std::string ext = core::asciiLower(path.extension().string());
  const std::string stem = path.stem().string();
  const bool exists = fs::exists(path, ec);

  Gtopo30Paths paths;
  if (ext == ".hdr") {
    if (!exists) return makeError(path.string() + ": missing GTOPO30 header: no such file");
    auto data = findWithExtension(dir, stem, {".dem", ".bil"});
    if (!data) {
      return makeError(path.string() + ": missing GTOPO30 data: no " + stem + ".DEM next to it");
    }
    paths = {*data, path};
  } else if (exists) {
    auto header = findWithExtension(dir, stem, {".hdr"});
    if (!header) {
      return makeError(path.string() + ": missing GTOPO30 header: no " + stem + ".HDR next to it");
    }
    paths = {path, *header};
  } else if (ext == ".dem" || ext == ".bil") {
    return makeError(path.string() + ": missing GTOPO30 data: no such file");
  } else {
    // A stem: append the extensions rather than replacing what looks like one ("N50.v2").
    const std::string base = path.filename().string();
    auto data = findWithExtension(dir, base, {".dem", ".bil"});
    auto header = findWithExtension(dir, base, {".hdr"});
    if (!data) {
      return makeError(path.string() + ": missing GTOPO30 data: no such file, nor " + base +
                       ".DEM");
    }
    if (!header) {
      return makeError(data->string() + ": missing GTOPO30 header: no " + base + ".HDR next to it");
    }
    paths = {*data, *header};
  }
  return paths;
}

Gtopo30File::Gtopo30File(Gtopo30Paths paths, Gtopo30Header header, int fd)
    : paths_(std::move(paths)), header_(std::move(header)), fd_(fd) {}

Gtopo30File::Gtopo30File(Gtopo30File&& other) noexcept
    : paths_(std::move(other.paths_)),
      header_(std::move(other.header_)),
      fd_(std::exchange(other.fd_, -1)) {}

Gtopo30File& Gtopo30File::operator=(Gtopo30File&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    paths_ = std::move(other.paths_);
    header_ = std::move(other.header_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

Gtopo30File::~Gtopo30File() {
  if (fd_ >= 0) ::close(fd_);
}

Result<Gtopo30File> Gtopo30File::open(const fs::path& path) {
  auto paths = findGtopo30Files(path);
  if (!paths) return Error{paths.error()};
  auto text = transport::readWholeFile(paths->header, kMaxHeaderBytes);
  if (!text) return Error{text.error()};
  auto header = parseGtopo30Header(
      std::string_view(reinterpret_cast<const char*>(text->data()), text->size()),
      paths->header.string());
  if (!header) return Error{header.error()};

  const int fd = ::open(paths->data.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errnoError(paths->data, "cannot open", errno);
  Gtopo30File file(std::move(*paths), std::move(*header), fd);  // owns fd from here on
  const fs::path& data = file.paths_.data;
  struct stat st {};
  if (::fstat(fd, &st) != 0) return errnoError(data, "cannot stat", errno);
  if (!S_ISREG(st.st_mode)) return makeError(data.string() + ": not a regular file");

  // The last row may lack the padding after its band (TOTALROWBYTES > BANDROWBYTES).
  const Gtopo30Header& h = file.header_;
  const auto actual = static_cast<int64_t>(st.st_size);
  const int64_t expected = h.rows * h.totalRowBytes;
  const int64_t minimum = expected - (h.totalRowBytes - h.bandRowBytes);
  const std::string described = " bytes, but " + file.paths_.header.filename().string() +
                                " describes " + std::to_string(h.rows) + " rows x " +
                                std::to_string(h.totalRowBytes) +
                                " bytes = " + std::to_string(expected) + " bytes";
  if (actual < minimum) {
    return makeError(data.string() + ": truncated: the file has " + std::to_string(actual) +
                     described);
  }
  if (actual > expected) {
    return makeError(data.string() + ": longer than its header says: the file has " +
                     std::to_string(actual) + described);
  }
  return file;
}

Result<void> Gtopo30File::readSamples(int64_t row, int64_t firstColumn, int64_t count,
                                      int16_t* out) const {
  const Gtopo30Header& h = header_;
  if (row < 0 || row >= h.rows || firstColumn < 0 || count < 0 || firstColumn > h.cols ||
      count > h.cols - firstColumn) {
    return makeError(paths_.data.string() + ": cannot read row " + std::to_string(row) +
                     " columns " + std::to_string(firstColumn) + " + " + std::to_string(count) +
                     " of a " + std::to_string(h.rows) + " x " + std::to_string(h.cols) +
                     " raster");
  }
  auto* bytes = reinterpret_cast<char*>(out);
  size_t left = static_cast<size_t>(count) * 2;
  auto offset = static_cast<off_t>(row * h.totalRowBytes + firstColumn * 2);
  while (left > 0) {
    ssize_t n = ::pread(fd_, bytes, left, offset);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errnoError(paths_.data, "read failed", errno);
    }
    if (n == 0) return makeError(paths_.data.string() + ": unexpected end of file (shrunk?)");
    bytes += n;
    offset += n;
    left -= static_cast<size_t>(n);
  }
  if (h.byteOrder != kHostByteOrder) {
    for (int64_t i = 0; i < count; ++i) {
      out[i] = static_cast<int16_t>(__builtin_bswap16(static_cast<uint16_t>(out[i])));
    }
  }
  return {};
}

int16_t Gtopo30Raster::at(int64_t row, int64_t col) const {
  if (row < 0 || col < 0 || row >= header.rows || col >= header.cols) return kNoDataHeight;
  const auto index = static_cast<size_t>(row * header.cols + col);
  return index < heights.size() ? heights[index] : kNoDataHeight;
}

Result<Gtopo30Raster> readGtopo30(const fs::path& path) {
  auto file = Gtopo30File::open(path);
  if (!file) return Error{file.error()};
  Gtopo30Raster raster;
  raster.header = file->header();
  const int64_t rows = raster.header.rows, cols = raster.header.cols;
  raster.heights.resize(static_cast<size_t>(rows * cols));  // bounded by the file size
  for (int64_t row = 0; row < rows; ++row) {
    auto read = file->readSamples(row, 0, cols, raster.heights.data() + row * cols);
    if (!read) return Error{read.error()};
  }
  return raster;
}

namespace {

constexpr std::string_view kWgs84Prj =
    "Projection    GEOGRAPHIC\n"
    "Datum         WGS84\n"
    "Zunits        METERS\n"
    "Units         DD\n"
    "Spheroid      WGS84\n"
    "Xshift        0.0000000000\n"
    "Yshift        0.0000000000\n"
    "Parameters\n";

// "1 min max mean stddev" over valid samples, as in GTOPO30's .STX (population stddev).
std::string formatStx(const Gtopo30Raster& raster) {
  const int32_t noData = raster.header.noData;
  int64_t n = 0, minimum = 0, maximum = 0;
  double sum = 0;
  for (int16_t h : raster.heights) {
    if (h == noData) continue;
    minimum = n == 0 ? h : std::min<int64_t>(minimum, h);
    maximum = n == 0 ? h : std::max<int64_t>(maximum, h);
    sum += h;
    ++n;
  }
  if (n == 0) minimum = maximum = noData;  // nothing valid: say so with the no-data value
  const double mean = n > 0 ? sum / static_cast<double>(n) : noData;
  double squares = 0;
  for (int16_t h : raster.heights) {
    if (h != noData) squares += (h - mean) * (h - mean);
  }
  const double stddev = n > 0 ? std::sqrt(squares / static_cast<double>(n)) : 0;
  char line[128];
  std::snprintf(line, sizeof line, "1 %lld %lld %.1f %.1f\n", static_cast<long long>(minimum),
                static_cast<long long>(maximum), mean, stddev);
  return line;
}

}  // namespace

Result<void> writeGtopo30(const fs::path& stem, const Gtopo30Raster& raster) {
  const Gtopo30Header& in = raster.header;
  const std::string name = stem.string();
  if (in.rows < 1 || in.cols < 1 || in.rows > 10'000'000 || in.cols > 10'000'000) {
    return makeError(name + ": cannot write a " + std::to_string(in.rows) + " x " +
                     std::to_string(in.cols) + " raster");
  }
  if (raster.heights.size() != static_cast<size_t>(in.rows * in.cols)) {
    return makeError(name + ": raster has " + std::to_string(raster.heights.size()) +
                     " heights but its header says " + std::to_string(in.rows) + " x " +
                     std::to_string(in.cols));
  }
  if (!(in.xDimDegrees > 0) || !(in.yDimDegrees > 0) || !std::isfinite(in.xDimDegrees) ||
      !std::isfinite(in.yDimDegrees) || !std::isfinite(in.ulxMapDegrees) ||
      !std::isfinite(in.ulyMapDegrees)) {
    return makeError(name + ": raster georeference is not finite with positive steps");
  }

  Gtopo30Header h = in;
  h.byteOrder = 'M';
  h.layout = "BIL";
  h.bands = 1;
  h.bitsPerSample = 16;
  h.bandRowBytes = h.totalRowBytes = h.cols * 2;
  h.bandGapBytes = 0;

  std::vector<std::byte> dem(raster.heights.size() * 2);
  for (size_t i = 0; i < raster.heights.size(); ++i) {
    const auto v = static_cast<uint16_t>(raster.heights[i]);
    dem[2 * i] = static_cast<std::byte>(v >> 8);
    dem[2 * i + 1] = static_cast<std::byte>(v & 0xff);
  }

  std::string base = name;
  const std::string ext = core::asciiLower(stem.extension().string());
  if (ext == ".dem" || ext == ".hdr") base.resize(base.size() - ext.size());
  if (auto r = transport::writeFileAtomically(base + ".DEM", std::span<const std::byte>(dem)); !r)
    return r;
  if (auto r = transport::writeFileAtomically(base + ".HDR", formatGtopo30Header(h)); !r) return r;
  if (auto r = transport::writeFileAtomically(base + ".PRJ", kWgs84Prj); !r) return r;
  return transport::writeFileAtomically(base + ".STX", formatStx(raster));
}

}  // namespace globe::rasters
