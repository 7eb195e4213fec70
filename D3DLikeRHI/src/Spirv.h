// SPIR-V opcodes, decorations and storage classes read by the reflection
// (Reflection.cpp) and the decoration stripper (Shaders.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace d3dl::impl {
namespace spirv {
enum : uint32_t {
  OpName = 5, OpExtension = 10, OpEntryPoint = 15, OpExecutionMode = 16, OpTypeInt = 21, OpTypeFloat = 22, OpTypeVector = 23,
  OpTypeMatrix = 24, OpTypeImage = 25, OpTypeSampler = 26, OpTypeSampledImage = 27,
  OpTypeArray = 28, OpTypeRuntimeArray = 29, OpTypeStruct = 30, OpTypePointer = 32,
  OpConstant = 43, OpVariable = 59, OpDecorate = 71, OpMemberDecorate = 72, OpDecorateId = 332,
  OpDecorateString = 5632, OpMemberDecorateString = 5633,
};
enum : uint32_t {
  DecBlock = 2, DecBufferBlock = 3, DecArrayStride = 6, DecMatrixStride = 7, DecBuiltIn = 11,
  DecLocation = 30, DecBinding = 33, DecDescriptorSet = 34, DecOffset = 35,
  DecHlslCounterBuffer = 5634, DecUserSemantic = 5635, DecUserType = 5636,
};
// Execution models and the execution modes of the tessellation and geometry
// stages that the reflection reads.
enum : uint32_t {
  ModelVertex = 0, ModelTessellationControl = 1, ModelTessellationEvaluation = 2, ModelGeometry = 3,
  ModelFragment = 4, ModelGLCompute = 5,
};
enum : uint32_t {
  ModePointMode = 10, ModeInputPoints = 19, ModeInputLines = 20, ModeInputLinesAdjacency = 21,
  ModeTriangles = 22, ModeInputTrianglesAdjacency = 23, ModeQuads = 24, ModeIsolines = 25,
};
enum : uint32_t {
  StorageUniformConstant = 0, StorageInput = 1, StorageUniform = 2, StorageOutput = 3,
  StorageStorageBuffer = 12,
};

// The type declarations the reflection records.
constexpr bool IsTypeOp(uint32_t op) {
  switch (op) {
    case OpTypeInt: case OpTypeFloat: case OpTypeVector: case OpTypeMatrix: case OpTypeImage:
    case OpTypeSampler: case OpTypeSampledImage: case OpTypeArray: case OpTypeRuntimeArray:
    case OpTypeStruct: case OpTypePointer: return true;
    default: return false;
  }
}
}  // namespace spirv

// A literal string of `count` words (nul-terminated within them).
std::string ReadSpirvString(const uint32_t* words, size_t count);

}  // namespace d3dl::impl
