// Temporary folders of the tests. ScratchDir makes a folder of its own under
// the system's temporary directory (mkdtemp: a name no other process has, so
// tests running in parallel and two CI jobs sharing /tmp never meet) and
// removes it with everything in it when it goes. ProcessScratchDir() is one
// such folder for the whole test process (ctest runs every test case in a
// process of its own), removed at the process's exit.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace drrtest {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& prefix) {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot make a temporary folder " + pattern);
    path_ = pattern;
  }
  ~ScratchDir() {
    // A child forked by the test (the import worker) that exits through
    // exit() runs this too: only the process that made the folder removes it.
    if (::getpid() != owner_) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
  pid_t owner_ = ::getpid();
};

inline const std::filesystem::path& ProcessScratchDir() {
  static const ScratchDir dir("drr_test_");
  return dir.path();
}

}  // namespace drrtest
