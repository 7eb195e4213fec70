// The sample's coordinator (see DynamicResolutionRendering.h).
#include "DynamicResolutionRendering.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/RecordingThreads.h"
#include "scene/Scene.h"

#ifndef DRR_DEFAULT_SCENE
#define DRR_DEFAULT_SCENE "Media/Arena/scene_description.txt"
#endif

namespace drr {

namespace {
void KeyThunk(void* user, int key, int action, int mods) { static_cast<Sample*>(user)->OnKey(key, action, mods); }
void MouseThunk(void* user, int button, int action, double x, double y) {
  static_cast<Sample*>(user)->OnMouse(button, action, x, y);
}

std::string DefaultScenePath(const std::string& option) {
  if (!option.empty()) return option;
  const char* media = std::getenv("DRR_MEDIA_DIR");
  return media && *media ? std::string(media) + "/Arena/scene_description.txt" : DRR_DEFAULT_SCENE;
}
}  // namespace

Sample::Sample() = default;
Sample::~Sample() { Shutdown(); }

// ---------------------------------------------------------------------------
// Set-up
int Sample::Init(const Options& options, std::string* error) {
  m_Options = options;
  m_Shaders.Open(ShaderLibrary::DefaultSpvDir(options.shaderDir), ShaderLibrary::DefaultSourceDir());
  m_ScenePath = DefaultScenePath(options.scene);
  std::error_code ec;
  if (!std::filesystem::exists(m_ScenePath, ec)) {
    *error = "scene file not found: " + m_ScenePath + (ec ? " (" + ec.message() + ")" : "");
    return 1;
  }
  m_Window.Start(options.headless);
  m_Options.headless = m_Window.Headless();
  if (m_Options.headless && (options.windowTest || options.fullscreen))
    Warn(std::string(options.windowTest ? "--window-test" : "--fullscreen") + " is ignored without a window (--headless)");
  m_Gui.enabled = options.gui;
  // Per-frame records: streamed to a temporary file for the report, else in
  // memory for in-process callers (Run turns them off without a report).
  if (!m_Log.SetRecords(options.report.empty() ? FrameRecords::Memory : FrameRecords::Stream))
    Warn("cannot create a temporary file for the report's frame records: the report lists none");

  const d3dl::DXGI_FORMAT headless =
      options.headlessBgra ? d3dl::DXGI_FORMAT_B8G8R8A8_UNORM_SRGB : d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
  if (!m_Device.Create(options.validation, m_Window, options.width, options.height, headless, error)) return 1;
  if (!m_Profiler.Init(m_Device.Device())) {
    *error = "cannot create the GPU timer queries";
    return 1;
  }
  if (!m_Passes.Init(m_Device.Device(), m_Shaders, error)) return 1;
  if (!LoadScene(error)) return 1;
  if (options.camera >= m_Cameras.Count()) {
    *error = "option --camera: value " + std::to_string(options.camera) + " is out of range [0, " +
             std::to_string(m_Cameras.Count() - 1) + "]";
    return 2;
  }
  m_Cameras.Select(options.camera >= 0 ? options.camera : m_Cameras.Default());
  m_Options.camera = m_Cameras.Current();
  if (!m_Gui.Init(m_Device.Device(), m_Shaders, error)) return 1;
  m_Window.InstallInput(&m_GuiInput, this, KeyThunk, MouseThunk);

  // Resolution control.
  m_Controller = MakeController(m_Options.law, m_LawLatency);
  m_Pacer = FramePacer(m_Options.headless ? options.paceHz : 0.0);
  m_RefreshHz = options.refresh > 0 ? options.refresh : m_Pacer.Enabled() ? options.paceHz : m_Window.RefreshHz(60.0);
  m_DynamicResolution.SetScale(options.scaleX, options.scaleY);
  if (!InitDynamicResolution()) {
    *error = "cannot create the render targets";
    return 1;
  }
  m_DynamicResolution.SetScale(options.scaleX, options.scaleY);
  WarnIfScaleCut(options);
  if (options.fullscreen) m_Window.ToggleFullscreen();
  m_LastFrameTime = std::chrono::steady_clock::now();
  return 0;
}

bool Sample::LoadScene(std::string* error) {
  SceneLoadOptions so;
  so.shaders = &m_Shaders;
  // The original samples the scene with anisotropic x16. llvmpipe's
  // anisotropic filter walks the whole footprint and costs 3-30x at some
  // sizes (Docs/Lavapipe-Performance.md), so CPU rasterisers default to
  // trilinear; --anisotropy N chooses explicitly.
  so.maxAnisotropy = m_Options.anisotropy > 0 ? uint32_t(m_Options.anisotropy) : 16u;
  if (m_Options.anisotropy == 0 && m_Device.Adapter().IsSoftware) {
    so.maxAnisotropy = 1;
    std::printf("%s is a CPU rasteriser: scene sampler trilinear instead of anisotropic x16 "
                "(--anisotropy 16 to force it)\n", m_Device.Adapter().Description);
  }
  std::string sceneError;
  m_Scene = Scene::Load(m_Device.Device(), m_ScenePath, so, &sceneError);
  if (!m_Scene) {
    *error = "cannot load the scene " + m_ScenePath + ": " + sceneError;
    return false;
  }
  m_Cameras.Init(m_Scene.get());
  for (const std::string& w : m_Scene->Warnings()) Warn("scene: " + w);
  return true;
}


// ---------------------------------------------------------------------------
// Render targets
FramePlan Sample::PlanNow() const {
  FrameInputs in;
  in.backBufferW = m_Device.Width();
  in.backBufferH = m_Device.Height();
  in.backBufferFormat = m_Device.Format();
  in.guiDrawn = m_Gui.enabled;
  in.softwareAdapter = m_Device.Adapter().IsSoftware;
  if (m_Scene)
    for (const SceneLight& l : m_Scene->Lights()) in.shadowedLights += l.shadow;
  in.viewport = m_DynamicResolution.GetViewport();
  in.dynamicW = m_DynamicResolution.GetDynamicBufferWidth();
  in.dynamicH = m_DynamicResolution.GetDynamicBufferHeight();
  in.rtScale = glm::vec2(m_DynamicResolution.GetRTScaleX(), m_DynamicResolution.GetRTScaleY());
  in.scaleX = m_DynamicResolution.GetScaleX();
  in.history = m_History.State();
  in.camera = m_Cameras.Pose();
  in.firstPersonEye = m_Cameras.ShadingEye(false);
  in.viewingEye = m_Cameras.ShadingEye(true);
  in.resetVelocity = m_ResetVelocityHistory;
  return PlanFrame(m_Options, in);
}

bool Sample::InitDynamicResolution() {
  ReleaseDynamicResolution();
  const float maxScaling = m_Options.superSampling ? 2.0f : 1.0f;
  m_DynamicResolution.InitializeResolutionParameters(m_Device.Width(), m_Device.Height(), kMaxRTSize, kMaxRTSize,
                                                     maxScaling);
  const bool ok = m_Targets.Allocate(m_Device.Device(), PlanNow().targets, m_DynamicResolution.GetDynamicBufferWidth(),
                                     m_DynamicResolution.GetDynamicBufferHeight());
  if (ok) m_Targets.ZeroContents(m_Device.Context());
  m_History.Reset();
  if (m_Controller) m_Controller->Reset();
  return ok;
}

void Sample::ReleaseDynamicResolution() { m_Targets.Release(); }

// The shadow maps and the zoom box's copy alone are made or freed in place:
// a pass rewrites them whole each frame, so the other targets, the temporal
// history and the controller carry on.
void Sample::UpdateTargets() {
  const RenderTargetPlan plan = PlanNow().targets;
  if (plan == m_Targets.Plan()) return;
  if (!plan.SameButRewrittenEachFrame(m_Targets.Plan())) {
    InitDynamicResolution();
    return;
  }
  m_Targets.Allocate(m_Device.Device(), plan, m_DynamicResolution.GetDynamicBufferWidth(),
                     m_DynamicResolution.GetDynamicBufferHeight());
}

uint64_t Sample::RenderTargetBytes() const { return m_Targets.Bytes(); }

// ---------------------------------------------------------------------------
// Per frame
void Sample::OnFrameMove(double elapsed) {
  // Animation time: fixed (--time / --fixed-dt) or the smoothed real time.
  if (!m_Options.pause) {
    if (m_Options.fixedDt > 0.0) {
      m_AnimationTime = std::max(m_Options.time, 0.0) + double(m_FrameCount) * m_Options.fixedDt;
    } else if (m_Options.time >= 0.0) {
      m_AnimationTime = m_Options.time;
    } else {
      m_DeltaHistory[m_DeltaCount % m_DeltaHistory.size()] = elapsed;
      ++m_DeltaCount;
      const size_t n = std::min<size_t>(m_DeltaCount, m_DeltaHistory.size());
      double sum = 0;
      for (size_t i = 0; i < n; ++i) sum += m_DeltaHistory[i];
      m_AnimationTime += sum / double(n);
    }
  }
  m_Scene->Update(m_AnimationTime);
  // The original moves its first-person camera only while not paused.
  if (!m_Options.pause) m_Cameras.UpdateFirstPerson(m_Window.Handle(), !GuiInput::WantsKeyboard(), elapsed);
}

void Sample::ControlResolution(double innerFrameSeconds, double frameSeconds, double gpuScale) {
  if (m_CostModel) {
    innerFrameSeconds = frameSeconds =
        m_CostModel(m_DynamicResolution.GetScaleX(), m_DynamicResolution.GetScaleY()) / 1000.0;
  }
  FrameTiming timing;
  timing.gpuInnerSeconds = innerFrameSeconds;
  timing.frameSeconds = frameSeconds;
  timing.gpuScale = m_CostModel ? m_DynamicResolution.GetScaleX() : gpuScale;
  m_LawInput = timing;
  ControlTarget target;
  target.budgetSeconds = TargetFrameSeconds(m_RefreshHz, m_Options.control);
  target.minScale = 0.3;
  target.maxScale = m_Options.superSampling ? 2.0 : 1.0;
  const double s = m_Controller->Update(m_DynamicResolution.GetScaleX(), timing, target);
  m_DynamicResolution.SetScale(float(s), float(s));
}

// Which law runs when, on which GPU result (Feed in ResolutionController.h).
void Sample::RunResolutionControl() {
  if (!m_Options.dynamicResolution || m_Options.control == ControlMode::Manual) return;
  const AveragedGPUTimer& timer = m_Profiler.Timers().frame;
  if (FeedFor(m_Options.law) == Feed::Original) {
    // The original: every frame from the first, on the 10-result average of
    // the inner-frame timer (0 until the first average) and 1 / DXUTGetFPS(),
    // a figure up to two seconds old (fix ctrl-frame-period: the last period).
    const bool lastPeriod = m_Options.fixes.Has(Fix::CtrlFramePeriod);
    ControlResolution(timer.AverageMs() / 1000.0, lastPeriod ? m_LastFrameSeconds : m_Fps.FrameSeconds());
  } else if (timer.NewResults() > 0) {
    // Per-result laws: one call per new inner-frame result. A result polled
    // d frames after its Start leaves d - 1 results of the old scale after a
    // change; the robust law is told the largest such count seen.
    const int stale = std::max(0, int(timer.LastDelayFrames()) - 1);
    if (m_Options.law == ControlLaw::Robust && stale > m_LawLatency) {
      m_LawLatency = stale;
      m_Controller = MakeController(m_Options.law, m_LawLatency);
    }
    // The result measured frame m_FrameCount - delay, rendered at that frame's scale.
    ControlResolution(timer.LastMs() / 1000.0, m_LastFrameSeconds, m_Profiler.ScaleOfLastResult(m_FrameCount));
  }
}


void Sample::OnFrameRender(double elapsed) {
  d3dl::DeviceContext* ctx = m_Device.Context();
  UpdateTargets();
  m_Profiler.Poll(ctx);
  RunResolutionControl();
  if (m_Profiler.Timers().scene.NewAverage()) UpdateStats();  // as the original: after the control, when the scene timer completes a block

  const FramePlan plan = PlanNow();
  m_History.Begin(plan);
  PassFrame frame;
  frame.ctx = ctx;
  frame.plan = &plan;
  frame.targets = &m_Targets;
  frame.backBuffer = m_Device.Back();
  frame.scene = ChooseSceneTargets(m_Targets, plan.setup, frame.backBuffer);
  frame.sceneData = m_Scene.get();
  frame.profiler = &m_Profiler;
  frame.zoomCentre[0] = m_ZoomCentre[0];
  frame.zoomCentre[1] = m_ZoomCentre[1];
  const d3dl::VIEWPORT viewport = plan.setup.backBufferViewport;
  frame.gui = [this, viewport, rtv = frame.backBuffer.rtv](d3dl::DeviceContext* c) {
    m_Gui.Render(c, rtv, viewport);
    return m_Gui.Drawn();
  };
  // The zoom box, then the GUI at back-buffer resolution: both inside the
  // inner frame, as in the original (its timer ends after the GUI and the text).
  m_Profiler.Timers().frame.Start(ctx);
  m_Passes.Record(frame, [&](PassStage stage) {
    if (stage == PassStage::Scene) m_ResetVelocityHistory = false;
    if (stage == PassStage::Scale) m_History.Commit();
    if (stage == PassStage::Overlay) BuildGui(elapsed);
    if (!m_Log.Capturing()) return;
    if (stage == PassStage::Scene) {
      m_Log.Queue(m_Device.Device(), ctx, frame.scene.colour, Capture::SceneColor);
      m_Log.Queue(m_Device.Device(), ctx, frame.scene.velocity, Capture::Velocity);
    }
    if (stage == PassStage::Overlay) m_Log.Queue(m_Device.Device(), ctx, frame.backBuffer.texture, Capture::BackBufferNoGui);
  });
  m_Profiler.Timers().frame.Stop(ctx);
  if (m_Log.Capturing()) m_Log.Queue(m_Device.Device(), ctx, frame.backBuffer.texture, Capture::BackBuffer);
  ctx->OMSetRenderTargets(0, nullptr, nullptr);
}

// ---------------------------------------------------------------------------
// Frame loop
bool Sample::RenderFrame() {
  uint32_t fbW = 0, fbH = 0;
  switch (m_Window.BeginFrame(m_FrameCount, m_Options.windowTest, m_Options.width, m_Options.height, &fbW, &fbH)) {
    case AppWindow::Frame::Closed: return false;
    case AppWindow::Frame::Minimised:
      m_Profiler.EndFrame(m_FrameCount, 0.0f);
      m_Log.AddMinimised(m_FrameCount++, m_Window.Fullscreen());  // render nothing, wait for an event
      ++m_MinimisedFrames;
      m_Window.WaitWhileMinimised(m_Options.windowTest);
      return true;
    case AppWindow::Frame::Ready: break;
  }
  if (m_Window.Handle() && (fbW != m_Device.Width() || fbH != m_Device.Height()) && !ResizeSwapChain(fbW, fbH)) {
    std::fprintf(stderr, "resize to %ux%u failed\n", fbW, fbH);
    return false;
  }
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = m_FrameCount == 0 ? 1.0 / 60.0 : std::chrono::duration<double>(now - m_LastFrameTime).count();
  m_LastFrameTime = now;
  if (m_FrameCount > 0) m_LastFrameSeconds = m_Pacer.FrameSeconds(elapsed);  // paced: whole periods, as VSync
  m_Fps.Tick(std::chrono::duration<double>(now.time_since_epoch()).count());  // DXUT: before the frame's callbacks

  m_Log.BeginFrame();
  OnFrameMove(elapsed);
  OnFrameRender(elapsed);
  const d3dl::HRESULT hr = m_Device.SwapChain()->Present(m_Window.Handle() && m_Options.vsync ? 1 : 0, 0);
  m_Pacer.Present();  // --pace-hz: to the next refresh boundary, as VSync
  if (d3dl::FAILED(hr)) {
    std::fprintf(stderr, "Present failed: %s\n", d3dl::HResultName(hr));
    return false;
  }
  m_Log.Resolve(m_Device.Device(), m_Device.Context());
  m_Profiler.EndFrame(m_FrameCount, m_DynamicResolution.GetScaleX());
  m_Log.AddRendered(m_FrameCount++, m_DynamicResolution, m_Options.dynamicResolution, m_Device.Back(),
                    m_Window.Fullscreen(), elapsed, m_Profiler.Timers());
  RunGuiActions();
  return true;
}


int Sample::Run() {
  const int64_t frames = m_Options.EffectiveFrames();
  const bool wantShot = !m_Options.screenshot.empty();
  // The application loop reads no record itself: without a report none is
  // kept, so memory stays flat however long the sample runs.
  if (m_Log.Records() == FrameRecords::Memory) m_Log.SetRecords(FrameRecords::Off);
  while (frames < 0 || m_FrameCount < frames) {
    if (wantShot && frames >= 0 && m_FrameCount == frames - 1) RequestCapture();
    if (!RenderFrame()) break;
  }
  m_Device.Device()->WaitIdle();
  int rc = 0;
  std::string err;
  auto written = [&](bool ok, const char* what, const std::string& path) {
    if (ok) std::printf("%s written: %s\n", what, path.c_str());
    else std::fprintf(stderr, "%s: %s\n", what, err.c_str());
    rc = ok ? rc : 1;
  };
  if (wantShot) {
    // The last frame was skipped (minimised) or the window closed early: capture one more.
    if (CapturedBackBuffer().Empty() && !(m_Window.Handle() && glfwWindowShouldClose(m_Window.Handle()))) {
      RequestCapture();
      RenderFrame();
    }
    written(SaveScreenshot(m_Options.screenshot, m_Options.screenshotNoGui, &err), "screenshot", m_Options.screenshot);
  }
  if (!m_Options.report.empty()) written(WriteReport(m_Options.report, &err), "report", m_Options.report);
  PrintStats();
  const uint64_t messages = ValidationMessages();
  if (messages > 0) std::fprintf(stderr, "validation messages: %llu\n", (unsigned long long)messages);
  if (m_Options.validation && messages > 0) rc = 3;
  return rc;
}

bool Sample::Shutdown() {
  if (m_Device.Device()) m_Device.Device()->WaitIdle();
  if (m_Device.Context()) m_Device.Context()->ClearState();
  m_Log.DropPending();
  m_Scene.reset();
  m_Gui.Release();
  m_Passes.Release();
  m_Profiler.Release();
  ReleaseDynamicResolution();
  const bool clean = m_Device.Release();
  m_Window.Destroy();
  return clean;
}

}  // namespace drr
