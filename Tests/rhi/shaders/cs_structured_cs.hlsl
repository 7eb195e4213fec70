// StructuredBuffer in, RWStructuredBuffer out: value * scale + 1, bits ^ hash.
struct Element {
  float value;
  uint bits;
};
StructuredBuffer<Element> g_In : register(t0);
RWStructuredBuffer<Element> g_Out : register(u0);
cbuffer Params : register(b0) {
  uint g_Count;
  float g_Scale;
};

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  if (id.x >= g_Count) return;
  Element e = g_In[id.x];
  e.value = e.value * g_Scale + 1.0;
  e.bits = e.bits ^ (id.x * 2654435761u);
  g_Out[id.x] = e;
}
