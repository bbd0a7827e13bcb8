#include "tests/support/avif_encoder.hpp"

#include <avif/avif.h>

#include <memory>

namespace globe::testing {
namespace {

struct ImageDeleter {
  void operator()(avifImage* image) const { avifImageDestroy(image); }
};
struct EncoderDeleter {
  void operator()(avifEncoder* encoder) const { avifEncoderDestroy(encoder); }
};

}  // namespace

std::vector<std::byte> encodeAvifLossless(const formats::ImageRgba& image) {
  std::unique_ptr<avifImage, ImageDeleter> yuv(
      avifImageCreate(static_cast<uint32_t>(image.widthPixels),
                      static_cast<uint32_t>(image.heightPixels), 8, AVIF_PIXEL_FORMAT_YUV444));
  if (!yuv) return {};
  yuv->matrixCoefficients = AVIF_MATRIX_COEFFICIENTS_IDENTITY;  // RGB stored as is: lossless
  yuv->yuvRange = AVIF_RANGE_FULL;
  avifRGBImage rgb;
  avifRGBImageSetDefaults(&rgb, yuv.get());
  rgb.format = AVIF_RGB_FORMAT_RGBA;
  rgb.depth = 8;
  rgb.pixels = const_cast<uint8_t*>(image.pixels.data());  // read only: RGB to YUV
  rgb.rowBytes = static_cast<uint32_t>(image.widthPixels) * 4;
  if (avifImageRGBToYUV(yuv.get(), &rgb) != AVIF_RESULT_OK) return {};
  std::unique_ptr<avifEncoder, EncoderDeleter> encoder(avifEncoderCreate());
  if (!encoder) return {};
  encoder->minQuantizer = encoder->maxQuantizer = AVIF_QUANTIZER_LOSSLESS;
  encoder->minQuantizerAlpha = encoder->maxQuantizerAlpha = AVIF_QUANTIZER_LOSSLESS;
  encoder->speed = AVIF_SPEED_FASTEST;
  encoder->maxThreads = 1;
  avifRWData output = AVIF_DATA_EMPTY;
  if (avifEncoderWrite(encoder.get(), yuv.get(), &output) != AVIF_RESULT_OK) {
    avifRWDataFree(&output);
    return {};
  }
  const auto* bytes = reinterpret_cast<const std::byte*>(output.data);
  std::vector<std::byte> avif(bytes, bytes + output.size);
  avifRWDataFree(&output);
  return avif;
}

}  // namespace globe::testing
