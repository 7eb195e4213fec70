// Standalone driver for the fuzz targets (LLVMFuzzerTestOneInput), used when
// the build is not clang's libFuzzer (DRR_FUZZ_ENGINE=standalone, the
// default): replays every file of the corpus folders given, then runs
// bounded random mutations of them (bit flips, byte sets, truncations,
// insertions, splices) from a fixed seed, so a CI run is reproducible.
//   <target> [-runs=N] [-max_total_time=S] [-seed=N] corpus_dir...
// A crash is the process dying (the sanitizers abort); the input that was
// running is written to ./crash-<target>-<n> first, so it can become a corpus entry.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {
namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;

std::string g_current = "crash-input";

void Run(const Bytes& input) {
  {  // keep the input on disk while it runs: a crash leaves it behind
    std::ofstream f(g_current, std::ios::binary);
    f.write(reinterpret_cast<const char*>(input.data()), std::streamsize(input.size()));
  }
  LLVMFuzzerTestOneInput(input.data(), input.size());
}

Bytes Mutate(const std::vector<Bytes>& corpus, std::mt19937_64& rng) {
  Bytes b = corpus[rng() % corpus.size()];
  const int edits = 1 + int(rng() % 8);
  for (int e = 0; e < edits; ++e) {
    const size_t at = b.empty() ? 0 : rng() % b.size();
    switch (rng() % 6) {
      case 0: if (!b.empty()) b[at] ^= uint8_t(1u << (rng() % 8)); break;
      case 1: if (!b.empty()) b[at] = uint8_t(rng()); break;
      case 2: b.resize(at); break;
      case 3: b.insert(b.begin() + long(at), uint8_t(rng())); break;
      case 4: {  // an interesting value: 0, 0xff, 0x7f, 0x80 runs
        static const uint8_t v[] = {0, 0xff, 0x7f, 0x80};
        for (size_t k = at; k < std::min(b.size(), at + 4); ++k) b[k] = v[rng() % 4];
        break;
      }
      default: {  // splice in a piece of another input
        const Bytes& o = corpus[rng() % corpus.size()];
        if (o.empty()) break;
        const size_t from = rng() % o.size(), n = std::min<size_t>(o.size() - from, 1 + rng() % 64);
        b.insert(b.begin() + long(at), o.begin() + long(from), o.begin() + long(from + n));
      }
    }
  }
  if (b.size() > (1u << 20)) b.resize(1u << 20);
  return b;
}

long Arg(const char* a, const char* name, long fallback) {
  const size_t n = std::strlen(name);
  return std::strncmp(a, name, n) == 0 ? std::atol(a + n) : fallback;
}
}  // namespace

int main(int argc, char** argv) {
  long runs = 1000, seconds = 30, seed = 1;
  std::vector<Bytes> corpus;
  for (int i = 1; i < argc; ++i) {
    if (argv[i][0] == '-') {
      runs = Arg(argv[i], "-runs=", runs);
      seconds = Arg(argv[i], "-max_total_time=", seconds);
      seed = Arg(argv[i], "-seed=", seed);
      continue;
    }
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(argv[i], ec)) {
      std::ifstream f(e.path(), std::ios::binary);
      corpus.emplace_back(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
  }
  if (corpus.empty()) corpus.emplace_back();
  g_current = "crash-" + fs::path(argv[0]).filename().string();
  for (const Bytes& b : corpus) Run(b);
  std::mt19937_64 rng{uint64_t(seed)};
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  long done = 0;
  while (done < runs && std::chrono::steady_clock::now() < end) {
    Run(Mutate(corpus, rng));
    ++done;
  }
  std::remove(g_current.c_str());
  std::printf("%s: %zu corpus inputs and %ld mutations, no crash\n", argv[0], corpus.size(), done);
  return 0;
}
