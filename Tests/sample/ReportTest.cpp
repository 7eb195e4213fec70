// The --report JSON file (FrameReport.cpp), read with nlohmann-json: strict
// JSON, the options as given, sizes and bytes consistent with the sample's
// own figures, per-frame records, and where the GUI panel was drawn.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "DynamicResolutionRendering.h"
#include "SampleTestKit.h"

using namespace drr;
using Json = nlohmann::json;

namespace {
std::string OutDir() {
  const char* d = std::getenv("DRR_TEST_OUT");
  std::string dir = std::string(d && *d ? d : "sample_test_out") + "/report";
  std::filesystem::create_directories(dir);
  return dir;
}

// A few frames of the first static camera at a fixed time (testkit's headless options).
Options TinyOptions(uint32_t w, uint32_t h) {
  Options o = testkit::HeadlessOptions(w, h, 1.0);
  o.frames = 3;
  o.camera = 2;  // static camera 1 (0 is First Person, 1 the cinematic camera)
  return o;
}

// Runs the sample to its end with a report; the report parsed (null when it is not JSON).
Json RunWithReport(Options o, const std::string& name) {
  o.report = std::filesystem::absolute(OutDir()).string() + "/" + name + ".json";
  std::filesystem::remove(o.report);
  Sample s;
  if (!testkit::Start(s, o)) return Json();
  EXPECT_EQ(s.Run(), 0);
  testkit::Finish(s);
  std::ifstream f(o.report);
  std::stringstream text;
  text << f.rdbuf();
  Json j = Json::parse(text.str(), nullptr, false);
  return j.is_discarded() ? Json() : j;
}
}  // namespace

namespace {
// Sizes and render-target bytes: the total is the sum of the listed targets,
// each width x height (x slices for an array) x bytes per pixel of its
// format. The zoom box's copy is a row: the back buffer's size and format.
// Returns the sum.
double ExpectTargetBytes(Json& j, const Sample& s) {
  double sum = 0;
  EXPECT_TRUE(j["render_targets"].is_object());
  for (auto& [name, rt] : j["render_targets"].items()) {
    EXPECT_TRUE(rt["bytes"].is_number()) << name;
    sum += rt["bytes"].get<double>();
    Json& size = rt["size"];
    const std::string fmt = rt["format"];
    const int bpp = (fmt == "R8G8B8A8_UNORM" || fmt == "R8G8B8A8_UNORM_SRGB" || fmt == "D32_FLOAT" ||
                     fmt == "R32_TYPELESS" || fmt == "R16G16_FLOAT") ? 4 : 0;
    const double slices = rt.contains("slices") ? rt["slices"].get<double>() : 1.0;
    EXPECT_EQ(rt["bytes"].get<double>(), size[0].get<double>() * size[1].get<double>() * slices * bpp)
        << name << " " << fmt;
  }
  EXPECT_TRUE(j["render_targets"].contains("zoom_box_copy")) << "zoom box copy missing from the list";
  EXPECT_EQ(j["render_targets"]["zoom_box_copy"]["size"], j["back_buffer"]);
  EXPECT_EQ(j["render_targets"]["zoom_box_copy"]["format"], "R8G8B8A8_UNORM_SRGB");
  EXPECT_EQ(j["render_target_bytes"].get<double>(), sum);
  EXPECT_EQ(j["render_target_bytes"].get<double>(), double(s.RenderTargetBytes()));
  // The original allocates every target whatever the mode: colour, velocity,
  // depth and the zoom box's copy at the back buffer's size, 24 bytes a pixel
  // at the dynamic RT's.
  const double backPx = j["back_buffer"][0].get<double>() * j["back_buffer"][1].get<double>();
  const double dynPx = j["dynamic_rt"][0].get<double>() * j["dynamic_rt"][1].get<double>();
  EXPECT_EQ(j["render_target_bytes_original"].get<double>(), backPx * 16 + dynPx * 24);
  return sum;
}

// Frames: finite per-frame GPU times, scales in the law's range; the GPU
// averages are the means over the frames that received a new result.
// Returns the number of new GPU results.
int ExpectFramesAndAverages(Json& j, size_t count) {
  Json& frames = j["frames"];
  EXPECT_EQ(frames.size(), count);
  double gpuSum = 0, sceneSum = 0;
  int gpuN = 0;
  for (Json& fr : frames) {
    for (const char* k : {"frame", "clear", "scene", "postp", "scale"}) {
      EXPECT_TRUE(fr["gpu_ms"][k].is_number()) << k;
      EXPECT_GE(fr["gpu_ms"][k].get<double>(), 0.0) << k;
    }
    EXPECT_GT(fr["cpu_ms"].get<double>(), 0.0);
    for (Json& sc : fr["scale"]) {
      EXPECT_GE(sc.get<double>(), 0.3 - 1e-6);
      EXPECT_LE(sc.get<double>(), 1.0 + 1e-6);
    }
    if (fr["gpu_new"].get<bool>()) {
      EXPECT_GE(fr["gpu_delay_frames"].get<double>(), 1);
      EXPECT_LE(fr["gpu_delay_frames"].get<double>(), 4);
      gpuSum += fr["gpu_ms"]["frame"].get<double>();
      sceneSum += fr["gpu_ms"]["scene"].get<double>();
      ++gpuN;
    }
  }
  if (gpuN == 0) return 0;
  Json& avg = j["averages_ms"];
  for (const char* k : {"cpu_frame", "gpu_frame", "clear", "scene", "postp", "scale"}) {
    EXPECT_TRUE(avg[k].is_number()) << k;
    EXPECT_GT(avg[k].get<double>(), 0.0) << k;
  }
  EXPECT_NEAR(avg["gpu_frame"].get<double>(), gpuSum / gpuN, 1e-6 * gpuSum / gpuN + 1e-6);
  EXPECT_NEAR(avg["scene"].get<double>(), sceneSum / gpuN, 1e-6 * sceneSum / gpuN + 1e-6);
  EXPECT_LE(avg["scene"].get<double>(), avg["gpu_frame"].get<double>());  // the scene is inside the inner frame
  return gpuN;
}
}  // namespace

TEST(SampleReport, JsonIsStrictAndConsistent) {
  Options o = TinyOptions(160, 90);
  o.frames = 12;
  o.filter = Filter::TAA;
  o.control = ControlMode::VSync;
  o.law = ControlLaw::Robust;
  o.refresh = 30;
  o.zoom = true;
  o.gui = true;
  o.report = std::filesystem::absolute(OutDir()).string() + "/report_test.json";
  std::filesystem::remove(o.report);
  Sample s;
  if (!testkit::Start(s, o)) return;
  ASSERT_EQ(s.Run(), 0);
  std::ifstream f(o.report);
  std::stringstream text;
  text << f.rdbuf();
  // Strict JSON: nlohmann-json refuses NaN, infinity and trailing commas.
  Json j = Json::parse(text.str(), nullptr, false);  // not const: a missing key reads as null
  ASSERT_FALSE(j.is_discarded()) << "not JSON: " << text.str().substr(0, 200);
  // Options as given, and what the controller actually used.
  Json& opt = j["options"];
  EXPECT_EQ(opt["width"], 160);
  EXPECT_EQ(opt["height"], 90);
  EXPECT_EQ(opt["frames"], 12);
  EXPECT_EQ(opt["filter"], "taa");
  EXPECT_EQ(opt["control"], "vsync");
  EXPECT_EQ(opt["law"], "robust");
  EXPECT_EQ(opt["headless"], true);
  EXPECT_EQ(opt["zoom"], true);
  EXPECT_EQ(j["control"]["law"], "robust");
  EXPECT_EQ(j["control"]["refresh_hz"], 30);
  EXPECT_NEAR(j["control"]["budget_ms"].get<double>(), 1000.0 / 30.0, 1e-6);
  EXPECT_EQ(j["control"]["law_latency_frames"], s.LawLatencyFrames());
  EXPECT_FALSE(j["adapter"].get<std::string>().empty());
  EXPECT_FALSE(j["driver"].get<std::string>().empty());
  EXPECT_EQ(j["back_buffer"], Json::array({160, 90}));
  const double targetBytes = ExpectTargetBytes(j, s);
  // Passes run: as counted by the sample, one scene pass per frame.
  Json& passes = j["passes_run"];
  EXPECT_EQ(passes.size(), s.PassesRun().size());
  for (const auto& [name, count] : s.PassesRun()) EXPECT_EQ(passes[name], count) << name;
  EXPECT_EQ(passes["Scene"], 12);
  EXPECT_EQ(passes["ResolveTAAFast"], 12);
  EXPECT_EQ(passes["ZoomBox"], 12);
  EXPECT_EQ(j["validation_messages"], 0);
  EXPECT_EQ(j["frames_rendered"], 12);
  const int gpuResults = ExpectFramesAndAverages(j, 12);
  EXPECT_GT(gpuResults, 0) << "no GPU result in 12 frames";
  EXPECT_EQ(j["final_scale"].size(), 2u);
  std::printf("[report] %zu bytes of JSON, %d GPU results, gpu frame avg %.2f ms, RT bytes %.0f\n",
              text.str().size(), gpuResults, j["averages_ms"]["gpu_frame"].get<double>(), targetBytes);
  testkit::Finish(s);
}

// The panel fits the two window sizes a user starts with: its last section's
// header is inside the panel (no scrolling needed) and the panel inside the
// back buffer, with every section collapsed as the panel starts.
TEST(SampleReport, GuiPanelFitsTheWindow) {
  for (const auto& [w, h] : {std::pair{1024u, 768u}, std::pair{1280u, 720u}}) {
    Options o = TinyOptions(w, h);
    o.frames = 2;
    o.gui = true;
    Json j = RunWithReport(o, "gui_" + std::to_string(w) + "x" + std::to_string(h));
    ASSERT_TRUE(j.contains("gui")) << w << "x" << h;
    const Json& panel = j["gui"]["panel"];
    const Json& header = j["gui"]["last_header"];
    std::printf("[gui] %ux%u: panel y %.0f..%.0f, last header '%s' y %.0f..%.0f\n", w, h, panel[1].get<double>(),
                panel[3].get<double>(), j["gui"]["last_header_title"].get<std::string>().c_str(),
                header[1].get<double>(), header[3].get<double>());
    EXPECT_LE(panel[2].get<double>(), double(w));
    EXPECT_LE(panel[3].get<double>(), double(h));
    EXPECT_GE(header[1].get<double>(), panel[1].get<double>());
    EXPECT_LE(header[3].get<double>(), panel[3].get<double>());
    EXPECT_GT(header[3].get<double>(), header[1].get<double>());
  }
}
