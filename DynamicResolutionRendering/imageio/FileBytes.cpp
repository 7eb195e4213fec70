#include "imageio/FileBytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace drr {

bool WriteFileBytes(const std::string& path, const std::vector<uint8_t>& bytes, std::string* error) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    if (error) *error = path + ": cannot open for writing (" + std::strerror(errno) + ")";
    return false;
  }
  errno = 0;
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  ok = std::fflush(f) == 0 && ok;
  const int writeErr = errno;
  ok = std::fclose(f) == 0 && ok;
  if (!ok && error) *error = path + ": write failed (" + std::strerror(errno ? errno : writeErr) + ")";
  return ok;
}

std::string FileBesideExecutable(const std::string& name) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const std::filesystem::path sibling = self.parent_path() / name;
  return std::filesystem::is_regular_file(sibling, ec) ? sibling.string() : std::string();
}

}  // namespace drr
