// The bench column table: a row written to CSV and read back keeps every
// column; the JSON row puts each column where its pointer says, with null for
// what JSON cannot hold; a file of an older run (fewer columns) still loads.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "bench/BenchColumns.h"

namespace {

std::map<std::string, size_t> Index(const std::vector<std::string>& names) {
  std::map<std::string, size_t> col;
  for (size_t i = 0; i < names.size(); ++i) col[names[i]] = i;
  return col;
}

drr::BenchRow SampleRow() {
  drr::BenchRow r;
  r.view = "cinematic moving x1.00";
  r.filter = "taa fast (motion blur on)";
  r.scale = 0.71;
  r.viewportW = 227.5f;
  r.error.psnr = 31.25;
  r.error.valid = true;
  r.error.mse = 0.00075;
  r.gpuFrame = {1.5, 1.25, 1.75};
  r.gpuSamples = 7;
  r.moving = true;
  r.qualityFrames = 4;
  r.flip = 0.125;
  r.instability = 0.0042;
  r.framePsnr = {31, 31.5};
  return r;
}

TEST(BenchColumns, NamesAndJsonPlacesAreUnique) {
  std::set<std::string> names, places;
  for (const drr::BenchColumn& c : drr::BenchColumns()) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_TRUE(places.insert(c.json).second) << c.json;
  }
  EXPECT_TRUE(names.count("instability_rms"));
  EXPECT_TRUE(names.count("flicker_rms"));
}

TEST(BenchColumns, CsvRoundTripKeepsEveryColumn) {
  const drr::BenchRow r = SampleRow();
  const std::vector<std::string> header = drr::SplitCsvLine(drr::CsvHeader()), fields = drr::SplitCsvLine(drr::CsvLine(r));
  ASSERT_EQ(header.size(), fields.size());
  const drr::BenchRow back = drr::RowFromFields(fields, Index(header));
  EXPECT_EQ(drr::CsvLine(back), drr::CsvLine(r));
  EXPECT_EQ(back.filter, r.filter);
  EXPECT_TRUE(back.moving);
  EXPECT_EQ(back.gpuSamples, 7);
  EXPECT_DOUBLE_EQ(back.gpuFrame.p75, 1.75);
  EXPECT_TRUE(std::isnan(back.ghostFraction));
}

TEST(BenchColumns, JsonRowNestsTimesAndWritesNullForInfinity) {
  drr::BenchRow r = SampleRow();
  r.error.psnr = INFINITY;
  const nlohmann::json j = drr::RowJson(r);
  EXPECT_EQ(j["gpu_ms"]["frame"]["p25"], 1.25);
  EXPECT_EQ(j["viewport"][0], 227.5);
  EXPECT_TRUE(j["psnr_db"].is_null());
  EXPECT_TRUE(j["ghost_fraction"].is_null());
  EXPECT_EQ(j["moving"], true);
  EXPECT_EQ(j["scale"], 0.71);
  EXPECT_EQ(j["per_frame"]["psnr_db"].size(), 2u);
}

TEST(BenchColumns, AnOlderFileWithFewerColumnsLoads) {
  const drr::BenchRow back = drr::RowFromFields({"static 1", "point", "0.5", "1"}, Index({"view", "filter", "scale", "valid"}));
  EXPECT_EQ(back.view, "static 1");
  EXPECT_DOUBLE_EQ(back.scale, 0.5);
  EXPECT_TRUE(back.error.valid);
  EXPECT_TRUE(std::isnan(back.instability));
  EXPECT_EQ(back.qualityFrames, 0);
}

TEST(BenchColumns, NumbersParseAndFormat) {
  EXPECT_EQ(drr::FormatNumber(NAN, 3), "");
  EXPECT_EQ(drr::FormatNumber(-INFINITY, 3), "-inf");
  EXPECT_EQ(drr::FormatNumber(0.71, 3), "0.710");
  EXPECT_TRUE(std::isinf(drr::ParseNumber("inf")));
  EXPECT_TRUE(std::isnan(drr::ParseNumber("1.5x")));
}

}  // namespace
