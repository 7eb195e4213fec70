// Screen-space adaptive tessellation of the scene's triangle meshes
// (Docs/Tessellation.md): each patch edge gets a factor from its on-screen
// length in pixels of the dynamic viewport, divided by the target pixels per
// edge and clamped to the maximum factor; patches wholly off screen or facing
// away are culled in the hull shader (factor 0). The domain shader places the
// point by Phong tessellation (smooth objects) or by a displacement map along
// the normal (relief), in object space, so that this frame's and the previous
// frame's clip positions come from the same tessellated point.
// Variants (Shaders/CMakeLists.txt): NORMAL_MAP and WRITE_VELOCITY as the
// scene's SceneVS, so that the domain shader's outputs are exactly what the
// scene's pixel shader (SceneShaders.hlsl, ScenePS) reads.
// The scene's per-object constants (b0, read by HS and DS), vertex input and
// interpolants (ScenePS reads them): SceneCommon.hlsli.
#include "SceneCommon.hlsli"

// Per-draw tessellation constants (TessConstants in SceneTessellation.cpp).
cbuffer TessConstants : register(b1) {
  float4 g_FrustumPlanes[6];  // world space, normalised; inside where dot(plane, p) >= 0
  float4 g_TessEye;           // xyz: the camera (world); w: pixels per world unit at distance 1
  float4 g_TessDetail;        // x: target pixels per edge, y: max factor, z: 1 = cull back faces, w: back-face margin
  float4 g_Surface;           // x: 0 Phong, 1 displacement; y: relief (object units below the mesh at height 0); z: Phong shape factor; w: unused
};

Texture2D<float4> g_Displacement : register(t0);
SamplerState g_DisplacementSampler : register(s0);

// Object space: the vertex shader only hands the vertex on.
typedef VSIn ControlPoint;

struct PatchFactors {
  float edges[3] : SV_TessFactor;
  float inside : SV_InsideTessFactor;
};

ControlPoint TessVS(VSIn v) {
  ControlPoint c;
  c.position = v.position;
  c.normal = v.normal;
  c.texcoord = v.texcoord;
#if NORMAL_MAP
  c.tangent = v.tangent;
  c.binormal = v.binormal;
#endif
  return c;
}

// An edge's factor from its two end points only (world space), so that the
// two patches sharing it agree: the projected diameter of the edge's bounding
// sphere in pixels, over the target pixels per edge.
float EdgeFactor(float3 a, float3 b) {
  const float len = length(a - b);
  const float dist = max(length(0.5 * (a + b) - g_TessEye.xyz), 1e-3);
  const float pixels = len * g_TessEye.w / dist;
  // Rounded, for integer partitioning: the vertex work then falls with the
  // square of the scale down to factor 1 (fractional_odd would turn 1.2 into
  // three segments, as many as 2.4 gets).
  return clamp(round(pixels / g_TessDetail.x), 1.0, g_TessDetail.y);
}

// Off screen: all three corners, grown by the surface's bound, outside one plane.
bool OutsideFrustum(float3 p[3], float margin) {
  [unroll] for (int k = 0; k < 6; ++k) {
    const float4 pl = g_FrustumPlanes[k];
    if (dot(pl.xyz, p[0]) + pl.w < -margin && dot(pl.xyz, p[1]) + pl.w < -margin &&
        dot(pl.xyz, p[2]) + pl.w < -margin)
      return true;
  }
  return false;
}

// Facing away: the flat triangle (turned to agree with its normals) and every
// vertex normal point away from the eye by more than the margin. A patch near
// the silhouette has one of them within the margin and keeps its factors.
bool FacesAway(float3 p[3], float3 n[3]) {
  float3 face = cross(p[1] - p[0], p[2] - p[0]);
  const float3 sumN = n[0] + n[1] + n[2];
  if (dot(face, sumN) < 0) face = -face;
  const float faceLen = length(face);
  const float3 centre = (p[0] + p[1] + p[2]) / 3.0;
  const float margin = g_TessDetail.w;
  if (faceLen > 0 && dot(face / faceLen, normalize(g_TessEye.xyz - centre)) >= -margin) return false;
  [unroll] for (int i = 0; i < 3; ++i)
    if (dot(normalize(n[i]), normalize(g_TessEye.xyz - p[i])) >= -margin) return false;
  return true;
}

PatchFactors TessPatch(InputPatch<ControlPoint, 3> patch) {
  float3 p[3], n[3];
  [unroll] for (int i = 0; i < 3; ++i) {
    p[i] = mul(g_World, float4(patch[i].position, 1.0)).xyz;
    n[i] = mul((float3x3)g_World, patch[i].normal);
  }
  const float longest = max(length(p[1] - p[0]), max(length(p[2] - p[1]), length(p[0] - p[2])));
  const float3 scale = float3(length(g_World[0].xyz), length(g_World[1].xyz), length(g_World[2].xyz));
  const float bound = 0.25 * longest + abs(g_Surface.y) * max(scale.x, max(scale.y, scale.z));
  PatchFactors f;
  if (OutsideFrustum(p, bound) || (g_TessDetail.z > 0 && FacesAway(p, n))) {
    f.edges[0] = f.edges[1] = f.edges[2] = f.inside = 0;
    return f;
  }
  // Edge i is the one opposite control point i (D3D's and Vulkan's order).
  f.edges[0] = EdgeFactor(p[1], p[2]);
  f.edges[1] = EdgeFactor(p[2], p[0]);
  f.edges[2] = EdgeFactor(p[0], p[1]);
  f.inside = round((f.edges[0] + f.edges[1] + f.edges[2]) / 3.0);
  return f;
}

[domain("tri")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("TessPatch")]
ControlPoint TessHS(InputPatch<ControlPoint, 3> patch, uint i : SV_OutputControlPointID) {
  return patch[i];
}

// Phong tessellation: the linear point projected onto each corner's tangent
// plane, those blended by the barycentrics, mixed with the linear point.
float3 PhongPoint(float3 uvw, float3 q, const OutputPatch<ControlPoint, 3> patch) {
  float3 blended = 0;
  [unroll] for (int i = 0; i < 3; ++i) {
    const float3 n = normalize(patch[i].normal);
    blended += uvw[i] * (q - dot(q - patch[i].position, n) * n);
  }
  return lerp(q, blended, g_Surface.z);
}

[domain("tri")]
VSOut TessDS(PatchFactors factors, float3 uvw : SV_DomainLocation, const OutputPatch<ControlPoint, 3> patch) {
  const float3 q = uvw.x * patch[0].position + uvw.y * patch[1].position + uvw.z * patch[2].position;
  const float3 n = normalize(uvw.x * patch[0].normal + uvw.y * patch[1].normal + uvw.z * patch[2].normal);
  const float2 uv = uvw.x * patch[0].texcoord + uvw.y * patch[1].texcoord + uvw.z * patch[2].texcoord;
  float3 pos;
  if (g_Surface.x > 0.5) {
    // Level 0 everywhere: a point on a shared edge reads the same texel on both sides.
    const float h = g_Displacement.SampleLevel(g_DisplacementSampler, uv, 0).r;
    pos = q + n * ((h - 1.0) * g_Surface.y);  // white: the mesh surface; black: relief units below
  } else {
    pos = PhongPoint(uvw, q, patch);
  }
  VSIn v;
  v.position = pos;
  v.normal = n;
  v.texcoord = uv;
#if NORMAL_MAP
  v.tangent = uvw.x * patch[0].tangent + uvw.y * patch[1].tangent + uvw.z * patch[2].tangent;
  v.binormal = uvw.x * patch[0].binormal + uvw.y * patch[1].binormal + uvw.z * patch[2].binormal;
#endif
  return ToInterpolants(v);
}
