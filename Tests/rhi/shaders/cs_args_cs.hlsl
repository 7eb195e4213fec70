// Writes DispatchIndirect arguments (5, 2, 1) at byte 16 of its UAV.
RWByteAddressBuffer g_Args : register(u0);

[numthreads(1, 1, 1)]
void main() {
  g_Args.Store3(16, uint3(5, 2, 1));
}
