// Deferred shading, first pass (Docs/Deferred.md): the scene's vertex stage
// and material sampling (SceneShaders.hlsl), written into the G-buffer in the
// formats the 3DMark 11 article lists instead of being lit here:
//   SV_Target0  diffuse   R8G8B8A8_UNORM_SRGB  texture x tint; alpha: the forward shader's output alpha
//   SV_Target1  specular  R8G8B8A8_UNORM_SRGB  the specular map; alpha: the same (decal blend factor)
//   SV_Target2  normal    R10G10B10A2_UNORM    world normal * 0.5 + 0.5, (0,0,0) = unlit; alpha: the same
//   SV_Target3  velocity  R16G16_FLOAT         as the forward shader's SV_Target1 (WRITE_VELOCITY)
// Depth goes to the R32_TYPELESS depth target (read later through R32_FLOAT).
// Also the depth-only stage of the spot-light shadow maps (ShadowVS/ShadowPS).
#include "SceneShaders.hlsl"

struct GBufferOut {
  float4 diffuse : SV_Target0;
  float4 specular : SV_Target1;
  float4 normal : SV_Target2;
#if WRITE_VELOCITY
  float2 velocity : SV_Target3;
#endif
};

GBufferOut GBufferPS(VSOut i) {
  const float4 texColor = g_DiffuseMap.Sample(g_Sampler, i.texcoord);
  if (texColor.a == 0.0) discard;  // the forward shader's alpha test
  const float3 n = normalize(i.normal);
#if NORMAL_MAP
  const float3 tn = g_NormalMap.Sample(g_Sampler, i.texcoord).xyz * 2.0 - 1.0;
  const float3 bump = normalize(tn.z * n + tn.x * normalize(i.tangent) + tn.y * normalize(i.binormal));
#else
  const float3 bump = n;
#endif
#if SPECULAR_MAP
  const float3 specularMap = g_SpecularMap.Sample(g_Sampler, i.texcoord).rgb;
#else
  const float3 specularMap = float3(0.0, 0.0, 0.0);
#endif
  const float4 albedo = texColor * g_DiffuseTint;
  // The forward shader's output alpha: the original's decal blending uses it
  // as the blend factor (clamped to 1 by the UNORM target), and it is the
  // colour target's alpha; the lighting pass writes it back unchanged.
  const float3 toLight = -g_LightDirection.xyz;
  const float intensity = saturate(dot(bump, toLight));
  float alpha = (saturate(g_LightDiffuse.a * intensity) + g_LightAmbient.a) * albedo.a;
  if (intensity > 0.0) {
    const float3 reflected = normalize(2.0 * intensity * bump - toLight);
    const float phong = pow(saturate(dot(reflected, normalize(g_EyePosition.xyz - i.worldPos))), g_LightDirection.w);
    alpha += phong * g_LightSpecular.a;  // the specular map's alpha is 1 (the original's black.png too)
  }
  alpha = saturate(alpha);
  // An UNLIT entry is drawn with lighting constants that have no diffuse term
  // (the scene binds its unlit buffer at b1): the lighting pass then keeps
  // only the ambient 1, as the forward shader computes with those constants.
  const bool lit = any(g_LightDiffuse.rgb != 0.0);
  GBufferOut o;
  o.diffuse = float4(albedo.rgb, alpha);
  o.specular = float4(specularMap, alpha);
  o.normal = float4(lit ? bump * 0.5 + 0.5 : float3(0.0, 0.0, 0.0), alpha);
#if WRITE_VELOCITY
  o.velocity = ScreenVelocity(i.currClip, i.prevClip);
#endif
  return o;
}

// Spot-light shadow maps: depth only, g_WorldViewProj = the light's view-projection x world.
float4 ShadowVS(float3 position : POSITION) : SV_Position {
  return mul(g_WorldViewProj, float4(position, 1.0));
}

void ShadowPS() {}
