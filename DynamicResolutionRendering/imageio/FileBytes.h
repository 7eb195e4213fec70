// Files around the image backends: writing a whole file with every error
// checked (a full disk (/dev/full) or a failed close must not look like
// success, as it can through the image libraries' own file writers; both
// backends encode in memory and write through this), and finding a file
// beside the running program.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace drr {

// On failure, *error names the path and the system's reason.
bool WriteFileBytes(const std::string& path, const std::vector<uint8_t>& bytes, std::string* error);

// The path of the regular file `name` in the running executable's folder, or
// "" when there is none (how the import worker and the image module are found
// beside a moved or bundled program).
std::string FileBesideExecutable(const std::string& name);

}  // namespace drr
