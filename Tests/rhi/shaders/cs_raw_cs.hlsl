// ByteAddressBuffer in (t1), RWByteAddressBuffer out (u2): word * 3 + 7.
ByteAddressBuffer g_RawIn : register(t1);
RWByteAddressBuffer g_RawOut : register(u2);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  g_RawOut.Store(id.x * 4, g_RawIn.Load(id.x * 4) * 3u + 7u);
}
