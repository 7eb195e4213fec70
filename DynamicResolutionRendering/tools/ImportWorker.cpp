// drr_import_worker: decodes one untrusted model or texture file for the
// sample (scene/IsolatedImport.h) and writes the result to stdout in the
// ImportWire.h format. It limits itself first, so that a malformed file that
// makes Assimp or an image decoder allocate without bound or loop ends here.
//   drr_import_worker <memory MiB> <cpu s> model|animation <file> <max vertices> <max triangles>
//   drr_import_worker <memory MiB> <cpu s> texture <file> <kind 0..2> <max dimension>
// Exit 0 with a result, 1 with an error reply, 2 on bad usage.
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include "scene/ImportWire.h"
#include "scene/ModelLoader.h"
#include "scene/TextureLoader.h"

using namespace drr;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;  // its shadow memory needs terabytes of address space
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

void SetLimit(int resource, rlim_t soft, rlim_t hard) {
  rlimit rl{soft, hard};
  setrlimit(resource, &rl);
}

void LimitSelf(unsigned long long memoryMiB, unsigned long long cpuSeconds) {
  if (!kAddressSanitizer) SetLimit(RLIMIT_AS, rlim_t(memoryMiB) << 20, rlim_t(memoryMiB) << 20);
  SetLimit(RLIMIT_CPU, cpuSeconds, cpuSeconds + 2);  // SIGXCPU, then SIGKILL
  SetLimit(RLIMIT_CORE, 0, 0);
  SetLimit(RLIMIT_FSIZE, 0, 0);  // it writes no files
}

// The reply goes to the original stdout; anything a library prints goes nowhere.
int TakeStdout() {
  int out = dup(1);
  int null = open("/dev/null", O_WRONLY);
  if (null >= 0) dup2(null, 1), close(null);
  return out;
}

bool WriteAll(int fd, const std::vector<uint8_t>& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) return false;
    done += size_t(n);
  }
  return true;
}

// Compressed embedded textures become RGBA8 texels here, so that the sample
// never runs an image decoder on them.
void DecodeEmbedded(ModelData* model) {
  for (size_t i = 0; i < model->embedded.size(); ++i) {
    EmbeddedTexture& e = model->embedded[i];
    if (e.width || e.bytes.empty()) continue;
    TextureLoadOptions o;
    o.generateMips = false;
    TextureData t;
    const std::string name = model->file + " (embedded texture *" + std::to_string(i) + ")";
    if (LoadTextureMemory(e.bytes.data(), e.bytes.size(), e.hint, name, TextureKind::Color, o, &t, &e.error)) {
      e.bytes = std::move(t.mips[0].rgba);
      e.width = t.mips[0].width;
      e.height = t.mips[0].height;
    } else {
      e.bytes.clear();
    }
  }
}

bool Run(const std::string& mode, const std::string& path, char** rest, std::vector<uint8_t>* reply,
         std::string* error) {
  if (mode == "model" || mode == "animation") {
    ModelLoadOptions o;
    o.animationsOnly = mode == "animation";
    o.maxVertices = std::strtoull(rest[0], nullptr, 10);
    o.maxTriangles = std::strtoull(rest[1], nullptr, 10);
    ModelData m;
    if (!LoadModel(path, o, &m, error)) return false;
    DecodeEmbedded(&m);
    WireWriteModel(m, reply);
    return true;
  }
  TextureLoadOptions o;
  o.generateMips = false;
  o.maxDimension = uint32_t(std::strtoul(rest[1], nullptr, 10));
  const int kind = std::atoi(rest[0]);
  TextureData t;
  if (kind < 0 || kind > 2 || !LoadTextureFile(path, TextureKind(kind), o, &t, error)) return false;
  WireWriteTexture(t, reply);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: see the header of tools/ImportWorker.cpp\n");
    return 2;
  }
  const unsigned long long memoryMiB = std::strtoull(argv[1], nullptr, 10);
  LimitSelf(memoryMiB, std::strtoull(argv[2], nullptr, 10));
  const int out = TakeStdout();
  std::vector<uint8_t> reply;
  std::string error;
  bool ok = false;
  try {
    ok = Run(argv[3], argv[4], argv + 5, &reply, &error);
  } catch (const std::bad_alloc&) {
    error = std::string(argv[4]) + ": out of memory while decoding (limit " + std::to_string(memoryMiB) + " MiB)";
  } catch (const std::exception& e) {
    error = std::string(argv[4]) + ": decoding failed (" + e.what() + ")";
  }
  if (!ok) {
    reply.clear();
    WireWriteError(error.empty() ? std::string(argv[4]) + ": decoding failed" : error, &reply);
  }
  return WriteAll(out, reply) ? (ok ? 0 : 1) : 3;
}
