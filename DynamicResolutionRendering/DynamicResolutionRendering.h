// The application, as the original's DynamicResolutionRendering.cpp: device
// and swap-chain set-up, OnFrameMove, OnFrameRender, InitDynamicResolution /
// ReleaseDynamicResolution, UpdateStats and ControlResolution. Each frame it
// runs the control step, asks PlanFrame (FramePlan.h) for the frame's plan
// and records the plan's passes (passes/PassRegistry.h). Beside it: AppWindow
// (window and input), Cameras, RenderTargets (the target table),
// TemporalHistory, GuiPanel and FrameLog (records, captures, screenshot,
// report); SampleServices.cpp holds what is not the frame loop (settings,
// keys, reload, GUI view, report and statistics). It is a class so tests can
// drive it in process (Init, RenderFrame, Shutdown).
#pragma once

#include <array>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "AppWindow.h"
#include "Cameras.h"
#include "DeviceResources.h"
#include "DynamicResolution.h"
#include "FrameLog.h"
#include "FramePacer.h"
#include "FrameProfiler.h"
#include "FramePlan.h"
#include "TemporalHistory.h"
#include "passes/PassRegistry.h"
#include "GuiPanel.h"
#include "Options.h"
#include "ResolutionController.h"
#include "ShaderLibrary.h"
#include "d3dl/D3DLike.h"

namespace drr {

class Scene;

class Sample {
 public:
  Sample();
  ~Sample();
  Sample(const Sample&) = delete;
  Sample& operator=(const Sample&) = delete;

  // Returns 0 on success, else an exit code (1, 2 for a bad option) with error set.
  int Init(const Options& options, std::string* error);
  // Changes what the GUI can change (filter, scales, toggles, camera, control)
  // and re-creates the render targets when the allocation depends on it.
  void ApplySettings(const Options& options);
  // One frame: events, OnFrameMove, OnFrameRender, Present. False when the
  // window was closed.
  bool RenderFrame();
  // Runs the configured number of frames (or until the window closes), writes
  // the screenshot and the report; returns the exit code.
  int Run();
  // False when the shutdown was not clean (DeviceResources::Release).
  bool Shutdown();

  // --- test hooks -----------------------------------------------------------
  // The next RenderFrame reads back the back buffer (with and without the
  // GUI), the target the scene drew colour into, and the current velocity.
  void RequestCapture() { m_Log.RequestCapture(); }
  // Replaces the measured times that ControlResolution sees with a model of
  // the GPU frame time (ms) at a viewport scale, so a closed-loop test is
  // deterministic; the laws still run on the real timer cadence. Empty = off.
  void SetFrameCostModel(std::function<double(double scaleX, double scaleY)> gpuMs) {
    m_CostModel = std::move(gpuMs);
  }
  const Image& CapturedBackBuffer() const { return m_Log.Captured(Capture::BackBuffer); }
  const Image& CapturedBackBufferNoGui() const { return m_Log.Captured(Capture::BackBufferNoGui); }
  const Image& CapturedSceneColor() const { return m_Log.Captured(Capture::SceneColor); }  // whole RT
  const Image& CapturedVelocity() const { return m_Log.Captured(Capture::Velocity); }      // may be empty
  uint64_t ValidationMessages() const;
  bool ValidationLayerMissing() const;
  const DynamicResolution& GetDynamicResolution() const { return m_DynamicResolution; }
  uint64_t RenderTargetBytes() const;
  const std::map<std::string, uint64_t>& PassesRun() const { return m_Profiler.PassesRun(); }
  const RenderTargetSet& Targets() const { return m_Targets; }
  const DeferredShared& Deferred() const { return m_Passes.Deferred(); }
  // The deferred renderer's line of --stats (G-buffer targets and bytes, shadow maps, lights).
  std::string DeferredStats() const;
  const std::vector<FrameRecord>& Frames() const { return m_Log.Frames(); }
  const Options& Settings() const { return m_Options; }
  bool IsHeadless() const { return m_Window.Headless(); }
  int64_t FrameCount() const { return m_FrameCount; }
  int64_t MinimisedFrames() const { return m_MinimisedFrames; }
  uint32_t BackBufferWidth() const { return m_Device.Width(); }
  uint32_t BackBufferHeight() const { return m_Device.Height(); }
  std::array<float, 4> GuiStaticRect() const { return m_Gui.staticRect; }
  const SampleStats& Stats() const { return m_Stats; }
  d3dl::Device* GetDevice() const { return m_Device.Device(); }
  const Scene* GetScene() const { return m_Scene.get(); }
  const Cameras& GetCameras() const { return m_Cameras; }
  bool SaveScreenshot(const std::string& path, bool noGui, std::string* error) const {
    return m_Log.SaveScreenshot(path, noGui, error);
  }
  bool WriteReport(const std::string& path, std::string* error) const;
  // Test hook (soak, tests): resizes the back buffer as a window resize does.
  bool Resize(uint32_t w, uint32_t h) { return ResizeSwapChain(w, h); }
  // F4: recompiles every shader of the sample from its HLSL source
  // (ShaderLibrary::DefaultSourceDir(); the .spv files when the sources are
  // absent). On any error the old shaders stay and the message is shown.
  bool ReloadShaders();
  const std::string& LastMessage() const { return m_LastMessage; }
  // DXUT-style frames per second (DXUTGetFPS): frames / elapsed over the last
  // period of just over a second, updated once per such period; 0 during the
  // first second. The article law's frame time is 1 / this.
  double DxutFps() const { return m_Fps.Fps(); }
  // What the control law was last fed (after a cost model's replacement).
  const FrameTiming& LastLawInput() const { return m_LawInput; }
  // Control law in use and the latency (in GPU results) it was told.
  ControlLaw Law() const { return m_Options.law; }
  int LawLatencyFrames() const { return m_LawLatency; }

  // The zoom centre in UV of the back buffer (the right mouse button sets it).
  void SetZoomCentre(float u, float v) {
    m_ZoomCentre[0] = u;
    m_ZoomCentre[1] = v;
  }

  // Input (called by the GLFW callbacks).
  void OnKey(int key, int action, int mods);
  void OnMouse(int button, int action, double x, double y);

 private:
  static constexpr uint32_t kMaxRTSize = 8192;  // as the original
  // Units of the original.
  void OnFrameMove(double elapsed);
  void OnFrameRender(double elapsed);
  bool InitDynamicResolution();
  void ReleaseDynamicResolution();
  // Re-creates the targets when an option that decides them changed (GUI).
  void UpdateTargets();
  void UpdateStats();
  void ControlResolution(double innerFrameSeconds, double frameSeconds, double gpuScale = 0.0);

  bool LoadScene(std::string* error);
  bool ResizeSwapChain(uint32_t w, uint32_t h);
  // This frame's plan (FramePlan.h) from the settings and the back buffer.
  FramePlan PlanNow() const;
  void RunResolutionControl();
  void BuildGui(double elapsed);
  void PrintStats() const;
    void RunGuiActions();

  Options m_Options;
  std::string m_ScenePath;
  AppWindow m_Window;
  GuiInput m_GuiInput;
  ShaderLibrary m_Shaders;

  DeviceResources m_Device;

  DynamicResolution m_DynamicResolution;
  RenderTargetSet m_Targets;
  TemporalHistory m_History;  // the TAA ping-pong and TAAU's history (FramePlan::history)
  bool m_ResetVelocityHistory = true;  // the scene's previous matrices restart (first frame, resize)

  FrameProfiler m_Profiler;  // GPU timers, pass counts, the scale of recent frames
  PassRegistry m_Passes;  // every pass of the frame (passes/)
  GuiPanel m_Gui;
  std::unique_ptr<Scene> m_Scene;
  // Fallback textures, rejected transforms, cut scales, ignored options: on
  // stderr unless --quiet, in --stats and in the report.
  std::vector<std::string> m_Warnings;
  void Warn(const std::string& message);
  void WarnIfScaleCut(const Options& options);
  Cameras m_Cameras;
  float m_ZoomCentre[2] = {0.5f, 0.5f};  // UV of the back buffer, as the original's

  std::unique_ptr<ResolutionController> m_Controller;
  // Stale GPU results after a scale change (largest timer delay seen - 1),
  // told to the robust law as RobustController::Params::latencyFrames.
  int m_LawLatency = 0;
  double m_RefreshHz = 60.0;
  std::chrono::steady_clock::time_point m_LastFrameTime;
  FramePacer m_Pacer;  // --pace-hz: headless presents at the refresh period
  std::array<double, 10> m_DeltaHistory{};  // SmoothedTimer: last 10 frame deltas
  int m_DeltaCount = 0;
  double m_AnimationTime = 0.0;
  double m_LastFrameSeconds = 1.0 / 60.0;  // last frame's period (the port's per-result laws)
  DxutFpsCounter m_Fps;                     // the original's 1 / DXUTGetFPS() frame time
  FrameTiming m_LawInput;
  SampleStats m_Stats;
  int64_t m_FrameCount = 0, m_MinimisedFrames = 0;
  FrameLog m_Log;
  std::string m_LastMessage;
  std::function<double(double, double)> m_CostModel;
};

}  // namespace drr
