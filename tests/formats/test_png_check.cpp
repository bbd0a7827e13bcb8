// PNGs that would make stb_image allocate far more than they hold: a chunk that declares more
// bytes than the file has (fuzzing's 368-byte file declaring a 922 MB IDAT) and a zlib bomb (a
// 16 x 16 image whose data inflates to 64 MiB), refused by name before stb sees them; real PNGs
// (the encoder's) still decode.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "formats/png_check.hpp"

namespace globe::formats {
namespace {

void put32(std::vector<std::byte>& out, uint32_t v) {
  for (const int shift : {24, 16, 8, 0}) out.push_back(static_cast<std::byte>(v >> shift));
}

void chunk(std::vector<std::byte>& png, const char* type, const std::vector<std::byte>& data) {
  put32(png, static_cast<uint32_t>(data.size()));
  std::vector<std::byte> typed(reinterpret_cast<const std::byte*>(type),
                               reinterpret_cast<const std::byte*>(type) + 4);
  typed.insert(typed.end(), data.begin(), data.end());
  png.insert(png.end(), typed.begin(), typed.end());
  put32(png, static_cast<uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(typed.data()),
                                         static_cast<uInt>(typed.size()))));
}

// A 16 x 16 RGBA PNG whose image data is `raw` (filter bytes included), deflated.
std::vector<std::byte> pngOf(const std::vector<unsigned char>& raw) {
  std::vector<std::byte> png;
  for (const int b : {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a}) png.push_back(std::byte(b));
  std::vector<std::byte> header;
  put32(header, 16);
  put32(header, 16);
  for (const int b : {8, 6, 0, 0, 0}) header.push_back(std::byte(b));
  chunk(png, "IHDR", header);
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<std::byte> deflated(size);
  EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(deflated.data()), &size, raw.data(),
                      static_cast<uLong>(raw.size()), 9),
            Z_OK);
  deflated.resize(size);
  chunk(png, "IDAT", deflated);
  chunk(png, "IEND", {});
  return png;
}

TEST(PngCheck, ARightSizedPngDecodesAndABombIsRefused) {
  const std::vector<unsigned char> exact(16 * (16 * 4 + 1), 0);
  auto good = decodeImageRgba(pngOf(exact), "good.png");
  ASSERT_TRUE(good) << good.error();
  EXPECT_EQ(good->widthPixels, 16);
  const std::vector<unsigned char> bomb(64u << 20, 0);  // 64 MiB of zeros: ~64 KB deflated
  const std::vector<std::byte> png = pngOf(bomb);
  EXPECT_LT(png.size(), 200000u);
  auto refused = decodeImageRgba(png, "bomb.png");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("bomb.png: PNG image data inflates to more than the 1040 bytes"),
            std::string::npos)
      << refused.error();
}

TEST(PngCheck, AChunkLongerThanTheFileIsRefusedByItsLength) {
  const std::string path = std::string(GLOBE_SOURCE_DIR) +
                           "/tests/fuzz/corpus/elevation_image/regression-idat-declares-922MB.png";
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  ASSERT_EQ(text.size(), 368u);
  const auto* p = reinterpret_cast<const std::byte*>(text.data());
  auto refused = decodeImageRgba(std::vector<std::byte>(p, p + text.size()), "fuzz.png");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("fuzz.png: PNG chunk declares 922747191 bytes, 323 are left"),
            std::string::npos)
      << refused.error();
  // Cut inside a chunk header: refused too; not a PNG at all: left to the decoders.
  EXPECT_FALSE(checkPngStructure(std::vector<std::byte>(p, p + 40), "cut.png"));
  EXPECT_TRUE(checkPngStructure(std::vector<std::byte>(8, std::byte{0}), "zeros"));
}

}  // namespace
}  // namespace globe::formats
