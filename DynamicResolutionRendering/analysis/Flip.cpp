// FLIP, LDR, from the paper's description (see Flip.h).
#include "analysis/Flip.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace drr {
namespace {

constexpr double kPi = 3.14159265358979323846;
// D65 reference white, and linear sRGB <-> XYZ (IEC 61966-2-1).
constexpr double kWhite[3] = {0.950428545, 1.0, 1.088900371};
constexpr double kRgbToXyz[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                                    {0.2126729, 0.7151522, 0.0721750},
                                    {0.0193339, 0.1191920, 0.9503041}};
constexpr double kXyzToRgb[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                    {-0.9692660, 1.8760108, 0.0415560},
                                    {0.0556434, -0.2040259, 1.0572252}};
// Contrast sensitivity per channel (Yy, Cx, Cz): a1, b1, a2, b2 of
// a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 x^2 / b2), x in degrees.
constexpr double kCsf[3][4] = {{1.0, 0.0047, 0.0, 1e-5}, {1.0, 0.0053, 0.0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};
constexpr double kCsfWidestB = 0.04;
constexpr double kColorExponent = 0.7, kFeatureExponent = 0.5;
constexpr double kPc = 0.4, kPt = 0.95;  // colour-error mapping: knee and its value
constexpr double kFeatureWidthDeg = 0.082;

using Vec3 = std::array<double, 3>;

Vec3 Mul(const double m[3][3], const Vec3& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

Vec3 XyzToLab(const Vec3& xyz) {
  auto f = [](double t) {
    constexpr double d = 6.0 / 29.0;
    return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
  };
  const double fx = f(xyz[0] / kWhite[0]), fy = f(xyz[1] / kWhite[1]), fz = f(xyz[2] / kWhite[2]);
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

Vec3 LinearRgbToYyCxCz(const Vec3& rgb) {
  const Vec3 xyz = Mul(kRgbToXyz, rgb);
  const double x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
  return {116 * y - 16, 500 * (x - y), 200 * (y - z)};
}

Vec3 YyCxCzToLinearRgb(const Vec3& o) {
  const double y = (o[0] + 16) / 116, x = y + o[1] / 500, z = y - o[2] / 200;
  return Mul(kXyzToRgb, Vec3{x * kWhite[0], y * kWhite[1], z * kWhite[2]});
}

// One channel plane with clamp-to-edge convolutions along x and y.
struct Plane {
  int w = 0, h = 0;
  std::vector<double> v;
  double At(int x, int y) const { return v[size_t(std::clamp(y, 0, h - 1)) * w + std::clamp(x, 0, w - 1)]; }
};

Plane Convolve(const Plane& in, const std::vector<double>& k, bool alongX) {
  const int r = int(k.size() / 2);
  Plane out{in.w, in.h, std::vector<double>(in.v.size())};
  for (int y = 0; y < in.h; ++y)
    for (int x = 0; x < in.w; ++x) {
      double s = 0;
      for (int i = -r; i <= r; ++i) s += k[size_t(i + r)] * (alongX ? in.At(x + i, y) : in.At(x, y + i));
      out.v[size_t(y) * in.w + x] = s;
    }
  return out;
}

Plane Separable(const Plane& in, const std::vector<double>& kx, const std::vector<double>& ky) {
  return Convolve(Convolve(in, kx, true), ky, false);
}

// exp(-pi^2 d^2 / b) at pixel offsets -r..r, d = offset / ppd degrees.
std::vector<double> CsfGaussian(double b, double ppd, int r) {
  std::vector<double> g;
  for (int i = -r; i <= r; ++i) g.push_back(std::exp(-kPi * kPi * (i / ppd) * (i / ppd) / b));
  return g;
}

// The channel's CSF filter (normalised to sum 1): each Gaussian term is
// separable, so the sum of the two is two separable passes, weighted.
Plane CsfFilter(const Plane& in, const double c[4], double ppd, int r) {
  const std::vector<double> g1 = CsfGaussian(c[1], ppd, r), g2 = CsfGaussian(c[3], ppd, r);
  double s1 = 0, s2 = 0;
  for (double v : g1) s1 += v;
  for (double v : g2) s2 += v;
  const double w1 = c[0] * std::sqrt(kPi / c[1]), w2 = c[2] * std::sqrt(kPi / c[3]);
  const double norm = w1 * s1 * s1 + w2 * s2 * s2;
  Plane out = Separable(in, g1, g1);
  for (double& v : out.v) v *= w1 / norm;
  if (w2 > 0) {
    const Plane second = Separable(in, g2, g2);
    for (size_t i = 0; i < out.v.size(); ++i) out.v[i] += second.v[i] * w2 / norm;
  }
  return out;
}

// 1D kernels of the feature detectors: the Gaussian (sum 1), its first and
// second derivatives with positive weights summing to 1 and negative to -1.
struct FeatureKernels {
  std::vector<double> gauss, edge, point;
};

FeatureKernels MakeFeatureKernels(double ppd) {
  const double sigma = 0.5 * kFeatureWidthDeg * ppd;
  const int r = FlipFeatureRadius(ppd);
  FeatureKernels k;
  for (int i = -r; i <= r; ++i) {
    const double g = std::exp(-double(i * i) / (2 * sigma * sigma));
    k.gauss.push_back(g);
    k.edge.push_back(-i * g);
    k.point.push_back((double(i * i) / (sigma * sigma) - 1) * g);
  }
  auto normalise = [](std::vector<double>& v, bool split) {
    double pos = 0, neg = 0;
    for (double x : v) (x > 0 ? pos : neg) += x;
    for (double& x : v) x = split ? (x > 0 ? x / pos : x / -neg) : x / pos;
  };
  normalise(k.gauss, false);
  normalise(k.edge, true);
  normalise(k.point, true);
  return k;
}

// Edge and point magnitudes of a luminance plane in [0, 1].
void Features(const Plane& y, const FeatureKernels& k, Plane* edges, Plane* points) {
  const Plane ex = Separable(y, k.edge, k.gauss), ey = Separable(y, k.gauss, k.edge);
  const Plane px = Separable(y, k.point, k.gauss), py = Separable(y, k.gauss, k.point);
  *edges = ex;
  *points = px;
  for (size_t i = 0; i < y.v.size(); ++i) {
    edges->v[i] = std::hypot(ex.v[i], ey.v[i]);
    points->v[i] = std::hypot(px.v[i], py.v[i]);
  }
}

// The three YyCxCz planes of a display-encoded image.
std::array<Plane, 3> ToOpponent(const ImageF& img) {
  std::array<Plane, 3> p;
  for (Plane& q : p) q = {int(img.width), int(img.height), std::vector<double>(size_t(img.width) * img.height)};
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const Vec3 o = LinearRgbToYyCxCz({SrgbToLinear(img.At(x, y, 0)), SrgbToLinear(img.At(x, y, 1)),
                                        SrgbToLinear(img.At(x, y, 2))});
      for (int c = 0; c < 3; ++c) p[c].v[size_t(y) * img.width + x] = o[c];
    }
  return p;
}

// Filtered opponent planes -> Hunt-adjusted L*a*b* per pixel.
std::vector<Vec3> FilteredHuntLab(const std::array<Plane, 3>& opp, double ppd) {
  const int r = FlipCsfRadius(ppd);
  std::array<Plane, 3> f;
  for (int c = 0; c < 3; ++c) f[c] = CsfFilter(opp[c], kCsf[c], ppd, r);
  std::vector<Vec3> lab(opp[0].v.size());
  for (size_t i = 0; i < lab.size(); ++i) {
    Vec3 rgb = YyCxCzToLinearRgb({f[0].v[i], f[1].v[i], f[2].v[i]});
    for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);
    lab[i] = FlipHunt(XyzToLab(Mul(kRgbToXyz, rgb)));
  }
  return lab;
}

}  // namespace

double FlipPixelsPerDegree(double distanceM, double widthM, double widthPixels) {
  return distanceM * (widthPixels / widthM) * kPi / 180.0;
}

double FlipFullScreenPpd(double widthPixels) {
  return FlipPixelsPerDegree(kFlipDisplayDistanceM, kFlipDisplayWidthM, widthPixels);
}

int FlipCsfRadius(double ppd) { return int(std::ceil(3.0 * std::sqrt(kCsfWidestB / (2 * kPi * kPi)) * ppd)); }

int FlipFeatureRadius(double ppd) { return int(std::ceil(3.0 * 0.5 * kFeatureWidthDeg * ppd)); }

std::array<double, 3> FlipSrgbToLab(const std::array<double, 3>& srgb) {
  return XyzToLab(Mul(kRgbToXyz, Vec3{SrgbToLinear(float(srgb[0])), SrgbToLinear(float(srgb[1])),
                                      SrgbToLinear(float(srgb[2]))}));
}

std::array<double, 3> FlipHunt(const std::array<double, 3>& lab) {
  return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]};
}

double FlipHyAB(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

double FlipMaxColorDistance() {
  const Vec3 green = FlipHunt(XyzToLab(Mul(kRgbToXyz, Vec3{0, 1, 0})));
  const Vec3 blue = FlipHunt(XyzToLab(Mul(kRgbToXyz, Vec3{0, 0, 1})));
  return std::pow(FlipHyAB(green, blue), kColorExponent);
}

double FlipColorError(double hyab) {
  static const double cmax = FlipMaxColorDistance();
  const double e = std::pow(hyab, kColorExponent), knee = kPc * cmax;
  return e < knee ? e * kPt / knee : kPt + (e - knee) / (cmax - knee) * (1.0 - kPt);
}

FlipResult ComputeFlip(const ImageF& reference, const ImageF& test, double ppd, bool keepMap) {
  FlipResult result;
  if (reference.width != test.width || reference.height != test.height || reference.width == 0 ||
      reference.height == 0 || reference.channels < 3 || test.channels < 3 || !(ppd > 0))
    return result;
  const std::array<Plane, 3> oppRef = ToOpponent(reference), oppTest = ToOpponent(test);
  const std::vector<Vec3> labRef = FilteredHuntLab(oppRef, ppd), labTest = FilteredHuntLab(oppTest, ppd);
  // Features on the unfiltered luminance, normalised to [0, 1]: (Yy + 16) / 116 = Y / Yn.
  Plane yRef = oppRef[0], yTest = oppTest[0];
  for (double& v : yRef.v) v = (v + 16) / 116;
  for (double& v : yTest.v) v = (v + 16) / 116;
  const FeatureKernels k = MakeFeatureKernels(ppd);
  Plane eRef, pRef, eTest, pTest;
  Features(yRef, k, &eRef, &pRef);
  Features(yTest, k, &eTest, &pTest);
  if (keepMap) result.map = {reference.width, reference.height, 1, std::vector<float>(labRef.size())};
  double sum = 0;
  for (size_t i = 0; i < labRef.size(); ++i) {
    const double color = FlipColorError(FlipHyAB(labRef[i], labTest[i]));
    const double feature = std::pow(
        std::max(std::abs(eRef.v[i] - eTest.v[i]), std::abs(pRef.v[i] - pTest.v[i])) / std::sqrt(2.0),
        kFeatureExponent);
    const double e = std::pow(color, 1.0 - feature);
    if (!std::isfinite(e)) return FlipResult{};
    sum += e;
    if (keepMap) result.map.pixels[i] = float(e);
  }
  result.mean = sum / double(labRef.size());
  result.valid = true;
  return result;
}

}  // namespace drr
