// Screen-space adaptive tessellation of the scene (Docs/Tessellation.md):
// the entries' tessellate= rules resolved per material at load, the height
// maps of the displace rules, and per draw the hull/domain stages that
// Shaders/SceneTessellation.hlsl holds. Nothing here runs, and no shader of it
// is created, unless SceneRenderParams::tessellation is enabled and some entry
// has a rule.
#include <algorithm>
#include <cstring>

#include "scene/ImportLimits.h"
#include "scene/SceneImpl.h"

namespace drr {
using d3dl::FAILED;
using d3dl::UINT;

namespace {
// b1 of the hull and domain shaders (SceneTessellation.hlsl, TessConstants).
struct TessConstants {
  glm::vec4 planes[6];  // world space, normalised
  glm::vec4 eye;        // xyz camera; w: pixels per world unit at distance 1
  glm::vec4 detail;     // target pixels per edge, max factor, cull back faces, back-face margin
  glm::vec4 surface;    // mode (0 Phong, 1 displacement), relief, Phong shape factor, unused
};
static_assert(sizeof(TessConstants) == 144);

constexpr float kPhongShape = 0.75f;  // Boubekeur and Alexa's suggested alpha
// Cosine below which a patch counts as facing away: a little past the
// silhouette for Phong (the curved surface bulges past its flat triangle),
// more for displacement (the relief tilts the surface).
constexpr float kBackFaceMarginPhong = 0.25f, kBackFaceMarginDisplace = 0.5f;

const char* const kInputNames[] = {"POSITION", "NORMAL", "TEXCOORD", "TANGENT", "BINORMAL"};
}  // namespace

// The entry's mode per material, the rules' unknown material names as
// warnings, and the height map when a displace rule applies to some material.
bool SceneImpl::LoadTessellation(Entry& e, std::string* error) {
  e.tess.materialMode.clear();
  bool displace = false;
  for (const GpuMaterial& mat : e.materials) {
    e.tess.materialMode.push_back(e.desc.TessModeOf(mat.name));
    displace = displace || e.tess.materialMode.back() == TessMode::Displace;
  }
  for (const TessRule& r : e.desc.tessellate) {
    if (r.material.empty()) continue;
    const bool found = std::any_of(e.materials.begin(), e.materials.end(),
                                   [&](const GpuMaterial& m) { return m.name == r.material; });
    if (!found)
      Warn(e.desc.meshPath + " (scene description line " + std::to_string(e.desc.line) + "): tessellate= names material '" +
           r.material + "', which the model does not have");
  }
  if (!displace) return true;
  auto tex = std::make_shared<TextureData>();
  std::string why;
  if (!ImportTextureIsolated(e.desc.displacementFile, TextureKind::Specular, 16384, ImportLimits::FromEnvironment(),
                             tex.get(), &why)) {
    *error = "scene description line " + std::to_string(e.desc.line) + ": displacement map: " + why;
    return false;
  }
  e.tess.displacement = Upload(tex, error);
  return bool(e.tess.displacement);
}

// The first tessellated frame creates the stages (only if some material has a
// mode); every frame takes the frustum and eye that the hull shader culls with.
bool SceneImpl::PrepareTessellation(const SceneRenderParams& p, const glm::vec4 planes[6]) {
  TessellationStages& t = tessStages;
  if (!p.tessellation.enabled) return false;
  std::copy(planes, planes + 6, t.planes);
  t.eye = glm::vec3(glm::inverse(history.view)[3]);
  if (t.tried) return t.ok;
  t.tried = true;
  const bool anyRule = std::any_of(entries.begin(), entries.end(), [](const Entry& e) {
    return std::any_of(e.tess.materialMode.begin(), e.tess.materialMode.end(),
                       [](TessMode m) { return m != TessMode::None; });
  });
  if (!anyRule) return false;
  std::string err;
  std::vector<uint32_t> code;
  auto fail = [&](const std::string& what) {
    Warn("tessellation off: " + what + (err.empty() ? "" : ": " + err));
    return false;
  };
  for (int n = 0; n < 2; ++n) {
    const std::string suffix = "_n" + std::to_string(n);
    if (!shaders.Load("scene_tess_vs" + suffix, t.fromSource, &code, &err) ||
        FAILED(device->CreateVertexShader(code.data(), code.size() * 4, t.vs[n].ReleaseAndGetAddressOf())))
      return fail("scene_tess_vs" + suffix);
    d3dl::INPUT_ELEMENT_DESC elems[5];
    const UINT offsets[5] = {0, 12, 24, 32, 44};
    const d3dl::DXGI_FORMAT formats[5] = {d3dl::DXGI_FORMAT_R32G32B32_FLOAT, d3dl::DXGI_FORMAT_R32G32B32_FLOAT,
                                          d3dl::DXGI_FORMAT_R32G32_FLOAT, d3dl::DXGI_FORMAT_R32G32B32_FLOAT,
                                          d3dl::DXGI_FORMAT_R32G32B32_FLOAT};
    for (int k = 0; k < 5; ++k) elems[k] = {kInputNames[k], 0, formats[k], 0, offsets[k], d3dl::INPUT_PER_VERTEX_DATA, 0};
    if (FAILED(device->CreateInputLayout(elems, n ? 5 : 3, code.data(), code.size() * 4,
                                         t.layout[n].ReleaseAndGetAddressOf())))
      return fail("the input layout of scene_tess_vs" + suffix);
    if (!shaders.Load("scene_tess_hs" + suffix, t.fromSource, &code, &err) ||
        FAILED(device->CreateHullShader(code.data(), code.size() * 4, t.hs[n].ReleaseAndGetAddressOf())))
      return fail("scene_tess_hs" + suffix + " (does the adapter support tessellation?)");
    for (int v = 0; v < 2; ++v) {
      const std::string name = "scene_tess_ds" + suffix + "_v" + std::to_string(v);
      if (!shaders.Load(name, t.fromSource, &code, &err) ||
          FAILED(device->CreateDomainShader(code.data(), code.size() * 4, t.ds[n * 2 + v].ReleaseAndGetAddressOf())))
        return fail(name);
    }
  }
  d3dl::BUFFER_DESC bd;
  bd.ByteWidth = sizeof(TessConstants);
  bd.Usage = d3dl::USAGE_DYNAMIC;
  bd.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  bd.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  d3dl::SAMPLER_DESC sd;
  sd.Filter = d3dl::FILTER_MIN_MAG_MIP_LINEAR;
  sd.AddressU = sd.AddressV = sd.AddressW = d3dl::TEXTURE_ADDRESS_WRAP;
  auto flat = std::make_shared<TextureData>(FallbackTexture(TextureKind::Color));  // white: no displacement
  if (FAILED(device->CreateBuffer(&bd, nullptr, t.cb.ReleaseAndGetAddressOf())) ||
      FAILED(device->CreateSamplerState(&sd, t.sampler.ReleaseAndGetAddressOf())) ||
      !(t.flatHeight = Upload(flat, &err)))
    return fail("its constant buffer, sampler or flat height map");
  t.ok = true;
  return true;
}

// F4: when the stages exist, every tessellation shader must load (compile)
// before the scene swaps its shaders; the stages are then re-created from the
// new code at the next tessellated frame.
bool SceneImpl::ReloadTessellation(const ShaderLibrary& lib, bool fromSource, std::string* error) {
  if (!tessStages.ok) return true;
  std::vector<uint32_t> code;
  for (const char* name : {"scene_tess_vs_n0", "scene_tess_vs_n1", "scene_tess_hs_n0", "scene_tess_hs_n1",
                           "scene_tess_ds_n0_v0", "scene_tess_ds_n0_v1", "scene_tess_ds_n1_v0", "scene_tess_ds_n1_v1"})
    if (!lib.Load(name, fromSource, &code, error)) return false;
  return true;
}

void SceneImpl::ResetTessellationStages(bool fromSource) {
  tessStages = TessellationStages{};
  tessStages.fromSource = fromSource;
}

TessMode SceneImpl::TessModeFor(const SceneRenderParams& p, const Entry& e, const GpuMesh& m) const {
  if (!p.tessellation.enabled || !tessStages.ok || m.material >= e.tess.materialMode.size()) return TessMode::None;
  return e.tess.materialMode[m.material];
}

// The draw's input assembler and vertex, hull and domain stages; the caller
// has filled b0 (ObjectConstants) and binds the pixel stage as for any draw.
bool SceneImpl::BindTessellation(d3dl::DeviceContext* ctx, const SceneRenderParams& p, const Entry& e,
                                 const GpuMesh& m, const GpuMaterial& mat, TessMode mode) const {
  const TessellationStages& t = tessStages;
  const int n = mat.hasNormal ? 1 : 0;
  const bool displace = mode == TessMode::Displace && e.tess.displacement;
  TessConstants tc;
  std::copy(t.planes, t.planes + 6, tc.planes);
  const float pixelsPerUnit = 0.5f * p.tessellation.viewportHeight * p.proj[1][1];
  tc.eye = glm::vec4(t.eye, pixelsPerUnit);
  tc.detail = glm::vec4(std::max(p.tessellation.pixelsPerEdge, 0.5f), std::clamp(p.tessellation.maxFactor, 1.f, 64.f),
                        mat.twoSided ? 0.f : 1.f, displace ? kBackFaceMarginDisplace : kBackFaceMarginPhong);
  tc.surface = glm::vec4(displace ? 1.f : 0.f, displace ? e.desc.relief : 0.f, kPhongShape, 0.f);
  d3dl::MAPPED_SUBRESOURCE map;
  if (FAILED(ctx->Map(t.cb.Get(), 0, d3dl::MAP_WRITE_DISCARD, 0, &map))) return false;
  std::memcpy(map.pData, &tc, sizeof tc);
  ctx->Unmap(t.cb.Get(), 0);
  d3dl::Buffer* cbs[2] = {objectCB.Get(), t.cb.Get()};
  d3dl::ShaderResourceView* height = displace ? e.tess.displacement.Get() : t.flatHeight.Get();
  d3dl::SamplerState* smp = t.sampler.Get();
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_3_CONTROL_POINT_PATCHLIST);
  ctx->IASetInputLayout(t.layout[n].Get());
  ctx->VSSetShader(t.vs[n].Get());
  ctx->HSSetShader(t.hs[n].Get());
  ctx->HSSetConstantBuffers(0, 2, cbs);
  ctx->DSSetShader(t.ds[n * 2 + (p.writeVelocity ? 1 : 0)].Get());
  ctx->DSSetConstantBuffers(0, 2, cbs);
  ctx->DSSetShaderResources(0, 1, &height);
  ctx->DSSetSamplers(0, 1, &smp);
  return true;
}

void SceneImpl::UnbindTessellation(d3dl::DeviceContext* ctx) {
  ctx->HSSetShader(nullptr);
  ctx->DSSetShader(nullptr);
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
}

}  // namespace drr
