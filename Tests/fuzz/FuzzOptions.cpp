// Fuzz target: the sample's command line (arguments split at NUL or newline),
// and the report's options JSON of what it accepted (any bytes in a path,
// invalid UTF-8 included, must be written without throwing).
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
  if (drr::ParseCommandLine(args, &o, &message) == drr::ParseStatus::Ok) (void)drr::OptionsToJson(o);
  return 0;
}
