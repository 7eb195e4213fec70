// Counts its invocations in word 0 (4 threads per group).
RWByteAddressBuffer g_Counter : register(u0);

[numthreads(4, 1, 1)]
void main() {
  uint before;
  g_Counter.InterlockedAdd(0, 1u, before);
}
