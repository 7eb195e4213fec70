#include "scene/IsolatedImport.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "imageio/FileBytes.h"
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

// CPU time (user + system) that process pid has used, in clock ticks
// (fields 14 and 15 of /proc/<pid>/stat); -1 when it cannot be read.
long long ProcessCpuTicks(pid_t pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  std::getline(f, line);
  const size_t nameEnd = line.rfind(')');  // the name may hold spaces
  if (nameEnd == std::string::npos) return -1;
  std::istringstream fields(line.substr(nameEnd + 1));
  std::string skipped;
  for (int i = 3; i < 14; ++i) fields >> skipped;
  long long user = 0, system = 0;
  return (fields >> user >> system) ? user + system : -1;
}

// The worker serves one request after another over a socket (a socket, not
// pipes, so that writing to a worker that died is an error, not SIGPIPE).
// It is started on the first request, kept for the next ones (starting it
// costs more than most decodes), and replaced after any request that did
// not succeed: a crash, a limit, or an error that may have left it damaged.
class Worker {
 public:
  ~Worker() { Stop(); }
  // Sends the request's fields and reads the reply; false with *error set
  // (naming path) when the worker died, passed a limit or could not start.
  // caps: the worker's limits; CPU and wall time of this request are those
  // for path's size (ImportLimitsForFile).
  bool Request(const std::string& path, const std::vector<std::string>& fields, const ImportLimits& caps,
               std::vector<uint8_t>* reply, std::string* error);

 private:
  enum class Stop_ { None, Timeout, CpuTime, TooLarge, Broken };
  bool Start(const ImportLimits& limits, std::string* error);
  Stop_ Exchange(const std::string& request, const ImportLimits& limits, std::vector<uint8_t>* reply);
  bool PastCpuLimit(long long startTicks, uint32_t cpuSeconds) const;
  int Stop(bool kill = false);  // the wait status
  pid_t pid_ = -1;
  int fd_ = -1;
  ImportLimits limits_;
};

bool Worker::Start(const ImportLimits& limits, std::string* error) {
  int sv[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
    *error = std::string("cannot create a socket for the import worker: ") + std::strerror(errno);
    return false;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, sv[1], 0);  // requests
  posix_spawn_file_actions_adddup2(&fa, sv[1], 1);  // replies
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  const std::vector<std::string> args = {ImportWorkerPath(), std::to_string(limits.memoryMiB),
                                         std::to_string(limits.cpuSeconds)};
  std::vector<char*> argv, envp;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const std::vector<std::string> env = WorkerEnvironment(limits);
  for (const auto& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  const int rc = posix_spawn(&pid_, args[0].c_str(), &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  close(sv[1]);
  if (rc != 0) {
    close(sv[0]);
    pid_ = -1;
    *error = "cannot start the import worker " + args[0] + ": " + std::strerror(rc);
    return false;
  }
  fd_ = sv[0];
  limits_ = limits;
  return true;
}

int Worker::Stop(bool kill) {
  if (pid_ < 0) return 0;
  if (kill) ::kill(pid_, SIGKILL);
  close(fd_);  // a live worker reads end-of-file and exits
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {}
  pid_ = -1;
  fd_ = -1;
  return status;
}

// Whether the worker has used more than cpuSeconds of CPU since startTicks.
// The worker's own RLIMIT_CPU (its caps) stays as the backstop.
bool Worker::PastCpuLimit(long long startTicks, uint32_t cpuSeconds) const {
  static const long ticksPerSecond = sysconf(_SC_CLK_TCK);
  const long long now = ProcessCpuTicks(pid_);
  return startTicks >= 0 && now >= 0 && now - startTicks > (long long)cpuSeconds * ticksPerSecond;
}

// Writes the request, then reads the reply (a 64-bit length, then the bytes)
// within the CPU-time, wall-time and size limits; the CPU time is looked at
// every tenth of a second while the worker has not answered.
Worker::Stop_ Worker::Exchange(const std::string& request, const ImportLimits& limits, std::vector<uint8_t>* reply) {
  const long long cpuStart = ProcessCpuTicks(pid_);
  if (send(fd_, request.data(), request.size(), MSG_NOSIGNAL) != ssize_t(request.size())) return Stop_::Broken;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(limits.wallSeconds);
  uint64_t length = 0;
  size_t headerRead = 0;
  uint8_t buf[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return Stop_::Timeout;
    pollfd p{fd_, POLLIN, 0};
    const int pr = poll(&p, 1, int(std::min<int64_t>(left.count(), 100)));
    if (pr < 0 && errno != EINTR) return Stop_::Broken;
    if (pr == 0 && PastCpuLimit(cpuStart, limits.cpuSeconds)) return Stop_::CpuTime;
    if (pr <= 0) continue;
    const size_t want = headerRead < 8 ? 8 - headerRead : std::min<uint64_t>(sizeof buf, length - reply->size());
    const ssize_t n = recv(fd_, buf, want, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return Stop_::Broken;
    if (headerRead < 8) {
      std::memcpy(reinterpret_cast<uint8_t*>(&length) + headerRead, buf, size_t(n));
      headerRead += size_t(n);
      if (headerRead == 8 && length > (limits.replyMiB << 20)) return Stop_::TooLarge;
    } else {
      reply->insert(reply->end(), buf, buf + n);
    }
    if (headerRead == 8 && reply->size() == length) return Stop_::None;
  }
}

std::string SignalText(int sig) {
  const char* d = strsignal(sig);
  return "signal " + std::to_string(sig) + (d ? std::string(": ") + d : std::string());
}

// Why the worker ended without a usable reply, as a sentence; limits are
// those of this file.
std::string Failure(bool timeout, bool cpuTime, bool tooLarge, int status, const ImportLimits& limits) {
  if (timeout) return "the import did not finish within " + std::to_string(limits.wallSeconds) + " s (killed)";
  if (cpuTime)
    return "the import used more than its " + std::to_string(limits.cpuSeconds) +
           " s of CPU time (the limit for a file of this size; killed)";
  if (tooLarge) return "the decoded data exceeds " + std::to_string(limits.replyMiB) + " MiB (killed)";
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

bool Worker::Request(const std::string& path, const std::vector<std::string>& fields, const ImportLimits& caps,
                     std::vector<uint8_t>* reply, std::string* error) {
  std::string request;
  for (const auto& f : fields) {
    if (f.find_first_of("\t\n") != std::string::npos) {
      *error = path + ": the path contains a tab or a line break, which the import worker cannot be given";
      return false;
    }
    request += (request.empty() ? "" : "\t") + f;
  }
  request += '\n';
  const bool sameLimits = caps.memoryMiB == limits_.memoryMiB && caps.cpuSeconds == limits_.cpuSeconds &&
                          caps.wallSeconds == limits_.wallSeconds && caps.replyMiB == limits_.replyMiB;
  if (pid_ >= 0 && !sameLimits) Stop();
  if (pid_ < 0 && !Start(caps, error)) {
    *error = path + ": " + *error;
    return false;
  }
  const ImportLimits limits = ImportLimitsForFile(caps, path);
  const Stop_ stop = Exchange(request, limits, reply);
  if (stop == Stop_::None) {
    // A worker's error reply (not status 0) may follow damage: start afresh next time.
    if (reply->size() < 9 || (*reply)[8] != 0) Stop();
    return true;
  }
  const int status = Stop(stop != Stop_::Broken);
  *error = path + ": " +
           Failure(stop == Stop_::Timeout, stop == Stop_::CpuTime, stop == Stop_::TooLarge, status, limits);
  reply->clear();
  return false;
}

// One worker for the process; imports are serialised through it.
bool RunWorker(const std::string& path, const std::vector<std::string>& fields, const ImportLimits& limits,
               std::vector<uint8_t>* reply, std::string* error) {
  static std::mutex mutex;
  static Worker worker;
  std::lock_guard<std::mutex> lock(mutex);
  return worker.Request(path, fields, limits, reply, error);
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

uint64_t ImportInputBytes(const std::string& path) {
  constexpr int kMostEntriesLookedAt = 4096;  // a huge folder costs no more than this
  std::error_code ec;
  const fs::path file(path);
  uint64_t total = fs::file_size(file, ec);
  if (ec) return 0;
  const std::string stem = file.stem().string();
  const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
  int looked = 0;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end && looked < kMostEntriesLookedAt;
       it.increment(ec), ++looked) {
    const std::string name = it->path().filename().string();
    if (name == file.filename().string() || name.rfind(stem, 0) != 0) continue;
    std::error_code sizeError;
    const uint64_t size = it->is_regular_file(sizeError) ? it->file_size(sizeError) : 0;
    if (!sizeError) total += size;
  }
  return total;
}

ImportLimits ImportLimitsForFile(const ImportLimits& caps, const std::string& path) {
  return caps.ForInput(ImportInputBytes(path));
}

std::string ImportWorkerPath() {
  if (const char* v = std::getenv("DRR_IMPORT_WORKER"); v && *v) return v;
  if (std::string sibling = FileBesideExecutable("drr_import_worker"); !sibling.empty()) return sibling;
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
