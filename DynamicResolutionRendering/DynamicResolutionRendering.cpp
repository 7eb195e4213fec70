// The sample application (see DynamicResolutionRendering.h).
#include "DynamicResolutionRendering.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "d3dl/ShaderCompiler.h"
#include "scene/Scene.h"

#ifndef DRR_DEFAULT_SHADER_DIR
#define DRR_DEFAULT_SHADER_DIR "shaders"
#endif
#ifndef DRR_DEFAULT_SCENE
#define DRR_DEFAULT_SCENE "Media/Arena/scene_description.txt"
#endif

namespace drr {

namespace {

constexpr float kClearColor[4] = {0.0f, 0.1f, 0.1f, 1.0f};
constexpr float kZero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
constexpr float kMarkerColor[4] = {1.0f, 0.0f, 1.0f, 1.0f};     // magenta, never in the Arena
constexpr float kMarkerVelocity[4] = {0.5f, -0.5f, 0.0f, 0.0f}; // a huge velocity
constexpr uint32_t kMaxRTSize = 8192;                            // as the original

// Post-processing shaders: the sample's members and how the build compiles
// them (Shaders/PostProcess.cmake), so F4 can recompile the same SPIR-V.
struct PostShader {
  const char* name;    // <name>.spv in the shader folder
  const char* source;  // file in the shader source folder
  const char* entry;
  bool vertex;
  const char* define;  // nullptr or a macro defined as 1
};
constexpr PostShader kPostShaders[] = {
    {"PostProcessDynamic_FullScreenVS", "PostProcessDynamic.hlsl", "FullScreenVS", true, nullptr},
    {"PostProcess_FullScreenVS", "PostProcess.hlsl", "FullScreenVS", true, nullptr},
    {"PostProcessDynamic_ClearPS", "PostProcessDynamic.hlsl", "ClearPS", false, nullptr},
    {"PostProcessDynamic_ClearVelocityPS", "PostProcessDynamic.hlsl", "ClearPS", false, "CLEAR_VELOCITY"},
    {"PostProcessDynamic_MotionBlurPS", "PostProcessDynamic.hlsl", "MotionBlurPS", false, nullptr},
    {"PostProcess_ClearPS", "PostProcess.hlsl", "ClearPS", false, nullptr},
    {"PostProcess_ClearVelocityPS", "PostProcess.hlsl", "ClearPS", false, "CLEAR_VELOCITY"},
    {"PostProcess_MotionBlurPS", "PostProcess.hlsl", "MotionBlurPS", false, nullptr},
    {"PostProcessDynamic_ResolvePS", "PostProcessDynamic.hlsl", "ResolvePS", false, nullptr},
    {"PostProcessDynamic_BicubicPS", "PostProcessDynamic.hlsl", "BicubicPS", false, nullptr},
    {"PostProcessDynamic_NoisePS", "PostProcessDynamic.hlsl", "NoisePS", false, nullptr},
    {"PostProcessDynamic_NoiseOffsetPS", "PostProcessDynamic.hlsl", "NoiseOffsetPS", false, nullptr},
    {"PostProcessDynamic_TAAPS", "PostProcessDynamic.hlsl", "TAAPS", false, nullptr},
    {"PostProcessDynamic_TAAFastPS", "PostProcessDynamic.hlsl", "TAAPS", false, "TAA_FAST"},
    {"PostProcessDynamic_TAANoiseOffsetPS", "PostProcessDynamic.hlsl", "TAANoiseOffsetPS", false, nullptr},
    {"PostProcessDynamic_TAANoiseOffsetFastPS", "PostProcessDynamic.hlsl", "TAANoiseOffsetPS", false, "TAA_FAST"},
    {"PostProcessDynamic_TAABasicPS", "PostProcessDynamic.hlsl", "TAABasicPS", false, nullptr},
};

// SPIR-V of one post shader: compiled from <srcDir>/<source> when fromSources
// and the source exists (*compiled set), else read from <spvDir>/<name>.spv.
bool PostShaderCode(const PostShader& ps, bool fromSources, const std::string& srcDir,
                    const std::string& spvDir, std::vector<uint32_t>* code, bool* compiled,
                    std::string* error) {
  *compiled = false;
  const std::string src = srcDir + "/" + ps.source;
  if (fromSources && std::filesystem::exists(src)) {
    d3dl::ShaderCompileDesc d;
    d.SourcePath = src;
    d.EntryPoint = ps.entry;
    d.Stage = ps.vertex ? d3dl::ShaderStage::Vertex : d3dl::ShaderStage::Pixel;
    if (ps.define) d.Defines = {{ps.define, "1"}};
    std::string errs;
    if (d3dl::FAILED(d3dl::CompileHLSL(d, code, &errs))) {
      *error = std::string(ps.source) + " (" + ps.entry + (ps.define ? std::string(", ") + ps.define : "") +
               ") did not compile:\n" + errs;
      return false;
    }
    *compiled = true;
    return true;
  }
  return Utility::ReadFile(spvDir + "/" + ps.name + ".spv", code, error);
}

// Constants of PostProcessDynamic.hlsl (cbPostProcessDynamic).
struct DynamicConstants {
  float ratioCurr[2], ratioPrev[2];
  float jitterCurr[2], jitterPrev[2];
  float dynSize[2], invDynSize[2];
  float noiseOffset[2], backBufferSize[2];
  float clearColor[4];
};
static_assert(sizeof(DynamicConstants) == 80);

// Constants of PostProcess.hlsl (cbPostProcess).
struct FullConstants {
  float size[2], invSize[2];
  float clearColor[4];
  float pad[8];
};
static_assert(sizeof(FullConstants) == 64);

float HalfToFloat(uint16_t h) {
  const uint32_t sign = (h >> 15) & 1, exp = (h >> 10) & 0x1f, man = h & 0x3ff;
  float v;
  if (exp == 0)
    v = std::ldexp(float(man), -24);
  else if (exp == 31)
    v = man ? std::nanf("") : INFINITY;
  else
    v = std::ldexp(float(man | 0x400), int(exp) - 25);
  return sign ? -v : v;
}

std::string JsonString(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      o += ' ';
      continue;
    }
    o += c;
  }
  return o + "\"";
}

// A JSON number; JSON has no NaN/Inf, so those become null.
std::string JsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream o;
  o.precision(9);
  o << v;
  return o.str();
}

void LogToStderr(d3dl::LogLevel level, const char* message, void*) {
  const char* tag = level == d3dl::LogLevel::Validation ? "validation"
                    : level == d3dl::LogLevel::Error    ? "error"
                    : level == d3dl::LogLevel::Warning  ? "warning"
                                                        : "info";
  if (level != d3dl::LogLevel::Info) std::fprintf(stderr, "[d3dl %s] %s\n", tag, message);
}

void KeyThunk(void* user, int key, int action, int mods) {
  static_cast<Sample*>(user)->OnKey(key, action, mods);
}
void MouseThunk(void* user, int button, int action, double x, double y) {
  static_cast<Sample*>(user)->OnMouse(button, action, x, y);
}

d3dl::VIEWPORT ToViewport(const DynamicViewport& v) {
  d3dl::VIEWPORT o;
  o.TopLeftX = v.TopLeftX;
  o.TopLeftY = v.TopLeftY;
  o.Width = v.Width;
  o.Height = v.Height;
  o.MinDepth = v.MinDepth;
  o.MaxDepth = v.MaxDepth;
  return o;
}

}  // namespace

Sample::Sample() = default;
Sample::~Sample() { Shutdown(); }

// ---------------------------------------------------------------------------
// Set-up
int Sample::Init(const Options& options, std::string* error) {
  m_Options = options;
  m_ShowGUI = options.gui;
  const char* envShaders = std::getenv("DRR_SHADER_DIR");
  m_ShaderDir = !options.shaderDir.empty() ? options.shaderDir
                : (envShaders && *envShaders) ? envShaders
                                              : DRR_DEFAULT_SHADER_DIR;
  const char* envMedia = std::getenv("DRR_MEDIA_DIR");
  m_ScenePath = !options.scene.empty() ? options.scene
                : (envMedia && *envMedia) ? std::string(envMedia) + "/Arena/scene_description.txt"
                                          : DRR_DEFAULT_SCENE;
  if (!std::filesystem::exists(m_ScenePath)) {
    *error = "scene file not found: " + m_ScenePath;
    return 1;
  }

  // Headless when asked, or when there is no display, or GLFW cannot start.
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  m_Headless = options.headless || ((!display || !*display) && (!wayland || !*wayland));
  if (!m_Headless) {
    if (glfwInit() == GLFW_TRUE) {
      m_GlfwInitialised = true;
      if (!glfwVulkanSupported()) {
        std::fprintf(stderr, "GLFW: no Vulkan loader for windows; running headless\n");
        m_Headless = true;
      }
    } else {
      std::fprintf(stderr, "GLFW could not start; running headless\n");
      m_Headless = true;
    }
  }
  m_Options.headless = m_Headless;

  if (!CreateDeviceAndSwapChain(error)) return 1;
  if (!LoadShaders(error) || !CreateStates(error)) return 1;

  if (d3dl::FAILED(m_CubicLookup.Create(m_Device.Get())) ||
      d3dl::FAILED(m_Noise.Create(m_Device.Get()))) {
    *error = "cannot create the lookup/noise textures";
    return 1;
  }
  for (AveragedGPUTimer* t : {&m_TimerFrame, &m_TimerClear, &m_TimerScene, &m_TimerPostP, &m_TimerScale})
    if (d3dl::FAILED(t->Init(m_Device.Get()))) {
      *error = "cannot create the GPU timer queries";
      return 1;
    }

  SceneLoadOptions so;
  so.shaderDir = m_ShaderDir;
  // The original samples the scene with anisotropic x16. llvmpipe's
  // anisotropic filter walks the whole footprint and costs 3-30x at some
  // sizes (Docs/Lavapipe-Performance.md), so CPU rasterisers default to
  // trilinear; --anisotropy N chooses explicitly.
  so.maxAnisotropy = options.anisotropy > 0 ? uint32_t(options.anisotropy) : 16u;
  if (options.anisotropy == 0) {
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
    return 1;
  }
  if (options.camera >= CameraCount()) {
    *error = "option --camera: value " + std::to_string(options.camera) + " is out of range [0, " +
             std::to_string(CameraCount() - 1) + "]";
    return 2;
  }
  {
    const glm::vec3 lo = m_Scene->BoundsMin(), hi = m_Scene->BoundsMax();
    const float diag = glm::length(hi - lo);
    m_FPSpeed = std::isfinite(diag) && diag > 0 ? diag * 0.1f : 100.0f;
  }
  SelectCamera(options.camera >= 0 ? options.camera : m_Scene->DefaultCamera());

  // GUI.
  m_ImGui = ImGui::CreateContext();
  ImGui::SetCurrentContext(m_ImGui);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 1.0f;  // opaque panel
  if (!m_GuiRenderer.Init(m_Device.Get(), m_ShaderDir, error)) return 1;
  if (!m_ZoomBox.Init(m_Device.Get(), m_ShaderDir, error)) return 1;
  if (m_Window) m_GuiInput.Install(m_Window, this, KeyThunk, MouseThunk);

  // Resolution control.
  m_Controller = MakeController(m_Options.law, m_LawLatency);
  m_RefreshHz = options.refresh > 0 ? options.refresh : 60.0;
  if (options.refresh <= 0 && m_Window) {
    if (GLFWmonitor* mon = glfwGetPrimaryMonitor())
      if (const GLFWvidmode* mode = glfwGetVideoMode(mon); mode && mode->refreshRate > 0)
        m_RefreshHz = mode->refreshRate;
  }
  m_DynamicResolution.SetScale(options.scaleX, options.scaleY);
  if (!InitDynamicResolution()) {
    *error = "cannot create the render targets";
    return 1;
  }
  m_DynamicResolution.SetScale(options.scaleX, options.scaleY);
  if (options.fullscreen && m_Window) ToggleFullscreen();

  m_StartTime = m_LastFrameTime = std::chrono::steady_clock::now();
  d3dl::DEVICE_STATS st;
  m_Device->GetStats(&st);
  m_ValidationAtInit = st.ValidationMessages;
  return 0;
}

bool Sample::CreateDeviceAndSwapChain(std::string* error) {
  d3dl::DEVICE_CREATE_DESC dd;
  dd.Validation = m_Options.validation ? d3dl::ValidationMode::CoreAndSync
                                       : d3dl::ValidationMode::FromEnvironment;
  dd.Log = LogToStderr;
  dd.EnableWindowSurfaces = !m_Headless;
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
  if (!m_Headless) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    m_Window = glfwCreateWindow(int(m_Options.width), int(m_Options.height),
                                "Dynamic Resolution Rendering", nullptr, nullptr);
    if (!m_Window) {
      *error = "cannot create the window";
      return false;
    }
    glfwSetWindowUserPointer(m_Window, this);
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(m_Window, &fw, &fh);
    sd.Width = uint32_t(std::max(fw, 1));
    sd.Height = uint32_t(std::max(fh, 1));
    if (d3dl::FAILED(m_Device->CreateSwapChainForWindow(m_Window, &sd, m_SwapChain.GetAddressOf()))) {
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

bool Sample::CreateBackBufferViews() {
  if (d3dl::FAILED(m_SwapChain->GetBuffer(0, m_BackBuffer.ReleaseAndGetAddressOf()))) return false;
  if (d3dl::FAILED(m_Device->CreateRenderTargetView(m_BackBuffer.Get(), nullptr,
                                                    m_BackBufferRTV.ReleaseAndGetAddressOf())))
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

void Sample::ReleaseBackBufferViews() {
  m_BackBufferRTV = nullptr;
  m_BackBuffer = nullptr;
  m_ZoomBox.ReleaseCopy();
}

bool Sample::ResizeSwapChain(uint32_t w, uint32_t h) {
  m_Context->ClearState();
  ReleaseBackBufferViews();
  if (d3dl::FAILED(m_SwapChain->ResizeBuffers(0, w, h, m_BackBufferFormat, 0))) return false;
  if (!CreateBackBufferViews()) return false;
  m_ZoomCentre[0] = std::min(m_ZoomCentre[0], float(m_BackBufferWidth));
  m_ZoomCentre[1] = std::min(m_ZoomCentre[1], float(m_BackBufferHeight));
  ReleaseDynamicResolution();
  return InitDynamicResolution();
}

bool Sample::LoadShaders(std::string* error, bool fromSources) {
  d3dl::Device* dev = m_Device.Get();
  // Same order as kPostShaders.
  d3dl::ComPtr<d3dl::VertexShader>* vertex[] = {&m_FullScreenVS, &m_FullScreenFullVS};
  d3dl::ComPtr<d3dl::PixelShader>* pixel[] = {
      &m_ClearPS,   &m_ClearVelocityPS, &m_MotionBlurPS,  &m_FullClearPS,  &m_FullClearVelocityPS,
      &m_FullMotionBlurPS, &m_ResolvePS, &m_BicubicPS,   &m_NoisePS,      &m_NoiseOffsetPS,
      &m_TAAPS,     &m_TAAFastPS,       &m_TAANoiseOffsetPS, &m_TAANoiseOffsetFastPS, &m_TAABasicPS};
  static_assert(std::size(kPostShaders) == 17);
  const std::string srcDir = ShaderSourceDir();
  // Load everything first, replace only when all succeeded (F4 keeps the old set on error).
  std::vector<d3dl::ComPtr<d3dl::VertexShader>> vs(std::size(vertex));
  std::vector<d3dl::ComPtr<d3dl::PixelShader>> ps(std::size(pixel));
  size_t v = 0, p = 0, compiledCount = 0;
  for (const PostShader& sh : kPostShaders) {
    std::vector<uint32_t> code;
    bool compiled = false;
    if (!PostShaderCode(sh, fromSources, srcDir, m_ShaderDir, &code, &compiled, error)) return false;
    compiledCount += compiled;
    const d3dl::HRESULT hr =
        sh.vertex ? dev->CreateVertexShader(code.data(), code.size() * 4, vs[v++].GetAddressOf())
                  : dev->CreatePixelShader(code.data(), code.size() * 4, ps[p++].GetAddressOf());
    if (d3dl::FAILED(hr)) {
      *error = std::string(sh.vertex ? "CreateVertexShader(" : "CreatePixelShader(") + sh.name + ") failed";
      return false;
    }
  }
  for (size_t i = 0; i < vs.size(); ++i) *vertex[i] = vs[i];
  for (size_t i = 0; i < ps.size(); ++i) *pixel[i] = ps[i];
  m_PostShadersCompiled = compiledCount;
  return true;
}

std::string Sample::ShaderSourceDir() {
  const char* env = std::getenv("DRR_SHADER_SOURCE_DIR");
  if (env && *env) return env;
#ifdef DRR_SHADER_SOURCE_DIR
  return DRR_SHADER_SOURCE_DIR;  // set by the build
#else
  // The repository's Shaders folder, next to this file's folder.
  return (std::filesystem::path(__FILE__).parent_path().parent_path() / "Shaders").string();
#endif
}

bool Sample::CreateStates(std::string* error) {
  d3dl::Device* dev = m_Device.Get();
  d3dl::BUFFER_DESC cb;
  cb.ByteWidth = sizeof(DynamicConstants);
  cb.Usage = d3dl::USAGE_DYNAMIC;
  cb.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  cb.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  d3dl::SAMPLER_DESC point;
  point.Filter = d3dl::FILTER_MIN_LINEAR_MAG_MIP_POINT;
  d3dl::SAMPLER_DESC linear;
  linear.Filter = d3dl::FILTER_MIN_MAG_MIP_LINEAR;
  d3dl::SAMPLER_DESC wrap;
  wrap.Filter = d3dl::FILTER_MIN_MAG_MIP_POINT;
  wrap.AddressU = wrap.AddressV = wrap.AddressW = d3dl::TEXTURE_ADDRESS_WRAP;
  d3dl::DEPTH_STENCIL_DESC nd;
  nd.DepthEnable = 0;
  nd.DepthWriteMask = d3dl::DEPTH_WRITE_MASK_ZERO;
  d3dl::RASTERIZER_DESC rd;
  rd.CullMode = d3dl::CULL_NONE;
  if (d3dl::FAILED(dev->CreateBuffer(&cb, nullptr, m_PostCB.GetAddressOf())) ||
      d3dl::FAILED(dev->CreateSamplerState(&point, m_SamplerPoint.GetAddressOf())) ||
      d3dl::FAILED(dev->CreateSamplerState(&linear, m_SamplerLinear.GetAddressOf())) ||
      d3dl::FAILED(dev->CreateSamplerState(&wrap, m_SamplerPointWrap.GetAddressOf())) ||
      d3dl::FAILED(dev->CreateDepthStencilState(&nd, m_NoDepth.GetAddressOf())) ||
      d3dl::FAILED(dev->CreateRasterizerState(&rd, m_NoCull.GetAddressOf()))) {
    *error = "cannot create the post-processing states";
    return false;
  }
  return true;
}

bool Sample::ReloadShaders() {
  std::string err;
  // Nothing may still use the shaders that get replaced.
  m_Context->Flush();
  m_Device->WaitIdle();
  bool guiCompiled = false;
  bool ok = LoadShaders(&err, /*fromSources=*/true);
  ok = ok && m_GuiRenderer.ReloadShaders(m_ShaderDir, &err, ShaderSourceDir(), &guiCompiled);
  ok = ok && m_ZoomBox.ReloadShaders(m_ShaderDir, &err);
  ok = ok && m_Scene->ReloadShaders(&err);
  if (ok) {
    m_LastMessage = m_PostShadersCompiled > 0
                        ? "Shaders reloaded: " + std::to_string(m_PostShadersCompiled) +
                              " post-processing shaders" + (guiCompiled ? " and the GUI's" : "") +
                              " compiled from " + ShaderSourceDir()
                        : "Shaders reloaded from " + m_ShaderDir + " (no HLSL sources in " +
                              ShaderSourceDir() + ")";
  } else {
    m_LastMessage = "Shader reload failed, the previous shaders stay: " + err;
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

bool Sample::InitDynamicResolution() {
  ReleaseDynamicResolution();
  d3dl::Device* dev = m_Device.Get();
  const float maxScaling = m_Options.superSampling ? 2.0f : 1.0f;
  m_DynamicResolution.InitializeResolutionParameters(m_BackBufferWidth, m_BackBufferHeight, kMaxRTSize,
                                                     kMaxRTSize, maxScaling);
  const bool mb = m_Options.motionBlur, taa = TAAActive();
  bool ok = true;
  auto make = [&](Utility::RenderTarget& rt, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT f, const char* n) {
    ok = ok && d3dl::SUCCEEDED(rt.Create(dev, w, h, f, n));
  };
  if (m_Options.dynamicResolution) {
    const uint32_t w = m_DynamicResolution.GetDynamicBufferWidth();
    const uint32_t h = m_DynamicResolution.GetDynamicBufferHeight();
    make(g_DepthDynamic, w, h, d3dl::DXGI_FORMAT_D32_FLOAT, "g_DepthDynamic");
    make(g_FinalRTDynamic[0], w, h, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, "g_FinalRTDynamic[0]");
    if (taa) make(g_FinalRTDynamic[1], w, h, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, "g_FinalRTDynamic[1]");
    if (mb) make(g_ColorDynamic, w, h, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, "g_ColorDynamic");
    if (mb || taa) make(g_VelocityDynamic[0], w, h, d3dl::DXGI_FORMAT_R16G16_FLOAT, "g_VelocityDynamic[0]");
    // The fast TAA path reads velocity from the motion-blur alpha: one velocity target is enough.
    if (taa && !mb) make(g_VelocityDynamic[1], w, h, d3dl::DXGI_FORMAT_R16G16_FLOAT, "g_VelocityDynamic[1]");
  } else {
    const uint32_t w = m_BackBufferWidth, h = m_BackBufferHeight;
    make(g_DepthFull, w, h, d3dl::DXGI_FORMAT_D32_FLOAT, "g_DepthFull");
    if (mb) {
      make(g_ColorFull, w, h, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, "g_ColorFull");
      make(g_VelocityFull, w, h, d3dl::DXGI_FORMAT_R16G16_FLOAT, "g_VelocityFull");
    }
  }
  m_Allocated = {m_Options.dynamicResolution, m_Options.superSampling, mb, taa, m_BackBufferWidth,
                 m_BackBufferHeight};
  g_CurrentRT = 0;
  m_HistoryValid = false;
  m_ResetVelocityHistory = true;
  if (m_Controller) m_Controller->Reset();
  return ok;
}

void Sample::ReleaseDynamicResolution() {
  for (Utility::RenderTarget* rt : {&g_ColorDynamic, &g_DepthDynamic, &g_VelocityDynamic[0],
                                    &g_VelocityDynamic[1], &g_FinalRTDynamic[0], &g_FinalRTDynamic[1],
                                    &g_ColorFull, &g_VelocityFull, &g_DepthFull})
    rt->Release();
  m_Allocated = {};
}

uint64_t Sample::RenderTargetBytes() const {
  uint64_t b = 0;
  for (const Utility::RenderTarget* rt : {&g_ColorDynamic, &g_DepthDynamic, &g_VelocityDynamic[0],
                                          &g_VelocityDynamic[1], &g_FinalRTDynamic[0],
                                          &g_FinalRTDynamic[1], &g_ColorFull, &g_VelocityFull,
                                          &g_DepthFull})
    b += rt->Bytes();
  return b + m_ZoomBox.Bytes();
}

// ---------------------------------------------------------------------------
// Settings and input
void Sample::ApplySettings(const Options& o) {
  const bool scaleChanged = o.scaleX != m_Options.scaleX || o.scaleY != m_Options.scaleY ||
                            o.superSampling != m_Options.superSampling;
  const int camera = o.camera;
  Options keep = m_Options;
  m_Options = o;
  m_Options.headless = keep.headless;
  m_Options.width = keep.width;
  m_Options.height = keep.height;
  m_ShowGUI = o.gui;
  if (o.refresh > 0) m_RefreshHz = o.refresh;
  if (o.law != keep.law || !m_Controller)  // switching resets the law
    m_Controller = MakeController(m_Options.law, m_LawLatency);
  else if (o.control != keep.control) m_Controller->Reset();
  if (camera >= 0 && camera < CameraCount() && camera != m_Camera) SelectCamera(camera);
  AllocationKey want{m_Options.dynamicResolution, m_Options.superSampling, m_Options.motionBlur,
                     TAAActive(), m_BackBufferWidth, m_BackBufferHeight};
  if (!(want == m_Allocated)) InitDynamicResolution();
  if (scaleChanged || m_Options.control == ControlMode::Manual)
    m_DynamicResolution.SetScale(m_Options.scaleX, m_Options.scaleY);
}

int Sample::SceneCameraCount() const { return m_Scene ? m_Scene->CameraCount() : 0; }
int Sample::CameraCount() const { return SceneCameraCount() + 1; }
std::string Sample::CameraName(int i) const {
  return i < SceneCameraCount() ? m_Scene->CameraName(i) : std::string("First Person");
}

void Sample::SelectCamera(int i) {
  const int prev = m_Camera;
  i = std::clamp(i, 0, CameraCount() - 1);
  if (i == SceneCameraCount() && prev < SceneCameraCount() && SceneCameraCount() > 0) {
    // First Person starts where the previous camera was.
    const CameraPose pose = m_Scene->Camera(std::max(prev, 0));
    const glm::mat4 inv = glm::inverse(pose.view);
    m_FPPosition = glm::vec3(inv[3]);
    const glm::vec3 fwd = -glm::normalize(glm::vec3(inv[2]));
    m_FPYaw = std::atan2(fwd.x, -fwd.z);
    m_FPPitch = std::asin(std::clamp(fwd.y, -1.0f, 1.0f));
  }
  if (i != m_Camera) m_ResetVelocityHistory = true;  // camera cut
  m_Camera = i;
  m_Options.camera = i;
}

void Sample::UpdateFirstPersonCamera(double elapsed) {
  if (!m_Window || m_Camera != SceneCameraCount()) return;
  double x = 0, y = 0;
  glfwGetCursorPos(m_Window, &x, &y);
  if (m_FPDragging) {
    if (glfwGetMouseButton(m_Window, GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS) {
      m_FPDragging = false;
    } else {
      m_FPYaw += float(x - m_LastCursor[0]) * 0.005f;
      m_FPPitch = std::clamp(m_FPPitch - float(y - m_LastCursor[1]) * 0.005f, -1.5f, 1.5f);
    }
  }
  m_LastCursor[0] = x;
  m_LastCursor[1] = y;
  if (GuiInput::WantsKeyboard()) return;
  const glm::vec3 fwd(std::sin(m_FPYaw) * std::cos(m_FPPitch), std::sin(m_FPPitch),
                      -std::cos(m_FPYaw) * std::cos(m_FPPitch));
  const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
  glm::vec3 move(0.f);
  if (glfwGetKey(m_Window, GLFW_KEY_W) == GLFW_PRESS) move += fwd;
  if (glfwGetKey(m_Window, GLFW_KEY_S) == GLFW_PRESS) move -= fwd;
  if (glfwGetKey(m_Window, GLFW_KEY_D) == GLFW_PRESS) move += right;
  if (glfwGetKey(m_Window, GLFW_KEY_A) == GLFW_PRESS) move -= right;
  const float speed = m_FPSpeed * ((glfwGetKey(m_Window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS) ? 4.f : 1.f);
  m_FPPosition += move * speed * float(elapsed);
}

void Sample::OnKey(int key, int action, int mods) {
  if (action != GLFW_PRESS) return;
  switch (key) {
    case GLFW_KEY_F1: m_ShowHelp = !m_ShowHelp; break;
    case GLFW_KEY_F2: ToggleFullscreen(); break;
    case GLFW_KEY_F4: (void)ReloadShaders(); break;
    case GLFW_KEY_F10: m_ShowGUI = !m_ShowGUI; break;
    case GLFW_KEY_F11: m_ShowText = !m_ShowText; break;
    case GLFW_KEY_P: m_Options.pause = !m_Options.pause; break;
    case GLFW_KEY_Z: m_Options.zoom = !m_Options.zoom; break;
    case GLFW_KEY_ESCAPE:
      if (m_Window) glfwSetWindowShouldClose(m_Window, GLFW_TRUE);
      break;
    default: break;
  }
}

void Sample::OnMouse(int button, int action, double x, double y) {
  if (!m_Window) return;
  int ww = 1, wh = 1, fw = 1, fh = 1;
  glfwGetWindowSize(m_Window, &ww, &wh);
  glfwGetFramebufferSize(m_Window, &fw, &fh);
  if (button == GLFW_MOUSE_BUTTON_RIGHT && action == GLFW_PRESS) {
    m_ZoomCentre[0] = float(x) * fw / std::max(ww, 1);
    m_ZoomCentre[1] = float(y) * fh / std::max(wh, 1);
  }
  if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS) {
    m_FPDragging = true;
    m_LastCursor[0] = x;
    m_LastCursor[1] = y;
  }
}

bool Sample::WindowShown() const {
  return m_Window && glfwGetWindowAttrib(m_Window, GLFW_VISIBLE) && !glfwGetWindowAttrib(m_Window, GLFW_ICONIFIED);
}

void Sample::ToggleFullscreen() {
  if (!m_Window) return;
  // GLFW 3.3's X11 backend maps a hidden window before going full screen and
  // waits for it to become visible; that wait never times out while unrelated
  // events are queued, so a toggle while minimised would spin forever. Defer
  // the toggle until the window is shown again.
  if (!WindowShown()) {
    m_FullscreenTogglePending = !m_FullscreenTogglePending;
    return;
  }
  m_FullscreenTogglePending = false;
  if (!m_Fullscreen) {
    GLFWmonitor* mon = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = mon ? glfwGetVideoMode(mon) : nullptr;
    if (!mode) return;
    glfwGetWindowPos(m_Window, &m_WindowedPos[0], &m_WindowedPos[1]);
    glfwGetWindowSize(m_Window, &m_WindowedSize[0], &m_WindowedSize[1]);
    glfwSetWindowMonitor(m_Window, mon, 0, 0, mode->width, mode->height, mode->refreshRate);
    m_Fullscreen = true;
  } else {
    glfwSetWindowMonitor(m_Window, nullptr, m_WindowedPos[0], m_WindowedPos[1], m_WindowedSize[0],
                         m_WindowedSize[1], GLFW_DONT_CARE);
    m_Fullscreen = false;
  }
}

// ---------------------------------------------------------------------------
// Per frame
void Sample::OnFrameMove(double time, double elapsed) {
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
  UpdateFirstPersonCamera(elapsed);

  // Flip the final/velocity targets each frame for TAA (precedence bug of the
  // original fixed: only with a TAA mode and dynamic resolution on). The jitter
  // is tied to the target index, so a paused scene keeps both targets stable:
  // the un-jittered frame always lands in the same target (no flicker).
  if (TAAActive()) g_CurrentRT = 1 - g_CurrentRT;
  else g_CurrentRT = 0;
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

void Sample::UpdateStats() {
  m_Stats.frameMs = m_TimerFrame.AverageMs();
  m_Stats.clearMs = m_TimerClear.AverageMs();
  m_Stats.sceneMs = m_TimerScene.AverageMs();
  m_Stats.postPMs = m_TimerPostP.AverageMs();
  m_Stats.scaleMs = m_TimerScale.AverageMs();
  double budget = 1000.0 / m_RefreshHz;
  if (m_Options.control == ControlMode::HalfVSync) budget *= 2.0;
  m_Stats.vsyncMs = budget;
  m_Stats.fps = m_LastFrameSeconds > 0 ? 1.0 / m_LastFrameSeconds : 0.0;
  m_Stats.scaleX = m_DynamicResolution.GetScaleX();
  m_Stats.scaleY = m_DynamicResolution.GetScaleY();
}

void Sample::SetPostConstants(const void* data, size_t size) {
  d3dl::MAPPED_SUBRESOURCE m;
  if (d3dl::SUCCEEDED(m_Context->Map(m_PostCB.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &m))) {
    std::memcpy(m.pData, data, size);
    m_Context->Unmap(m_PostCB.Get(), 0);
  }
}

void Sample::DrawFullScreen(d3dl::PixelShader* ps) {
  d3dl::DeviceContext* ctx = m_Context.Get();
  ctx->IASetInputLayout(nullptr);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  ctx->RSSetState(m_NoCull.Get());
  ctx->OMSetDepthStencilState(m_NoDepth.Get(), 0);
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  ctx->VSSetConstantBuffers(0, 1, m_PostCB.GetAddressOf());
  ctx->PSSetConstantBuffers(0, 1, m_PostCB.GetAddressOf());
  ctx->PSSetShader(ps);
  ctx->Draw(3, 0);
}

void Sample::UnbindPixelSRVs() {
  d3dl::ShaderResourceView* none[6] = {};
  m_Context->PSSetShaderResources(0, 6, none);
}

void Sample::OnFrameRender(double elapsed) {
  d3dl::DeviceContext* ctx = m_Context.Get();
  const bool dynamic = m_Options.dynamicResolution;

  // Re-create the targets when an option that decides them changed (GUI).
  AllocationKey want{dynamic, m_Options.superSampling, m_Options.motionBlur, TAAActive(),
                     m_BackBufferWidth, m_BackBufferHeight};
  if (!(want == m_Allocated)) {
    InitDynamicResolution();
    if (TAAActive()) g_CurrentRT = 1;
  }
  const bool taa = TAAActive();
  const bool mb = m_Options.motionBlur;

  // 1. Timers and resolution control.
  bool newAverage = m_TimerFrame.Update(ctx);
  m_TimerClear.Update(ctx);
  m_TimerScene.Update(ctx);
  m_TimerPostP.Update(ctx);
  m_TimerScale.Update(ctx);
  if (newAverage || m_FrameCount % 10 == 0) UpdateStats();
  if (dynamic && m_Options.control != ControlMode::Manual) {
    if (m_Options.law == ControlLaw::Article) {
      // The original: every frame, on the 10-result average of the inner-frame timer.
      if (m_TimerFrame.ResultCount() > 0)
        ControlResolution(m_TimerFrame.AverageMs() / 1000.0, m_LastFrameSeconds);
    } else if (m_TimerFrame.NewResults() > 0) {
      // Per-frame laws: one call per new inner-frame result. A result polled
      // d frames after its Start leaves d - 1 results of the old scale after a
      // change; the robust law is told the largest such count seen.
      const int stale = std::max(0, int(m_TimerFrame.LastDelayFrames()) - 1);
      if (m_Options.law == ControlLaw::Robust && stale > m_LawLatency) {
        m_LawLatency = stale;
        m_Controller = MakeController(m_Options.law, m_LawLatency);
      }
      ControlResolution(m_TimerFrame.LastMs() / 1000.0, m_LastFrameSeconds);
    }
  }

  // 2. TAA jitter and RT ratios: keep last frame's as "previous".
  m_JitterPrev = m_JitterCurr;
  m_RatioPrev = m_RatioCurr;
  const DynamicViewport dvp = m_DynamicResolution.GetViewport();
  const d3dl::VIEWPORT sceneViewport =
      dynamic ? ToViewport(dvp)
              : d3dl::VIEWPORT{0, 0, float(m_BackBufferWidth), float(m_BackBufferHeight), 0, 1};
  m_RatioCurr = dynamic ? glm::vec2(m_DynamicResolution.GetRTScaleX(), m_DynamicResolution.GetRTScaleY())
                        : glm::vec2(1.f);
  if (taa) {
    static const glm::vec2 kAsymmetric[2] = {{0.0f, 0.0f}, {0.5f, 0.5f}};
    static const glm::vec2 kSymmetric[2] = {{-0.25f, -0.25f}, {0.25f, 0.25f}};
    const glm::vec2 px = (m_Options.symmetricTAA ? kSymmetric : kAsymmetric)[g_CurrentRT];
    m_JitterCurr = px / glm::vec2(sceneViewport.Width, sceneViewport.Height);
  } else {
    m_JitterCurr = glm::vec2(0.f);
  }
  if (!m_HistoryValid) {
    m_JitterPrev = m_JitterCurr;
    m_RatioPrev = m_RatioCurr;
  }
  const int cur = g_CurrentRT;
  const int prev = (taa && m_HistoryValid) ? 1 - cur : cur;

  // Camera.
  glm::mat4 view;
  float fovY = glm::radians(45.f), nearZ = 20.f, farZ = 400000.f;
  if (m_Camera < SceneCameraCount()) {
    const CameraPose pose = m_Scene->Camera(m_Camera);
    view = pose.view;
    fovY = pose.fovY;
    nearZ = pose.nearZ;
    farZ = pose.farZ;
  } else {
    const glm::vec3 fwd(std::sin(m_FPYaw) * std::cos(m_FPPitch), std::sin(m_FPPitch),
                        -std::cos(m_FPYaw) * std::cos(m_FPPitch));
    view = glm::lookAtRH(m_FPPosition, m_FPPosition + fwd, glm::vec3(0, 1, 0));
  }
  const float aspect = float(std::max(m_BackBufferWidth, 1u)) / float(std::max(m_BackBufferHeight, 1u));

  // 3. Scene targets.
  d3dl::RenderTargetView* sceneRTV[2] = {nullptr, nullptr};
  d3dl::Texture2D* sceneColorTex = nullptr;
  d3dl::Texture2D* sceneVelocityTex = nullptr;
  d3dl::DepthStencilView* dsv = nullptr;
  int velIndex = 0;
  if (dynamic) {
    Utility::RenderTarget& colour = mb ? g_ColorDynamic : g_FinalRTDynamic[cur];
    sceneRTV[0] = colour.rtv.Get();
    sceneColorTex = colour.texture.Get();
    velIndex = (taa && !mb) ? cur : 0;
    if (mb || taa) {
      sceneRTV[1] = g_VelocityDynamic[velIndex].rtv.Get();
      sceneVelocityTex = g_VelocityDynamic[velIndex].texture.Get();
    }
    dsv = g_DepthDynamic.dsv.Get();
  } else {
    sceneRTV[0] = mb ? g_ColorFull.rtv.Get() : m_BackBufferRTV.Get();
    sceneColorTex = mb ? g_ColorFull.texture.Get() : m_BackBuffer.Get();
    if (mb) {
      sceneRTV[1] = g_VelocityFull.rtv.Get();
      sceneVelocityTex = g_VelocityFull.texture.Get();
    }
    dsv = g_DepthFull.dsv.Get();
  }
  const uint32_t numSceneRT = sceneRTV[1] ? 2 : 1;

  const float dynW = float(m_DynamicResolution.GetDynamicBufferWidth());
  const float dynH = float(m_DynamicResolution.GetDynamicBufferHeight());
  DynamicConstants dc{};
  dc.ratioCurr[0] = m_RatioCurr.x;
  dc.ratioCurr[1] = m_RatioCurr.y;
  dc.ratioPrev[0] = m_RatioPrev.x;
  dc.ratioPrev[1] = m_RatioPrev.y;
  dc.jitterCurr[0] = m_JitterCurr.x;
  dc.jitterCurr[1] = m_JitterCurr.y;
  dc.jitterPrev[0] = m_JitterPrev.x;
  dc.jitterPrev[1] = m_JitterPrev.y;
  dc.dynSize[0] = dynW;
  dc.dynSize[1] = dynH;
  dc.invDynSize[0] = 1.0f / dynW;
  dc.invDynSize[1] = 1.0f / dynH;
  dc.noiseOffset[0] = float(std::rand() % 128);
  dc.noiseOffset[1] = float(std::rand() % 128);
  dc.backBufferSize[0] = float(m_BackBufferWidth);
  dc.backBufferSize[1] = float(m_BackBufferHeight);
  std::memcpy(dc.clearColor, kClearColor, sizeof kClearColor);
  FullConstants fc{};
  fc.size[0] = float(m_BackBufferWidth);
  fc.size[1] = float(m_BackBufferHeight);
  fc.invSize[0] = 1.0f / fc.size[0];
  fc.invSize[1] = 1.0f / fc.size[1];
  std::memcpy(fc.clearColor, kClearColor, sizeof kClearColor);

  m_TimerFrame.Start(ctx);

  // Test aid: mark everything outside the viewport.
  if (dynamic && m_Options.debugMarkerOutside) {
    ctx->ClearRenderTargetView(sceneRTV[0], kMarkerColor);
    if (sceneRTV[1]) ctx->ClearRenderTargetView(sceneRTV[1], kMarkerVelocity);
    ctx->ClearRenderTargetView(g_FinalRTDynamic[cur].rtv.Get(), kMarkerColor);
  }
  // None (debug) shows the whole RT: clear the final target to zero first.
  if (dynamic && m_Options.filter == Filter::None) {
    ctx->ClearRenderTargetView(g_FinalRTDynamic[cur].rtv.Get(), kZero);
    CountPass("ClearFinalNone");
  }

  // 4. Clear. Depth always with the API (it may be hierarchical).
  ctx->BeginEvent("Clear");
  m_TimerClear.Start(ctx);
  ctx->ClearDepthStencilView(dsv, d3dl::CLEAR_DEPTH, 1.0f, 0);
  if (m_Options.psClear) {
    ctx->OMSetRenderTargets(numSceneRT, sceneRTV, nullptr);
    ctx->RSSetViewports(1, &sceneViewport);
    if (dynamic) {
      SetPostConstants(&dc, sizeof dc);
      ctx->VSSetShader(m_FullScreenVS.Get());
      DrawFullScreen(numSceneRT == 2 ? m_ClearVelocityPS.Get() : m_ClearPS.Get());
    } else {
      SetPostConstants(&fc, sizeof fc);
      ctx->VSSetShader(m_FullScreenFullVS.Get());
      DrawFullScreen(numSceneRT == 2 ? m_FullClearVelocityPS.Get() : m_FullClearPS.Get());
    }
    CountPass("ClearPS");
  } else {
    d3dl::RECT r;
    r.right = int32_t(sceneViewport.Width);
    r.bottom = int32_t(sceneViewport.Height);
    ctx->ClearView(sceneRTV[0], kClearColor, &r, 1);
    if (sceneRTV[1]) ctx->ClearView(sceneRTV[1], kZero, &r, 1);
    CountPass("ClearAPI");
  }
  m_TimerClear.Stop(ctx);
  ctx->EndEvent();

  // 5. Scene.
  ctx->BeginEvent("Scene");
  m_TimerScene.Start(ctx);
  ctx->OMSetRenderTargets(numSceneRT, sceneRTV, dsv);
  ctx->RSSetViewports(1, &sceneViewport);
  SceneRenderParams sp;
  sp.view = view;
  sp.proj = glm::perspectiveRH_ZO(fovY, aspect, nearZ, farZ);
  // Jitter in pixels (x right, y down) -> NDC (+Y up).
  sp.jitterNdc = glm::vec2(2.0f * m_JitterCurr.x, -2.0f * m_JitterCurr.y);
  sp.mipBiasSampler = taa;
  sp.writeVelocity = numSceneRT == 2;
  sp.resetHistory = m_ResetVelocityHistory;
  sp.showCameras = m_Options.showCameras;
  m_Scene->Render(ctx, sp);
  m_ResetVelocityHistory = false;
  m_TimerScene.Stop(ctx);
  ctx->EndEvent();
  CountPass("Scene");
  if (m_CaptureThisFrame) {
    ctx->OMSetRenderTargets(0, nullptr, nullptr);
    QueueCopy(sceneColorTex, 2);
    if (sceneVelocityTex) QueueCopy(sceneVelocityTex, 3);
  }

  // 6. Motion blur into the final target (dynamic) or the back buffer (full).
  m_TimerPostP.Start(ctx);
  if (mb) {
    ctx->BeginEvent("MotionBlur");
    if (dynamic) {
      d3dl::RenderTargetView* rtv = g_FinalRTDynamic[cur].rtv.Get();
      ctx->OMSetRenderTargets(1, &rtv, nullptr);
      ctx->RSSetViewports(1, &sceneViewport);
      SetPostConstants(&dc, sizeof dc);
      d3dl::ShaderResourceView* srv[3] = {g_ColorDynamic.srv.Get(), nullptr, g_VelocityDynamic[0].srv.Get()};
      ctx->PSSetShaderResources(0, 3, srv);
      ctx->PSSetSamplers(1, 1, m_SamplerLinear.GetAddressOf());
      ctx->VSSetShader(m_FullScreenVS.Get());
      DrawFullScreen(m_MotionBlurPS.Get());
      CountPass("MotionBlurDynamic");
    } else {
      d3dl::RenderTargetView* rtv = m_BackBufferRTV.Get();
      ctx->OMSetRenderTargets(1, &rtv, nullptr);
      ctx->RSSetViewports(1, &sceneViewport);
      SetPostConstants(&fc, sizeof fc);
      d3dl::ShaderResourceView* srv[3] = {g_ColorFull.srv.Get(), nullptr, g_VelocityFull.srv.Get()};
      ctx->PSSetShaderResources(0, 3, srv);
      ctx->PSSetSamplers(1, 1, m_SamplerLinear.GetAddressOf());
      ctx->VSSetShader(m_FullScreenFullVS.Get());
      DrawFullScreen(m_FullMotionBlurPS.Get());
      CountPass("MotionBlurFull");
    }
    UnbindPixelSRVs();
    ctx->EndEvent();
  }
  m_TimerPostP.Stop(ctx);

  // 7. Scale / resolve into the back buffer.
  d3dl::VIEWPORT bbViewport{0, 0, float(m_BackBufferWidth), float(m_BackBufferHeight), 0, 1};
  m_TimerScale.Start(ctx);
  if (dynamic) {
    ctx->BeginEvent("Scale");
    d3dl::RenderTargetView* rtv = m_BackBufferRTV.Get();
    ctx->OMSetRenderTargets(1, &rtv, nullptr);
    ctx->RSSetViewports(1, &bbViewport);
    DynamicConstants rc = dc;
    if (m_Options.filter == Filter::None) {
      rc.ratioCurr[0] = rc.ratioCurr[1] = rc.ratioPrev[0] = rc.ratioPrev[1] = 1.0f;
    }
    SetPostConstants(&rc, sizeof rc);
    const bool velocityTAA = taa && !mb;
    d3dl::ShaderResourceView* srv[6] = {
        g_FinalRTDynamic[cur].srv.Get(),
        taa ? g_FinalRTDynamic[prev].srv.Get() : nullptr,
        velocityTAA ? g_VelocityDynamic[cur].srv.Get() : nullptr,
        velocityTAA ? g_VelocityDynamic[prev].srv.Get() : nullptr,
        m_Noise.GetSRV(),
        m_CubicLookup.GetSRV()};
    ctx->PSSetShaderResources(0, 6, srv);
    d3dl::SamplerState* samplers[3] = {
        m_Options.filter == Filter::Bilinear ? m_SamplerLinear.Get() : m_SamplerPoint.Get(),
        m_SamplerLinear.Get(), m_SamplerPointWrap.Get()};
    ctx->PSSetSamplers(0, 3, samplers);
    d3dl::PixelShader* ps = m_ResolvePS.Get();
    const char* pass = "ResolvePoint";
    switch (m_Options.filter) {
      case Filter::None: pass = "ResolveNone"; break;
      case Filter::Point: break;
      case Filter::Bilinear: pass = "ResolveBilinear"; break;
      case Filter::Bicubic: ps = m_BicubicPS.Get(); pass = "ResolveBicubic"; break;
      case Filter::Noise: ps = m_NoisePS.Get(); pass = "ResolveNoise"; break;
      case Filter::NoiseOffset: ps = m_NoiseOffsetPS.Get(); pass = "ResolveNoiseOffset"; break;
      case Filter::TAA:
        ps = mb ? m_TAAFastPS.Get() : m_TAAPS.Get();
        pass = mb ? "ResolveTAAFast" : "ResolveTAA";
        break;
      case Filter::TAANoiseOffset:
        ps = mb ? m_TAANoiseOffsetFastPS.Get() : m_TAANoiseOffsetPS.Get();
        pass = mb ? "ResolveTAANoiseOffsetFast" : "ResolveTAANoiseOffset";
        break;
      case Filter::TAABasic: ps = m_TAABasicPS.Get(); pass = "ResolveTAABasic"; break;
      default: break;
    }
    ctx->VSSetShader(m_FullScreenVS.Get());
    DrawFullScreen(ps);
    UnbindPixelSRVs();
    CountPass(pass);
    ctx->EndEvent();
    if (taa) m_HistoryValid = true;
  }
  m_TimerScale.Stop(ctx);
  m_TimerFrame.Stop(ctx);

  // 8. Zoom box, then the GUI at back-buffer resolution.
  if (m_Options.zoom) {
    ctx->BeginEvent("ZoomBox");
    ctx->OMSetRenderTargets(0, nullptr, nullptr);
    m_ZoomBox.Render(ctx, m_BackBuffer.Get(), m_BackBufferRTV.Get(), m_BackBufferWidth,
                     m_BackBufferHeight, m_ZoomCentre[0], m_ZoomCentre[1]);
    ctx->EndEvent();
    CountPass("ZoomBox");
  }
  if (m_CaptureThisFrame) {
    ctx->OMSetRenderTargets(0, nullptr, nullptr);
    QueueCopy(m_BackBuffer.Get(), 1);
  }

  m_GuiInput.NewFrame(m_Window, float(m_BackBufferWidth), float(m_BackBufferHeight), float(elapsed));
  ImGui::NewFrame();
  if (m_ShowGUI) {
    RenderGUI();
    RenderText();
  }
  ImGui::Render();
  if (m_ShowGUI) {
    ctx->BeginEvent("GUI");
    d3dl::RenderTargetView* rtv = m_BackBufferRTV.Get();
    ctx->OMSetRenderTargets(1, &rtv, nullptr);
    ctx->RSSetViewports(1, &bbViewport);
    m_GuiRenderer.Render(ctx, ImGui::GetDrawData());
    ctx->EndEvent();
    CountPass("GUI");
  }
  if (m_CaptureThisFrame) {
    ctx->OMSetRenderTargets(0, nullptr, nullptr);
    QueueCopy(m_BackBuffer.Get(), 0);
  }
  ctx->OMSetRenderTargets(0, nullptr, nullptr);
}

// ---------------------------------------------------------------------------
// GUI (mirrors the original's panel)
void Sample::RenderGUI() {
  const float panelW = 300.0f;
  ImGui::SetNextWindowPos(ImVec2(float(m_BackBufferWidth) - panelW - 10.0f, 10.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(panelW, 0.0f), ImGuiCond_Always);
  ImGui::Begin("Dynamic Resolution Rendering", nullptr,
               ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  const ImVec2 top = ImGui::GetWindowPos();
  Options o = m_Options;
  ImGui::Checkbox("Pause (P)", &o.pause);
  ImGui::Checkbox("Show cameras", &o.showCameras);
  ImGui::Checkbox("Motion blur", &o.motionBlur);
  ImGui::Checkbox("Zoom box (Z)", &o.zoom);
  int cam = m_Camera;
  const std::string camName = CameraName(cam);
  if (ImGui::BeginCombo("Camera", camName.c_str())) {
    for (int i = 0; i < CameraCount(); ++i)
      if (ImGui::Selectable(CameraName(i).c_str(), i == cam)) cam = i;
    ImGui::EndCombo();
  }
  o.camera = cam;
  ImGui::Checkbox("Clear with pixel shader", &o.psClear);
  ImGui::Checkbox("Dynamic resolution", &o.dynamicResolution);
  ImGui::Checkbox("Allow super sampling", &o.superSampling);
  ImGui::Checkbox("Lock aspect ratio", &o.aspectLock);
  int filter = static_cast<int>(o.filter);
  if (ImGui::BeginCombo("Filter", FilterName(o.filter))) {
    for (int i = 0; i < static_cast<int>(Filter::Count); ++i)
      if (ImGui::Selectable(FilterName(static_cast<Filter>(i)), i == filter)) filter = i;
    ImGui::EndCombo();
  }
  o.filter = static_cast<Filter>(filter);
  ImGui::Checkbox("Symmetric TAA", &o.symmetricTAA);
  int control = static_cast<int>(o.control);
  if (ImGui::BeginCombo("Control", ControlModeName(o.control))) {
    for (int i = 0; i < static_cast<int>(ControlMode::Count); ++i)
      if (ImGui::Selectable(ControlModeName(static_cast<ControlMode>(i)), i == control)) control = i;
    ImGui::EndCombo();
  }
  o.control = static_cast<ControlMode>(control);
  int law = static_cast<int>(o.law);
  if (ImGui::BeginCombo("Control law", ControlLawName(o.law))) {
    for (int i = 0; i < static_cast<int>(ControlLaw::Count); ++i)
      if (ImGui::Selectable(ControlLawName(static_cast<ControlLaw>(i)), i == law)) law = i;
    ImGui::EndCombo();
  }
  o.law = static_cast<ControlLaw>(law);
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  m_GuiStaticRect = {top.x, top.y, top.x + panelW, cursor.y - 2.0f};

  // Scales (the controller overrides them unless Manual).
  const float maxPct = o.superSampling ? 200.0f : 100.0f;
  float sx = m_DynamicResolution.GetScaleX() * 100.0f, sy = m_DynamicResolution.GetScaleY() * 100.0f;
  bool scaleEdited = ImGui::SliderFloat("Scale X %", &sx, 1.0f, maxPct, "%.1f");
  scaleEdited |= ImGui::SliderFloat("Scale Y %", &sy, 1.0f, maxPct, "%.1f");
  if (scaleEdited) {
    if (o.aspectLock) sy = sx;
    o.scaleX = std::clamp(sx, 1.0f, maxPct) / 100.0f;
    o.scaleY = std::clamp(sy, 1.0f, maxPct) / 100.0f;
  }
  ImGui::Separator();
  ImGui::Text("Frame %6.2f ms   Clear %6.2f ms", m_Stats.frameMs, m_Stats.clearMs);
  ImGui::Text("Scene %6.2f ms   PostP %6.2f ms", m_Stats.sceneMs, m_Stats.postPMs);
  ImGui::Text("Scale %6.2f ms   VSync %6.2f ms", m_Stats.scaleMs, m_Stats.vsyncMs);
  ImGui::Text("Scale X %.1f %%  Y %.1f %%", m_Stats.scaleX * 100.0f, m_Stats.scaleY * 100.0f);
  ImGui::End();

  const bool changed = o.pause != m_Options.pause || o.showCameras != m_Options.showCameras || o.motionBlur != m_Options.motionBlur ||
                       o.zoom != m_Options.zoom || o.camera != m_Options.camera ||
                       o.psClear != m_Options.psClear || o.dynamicResolution != m_Options.dynamicResolution ||
                       o.superSampling != m_Options.superSampling || o.aspectLock != m_Options.aspectLock ||
                       o.filter != m_Options.filter || o.symmetricTAA != m_Options.symmetricTAA ||
                       o.control != m_Options.control || o.law != m_Options.law || scaleEdited;
  if (changed) {
    if (!scaleEdited) {
      o.scaleX = m_DynamicResolution.GetScaleX();
      o.scaleY = m_DynamicResolution.GetScaleY();
    }
    ApplySettings(o);
  }

  if (m_ShowHelp) {
    ImGui::SetNextWindowPos(ImVec2(10.0f, float(m_BackBufferHeight) * 0.5f), ImGuiCond_FirstUseEver);
    ImGui::Begin("Help", &m_ShowHelp, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted(
        "F1  help\nF2  fullscreen\nF4  reload shaders\nF10 GUI\nF11 text\nP   pause\nZ   zoom box\n"
        "Right mouse: zoom centre\nFirst Person camera: WASD + left mouse drag\nEsc quit");
    ImGui::End();
  }
}

void Sample::RenderText() {
  if (!m_ShowText) return;
  ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.35f);
  ImGui::Begin("##stats", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  ImGui::Text("%.1f fps  %s", m_Stats.fps, m_AdapterName.c_str());
  ImGui::Text("Back buffer %ux%u  RT %ux%u  viewport %ux%u", m_BackBufferWidth, m_BackBufferHeight,
              m_DynamicResolution.GetDynamicBufferWidth(), m_DynamicResolution.GetDynamicBufferHeight(),
              m_DynamicResolution.GetViewportWidth(), m_DynamicResolution.GetViewportHeight());
  ImGui::Text("Filter %s  control %s (%s)  camera %s", FilterName(m_Options.filter),
              ControlModeName(m_Options.control), ControlLawOption(m_Options.law), CameraName(m_Camera).c_str());
  if (!m_LastMessage.empty()) {
    // Compiler output can be long: the first lines here, all of it on stderr.
    std::string shown;
    std::istringstream lines(m_LastMessage);
    std::string line;
    for (int n = 0; n < 6 && std::getline(lines, line); ++n) shown += (n ? "\n" : "") + line.substr(0, 160);
    ImGui::TextUnformatted(shown.c_str());
  }
  ImGui::Text("F1 help");
  ImGui::End();
}

// ---------------------------------------------------------------------------
// Frame loop
bool Sample::RenderFrame() {
  if (m_Window && m_Options.windowTest) {
    // Scripted window events for the window test (frame numbers are arbitrary).
    switch (m_FrameCount) {
      case 5: glfwSetWindowSize(m_Window, 1, 1); break;
      case 10: glfwIconifyWindow(m_Window); break;
      case 13: ToggleFullscreen(); break;  // while minimised: deferred to the restore
      case 15: glfwRestoreWindow(m_Window); break;
      case 20: ToggleFullscreen(); break;
      case 23: glfwSetWindowSize(m_Window, int(m_Options.width), int(m_Options.height)); break;
      case 26: ToggleFullscreen(); break;
      case 31: ToggleFullscreen(); break;
      case 35: glfwSetWindowSize(m_Window, int(m_Options.width), int(m_Options.height)); break;
      default: break;
    }
  }
  if (m_Window) {
    glfwPollEvents();
    if (glfwWindowShouldClose(m_Window)) return false;
    if (m_FullscreenTogglePending && WindowShown()) ToggleFullscreen();
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(m_Window, &fw, &fh);
    if (m_Options.windowTest) {  // log each change of the window's state
      char state[160];
      std::snprintf(state, sizeof(state), "framebuffer %dx%d visible %d iconified %d fullscreen %d%s", fw, fh,
                    glfwGetWindowAttrib(m_Window, GLFW_VISIBLE), glfwGetWindowAttrib(m_Window, GLFW_ICONIFIED),
                    int(m_Fullscreen), m_FullscreenTogglePending ? " (toggle pending)" : "");
      if (m_WindowTestState != state)
        std::fprintf(stderr, "window-test frame %lld: %s\n", static_cast<long long>(m_FrameCount), state);
      m_WindowTestState = state;
    }
    if (fw <= 0 || fh <= 0 || glfwGetWindowAttrib(m_Window, GLFW_ICONIFIED)) {
      // Minimised: render nothing, wait a little.
      ++m_FrameCount;
      ++m_MinimisedFrames;
      FrameRecord r;
      r.frame = m_FrameCount - 1;
      r.rendered = false;
      r.fullscreen = m_Fullscreen;
      m_Frames.push_back(r);
      glfwWaitEventsTimeout(0.02);
      return true;
    }
    if (uint32_t(fw) != m_BackBufferWidth || uint32_t(fh) != m_BackBufferHeight) {
      if (!ResizeSwapChain(uint32_t(fw), uint32_t(fh))) {
        std::fprintf(stderr, "resize to %dx%d failed\n", fw, fh);
        return false;
      }
    }
  }
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = m_FrameCount == 0 ? 1.0 / 60.0
                                           : std::chrono::duration<double>(now - m_LastFrameTime).count();
  m_LastFrameTime = now;
  if (m_FrameCount > 0) m_LastFrameSeconds = elapsed;
  const double time = std::chrono::duration<double>(now - m_StartTime).count();

  m_CaptureThisFrame = m_CaptureRequested;
  m_CaptureRequested = false;
  m_Pending.clear();

  OnFrameMove(time, elapsed);
  OnFrameRender(elapsed);
  const d3dl::HRESULT hr = m_SwapChain->Present(m_Window && m_Options.vsync ? 1 : 0, 0);
  if (d3dl::FAILED(hr)) {
    std::fprintf(stderr, "Present failed: %s\n", d3dl::HResultName(hr));
    return false;
  }
  if (m_CaptureThisFrame) ResolvePendingCaptures();
  m_CaptureThisFrame = false;

  FrameRecord r;
  r.frame = m_FrameCount;
  r.scaleX = m_DynamicResolution.GetScaleX();
  r.scaleY = m_DynamicResolution.GetScaleY();
  r.viewportW = m_Options.dynamicResolution ? m_DynamicResolution.GetViewportWidth() : m_BackBufferWidth;
  r.viewportH = m_Options.dynamicResolution ? m_DynamicResolution.GetViewportHeight() : m_BackBufferHeight;
  r.backBufferW = m_BackBufferWidth;
  r.backBufferH = m_BackBufferHeight;
  r.fullscreen = m_Fullscreen;
  r.cpuFrameMs = elapsed * 1000.0;
  r.gpuFrame = m_TimerFrame.LastMs();
  r.gpuFrameNew = m_TimerFrame.NewResults() > 0;
  r.gpuFrameDelay = m_TimerFrame.LastDelayFrames();
  r.gpuClear = m_TimerClear.LastMs();
  r.gpuScene = m_TimerScene.LastMs();
  r.gpuPostP = m_TimerPostP.LastMs();
  r.gpuScale = m_TimerScale.LastMs();
  m_Frames.push_back(r);
  ++m_FrameCount;
  return true;
}

void Sample::QueueCopy(d3dl::Texture2D* src, int kind) {
  if (!src) return;
  d3dl::TEXTURE2D_DESC d;
  src->GetDesc(&d);
  d3dl::TEXTURE2D_DESC s;
  s.Width = d.Width;
  s.Height = d.Height;
  s.Format = d.Format;
  s.Usage = d3dl::USAGE_STAGING;
  s.CPUAccessFlags = d3dl::CPU_ACCESS_READ;
  s.BindFlags = 0;
  Pending p;
  p.kind = kind;
  if (d3dl::FAILED(m_Device->CreateTexture2D(&s, nullptr, p.staging.GetAddressOf()))) return;
  m_Context->CopyResource(p.staging.Get(), src);
  m_Pending.push_back(std::move(p));
}

void Sample::ResolvePendingCaptures() {
  if (m_Pending.empty()) return;
  m_Context->Flush();
  m_Device->WaitIdle();
  m_CapVelocity = {};
  for (Pending& p : m_Pending) {
    d3dl::TEXTURE2D_DESC d;
    p.staging->GetDesc(&d);
    d3dl::MAPPED_SUBRESOURCE m;
    if (d3dl::FAILED(m_Context->Map(p.staging.Get(), 0, d3dl::MAP_READ, 0, &m))) continue;
    const auto* base = static_cast<const uint8_t*>(m.pData);
    if (p.kind == 3) {
      ImageRG32F& out = m_CapVelocity;
      out.width = d.Width;
      out.height = d.Height;
      out.pixels.resize(size_t(d.Width) * d.Height * 2);
      for (uint32_t y = 0; y < d.Height; ++y) {
        const auto* row = reinterpret_cast<const uint16_t*>(base + size_t(y) * m.RowPitch);
        for (uint32_t x = 0; x < d.Width * 2; ++x) out.pixels[size_t(y) * d.Width * 2 + x] = HalfToFloat(row[x]);
      }
    } else {
      ImageRGBA8& out = p.kind == 0 ? m_CapBackBuffer : p.kind == 1 ? m_CapBackBufferNoGui : m_CapSceneColor;
      out.width = d.Width;
      out.height = d.Height;
      out.pixels.resize(size_t(d.Width) * d.Height * 4);
      const bool bgra = d.Format == d3dl::DXGI_FORMAT_B8G8R8A8_UNORM ||
                        d.Format == d3dl::DXGI_FORMAT_B8G8R8A8_UNORM_SRGB;
      for (uint32_t y = 0; y < d.Height; ++y) {
        uint8_t* dst = out.pixels.data() + size_t(y) * d.Width * 4;
        std::memcpy(dst, base + size_t(y) * m.RowPitch, size_t(d.Width) * 4);
        if (bgra)
          for (uint32_t x = 0; x < d.Width; ++x) std::swap(dst[x * 4], dst[x * 4 + 2]);
      }
    }
    m_Context->Unmap(p.staging.Get(), 0);
  }
  m_Pending.clear();
}

uint64_t Sample::ValidationMessages() const {
  if (!m_Device) return 0;
  d3dl::DEVICE_STATS st;
  m_Device->GetStats(&st);
  return st.ValidationMessages;
}

bool Sample::SaveScreenshot(const std::string& path, bool noGui, std::string* error) const {
  const ImageRGBA8& img = noGui ? m_CapBackBufferNoGui : m_CapBackBuffer;
  if (img.Empty()) {
    *error = "no frame was captured for the screenshot";
    return false;
  }
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  // The back buffer's alpha holds no coverage (the post passes write velocity
  // weights there); a screenshot is what the window shows: opaque.
  std::vector<uint8_t> opaque = img.pixels;
  for (size_t i = 3; i < opaque.size(); i += 4) opaque[i] = 255;
  return Utility::SaveImageRGBA8(path, img.width, img.height, opaque.data(), error);
}

bool Sample::WriteReport(const std::string& path, std::string* error) const {
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  std::ofstream f(path);
  if (!f) {
    *error = "cannot write " + path;
    return false;
  }
  // GPU averages over the frames that received a new result (the records
  // repeat the last result in between); the CPU average over rendered frames.
  auto avg = [&](double FrameRecord::*m, bool gpu) {
    double s = 0;
    int n = 0;
    for (const FrameRecord& r : m_Frames)
      if (r.rendered && (!gpu || r.gpuFrameNew) && std::isfinite(r.*m) && r.*m > 0) {
        s += r.*m;
        ++n;
      }
    return JsonNumber(n ? s / n : 0.0);
  };
  f << "{\n  \"options\": " << OptionsToJson(m_Options) << ",\n";
  f << "  \"control\": {\"mode\": \"" << ControlModeOption(m_Options.control) << "\", \"law\": \""
    << ControlLawOption(m_Options.law) << "\", \"refresh_hz\": " << JsonNumber(m_RefreshHz)
    << ", \"budget_ms\": " << JsonNumber(m_Stats.vsyncMs > 0 ? m_Stats.vsyncMs : 1000.0 / m_RefreshHz)
    << ", \"law_latency_frames\": " << m_LawLatency << "},\n";
  f << "  \"adapter\": " << JsonString(m_AdapterName) << ",\n  \"driver\": " << JsonString(m_AdapterDriver)
    << ",\n";
  f << "  \"scene\": " << JsonString(m_ScenePath) << ",\n";
  f << "  \"back_buffer\": [" << m_BackBufferWidth << ", " << m_BackBufferHeight << "],\n";
  f << "  \"dynamic_rt\": [" << m_DynamicResolution.GetDynamicBufferWidth() << ", "
    << m_DynamicResolution.GetDynamicBufferHeight() << "],\n";
  f << "  \"render_target_bytes\": " << RenderTargetBytes() << ",\n";
  f << "  \"render_targets\": {";
  bool first = true;
  for (const Utility::RenderTarget* rt : {&g_ColorDynamic, &g_DepthDynamic, &g_VelocityDynamic[0],
                                          &g_VelocityDynamic[1], &g_FinalRTDynamic[0], &g_FinalRTDynamic[1],
                                          &g_ColorFull, &g_VelocityFull, &g_DepthFull}) {
    if (!rt->Valid()) continue;
    static const char* names[] = {"g_ColorDynamic", "g_DepthDynamic", "g_VelocityDynamic[0]",
                                  "g_VelocityDynamic[1]", "g_FinalRTDynamic[0]", "g_FinalRTDynamic[1]",
                                  "g_ColorFull", "g_VelocityFull", "g_DepthFull"};
    const Utility::RenderTarget* all[] = {&g_ColorDynamic, &g_DepthDynamic, &g_VelocityDynamic[0],
                                          &g_VelocityDynamic[1], &g_FinalRTDynamic[0], &g_FinalRTDynamic[1],
                                          &g_ColorFull, &g_VelocityFull, &g_DepthFull};
    const size_t idx = size_t(std::find(std::begin(all), std::end(all), rt) - std::begin(all));
    f << (first ? "" : ", ") << "\"" << names[idx] << "\": {\"size\": [" << rt->width << ", " << rt->height
      << "], \"format\": \"" << d3dl::FormatName(rt->format) << "\", \"bytes\": " << rt->Bytes() << "}";
    first = false;
  }
  if (m_ZoomBox.Bytes() > 0) {  // counted in render_target_bytes too
    f << (first ? "" : ", ") << "\"zoom_box_copy\": {\"bytes\": " << m_ZoomBox.Bytes() << "}";
    first = false;
  }
  f << "},\n  \"passes_run\": {";
  first = true;
  for (const auto& [name, count] : m_PassesRun) {
    f << (first ? "" : ", ") << "\"" << name << "\": " << count;
    first = false;
  }
  f << "},\n";
  f << "  \"validation_messages\": " << ValidationMessages() << ",\n";
  f << "  \"frames_rendered\": " << (m_FrameCount - m_MinimisedFrames) << ",\n";
  f << "  \"frames_minimised\": " << m_MinimisedFrames << ",\n";
  f << "  \"averages_ms\": {\"cpu_frame\": " << avg(&FrameRecord::cpuFrameMs, false)
    << ", \"gpu_frame\": " << avg(&FrameRecord::gpuFrame, true) << ", \"clear\": " << avg(&FrameRecord::gpuClear, true)
    << ", \"scene\": " << avg(&FrameRecord::gpuScene, true) << ", \"postp\": " << avg(&FrameRecord::gpuPostP, true)
    << ", \"scale\": " << avg(&FrameRecord::gpuScale, true) << "},\n";
  f << "  \"final_scale\": [" << JsonNumber(m_DynamicResolution.GetScaleX()) << ", "
    << JsonNumber(m_DynamicResolution.GetScaleY()) << "],\n";
  if (m_Scene) {
    const SceneStats st = m_Scene->Stats();
    f << "  \"scene_stats\": {\"draws_issued\": " << st.drawsIssued << ", \"draws_culled\": " << st.drawsCulled
      << ", \"triangles\": " << st.triangles << ", \"texture_bytes\": " << st.textureBytes << "},\n";
  }
  f << "  \"frames\": [\n";
  for (size_t i = 0; i < m_Frames.size(); ++i) {
    const FrameRecord& r = m_Frames[i];
    f << "    {\"frame\": " << r.frame << ", \"rendered\": " << (r.rendered ? "true" : "false")
      << ", \"scale\": [" << JsonNumber(r.scaleX) << ", " << JsonNumber(r.scaleY) << "], \"viewport\": ["
      << r.viewportW << ", " << r.viewportH << "], \"back_buffer\": [" << r.backBufferW << ", " << r.backBufferH
      << "], \"fullscreen\": " << (r.fullscreen ? "true" : "false") << ", \"cpu_ms\": " << JsonNumber(r.cpuFrameMs)
      << ", \"gpu_new\": " << (r.gpuFrameNew ? "true" : "false") << ", \"gpu_delay_frames\": " << r.gpuFrameDelay
      << ", \"gpu_ms\": {\"frame\": " << JsonNumber(r.gpuFrame) << ", \"clear\": " << JsonNumber(r.gpuClear)
      << ", \"scene\": " << JsonNumber(r.gpuScene) << ", \"postp\": " << JsonNumber(r.gpuPostP)
      << ", \"scale\": " << JsonNumber(r.gpuScale) << "}}" << (i + 1 < m_Frames.size() ? "," : "") << "\n";
  }
  f << "  ]\n}\n";
  return bool(f);
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
    if (m_CapBackBuffer.Empty()) {
      // The last frame was skipped (minimised) or the window closed early: capture one more.
      if (!m_Window || !glfwWindowShouldClose(m_Window)) {
        RequestCapture();
        RenderFrame();
      }
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
  m_Pending.clear();
  m_Scene.reset();
  m_GuiRenderer.Release();
  m_ZoomBox.Release();
  if (m_ImGui) {
    ImGui::DestroyContext(m_ImGui);
    m_ImGui = nullptr;
  }
  ReleaseDynamicResolution();
  for (AveragedGPUTimer* t : {&m_TimerFrame, &m_TimerClear, &m_TimerScene, &m_TimerPostP, &m_TimerScale})
    t->Release();
  m_CubicLookup.Release();
  m_Noise.Release();
  m_FullScreenVS = m_FullScreenFullVS = nullptr;
  m_ClearPS = m_ClearVelocityPS = m_MotionBlurPS = nullptr;
  m_FullClearPS = m_FullClearVelocityPS = m_FullMotionBlurPS = nullptr;
  m_ResolvePS = m_BicubicPS = m_NoisePS = m_NoiseOffsetPS = nullptr;
  m_TAAPS = m_TAAFastPS = m_TAANoiseOffsetPS = m_TAANoiseOffsetFastPS = m_TAABasicPS = nullptr;
  m_PostCB = nullptr;
  m_SamplerPoint = m_SamplerLinear = m_SamplerPointWrap = nullptr;
  m_NoDepth = nullptr;
  m_NoCull = nullptr;
  ReleaseBackBufferViews();
  m_SwapChain = nullptr;
  m_Context = nullptr;
  m_Device = nullptr;
  if (m_Window) {
    glfwDestroyWindow(m_Window);
    m_Window = nullptr;
  }
  if (m_GlfwInitialised) {
    glfwTerminate();
    m_GlfwInitialised = false;
  }
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
