#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>

#include "analysis/Plot.h"

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
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in);
  const auto& spec = in->spec();
  EXPECT_EQ(spec.width, 400);
  EXPECT_EQ(spec.height, 300);
  std::vector<uint8_t> px(size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, px.data()));
  size_t dark = 0;
  for (size_t i = 0; i < px.size(); i += spec.nchannels) dark += px[i] < 128;
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
