// Point centres from a vertex buffer (pixel coordinates), passed through.
struct PointIn {
  float2 centre : POSITION;
};
struct PointOut {
  float2 centre : CENTRE;
};
PointOut main(PointIn p) {
  PointOut o;
  o.centre = p.centre;
  return o;
}
