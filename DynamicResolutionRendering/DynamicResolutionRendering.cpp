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

#include "scene/Scene.h"

#ifndef DRR_DEFAULT_SCENE
#define DRR_DEFAULT_SCENE "Media/Arena/scene_description.txt"
#endif

namespace drr {

namespace {
constexpr float kClearColor[4] = {0.0f, 0.1f, 0.1f, 1.0f};
constexpr uint32_t kMaxRTSize = 8192;  // as the original

void LogToStderr(d3dl::LogLevel level, const char* message, void*) {
  const char* tag = level == d3dl::LogLevel::Validation ? "validation"
                    : level == d3dl::LogLevel::Error    ? "error"
                    : level == d3dl::LogLevel::Warning  ? "warning"
                                                        : "info";
  if (level != d3dl::LogLevel::Info) std::fprintf(stderr, "[d3dl %s] %s\n", tag, message);
}

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
  m_Gui.show = options.gui;

  if (!CreateDeviceAndSwapChain(error)) return 1;
  if (!m_Passes.Init(m_Device.Get(), m_Shaders, error)) return 1;
  if (!LoadScene(error)) return 1;
  if (options.camera >= m_Cameras.Count()) {
    *error = "option --camera: value " + std::to_string(options.camera) + " is out of range [0, " +
             std::to_string(m_Cameras.Count() - 1) + "]";
    return 2;
  }
  m_Cameras.Select(options.camera >= 0 ? options.camera : m_Scene->DefaultCamera());
  m_Options.camera = m_Cameras.Current();
  if (!m_Gui.Init(m_Device.Get(), m_Shaders, error)) return 1;
  m_Window.InstallInput(&m_GuiInput, this, KeyThunk, MouseThunk);

  // Resolution control.
  m_Controller = MakeController(m_Options.law, m_LawLatency);
  m_RefreshHz = options.refresh > 0 ? options.refresh : m_Window.RefreshHz(60.0);
  m_DynamicResolution.SetScale(options.scaleX, options.scaleY);
  if (!InitDynamicResolution()) {
    *error = "cannot create the render targets";
    return 1;
  }
  m_DynamicResolution.SetScale(options.scaleX, options.scaleY);
  if (options.fullscreen) m_Window.ToggleFullscreen();
  m_LastFrameTime = std::chrono::steady_clock::now();
  return 0;
}

bool Sample::CreateDeviceAndSwapChain(std::string* error) {
  d3dl::DEVICE_CREATE_DESC dd;
  dd.Validation = m_Options.validation ? d3dl::ValidationMode::CoreAndSync : d3dl::ValidationMode::FromEnvironment;
  dd.Log = LogToStderr;
  dd.EnableWindowSurfaces = !m_Window.Headless();
  dd.ApplicationName = "DynamicResolutionRendering";
  if (d3dl::FAILED(d3dl::CreateDevice(&dd, m_Device.GetAddressOf(), m_Context.GetAddressOf()))) {
    *error = "cannot create the Vulkan device (see the messages above)";
    return false;
  }
  d3dl::ADAPTER_DESC ad;
  m_Device->GetAdapterDesc(&ad);
  m_AdapterName = ad.Description;
  m_AdapterDriver = ad.Driver;

  d3dl::SWAP_CHAIN_DESC sd;
  sd.Format = m_BackBufferFormat;
  sd.BufferCount = 2;
  if (!m_Window.Headless()) {
    if (!m_Window.Create(m_Options.width, m_Options.height, error)) return false;
    m_Window.FramebufferSize(&sd.Width, &sd.Height);
    sd.Width = std::max(sd.Width, 1u);
    sd.Height = std::max(sd.Height, 1u);
    if (d3dl::FAILED(m_Device->CreateSwapChainForWindow(m_Window.Handle(), &sd, m_SwapChain.GetAddressOf()))) {
      *error = "cannot create the window swap chain";
      return false;
    }
  } else {
    sd.Width = m_Options.width;
    sd.Height = m_Options.height;
    if (d3dl::FAILED(m_Device->CreateHeadlessSwapChain(&sd, m_SwapChain.GetAddressOf()))) {
      *error = "cannot create the headless swap chain";
      return false;
    }
  }
  if (!CreateBackBufferViews()) {
    *error = "cannot create the back-buffer views";
    return false;
  }
  return true;
}

bool Sample::LoadScene(std::string* error) {
  SceneLoadOptions so;
  so.shaders = &m_Shaders;
  // The original samples the scene with anisotropic x16. llvmpipe's
  // anisotropic filter walks the whole footprint and costs 3-30x at some
  // sizes (Docs/Lavapipe-Performance.md), so CPU rasterisers default to
  // trilinear; --anisotropy N chooses explicitly.
  so.maxAnisotropy = m_Options.anisotropy > 0 ? uint32_t(m_Options.anisotropy) : 16u;
  if (m_Options.anisotropy == 0) {
    d3dl::ADAPTER_DESC adapter;
    m_Device->GetAdapterDesc(&adapter);
    if (adapter.IsSoftware) {
      so.maxAnisotropy = 1;
      std::printf("%s is a CPU rasteriser: scene sampler trilinear instead of anisotropic x16 "
                  "(--anisotropy 16 to force it)\n", adapter.Description);
    }
  }
  std::string sceneError;
  m_Scene = Scene::Load(m_Device.Get(), m_ScenePath, so, &sceneError);
  if (!m_Scene) {
    *error = "cannot load the scene " + m_ScenePath + ": " + sceneError;
    return false;
  }
  m_Cameras.Init(m_Scene.get());
  return true;
}

bool Sample::CreateBackBufferViews() {
  if (d3dl::FAILED(m_SwapChain->GetBuffer(0, m_BackBuffer.ReleaseAndGetAddressOf()))) return false;
  if (d3dl::FAILED(m_Device->CreateRenderTargetView(m_BackBuffer.Get(), nullptr, m_BackBufferRTV.ReleaseAndGetAddressOf())))
    return false;
  d3dl::TEXTURE2D_DESC d;
  m_BackBuffer->GetDesc(&d);
  m_BackBufferWidth = d.Width;
  m_BackBufferHeight = d.Height;
  m_BackBufferFormat = d.Format;
  if (m_ZoomCentre[0] < 0) {
    m_ZoomCentre[0] = d.Width * 0.5f;
    m_ZoomCentre[1] = d.Height * 0.5f;
  }
  return true;
}

bool Sample::ResizeSwapChain(uint32_t w, uint32_t h) {
  m_Context->ClearState();
  m_BackBufferRTV = nullptr;
  m_BackBuffer = nullptr;
  m_Passes.GetZoomBox().ReleaseCopy();
  if (d3dl::FAILED(m_SwapChain->ResizeBuffers(0, w, h, m_BackBufferFormat, 0))) return false;
  if (!CreateBackBufferViews()) return false;
  m_ZoomCentre[0] = std::min(m_ZoomCentre[0], float(m_BackBufferWidth));
  m_ZoomCentre[1] = std::min(m_ZoomCentre[1], float(m_BackBufferHeight));
  ReleaseDynamicResolution();
  return InitDynamicResolution();
}

bool Sample::ReloadShaders() {
  // Nothing may still use the shaders that get replaced.
  m_Context->Flush();
  m_Device->WaitIdle();
  m_Shaders.Open(m_Shaders.SpvDir(), ShaderLibrary::DefaultSourceDir());  // the manifest and sources of now
  std::string err;
  size_t postCompiled = 0;
  bool guiCompiled = false;
  bool ok = m_Passes.LoadShaders(m_Shaders, true, &err, &postCompiled);
  ok = ok && m_Gui.Renderer().LoadShaders(m_Shaders, true, &err, &guiCompiled);
  ok = ok && m_Passes.GetZoomBox().LoadShaders(m_Shaders, true, &err);
  ok = ok && m_Scene->ReloadShaders(m_Shaders, true, &err);
  if (!ok) {
    m_LastMessage = "Shader reload failed, the previous shaders stay: " + err;
  } else if (postCompiled > 0) {
    m_LastMessage = "Shaders reloaded: " + std::to_string(postCompiled) + " post-processing shaders" +
                    (guiCompiled ? " and the GUI's" : "") + " compiled from " + m_Shaders.SourceDir();
  } else {
    m_LastMessage = "Shaders reloaded from " + m_Shaders.SpvDir() + " (no HLSL sources in " + m_Shaders.SourceDir() + ")";
  }
  std::fprintf(stderr, "%s\n", m_LastMessage.c_str());
  return ok;
}

// ---------------------------------------------------------------------------
// Render targets
bool Sample::TAAActive() const {
  // The original tested `enabled && TAA || TAA_NO || TAA_BASIC`; only a TAA
  // mode with dynamic resolution on uses the two final targets.
  return m_Options.dynamicResolution && IsTAA(m_Options.filter);
}

RenderTargetPlan Sample::Plan() const {
  return {m_Options.dynamicResolution, m_Options.superSampling, m_Options.motionBlur, TAAActive(),
          m_BackBufferWidth, m_BackBufferHeight};
}

bool Sample::InitDynamicResolution() {
  ReleaseDynamicResolution();
  const float maxScaling = m_Options.superSampling ? 2.0f : 1.0f;
  m_DynamicResolution.InitializeResolutionParameters(m_BackBufferWidth, m_BackBufferHeight, kMaxRTSize, kMaxRTSize,
                                                     maxScaling);
  const bool ok = m_Targets.Allocate(m_Device.Get(), Plan(), m_DynamicResolution.GetDynamicBufferWidth(),
                                     m_DynamicResolution.GetDynamicBufferHeight());
  g_CurrentRT = 0;
  m_HistoryValid = false;
  m_ResetVelocityHistory = true;
  if (m_Controller) m_Controller->Reset();
  return ok;
}

void Sample::ReleaseDynamicResolution() { m_Targets.Release(); }

uint64_t Sample::RenderTargetBytes() const { return m_Targets.Bytes() + m_Passes.GetZoomBoxBytes(); }

// ---------------------------------------------------------------------------
// Settings and input
void Sample::ApplySettings(const Options& o) {
  const bool scaleChanged = o.scaleX != m_Options.scaleX || o.scaleY != m_Options.scaleY ||
                            o.superSampling != m_Options.superSampling;
  const Options keep = m_Options;
  m_Options = o;
  m_Options.headless = keep.headless;
  m_Options.width = keep.width;
  m_Options.height = keep.height;
  m_Gui.show = o.gui;
  if (o.refresh > 0) m_RefreshHz = o.refresh;
  if (o.law != keep.law || !m_Controller) m_Controller = MakeController(m_Options.law, m_LawLatency);  // resets
  else if (o.control != keep.control) m_Controller->Reset();
  if (o.camera >= 0 && o.camera < m_Cameras.Count() && o.camera != m_Cameras.Current() && m_Cameras.Select(o.camera))
    m_ResetVelocityHistory = true;  // camera cut
  m_Options.camera = m_Cameras.Current();
  if (!m_Targets.Allocated() || !(Plan() == m_Targets.Plan())) InitDynamicResolution();
  if (scaleChanged || m_Options.control == ControlMode::Manual)
    m_DynamicResolution.SetScale(m_Options.scaleX, m_Options.scaleY);
}

void Sample::OnKey(int key, int action, int /*mods*/) {
  if (action != GLFW_PRESS) return;
  switch (key) {
    case GLFW_KEY_F1: m_Gui.showHelp = !m_Gui.showHelp; break;
    case GLFW_KEY_F2: m_Window.ToggleFullscreen(); break;
    case GLFW_KEY_F4: (void)ReloadShaders(); break;
    case GLFW_KEY_F10: m_Gui.show = !m_Gui.show; break;
    case GLFW_KEY_F11: m_Gui.showText = !m_Gui.showText; break;
    case GLFW_KEY_P: m_Options.pause = !m_Options.pause; break;
    case GLFW_KEY_Z: m_Options.zoom = !m_Options.zoom; break;
    case GLFW_KEY_ESCAPE: m_Window.RequestClose(); break;
    default: break;
  }
}

void Sample::OnMouse(int button, int action, double x, double y) {
  if (!m_Window.Handle() || action != GLFW_PRESS) return;
  if (button == GLFW_MOUSE_BUTTON_RIGHT) m_Window.ToFramebuffer(x, y, &m_ZoomCentre[0], &m_ZoomCentre[1]);
  if (button == GLFW_MOUSE_BUTTON_LEFT) m_Cameras.BeginDrag(x, y);
}

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
  m_Cameras.UpdateFirstPerson(m_Window.Handle(), !GuiInput::WantsKeyboard(), elapsed);

  // Flip the final/velocity targets each frame for TAA (precedence bug of the
  // original fixed: only with a TAA mode and dynamic resolution on). The jitter
  // is tied to the target index, so a paused scene keeps both targets stable:
  // the un-jittered frame always lands in the same target (no flicker).
  g_CurrentRT = TAAActive() ? 1 - g_CurrentRT : 0;
}

void Sample::ControlResolution(double innerFrameSeconds, double frameSeconds) {
  if (m_CostModel) {
    innerFrameSeconds = frameSeconds =
        m_CostModel(m_DynamicResolution.GetScaleX(), m_DynamicResolution.GetScaleY()) / 1000.0;
  }
  FrameTiming timing;
  timing.gpuInnerSeconds = innerFrameSeconds;
  timing.frameSeconds = frameSeconds;
  ControlTarget target;
  target.budgetSeconds = TargetFrameSeconds(m_RefreshHz, m_Options.control);
  target.minScale = 0.3;
  target.maxScale = m_Options.superSampling ? 2.0 : 1.0;
  const double s = m_Controller->Update(m_DynamicResolution.GetScaleX(), timing, target);
  m_DynamicResolution.SetScale(float(s), float(s));
}

// Which law runs when, on which GPU result.
void Sample::RunResolutionControl() {
  if (!m_Options.dynamicResolution || m_Options.control == ControlMode::Manual) return;
  const AveragedGPUTimer& timer = m_Passes.Timers().frame;
  if (m_Options.law == ControlLaw::Article) {
    // The original: every frame, on the 10-result average of the inner-frame timer.
    if (timer.ResultCount() > 0) ControlResolution(timer.AverageMs() / 1000.0, m_LastFrameSeconds);
  } else if (timer.NewResults() > 0) {
    // Per-frame laws: one call per new inner-frame result. A result polled
    // d frames after its Start leaves d - 1 results of the old scale after a
    // change; the robust law is told the largest such count seen.
    const int stale = std::max(0, int(timer.LastDelayFrames()) - 1);
    if (m_Options.law == ControlLaw::Robust && stale > m_LawLatency) {
      m_LawLatency = stale;
      m_Controller = MakeController(m_Options.law, m_LawLatency);
    }
    ControlResolution(timer.LastMs() / 1000.0, m_LastFrameSeconds);
  }
}

void Sample::UpdateStats() {
  const FrameTimers& t = m_Passes.Timers();
  m_Stats.frameMs = t.frame.AverageMs();
  m_Stats.clearMs = t.clear.AverageMs();
  m_Stats.sceneMs = t.scene.AverageMs();
  m_Stats.postPMs = t.postP.AverageMs();
  m_Stats.scaleMs = t.scale.AverageMs();
  m_Stats.vsyncMs = 1000.0 * TargetFrameSeconds(m_RefreshHz, m_Options.control);
  m_Stats.fps = m_LastFrameSeconds > 0 ? 1.0 / m_LastFrameSeconds : 0.0;
  m_Stats.scaleX = m_DynamicResolution.GetScaleX();
  m_Stats.scaleY = m_DynamicResolution.GetScaleY();
}

// The frame's viewports, TAA jitter, ratios, target indices and constants.
FrameSetup Sample::MakeFrameSetup() {
  FrameSetup s;
  s.dynamic = m_Options.dynamicResolution;
  s.taa = TAAActive();
  s.motionBlur = m_Options.motionBlur;
  s.psClear = m_Options.psClear;
  s.markOutside = m_Options.debugMarkerOutside;
  s.filter = m_Options.filter;

  // TAA jitter and RT ratios: keep last frame's as "previous".
  m_JitterPrev = m_JitterCurr;
  m_RatioPrev = m_RatioCurr;
  const DynamicViewport dvp = m_DynamicResolution.GetViewport();
  s.backBufferViewport = {0, 0, float(m_BackBufferWidth), float(m_BackBufferHeight), 0, 1};
  s.sceneViewport = s.dynamic ? d3dl::VIEWPORT{dvp.TopLeftX, dvp.TopLeftY, dvp.Width, dvp.Height, dvp.MinDepth, dvp.MaxDepth}
                              : s.backBufferViewport;
  m_RatioCurr = s.dynamic ? glm::vec2(m_DynamicResolution.GetRTScaleX(), m_DynamicResolution.GetRTScaleY()) : glm::vec2(1.f);
  m_JitterCurr = glm::vec2(0.f);
  if (s.taa) {
    static const glm::vec2 kAsymmetric[2] = {{0.0f, 0.0f}, {0.5f, 0.5f}};
    static const glm::vec2 kSymmetric[2] = {{-0.25f, -0.25f}, {0.25f, 0.25f}};
    const glm::vec2 px = (m_Options.symmetricTAA ? kSymmetric : kAsymmetric)[g_CurrentRT];
    m_JitterCurr = px / glm::vec2(s.sceneViewport.Width, s.sceneViewport.Height);
  }
  if (!m_HistoryValid) {
    m_JitterPrev = m_JitterCurr;
    m_RatioPrev = m_RatioCurr;
  }
  s.cur = g_CurrentRT;
  s.prev = (s.taa && m_HistoryValid) ? 1 - s.cur : s.cur;

  const float dynW = float(m_DynamicResolution.GetDynamicBufferWidth());
  const float dynH = float(m_DynamicResolution.GetDynamicBufferHeight());
  DynamicConstants& dc = s.dc;
  dc = {{m_RatioCurr.x, m_RatioCurr.y}, {m_RatioPrev.x, m_RatioPrev.y}, {m_JitterCurr.x, m_JitterCurr.y},
        {m_JitterPrev.x, m_JitterPrev.y}, {dynW, dynH}, {1.0f / dynW, 1.0f / dynH}, {}, {}, {}};
  dc.noiseOffset[0] = float(std::rand() % 128);
  dc.noiseOffset[1] = float(std::rand() % 128);
  dc.backBufferSize[0] = float(m_BackBufferWidth);
  dc.backBufferSize[1] = float(m_BackBufferHeight);
  std::memcpy(dc.clearColor, kClearColor, sizeof kClearColor);
  s.fc.size[0] = float(m_BackBufferWidth);
  s.fc.size[1] = float(m_BackBufferHeight);
  s.fc.invSize[0] = 1.0f / s.fc.size[0];
  s.fc.invSize[1] = 1.0f / s.fc.size[1];
  std::memcpy(s.fc.clearColor, kClearColor, sizeof kClearColor);
  return s;
}

SceneRenderParams Sample::SceneParams() const {
  const CameraPose pose = m_Cameras.Pose();
  const float aspect = float(std::max(m_BackBufferWidth, 1u)) / float(std::max(m_BackBufferHeight, 1u));
  SceneRenderParams p;
  p.view = pose.view;
  p.proj = glm::perspectiveRH_ZO(pose.fovY, aspect, pose.nearZ, pose.farZ);
  // Jitter in pixels (x right, y down) -> NDC (+Y up).
  p.jitterNdc = glm::vec2(2.0f * m_JitterCurr.x, -2.0f * m_JitterCurr.y);
  p.mipBiasSampler = TAAActive();
  p.resetHistory = m_ResetVelocityHistory;
  p.showCameras = m_Options.showCameras;
  return p;
}

BackBuffer Sample::CurrentBackBuffer() const {
  return {m_BackBuffer.Get(), m_BackBufferRTV.Get(), m_BackBufferWidth, m_BackBufferHeight};
}

void Sample::OnFrameRender(double elapsed) {
  d3dl::DeviceContext* ctx = m_Context.Get();
  // Re-create the targets when an option that decides them changed (GUI).
  if (!(Plan() == m_Targets.Plan())) {
    InitDynamicResolution();
    if (TAAActive()) g_CurrentRT = 1;
  }
  FrameTimers& timers = m_Passes.Timers();
  if (timers.Update(ctx) || m_FrameCount % 10 == 0) UpdateStats();
  RunResolutionControl();

  const FrameSetup setup = MakeFrameSetup();
  const BackBuffer bb = CurrentBackBuffer();
  const SceneTargets scene = ChooseSceneTargets(m_Targets, setup, bb);
  SceneRenderParams params = SceneParams();
  params.writeVelocity = scene.count == 2;

  timers.frame.Start(ctx);
  m_Passes.Clear(ctx, setup, m_Targets, scene);
  m_Passes.Scene(ctx, setup, scene, *m_Scene, params);
  m_ResetVelocityHistory = false;
  if (m_Log.Capturing()) {
    m_Log.Queue(m_Device.Get(), ctx, scene.colour, Capture::SceneColor);
    m_Log.Queue(m_Device.Get(), ctx, scene.velocity, Capture::Velocity);
  }
  m_Passes.MotionBlur(ctx, setup, m_Targets, bb);
  m_Passes.Scale(ctx, setup, m_Targets, bb);
  if (setup.dynamic && setup.taa) m_HistoryValid = true;
  timers.frame.Stop(ctx);

  // Zoom box, then the GUI at back-buffer resolution.
  if (m_Options.zoom) m_Passes.Zoom(ctx, bb, m_ZoomCentre[0], m_ZoomCentre[1]);
  if (m_Log.Capturing()) m_Log.Queue(m_Device.Get(), ctx, bb.texture, Capture::BackBufferNoGui);
  RenderGui(elapsed);
  if (m_Log.Capturing()) m_Log.Queue(m_Device.Get(), ctx, bb.texture, Capture::BackBuffer);
  ctx->OMSetRenderTargets(0, nullptr, nullptr);
}

void Sample::RenderGui(double elapsed) {
  m_GuiInput.NewFrame(m_Window.Handle(), float(m_BackBufferWidth), float(m_BackBufferHeight), float(elapsed));
  GuiView v;
  v.options = &m_Options;
  v.stats = &m_Stats;
  v.camera = m_Cameras.Current();
  v.cameraCount = m_Cameras.Count();
  v.cameraName = [this](int i) { return m_Cameras.Name(i); };
  v.scaleX = m_DynamicResolution.GetScaleX();
  v.scaleY = m_DynamicResolution.GetScaleY();
  v.backBufferW = m_BackBufferWidth;
  v.backBufferH = m_BackBufferHeight;
  v.rtW = m_DynamicResolution.GetDynamicBufferWidth();
  v.rtH = m_DynamicResolution.GetDynamicBufferHeight();
  v.viewportW = m_DynamicResolution.GetViewportWidth();
  v.viewportH = m_DynamicResolution.GetViewportHeight();
  v.adapter = m_AdapterName;
  v.lastMessage = m_LastMessage;
  v.apply = [this](const Options& o) { ApplySettings(o); };
  m_Gui.Build(v);
  if (m_Gui.show) m_Passes.CountPass("GUI");
  const d3dl::VIEWPORT viewport{0, 0, float(m_BackBufferWidth), float(m_BackBufferHeight), 0, 1};
  m_Gui.Render(m_Context.Get(), m_BackBufferRTV.Get(), viewport);
}

// ---------------------------------------------------------------------------
// Frame loop
bool Sample::RenderFrame() {
  uint32_t fbW = 0, fbH = 0;
  switch (m_Window.BeginFrame(m_FrameCount, m_Options.windowTest, m_Options.width, m_Options.height, &fbW, &fbH)) {
    case AppWindow::Frame::Closed: return false;
    case AppWindow::Frame::Minimised:
      RecordMinimisedFrame();  // render nothing, wait a little
      m_Window.WaitWhileMinimised();
      return true;
    case AppWindow::Frame::Ready: break;
  }
  if (m_Window.Handle() && (fbW != m_BackBufferWidth || fbH != m_BackBufferHeight) && !ResizeSwapChain(fbW, fbH)) {
    std::fprintf(stderr, "resize to %ux%u failed\n", fbW, fbH);
    return false;
  }
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = m_FrameCount == 0 ? 1.0 / 60.0 : std::chrono::duration<double>(now - m_LastFrameTime).count();
  m_LastFrameTime = now;
  if (m_FrameCount > 0) m_LastFrameSeconds = elapsed;

  m_Log.BeginFrame();
  OnFrameMove(elapsed);
  OnFrameRender(elapsed);
  const d3dl::HRESULT hr = m_SwapChain->Present(m_Window.Handle() && m_Options.vsync ? 1 : 0, 0);
  if (d3dl::FAILED(hr)) {
    std::fprintf(stderr, "Present failed: %s\n", d3dl::HResultName(hr));
    return false;
  }
  m_Log.Resolve(m_Device.Get(), m_Context.Get());
  RecordFrame(elapsed);
  return true;
}

void Sample::RecordMinimisedFrame() {
  FrameRecord r;
  r.frame = m_FrameCount++;
  r.rendered = false;
  r.fullscreen = m_Window.Fullscreen();
  m_Log.Add(r);
  ++m_MinimisedFrames;
}

void Sample::RecordFrame(double elapsed) {
  const bool dynamic = m_Options.dynamicResolution;
  const FrameTimers& t = m_Passes.Timers();
  FrameRecord r;
  r.frame = m_FrameCount++;
  r.scaleX = m_DynamicResolution.GetScaleX();
  r.scaleY = m_DynamicResolution.GetScaleY();
  r.viewportW = dynamic ? m_DynamicResolution.GetViewportWidth() : m_BackBufferWidth;
  r.viewportH = dynamic ? m_DynamicResolution.GetViewportHeight() : m_BackBufferHeight;
  r.backBufferW = m_BackBufferWidth;
  r.backBufferH = m_BackBufferHeight;
  r.fullscreen = m_Window.Fullscreen();
  r.cpuFrameMs = elapsed * 1000.0;
  r.gpuFrame = t.frame.LastMs();
  r.gpuFrameNew = t.frame.NewResults() > 0;
  r.gpuFrameDelay = t.frame.LastDelayFrames();
  r.gpuClear = t.clear.LastMs();
  r.gpuScene = t.scene.LastMs();
  r.gpuPostP = t.postP.LastMs();
  r.gpuScale = t.scale.LastMs();
  m_Log.Add(r);
}

uint64_t Sample::ValidationMessages() const {
  if (!m_Device) return 0;
  d3dl::DEVICE_STATS st;
  m_Device->GetStats(&st);
  return st.ValidationMessages;
}

bool Sample::WriteReport(const std::string& path, std::string* error) const {
  ReportInfo info;
  info.options = &m_Options;
  info.refreshHz = m_RefreshHz;
  info.budgetMs = m_Stats.vsyncMs > 0 ? m_Stats.vsyncMs : 1000.0 / m_RefreshHz;
  info.lawLatencyFrames = m_LawLatency;
  info.adapter = m_AdapterName;
  info.driver = m_AdapterDriver;
  info.scenePath = m_ScenePath;
  info.backBuffer[0] = m_BackBufferWidth;
  info.backBuffer[1] = m_BackBufferHeight;
  info.dynamicRT[0] = m_DynamicResolution.GetDynamicBufferWidth();
  info.dynamicRT[1] = m_DynamicResolution.GetDynamicBufferHeight();
  info.targets = &m_Targets;
  info.zoomBoxBytes = m_Passes.GetZoomBoxBytes();
  info.passesRun = &m_Passes.PassesRun();
  info.validationMessages = ValidationMessages();
  info.framesRendered = m_FrameCount - m_MinimisedFrames;
  info.framesMinimised = m_MinimisedFrames;
  info.finalScale[0] = m_DynamicResolution.GetScaleX();
  info.finalScale[1] = m_DynamicResolution.GetScaleY();
  info.scene = m_Scene.get();
  return m_Log.WriteReport(path, info, error);
}

int Sample::Run() {
  const int64_t frames = m_Options.EffectiveFrames();
  const bool wantShot = !m_Options.screenshot.empty();
  while (frames < 0 || m_FrameCount < frames) {
    if (wantShot && frames >= 0 && m_FrameCount == frames - 1) RequestCapture();
    if (!RenderFrame()) break;
  }
  m_Device->WaitIdle();
  int rc = 0;
  std::string err;
  if (wantShot) {
    // The last frame was skipped (minimised) or the window closed early: capture one more.
    if (CapturedBackBuffer().Empty() && !(m_Window.Handle() && glfwWindowShouldClose(m_Window.Handle()))) {
      RequestCapture();
      RenderFrame();
    }
    if (!SaveScreenshot(m_Options.screenshot, m_Options.screenshotNoGui, &err)) {
      std::fprintf(stderr, "screenshot: %s\n", err.c_str());
      rc = 1;
    } else {
      std::printf("screenshot written: %s\n", m_Options.screenshot.c_str());
    }
  }
  if (!m_Options.report.empty()) {
    if (!WriteReport(m_Options.report, &err)) {
      std::fprintf(stderr, "report: %s\n", err.c_str());
      rc = 1;
    } else {
      std::printf("report written: %s\n", m_Options.report.c_str());
    }
  }
  if (m_Options.stats && m_Scene) std::printf("%s\n", m_Scene->Stats().ToString().c_str());
  const uint64_t messages = ValidationMessages();
  if (messages > 0) std::fprintf(stderr, "validation messages: %llu\n", (unsigned long long)messages);
  if (m_Options.validation && messages > 0) rc = 3;
  return rc;
}

void Sample::Shutdown() {
  if (m_Device) m_Device->WaitIdle();
  if (m_Context) m_Context->ClearState();
  m_Log.DropPending();
  m_Scene.reset();
  m_Gui.Release();
  m_Passes.Release();
  ReleaseDynamicResolution();
  m_BackBufferRTV = nullptr;
  m_BackBuffer = nullptr;
  m_SwapChain = nullptr;
  m_Context = nullptr;
  m_Device = nullptr;
  m_Window.Destroy();
}

int SampleMain(int argc, char** argv) {
  Options options;
  std::string message;
  switch (ParseCommandLine(argc, argv, &options, &message)) {
    case ParseStatus::Help:
      std::printf("%s", message.c_str());
      return 0;
    case ParseStatus::Error:
      std::fprintf(stderr, "error: %s\n\n%s", message.c_str(), Usage().c_str());
      return 2;
    case ParseStatus::Ok:
      break;
  }
  Sample sample;
  std::string error;
  if (int rc = sample.Init(options, &error); rc != 0) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return rc;
  }
  const int rc = sample.Run();
  sample.Shutdown();
  return rc;
}

}  // namespace drr
