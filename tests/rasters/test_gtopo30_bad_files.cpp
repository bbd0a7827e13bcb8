// Bad GTOPO30 files: each is refused with a message naming the file and the problem, quickly and
// without allocating what the header claims.
#include <gtest/gtest.h>

#include <chrono>

#include "rasters/gtopo30.hpp"
#include "rasters/raster_source.hpp"
#include "tests/support/test_io_util.hpp"

namespace globe::rasters {
namespace {

using globe::testing::TempDir;

std::string hdr(const std::string& rows = "3", const std::string& cols = "4",
                const std::string& extra = "") {
  return "BYTEORDER M\nLAYOUT BIL\nNROWS " + rows + "\nNCOLS " + cols +
         "\nNBANDS 1\nNBITS 16\nNODATA -9999\nULXMAP 0.25\nULYMAP 1.75\nXDIM 0.5\nYDIM 0.5\n" +
         extra;
}

// Writes T.HDR (unless hdrText is null) and T.DEM (unless demBytes < 0) and returns T.DEM.
std::filesystem::path makePair(const TempDir& dir, const char* hdrText, long demBytes) {
  if (hdrText) globe::testing::writeText(dir / "T.HDR", hdrText);
  if (demBytes >= 0) globe::testing::writeBytes(dir / "T.DEM", static_cast<size_t>(demBytes), '\1');
  return dir / "T.DEM";
}

// Every way in must fail the same way: the whole-raster reader and both source openers.
void expectRejected(const std::filesystem::path& path, const std::vector<std::string>& needles) {
  auto raster = readGtopo30(path);
  ASSERT_FALSE(raster.ok()) << path;
  auto native = openGtopo30Source(path);
  ASSERT_FALSE(native.ok()) << path;
  EXPECT_EQ(native.error(), raster.error());
  auto chosen = openRasterSource(path);
  ASSERT_FALSE(chosen.ok()) << path;
  for (const std::string& needle : needles) {
    EXPECT_NE(raster.error().find(needle), std::string::npos)
        << "'" << needle << "' not in: " << raster.error();
    EXPECT_NE(chosen.error().find(needle), std::string::npos)
        << "'" << needle << "' not in: " << chosen.error();
  }
}

TEST(Gtopo30BadFiles, TruncatedDem) {
  TempDir dir;
  const auto dem = makePair(dir, hdr().c_str(), 23);
  expectRejected(dem, {dem.string() + ": truncated", "has 23 bytes",
                       "T.HDR describes 3 rows x 8 bytes = 24 bytes"});
}

TEST(Gtopo30BadFiles, DemLongerThanHeaderSays) {
  TempDir dir;
  const auto dem = makePair(dir, hdr().c_str(), 25);
  expectRejected(dem,
                 {dem.string() + ": longer than its header says", "has 25 bytes", "= 24 bytes"});
}

TEST(Gtopo30BadFiles, HeaderSizeDisagreesWithFile) {
  TempDir dir;
  const auto dem = makePair(dir, hdr("4", "3").c_str(), 24);  // 4 x 3 fits
  EXPECT_TRUE(readGtopo30(dem).ok());
  makePair(dir, hdr("100", "100").c_str(), -1);
  expectRejected(dem,
                 {dem.string(), "truncated", "has 24 bytes", "100 rows x 200 bytes = 20000 bytes"});
}

TEST(Gtopo30BadFiles, HeaderValuesOutOfSpec) {
  struct Case {
    std::string text, needle;
  };
  const std::vector<Case> cases = {
      {hdr("3", "4", "NBITS 8\n"), "NBITS is 8; only 16-bit GTOPO30 is supported"},
      {hdr("3", "4", "NBITS 32\n"), "NBITS is 32; only 16-bit GTOPO30 is supported"},
      {hdr("3", "4", "BYTEORDER X\n"), "BYTEORDER is X"},
      {hdr("3", "4", "LAYOUT BIP\n"), "LAYOUT is BIP; only BIL is supported"},
      {hdr("-5"), "NROWS is -5; must be between 1 and 10000000"},
      {hdr("0"), "NROWS is 0; must be between 1 and 10000000"},
      {hdr("99999999999", "99999999999"), "NROWS is 99999999999; must be between 1 and 10000000"},
      {hdr("3", "4", "XDIM twelve\n"), "XDIM is twelve; expected a number"},
  };
  for (const Case& c : cases) {
    TempDir dir;
    const auto dem = makePair(dir, c.text.c_str(), 24);
    expectRejected(dem, {(dir / "T.HDR").string() + ": " + c.needle});
  }
}

TEST(Gtopo30BadFiles, HugeClaimsFailFastWithoutAllocating) {
  // Each dimension is legal and the total (1e12 bytes) is under the 2^40 cap, so only the check
  // against the real file size stands between this header and a terabyte allocation.
  TempDir dir;
  const auto dem = makePair(dir, hdr("10000000", "50000").c_str(), 24);
  const auto start = std::chrono::steady_clock::now();
  expectRejected(dem, {"truncated", "has 24 bytes", "10000000 rows x 100000 bytes"});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST(Gtopo30BadFiles, MissingHeader) {
  TempDir dir;
  const auto dem = makePair(dir, nullptr, 24);
  expectRejected(dem, {dem.string() + ": missing GTOPO30 header: no T.HDR"});
  auto stem = readGtopo30(dir / "T");
  ASSERT_FALSE(stem.ok());
  EXPECT_NE(stem.error().find("missing GTOPO30 header"), std::string::npos) << stem.error();
}

TEST(Gtopo30BadFiles, MissingDem) {
  TempDir dir;
  makePair(dir, hdr().c_str(), -1);
  expectRejected(dir / "T.HDR", {(dir / "T.HDR").string() + ": missing GTOPO30 data: no T.DEM"});
  expectRejected(dir / "T.DEM", {(dir / "T.DEM").string() + ": missing GTOPO30 data"});
  expectRejected(dir / "T", {(dir / "T").string() + ": missing GTOPO30 data"});
}

TEST(Gtopo30BadFiles, EmptyOrOversizedHeader) {
  TempDir dir;
  const auto dem = makePair(dir, "", 24);
  expectRejected(dem, {(dir / "T.HDR").string() + ": header is empty"});
  globe::testing::writeText(dir / "T.HDR", hdr() + std::string(2 << 20, ' '));
  expectRejected(dem, {(dir / "T.HDR").string() + ": file is", "more than the 1048576 allowed"});
}

TEST(Gtopo30BadFiles, DirectoryInsteadOfFile) {
  TempDir dir;
  std::filesystem::create_directory(dir / "T.DEM");
  globe::testing::writeText(dir / "T.HDR", hdr());
  auto raster = readGtopo30(dir / "T.DEM");
  ASSERT_FALSE(raster.ok());
  EXPECT_NE(raster.error().find((dir / "T.DEM").string() + ": is a directory"), std::string::npos)
      << raster.error();
  auto source = openGtopo30Source(dir.path());
  ASSERT_FALSE(source.ok());
  EXPECT_NE(source.error().find(dir.path().string() + ": is a directory"), std::string::npos)
      << source.error();
  // Through the .HDR the data "file" is found but is not a regular file.
  auto viaHeader = readGtopo30(dir / "T.HDR");
  ASSERT_FALSE(viaHeader.ok());
  EXPECT_NE(viaHeader.error().find("T.DEM"), std::string::npos) << viaHeader.error();
}

}  // namespace
}  // namespace globe::rasters
