// drr_model_probe: loads a model (or a scene description) on the CPU exactly as
// the scene does (through the import worker, IsolatedImport.h, unless
// --in-process) and prints counts.
// Exit 0 on success, 1 on a clean failure (the message says why), 2 on bad usage.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

#include <assimp/Importer.hpp>

#include "scene/IsolatedImport.h"
#include "scene/ModelLoader.h"
#include "scene/SceneDescription.h"

using namespace drr;

namespace {

int Usage() {
  std::fprintf(stderr,
               "usage: drr_model_probe [--quiet] [--no-textures] [--in-process [--max-memory-mb N]]\n"
               "                       <model file | scene_description.txt>\n"
               "       Files are decoded by drr_import_worker under its limits (DRR_IMPORT_* variables).\n"
               "       --in-process decodes them here instead, with the address space limited to\n"
               "       min(8 GiB, 3/4 of RAM) by default (--max-memory-mb, 0 = no limit).\n"
               "       drr_model_probe --list-extensions   (the model file extensions Assimp imports)\n");
  return 2;
}

struct ProbeArgs {
  bool quiet = false, textures = true, inProcess = false;
  long long maxMemMb = -1;  // -1: the default limit, 0: none
  std::string path;
};

constexpr int kRun = -1;  // ParseArgs: go on and probe

void ListExtensions() {
  Assimp::Importer imp;
  std::string ext;
  imp.GetExtensionList(ext);  // "*.3ds;*.obj;..."
  for (char& c : ext) if (c == ';') c = '\n';
  std::printf("%s\n", ext.c_str());
}

// kRun, or the exit code when the arguments are bad or the run is over.
int ParseArgs(int argc, char** argv, ProbeArgs* args) {
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--quiet") args->quiet = true;
    else if (a == "--no-textures") args->textures = false;
    else if (a == "--in-process") args->inProcess = true;
    else if (a == "--max-memory-mb" && i + 1 < argc) args->maxMemMb = std::atoll(argv[++i]);
    else if (a == "--list-extensions") {
      ListExtensions();
      return 0;
    } else if (a == "-h" || a == "--help") return Usage();
    else if (args->path.empty()) args->path = a;
    else return Usage();
  }
  if (args->path.empty()) return Usage();
  return kRun;
}

// Files that claim absurd element counts then fail with 'out of memory'
// instead of thrashing.
void LimitAddressSpace(long long maxMemMb) {
  if (maxMemMb < 0) {
    long long ramMb = (long long)sysconf(_SC_PHYS_PAGES) * sysconf(_SC_PAGE_SIZE) / 1048576;
    maxMemMb = std::min(8192LL, ramMb > 0 ? ramMb * 3 / 4 : 8192LL);
  }
  if (maxMemMb > 0) {
    rlimit rl{};
    rl.rlim_cur = rl.rlim_max = rlim_t(maxMemMb) * 1048576;
    setrlimit(RLIMIT_AS, &rl);
  }
}

struct Item { std::string mesh, anim; EntryType type; };

// The entries of a scene description, or the one model file.
bool ReadItems(const std::string& path, std::vector<Item>* items) {
  if (!IsSceneDescriptionPath(path)) {
    items->push_back({path, {}, EntryType::Lit});
    return true;
  }
  SceneDescription desc;
  std::string err;
  if (!LoadSceneDescription(path, {}, &desc, &err)) {
    std::fprintf(stderr, "error: %s\n", err.c_str());
    return false;
  }
  for (const auto& e : desc.entries) items->push_back({e.meshFile, e.animFile, e.type});
  return true;
}

// The model with its animation file's animations attached, as the scene loads it.
bool Load(bool inProcess, const std::string& path, const ModelLoadOptions& o, ModelData* m, std::string* err) {
  return inProcess ? LoadModel(path, o, m, err) : ImportModelIsolated(path, o, ImportLimits::FromEnvironment(), m, err);
}

bool LoadItem(const Item& it, bool inProcess, ModelData* m) {
  std::string err;
  if (!Load(inProcess, it.mesh, {}, m, &err)) {
    std::fprintf(stderr, "error: %s\n", err.c_str());
    return false;
  }
  if (!it.anim.empty() && it.anim != it.mesh) {
    ModelData a;
    ModelLoadOptions ao;
    ao.animationsOnly = true;
    if (!Load(inProcess, it.anim, ao, &a, &err)) {
      std::fprintf(stderr, "error: %s\n", err.c_str());
      return false;
    }
    AttachAnimations(m, a);
  }
  return true;
}

void LoadTextures(const ModelData& m, TextureCache& cache, std::vector<std::string>* warnings) {
  for (const auto& mat : m.materials) {
    if (!mat.diffuseTex.empty()) cache.Get(m, mat.diffuseTex, TextureKind::Color, warnings);
    if (!mat.normalTex.empty()) cache.Get(m, mat.normalTex, TextureKind::Normal, warnings);
    if (!mat.specularTex.empty()) cache.Get(m, mat.specularTex, TextureKind::Specular, warnings);
  }
}

void PrintModel(const std::string& file, const ModelData& m) {
  glm::vec3 mn, mx;
  m.Bounds(&mn, &mx);
  std::printf("model %s: %zu meshes (%llu with 16-bit indices), %llu vertices, %llu triangles, %zu materials, "
              "%zu nodes, %zu animations (%.3f s), %zu cameras, bounds (%g %g %g)..(%g %g %g)\n",
              file.c_str(), m.meshes.size(),
              (unsigned long long)std::count_if(m.meshes.begin(), m.meshes.end(), [](auto& x) { return x.Use16BitIndices(); }),
              (unsigned long long)m.Vertices(), (unsigned long long)m.Triangles(), m.materials.size(), m.nodes.size(),
              m.animations.size(), m.AnimationDuration(), m.cameras.size(), mn.x, mn.y, mn.z, mx.x, mx.y, mx.z);
  for (const auto& mat : m.materials)
    std::printf("  material '%s': diffuse=%s normal=%s specular=%s%s\n", mat.name.c_str(),
                mat.diffuseTex.empty() ? "-" : mat.diffuseTex.c_str(), mat.normalTex.empty() ? "-" : mat.normalTex.c_str(),
                mat.specularTex.empty() ? "-" : mat.specularTex.c_str(), mat.alphaBlend ? " (alpha blend)" : "");
}

// Counts over all the models probed.
struct Totals {
  uint64_t meshes = 0, verts = 0, tris = 0, nodes = 0, anims = 0, cams = 0, mats = 0, idx16 = 0;
  void Add(const ModelData& m) {
    meshes += m.meshes.size();
    verts += m.Vertices();
    tris += m.Triangles();
    nodes += m.nodes.size();
    anims += m.animations.size();
    cams += m.cameras.size();
    mats += m.materials.size();
    for (const auto& mm : m.meshes) idx16 += mm.Use16BitIndices();
  }
};

}  // namespace

int main(int argc, char** argv) {
  ProbeArgs args;
  if (const int rc = ParseArgs(argc, argv, &args); rc != kRun) return rc;
  if (args.inProcess) LimitAddressSpace(args.maxMemMb);

  auto t0 = std::chrono::steady_clock::now();
  std::vector<Item> items;
  if (!ReadItems(args.path, &items)) return 1;
  TextureCache cache({}, args.inProcess ? TextureCache::FileLoader() : IsolatedTextureLoader());
  Totals total;
  std::vector<std::string> warnings;
  for (const auto& it : items) {
    ModelData m;
    if (!LoadItem(it, args.inProcess, &m)) return 1;
    for (auto& w : m.warnings) warnings.push_back(it.mesh + ": " + w);
    if (args.textures) LoadTextures(m, cache, &warnings);
    total.Add(m);
    if (!args.quiet) PrintModel(it.mesh, m);
  }
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!args.quiet)
    for (const auto& w : warnings) std::printf("warning: %s\n", w.c_str());
  std::printf("ok: %zu models, %llu meshes (%llu 16-bit), %llu vertices, %llu triangles, %llu materials, %llu nodes, "
              "%llu animations, %llu cameras, %zu textures (%.1f MiB with mips), %zu warnings, %.2f s\n",
              items.size(), (unsigned long long)total.meshes, (unsigned long long)total.idx16,
              (unsigned long long)total.verts, (unsigned long long)total.tris, (unsigned long long)total.mats,
              (unsigned long long)total.nodes, (unsigned long long)total.anims, (unsigned long long)total.cams,
              cache.LoadedCount(), cache.LoadedBytes() / 1048576.0, warnings.size(), secs);
  return 0;
}
