// parseGtopo30Header / formatGtopo30Header: real headers, defaults, round trip, and every
// rejection.
#include "rasters/gtopo30_header.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/support/test_io_util.hpp"

namespace globe::rasters {
namespace {

constexpr const char* kFile = "/data/T.HDR";

std::string header(const std::string& replaceKey = "", const std::string& value = "") {
  const std::vector<std::pair<std::string, std::string>> keys = {
      {"BYTEORDER", "M"},    {"LAYOUT", "BIL"},   {"NROWS", "4"},        {"NCOLS", "3"},
      {"NBANDS", "1"},       {"NBITS", "16"},     {"BANDROWBYTES", "6"}, {"TOTALROWBYTES", "6"},
      {"BANDGAPBYTES", "0"}, {"NODATA", "-9999"}, {"ULXMAP", "10.5"},    {"ULYMAP", "-20.25"},
      {"XDIM", "0.5"},       {"YDIM", "0.25"}};
  std::string text;
  bool replaced = false;
  for (const auto& [k, v] : keys) {
    if (k == replaceKey) {
      replaced = true;
      if (value != "<drop>") text += k + " " + value + "\n";
    } else {
      text += k + " " + v + "\n";
    }
  }
  if (!replaced && !replaceKey.empty()) text += replaceKey + " " + value + "\n";
  return text;
}

TEST(Gtopo30Header, ParsesRealW002N52) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  std::stringstream text;
  text << std::ifstream(dir / "W002N52.HDR").rdbuf();
  auto h = parseGtopo30Header(text.str(), "W002N52.HDR");
  ASSERT_TRUE(h.ok()) << h.error();
  EXPECT_EQ(h->byteOrder, 'M');
  EXPECT_EQ(h->layout, "BIL");
  EXPECT_EQ(h->rows, 240);
  EXPECT_EQ(h->cols, 240);
  EXPECT_EQ(h->bandRowBytes, 480);
  EXPECT_EQ(h->totalRowBytes, 480);
  EXPECT_EQ(h->noData, -9999);
  EXPECT_DOUBLE_EQ(h->ulxMapDegrees, -1.9958333333333333);
  EXPECT_DOUBLE_EQ(h->ulyMapDegrees, 53.99583333333333);
  EXPECT_DOUBLE_EQ(h->xDimDegrees, 1.0 / 120);
}

TEST(Gtopo30Header, CaseInsensitiveKeysUnknownKeysAndDefaults) {
  const std::string text =
      "byteorder i\r\nlayout bil\nPixelType SIGNEDINT\n  nrows   2\nncols 5\n"
      "ulxmap -179.5\nULYMAP 89.5\nxdim 1\nydim 1\nCOMMENT made by some tool\n";
  auto h = parseGtopo30Header(text, kFile);
  ASSERT_TRUE(h.ok()) << h.error();
  EXPECT_EQ(h->byteOrder, 'I');
  EXPECT_EQ(h->rows, 2);
  EXPECT_EQ(h->cols, 5);
  EXPECT_EQ(h->bandRowBytes, 10);
  EXPECT_EQ(h->totalRowBytes, 10);
  EXPECT_EQ(h->noData, -9999);
  EXPECT_EQ(h->bands, 1);
  EXPECT_EQ(h->bitsPerSample, 16);
}

TEST(Gtopo30Header, PaddedRowsAreAccepted) {
  auto h = parseGtopo30Header(header("TOTALROWBYTES", "8"), kFile);
  ASSERT_TRUE(h.ok()) << h.error();
  EXPECT_EQ(h->totalRowBytes, 8);
}

TEST(Gtopo30Header, FormatRoundTripsAndUsesGtopo30KeyOrder) {
  Gtopo30Header h;
  h.rows = 540;
  h.cols = 1080;
  h.bandRowBytes = h.totalRowBytes = 2160;
  h.ulxMapDegrees = -1079.0 / 6;
  h.ulyMapDegrees = 539.0 / 6;
  h.xDimDegrees = h.yDimDegrees = 1.0 / 3;
  const std::string text = formatGtopo30Header(h);
  EXPECT_EQ(text.substr(0, 36), "BYTEORDER      M\nLAYOUT         BIL\n");
  std::vector<std::string> order;
  std::istringstream lines(text);
  for (std::string key, rest; lines >> key && std::getline(lines, rest);) order.push_back(key);
  EXPECT_EQ(order,
            (std::vector<std::string>{"BYTEORDER", "LAYOUT", "NROWS", "NCOLS", "NBANDS", "NBITS",
                                      "BANDROWBYTES", "TOTALROWBYTES", "BANDGAPBYTES", "NODATA",
                                      "ULXMAP", "ULYMAP", "XDIM", "YDIM"}));
  EXPECT_NE(text.find("NODATA         -9999\n"), std::string::npos) << text;
  EXPECT_NE(text.find("NROWS          540\n"), std::string::npos) << text;

  auto back = parseGtopo30Header(text, kFile);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->ulxMapDegrees, h.ulxMapDegrees);  // bit-exact
  EXPECT_EQ(back->ulyMapDegrees, h.ulyMapDegrees);
  EXPECT_EQ(back->xDimDegrees, h.xDimDegrees);
  EXPECT_EQ(back->rows, 540);
  EXPECT_EQ(back->totalRowBytes, 2160);
}

TEST(Gtopo30Header, FormatRoundTripsEveryRealHeader) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  for (const std::string& stem : globe::testing::gtopo30Stems()) {
    std::stringstream text;
    text << std::ifstream(dir / (stem + ".HDR")).rdbuf();
    auto h = parseGtopo30Header(text.str(), stem);
    ASSERT_TRUE(h.ok()) << h.error();
    auto again = parseGtopo30Header(formatGtopo30Header(*h), stem);
    ASSERT_TRUE(again.ok()) << again.error();
    EXPECT_EQ(again->ulxMapDegrees, h->ulxMapDegrees) << stem;
    EXPECT_EQ(again->ulyMapDegrees, h->ulyMapDegrees) << stem;
    EXPECT_EQ(again->xDimDegrees, h->xDimDegrees) << stem;
    EXPECT_EQ(again->yDimDegrees, h->yDimDegrees) << stem;
    EXPECT_EQ(again->rows, h->rows) << stem;
    EXPECT_EQ(again->cols, h->cols) << stem;
  }
}

TEST(Gtopo30Header, NonNegativeNoDataAddsSignedPixelType) {
  Gtopo30Header h;
  h.rows = h.cols = 1;
  h.bandRowBytes = h.totalRowBytes = 2;
  h.xDimDegrees = h.yDimDegrees = 1;
  h.noData = 0;
  const std::string text = formatGtopo30Header(h);
  EXPECT_NE(text.find("PIXELTYPE      SIGNEDINT\n"), std::string::npos) << text;
  EXPECT_TRUE(parseGtopo30Header(text, kFile).ok());
}

struct BadHeader {
  std::string key, value, expected;  // value "<drop>" removes the key
};

// How GoogleTest (and so CTest's test names) shows a case: KEY=value, not the struct's raw bytes,
// which differ from build to build.
void PrintTo(const BadHeader& bad, std::ostream* out) { *out << bad.key << "=" << bad.value; }

class Gtopo30HeaderRejects : public ::testing::TestWithParam<BadHeader> {};

TEST_P(Gtopo30HeaderRejects, WithMessageNamingFileKeyAndProblem) {
  const BadHeader& bad = GetParam();
  auto h = parseGtopo30Header(header(bad.key, bad.value), kFile);
  ASSERT_FALSE(h.ok()) << bad.key << " " << bad.value;
  EXPECT_EQ(h.error().rfind(std::string(kFile) + ": ", 0), 0u) << h.error();
  EXPECT_NE(h.error().find(bad.expected), std::string::npos) << h.error();
}

INSTANTIATE_TEST_SUITE_P(
    Cases, Gtopo30HeaderRejects,
    ::testing::Values(
        BadHeader{"NBITS", "8", "NBITS is 8; only 16-bit GTOPO30 is supported"},
        BadHeader{"NBITS", "32", "NBITS is 32; only 16-bit"},
        BadHeader{"NBANDS", "3", "NBANDS is 3; only single-band"},
        BadHeader{"BYTEORDER", "X", "BYTEORDER is X; expected M"},
        BadHeader{"LAYOUT", "BIP", "LAYOUT is BIP; only BIL"},
        BadHeader{"NROWS", "-5", "NROWS is -5; must be between 1 and 10000000"},
        BadHeader{"NROWS", "0", "NROWS is 0; must be between 1"},
        BadHeader{"NCOLS", "99999999999", "NCOLS is 99999999999; must be between 1"},
        BadHeader{"NROWS", "99999999999999999999999", "NROWS is 99999999999999999999999; out of"},
        BadHeader{"NROWS", "12abc", "NROWS is 12abc; expected an integer"},
        BadHeader{"NROWS", "4.5", "NROWS is 4.5; expected an integer"},
        BadHeader{"NROWS", "", "NROWS is empty; expected an integer"},
        BadHeader{"NROWS", "<drop>", "missing NROWS"},
        BadHeader{"NCOLS", "<drop>", "missing NCOLS"}, BadHeader{"XDIM", "<drop>", "missing XDIM"},
        BadHeader{"YDIM", "<drop>", "missing YDIM"},
        BadHeader{"ULXMAP", "<drop>", "missing ULXMAP"},
        BadHeader{"ULYMAP", "<drop>", "missing ULYMAP"},
        BadHeader{"XDIM", "abc", "XDIM is abc; expected a number"},
        BadHeader{"XDIM", "0", "XDIM is 0; must be > 0"},
        BadHeader{"YDIM", "-0.5", "YDIM is -0.5; must be > 0"},
        BadHeader{"XDIM", "inf", "XDIM is inf; must be finite"},
        BadHeader{"YDIM", "nan", "YDIM is nan; must be finite"},
        BadHeader{"ULYMAP", "1e999", "ULYMAP is 1e999; expected a number"},
        BadHeader{"NODATA", "-9999.5", "NODATA is -9999.5; expected a 32-bit integer"},
        BadHeader{"BANDROWBYTES", "8", "BANDROWBYTES is 8; expected NCOLS*2 = 6"},
        BadHeader{"TOTALROWBYTES", "4", "TOTALROWBYTES is 4; smaller than BANDROWBYTES 6"},
        BadHeader{"BANDGAPBYTES", "-1", "BANDGAPBYTES is -1"},
        BadHeader{"SKIPBYTES", "100", "SKIPBYTES is 100; only 0 is supported"},
        BadHeader{"TOTALROWBYTES", "1000000000000", "more than 2^40 bytes"}));

TEST(Gtopo30Header, HugeButIndividuallyValidSizesAreRejected) {
  const std::string text = "NROWS 10000000\nNCOLS 10000000\nULXMAP 0\nULYMAP 0\nXDIM 1\nYDIM 1\n";
  auto h = parseGtopo30Header(text, kFile);
  ASSERT_FALSE(h.ok());
  EXPECT_NE(h.error().find("NROWS 10000000 x TOTALROWBYTES 20000000 is more than 2^40 bytes"),
            std::string::npos)
      << h.error();
}

TEST(Gtopo30Header, EmptyTextIsAnError) {
  for (const char* text : {"", "\n\n   \n"}) {
    auto h = parseGtopo30Header(text, kFile);
    ASSERT_FALSE(h.ok());
    EXPECT_EQ(h.error(), std::string(kFile) + ": header is empty (no KEY VALUE lines)");
  }
}

}  // namespace
}  // namespace globe::rasters
