// The scene of the sample: models listed in a scene description (or a single
// model file), their animation, the cameras, and the forward renderer that
// writes colour (RT0) and velocity (RT1), as the original's Scene class.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include "ShaderLibrary.h"
#include "scene/SceneDescription.h"
#include "d3dl/Types.h"
#include "scene/SceneVertex.h"

namespace d3dl {
class Device;
class DeviceContext;
}  // namespace d3dl

namespace drr {

struct SceneLoadOptions {
  const ShaderLibrary* shaders = nullptr;  // the compiled scene_* shaders; null = the build's
  bool verbose = false;   // print what is loaded (and the warnings) to stdout
  // Anisotropy of the scene samplers (the original: x16); 1 = trilinear.
  uint32_t maxAnisotropy = 16;
};

struct CameraPose {
  glm::mat4 view;
  glm::vec3 position;
  float fovY = glm::radians(45.f);
  float nearZ = 20.f;
  float farZ = 400000.f;
};

// Screen-space adaptive tessellation (Docs/Tessellation.md): the entries'
// tessellate= rules act only when enabled.
struct TessellationParams {
  bool enabled = false;
  float pixelsPerEdge = 8.f;   // target on-screen edge length ("tessellation detail")
  float maxFactor = 16.f;      // "max tessellation factor", 1..64
  float viewportHeight = 0.f;  // of the dynamic (scene) viewport in pixels; the factors follow it
};

struct SceneRenderParams {
  glm::mat4 view{1.f};
  glm::mat4 proj{1.f};          // glm::perspectiveRH_ZO: right-handed world, clip depth 0..1, +Y up (D3D clip)
  glm::vec2 jitterNdc{0.f};     // added to NDC x,y: clip = T(jitter) * proj * view * world, on current AND previous WVP
  bool mipBiasSampler = false;  // TAA on: sampler with MipLODBias = -0.5 instead of the anisotropic x16 wrap sampler
  bool writeVelocity = true;    // RT1 (R16G16_FLOAT) is bound; false = shader variant without the velocity output
  // The original's matrix history (three slots per draw). resetHistory: the
  // original's resize, the previous matrices become this frame's. paused: the
  // original's OnFramePaused, nothing moves and `target` (the TAA ping-pong
  // index) is redrawn with the matrices it was last drawn with.
  bool resetHistory = false;
  bool paused = false;
  int target = 0;
  bool showCameras = false;     // draw CAMERA entries' models
  // Eye of the specular term; none: the view's. The sample passes the
  // original's first-person eye (Cameras::ShadingEye).
  std::optional<glm::vec3> shadingEye;
  bool frustumCulling = false;  // fix frustum-cull; the original culls only meshes behind the eye
  // Port addition (TAAU, Docs/Upscaling.md): the view mip bias of the texture
  // sampler (anisotropic/trilinear as the scene's, MipLODBias this), except
  // on the materials named in mipBiasOptOut.
  std::optional<float> viewMipBias;
  std::vector<std::string> mipBiasOptOut;
  // Deferred shading (Docs/Deferred.md): the caller bound the G-buffer
  // (diffuse, specular, normal, then velocity when writeVelocity) instead of
  // colour (+ velocity); the materials are written, not lit.
  bool gbuffer = false;
  TessellationParams tessellation;
  // Port addition (Docs/Threads.md): 1 records on the caller's context; 0
  // picks the count per frame (AutoRecordingThreads, RecordingThreads.h); N > 1
  // splits the draws across N deferred contexts (the caller's thread and N - 1
  // persistent workers) and executes the lists on the caller's context, which
  // must then be the immediate one. The lists set the render targets and
  // viewport themselves: the bound views are read back (OMGetRenderTargets),
  // the viewport must be given here (without it, one thread).
  int recordingThreads = 1;
  std::optional<d3dl::VIEWPORT> viewport;
  // The caller's thread, done with its chunk, draws the next chunks itself
  // while their workers have not started (false: always the workers; tests).
  bool callerTakesLateChunks = true;
  // Measurement (drr_scene_record_bench --contention): chunks of equal draw
  // counts instead of by measured speed, and the caller drawing its chunk only
  // after the workers have finished theirs, so that every chunk is recorded
  // with no other recording beside it. The image does not change.
  bool evenChunks = false;
  bool callerDrawsAfterWorkers = false;
};

// The original's lighting constants (its RenderScene values): LIT entries'
// directional light, or UNLIT's ambient-only set; the scene's b1 buffers and
// the deferred lighting pass both read them.
struct SceneLightingValues {
  glm::vec4 diffuse, ambient, specular;
  glm::vec4 directionAndPower;  // xyz: the direction the light travels (not normalised); w: specular power
};
SceneLightingValues SceneLighting(bool lit);

struct SceneStats {
  uint32_t drawsIssued = 0, drawsCulled = 0, shaderVariantsUsed = 0, texturesLoaded = 0;
  uint64_t textureBytes = 0, vertexBytes = 0, indexBytes = 0;
  uint64_t textureBytesAsRgba8 = 0;  // the uploaded textures as RGBA8 (textureBytes is less where BC data stays compressed)
  uint64_t triangles = 0;  // of the whole scene (drawn or not)
  uint32_t tessellatedDraws = 0;  // draws through the hull/domain shaders (--tessellation)
  uint64_t patchesSubmitted = 0;  // their input triangles (the hull shader culls some)
  // The last Render: threads that recorded it (1: the caller's context) and
  // the draws each recorded, and its wall-clock CPU time from entry to the
  // last ExecuteCommandList (GPU execution not included).
  uint32_t recordingThreads = 1;
  std::vector<uint32_t> drawsPerThread;
  double recordMs = 0.0;
  // Per thread, wall clock, where the time goes: from its first draw to the
  // end of its chunk (workers: FinishCommandList included); and for workers
  // (0 for the caller's thread) from the wake-up call to the worker running,
  // and its FinishCommandList.
  std::vector<double> chunkMs, wakeMs, finishMs;
  // The rest of the last Render's serial path, wall clock: building the draw
  // list (frame move, culling), the caller's wait for the workers after its
  // own chunk, and the ExecuteCommandList calls (0 and 0 on one thread).
  double planMs = 0.0, waitMs = 0.0, executeMs = 0.0;
  // Chunks the caller's thread drew: 1, more when it took over the chunks of
  // workers that had not started yet (their drawsPerThread are then 0).
  uint32_t callerChunks = 1;
  std::string ToString() const;
  // "recording threads 2: draws 30 + 29, 0.210 ms CPU" (the last Render).
  std::string RecordingString() const;
};

struct SceneImpl;

class Scene {
 public:
  // path: a scene description file, or a single model file (framed by an automatic camera).
  static std::unique_ptr<Scene> Load(d3dl::Device* device, const std::string& path,
                                     const SceneLoadOptions& opts, std::string* error);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  void Update(double timeSeconds);  // animation (bell, cinematic camera path), loops
  // The scene's cameras: a description's CAMERA entries in file order (a single
  // model file: an automatic camera, then the file's own). The sample lists
  // them after "First Person" (Cameras.h).
  int CameraCount() const;
  const std::string& CameraName(int i) const;
  CameraPose Camera(int i) const;
  // The original's scene centre (mean of the meshes' box centres at time 0),
  // where its first-person camera starts.
  glm::vec3 OriginalCentre() const;
  // Caller has set RTVs, DSV and viewport; Render sets everything else it needs.
  void Render(d3dl::DeviceContext* ctx, const SceneRenderParams& p);
  SceneStats Stats() const;
  // F4: reloads (fromSource: recompiles) every variant; the old ones stay on error.
  bool ReloadShaders(const ShaderLibrary& shaders, bool fromSource, std::string* error);

  // Deferred shading (SceneDeferred.cpp). The description's LIGHT entries.
  const std::vector<SceneLight>& Lights() const;
  // Depth only, for a shadow map: the opaque draws of LIT entries (no sky, no
  // decals, no cameras) inside viewProj's frustum, into the caller's DSV and
  // viewport. Returns the number of draws.
  uint32_t RenderDepth(d3dl::DeviceContext* ctx, const glm::mat4& viewProj);

  // Additions: warnings gathered while loading (missing textures, repaired data).
  const std::vector<std::string>& Warnings() const;
  // World-space bounds of everything drawn (for framing and tests).
  glm::vec3 BoundsMin() const;
  glm::vec3 BoundsMax() const;

 private:
  Scene();
  std::unique_ptr<SceneImpl> impl_;
};

}  // namespace drr
