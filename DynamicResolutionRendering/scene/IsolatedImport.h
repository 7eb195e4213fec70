// Untrusted model and texture files are decoded in a separate process, the
// import worker (drr_import_worker, tools/ImportWorker.cpp), under limits on
// address space, CPU time, wall time and reply size. Assimp and the image
// decoders can crash, loop or allocate without bound on malformed input; in
// the worker that ends the worker only, and the sample gets an error naming
// the file. The reply is validated (ImportWire.h) before it is used.
//
// Why a separate executable (posix_spawn) rather than fork(): the sample has
// Vulkan driver threads running when it loads a scene, and a forked child of a
// multi-threaded process may only call async-signal-safe functions (a lock
// held by another thread at fork time stays held for ever in the child).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "scene/ImportLimits.h"
#include "scene/ModelLoader.h"
#include "scene/TextureLoader.h"

namespace drr {

// The worker's path: $DRR_IMPORT_WORKER, else drr_import_worker next to the
// running executable, else the one of the build tree.
std::string ImportWorkerPath();

bool ImportModelIsolated(const std::string& path, const ModelLoadOptions& opts, const ImportLimits& limits,
                         ModelData* out, std::string* error);
// The full-size level only; the caller builds the mip chain (GenerateMipChain).
bool ImportTextureIsolated(const std::string& path, TextureKind kind, uint32_t maxDimension,
                           const ImportLimits& limits, TextureData* out, std::string* error);

// A TextureCache loader that decodes files in the worker and builds the mip
// chain here (on validated, size-checked texels).
TextureCache::FileLoader IsolatedTextureLoader(ImportLimits limits = ImportLimits::FromEnvironment());

// One import per distinct file (and animationsOnly flag): a scene that lists a
// model many times imports it once. Failures are remembered too.
class ModelCache {
 public:
  explicit ModelCache(ImportLimits limits = ImportLimits::FromEnvironment()) : limits_(limits) {}
  std::shared_ptr<const ModelData> Get(const std::string& path, const ModelLoadOptions& opts, std::string* error);
  size_t Imports() const { return imports_; }

 private:
  struct Result { std::shared_ptr<const ModelData> model; std::string error; };
  ImportLimits limits_;
  std::map<std::string, Result> results_;
  size_t imports_ = 0;
};

}  // namespace drr
