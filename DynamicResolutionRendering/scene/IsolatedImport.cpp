#include "scene/IsolatedImport.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "scene/ImportWire.h"

extern char** environ;

namespace drr {
namespace fs = std::filesystem;

namespace {

uint64_t EnvNumber(const char* name, uint64_t fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  char* end = nullptr;
  errno = 0;
  unsigned long long n = std::strtoull(v, &end, 10);
  return (errno || *end || n == 0 || v[0] == '-') ? fallback : n;
}

// The environment for the worker: the sample's, with sanitizer options that
// make a sanitizer build's worker behave like the limits say (ASan reserves
// terabytes of address space, so RLIMIT_AS cannot apply there; its RSS limit
// does instead) and not report Assimp's leaks on error paths.
std::vector<std::string> WorkerEnvironment(const ImportLimits& limits) {
  std::vector<std::string> env;
  std::string asan = "ASAN_OPTIONS=";
  for (char** e = environ; e && *e; ++e) {
    if (std::strncmp(*e, "ASAN_OPTIONS=", 13) == 0) asan = std::string(*e) + ":";
    else env.emplace_back(*e);
  }
  asan += "detect_leaks=0:allocator_may_return_null=1:hard_rss_limit_mb=" + std::to_string(limits.memoryMiB);
  env.push_back(asan);
  return env;
}

struct Child {
  pid_t pid = -1;
  int out = -1;  // read end of the worker's stdout
};

bool Spawn(const std::vector<std::string>& args, const ImportLimits& limits, Child* child, std::string* error) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    *error = std::string("cannot create a pipe for the import worker: ") + std::strerror(errno);
    return false;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, fds[1], 1);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  std::vector<char*> argv, envp;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const std::vector<std::string> env = WorkerEnvironment(limits);
  for (const auto& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  const int rc = posix_spawn(&child->pid, args[0].c_str(), &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  close(fds[1]);
  if (rc != 0) {
    close(fds[0]);
    *error = "cannot start the import worker " + args[0] + ": " + std::strerror(rc);
    return false;
  }
  child->out = fds[0];
  return true;
}

enum class Stop { None, Timeout, TooLarge };

// Reads the reply until the worker closes its end, the wall-time limit passes
// or the reply grows past its limit.
Stop ReadReply(int fd, const ImportLimits& limits, std::vector<uint8_t>* reply) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(limits.wallSeconds);
  const uint64_t cap = limits.replyMiB << 20;
  uint8_t buf[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return Stop::Timeout;
    pollfd p{fd, POLLIN, 0};
    int pr = poll(&p, 1, int(std::min<int64_t>(left.count(), 1000)));
    if (pr < 0 && errno != EINTR) return Stop::None;
    if (pr <= 0) continue;
    ssize_t n = read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return Stop::None;
    if (reply->size() + size_t(n) > cap) return Stop::TooLarge;
    reply->insert(reply->end(), buf, buf + n);
  }
}

std::string SignalText(int sig) {
  const char* d = strsignal(sig);
  return "signal " + std::to_string(sig) + (d ? std::string(": ") + d : std::string());
}

// Why the worker ended without a usable reply, as a sentence.
std::string Failure(Stop stop, int status, const ImportLimits& limits) {
  if (stop == Stop::Timeout) return "the import did not finish within " + std::to_string(limits.wallSeconds) + " s (killed)";
  if (stop == Stop::TooLarge) return "the decoded data exceeds " + std::to_string(limits.replyMiB) + " MiB (killed)";
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGXCPU || sig == SIGKILL)
      return "the import was stopped at its CPU-time or memory limit (" + std::to_string(limits.cpuSeconds) + " s, " +
             std::to_string(limits.memoryMiB) + " MiB; " + SignalText(sig) + ")";
    return "the importer crashed (" + SignalText(sig) + "); the file is probably malformed";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    return "the import worker failed (exit code " + std::to_string(WEXITSTATUS(status)) + ")";
  return "the import worker gave no reply";
}

// Runs the worker with args (after the worker's path and the limits); true
// with the reply when the worker exited normally and wrote one.
bool RunWorker(const std::string& path, std::vector<std::string> args, const ImportLimits& limits,
               std::vector<uint8_t>* reply, std::string* error) {
  const std::string worker = ImportWorkerPath();
  args.insert(args.begin(), {worker, std::to_string(limits.memoryMiB), std::to_string(limits.cpuSeconds)});
  Child child;
  if (!Spawn(args, limits, &child, error)) {
    *error = path + ": " + *error;
    return false;
  }
  const Stop stop = ReadReply(child.out, limits, reply);
  if (stop != Stop::None) kill(child.pid, SIGKILL);
  close(child.out);
  int status = 0;
  while (waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {}
  const bool exited = stop == Stop::None && WIFEXITED(status);
  // A worker that reports an error (exit 1) still sends a well-formed reply.
  if (exited && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 1) && !reply->empty()) return true;
  *error = path + ": " + Failure(stop, status, limits);
  return false;
}

}  // namespace

ImportLimits ImportLimits::FromEnvironment() {
  ImportLimits l;
  l.memoryMiB = EnvNumber("DRR_IMPORT_MEMORY_MB", l.memoryMiB);
  l.cpuSeconds = uint32_t(std::min<uint64_t>(EnvNumber("DRR_IMPORT_CPU_SECONDS", l.cpuSeconds), 86400));
  l.wallSeconds = uint32_t(std::min<uint64_t>(EnvNumber("DRR_IMPORT_TIMEOUT_SECONDS", l.wallSeconds), 86400));
  l.replyMiB = std::min<uint64_t>(EnvNumber("DRR_IMPORT_REPLY_MB", l.replyMiB), 1 << 20);
  l.memoryMiB = std::min<uint64_t>(l.memoryMiB, 1 << 24);
  return l;
}

std::string ImportWorkerPath() {
  if (const char* v = std::getenv("DRR_IMPORT_WORKER"); v && *v) return v;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path sibling = self.parent_path() / "drr_import_worker";
    if (fs::is_regular_file(sibling, ec)) return sibling.string();
  }
  return DRR_IMPORT_WORKER_BUILD_PATH;
}

bool ImportModelIsolated(const std::string& path, const ModelLoadOptions& opts, const ImportLimits& limits,
                         ModelData* out, std::string* error) {
  std::vector<uint8_t> reply;
  if (!RunWorker(path, {opts.animationsOnly ? "animation" : "model", path, std::to_string(opts.maxVertices),
                        std::to_string(opts.maxTriangles)},
                 limits, &reply, error))
    return false;
  if (!WireReadModel(reply, opts, out, error)) {
    if (error->rfind(path, 0) != 0) *error = path + ": " + *error;
    return false;
  }
  return true;
}

bool ImportTextureIsolated(const std::string& path, TextureKind kind, uint32_t maxDimension,
                           const ImportLimits& limits, TextureData* out, std::string* error) {
  std::vector<uint8_t> reply;
  if (!RunWorker(path, {"texture", path, std::to_string(int(kind)), std::to_string(maxDimension)}, limits, &reply,
                 error))
    return false;
  if (!WireReadTexture(reply, maxDimension, out, error)) {
    if (error->rfind(path, 0) != 0) *error = path + ": " + *error;
    return false;
  }
  return true;
}

TextureCache::FileLoader IsolatedTextureLoader(ImportLimits limits) {
  return [limits](const std::string& path, TextureKind kind, const TextureLoadOptions& opts, TextureData* out,
                  std::string* error) {
    if (!ImportTextureIsolated(path, kind, opts.maxDimension, limits, out, error)) return false;
    if (opts.generateMips) GenerateMipChain(out);
    return true;
  };
}

std::shared_ptr<const ModelData> ModelCache::Get(const std::string& path, const ModelLoadOptions& opts,
                                                 std::string* error) {
  std::error_code ec;
  fs::path canon = fs::weakly_canonical(path, ec);
  const std::string key = (ec ? path : canon.string()) + (opts.animationsOnly ? "|anim" : "|model");
  auto it = results_.find(key);
  if (it == results_.end()) {
    Result r;
    auto m = std::make_shared<ModelData>();
    ++imports_;
    if (ImportModelIsolated(path, opts, limits_, m.get(), &r.error)) r.model = std::move(m);
    it = results_.emplace(key, std::move(r)).first;
  }
  if (!it->second.model) *error = it->second.error;
  return it->second.model;
}

}  // namespace drr
