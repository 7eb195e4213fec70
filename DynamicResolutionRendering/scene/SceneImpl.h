// Private to the scene renderer: the loaded entries, their GPU meshes and
// materials, the per-draw matrix history and the renderer's states. Scene.cpp
// loads and lists cameras; SceneDraw.cpp moves frames, culls and draws.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "d3dl/D3DLike.h"
#include "scene/IsolatedImport.h"
#include "scene/ModelLoader.h"
#include "scene/Scene.h"
#include "scene/SceneDescription.h"
#include "scene/SceneThreads.h"

namespace drr {

using d3dl::ComPtr;

// Per-object constants (b0, VS and PS).
struct ObjectConstants {
  glm::mat4 worldViewProj;
  glm::mat4 prevWorldViewProj;
  glm::mat4 world;
  glm::vec4 diffuseTint;
  glm::vec4 eyePosition;
};
static_assert(sizeof(ObjectConstants) == 224);

// Per-type constants (b1, PS): the original's colours with alpha 1, and the
// light direction with the specular power in w.
struct LightingConstants {
  glm::vec4 diffuse, ambient, specular, directionAndPower;
};

inline int VariantIndex(bool normal, bool specular, bool velocity) {
  return (normal ? 4 : 0) | (specular ? 2 : 0) | (velocity ? 1 : 0);
}

struct GpuMesh {
  ComPtr<d3dl::Buffer> vb, ib;
  d3dl::DXGI_FORMAT indexFormat = d3dl::DXGI_FORMAT_R32_UINT;
  uint32_t indexCount = 0;
  uint32_t material = 0;
  glm::vec3 boxCenter{0.f}, boxExtents{0.f};  // the original culls with the bounding box
  glm::vec3 sphereCenter{0.f};                // the frustum-cull fix with the sphere
  float sphereRadius = 0.f;
};

struct GpuMaterial {
  ComPtr<d3dl::ShaderResourceView> diffuse, normal, specular;
  bool hasNormal = false, hasSpecular = false, blend = false, twoSided = false;
  glm::vec4 tint{1.f};
  std::string name;  // the model's material name (the view mip bias opt-out)
};

// The original keeps three world-view-projection matrices per draw: the
// current frame's, the previous frame's, and the one before, so that a paused
// TAA target can be redrawn with the matrices it was last drawn with.
struct DrawItem {
  int node = 0;
  int mesh = 0;
  glm::mat4 wvp[3] = {glm::mat4(1.f), glm::mat4(1.f), glm::mat4(1.f)};  // un-jittered
};

// Tessellation of an entry (SceneTessellation.cpp): the mode of each of its
// materials (from the description's rules) and the displace rules' height map.
struct EntryTessellation {
  std::vector<TessMode> materialMode;
  ComPtr<d3dl::ShaderResourceView> displacement;
};

// The tessellation stages, created at the first tessellated frame; a scene
// without tessellate= rules never creates them.
struct TessellationStages {
  bool tried = false, ok = false;
  bool fromSource = false;           // after F4 with recompilation
  ComPtr<d3dl::VertexShader> vs[2];  // by normal map
  ComPtr<d3dl::InputLayout> layout[2];
  ComPtr<d3dl::HullShader> hs[2];
  ComPtr<d3dl::DomainShader> ds[4];  // normal map * 2 + velocity
  ComPtr<d3dl::Buffer> cb;
  ComPtr<d3dl::SamplerState> sampler;
  ComPtr<d3dl::ShaderResourceView> flatHeight;  // bound for Phong draws (the DS declares t0)
  glm::vec4 planes[6];                          // this frame's frustum (world)
  glm::vec3 eye{0.f};
};

struct Entry {
  SceneEntry desc;
  EntryTessellation tess;
  ModelData model;
  glm::mat4 transform{1.f};
  std::vector<GpuMesh> meshes;
  std::vector<GpuMaterial> materials;
  std::vector<glm::mat4> globals;
  std::vector<DrawItem> items;
};

struct CameraRef {
  std::string name;
  int entry = -1;    // -1: automatic camera (fixed pose)
  int camera = -1;   // index into the entry model's cameras, -1 = its last node with a mesh
  CameraPose fixed;  // automatic camera
  bool fileFov = false;  // a single model's own camera: its field of view
};

// The matrix ring of the original's Scene (m_CurrentFrameIndex, m_TrackIndex).
struct MatrixHistory {
  int current = 0, previous = 0;  // slots of DrawItem::wvp used by this frame's draws
  int frameIndex = 0;             // slot written by the last frame move
  int track[2] = {0, 0};          // slot last written for each TAA target
  bool started = false;           // a frame move has filled the slots
  glm::mat4 view{1.f};            // the view of the last frame move (culling)
};

// One draw of the frame, culled and with its shaders and sampler resolved on
// the calling thread before the split (their lazy creation is not
// thread-safe): the recording threads only read it.
struct DrawRecord {
  const GpuMesh* mesh = nullptr;
  const GpuMaterial* material = nullptr;
  const DrawItem* item = nullptr;
  glm::mat4 world{1.f};
  d3dl::VertexShader* vs = nullptr;
  d3dl::InputLayout* il = nullptr;
  d3dl::PixelShader* ps = nullptr;
  d3dl::SamplerState* sampler = nullptr;  // per-draw s0 (view mip bias); null: the frame's
  d3dl::Buffer* lightCB = nullptr;        // b1 of the entry's type
  bool decal = false;                     // decal depth and blend states
  const Entry* entry = nullptr;           // tessellated draws: the entry's height map and relief
  TessMode tess = TessMode::None;         // through the hull/domain stages (SceneTessellation.cpp)
};

// What every draw of a frame shares; each recording context starts from it.
struct FrameDraw {
  glm::mat4 jitter{1.f};
  glm::vec3 eye{0.f};
  int current = 0, previous = 0;  // MatrixHistory slots
  d3dl::Buffer* objectCB = nullptr;       // b0, mapped per draw
  d3dl::SamplerState* sampler = nullptr;  // s0
  const SceneRenderParams* params = nullptr;
  d3dl::BlendState* decalBlend = nullptr;  // the decals' (forward or G-buffer)
  d3dl::RenderTargetView* rtv[d3dl::SIMULTANEOUS_RENDER_TARGET_COUNT] = {};  // deferred contexts: the caller's targets
  d3dl::DepthStencilView* dsv = nullptr;
  d3dl::VIEWPORT viewport{};
};

struct SceneImpl {
  ComPtr<d3dl::Device> device;
  SceneLoadOptions opts;
  ShaderLibrary shaders;
  std::vector<Entry> entries;
  std::vector<CameraRef> cameras;
  std::vector<std::string> warnings;
  glm::vec3 boundsMin{0.f}, boundsMax{0.f};
  glm::vec3 originalCentre{0.f};
  MatrixHistory history;

  // Vertex shader variants by (NORMAL_MAP, WRITE_VELOCITY): index n*2+v.
  std::vector<uint32_t> vsCode[4];
  ComPtr<d3dl::VertexShader> vs[4];
  ComPtr<d3dl::InputLayout> layout[4];
  std::vector<uint32_t> psCode[8];
  bool psWanted[8] = {};
  ComPtr<d3dl::PixelShader> ps[8];
  ComPtr<d3dl::Buffer> objectCB, litCB, unlitCB;
  ComPtr<d3dl::SamplerState> samplerAniso, samplerBias;
  // TAAU's view mip bias samplers, by bias in 1/16 steps (Docs/Upscaling.md).
  std::map<int, ComPtr<d3dl::SamplerState>> samplersViewBias;
  d3dl::SamplerState* ViewBiasSampler(float bias);
  d3dl::SamplerState* MaterialSampler(const SceneRenderParams& p, const GpuMaterial& mat);
  ComPtr<d3dl::RasterizerState> rsBack, rsNone;
  ComPtr<d3dl::DepthStencilState> dsOpaque, dsDecal;
  ComPtr<d3dl::BlendState> bsDecal;

  SceneStats stats;
  ModelCache models;                                     // one import per distinct file
  std::map<std::string, std::vector<GpuMesh>> uploaded;  // one upload per distinct file
  std::map<const TextureData*, ComPtr<d3dl::ShaderResourceView>> srvs;
  uint64_t gpuTextureBytes = 0;
  uint64_t gpuTextureBytesAsRgba8 = 0;  // the same textures expanded to RGBA8

  void Warn(const std::string& w);
  bool CreateShaders(std::string* error);
  bool ReadEntries(const std::string& path, bool single, std::string* error);
  bool LoadEntry(Entry& e, TextureCache& cache, std::string* error);
  bool UploadMesh(const Entry& e, const MeshData& m, GpuMesh* g, std::string* error);
  bool UploadMaterials(Entry& e, TextureCache& cache, std::string* error);
  bool CreateConstantBuffers();
  bool CreateStates();
  void ListCamerasAndBounds();
  void ComputeOriginalCentre();
  CameraRef AutomaticCamera() const;
  ComPtr<d3dl::ShaderResourceView> Upload(const std::shared_ptr<const TextureData>& t, std::string* error);
  d3dl::PixelShader* Variant(int v);
  bool VertexStage(int v, d3dl::VertexShader** shader, d3dl::InputLayout** il);

  // Deferred shading (SceneDeferred.cpp), created on first use so that the
  // forward path loads none of it.
  std::vector<SceneLight> lights;
  std::vector<uint32_t> gbufferPsCode[8];
  ComPtr<d3dl::PixelShader> gbufferPs[8];
  ComPtr<d3dl::VertexShader> shadowVs;
  ComPtr<d3dl::PixelShader> shadowPs;
  ComPtr<d3dl::InputLayout> shadowLayout;
  ComPtr<d3dl::BlendState> bsDecalGBuffer;
  ComPtr<d3dl::RasterizerState> rsShadow;
  d3dl::PixelShader* GBufferVariant(int v);
  d3dl::BlendState* DecalBlend(bool gbuffer);
  bool CreateShadowStage();
  bool ReloadDeferredShaders(const ShaderLibrary& lib, bool fromSource, std::string* error);
  // SceneTessellation.cpp
  TessellationStages tessStages;
  bool LoadTessellation(Entry& e, std::string* error);
  bool PrepareTessellation(const SceneRenderParams& p, const glm::vec4 planes[6]);
  TessMode TessModeFor(const SceneRenderParams& p, const Entry& e, const GpuMesh& m) const;
  bool BindTessellation(d3dl::DeviceContext* ctx, const SceneRenderParams& p, const Entry& e, const GpuMesh& m,
                        const GpuMaterial& mat, TessMode mode) const;
  static void UnbindTessellation(d3dl::DeviceContext* ctx);
  bool ReloadTessellation(const ShaderLibrary& lib, bool fromSource, std::string* error);
  void ResetTessellationStages(bool fromSource);

  // SceneDraw.cpp
  void ResetHistory(const glm::mat4& view, const glm::mat4& viewProj);
  void FrameMove(const glm::mat4& view, const glm::mat4& viewProj, int target);
  void FramePaused(int target);
  bool Culled(const Entry& e, const DrawItem& it, const glm::mat4& world, const glm::vec4 planes[6],
              bool frustum) const;
  void CollectEntry(const SceneRenderParams& p, const Entry& e, bool blendedOnly, const glm::vec4 planes[6]);
  bool Resolve(const SceneRenderParams& p, DrawRecord& r);
  static void BeginDraws(d3dl::DeviceContext* ctx, const FrameDraw& f, bool setTargets);
  uint32_t RecordDraws(d3dl::DeviceContext* ctx, const FrameDraw& f, const DrawRecord* first,
                       const DrawRecord* last) const;
  static void EndDraws(d3dl::DeviceContext* ctx);
  std::vector<DrawRecord> drawList;  // this frame's, rebuilt by Render

  // SceneRecordThreads.cpp: the split across deferred contexts.
  bool EnsurePool(int threads);
  bool RecordThreaded(d3dl::DeviceContext* immediate, int threads, const SceneRenderParams& p, FrameDraw& f,
                      const std::function<void()>& prepare);
  ChunkBalance chunkBalance;            // learnt from the frames RecordThreaded recorded
  std::unique_ptr<RecordingPool> pool;  // last member: joined before the device goes
};

}  // namespace drr
