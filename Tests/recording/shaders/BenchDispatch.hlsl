// One 64-thread group per dispatch, read-modify-writing one UAV with
// constants that change every dispatch: the workload of the dispatch
// benchmark. Consecutive dispatches depend on each other (as D3D11 orders them).
cbuffer DispatchConstants : register(b0) {
  uint g_Index;
  uint g_Value;
};
RWByteAddressBuffer g_Words : register(u0);

[numthreads(64, 1, 1)]
void CSMain(uint3 id : SV_DispatchThreadID) {
  const uint a = id.x * 4;
  g_Words.Store(a, g_Words.Load(a) * 3u + g_Value + id.x);
}
