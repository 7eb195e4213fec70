#include "scene/Scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "d3dl/D3DLike.h"
#include "scene/DdsBlocks.h"
#include "scene/IsolatedImport.h"
#include "scene/ModelLoader.h"
#include "scene/SceneDescription.h"
#include "scene/SceneImpl.h"


namespace drr {
namespace fs = std::filesystem;
using d3dl::ComPtr;
using d3dl::FAILED;
using d3dl::SUCCEEDED;
using d3dl::UINT;

std::string SceneStats::ToString() const {
  char b[512];
  snprintf(b, sizeof b,
           "draws %u (culled %u), shader variants %u, textures %u (%.1f MiB), vertices %.1f MiB, indices %.1f MiB, "
           "triangles %llu",
           drawsIssued, drawsCulled, shaderVariantsUsed, texturesLoaded, textureBytes / 1048576.0, vertexBytes / 1048576.0,
           indexBytes / 1048576.0, (unsigned long long)triangles);
  if (tessellatedDraws == 0) return b;
  char t[128];
  snprintf(t, sizeof t, ", tessellated draws %u (patches %llu)", tessellatedDraws, (unsigned long long)patchesSubmitted);
  return std::string(b) + t;
}

std::string SceneStats::RecordingString() const {
  std::string draws;
  for (uint32_t n : drawsPerThread) draws += (draws.empty() ? "" : " + ") + std::to_string(n);
  char b[96];
  snprintf(b, sizeof b, ", %.3f ms CPU", recordMs);
  std::string taken;
  if (callerChunks > 1) taken = " (the main thread drew " + std::to_string(callerChunks) + " chunks)";
  return "recording threads " + std::to_string(recordingThreads) + ": draws " + (draws.empty() ? "-" : draws) + taken + b;
}

namespace {
// Names of the compiled variants in Shaders/CMakeLists.txt.
std::string VariantFile(int v) {
  char b[64];
  snprintf(b, sizeof b, "scene_ps_n%d_s%d_v%d", (v >> 2) & 1, (v >> 1) & 1, v & 1);
  return b;
}
}  // namespace

void SceneImpl::Warn(const std::string& w) {
  warnings.push_back(w);
  if (opts.verbose) std::printf("scene: warning: %s\n", w.c_str());
}

// ---------------------------------------------------------------------------
static std::string VsFile(int i) { return "scene_vs_n" + std::to_string(i >> 1) + "_v" + std::to_string(i & 1); }

bool SceneImpl::CreateShaders(std::string* error) {
  for (int v = 0; v < 8; ++v) {
    ps[v] = nullptr;
    if (!psWanted[v]) continue;
    if (!shaders.Load(VariantFile(v), false, &psCode[v], error)) return false;
    int vi = ((v >> 2) & 1) * 2 + (v & 1);
    if (vsCode[vi].empty() && !shaders.Load(VsFile(vi), false, &vsCode[vi], error)) return false;
    int vi0 = ((v >> 2) & 1) * 2;  // the no-velocity variant of the same material
    if (vsCode[vi0].empty() && !shaders.Load(VsFile(vi0), false, &vsCode[vi0], error)) return false;
  }
  return true;
}

// The vertex shader (and its input layout) matching pixel-shader variant v.
bool SceneImpl::VertexStage(int v, d3dl::VertexShader** shader, d3dl::InputLayout** il) {
  int vi = ((v >> 2) & 1) * 2 + (v & 1);
  if (!vs[vi]) {
    std::string err;
    if (vsCode[vi].empty() && !shaders.Load(VsFile(vi), false, &vsCode[vi], &err)) {
      Warn(err);
      return false;
    }
    if (FAILED(device->CreateVertexShader(vsCode[vi].data(), vsCode[vi].size() * 4, vs[vi].ReleaseAndGetAddressOf()))) {
      Warn("scene: CreateVertexShader failed for " + VsFile(vi));
      return false;
    }
    const d3dl::INPUT_ELEMENT_DESC elems[] = {
        {"POSITION", 0, d3dl::DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, d3dl::INPUT_PER_VERTEX_DATA, 0},
        {"NORMAL", 0, d3dl::DXGI_FORMAT_R32G32B32_FLOAT, 0, 12, d3dl::INPUT_PER_VERTEX_DATA, 0},
        {"TEXCOORD", 0, d3dl::DXGI_FORMAT_R32G32_FLOAT, 0, 24, d3dl::INPUT_PER_VERTEX_DATA, 0},
        {"TANGENT", 0, d3dl::DXGI_FORMAT_R32G32B32_FLOAT, 0, 32, d3dl::INPUT_PER_VERTEX_DATA, 0},
        {"BINORMAL", 0, d3dl::DXGI_FORMAT_R32G32B32_FLOAT, 0, 44, d3dl::INPUT_PER_VERTEX_DATA, 0},
    };
    // Variants without normal mapping do not read the tangent frame.
    UINT count = (vi >> 1) ? 5 : 3;
    if (FAILED(device->CreateInputLayout(elems, count, vsCode[vi].data(), vsCode[vi].size() * 4,
                                         layout[vi].ReleaseAndGetAddressOf()))) {
      vs[vi] = nullptr;
      Warn("scene: CreateInputLayout failed for " + VsFile(vi));
      return false;
    }
  }
  *shader = vs[vi].Get();
  *il = layout[vi].Get();
  return true;
}

d3dl::PixelShader* SceneImpl::Variant(int v) {
  if (!ps[v]) {
    if (psCode[v].empty()) {
      std::string err;
      if (!shaders.Load(VariantFile(v), false, &psCode[v], &err)) {
        Warn(err);
        return nullptr;
      }
    }
    if (FAILED(device->CreatePixelShader(psCode[v].data(), psCode[v].size() * 4, ps[v].ReleaseAndGetAddressOf()))) {
      Warn("scene: CreatePixelShader failed for " + VariantFile(v));
      return nullptr;
    }
    psWanted[v] = true;
  }
  return ps[v].Get();
}

ComPtr<d3dl::ShaderResourceView> SceneImpl::Upload(const std::shared_ptr<const TextureData>& loaded,
                                                   std::string* error) {
  if (auto it = srvs.find(loaded.get()); it != srvs.end()) return it->second;
  // Block-compressed data as it is where the device samples it, else expanded to RGBA8 on the CPU.
  const bool samples = device->CheckFormatSupport(loaded->format, d3dl::BIND_SHADER_RESOURCE);
  const auto t = TextureForDevice(loaded, samples, error);
  if (!t) return nullptr;
  d3dl::TEXTURE2D_DESC td;
  td.Width = t->Width();
  td.Height = t->Height();
  td.MipLevels = UINT(t->mips.size());
  td.Format = t->format;
  td.Usage = d3dl::USAGE_IMMUTABLE;
  td.BindFlags = d3dl::BIND_SHADER_RESOURCE;
  std::vector<d3dl::SUBRESOURCE_DATA> init(t->mips.size());
  for (size_t i = 0; i < t->mips.size(); ++i) {
    init[i].pSysMem = t->mips[i].rgba.data();
    init[i].SysMemPitch = UINT(TextureRowPitch(t->format, t->mips[i].width));
  }
  ComPtr<d3dl::Texture2D> tex;
  ComPtr<d3dl::ShaderResourceView> srv;
  if (FAILED(device->CreateTexture2D(&td, init.data(), tex.GetAddressOf())) ||
      FAILED(device->CreateShaderResourceView(tex.Get(), nullptr, srv.GetAddressOf()))) {
    *error = t->source + ": texture upload failed (" + std::to_string(td.Width) + "x" + std::to_string(td.Height) + ")";
    return nullptr;
  }
  tex->SetDebugName(t->source.c_str());
  gpuTextureBytes += t->Bytes();
  gpuTextureBytesAsRgba8 += t->BytesAsRgba8();
  srvs[loaded.get()] = srv;
  return srv;
}

bool SceneImpl::UploadMesh(const Entry& e, const MeshData& m, GpuMesh* g, std::string* error) {
  d3dl::BUFFER_DESC bd;
  bd.ByteWidth = UINT(m.vertices.size() * sizeof(SceneVertex));
  bd.Usage = d3dl::USAGE_IMMUTABLE;
  bd.BindFlags = d3dl::BIND_VERTEX_BUFFER;
  d3dl::SUBRESOURCE_DATA vd;
  vd.pSysMem = m.vertices.data();
  if (FAILED(device->CreateBuffer(&bd, &vd, g->vb.GetAddressOf()))) {
    *error = e.desc.meshFile + ": vertex buffer creation failed for mesh '" + m.name + "'";
    return false;
  }
  std::vector<uint16_t> i16;
  d3dl::SUBRESOURCE_DATA id;
  if (m.Use16BitIndices()) {
    i16.assign(m.indices.begin(), m.indices.end());
    id.pSysMem = i16.data();
    bd.ByteWidth = UINT(i16.size() * 2);
    g->indexFormat = d3dl::DXGI_FORMAT_R16_UINT;
  } else {
    id.pSysMem = m.indices.data();
    bd.ByteWidth = UINT(m.indices.size() * 4);
    g->indexFormat = d3dl::DXGI_FORMAT_R32_UINT;
  }
  bd.BindFlags = d3dl::BIND_INDEX_BUFFER;
  if (FAILED(device->CreateBuffer(&bd, &id, g->ib.GetAddressOf()))) {
    *error = e.desc.meshFile + ": index buffer creation failed for mesh '" + m.name + "'";
    return false;
  }
  g->vb->SetDebugName((e.desc.name + "/" + m.name + " VB").c_str());
  g->ib->SetDebugName((e.desc.name + "/" + m.name + " IB").c_str());
  stats.vertexBytes += m.vertices.size() * sizeof(SceneVertex);
  stats.indexBytes += bd.ByteWidth;
  stats.triangles += m.indices.size() / 3;
  g->indexCount = UINT(m.indices.size());
  g->material = m.material;
  g->boxCenter = (m.boundsMin + m.boundsMax) * 0.5f;
  g->boxExtents = (m.boundsMax - m.boundsMin) * 0.5f;
  g->sphereCenter = m.sphereCenter;
  g->sphereRadius = m.sphereRadius;
  return true;
}

// Only the textures that materials of drawn meshes use are uploaded.
bool SceneImpl::UploadMaterials(Entry& e, TextureCache& cache, std::string* error) {
  std::vector<bool> used(e.model.materials.size(), false);
  for (const auto& m : e.model.meshes)
    if (m.material < used.size()) used[m.material] = true;
  e.materials.resize(e.model.materials.size());
  for (size_t i = 0; i < e.model.materials.size(); ++i) {
    if (!used[i]) continue;
    const MaterialData& md = e.model.materials[i];
    GpuMaterial& gm = e.materials[i];
    std::vector<std::string> w;
    gm.diffuse = Upload(cache.Get(e.model, md.diffuseTex, TextureKind::Color, &w), error);
    gm.hasNormal = !md.normalTex.empty();
    gm.hasSpecular = !md.specularTex.empty();
    if (gm.hasNormal) gm.normal = Upload(cache.Get(e.model, md.normalTex, TextureKind::Normal, &w), error);
    if (gm.hasSpecular) gm.specular = Upload(cache.Get(e.model, md.specularTex, TextureKind::Specular, &w), error);
    for (auto& x : w) Warn(x);
    if (!gm.diffuse || (gm.hasNormal && !gm.normal) || (gm.hasSpecular && !gm.specular)) return false;
    gm.blend = md.alphaBlend || e.desc.type == EntryType::Decal;
    gm.twoSided = md.twoSided;
    gm.tint = md.diffuseColor;
    gm.name = md.name;
    psWanted[VariantIndex(gm.hasNormal, gm.hasSpecular, true)] = true;
  }
  return true;
}

bool SceneImpl::LoadEntry(Entry& e, TextureCache& cache, std::string* error) {
  const std::shared_ptr<const ModelData> model = models.Get(e.desc.meshFile, {}, error);
  if (!model) return false;
  e.model = CopyWithoutGeometry(*model);  // the geometry lives in the shared GPU buffers
  if (!e.desc.animFile.empty() && fs::path(e.desc.animFile) != fs::path(e.desc.meshFile)) {
    ModelLoadOptions ao;
    ao.animationsOnly = true;
    const std::shared_ptr<const ModelData> anim = models.Get(e.desc.animFile, ao, error);
    if (!anim) return false;
    if (AttachAnimations(&e.model, *anim) == 0)
      Warn(e.desc.animFile + ": no animation channel matches a node of " + e.desc.meshFile);
  }
  e.transform = e.desc.Transform();
  auto [shared, firstUse] = uploaded.try_emplace(e.desc.meshFile);
  if (firstUse) {
    for (const auto& w : model->warnings) Warn(e.desc.meshFile + ": " + w);
    e.model.embedded = model->embedded;  // decoded once: later entries find them in the texture cache
    for (const MeshData& m : model->meshes) {
      GpuMesh g;
      if (!UploadMesh(e, m, &g, error)) return false;
      shared->second.push_back(std::move(g));
    }
  } else {
    stats.triangles += model->Triangles();
  }
  e.meshes = shared->second;
  if (!UploadMaterials(e, cache, error)) return false;
  std::vector<EmbeddedTexture>().swap(e.model.embedded);
  // Draw items: every (node, mesh) pair.
  for (size_t n = 0; n < e.model.nodes.size(); ++n)
    for (uint32_t m : e.model.nodes[n].meshes) e.items.push_back({int(n), int(m)});
  e.model.Evaluate(0.0, &e.globals, e.desc.loopSeconds);
  return true;
}

// Entries: from a description, or one LIT entry for a single model file.
bool SceneImpl::ReadEntries(const std::string& path, bool single, std::string* error) {
  if (single) {
    Entry e;
    e.desc.meshPath = path;
    e.desc.meshFile = path;
    e.desc.type = EntryType::Lit;
    e.desc.name = fs::path(path).stem().string();
    entries.push_back(std::move(e));
    return true;
  }
  SceneDescription desc;
  if (!LoadSceneDescription(path, {}, &desc, error)) return false;
  for (const auto& w : desc.warnings) Warn(w);
  lights = desc.lights;
  for (auto& d : desc.entries) {
    Entry e;
    e.desc = d;
    entries.push_back(std::move(e));
  }
  return true;
}

// The original's RenderScene values; UNLIT keeps only the ambient term at 1.
SceneLightingValues SceneLighting(bool lit) {
  const glm::vec4 light(0.89f, -0.45f, 0.089f, 16.f);
  if (!lit) return {{0.f, 0.f, 0.f, 1.f}, {1.f, 1.f, 1.f, 1.f}, {0.f, 0.f, 0.f, 1.f}, light};
  return {{1.58f, 1.36f, 0.74f, 1.f}, {0.42f, 0.44f, 0.46f, 1.f}, {1.30f, 1.18f, 0.78f, 1.f}, light};
}

bool SceneImpl::CreateConstantBuffers() {
  d3dl::BUFFER_DESC cb;
  cb.ByteWidth = sizeof(ObjectConstants);
  cb.Usage = d3dl::USAGE_DYNAMIC;
  cb.BindFlags = d3dl::BIND_CONSTANT_BUFFER;
  cb.CPUAccessFlags = d3dl::CPU_ACCESS_WRITE;
  bool ok = SUCCEEDED(device->CreateBuffer(&cb, nullptr, objectCB.GetAddressOf()));
  const SceneLightingValues lit = SceneLighting(true), unlit = SceneLighting(false);
  static_assert(sizeof(SceneLightingValues) == sizeof(LightingConstants));
  cb.ByteWidth = sizeof(LightingConstants);
  cb.Usage = d3dl::USAGE_IMMUTABLE;
  cb.CPUAccessFlags = 0;
  d3dl::SUBRESOURCE_DATA init;
  init.pSysMem = &lit;
  ok = ok && SUCCEEDED(device->CreateBuffer(&cb, &init, litCB.GetAddressOf()));
  init.pSysMem = &unlit;
  ok = ok && SUCCEEDED(device->CreateBuffer(&cb, &init, unlitCB.GetAddressOf()));
  return ok;
}

// Samplers, rasterizer, depth and blend states.
bool SceneImpl::CreateStates() {
  d3dl::SAMPLER_DESC sd;
  const uint32_t anisotropy = opts.maxAnisotropy;
  sd.Filter = anisotropy > 1 ? d3dl::FILTER_ANISOTROPIC : d3dl::FILTER_MIN_MAG_MIP_LINEAR;
  sd.AddressU = sd.AddressV = sd.AddressW = d3dl::TEXTURE_ADDRESS_WRAP;
  sd.MaxAnisotropy = std::clamp<uint32_t>(anisotropy, 1, 16);
  sd.MinLOD = 0.f;
  bool ok = SUCCEEDED(device->CreateSamplerState(&sd, samplerAniso.GetAddressOf()));
  sd.MipLODBias = -0.5f;
  ok = ok && SUCCEEDED(device->CreateSamplerState(&sd, samplerBias.GetAddressOf()));
  d3dl::RASTERIZER_DESC rd;
  rd.CullMode = d3dl::CULL_BACK;
  rd.FrontCounterClockwise = 1;  // glTF / right-handed models: counter-clockwise front faces
  ok = ok && SUCCEEDED(device->CreateRasterizerState(&rd, rsBack.GetAddressOf()));
  rd.CullMode = d3dl::CULL_NONE;
  ok = ok && SUCCEEDED(device->CreateRasterizerState(&rd, rsNone.GetAddressOf()));
  d3dl::DEPTH_STENCIL_DESC dd;  // depth test LESS with writes
  ok = ok && SUCCEEDED(device->CreateDepthStencilState(&dd, dsOpaque.GetAddressOf()));
  // Decals as the original: LESS_EQUAL (co-planar decals pass) without depth writes;
  // colour blended by source alpha, alpha written as the source's.
  dd.DepthWriteMask = d3dl::DEPTH_WRITE_MASK_ZERO;
  dd.DepthFunc = d3dl::COMPARISON_LESS_EQUAL;
  ok = ok && SUCCEEDED(device->CreateDepthStencilState(&dd, dsDecal.GetAddressOf()));
  d3dl::BLEND_DESC bd;
  bd.IndependentBlendEnable = 1;
  bd.RenderTarget[0].BlendEnable = 1;
  bd.RenderTarget[0].SrcBlend = d3dl::BLEND_SRC_ALPHA;
  bd.RenderTarget[0].DestBlend = d3dl::BLEND_INV_SRC_ALPHA;
  bd.RenderTarget[0].SrcBlendAlpha = d3dl::BLEND_ONE;
  bd.RenderTarget[0].DestBlendAlpha = d3dl::BLEND_ZERO;
  bd.RenderTarget[1].RenderTargetWriteMask = 0;  // decals keep the surface's velocity
  ok = ok && SUCCEEDED(device->CreateBlendState(&bd, bsDecal.GetAddressOf()));
  return ok;
}

// CAMERA entries' cameras (the file's first camera, or its last node with a mesh), and
// the world bounds of the entries that are drawn (the sky dome does not frame anything).
void SceneImpl::ListCamerasAndBounds() {
  glm::vec3 mn(1e30f), mx(-1e30f);
  for (size_t i = 0; i < entries.size(); ++i) {
    Entry& e = entries[i];
    if (e.desc.type == EntryType::Camera) {
      // One camera per CAMERA entry, named after its file as the original's list.
      cameras.push_back({e.desc.name, int(i), e.model.cameras.empty() ? -1 : 0, {}});
    } else if (e.desc.type != EntryType::Unlit) {
      glm::vec3 a, b;
      e.model.Bounds(&a, &b);
      for (int k = 0; k < 8; ++k) {
        glm::vec3 p((k & 1) ? b.x : a.x, (k & 2) ? b.y : a.y, (k & 4) ? b.z : a.z);
        glm::vec3 w = glm::vec3(e.transform * glm::vec4(p, 1.f));
        mn = glm::min(mn, w);
        mx = glm::max(mx, w);
      }
    }
  }
  if (mn.x > mx.x) mn = mx = glm::vec3(0.f);
  boundsMin = mn;
  boundsMax = mx;
}

// The original's scene centre: the mean of every drawn mesh's bounding-box
// centre (cameras, sky and decals included) at animation time 0. The original
// moves the scene there; the port keeps its coordinates and starts the
// first-person camera there instead, which frames the same view.
void SceneImpl::ComputeOriginalCentre() {
  glm::vec3 sum(0.f);
  int count = 0;
  for (Entry& e : entries) {
    std::vector<glm::mat4> atZero;
    e.model.Evaluate(0.0, &atZero, e.desc.loopSeconds);
    for (const DrawItem& it : e.items) {
      const GpuMesh& m = e.meshes[it.mesh];
      sum += glm::vec3(e.transform * atZero[it.node] * glm::vec4(m.boxCenter, 1.f));
      ++count;
    }
  }
  originalCentre = count ? sum / float(count) : glm::vec3(0.f);
}

// A camera that frames the scene's bounds from above and to the side.
CameraRef SceneImpl::AutomaticCamera() const {
  glm::vec3 center = (boundsMin + boundsMax) * 0.5f;
  float radius = std::max(glm::length(boundsMax - boundsMin) * 0.5f, 1e-3f);
  float dist = radius / std::sin(glm::radians(45.f) * 0.5f) * 1.1f;
  CameraRef a;
  a.name = "Automatic";
  a.fixed.position = center + glm::normalize(glm::vec3(0.6f, 0.45f, 1.f)) * dist;
  a.fixed.view = glm::lookAtRH(a.fixed.position, center, glm::vec3(0, 1, 0));
  a.fixed.nearZ = std::max(dist - radius * 1.5f, dist * 0.01f);
  a.fixed.farZ = std::max(dist + radius * 4.f, a.fixed.nearZ * 10.f);
  return a;
}

// ---------------------------------------------------------------------------
Scene::Scene() : impl_(std::make_unique<SceneImpl>()) {}
Scene::~Scene() = default;

std::unique_ptr<Scene> Scene::Load(d3dl::Device* device, const std::string& path, const SceneLoadOptions& opts,
                                   std::string* error) {
  std::string dummy;
  if (!error) error = &dummy;
  if (!device) {
    *error = "Scene::Load: no device";
    return nullptr;
  }
  std::unique_ptr<Scene> scene(new Scene());
  SceneImpl& s = *scene->impl_;
  s.device = ComPtr<d3dl::Device>(device);
  s.opts = opts;
  if (opts.shaders) s.shaders = *opts.shaders;
  else s.shaders.Open(ShaderLibrary::DefaultSpvDir({}), ShaderLibrary::DefaultSourceDir());

  const bool single = !IsSceneDescriptionPath(path);
  if (!s.ReadEntries(path, single, error)) return nullptr;
  TextureCache cache({}, IsolatedTextureLoader());
  for (auto& e : s.entries)
    if (!s.LoadEntry(e, cache, error) || !s.LoadTessellation(e, error)) return nullptr;
  s.stats.texturesLoaded = uint32_t(cache.LoadedCount());
  if (!s.CreateShaders(error)) return nullptr;
  if (!s.CreateConstantBuffers() || !s.CreateStates()) {
    *error = "scene: creating constant buffers or states failed";
    return nullptr;
  }

  s.ListCamerasAndBounds();
  if (single) {
    // Files' own cameras are listed after an automatic camera that frames the model.
    for (size_t c = 0; c < s.entries[0].model.cameras.size(); ++c)
      s.cameras.push_back({s.entries[0].model.cameras[c].name, 0, int(c), {}, true});
  }
  if (single) s.cameras.insert(s.cameras.begin(), s.AutomaticCamera());
  s.ComputeOriginalCentre();
  if (opts.verbose) std::printf("scene: %s: %s\n", path.c_str(), s.stats.ToString().c_str());
  scene->Update(0.0);
  return scene;
}

void Scene::Update(double t) {
  for (auto& e : impl_->entries) e.model.Evaluate(t, &e.globals, e.desc.loopSeconds);
}

int Scene::CameraCount() const { return int(impl_->cameras.size()); }
const std::string& Scene::CameraName(int i) const {
  static const std::string none;
  return i >= 0 && i < CameraCount() ? impl_->cameras[i].name : none;
}
glm::vec3 Scene::OriginalCentre() const { return impl_->originalCentre; }
const std::vector<std::string>& Scene::Warnings() const { return impl_->warnings; }
glm::vec3 Scene::BoundsMin() const { return impl_->boundsMin; }
glm::vec3 Scene::BoundsMax() const { return impl_->boundsMax; }

CameraPose Scene::Camera(int i) const {
  CameraPose pose;
  pose.view = glm::mat4(1.f);
  pose.position = glm::vec3(0.f);
  if (i < 0 || i >= CameraCount()) return pose;
  const CameraRef& c = impl_->cameras[i];
  if (c.entry < 0) return c.fixed;
  const Entry& e = impl_->entries[c.entry];
  glm::vec3 p(0.f), look(0, 0, -1), up(0, 1, 0);
  glm::mat4 w = e.transform;
  if (c.camera >= 0) {
    const CameraData& cd = e.model.cameras[c.camera];
    if (cd.node >= 0 && cd.node < int(e.globals.size())) w = w * e.globals[cd.node];
    p = cd.position;
    look = cd.lookAt;
    up = cd.up;
    // The original projects every camera with its own 45 degrees; a single
    // model's own cameras (the port's addition) keep their field of view.
    if (c.fileFov && cd.fovY > glm::radians(1.f) && cd.fovY < glm::radians(170.f)) pose.fovY = cd.fovY;
  } else {
    // The original views from its camera model's last node with a mesh, with the inverse of its
    // world matrix: a frame scaled by s (its files' cameras: 10) divides view depths by s, which
    // moves its 20 / 400000 clip planes to 20 s / 400000 s in world units.
    for (size_t n = e.model.nodes.size(); n-- > 0;)
      if (!e.model.nodes[n].meshes.empty() && n < e.globals.size()) {
        w = w * e.globals[n];
        break;
      }
    const float depthScale = glm::length(glm::vec3(w[2]));
    if (std::isfinite(depthScale) && depthScale > 1e-3f && depthScale < 1e3f) {
      pose.nearZ *= depthScale;
      pose.farZ *= depthScale;
    }
  }
  glm::vec3 wp = glm::vec3(w * glm::vec4(p, 1.f));
  glm::vec3 wf = glm::normalize(glm::vec3(w * glm::vec4(look, 0.f)));
  glm::vec3 wu = glm::normalize(glm::vec3(w * glm::vec4(up, 0.f)));
  pose.position = wp;
  pose.view = glm::lookAtRH(wp, wp + wf, wu);
  return pose;
}

SceneStats Scene::Stats() const {
  SceneStats s = impl_->stats;
  s.textureBytes = impl_->gpuTextureBytes;
  s.textureBytesAsRgba8 = impl_->gpuTextureBytesAsRgba8;
  s.shaderVariantsUsed = 0;
  for (auto& p : impl_->ps) s.shaderVariantsUsed += p ? 1 : 0;
  for (auto& p : impl_->gbufferPs) s.shaderVariantsUsed += p ? 1 : 0;
  return s;
}

bool Scene::ReloadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error) {
  SceneImpl& s = *impl_;
  std::string dummy;
  if (!error) error = &dummy;
  std::vector<uint32_t> vcode[4], code[8];
  for (int vi = 0; vi < 4; ++vi)
    if (!shaders.Load(VsFile(vi), fromSource, &vcode[vi], error)) return false;
  for (int v = 0; v < 8; ++v) {
    if (!s.psWanted[v] && !s.ps[v]) continue;
    if (!shaders.Load(VariantFile(v), fromSource, &code[v], error)) return false;
  }
  if (!s.ReloadDeferredShaders(shaders, fromSource, error)) return false;
  if (!s.ReloadTessellation(shaders, fromSource, error)) return false;
  s.shaders = shaders;
  s.ResetTessellationStages(fromSource);
  // All compiled: swap in (objects are recreated lazily from the new code).
  for (int vi = 0; vi < 4; ++vi) {
    s.vsCode[vi] = std::move(vcode[vi]);
    s.vs[vi] = nullptr;
    s.layout[vi] = nullptr;
  }
  for (int v = 0; v < 8; ++v) {
    if (code[v].empty()) continue;
    s.psCode[v] = std::move(code[v]);
    s.ps[v] = nullptr;
  }
  return true;
}

}  // namespace drr
