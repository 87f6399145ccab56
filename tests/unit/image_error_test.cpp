// Image error figures (core/measures/image_error.h) against hand-computed answers, and the
// error pictures read back as a person's image viewer would.

#include "core/measures/image_error.h"
#include "core/image/rgb_image.h"
#include "core/measures/error_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace probeproxy {
namespace {

TEST(ImageError, ConstantOffsetGivesTheAnalyticPsnr) {
  // Two masked pixels, one unmasked pixel that is wildly off and must not count.
  const std::vector<float> reference = {0.5f, 1.0f, 0.25f, 0.2f, 0.2f, 0.2f, 9.0f, 9.0f, 9.0f};
  std::vector<float> reconstruction = reference;
  for (int i = 0; i < 6; ++i) reconstruction[i] += 0.1f;
  reconstruction[6] = -100.0f;
  const std::vector<std::uint8_t> mask = {1, 1, 0}, miss = {0, 0, 0};
  const ImageErrorFigures e = imageError(reference, reconstruction, mask, miss);
  EXPECT_EQ(e.pixels, 2u);
  EXPECT_FLOAT_EQ(static_cast<float>(e.peak), 1.0f);
  EXPECT_NEAR(e.meanAbsError, 0.1, 1e-6);
  EXPECT_NEAR(e.psnrDb, 20.0, 1e-4);  // 10 log10(1 / 0.01)
  EXPECT_EQ(e.missRate, 0.0);
}

TEST(ImageError, MissCountsAsBlackAndIsReported) {
  const std::vector<float> reference = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f};
  const std::vector<float> reconstruction = reference;
  const std::vector<std::uint8_t> mask = {1, 1}, miss = {0, 1};
  const ImageErrorFigures e = imageError(reference, reconstruction, mask, miss);
  EXPECT_EQ(e.missRate, 0.5);
  EXPECT_NEAR(e.meanAbsError, 0.5, 1e-12);
  EXPECT_NEAR(e.psnrDb, 10.0 * std::log10(2.0), 1e-9);  // MSE = 0.5, peak 1
  EXPECT_TRUE(std::isinf(
      imageError(reference, reconstruction, mask, std::vector<std::uint8_t>{0, 0}).psnrDb));
}

TEST(ImageError, RejectsMismatchedSizesAndAnEmptyMask) {
  const std::vector<float> rgb(6, 0.0f);
  EXPECT_THROW(imageError(rgb, rgb, std::vector<std::uint8_t>{1}, std::vector<std::uint8_t>{0}),
               std::invalid_argument);
  EXPECT_THROW(
      imageError(rgb, rgb, std::vector<std::uint8_t>{0, 0}, std::vector<std::uint8_t>{0, 0}),
      std::invalid_argument);
}

TEST(ErrorImages, MissMaskAndComparisonReadBackWithTheirColours) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "probeproxy_error_images";
  std::filesystem::create_directories(dir);
  const std::vector<std::uint8_t> mask = {1, 1, 0, 1}, miss = {1, 0, 0, 0};
  writeMissMaskPng(dir / "miss.png", 2, 2, mask, miss);
  const RgbImage m = readRgbImage(dir / "miss.png");
  ASSERT_EQ(m.width, 2);
  EXPECT_EQ(m.at(0, 0), glm::vec3(1, 0, 0));  // missed: red
  EXPECT_EQ(m.at(1, 0), glm::vec3(1, 1, 1));  // seen: white
  EXPECT_EQ(m.at(0, 1), glm::vec3(0, 0, 0));  // outside the mask: black
  // The comparison: reference | reconstruction | |error|, each 2 x 2 view enlarged to 256 px.
  const std::vector<float> absError = {0.0f, 0.0f, 0.0f, 10.0f};
  const std::vector<float> reference(12, 2.0f), reconstruction(12, 1.0f);
  writeErrorComparisonPng(dir / "compare.png",
                          {2, 2, reference, reconstruction, absError, mask, miss, 2.0f, 1.0f});
  const RgbImage c = readRgbImage(dir / "compare.png");
  EXPECT_GE(c.width, 3 * 256);
  EXPECT_GE(c.height, 256);
  const auto pixel = [&](int panel, int col, int row) {  // the centre of an enlarged pixel
    return c.at(12 + panel * (256 + 12) + col * 128 + 64, 32 + row * 128 + 64);
  };
  EXPECT_EQ(pixel(0, 0, 0), glm::vec3(1, 1, 1));  // the reference at the peak: white
  // Half the peak, sRGB-encoded (the bytes are read back as they are stored).
  EXPECT_NEAR(pixel(1, 1, 0).x, 1.055f * std::pow(0.5f, 1 / 2.4f) - 0.055f, 1 / 255.0f);
  EXPECT_EQ(pixel(1, 0, 0), glm::vec3(0, 1, 1));  // a miss: cyan
  EXPECT_EQ(pixel(2, 0, 0), glm::vec3(0, 1, 1));
  EXPECT_EQ(pixel(2, 1, 0), glm::vec3(0, 0, 0));      // no error: black
  EXPECT_EQ(pixel(2, 1, 1), glm::vec3(1, 1, 1));      // at or above the scale: white
  EXPECT_EQ(pixel(2, 0, 1), glm::vec3(40 / 255.0f));  // outside the mask: dark grey
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace probeproxy
