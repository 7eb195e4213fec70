#include "GuiRenderer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstring>
#include <cstddef>
#include <vector>


namespace drr {


bool GuiRenderer::LoadShaders(ShaderLoad& load) {
  d3dl::ComPtr<d3dl::VertexShader> vs;
  d3dl::ComPtr<d3dl::PixelShader> ps;
  d3dl::ComPtr<d3dl::InputLayout> layout;
  std::vector<uint32_t> vsCode;
  if (!load.Load({{"Gui_GuiVS", &vs, &vsCode}}, {{"Gui_GuiPS", &ps}})) return false;
  const d3dl::INPUT_ELEMENT_DESC elements[] = {
      {"POSITION", 0, d3dl::DXGI_FORMAT_R32G32_FLOAT, 0, uint32_t(offsetof(ImDrawVert, pos))},
      {"TEXCOORD", 0, d3dl::DXGI_FORMAT_R32G32_FLOAT, 0, uint32_t(offsetof(ImDrawVert, uv))},
      {"COLOR", 0, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM, 0, uint32_t(offsetof(ImDrawVert, col))},
  };
  if (d3dl::FAILED(m_Device->CreateInputLayout(elements, 3, vsCode.data(), vsCode.size() * 4,
                                               layout.GetAddressOf()))) {
    *load.error = "GUI: CreateInputLayout failed";
    return false;
  }
  m_VS = vs;
  m_PS = ps;
  m_Layout = layout;
  return true;
}

bool GuiRenderer::Init(d3dl::Device* device, const ShaderLibrary& shaders, std::string* error) {
  m_Device = device;
  ShaderLoad load{device, &shaders, false, error};
  return LoadShaders(load) && CreateFontAtlas(error) && CreateStates(error);
}

bool GuiRenderer::CreateFontAtlas(std::string* error) {
  ImGuiIO& io = ImGui::GetIO();
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  d3dl::TEXTURE2D_DESC td;
  td.Width = uint32_t(w);
  td.Height = uint32_t(h);
  td.Format = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM;
  td.Usage = d3dl::USAGE_IMMUTABLE;
  td.BindFlags = d3dl::BIND_SHADER_RESOURCE;
  d3dl::SUBRESOURCE_DATA init;
  init.pSysMem = pixels;
  init.SysMemPitch = uint32_t(w) * 4u;
  if (d3dl::FAILED(m_Device->CreateTexture2D(&td, &init, m_FontTexture.ReleaseAndGetAddressOf())) ||
      d3dl::FAILED(m_Device->CreateShaderResourceView(m_FontTexture.Get(), nullptr,
                                                    m_FontSRV.ReleaseAndGetAddressOf()))) {
    if (error) *error = "GUI: cannot create the font atlas texture";
    return false;
  }
  m_FontTexture->SetDebugName("ImGuiFontAtlas");
  io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(m_FontSRV.Get()));
  return true;
}

bool GuiRenderer::CreateStates(std::string* error) {
  d3dl::Device* device = m_Device;
  const bool cbOk = m_CB.Create(device);

  d3dl::SAMPLER_DESC sd;
  sd.Filter = d3dl::FILTER_MIN_MAG_MIP_LINEAR;
  sd.AddressU = sd.AddressV = sd.AddressW = d3dl::TEXTURE_ADDRESS_CLAMP;
  device->CreateSamplerState(&sd, m_Sampler.ReleaseAndGetAddressOf());

  d3dl::BLEND_DESC bd;
  auto& rt = bd.RenderTarget[0];
  rt.BlendEnable = 1;
  rt.SrcBlend = d3dl::BLEND_SRC_ALPHA;
  rt.DestBlend = d3dl::BLEND_INV_SRC_ALPHA;
  rt.BlendOp = d3dl::BLEND_OP_ADD;
  rt.SrcBlendAlpha = d3dl::BLEND_ONE;
  rt.DestBlendAlpha = d3dl::BLEND_INV_SRC_ALPHA;
  rt.BlendOpAlpha = d3dl::BLEND_OP_ADD;
  device->CreateBlendState(&bd, m_Blend.ReleaseAndGetAddressOf());

  d3dl::RASTERIZER_DESC rd;
  rd.CullMode = d3dl::CULL_NONE;
  rd.ScissorEnable = 1;
  rd.DepthClipEnable = 1;
  device->CreateRasterizerState(&rd, m_Raster.ReleaseAndGetAddressOf());

  if (!cbOk || !CreateNoDepthState(device, &m_Depth) || !m_Sampler || !m_Blend || !m_Raster || !m_Depth) {
    if (error) *error = "GUI: cannot create states";
    return false;
  }
  return true;
}

void GuiRenderer::Release() {
  m_VS = nullptr;
  m_PS = nullptr;
  m_Layout = nullptr;
  m_VB = m_IB = nullptr;
  m_CB.Release();
  m_VBCapacity = m_IBCapacity = 0;
  m_FontSRV = nullptr;
  m_FontTexture = nullptr;
  m_Sampler = nullptr;
  m_Blend = nullptr;
  m_Raster = nullptr;
  m_Depth = nullptr;
  m_Device = nullptr;
}

bool GuiRenderer::EnsureBuffers(int vertexCount, int indexCount) {
  if (!m_VB || m_VBCapacity < vertexCount) {
    m_VBCapacity = std::max(vertexCount + 5000, m_VBCapacity * 2);
    d3dl::BUFFER_DESC d;
    d.ByteWidth = uint32_t(m_VBCapacity) * sizeof(ImDrawVert);
    d.Usage = d3dl::USAGE_DYNAMIC;
    d.BindFlags = d3dl::BIND_VERTEX_BUFFER;
    d.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
    if (d3dl::FAILED(m_Device->CreateBuffer(&d, nullptr, m_VB.ReleaseAndGetAddressOf()))) return false;
  }
  if (!m_IB || m_IBCapacity < indexCount) {
    m_IBCapacity = std::max(indexCount + 10000, m_IBCapacity * 2);
    d3dl::BUFFER_DESC d;
    d.ByteWidth = uint32_t(m_IBCapacity) * sizeof(ImDrawIdx);
    d.Usage = d3dl::USAGE_DYNAMIC;
    d.BindFlags = d3dl::BIND_INDEX_BUFFER;
    d.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
    if (d3dl::FAILED(m_Device->CreateBuffer(&d, nullptr, m_IB.ReleaseAndGetAddressOf()))) return false;
  }
  return true;
}

namespace {

// Copies every draw list's vertices and indices, one after the other, into the
// dynamic buffers.
bool UploadGeometry(d3dl::DeviceContext* ctx, d3dl::Buffer* vb, d3dl::Buffer* ib, const ImDrawData* dd) {
  d3dl::MAPPED_SUBRESOURCE vm, im;
  if (d3dl::FAILED(ctx->Map(vb, 0, d3dl::MAP_WRITE_DISCARD, 0, &vm))) return false;
  if (d3dl::FAILED(ctx->Map(ib, 0, d3dl::MAP_WRITE_DISCARD, 0, &im))) {
    ctx->Unmap(vb, 0);
    return false;
  }
  auto* vdst = static_cast<ImDrawVert*>(vm.pData);
  auto* idst = static_cast<ImDrawIdx*>(im.pData);
  for (int n = 0; n < dd->CmdListsCount; ++n) {
    const ImDrawList* list = dd->CmdLists[n];
    std::memcpy(vdst, list->VtxBuffer.Data, size_t(list->VtxBuffer.Size) * sizeof(ImDrawVert));
    std::memcpy(idst, list->IdxBuffer.Data, size_t(list->IdxBuffer.Size) * sizeof(ImDrawIdx));
    vdst += list->VtxBuffer.Size;
    idst += list->IdxBuffer.Size;
  }
  ctx->Unmap(ib, 0);
  ctx->Unmap(vb, 0);
  return true;
}

// Orthographic mapping of ImGui's pixel space (origin top-left) to clip space.
template <class Constants>
Constants Projection(const ImDrawData* dd) {
  Constants c;
  c.scale[0] = 2.0f / dd->DisplaySize.x;
  c.scale[1] = -2.0f / dd->DisplaySize.y;
  c.translate[0] = -1.0f - dd->DisplayPos.x * c.scale[0];
  c.translate[1] = 1.0f - dd->DisplayPos.y * c.scale[1];
  return c;
}

// One indexed draw per command, scissored to its clip rectangle, with its
// texture; user callbacks run in their place.
void DrawCommands(d3dl::DeviceContext* ctx, const ImDrawData* dd) {
  const ImVec2 clipOff = dd->DisplayPos;
  int vtxBase = 0, idxBase = 0;
  for (int n = 0; n < dd->CmdListsCount; ++n) {
    const ImDrawList* list = dd->CmdLists[n];
    for (int ci = 0; ci < list->CmdBuffer.Size; ++ci) {
      const ImDrawCmd& cmd = list->CmdBuffer[ci];
      if (cmd.UserCallback) {
        if (cmd.UserCallback != ImDrawCallback_ResetRenderState) cmd.UserCallback(list, &cmd);
        continue;
      }
      const float x0 = std::max(cmd.ClipRect.x - clipOff.x, 0.0f);
      const float y0 = std::max(cmd.ClipRect.y - clipOff.y, 0.0f);
      const float x1 = std::min(cmd.ClipRect.z - clipOff.x, dd->DisplaySize.x);
      const float y1 = std::min(cmd.ClipRect.w - clipOff.y, dd->DisplaySize.y);
      if (x1 <= x0 || y1 <= y0) continue;
      d3dl::RECT r;
      r.left = int32_t(x0);
      r.top = int32_t(y0);
      r.right = int32_t(x1);
      r.bottom = int32_t(y1);
      ctx->RSSetScissorRects(1, &r);
      auto* srv = reinterpret_cast<d3dl::ShaderResourceView*>(cmd.GetTexID());
      ctx->PSSetShaderResources(0, 1, &srv);
      ctx->DrawIndexed(cmd.ElemCount, cmd.IdxOffset + uint32_t(idxBase),
                       int32_t(cmd.VtxOffset) + vtxBase);
    }
    vtxBase += list->VtxBuffer.Size;
    idxBase += list->IdxBuffer.Size;
  }
}

}  // namespace

void GuiRenderer::Render(d3dl::DeviceContext* ctx, ImDrawData* dd) {
  if (!dd || dd->TotalVtxCount == 0 || dd->DisplaySize.x <= 0 || dd->DisplaySize.y <= 0 || !m_VS)
    return;
  if (!EnsureBuffers(dd->TotalVtxCount, dd->TotalIdxCount)) return;
  if (!UploadGeometry(ctx, m_VB.Get(), m_IB.Get(), dd)) return;
  m_CB.Upload(ctx, Projection<Constants>(dd));

  const uint32_t stride = sizeof(ImDrawVert), offset = 0;
  ctx->IASetInputLayout(m_Layout.Get());
  ctx->IASetVertexBuffers(0, 1, m_VB.GetAddressOf(), &stride, &offset);
  ctx->IASetIndexBuffer(m_IB.Get(),
                        sizeof(ImDrawIdx) == 2 ? d3dl::DXGI_FORMAT_R16_UINT : d3dl::DXGI_FORMAT_R32_UINT, 0);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  ctx->VSSetShader(m_VS.Get());
  ctx->VSSetConstantBuffers(0, 1, m_CB.Address());
  ctx->PSSetShader(m_PS.Get());
  ctx->PSSetSamplers(0, 1, m_Sampler.GetAddressOf());
  const float blendFactor[4] = {0, 0, 0, 0};
  ctx->OMSetBlendState(m_Blend.Get(), blendFactor, 0xffffffffu);
  ctx->OMSetDepthStencilState(m_Depth.Get(), 0);
  ctx->RSSetState(m_Raster.Get());

  DrawCommands(ctx, dd);
  d3dl::ShaderResourceView* none = nullptr;
  ctx->PSSetShaderResources(0, 1, &none);
  ctx->RSSetState(nullptr);
  ctx->OMSetBlendState(nullptr, blendFactor, 0xffffffffu);
  ctx->OMSetDepthStencilState(nullptr, 0);
}

// ---------------------------------------------------------------------------
namespace {
GuiInput* g_Input = nullptr;

void OnMouseButton(GLFWwindow* w, int button, int action, int mods) {
  ImGuiIO& io = ImGui::GetIO();
  if (button >= 0 && button < 5) io.MouseDown[button] = action != GLFW_RELEASE;
  if (g_Input && g_Input->mouseHandler && !io.WantCaptureMouse) {
    double x = 0, y = 0;
    glfwGetCursorPos(w, &x, &y);
    g_Input->mouseHandler(g_Input->user, button, action, x, y);
  }
}
void OnScroll(GLFWwindow*, double dx, double dy) {
  ImGuiIO& io = ImGui::GetIO();
  io.MouseWheelH += float(dx);
  io.MouseWheel += float(dy);
}
void OnKey(GLFWwindow*, int key, int, int action, int mods) {
  ImGuiIO& io = ImGui::GetIO();
  if (key >= 0 && key < 512) io.KeysDown[key] = action != GLFW_RELEASE;
  io.KeyCtrl = (mods & GLFW_MOD_CONTROL) != 0;
  io.KeyShift = (mods & GLFW_MOD_SHIFT) != 0;
  io.KeyAlt = (mods & GLFW_MOD_ALT) != 0;
  io.KeySuper = (mods & GLFW_MOD_SUPER) != 0;
  if (g_Input && g_Input->keyHandler && !io.WantTextInput)
    g_Input->keyHandler(g_Input->user, key, action, mods);
}
void OnChar(GLFWwindow*, unsigned int c) { ImGui::GetIO().AddInputCharacter(c); }
}  // namespace

void GuiInput::Install(GLFWwindow* window, void* u, KeyHandler keys, MouseHandler mouse) {
  user = u;
  keyHandler = keys;
  mouseHandler = mouse;
  g_Input = this;
  ImGuiIO& io = ImGui::GetIO();
  io.KeyMap[ImGuiKey_Tab] = GLFW_KEY_TAB;
  io.KeyMap[ImGuiKey_LeftArrow] = GLFW_KEY_LEFT;
  io.KeyMap[ImGuiKey_RightArrow] = GLFW_KEY_RIGHT;
  io.KeyMap[ImGuiKey_UpArrow] = GLFW_KEY_UP;
  io.KeyMap[ImGuiKey_DownArrow] = GLFW_KEY_DOWN;
  io.KeyMap[ImGuiKey_PageUp] = GLFW_KEY_PAGE_UP;
  io.KeyMap[ImGuiKey_PageDown] = GLFW_KEY_PAGE_DOWN;
  io.KeyMap[ImGuiKey_Home] = GLFW_KEY_HOME;
  io.KeyMap[ImGuiKey_End] = GLFW_KEY_END;
  io.KeyMap[ImGuiKey_Insert] = GLFW_KEY_INSERT;
  io.KeyMap[ImGuiKey_Delete] = GLFW_KEY_DELETE;
  io.KeyMap[ImGuiKey_Backspace] = GLFW_KEY_BACKSPACE;
  io.KeyMap[ImGuiKey_Space] = GLFW_KEY_SPACE;
  io.KeyMap[ImGuiKey_Enter] = GLFW_KEY_ENTER;
  io.KeyMap[ImGuiKey_Escape] = GLFW_KEY_ESCAPE;
  io.KeyMap[ImGuiKey_A] = GLFW_KEY_A;
  io.KeyMap[ImGuiKey_C] = GLFW_KEY_C;
  io.KeyMap[ImGuiKey_V] = GLFW_KEY_V;
  io.KeyMap[ImGuiKey_X] = GLFW_KEY_X;
  io.KeyMap[ImGuiKey_Y] = GLFW_KEY_Y;
  io.KeyMap[ImGuiKey_Z] = GLFW_KEY_Z;
  glfwSetMouseButtonCallback(window, OnMouseButton);
  glfwSetScrollCallback(window, OnScroll);
  glfwSetKeyCallback(window, OnKey);
  glfwSetCharCallback(window, OnChar);
}

void GuiInput::NewFrame(GLFWwindow* window, float width, float height, float dt) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(width, height);
  io.DeltaTime = dt > 0.0f ? dt : 1.0f / 60.0f;
  if (window) {
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    int ww = 0, wh = 0, fw = 0, fh = 0;
    glfwGetWindowSize(window, &ww, &wh);
    glfwGetFramebufferSize(window, &fw, &fh);
    const float sx = ww > 0 ? float(fw) / float(ww) : 1.0f;
    const float sy = wh > 0 ? float(fh) / float(wh) : 1.0f;
    if (glfwGetWindowAttrib(window, GLFW_FOCUSED))
      io.MousePos = ImVec2(float(x) * sx, float(y) * sy);
    else
      io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
  }
}

bool GuiInput::WantsMouse() { return ImGui::GetIO().WantCaptureMouse; }
bool GuiInput::WantsKeyboard() { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace drr
