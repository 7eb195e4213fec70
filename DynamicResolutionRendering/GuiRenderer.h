// A small Dear ImGui renderer on D3DLikeRHI (font atlas texture, dynamic
// vertex/index buffers filled with Map(WRITE_DISCARD), scissor rects, alpha
// blending) and the GLFW input glue of the sample.
#pragma once

#include <string>

#include "ConstantBuffer.h"
#include "ShaderLibrary.h"
#include "d3dl/D3DLike.h"

struct ImDrawData;
struct GLFWwindow;

namespace drr {

class GuiRenderer {
 public:
  // Needs an ImGui context; builds the font atlas texture.
  bool Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error);
  // Keeps the old shaders on error (F4).
  bool LoadShaders(ShaderLoad& load);
  void Release();
  // Draws into the bound render target; the caller set the back-buffer viewport.
  void Render(d3dl::DeviceContext* ctx, ImDrawData* drawData);

 private:
  bool EnsureBuffers(int vertexCount, int indexCount);
  bool CreateFontAtlas(std::string* error);
  bool CreateStates(std::string* error);

  d3dl::Device* m_Device = nullptr;
  d3dl::ComPtr<d3dl::VertexShader> m_VS;
  d3dl::ComPtr<d3dl::PixelShader> m_PS;
  d3dl::ComPtr<d3dl::InputLayout> m_Layout;
  d3dl::ComPtr<d3dl::Buffer> m_VB, m_IB;
  struct Constants {  // Gui.hlsl's cbuffer: pixel space -> clip space
    float scale[2];
    float translate[2];
  };
  ConstantBuffer<Constants> m_CB;
  int m_VBCapacity = 0, m_IBCapacity = 0;
  d3dl::ComPtr<d3dl::Texture2D> m_FontTexture;
  d3dl::ComPtr<d3dl::ShaderResourceView> m_FontSRV;
  d3dl::ComPtr<d3dl::SamplerState> m_Sampler;
  d3dl::ComPtr<d3dl::BlendState> m_Blend;
  d3dl::ComPtr<d3dl::RasterizerState> m_Raster;
  d3dl::ComPtr<d3dl::DepthStencilState> m_Depth;
};

// GLFW -> ImGui input (ImGui 1.86 API: KeyMap/KeysDown). Installs callbacks
// that forward to ImGui and then to the application's handler.
class GuiInput {
 public:
  using KeyHandler = void (*)(void* user, int key, int action, int mods);
  using MouseHandler = void (*)(void* user, int button, int action, double x, double y);
  void Install(GLFWwindow* window, void* user, KeyHandler keys, MouseHandler mouse);
  // Per frame: display size, delta time, mouse position.
  void NewFrame(GLFWwindow* window, float width, float height, float dt);
  static bool WantsMouse();
  static bool WantsKeyboard();

  void* user = nullptr;
  KeyHandler keyHandler = nullptr;
  MouseHandler mouseHandler = nullptr;
};

}  // namespace drr
