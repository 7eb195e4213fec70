// What the sample does besides its frame loop (DynamicResolutionRendering.cpp):
// warnings, settings from the GUI or a test, keys and mouse, shader reload
// (F4), the GUI's view of the sample, the report and the --stats lines.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "DynamicResolutionRendering.h"
#include "scene/Scene.h"

namespace drr {

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
  ShaderLoad gui{m_Device.Device(), &m_Shaders, true, &err};
  bool ok = m_Passes.LoadShaders(m_Shaders, true, &err, &postCompiled);
  ok = ok && m_Gui.Renderer().LoadShaders(gui);
  ok = ok && m_Scene->ReloadShaders(m_Shaders, true, &err);
  if (!ok) {
    m_LastMessage = "Shader reload failed, the previous shaders stay: " + err;
  } else if (postCompiled > 0) {
    m_LastMessage = "Shaders reloaded: " + std::to_string(postCompiled) + " post-processing shaders" +
                    (gui.compiled > 0 ? " and the GUI's" : "") + " compiled from " + m_Shaders.SourceDir();
  } else {
    m_LastMessage = "Shaders reloaded from " + m_Shaders.SpvDir() + " (no HLSL sources in " + m_Shaders.SourceDir() + ")";
  }
  std::fprintf(stderr, "%s\n", m_LastMessage.c_str());
  return ok;
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
    m_History.Invalidate();
  }
  m_Options.camera = m_Cameras.Current();
  UpdateTargets();
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


void Sample::UpdateStats() {
  const FrameTimers& t = m_Profiler.Timers();
  m_Stats.timing = {t.frame.AverageMs(), t.clear.AverageMs(), t.scene.AverageMs(), t.postP.AverageMs(),
                    t.scale.AverageMs(), m_RefreshHz};
  m_Stats.scaleX = m_DynamicResolution.GetScaleX();
  m_Stats.scaleY = m_DynamicResolution.GetScaleY();
}

std::string Sample::DeferredStats() const {
  const RenderTargetPlan& plan = m_Targets.Plan();
  uint64_t bytes = 0;
  int targets = 0;
  for (RT rt : {RT::GBufferDiffuse, RT::GBufferSpecular, RT::GBufferNormal, RT::GBufferAO}) {
    bytes += m_Targets[rt].Bytes();
    targets += m_Targets[rt].Valid();
  }
  const RenderTarget& shadowMaps = m_Targets[RT::SpotShadowMaps];
  int points = 0, spots = 0;
  for (const SceneLight& l : m_Scene->Lights()) (l.type == LightType::Point ? points : spots) += 1;
  char b[320];
  std::snprintf(b, sizeof b,
                "renderer %s: G-buffer targets %d (%.1f MiB), SSAO %s, shadow maps %u of %u^2 (%.1f MiB, scale %.3f, "
                "%u depth draws), scene lights %d point + %d spot",
                RendererOption(m_Options.renderer), targets, bytes / 1048576.0, plan.ssao ? "on" : "off",
                Deferred().ShadowSlices(), shadowMaps.width, shadowMaps.Bytes() / 1048576.0,
                Deferred().ShadowScaleUsed(), Deferred().ShadowMapDraws(), points, spots);
  return b;
}

void Sample::BuildGui(double elapsed) {
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
}

// The panel's buttons act after the frame (a reload flushes the device).
void Sample::RunGuiActions() {
  const GuiActions a = m_Gui.TakeActions();
  if (a.toggleFullscreen) m_Window.ToggleFullscreen();
  if (a.reloadShaders) (void)ReloadShaders();
}


uint64_t Sample::ValidationMessages() const { return m_Device.ValidationMessages(); }
bool Sample::ValidationLayerMissing() const { return m_Device.ValidationLayerMissing(); }

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


// --stats: the scene, recording, render-target and deferred lines, then the warnings.
void Sample::PrintStats() const {
  if (!m_Options.stats) return;
  if (m_Scene) {
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
  std::printf("warnings: %zu\n", m_Warnings.size());
  for (const std::string& w : m_Warnings) std::printf("  %s\n", w.c_str());
}

}  // namespace drr
