// The application of the Dynamic Resolution Rendering sample, as the
// original's DynamicResolutionRendering.cpp: device and swap-chain setup,
// OnFrameMove, OnFrameRender (resolution control, TAA jitter, clear, scene,
// motion blur, scale/resolve, zoom box, GUI), InitDynamicResolution /
// ReleaseDynamicResolution, UpdateStats and ControlResolution.
// It is a class so tests can drive it in process (Init, RenderFrame, Shutdown).
#pragma once

#include <array>
#include <chrono>
#include <functional>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "DynamicResolution.h"
#include "GPUTimer.h"
#include "GuiRenderer.h"
#include "Options.h"
#include "ResolutionController.h"
#include "TexGenUtils.h"
#include "Utility.h"
#include "ZoomBox.h"
#include "d3dl/D3DLike.h"

struct GLFWwindow;
struct ImGuiContext;

namespace drr {

class Scene;

struct ImageRGBA8 {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> pixels;  // tightly packed RGBA8 (sRGB-encoded for sRGB formats)
  bool Empty() const { return pixels.empty(); }
};

struct ImageRG32F {
  uint32_t width = 0, height = 0;
  std::vector<float> pixels;  // RG pairs
};

struct FrameRecord {
  int64_t frame = 0;
  float scaleX = 1, scaleY = 1;
  uint32_t viewportW = 0, viewportH = 0;
  double cpuFrameMs = 0;
  // Latest GPU results (ms) available at this frame (they lag a few frames).
  double gpuFrame = 0, gpuClear = 0, gpuScene = 0, gpuPostP = 0, gpuScale = 0;
  // True when a new inner-frame GPU result arrived this frame (else gpuFrame
  // repeats an older one), and that result's delay in frames (GPUTimer::LastDelay).
  bool gpuFrameNew = false;
  uint32_t gpuFrameDelay = 0;
  bool rendered = true;  // false while minimised
  uint32_t backBufferW = 0, backBufferH = 0;  // 0x0 while minimised
  bool fullscreen = false;
};

// Everything the GUI shows as statistics (refreshed by UpdateStats).
struct SampleStats {
  double frameMs = 0, clearMs = 0, sceneMs = 0, postPMs = 0, scaleMs = 0, vsyncMs = 0;
  double fps = 0;
  float scaleX = 1, scaleY = 1;
};

class Sample {
 public:
  Sample();
  ~Sample();
  Sample(const Sample&) = delete;
  Sample& operator=(const Sample&) = delete;

  // Returns 0 on success, else an exit code (1) with error set.
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
  void Shutdown();

  // --- test hooks -----------------------------------------------------------
  // The next RenderFrame reads back the back buffer (with and without the
  // GUI), the target the scene drew colour into, and the current velocity.
  void RequestCapture() { m_CaptureRequested = true; }
  // Replaces the measured times that ControlResolution sees with a model of
  // the GPU frame time (ms) at a viewport scale, so a closed-loop test is
  // deterministic; the laws still run on the real timer cadence. Empty = off.
  void SetFrameCostModel(std::function<double(double scaleX, double scaleY)> gpuMs) {
    m_CostModel = std::move(gpuMs);
  }
  const ImageRGBA8& CapturedBackBuffer() const { return m_CapBackBuffer; }
  const ImageRGBA8& CapturedBackBufferNoGui() const { return m_CapBackBufferNoGui; }
  const ImageRGBA8& CapturedSceneColor() const { return m_CapSceneColor; }  // whole RT
  const ImageRG32F& CapturedVelocity() const { return m_CapVelocity; }      // whole RT (may be empty)
  uint64_t ValidationMessages() const;
  const DynamicResolution& GetDynamicResolution() const { return m_DynamicResolution; }
  uint64_t RenderTargetBytes() const;
  const std::map<std::string, uint64_t>& PassesRun() const { return m_PassesRun; }
  const std::vector<FrameRecord>& Frames() const { return m_Frames; }
  const Options& Settings() const { return m_Options; }
  GLFWwindow* Window() const { return m_Window; }
  bool IsHeadless() const { return m_Headless; }
  int64_t FrameCount() const { return m_FrameCount; }
  int64_t MinimisedFrames() const { return m_MinimisedFrames; }
  uint32_t BackBufferWidth() const { return m_BackBufferWidth; }
  uint32_t BackBufferHeight() const { return m_BackBufferHeight; }
  // Part of the GUI panel above the scale sliders (content that does not
  // depend on the scale), in back-buffer pixels: x0, y0, x1, y1.
  std::array<float, 4> GuiStaticRect() const { return m_GuiStaticRect; }
  const SampleStats& Stats() const { return m_Stats; }
  d3dl::Device* GetDevice() const { return m_Device.Get(); }
  bool SaveScreenshot(const std::string& path, bool noGui, std::string* error) const;
  bool WriteReport(const std::string& path, std::string* error) const;
  void ToggleFullscreen();
  bool WindowShown() const;  // mapped and not minimised
  // F4: recompiles the post-processing shaders from their HLSL sources
  // (ShaderSourceDir(); the compiled .spv files when the sources are absent),
  // reloads the GUI and zoom-box shaders and the scene's. On any error the
  // old shaders stay and the message is shown (GUI text and stderr).
  bool ReloadShaders();
  const std::string& LastMessage() const { return m_LastMessage; }
  // $DRR_SHADER_SOURCE_DIR when set, else the build's Shaders folder.
  static std::string ShaderSourceDir();
  // Control law in use and the latency (in GPU results) it was told.
  ControlLaw Law() const { return m_Options.law; }
  int LawLatencyFrames() const { return m_LawLatency; }

  // Input (also called by the GLFW callbacks).
  void OnKey(int key, int action, int mods);
  void OnMouse(int button, int action, double x, double y);

 private:
  // Units of the original.
  void OnFrameMove(double time, double elapsed);
  void OnFrameRender(double elapsed);
  bool InitDynamicResolution();
  void ReleaseDynamicResolution();
  void UpdateStats();
  void ControlResolution(double innerFrameSeconds, double frameSeconds);
  void RenderGUI();
  void RenderText();

  bool CreateDeviceAndSwapChain(std::string* error);
  // fromSources: compile Shaders/*.hlsl at run time (F4); else load the .spv files.
  bool LoadShaders(std::string* error, bool fromSources = false);
  bool CreateStates(std::string* error);
  bool CreateBackBufferViews();
  void ReleaseBackBufferViews();
  bool ResizeSwapChain(uint32_t w, uint32_t h);
  bool TAAActive() const;
  int SceneCameraCount() const;
  int CameraCount() const;  // scene cameras + First Person
  std::string CameraName(int i) const;
  void SelectCamera(int i);
  void UpdateFirstPersonCamera(double elapsed);
  void SetPostConstants(const void* data, size_t size);
  void DrawFullScreen(d3dl::PixelShader* ps);
  void UnbindPixelSRVs();
  void CountPass(const char* name) { ++m_PassesRun[name]; }
  void QueueCopy(d3dl::Texture2D* src, int kind);
  void ResolvePendingCaptures();

  Options m_Options;
  bool m_Headless = true;
  GLFWwindow* m_Window = nullptr;
  bool m_GlfwInitialised = false;
  bool m_Fullscreen = false;
  bool m_FullscreenTogglePending = false;  // asked for while minimised
  std::string m_WindowTestState;           // --window-test: last state logged
  int m_WindowedPos[2] = {100, 100}, m_WindowedSize[2] = {1280, 720};
  std::string m_ShaderDir, m_ScenePath;

  d3dl::ComPtr<d3dl::Device> m_Device;
  d3dl::ComPtr<d3dl::DeviceContext> m_Context;
  d3dl::ComPtr<d3dl::SwapChain> m_SwapChain;
  d3dl::ComPtr<d3dl::Texture2D> m_BackBuffer;
  d3dl::ComPtr<d3dl::RenderTargetView> m_BackBufferRTV;
  uint32_t m_BackBufferWidth = 0, m_BackBufferHeight = 0;
  d3dl::DXGI_FORMAT m_BackBufferFormat = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
  std::string m_AdapterName, m_AdapterDriver;

  // Render targets (dynamic path).
  DynamicResolution m_DynamicResolution;
  Utility::RenderTarget g_ColorDynamic, g_DepthDynamic;
  Utility::RenderTarget g_VelocityDynamic[2];
  Utility::RenderTarget g_FinalRTDynamic[2];
  // Full-resolution path.
  Utility::RenderTarget g_ColorFull, g_VelocityFull, g_DepthFull;
  int g_CurrentRT = 0;
  struct AllocationKey {
    bool dynamic = false, superSampling = false, motionBlur = false, taa = false;
    uint32_t w = 0, h = 0;
    bool operator==(const AllocationKey&) const = default;
  } m_Allocated;
  bool m_HistoryValid = false;  // previous final RT holds a frame of the current allocation
  bool m_ResetVelocityHistory = true;

  // TAA jitter (fractions of the viewport) and RT ratios, current and previous.
  glm::vec2 m_JitterCurr{0.f}, m_JitterPrev{0.f};
  glm::vec2 m_RatioCurr{1.f}, m_RatioPrev{1.f};

  // Shaders and states.
  d3dl::ComPtr<d3dl::VertexShader> m_FullScreenVS, m_FullScreenFullVS;
  d3dl::ComPtr<d3dl::PixelShader> m_ClearPS, m_ClearVelocityPS, m_MotionBlurPS;
  d3dl::ComPtr<d3dl::PixelShader> m_FullClearPS, m_FullClearVelocityPS, m_FullMotionBlurPS;
  d3dl::ComPtr<d3dl::PixelShader> m_ResolvePS, m_BicubicPS, m_NoisePS, m_NoiseOffsetPS;
  d3dl::ComPtr<d3dl::PixelShader> m_TAAPS, m_TAAFastPS, m_TAANoiseOffsetPS, m_TAANoiseOffsetFastPS,
      m_TAABasicPS;
  d3dl::ComPtr<d3dl::Buffer> m_PostCB;
  d3dl::ComPtr<d3dl::SamplerState> m_SamplerPoint, m_SamplerLinear, m_SamplerPointWrap;
  d3dl::ComPtr<d3dl::DepthStencilState> m_NoDepth;
  d3dl::ComPtr<d3dl::RasterizerState> m_NoCull;
  CubicFilterLookupTable m_CubicLookup;
  NoiseTexture m_Noise;
  ZoomBox m_ZoomBox;
  GuiRenderer m_GuiRenderer;
  GuiInput m_GuiInput;
  ImGuiContext* m_ImGui = nullptr;

  // Scene and cameras.
  std::unique_ptr<Scene> m_Scene;
  int m_Camera = 1;
  glm::vec3 m_FPPosition{0.f};
  float m_FPYaw = 0.f, m_FPPitch = 0.f, m_FPSpeed = 100.f;
  bool m_FPDragging = false;
  double m_LastCursor[2] = {0, 0};

  // Timing.
  AveragedGPUTimer m_TimerFrame{10}, m_TimerClear{10}, m_TimerScene{10}, m_TimerPostP{10},
      m_TimerScale{10};
  std::unique_ptr<ResolutionController> m_Controller;
  // Stale GPU results after a scale change (largest timer delay seen - 1),
  // told to the robust law as RobustController::Params::latencyFrames.
  int m_LawLatency = 0;
  size_t m_PostShadersCompiled = 0;  // by the last LoadShaders (0: .spv files)
  double m_RefreshHz = 60.0;
  std::chrono::steady_clock::time_point m_StartTime, m_LastFrameTime;
  std::array<double, 10> m_DeltaHistory{};  // SmoothedTimer: last 10 frame deltas
  int m_DeltaCount = 0;
  double m_AnimationTime = 0.0;
  double m_LastFrameSeconds = 1.0 / 60.0;
  SampleStats m_Stats;
  int64_t m_FrameCount = 0, m_MinimisedFrames = 0;
  std::vector<FrameRecord> m_Frames;
  std::map<std::string, uint64_t> m_PassesRun;

  // GUI state.
  bool m_ShowGUI = true, m_ShowText = true, m_ShowHelp = false;
  float m_ZoomCentre[2] = {-1.f, -1.f};
  std::array<float, 4> m_GuiStaticRect{0, 0, 0, 0};
  std::string m_LastMessage;

  // Captures.
  bool m_CaptureRequested = false;
  bool m_CaptureThisFrame = false;
  struct Pending {
    d3dl::ComPtr<d3dl::Texture2D> staging;
    int kind = 0;  // 0 back buffer, 1 back buffer without GUI, 2 scene colour, 3 velocity
  };
  std::vector<Pending> m_Pending;
  ImageRGBA8 m_CapBackBuffer, m_CapBackBufferNoGui, m_CapSceneColor;
  ImageRG32F m_CapVelocity;

  uint64_t m_ValidationAtInit = 0;
  std::function<double(double, double)> m_CostModel;
};

// The program: parses the command line, runs the sample, returns the exit code.
int SampleMain(int argc, char** argv);

}  // namespace drr
