// The scene's part of the deferred renderer (Docs/Deferred.md): the G-buffer
// variants of the scene shader, the decal blend state over the G-buffer, the
// depth-only draws of the spot-light shadow maps, and the LIGHT entries.
// Everything here is created on first use: the forward path loads none of it.
#include <cstdio>
#include <cstring>

#include "scene/SceneImpl.h"

namespace drr {
using d3dl::FAILED;
using d3dl::SUCCEEDED;
using d3dl::UINT;

namespace {
std::string GBufferFile(int v) {
  char b[64];
  std::snprintf(b, sizeof b, "scene_gbuffer_ps_n%d_s%d_v%d", (v >> 2) & 1, (v >> 1) & 1, v & 1);
  return b;
}
constexpr const char* kShadowVS = "scene_shadow_vs";
constexpr const char* kShadowPS = "scene_shadow_ps";
// Shadow-map raster bias against acne (the lighting pass adds a small compare bias).
constexpr float kShadowSlopeBias = 2.0f;
}  // namespace

d3dl::PixelShader* SceneImpl::GBufferVariant(int v) {
  if (!gbufferPs[v]) {
    std::string err;
    if (gbufferPsCode[v].empty() && !shaders.Load(GBufferFile(v), false, &gbufferPsCode[v], &err)) {
      Warn(err);
      return nullptr;
    }
    if (FAILED(device->CreatePixelShader(gbufferPsCode[v].data(), gbufferPsCode[v].size() * 4,
                                         gbufferPs[v].ReleaseAndGetAddressOf()))) {
      Warn("scene: CreatePixelShader failed for " + GBufferFile(v));
      return nullptr;
    }
  }
  return gbufferPs[v].Get();
}

// Decals over the G-buffer: diffuse, specular and normal blended by the
// decal's opacity (each output carries it in alpha), velocity kept; over the
// forward targets the scene's own state.
d3dl::BlendState* SceneImpl::DecalBlend(bool gbuffer) {
  if (!gbuffer) return bsDecal.Get();
  if (!bsDecalGBuffer) {
    d3dl::BLEND_DESC bd;
    bd.IndependentBlendEnable = 1;
    for (int rt = 0; rt < 3; ++rt) {
      bd.RenderTarget[rt].BlendEnable = 1;
      bd.RenderTarget[rt].SrcBlend = d3dl::BLEND_SRC_ALPHA;
      bd.RenderTarget[rt].DestBlend = d3dl::BLEND_INV_SRC_ALPHA;
      bd.RenderTarget[rt].SrcBlendAlpha = d3dl::BLEND_ONE;
      bd.RenderTarget[rt].DestBlendAlpha = d3dl::BLEND_ZERO;
    }
    bd.RenderTarget[3].RenderTargetWriteMask = 0;
    if (FAILED(device->CreateBlendState(&bd, bsDecalGBuffer.GetAddressOf()))) return bsDecal.Get();
  }
  return bsDecalGBuffer.Get();
}

bool SceneImpl::CreateShadowStage() {
  if (shadowVs && shadowPs && shadowLayout && rsShadow) return true;
  std::vector<uint32_t> vsCode, psCode;
  std::string err;
  if (!shaders.Load(kShadowVS, false, &vsCode, &err) || !shaders.Load(kShadowPS, false, &psCode, &err)) {
    Warn(err);
    return false;
  }
  const d3dl::INPUT_ELEMENT_DESC position = {"POSITION", 0, d3dl::DXGI_FORMAT_R32G32B32_FLOAT, 0, 0,
                                             d3dl::INPUT_PER_VERTEX_DATA, 0};
  d3dl::RASTERIZER_DESC rd;
  rd.CullMode = d3dl::CULL_NONE;  // thin and open geometry casts from both sides
  rd.SlopeScaledDepthBias = kShadowSlopeBias;
  if (FAILED(device->CreateVertexShader(vsCode.data(), vsCode.size() * 4, shadowVs.ReleaseAndGetAddressOf())) ||
      FAILED(device->CreatePixelShader(psCode.data(), psCode.size() * 4, shadowPs.ReleaseAndGetAddressOf())) ||
      FAILED(device->CreateInputLayout(&position, 1, vsCode.data(), vsCode.size() * 4,
                                       shadowLayout.ReleaseAndGetAddressOf())) ||
      FAILED(device->CreateRasterizerState(&rd, rsShadow.ReleaseAndGetAddressOf()))) {
    Warn("scene: cannot create the shadow-map stage");
    return false;
  }
  return true;
}

bool SceneImpl::ReloadDeferredShaders(const ShaderLibrary& lib, bool fromSource, std::string* error) {
  std::vector<uint32_t> code[8];
  for (int v = 0; v < 8; ++v)
    if (gbufferPs[v] && !lib.Load(GBufferFile(v), fromSource, &code[v], error)) return false;
  for (int v = 0; v < 8; ++v) {
    if (code[v].empty()) continue;
    gbufferPsCode[v] = std::move(code[v]);
    gbufferPs[v] = nullptr;
  }
  shadowVs = nullptr;  // recreated from the library on the next shadow pass
  shadowPs = nullptr;
  return true;
}

const std::vector<SceneLight>& Scene::Lights() const { return impl_->lights; }

uint32_t Scene::RenderDepth(d3dl::DeviceContext* ctx, const glm::mat4& viewProj) {
  SceneImpl& s = *impl_;
  if (!ctx || !s.CreateShadowStage()) return 0;
  glm::vec4 planes[6];
  {
    const glm::mat4 t = glm::transpose(viewProj);
    const glm::vec4 all[6] = {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[2], t[3] - t[2]};
    for (int k = 0; k < 6; ++k) planes[k] = all[k] / glm::length(glm::vec3(all[k]));
  }
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  ctx->IASetInputLayout(s.shadowLayout.Get());
  ctx->VSSetShader(s.shadowVs.Get());
  ctx->PSSetShader(s.shadowPs.Get());
  ctx->VSSetConstantBuffers(0, 1, s.objectCB.GetAddressOf());
  ctx->RSSetState(s.rsShadow.Get());
  ctx->OMSetDepthStencilState(s.dsOpaque.Get(), 0);
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  uint32_t draws = 0;
  for (const Entry& e : s.entries) {
    // The sky dome and cameras cast nothing; decals lie on surfaces.
    if (e.desc.hidden || e.desc.type != EntryType::Lit) continue;
    for (const DrawItem& it : e.items) {
      const GpuMesh& m = e.meshes[it.mesh];
      const GpuMaterial& mat = e.materials[m.material < e.materials.size() ? m.material : 0];
      const glm::mat4 world = e.transform * e.globals[it.node];
      if (mat.blend || s.Culled(e, it, world, planes, true)) continue;
      d3dl::MAPPED_SUBRESOURCE map;
      if (FAILED(ctx->Map(s.objectCB.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &map))) continue;
      const ObjectConstants oc{viewProj * world, viewProj * world, world, mat.tint, glm::vec4(0.f)};
      std::memcpy(map.pData, &oc, sizeof oc);
      ctx->Unmap(s.objectCB.Get(), 0);
      d3dl::Buffer* vb = m.vb.Get();
      UINT stride = sizeof(SceneVertex), offset = 0;
      ctx->IASetVertexBuffers(0, 1, &vb, &stride, &offset);
      ctx->IASetIndexBuffer(m.ib.Get(), m.indexFormat, 0);
      ctx->DrawIndexed(m.indexCount, 0, 0);
      ++draws;
    }
  }
  ctx->RSSetState(nullptr);
  ctx->OMSetDepthStencilState(nullptr, 0);
  return draws;
}

}  // namespace drr
