// Read-modify-write of every word: w = w * 2 + 1. Repeated dispatches only
// give 2^n - 1 when each one sees the previous one's writes.
RWByteAddressBuffer g_Words : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  g_Words.Store(id.x * 4, g_Words.Load(id.x * 4) * 2u + 1u);
}
