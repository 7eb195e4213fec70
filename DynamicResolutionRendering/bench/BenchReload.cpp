// --report-from DIR: rebuilds the report (summary.md, plots, results.json)
// from a finished run's results.csv and results.json, without rendering, so a
// long sweep's report can be rewritten after the report code changed. The
// command line must name the same sweep as the run (views, filters, scales).
#include <fstream>
#include <map>

#include "bench/BenchColumns.h"
#include "bench/BenchCommon.h"

namespace drr {
bool ReloadBenchResults(const std::string& dir, BenchResults* res, std::string* error) {
  std::ifstream csv(dir + "/results.csv"), json(dir + "/results.json");
  if (!csv || !json) {
    *error = "cannot read " + dir + "/results.csv and results.json";
    return false;
  }
  const nlohmann::json header = nlohmann::json::parse(json, nullptr, false);
  if (header.is_discarded()) {
    *error = dir + "/results.json is not valid JSON";
    return false;
  }
  if (!ReadBenchJsonHeader(header, res, error)) return false;
  std::string line;
  size_t lineNumber = 1;
  std::getline(csv, line);
  const std::vector<std::string> names = SplitCsvLine(line);
  std::map<std::string, size_t> col;
  for (size_t i = 0; i < names.size(); ++i) col[names[i]] = i;
  while (std::getline(csv, line)) {
    ++lineNumber;
    if (line.empty()) continue;
    const std::vector<std::string> f = SplitCsvLine(line);
    if (f.size() != names.size()) {
      *error = dir + "/results.csv:" + std::to_string(lineNumber) + ": " + std::to_string(f.size()) +
               " fields, the header has " + std::to_string(names.size());
      return false;
    }
    res->rows.push_back(RowFromFields(f, col));
  }
  return ReadBenchJsonFrames(header, res, error);
}

}  // namespace drr
