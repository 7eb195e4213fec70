// SDKMESH and SDKMESH_ANIM files (SdkMesh.h) as the scene's ModelData, so the
// original's media load through the same import worker, validation, upload
// and drawing as every other model format (ModelLoader.h dispatches here).
//
// Conversion, as the original sample draws its media:
// - every triangle subset of a mesh is one MeshData (its material, indices
//   relative to the subset's VertexStart as the original's DrawIndexed base
//   vertex), drawn at every frame that names the mesh; only the mesh's first
//   vertex buffer is read, as the original's renderer binds only that one,
//   and its vertices as the original's one input layout reads them (tangent
//   and binormal at bytes 32 and 44) unless ModelLoadOptions asks for the
//   file's declaration;
// - frames are nodes, reached from frame 0 through child and sibling links as
//   the original's recursive transform does; the frame matrix is the node's;
// - materials keep their three texture names, resolved next to the mesh
//   file; their colours are ignored (the original lights by entry type);
// - SDKMESH_ANIM keys become one channel per animated frame, evaluated as the
//   original's interpolating transform (SDKMeshExt.cpp): key floor(fps * t)
//   modulo the key count, blended linearly (translation, scaling) and by
//   slerp (orientation) towards the next key, the last key blending into the
//   first; the loop lasts keys / fps seconds.
// - Direct3D's left-handed coordinates become the port's right-handed ones by
//   mirroring z (positions, normals, tangents, binormals, matrices and keys),
//   which leaves the image as it was; each triangle's corners are reordered so
//   that Direct3D's clockwise front faces are the port's counter-clockwise
//   ones, and a camera frame looks down its -z axis as the original's looks
//   down +z.
#pragma once

#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/ModelLoader.h"
#include "scene/SdkMesh.h"

namespace drr {

bool IsSdkMeshPath(const std::string& path);      // .sdkmesh (any case)
bool IsSdkMeshAnimPath(const std::string& path);  // .sdkmesh_anim (any case)

// Reads and converts a .sdkmesh or .sdkmesh_anim file (by extension).
bool LoadSdkMeshModel(const std::string& path, const ModelLoadOptions& opts, ModelData* out, std::string* error);

bool SdkMeshToModel(const sdkmesh::File& file, const ModelLoadOptions& opts, ModelData* out, std::string* error);
bool SdkMeshAnimToModel(const sdkmesh::AnimFile& file, ModelData* out, std::string* error);

// The left-handed to right-handed conversion: z mirrored.
glm::mat4 FrameMatrixToRightHanded(const float rowMajor[16]);
glm::vec3 VectorToRightHanded(const glm::vec3& v);
// A stored orientation (x, y, z, w): all zero is the identity, others normalised, then mirrored.
glm::quat OrientationToRightHanded(const glm::vec4& xyzw);

}  // namespace drr
