// The scene's frame: the original's matrix ring (frame move, pause, resize
// reset), its culling, the draw list in the description's order and its
// recording.
#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstring>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/SceneImpl.h"

namespace drr {
using d3dl::FAILED;
using d3dl::UINT;

namespace {
float MaxScale(const glm::mat4& m) {
  return std::sqrt(std::max({glm::dot(glm::vec3(m[0]), glm::vec3(m[0])), glm::dot(glm::vec3(m[1]), glm::vec3(m[1])),
                             glm::dot(glm::vec3(m[2]), glm::vec3(m[2]))}));
}

// World-space planes of a view-projection (left, right, bottom, top, near for 0..1 depth, far).
void FrustumPlanes(const glm::mat4& viewProj, glm::vec4 planes[6]) {
  const glm::mat4 t = glm::transpose(viewProj);
  const glm::vec4 all[6] = {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[2], t[3] - t[2]};
  for (int k = 0; k < 6; ++k) {
    planes[k] = all[k];
    const float l = glm::length(glm::vec3(planes[k]));
    if (l > 0 && std::isfinite(l)) planes[k] /= l;
  }
}
}  // namespace

// The original's resize: the current and previous slots both get this pose.
void SceneImpl::ResetHistory(const glm::mat4& view, const glm::mat4& viewProj) {
  history.frameIndex = 0;
  history.view = view;
  history.started = true;
  for (Entry& e : entries) {
    const glm::mat4 entryViewProj = viewProj * e.transform;  // once per entry: the same products
    for (DrawItem& it : e.items) it.wvp[0] = it.wvp[1] = entryViewProj * e.globals[it.node];
  }
}

// The original's OnFrameMove: the next slot of the ring gets this frame's
// matrices, and the TAA target remembers which slot it was drawn with.
void SceneImpl::FrameMove(const glm::mat4& view, const glm::mat4& viewProj, int target) {
  history.previous = history.frameIndex;
  history.frameIndex = (history.frameIndex + 1) % 3;
  history.current = history.frameIndex;
  history.track[target & 1] = history.current;
  history.view = view;
  for (Entry& e : entries) {
    const glm::mat4 entryViewProj = viewProj * e.transform;  // once per entry: the same products
    for (DrawItem& it : e.items) it.wvp[history.current] = entryViewProj * e.globals[it.node];
  }
}

// The original's OnFramePaused: nothing moves; the target is redrawn with the
// matrices it was last drawn with and the slot before them, so its velocity
// (and the motion blur) stays that of the frame before the pause.
void SceneImpl::FramePaused(int target) {
  history.current = history.track[target & 1];
  history.previous = (history.current + 2) % 3;
}

// The original culls only meshes whose box centre is behind the eye: wholly
// behind (box radius), or projected off the screen. With the frustum-cull fix,
// bounding spheres against the six frustum planes instead.
bool SceneImpl::Culled(const Entry& e, const DrawItem& it, const glm::mat4& world, const glm::vec4 planes[6],
                       bool frustum) const {
  const GpuMesh& m = e.meshes[it.mesh];
  if (frustum) {
    const glm::vec3 c = glm::vec3(world * glm::vec4(m.sphereCenter, 1.f));
    const float r = m.sphereRadius * MaxScale(world);
    for (int k = 0; k < 6; ++k)
      if (glm::dot(glm::vec3(planes[k]), c) + planes[k].w < -r) return true;
    return false;
  }
  const float depth = -(history.view * world * glm::vec4(m.boxCenter, 1.f)).z;  // right-handed view: -z ahead
  if (depth >= 0.f) return false;
  const float radius = glm::length(glm::mat3(world) * m.boxExtents);
  if (radius + depth < 0.f) return true;
  const glm::mat4& wvp = it.wvp[history.current];
  const glm::vec4 clip = wvp * glm::vec4(m.boxCenter, 1.f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  const float r = glm::length(glm::mat3(wvp) * m.boxExtents);  // the original's clip-space radius
  return ndc.x + r < -1.f || ndc.y + r < -1.f || ndc.x - r > 1.f || ndc.y - r > 1.f;
}

// The draw's shaders and sampler, created at first use: on the calling
// thread, before the split (creation is not thread-safe, recording only reads).
// A tessellated draw's vertex stage is the tessellation's (BindTessellation).
bool SceneImpl::Resolve(const SceneRenderParams& p, DrawRecord& r) {
  const int variant = VariantIndex(r.material->hasNormal, r.material->hasSpecular, p.writeVelocity);
  r.ps = p.gbuffer ? GBufferVariant(variant) : Variant(variant);
  if (!r.ps || (r.tess == TessMode::None && !VertexStage(variant, &r.vs, &r.il))) return false;
  r.sampler = p.viewMipBias ? MaterialSampler(p, *r.material) : nullptr;
  return true;
}

// One entry's draws, culled and appended to the draw list (culled here, so that
// the chunks of the split hold draws that are recorded). A DECAL entry draws all its
// meshes (blended, in the description's order, as the original); other
// entries draw their opaque meshes, or with blendedOnly the alpha-blended
// materials of model formats the original never loaded, after everything else.
void SceneImpl::CollectEntry(const SceneRenderParams& p, const Entry& e, bool blendedOnly, const glm::vec4 planes[6]) {
  const bool decalEntry = e.desc.type == EntryType::Decal;
  if (e.desc.hidden || (blendedOnly && decalEntry)) return;
  if (e.desc.type == EntryType::Camera && !p.showCameras) return;
  d3dl::Buffer* light = e.desc.type == EntryType::Unlit ? unlitCB.Get() : litCB.Get();
  for (const DrawItem& it : e.items) {
    const GpuMesh& m = e.meshes[it.mesh];
    const GpuMaterial& mat = e.materials[m.material < e.materials.size() ? m.material : 0];
    if (!decalEntry && mat.blend != blendedOnly) continue;
    DrawRecord r{&m, &mat, &it, e.transform * e.globals[it.node]};
    if (Culled(e, it, r.world, planes, p.frustumCulling)) {
      ++stats.drawsCulled;
      continue;
    }
    r.lightCB = light;
    r.decal = decalEntry || blendedOnly;
    r.entry = &e;
    r.tess = TessModeFor(p, e, m);  // None unless --tessellation and a rule (SceneTessellation.cpp)
    if (!Resolve(p, r)) continue;
    drawList.push_back(r);
    if (r.tess != TessMode::None) {
      ++stats.tessellatedDraws;
      stats.patchesSubmitted += m.indexCount / 3;
    }
  }
}

// The state every recording context starts with (a deferred context also
// needs the caller's render targets and viewport: a list starts from the
// default state, as in D3D11).
void SceneImpl::BeginDraws(d3dl::DeviceContext* ctx, const FrameDraw& f, bool setTargets) {
  if (setTargets) {
    UINT count = 0;
    while (count < std::size(f.rtv) && f.rtv[count]) ++count;
    ctx->OMSetRenderTargets(count, f.rtv, f.dsv);
    ctx->RSSetViewports(1, &f.viewport);
  }
  ctx->IASetPrimitiveTopology(d3dl::PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  ctx->VSSetConstantBuffers(0, 1, &f.objectCB);
  ctx->PSSetConstantBuffers(0, 1, &f.objectCB);
  ctx->PSSetSamplers(0, 1, &f.sampler);
}

// Draws [first, last) of the draw list on ctx; the per-object constants are
// a WRITE_DISCARD Map per draw on ctx. Reads only: safe on several threads at
// once, each with its own context. Returns the draws issued.
uint32_t SceneImpl::RecordDraws(d3dl::DeviceContext* ctx, const FrameDraw& f, const DrawRecord* first,
                                const DrawRecord* last) const {
  uint32_t issued = 0;
  int decal = -1;
  d3dl::Buffer* light = nullptr;
  for (const DrawRecord* r = first; r != last; ++r) {
    if (int(r->decal) != decal) {
      decal = int(r->decal);
      ctx->OMSetDepthStencilState(r->decal ? dsDecal.Get() : dsOpaque.Get(), 0);
      ctx->OMSetBlendState(r->decal ? f.decalBlend : nullptr, nullptr, 0xffffffffu);
    }
    if (r->lightCB != light) {
      light = r->lightCB;
      ctx->PSSetConstantBuffers(1, 1, &light);
    }
    d3dl::MAPPED_SUBRESOURCE map;
    if (FAILED(ctx->Map(f.objectCB, 0, d3dl::MAP_WRITE_DISCARD, 0, &map))) continue;
    // Both matrices jittered alike, so the jitter never shows as velocity.
    const ObjectConstants oc{f.jitter * r->item->wvp[f.current], f.jitter * r->item->wvp[f.previous], r->world,
                             r->material->tint, glm::vec4(f.eye, 1.f)};
    std::memcpy(map.pData, &oc, sizeof oc);
    ctx->Unmap(f.objectCB, 0);
    const GpuMaterial& mat = *r->material;
    if (r->tess == TessMode::None) {
      ctx->IASetInputLayout(r->il);
      ctx->VSSetShader(r->vs);
    } else if (!BindTessellation(ctx, *f.params, *r->entry, *r->mesh, mat, r->tess)) {
      continue;
    }
    ctx->PSSetShader(r->ps);
    d3dl::ShaderResourceView* views[3] = {mat.diffuse.Get(), mat.normal.Get(), mat.specular.Get()};
    ctx->PSSetShaderResources(0, 3, views);
    if (r->sampler) ctx->PSSetSamplers(0, 1, &r->sampler);
    ctx->RSSetState(mat.twoSided ? rsNone.Get() : rsBack.Get());
    const GpuMesh& m = *r->mesh;
    d3dl::Buffer* vb = m.vb.Get();
    UINT stride = sizeof(SceneVertex), offset = 0;
    ctx->IASetVertexBuffers(0, 1, &vb, &stride, &offset);
    ctx->IASetIndexBuffer(m.ib.Get(), m.indexFormat, 0);
    ctx->DrawIndexed(m.indexCount, 0, 0);
    if (r->tess != TessMode::None) UnbindTessellation(ctx);
    ++issued;
  }
  return issued;
}

// The caller's context after the scene: default blend, depth and rasterizer
// states, no scene textures bound.
void SceneImpl::EndDraws(d3dl::DeviceContext* ctx) {
  ctx->OMSetBlendState(nullptr, nullptr, 0xffffffffu);
  ctx->OMSetDepthStencilState(nullptr, 0);
  ctx->RSSetState(nullptr);
  d3dl::ShaderResourceView* none[3] = {};
  ctx->PSSetShaderResources(0, 3, none);
}

// TAAU's view mip bias: the scene's sampler with MipLODBias = bias (1/16
// steps, cached), or the plain one for a material that opted out.
d3dl::SamplerState* SceneImpl::ViewBiasSampler(float bias) {
  const int key = int(std::lround(std::clamp(bias, -16.f, 15.99f) * 16.f));
  ComPtr<d3dl::SamplerState>& smp = samplersViewBias[key];
  if (!smp) {
    d3dl::SAMPLER_DESC sd;
    const uint32_t anisotropy = opts.maxAnisotropy;
    sd.Filter = anisotropy > 1 ? d3dl::FILTER_ANISOTROPIC : d3dl::FILTER_MIN_MAG_MIP_LINEAR;
    sd.AddressU = sd.AddressV = sd.AddressW = d3dl::TEXTURE_ADDRESS_WRAP;
    sd.MaxAnisotropy = std::clamp<uint32_t>(anisotropy, 1, 16);
    sd.MinLOD = 0.f;
    sd.MipLODBias = float(key) / 16.f;
    if (FAILED(device->CreateSamplerState(&sd, smp.GetAddressOf()))) return samplerAniso.Get();
  }
  return smp.Get();
}

d3dl::SamplerState* SceneImpl::MaterialSampler(const SceneRenderParams& p, const GpuMaterial& mat) {
  for (const std::string& name : p.mipBiasOptOut)
    if (name == mat.name) return samplerAniso.Get();
  return ViewBiasSampler(*p.viewMipBias);
}

// The frame's draw list (matrix history, culling, shader resolution) is built
// on the calling thread; the draws are recorded there too, or split across
// the recording threads (SceneRecordThreads.cpp).
void Scene::Render(d3dl::DeviceContext* ctx, const SceneRenderParams& p) {
  const auto start = std::chrono::steady_clock::now();
  SceneImpl& s = *impl_;
  s.stats.drawsIssued = s.stats.drawsCulled = 0;
  s.stats.tessellatedDraws = 0;
  s.stats.patchesSubmitted = 0;
  if (!ctx) return;
  FrameDraw f;
  f.params = &p;
  f.objectCB = s.objectCB.Get();
  f.sampler = p.mipBiasSampler ? s.samplerBias.Get() : s.samplerAniso.Get();
  const std::function<void()> prepare = [&] {
    const glm::mat4 viewProj = p.proj * p.view;
    if (p.paused && s.history.started) {
      s.FramePaused(p.target);
    } else {
      if (p.resetHistory || !s.history.started) s.ResetHistory(p.view, viewProj);
      s.FrameMove(p.view, viewProj, p.target);
    }
    f.jitter = glm::translate(glm::mat4(1.f), glm::vec3(p.jitterNdc, 0.f));
    f.eye = p.shadingEye ? *p.shadingEye : glm::vec3(glm::inverse(s.history.view)[3]);
    f.current = s.history.current;
    f.previous = s.history.previous;
    glm::vec4 planes[6];
    FrustumPlanes(p.proj * s.history.view, planes);
    s.PrepareTessellation(p, planes);
    f.decalBlend = s.DecalBlend(p.gbuffer);
    s.drawList.clear();
    for (const Entry& e : s.entries) s.CollectEntry(p, e, false, planes);
    for (const Entry& e : s.entries) s.CollectEntry(p, e, true, planes);
  };
  ctx->BeginEvent("Scene");
  // Automatic (0): sized by the previous frame's draw list, as this one's is
  // built while the workers wake up.
  const int threads = p.recordingThreads > 0 ? p.recordingThreads : AutoRecordingThreads(uint32_t(s.drawList.size()));
  const bool threaded = threads > 1 && p.viewport && ctx->GetType() == d3dl::DEVICE_CONTEXT_IMMEDIATE;
  if (!threaded || !s.RecordThreaded(ctx, threads, p, f, prepare)) {
    const auto planning = std::chrono::steady_clock::now();
    prepare();
    SceneImpl::BeginDraws(ctx, f, false);
    const auto drawing = std::chrono::steady_clock::now();
    s.stats.planMs = std::chrono::duration<double, std::milli>(drawing - planning).count();
    s.stats.waitMs = s.stats.executeMs = 0.0;
    const uint32_t issued = s.RecordDraws(ctx, f, s.drawList.data(), s.drawList.data() + s.drawList.size());
    s.stats.recordingThreads = 1;
    s.stats.drawsPerThread.assign(1, issued);
    const auto drawn = std::chrono::steady_clock::now();
    s.stats.chunkMs.assign(1, std::chrono::duration<double, std::milli>(drawn - drawing).count());
    s.stats.wakeMs.assign(1, 0.0);
    s.stats.finishMs.assign(1, 0.0);
    s.stats.callerChunks = 1;
  }
  SceneImpl::EndDraws(ctx);
  ctx->EndEvent();
  s.stats.drawsIssued = 0;
  for (uint32_t n : s.stats.drawsPerThread) s.stats.drawsIssued += n;
  s.stats.recordMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace drr
