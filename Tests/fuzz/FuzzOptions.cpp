// Fuzz target: the sample's command line (arguments split at NUL or newline).
#include <cstdint>
#include <string>
#include <vector>

#include "Options.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> args(1);
  for (size_t i = 0; i < size && args.size() < 64; ++i) {
    const char c = char(data[i]);
    if (c == '\0' || c == '\n') args.emplace_back();
    else args.back() += c;
  }
  drr::Options o;
  std::string message;
  drr::ParseCommandLine(args, &o, &message);
  return 0;
}
