#include <gtest/gtest.h>


#include <cmath>
#include <filesystem>

#include "analysis/Plot.h"
#include "imageio/ImageFile.h"

namespace {

TEST(Plot, ParetoFrontKeepsOnlyUndominatedPoints) {
  const std::vector<double> cost = {1.0, 2.0, 3.0, 1.5, 4.0, NAN};
  const std::vector<double> err = {5.0, 2.0, 3.0, 6.0, 1.0, 0.0};
  EXPECT_EQ(drr::ParetoFront(cost, err), (std::vector<size_t>{0, 1, 4}));
}

TEST(Plot, WritesAPngWithTheRequestedSizeAndSomeInk) {
  drr::PlotDesc plot;
  plot.title = "error vs time";
  plot.xLabel = "ms";
  plot.yLabel = "PSNR dB";
  plot.series.push_back({"point", {0.1, 0.2, 0.4}, {20, 25, 31}});
  plot.series.push_back({"bad", {NAN, 0.3}, {1, INFINITY}});  // skipped, no crash
  plot.width = 400;
  plot.height = 300;
  const auto path = std::filesystem::temp_directory_path() / "drr_plot_test.png";
  std::string error;
  ASSERT_TRUE(drr::WritePlotPng(plot, path.string(), &error)) << error;
  drr::ImageFileData img;
  ASSERT_TRUE(drr::ReadImageFile(path.string(), &img, &error)) << error;
  EXPECT_EQ(img.width, 400u);
  EXPECT_EQ(img.height, 300u);
  ASSERT_FALSE(img.isFloat);
  size_t dark = 0;
  for (size_t i = 0; i < img.u8.size(); i += img.channels) dark += img.u8[i] < 128;
  EXPECT_GT(dark, 500u);  // axes, text and the series were drawn
  std::filesystem::remove(path);
}

TEST(Plot, UnwritablePathIsAnError) {
  drr::PlotDesc plot;
  std::string error;
  EXPECT_FALSE(drr::WritePlotPng(plot, "/nonexistent-dir/x.png", &error));
  EXPECT_FALSE(error.empty());
}

}  // namespace

namespace {

TEST(ImageFile, RoundTripsPngAndRejectsGarbage) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto png = (dir / "drr_imagefile_test.png").string();
  const uint8_t pixels[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 7, 8, 9, 10};
  std::string error;
  ASSERT_TRUE(drr::WriteImageFile(png, 2, 2, 4, pixels, &error)) << error;
  drr::ImageFileData img;
  ASSERT_TRUE(drr::ReadImageFile(png, &img, &error)) << error;
  EXPECT_EQ(img.width, 2u);
  EXPECT_EQ(img.channels, 4u);
  EXPECT_EQ(img.u8, std::vector<uint8_t>(pixels, pixels + 16));

  const auto garbage = (dir / "drr_imagefile_garbage.png").string();
  FILE* f = std::fopen(garbage.c_str(), "wb");
  std::fputs("definitely not a png", f);
  std::fclose(f);
  EXPECT_FALSE(drr::ReadImageFile(garbage, &img, &error));
  EXPECT_NE(error.find(garbage), std::string::npos) << error;
  EXPECT_FALSE(drr::ReadImageFile("/nonexistent/file.png", &img, &error));
  EXPECT_NE(error.find("/nonexistent/file.png"), std::string::npos) << error;
  std::filesystem::remove(png);
  std::filesystem::remove(garbage);
}

}  // namespace
