// The SDKMESH_ANIM reader (SdkMesh.h). As the original's loader: the frame
// records lie at AnimationDataOffset (from the file's start), each frame's
// keys at 40 + its DataOffset; every frame has NumAnimationKeys keys.
#include <cmath>

#include "scene/SdkMesh.h"
#include "scene/SdkMeshBytes.h"

namespace drr::sdkmesh {

namespace {

bool KeyFinite(const AnimKey& k) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(k.translation[i]) || !std::isfinite(k.scaling[i])) return false;
  for (int i = 0; i < 4; ++i)
    if (!std::isfinite(k.orientation[i])) return false;
  return true;
}

bool ReadKeys(const ByteView& b, uint64_t at, uint32_t numKeys, AnimFrame* frame, Failure& fail) {
  if (!b.Fits(at, numKeys, kAnimKeySize))
    return fail("frame '" + frame->name + "': " + std::to_string(numKeys) + " keys at offset " + std::to_string(at) +
                " do not fit in the file (" + std::to_string(b.size) + " bytes)");
  frame->keys.resize(numKeys);
  for (uint32_t k = 0; k < numKeys; ++k) {
    const uint64_t p = at + uint64_t(k) * kAnimKeySize;
    AnimKey& key = frame->keys[k];
    key.translation = {b.F32(p), b.F32(p + 4), b.F32(p + 8)};
    key.orientation = {b.F32(p + 12), b.F32(p + 16), b.F32(p + 20), b.F32(p + 24)};
    key.scaling = {b.F32(p + 28), b.F32(p + 32), b.F32(p + 36)};
    if (!KeyFinite(key)) return fail("frame '" + frame->name + "', key " + std::to_string(k) + ": value not finite");
  }
  return true;
}

}  // namespace

bool ReadAnim(const std::vector<uint8_t>& bytes, const std::string& path, AnimFile* out, std::string* error) {
  *out = AnimFile{};
  out->path = path;
  const ByteView b{bytes.data(), bytes.size()};
  Failure fail{path, error};
  if (b.size < kAnimHeaderSize)
    return fail("file of " + std::to_string(b.size) + " bytes is shorter than the 40-byte SDKMESH_ANIM header");
  const uint32_t version = b.U32(0);
  if (version != kFileVersion)
    return fail("SDKMESH_ANIM version " + std::to_string(version) + ", expected " + std::to_string(kFileVersion));
  // IsBigEndian (byte 4) is ignored as the original's loader does: its files set it over little-endian data.
  out->frameTransformType = b.U32(8);
  const uint32_t numFrames = b.U32(12);
  out->numKeys = b.U32(16);
  out->fps = b.U32(20);
  const uint64_t dataSize = b.U64(24), dataOffset = b.U64(32);
  if (out->frameTransformType > 1)
    return fail("frame transform type " + std::to_string(out->frameTransformType) + " (expected 0 or 1)");
  if (out->numKeys == 0) return fail("no animation keys (NumAnimationKeys = 0)");
  if (dataSize > b.size - kAnimHeaderSize)
    return fail("AnimationDataSize " + std::to_string(dataSize) + " is beyond the file's " +
                std::to_string(b.size) + " bytes");
  if (!b.Fits(dataOffset, numFrames, kAnimFrameSize))
    return fail(std::to_string(numFrames) + " frame records at offset " + std::to_string(dataOffset) +
                " do not fit in the file (" + std::to_string(b.size) + " bytes)");
  // Each frame's keys are its own bytes: F frames of K keys need F * K * 40 bytes.
  if (!b.Fits(0, uint64_t(numFrames) * out->numKeys, kAnimKeySize))
    return fail(std::to_string(numFrames) + " frames of " + std::to_string(out->numKeys) +
                " keys need more bytes than the file's " + std::to_string(b.size));
  for (uint32_t i = 0; i < numFrames; ++i) {
    const uint64_t at = dataOffset + uint64_t(i) * kAnimFrameSize;
    AnimFrame frame;
    frame.name = b.Name(at, kNameSize);
    const uint64_t keysOffset = b.U64(at + 104);
    if (keysOffset > b.size - kAnimHeaderSize)
      return fail("frame '" + frame.name + "': key offset " + std::to_string(keysOffset) + " is beyond the file");
    if (!ReadKeys(b, kAnimHeaderSize + keysOffset, out->numKeys, &frame, fail)) return false;
    out->frames.push_back(std::move(frame));
  }
  return true;
}

}  // namespace drr::sdkmesh
