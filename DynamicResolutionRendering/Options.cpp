#include "Options.h"

#include "Json.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace drr {

namespace {
constexpr const char* kFilterNames[] = {"None",          "Point",       "Bilinear",
                                        "Bicubic",       "Noise",       "Noise Offset",
                                        "Temporal AA",   "TAA Noise Offset", "TAA Basic"};
constexpr const char* kFilterOptions[] = {"none",  "point",        "bilinear",
                                          "bicubic", "noise",      "noise-offset",
                                          "taa",   "taa-noise-offset", "taa-basic"};

}  // namespace

const char* FilterName(Filter f) { return kFilterNames[static_cast<int>(f)]; }
const char* FilterOption(Filter f) { return kFilterOptions[static_cast<int>(f)]; }
bool IsTAA(Filter f) {
  return f == Filter::TAA || f == Filter::TAANoiseOffset || f == Filter::TAABasic;
}

std::string Usage() {
  std::ostringstream u;
  u << "Usage: DynamicResolutionRendering [options]\n"
       "Dynamic Resolution Rendering (Vulkan port of the Intel sample).\n\n"
       "  --help                   this text\n"
       "  --headless               no window (default when there is no display)\n"
       "  --width W --height H     back buffer size (default 1280x720, 1..16384)\n"
       "  --frames N               frames to render (default: 300 headless, windowed until closed)\n"
       "  --scene PATH             scene description or model (default: the build's Arena)\n"
       "  --camera N               camera index (default: the scene's default, 1)\n"
       "  --filter NAME            none|point|bilinear|bicubic|noise|noise-offset|taa|\n"
       "                           taa-noise-offset|taa-basic (default taa)\n"
       "  --scale S                resolution scale of both axes, fraction (default 1.0);\n"
       "                           range [0.01, 1], [0.01, 2] with --supersampling; implies\n"
       "                           --control manual unless --control is given\n"
       "  --scale-x S, --scale-y S one axis (turns the aspect-ratio lock off)\n"
       "  --no-dynamic-resolution  render at back-buffer size (full-resolution path)\n"
       "  --supersampling          allow super sampling (2x render targets)\n"
       "  --control MODE           manual|half-vsync|vsync (default vsync)\n"
       "  --law LAW                resolution control law of the vsync modes: article|robust|ue-style\n"
       "                           (default article: the original's S' = S (1 + k (1 - t/T)) on the\n"
       "                           10-frame GPU average; robust and ue-style get per-frame GPU times)\n"
       "  --refresh HZ             controller target rate (default: the monitor's, 60 headless; 1..1000)\n"
       "  --no-vsync               present without waiting for vertical sync\n"
       "  --no-motion-blur         motion blur off (default on)\n"
       "  --symmetric-taa          jitter -0.25/+0.25 px instead of 0/0.5 px\n"
       "  --no-ps-clear            clear with the API instead of a pixel shader\n"
       "  --pause                  start paused\n"
       "  --zoom                   show the zoom box\n"
       "  --show-cameras           draw the camera models\n"
       "  --no-gui                 hide the GUI\n"
       "  --fullscreen             start fullscreen (windowed mode)\n"
       "  --screenshot PATH        PNG/EXR of the back buffer after the last frame\n"
       "  --screenshot-no-gui      the screenshot excludes the GUI\n"
       "  --report PATH            JSON report (options, adapter, GPU times, scales, RT bytes)\n"
       "  --validation             Vulkan core + sync validation; exit code 3 on any message\n"
       "  --stats                  print the scene statistics\n"
       "  --anisotropy N           scene sampler: 0 auto (x16 on GPUs, trilinear on CPU\n"
       "                           rasterisers such as lavapipe), 1 trilinear, 2..16 (default 0)\n"
       "  --time T                 fixed animation time in seconds (reproducible frames)\n"
       "  --fixed-dt DT            animation advances DT seconds per frame (0..10)\n"
       "  --shader-dir DIR         compiled shaders (default: the build's, or DRR_SHADER_DIR)\n"
       "  --debug-marker-outside   test aid: mark the RT outside the viewport\n"
       "  --window-test            test aid: resize to 1x1, minimise, full screen while minimised,\n"
       "                           restore, windowed, full screen and back\n"
       "\n"
       "  --bench [--quick] --out DIR   measure image error against run time instead of running\n"
       "                           the sample (see --bench --help)\n";
  return u.str();
}

ParseStatus ParseCommandLine(int argc, char** argv, Options* options, std::string* message) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  return ParseCommandLine(args, options, message);
}

ParseStatus ParseCommandLine(const std::vector<std::string>& args, Options* o,
                             std::string* message) {
  Options r;
  bool scaleXGiven = false, scaleYGiven = false, scaleBothGiven = false;
  auto fail = [&](const std::string& m) {
    *message = m;
    return ParseStatus::Error;
  };
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    std::string value;
    bool hasInlineValue = false;
    std::string name = a;
    if (auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
      name = a.substr(0, eq);
      value = a.substr(eq + 1);
      hasInlineValue = true;
    }
    auto next = [&](std::string* v) -> bool {
      if (hasInlineValue) {
        *v = value;
        return true;
      }
      if (i + 1 >= args.size()) return false;
      *v = args[++i];
      return true;
    };
    auto number = [&](double lo, double hi, double* out) -> std::string {
      std::string v;
      if (!next(&v)) return "option " + name + " needs a value";
      errno = 0;
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      if (v.empty() || end != v.c_str() + v.size() || errno == ERANGE || !std::isfinite(d))
        return "option " + name + ": '" + v + "' is not a number";
      if (d < lo || d > hi) {
        std::ostringstream m;
        m << "option " << name << ": value " << v << " is out of range [" << lo << ", " << hi
          << "]";
        return m.str();
      }
      *out = d;
      return {};
    };
    auto integer = [&](double lo, double hi, int64_t* out) -> std::string {
      double d = 0;
      std::string e = number(lo, hi, &d);
      if (!e.empty()) return e;
      if (d != std::floor(d)) return "option " + name + ": '" + args[i] + "' is not an integer";
      *out = static_cast<int64_t>(d);
      return {};
    };
    std::string err;
    if (name == "--help" || name == "-h") {
      *message = Usage();
      return ParseStatus::Help;
    } else if (name == "--headless") {
      r.headless = true;
    } else if (name == "--width" || name == "--height") {
      int64_t v = 0;
      err = integer(1, 16384, &v);
      (name == "--width" ? r.width : r.height) = static_cast<uint32_t>(v);
    } else if (name == "--frames") {
      err = integer(0, 1e9, &r.frames);
    } else if (name == "--scene") {
      if (!next(&r.scene) || r.scene.empty()) err = "option --scene needs a path";
    } else if (name == "--shader-dir") {
      if (!next(&r.shaderDir) || r.shaderDir.empty()) err = "option --shader-dir needs a path";
    } else if (name == "--camera") {
      int64_t v = 0;
      err = integer(0, 1000, &v);
      r.camera = static_cast<int>(v);
    } else if (name == "--filter") {
      std::string v;
      if (!next(&v)) {
        err = "option --filter needs a value";
      } else {
        bool found = false;
        for (int f = 0; f < static_cast<int>(Filter::Count); ++f)
          if (v == kFilterOptions[f]) {
            r.filter = static_cast<Filter>(f);
            found = true;
          }
        if (!found)
          err = "option --filter: unknown filter '" + v +
                "' (allowed: none, point, bilinear, bicubic, noise, noise-offset, taa, "
                "taa-noise-offset, taa-basic)";
      }
    } else if (name == "--scale" || name == "--scale-x" || name == "--scale-y") {
      // Range checked below, once --supersampling is known.
      double v = 0;
      err = number(-1e30, 1e30, &v);
      if (name != "--scale-y") r.scaleX = static_cast<float>(v);
      if (name != "--scale-x") r.scaleY = static_cast<float>(v);
      (name == "--scale" ? scaleBothGiven : name == "--scale-x" ? scaleXGiven : scaleYGiven) = true;
      r.scaleGiven = true;
    } else if (name == "--no-dynamic-resolution") {
      r.dynamicResolution = false;
    } else if (name == "--supersampling") {
      r.superSampling = true;
    } else if (name == "--control") {
      std::string v;
      if (!next(&v)) {
        err = "option --control needs a value";
      } else {
        bool found = false;
        for (int m = 0; m < static_cast<int>(ControlMode::Count); ++m)
          if (v == ControlModeOption(static_cast<ControlMode>(m))) {
            r.control = static_cast<ControlMode>(m);
            found = true;
          }
        if (!found) err = "option --control: unknown mode '" + v + "' (allowed: manual, half-vsync, vsync)";
        r.controlGiven = true;
      }
    } else if (name == "--law") {
      std::string v;
      if (!next(&v)) {
        err = "option --law needs a value (allowed: article, robust, ue-style)";
      } else {
        bool found = false;
        for (int l = 0; l < static_cast<int>(ControlLaw::Count); ++l)
          if (v == ControlLawOption(static_cast<ControlLaw>(l))) {
            r.law = static_cast<ControlLaw>(l);
            found = true;
          }
        if (!found) err = "option --law: unknown law '" + v + "' (allowed: article, robust, ue-style)";
      }
    } else if (name == "--refresh") {
      err = number(1, 1000, &r.refresh);
    } else if (name == "--no-vsync") {
      r.vsync = false;
    } else if (name == "--no-motion-blur") {
      r.motionBlur = false;
    } else if (name == "--symmetric-taa") {
      r.symmetricTAA = true;
    } else if (name == "--no-ps-clear") {
      r.psClear = false;
    } else if (name == "--pause") {
      r.pause = true;
    } else if (name == "--zoom") {
      r.zoom = true;
    } else if (name == "--show-cameras") {
      r.showCameras = true;
    } else if (name == "--no-gui") {
      r.gui = false;
    } else if (name == "--fullscreen") {
      r.fullscreen = true;
    } else if (name == "--screenshot") {
      if (!next(&r.screenshot) || r.screenshot.empty()) err = "option --screenshot needs a path";
    } else if (name == "--screenshot-no-gui") {
      r.screenshotNoGui = true;
    } else if (name == "--report") {
      if (!next(&r.report) || r.report.empty()) err = "option --report needs a path";
    } else if (name == "--validation") {
      r.validation = true;
    } else if (name == "--stats") {
      r.stats = true;
    } else if (name == "--anisotropy") {
      double v = 0;
      err = number(0, 16, &v);
      if (err.empty() && v != std::floor(v)) err = "option --anisotropy: expected an integer in [0, 16]";
      r.anisotropy = int(v);
    } else if (name == "--time") {
      err = number(0, 1e7, &r.time);
    } else if (name == "--fixed-dt") {
      err = number(0, 10, &r.fixedDt);
    } else if (name == "--window-test") {
      r.windowTest = true;
    } else if (name == "--debug-marker-outside") {
      r.debugMarkerOutside = true;
    } else {
      err = "unknown option '" + a + "'";
    }
    if (!err.empty()) return fail(err);
  }
  // Scale ranges depend on super sampling.
  const double hi = r.MaxScale();
  auto checkScale = [&](const char* n, float v) -> std::string {
    if (!(v >= 0.01f && v <= hi)) {
      std::ostringstream m;
      m << "option " << n << ": value " << v << " is out of range [0.01, " << hi << "]"
        << (r.superSampling ? "" : " (up to 2 with --supersampling)");
      return m.str();
    }
    return {};
  };
  if (r.scaleGiven) {
    std::string e = checkScale(scaleBothGiven ? "--scale" : "--scale-x", r.scaleX);
    if (e.empty()) e = checkScale(scaleBothGiven ? "--scale" : "--scale-y", r.scaleY);
    if (!e.empty()) return fail(e);
    if (scaleXGiven || scaleYGiven) r.aspectLock = (r.scaleX == r.scaleY);
    if (!r.controlGiven) r.control = ControlMode::Manual;
  }
  *o = r;
  return ParseStatus::Ok;
}

std::string OptionsToJson(const Options& o) {
  std::ostringstream j;
  j << "{\"headless\": " << (o.headless ? "true" : "false") << ", \"width\": " << o.width
    << ", \"height\": " << o.height << ", \"frames\": " << o.EffectiveFrames()
    << ", \"scene\": " << JsonQuote(o.scene) << ", \"camera\": " << o.camera
    << ", \"filter\": \"" << FilterOption(o.filter) << "\", \"scale_x\": " << o.scaleX
    << ", \"scale_y\": " << o.scaleY
    << ", \"dynamic_resolution\": " << (o.dynamicResolution ? "true" : "false")
    << ", \"supersampling\": " << (o.superSampling ? "true" : "false") << ", \"control\": \""
    << ControlModeOption(o.control) << "\", \"law\": \"" << ControlLawOption(o.law)
    << "\", \"refresh\": " << o.refresh
    << ", \"vsync\": " << (o.vsync ? "true" : "false")
    << ", \"motion_blur\": " << (o.motionBlur ? "true" : "false")
    << ", \"symmetric_taa\": " << (o.symmetricTAA ? "true" : "false")
    << ", \"ps_clear\": " << (o.psClear ? "true" : "false")
    << ", \"pause\": " << (o.pause ? "true" : "false")
    << ", \"zoom\": " << (o.zoom ? "true" : "false") << ", \"gui\": " << (o.gui ? "true" : "false")
    << ", \"anisotropy\": " << o.anisotropy
    << ", \"time\": " << o.time << ", \"fixed_dt\": " << o.fixedDt
    << ", \"validation\": " << (o.validation ? "true" : "false") << "}";
  return j.str();
}

}  // namespace drr
