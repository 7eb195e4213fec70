// The byte format in which the import worker (tools/ImportWorker.cpp) hands a
// decoded model or texture to the sample. The reader trusts nothing: every
// count is checked against the bytes left before anything is allocated, and
// the decoded data is validated (indices in range, finite values, sizes
// consistent) before the sample sees it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/ModelLoader.h"
#include "scene/TextureLoader.h"

namespace drr {

// The first bytes of every reply; a reply without them is not the worker's.
inline constexpr uint32_t kImportWireMagic = 0x49525244;  // "DRRI"
inline constexpr uint32_t kImportWireVersion = 2;

// A reply: success with a payload, or failure with the worker's message.
void WireWriteError(const std::string& message, std::vector<uint8_t>* out);
void WireWriteModel(const ModelData& model, std::vector<uint8_t>* out);
void WireWriteTexture(const TextureData& texture, std::vector<uint8_t>* out);

// Return false with *error set when the reply is an error, malformed, or
// decodes to data that fails validation. maxVertices/maxDimension bound the sizes.
bool WireReadModel(const std::vector<uint8_t>& in, const ModelLoadOptions& opts, ModelData* model,
                   std::string* error);
bool WireReadTexture(const std::vector<uint8_t>& in, uint32_t maxDimension, TextureData* texture,
                     std::string* error);

// The checks WireReadModel applies, usable on any ModelData: every index
// below its mesh's vertex count, finite vertices and transforms, node parents
// before children, mesh/material/node references in range. "" when valid.
std::string ValidateModel(const ModelData& model, const ModelLoadOptions& opts);

}  // namespace drr
