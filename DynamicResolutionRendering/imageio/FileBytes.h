// Writing a whole file with every error checked: a full disk (/dev/full) or a
// failed close must not look like success, as it can through the image
// libraries' own file writers. Both image backends encode in memory and write
// through this.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace drr {

// On failure, *error names the path and the system's reason.
bool WriteFileBytes(const std::string& path, const std::vector<uint8_t>& bytes, std::string* error);

}  // namespace drr
