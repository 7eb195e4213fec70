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
constexpr uint32_t kMaxRTSize = 8192;  // as the original

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

  if (!m_Device.Create(options.validation, m_Window, options.width, options.height, error)) return 1;
  if (!m_Profiler.Init(m_Device.Device())) {
    *error = "cannot create the GPU timer queries";
    return 1;
  }
  if (!m_Passes.Init(m_Device.Device(), m_Shaders, &m_Profiler, error)) return 1;
  if (!m_Deferred.Init(m_Device.Device(), m_Shaders, error)) return 1;
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

void Sample::Warn(const std::string& message) {
  m_Warnings.push_back(message);
  if (!m_Options.quiet) std::fprintf(stderr, "warning: %s\n", message.c_str());
}

// A scale above what the 8192-pixel render targets allow at this back buffer
// is cut; with the aspect lock both axes take the smaller cut, so the aspect
// ratio stays, and the user is told.
void Sample::WarnIfScaleCut(const Options& options) {
  const float maxX = m_DynamicResolution.GetMaxScalingX(), maxY = m_DynamicResolution.GetMaxScalingY();
  if (options.scaleX <= maxX * 1.0001f && options.scaleY <= maxY * 1.0001f) return;
  float sx = std::min(options.scaleX, maxX), sy = std::min(options.scaleY, maxY);
  if (m_Options.aspectLock) sx = sy = std::min(sx, sy);
  m_DynamicResolution.SetScale(sx, sy);
  char text[256];
  std::snprintf(text, sizeof text,
                "scale %g x %g exceeds the %u-pixel render-target limit at %ux%u; using %g x %g", options.scaleX,
                options.scaleY, kMaxRTSize, m_Device.Width(), m_Device.Height(), m_DynamicResolution.GetScaleX(),
                m_DynamicResolution.GetScaleY());
  Warn(text);
}

bool Sample::ResizeSwapChain(uint32_t w, uint32_t h) {
  m_Passes.GetZoomBox().ReleaseCopy();
  if (!m_Device.Resize(w, h)) return false;
  ReleaseDynamicResolution();
  // The original's resize: the scene's previous matrices restart, and a paused sample resumes.
  m_ResetVelocityHistory = true;
  m_Options.pause = false;
  return InitDynamicResolution();
}

bool Sample::ReloadShaders() {
  // Nothing may still use the shaders that get replaced.
  m_Device.Context()->Flush();
  m_Device.Device()->WaitIdle();
  m_Shaders.Open(m_Shaders.SpvDir(), ShaderLibrary::DefaultSourceDir());  // the manifest and sources of now
  std::string err;
  size_t postCompiled = 0;
  bool guiCompiled = false;
  bool ok = m_Passes.LoadShaders(m_Shaders, true, &err, &postCompiled);
  ok = ok && m_Gui.Renderer().LoadShaders(m_Shaders, true, &err, &guiCompiled);
  ok = ok && m_Passes.GetZoomBox().LoadShaders(m_Shaders, true, &err);
  ok = ok && m_Deferred.LoadShaders(m_Shaders, true, &err);
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
FramePlan Sample::PlanNow() const {
  FrameInputs in;
  in.backBufferW = m_Device.Width();
  in.backBufferH = m_Device.Height();
  in.guiDrawn = m_Gui.enabled;
  if (m_Scene)
    for (const SceneLight& l : m_Scene->Lights()) in.shadowedLights += l.shadow;
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
  m_History.current = 0;
  m_History.valid = false;
  if (m_Controller) m_Controller->Reset();
  return ok;
}

void Sample::ReleaseDynamicResolution() { m_Targets.Release(); }

uint64_t Sample::RenderTargetBytes() const {
  return m_Targets.Bytes() + m_Passes.GetZoomBoxBytes() + m_Deferred.ShadowMapBytes();
}

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
  m_Gui.enabled = o.gui;
  if (o.refresh > 0) m_RefreshHz = o.refresh;
  if (o.law != keep.law || !m_Controller) m_Controller = MakeController(m_Options.law, m_LawLatency);  // resets
  else if (o.control != keep.control) m_Controller->Reset();
  // The original keeps the velocity history across a camera change (one frame
  // of smear); the camera-cut fix restarts it.
  const bool cut = o.camera >= 0 && o.camera < m_Cameras.Count() && o.camera != m_Cameras.Current() &&
                   m_Cameras.Select(o.camera);
  if (cut && m_Options.fixes.Has(Fix::CameraCut)) m_ResetVelocityHistory = true;
  // TAAU always restarts its history (and jitter) on a camera cut.
  if (cut && IsTemporalUpsample(m_Options.filter)) {
    m_ResetVelocityHistory = true;
    m_History.valid = false;
  }
  m_Options.camera = m_Cameras.Current();
  if (!(PlanNow().targets == m_Targets.Plan())) InitDynamicResolution();
  if (scaleChanged || m_Options.control == ControlMode::Manual)
    m_DynamicResolution.SetScale(m_Options.scaleX, m_Options.scaleY);
}

// The original's keys: F1, F10 (the panel), F11 (the text) in its keyboard
// callback; F2, F4, P and Z as its dialogs' hotkeys; Alt+Enter and Esc as DXUT's.
void Sample::OnKey(int key, int action, int mods) {
  if (action != GLFW_PRESS) return;
  switch (key) {
    case GLFW_KEY_F1: m_Gui.showHelp = !m_Gui.showHelp; break;
    case GLFW_KEY_F2: m_Window.ToggleFullscreen(); break;
    case GLFW_KEY_ENTER:
      if (mods & GLFW_MOD_ALT) m_Window.ToggleFullscreen();
      break;
    case GLFW_KEY_F4: (void)ReloadShaders(); break;
    case GLFW_KEY_F10: m_Gui.showPanel = !m_Gui.showPanel; break;
    case GLFW_KEY_F11: m_Gui.showText = !m_Gui.showText; break;
    case GLFW_KEY_P: m_Options.pause = !m_Options.pause; break;
    case GLFW_KEY_Z: m_Options.zoom = !m_Options.zoom; break;
    case GLFW_KEY_ESCAPE: m_Window.RequestClose(); break;
    default: break;
  }
}

void Sample::OnMouse(int button, int action, double x, double y) {
  if (!m_Window.Handle() || action != GLFW_PRESS) return;
  // The original's OnMouse: the zoom centre in client-area fractions.
  if (button == GLFW_MOUSE_BUTTON_RIGHT) m_Window.ToClientFraction(x, y, &m_ZoomCentre[0], &m_ZoomCentre[1]);
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
  // The original moves its first-person camera only while not paused.
  if (!m_Options.pause) m_Cameras.UpdateFirstPerson(m_Window.Handle(), !GuiInput::WantsKeyboard(), elapsed);
  m_History.current = PlanNow().flipsTargets ? 1 - m_History.current : 0;
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

void Sample::UpdateStats() {
  const FrameTimers& t = m_Profiler.Timers();
  m_Stats.timing = {t.frame.AverageMs(), t.clear.AverageMs(), t.scene.AverageMs(), t.postP.AverageMs(),
                    t.scale.AverageMs(), m_RefreshHz};
  m_Stats.scaleX = m_DynamicResolution.GetScaleX();
  m_Stats.scaleY = m_DynamicResolution.GetScaleY();
}

// The frame's viewports, TAA jitter, ratios, target indices and constants.
FrameSetup Sample::MakeFrameSetup(const FramePlan& plan) {
  FrameSetup s;
  s.dynamic = m_Options.dynamicResolution;
  s.taa = plan.TAA();
  s.motionBlur = m_Options.motionBlur;
  s.psClear = m_Options.psClear;
  s.markOutside = m_Options.debugMarkerOutside;
  s.filter = m_Options.filter;
  s.fixes = m_Options.fixes;
  const DynamicResolution& dr = m_DynamicResolution;
  const DynamicViewport v = dr.GetViewport();
  s.backBufferViewport = {0, 0, float(m_Device.Width()), float(m_Device.Height()), 0, 1};
  s.sceneViewport = s.dynamic ? d3dl::VIEWPORT{v.TopLeftX, v.TopLeftY, v.Width, v.Height, v.MinDepth, v.MaxDepth}
                              : s.backBufferViewport;
  const RenderTargetPlan& targets = m_Targets.Plan();
  s.taau = targets.taau;
  s.secondary = targets.dynamic && targets.Secondary();
  s.holdJitter = m_Options.pause;
  s.computeUpscale = m_Options.upscaleShader == UpscaleShader::Compute;
  s.outputViewport = s.secondary ? d3dl::VIEWPORT{0, 0, float(targets.outputW), float(targets.outputH), 0, 1}
                                 : s.backBufferViewport;
  m_History.Advance(s, s.dynamic ? glm::vec2(dr.GetRTScaleX(), dr.GetRTScaleY()) : glm::vec2(1.f),
                    m_Options.symmetricTAA);
  FillConstants(s, m_History, glm::vec2(dr.GetDynamicBufferWidth(), dr.GetDynamicBufferHeight()),
                glm::vec2(m_Device.Width(), m_Device.Height()));
  // The original's paused TAA resolve reads target 0 as the current frame.
  s.pausedSwap = m_Options.pause && s.taa && s.cur == 1;
  return s;
}

SceneRenderParams Sample::SceneParams() const {
  const CameraPose pose = m_Cameras.Pose();
  const float aspect = float(std::max(m_Device.Width(), 1u)) / float(std::max(m_Device.Height(), 1u));
  SceneRenderParams p;
  p.view = pose.view;
  p.proj = glm::perspectiveRH_ZO(pose.fovY, aspect, pose.nearZ, pose.farZ);
  // Jitter in pixels (x right, y down) -> NDC (+Y up).
  p.jitterNdc = glm::vec2(2.0f * m_History.jitterCurr.x, -2.0f * m_History.jitterCurr.y);
  p.mipBiasSampler = PlanNow().TAA() && m_Options.taaMipBias;
  // TAAU's automatic view mip bias: log2(screen percentage) + the user's bias.
  if (m_Targets.Plan().taau && m_Options.autoMipBias)
    p.viewMipBias = std::log2(m_DynamicResolution.GetScaleX()) + float(m_Options.mipBias);
  for (size_t at = 0; at < m_Options.mipBiasOptOut.size();) {
    const size_t comma = std::min(m_Options.mipBiasOptOut.find(',', at), m_Options.mipBiasOptOut.size());
    if (comma > at) p.mipBiasOptOut.push_back(m_Options.mipBiasOptOut.substr(at, comma - at));
    at = comma + 1;
  }
  p.resetHistory = m_ResetVelocityHistory;
  p.paused = m_Options.pause;
  p.target = m_History.current;
  p.showCameras = m_Options.showCameras;
  p.shadingEye = m_Cameras.ShadingEye(m_Options.fixes.Has(Fix::CameraEye));
  p.frustumCulling = m_Options.fixes.Has(Fix::FrustumCull);
  p.tessellation.enabled = m_Options.tessellation;  // the viewport height is set per frame (OnFrameRender)
  p.tessellation.pixelsPerEdge = float(m_Options.tessPixelsPerEdge);
  p.tessellation.maxFactor = float(m_Options.maxTessFactor);
  p.recordingThreads = RecordingThreadsFor(m_Options.threads);
  return p;
}

void Sample::OnFrameRender(double elapsed) {
  d3dl::DeviceContext* ctx = m_Device.Context();
  // Re-create the targets when an option that decides them changed (GUI).
  const FramePlan plan = PlanNow();
  if (!(plan.targets == m_Targets.Plan())) {
    InitDynamicResolution();
    if (plan.TAA()) m_History.current = 1;
  }
  FrameTimers& timers = m_Profiler.Timers();
  m_Profiler.Poll(ctx);
  RunResolutionControl();
  if (timers.scene.NewAverage()) UpdateStats();  // as the original: after the control, when the scene timer completes a block

  const FrameSetup setup = MakeFrameSetup(plan);
  const BackBuffer bb = m_Device.Back();
  const SceneTargets scene = ChooseSceneTargets(m_Targets, setup, bb);
  SceneRenderParams params = SceneParams();
  params.writeVelocity = scene.count == 2;
  params.tessellation.viewportHeight = setup.sceneViewport.Height;  // the dynamic viewport: factors follow the scale
  params.viewport = setup.sceneViewport;  // what FramePasses::Scene sets: deferred contexts set it too

  timers.frame.Start(ctx);
  m_Passes.Clear(ctx, setup, m_Targets, scene);
  if (m_Targets.Plan().deferred) m_Deferred.Render(ctx, setup, scene, m_Targets, *m_Scene, params,
                                                   MakeDeferredFrame(setup), m_Profiler);
  else m_Passes.Scene(ctx, setup, scene, *m_Scene, params);
  m_ResetVelocityHistory = false;
  if (m_Log.Capturing()) {
    m_Log.Queue(m_Device.Device(), ctx, scene.colour, Capture::SceneColor);
    m_Log.Queue(m_Device.Device(), ctx, scene.velocity, Capture::Velocity);
  }
  m_Passes.MotionBlur(ctx, setup, m_Targets, bb);
  m_Passes.Scale(ctx, setup, m_Targets, bb);
  if (setup.taa || setup.taau) m_History.valid = true;

  // Zoom box, then the GUI at back-buffer resolution: both inside the inner
  // frame, as in the original (its timer ends after the GUI and the text).
  if (m_Options.zoom) m_Passes.Zoom(ctx, bb, m_ZoomCentre[0], m_ZoomCentre[1]);
  if (m_Log.Capturing()) m_Log.Queue(m_Device.Device(), ctx, bb.texture, Capture::BackBufferNoGui);
  RenderGui(elapsed);
  timers.frame.Stop(ctx);
  if (m_Log.Capturing()) m_Log.Queue(m_Device.Device(), ctx, bb.texture, Capture::BackBuffer);
  ctx->OMSetRenderTargets(0, nullptr, nullptr);
}

// The deferred part of the frame: SSAO, the shadow maps' dynamic scale (their
// law on the main scale) and the G-buffer's read ratio: the resolve's RT
// scale on the dynamic path, back buffer / G-buffer on the full one.
DeferredFrame Sample::MakeDeferredFrame(const FrameSetup& s) const {
  DeferredFrame f;
  f.ssao = m_Targets.Plan().ssao;
  f.localLights = m_Options.localLights;
  const float mainScale = m_Options.dynamicResolution ? m_DynamicResolution.GetScaleX() : 1.0f;
  f.shadowScale = ShadowMapScale(m_Options.shadowLaw, float(m_Options.shadowScale), mainScale);
  f.shadowMapSize = m_Options.shadowMapSize;
  const RenderTarget& g = m_Targets[RT::GBufferDiffuse];
  f.ratio = s.dynamic ? glm::vec2(s.dc.ratioCurr[0], s.dc.ratioCurr[1])
                      : glm::vec2(s.sceneViewport.Width / float(g.width), s.sceneViewport.Height / float(g.height));
  return f;
}

std::string Sample::DeferredStats() const {
  const RenderTargetPlan& plan = m_Targets.Plan();
  uint64_t bytes = 0;
  int targets = 0;
  for (RT rt : {RT::GBufferDiffuse, RT::GBufferSpecular, RT::GBufferNormal, RT::GBufferAO}) {
    bytes += m_Targets[rt].Bytes();
    targets += m_Targets[rt].Valid();
  }
  int points = 0, spots = 0;
  for (const SceneLight& l : m_Scene->Lights()) (l.type == LightType::Point ? points : spots) += 1;
  char b[320];
  std::snprintf(b, sizeof b,
                "renderer %s: G-buffer targets %d (%.1f MiB), SSAO %s, shadow maps %u of %u^2 (%.1f MiB, scale %.3f, "
                "%u depth draws), scene lights %d point + %d spot",
                RendererOption(m_Options.renderer), targets, bytes / 1048576.0, plan.ssao ? "on" : "off",
                m_Deferred.ShadowSlices(), m_Deferred.ShadowMapSize(), m_Deferred.ShadowMapBytes() / 1048576.0,
                m_Deferred.ShadowScaleUsed(), m_Deferred.ShadowMapDraws(), points, spots);
  return b;
}

void Sample::RenderGui(double elapsed) {
  m_GuiInput.NewFrame(m_Window.Handle(), float(m_Device.Width()), float(m_Device.Height()), float(elapsed));
  GuiView v;
  v.options = &m_Options;
  v.stats = &m_Stats;
  v.camera = m_Cameras.Current();
  v.cameraCount = m_Cameras.Count();
  v.cameraName = [this](int i) { return m_Cameras.Name(i); };
  v.scaleX = m_DynamicResolution.GetScaleX();
  v.scaleY = m_DynamicResolution.GetScaleY();
  v.backBufferW = m_Device.Width();
  v.backBufferH = m_Device.Height();
  v.dxutFps = m_Fps.Fps();
  v.vsync = m_Window.Handle() && m_Options.vsync;  // as Present is called
  d3dl::TEXTURE2D_DESC bd;
  m_Device.Back().texture->GetDesc(&bd);
  v.backBufferFormat = d3dl::FormatName(bd.Format);
  v.softwareAdapter = m_Device.Adapter().IsSoftware;
  v.adapter = m_Device.Adapter().Description;
  v.lastMessage = m_LastMessage;
  if (m_Scene) {
    const SceneStats st = m_Scene->Stats();
    v.recording = {m_Options.threads, st.drawsPerThread, st.recordMs};
  }
  v.apply = [this](const Options& o) { ApplySettings(o); };
  m_Gui.Build(v);
  if (m_Gui.Drawn()) m_Profiler.CountPass("GUI");
  const d3dl::VIEWPORT viewport{0, 0, float(m_Device.Width()), float(m_Device.Height()), 0, 1};
  m_Gui.Render(m_Device.Context(), m_Device.Back().rtv, viewport);
}

// The panel's buttons act after the frame (a reload flushes the device).
void Sample::RunGuiActions() {
  const GuiActions a = m_Gui.TakeActions();
  if (a.toggleFullscreen) m_Window.ToggleFullscreen();
  if (a.reloadShaders) (void)ReloadShaders();
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

uint64_t Sample::ValidationMessages() const { return m_Device.ValidationMessages(); }

bool Sample::WriteReport(const std::string& path, std::string* error) const {
  ReportInfo info;
  info.options = &m_Options;
  info.refreshHz = m_RefreshHz;
  info.budgetMs = 1000.0 * TargetFrameSeconds(m_RefreshHz, m_Options.control);
  info.lawLatencyFrames = m_LawLatency;
  info.adapter = m_Device.Adapter().Description;
  info.driver = m_Device.Adapter().Driver;
  info.scenePath = m_ScenePath;
  info.backBuffer[0] = m_Device.Width();
  info.backBuffer[1] = m_Device.Height();
  info.dynamicRT[0] = m_DynamicResolution.GetDynamicBufferWidth();
  info.dynamicRT[1] = m_DynamicResolution.GetDynamicBufferHeight();
  info.targets = &m_Targets;
  info.zoomBoxBytes = m_Passes.GetZoomBoxBytes();
  info.passesRun = &m_Profiler.PassesRun();
  info.validationMessages = ValidationMessages();
  info.framesRendered = m_FrameCount - m_MinimisedFrames;
  info.framesMinimised = m_MinimisedFrames;
  info.finalScale[0] = m_DynamicResolution.GetScaleX();
  info.finalScale[1] = m_DynamicResolution.GetScaleY();
  info.scene = m_Scene.get();
  info.warnings = &m_Warnings;
  info.gui = &m_Gui.Layout();
  return m_Log.WriteReport(path, info, error);
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
  if (m_Options.stats && m_Scene) {
    const SceneStats st = m_Scene->Stats();
    std::printf("%s\n", st.ToString().c_str());
    std::printf("%s\n", st.RecordingString().c_str());
    const uint64_t original = RenderTargetSet::OriginalBytes(m_Device.Width(), m_Device.Height(),
                                                             m_DynamicResolution.GetDynamicBufferWidth(),
                                                             m_DynamicResolution.GetDynamicBufferHeight());
    std::printf("render targets %.1f MiB (the original allocates %.1f MiB for this mode)\n",
                RenderTargetBytes() / 1048576.0, original / 1048576.0);
    std::printf("%s\n", DeferredStats().c_str());
  }
  if (m_Options.stats) {
    std::printf("warnings: %zu\n", m_Warnings.size());
    for (const std::string& w : m_Warnings) std::printf("  %s\n", w.c_str());
  }
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
  m_Deferred.Release();
  m_Profiler.Release();
  ReleaseDynamicResolution();
  const bool clean = m_Device.Release();
  m_Window.Destroy();
  return clean;
}

}  // namespace drr
