// drr_import_worker: decodes untrusted model and texture files for the
// sample (scene/IsolatedImport.h). It limits itself first, so that a
// malformed file that makes Assimp or an image decoder allocate without bound
// or loop ends here, then serves requests read from stdin, one per line
// (fields separated by tabs):
//   model|animation <file> <max vertices> <max triangles>
//   texture <file> <kind 0..2> <max dimension>
// Each reply goes to stdout as a 64-bit length and the ImportWire.h bytes.
//   drr_import_worker <memory MiB> <cpu s per request>
// Exits 0 at the end of the input, 2 on bad usage, 3 when stdout is gone.
#include <cerrno>
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

void LimitSelf(unsigned long long memoryMiB) {
  if (!kAddressSanitizer) SetLimit(RLIMIT_AS, rlim_t(memoryMiB) << 20, rlim_t(memoryMiB) << 20);
  SetLimit(RLIMIT_CORE, 0, 0);
  SetLimit(RLIMIT_FSIZE, 0, 0);  // it writes no files
}

// The CPU-time limit counts the whole process: each request gets cpuSeconds
// more than what was used so far (SIGXCPU ends the worker past it).
void LimitCpuOfNextRequest(unsigned long long cpuSeconds) {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const rlim_t used = rlim_t(u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1);
  SetLimit(RLIMIT_CPU, used + cpuSeconds, RLIM_INFINITY);
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

bool Run(const std::vector<std::string>& f, std::vector<uint8_t>* reply, std::string* error) {
  if (f.size() != 4) {
    *error = "bad request";
    return false;
  }
  const std::string& mode = f[0];
  const std::string& path = f[1];
  if (mode == "model" || mode == "animation") {
    ModelLoadOptions o;
    o.animationsOnly = mode == "animation";
    o.maxVertices = std::strtoull(f[2].c_str(), nullptr, 10);
    o.maxTriangles = std::strtoull(f[3].c_str(), nullptr, 10);
    ModelData m;
    if (!LoadModel(path, o, &m, error)) return false;
    DecodeEmbedded(&m);
    WireWriteModel(m, reply);
    return true;
  }
  TextureLoadOptions o;
  o.generateMips = false;
  o.maxDimension = uint32_t(std::strtoul(f[3].c_str(), nullptr, 10));
  const int kind = std::atoi(f[2].c_str());
  TextureData t;
  if (mode != "texture" || kind < 0 || kind > 2 || !LoadTextureFile(path, TextureKind(kind), o, &t, error)) {
    if (error->empty()) *error = path + ": bad request";
    return false;
  }
  WireWriteTexture(t, reply);
  return true;
}

// One request line from fd 0, split at tabs; false at the end of the input.
bool ReadRequest(std::vector<std::string>* fields) {
  std::string line;
  char c;
  for (;;) {
    const ssize_t n = read(0, &c, 1);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    if (c == '\n') break;
    line += c;
  }
  fields->assign(1, std::string());
  for (char ch : line) {
    if (ch == '\t') fields->emplace_back();
    else fields->back() += ch;
  }
  return true;
}

std::vector<uint8_t> Serve(const std::vector<std::string>& fields, unsigned long long memoryMiB) {
  const std::string path = fields.size() > 1 ? fields[1] : std::string("?");
  std::vector<uint8_t> reply;
  std::string error;
  bool ok = false;
  try {
    ok = Run(fields, &reply, &error);
  } catch (const std::bad_alloc&) {
    error = path + ": out of memory while decoding (limit " + std::to_string(memoryMiB) + " MiB)";
  } catch (const std::exception& e) {
    error = path + ": decoding failed (" + e.what() + ")";
  }
  if (!ok) {
    reply.clear();
    WireWriteError(error.empty() ? path + ": decoding failed" : error, &reply);
  }
  return reply;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: see the header of tools/ImportWorker.cpp\n");
    return 2;
  }
  const unsigned long long memoryMiB = std::strtoull(argv[1], nullptr, 10);
  const unsigned long long cpuSeconds = std::strtoull(argv[2], nullptr, 10);
  LimitSelf(memoryMiB);
  const int out = TakeStdout();
  std::vector<std::string> fields;
  while (ReadRequest(&fields)) {
    LimitCpuOfNextRequest(cpuSeconds);
    const std::vector<uint8_t> reply = Serve(fields, memoryMiB);
    const uint64_t length = reply.size();
    std::vector<uint8_t> framed(reinterpret_cast<const uint8_t*>(&length), reinterpret_cast<const uint8_t*>(&length) + 8);
    framed.insert(framed.end(), reply.begin(), reply.end());
    if (!WriteAll(out, framed)) return 3;
  }
  return 0;
}
