// BlitExtension::BlitRegion (Vulkan-backend extension: vkCmdBlitImage with the
// RHI's layout/barrier tracking). Pixels are read back; the fixture checks
// that synchronization validation stays silent.
#include "RhiTest.h"
#include "d3dl/BlitExtension.h"

namespace rhitest {
namespace {

class RhiBlit : public RhiTest {
 protected:
  BlitExtension* blit() {
    BlitExtension* b = GetBlitExtension(context());
    EXPECT_NE(b, nullptr);
    return b;
  }
};

uint32_t Rgba(uint8_t r, uint8_t g, uint8_t b, uint8_t a = 255) {
  return uint32_t(r) | uint32_t(g) << 8 | uint32_t(b) << 16 | uint32_t(a) << 24;
}

TEST_F(RhiBlit, NearestDuplicatesTexels) {
  // 4x2 source, blitted to 8x4 with a point filter: every texel becomes a 2x2 block.
  std::vector<uint32_t> texels(8);
  for (uint32_t i = 0; i < 8; ++i) texels[i] = Rgba(uint8_t(i * 30), uint8_t(255 - i * 30), uint8_t(i), 255);
  auto src = MakeTexture(4, 2, DXGI_FORMAT_R8G8B8A8_UNORM, texels.data());
  auto dst = MakeRenderTarget(8, 4);
  blit()->BlitRegion(dst.texture.Get(), RECT{0, 0, 8, 4}, src.Get(), RECT{0, 0, 4, 2},
                        FILTER_MIN_MAG_MIP_POINT);
  auto img = ReadBack(dst.texture.Get());
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 8; ++x) {
      const uint32_t t = texels[(y / 2) * 4 + x / 2];
      const auto p = img.RGBA8(x, y);
      ASSERT_EQ(p[0], t & 0xff) << x << "," << y;
      ASSERT_EQ(p[1], (t >> 8) & 0xff) << x << "," << y;
      ASSERT_EQ(p[2], (t >> 16) & 0xff) << x << "," << y;
    }
  EXPECT_EQ(CountMessages(LogLevel::Error), 0u);
}

TEST_F(RhiBlit, LinearInterpolatesWithClampToEdge) {
  // Black | white, 2x1 -> 4x1 with a linear filter. Destination pixel centres
  // map to source x = 0.25, 0.75, 1.25, 1.75 texels: weights of the white
  // texel 0 (clamped), 0.25, 0.75, 1 (clamped).
  std::vector<uint32_t> texels = {Rgba(0, 0, 0), Rgba(255, 255, 255)};
  auto src = MakeTexture(2, 1, DXGI_FORMAT_R8G8B8A8_UNORM, texels.data());
  auto dst = MakeRenderTarget(4, 1);
  blit()->BlitRegion(dst.texture.Get(), RECT{0, 0, 4, 1}, src.Get(), RECT{0, 0, 2, 1},
                        FILTER_MIN_MAG_MIP_LINEAR);
  auto img = ReadBack(dst.texture.Get());
  EXPECT_TRUE(Near(img.RGBA8(0, 0)[0], 0, 1));
  EXPECT_TRUE(Near(img.RGBA8(1, 0)[0], 64, 2)) << int(img.RGBA8(1, 0)[0]);
  EXPECT_TRUE(Near(img.RGBA8(2, 0)[0], 191, 2)) << int(img.RGBA8(2, 0)[0]);
  EXPECT_TRUE(Near(img.RGBA8(3, 0)[0], 255, 1));
  // The sample's point sampler (MIN_LINEAR_MAG_MIP_POINT) magnifies with points.
  blit()->BlitRegion(dst.texture.Get(), RECT{0, 0, 4, 1}, src.Get(), RECT{0, 0, 2, 1},
                        FILTER_MIN_LINEAR_MAG_MIP_POINT);
  img = ReadBack(dst.texture.Get());
  EXPECT_EQ(img.RGBA8(1, 0)[0], 0);
  EXPECT_EQ(img.RGBA8(2, 0)[0], 255);
}

TEST_F(RhiBlit, SubRegionOfRenderedTargetsLeavesTheRestAlone) {
  // Source: a render target cleared green, then a 2x2 sub-rectangle of it
  // (the "viewport") blitted to the middle of a destination cleared red that
  // is still bound as the render target (a rendering scope is open).
  auto src = MakeRenderTarget(8, 8);
  auto dst = MakeRenderTarget(16, 16);
  const float green[4] = {0, 1, 0, 1}, red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
  context()->ClearRenderTargetView(src.rtv.Get(), green);
  context()->ClearRenderTargetView(dst.rtv.Get(), red);
  Bind(dst, 16, 16);
  blit()->BlitRegion(dst.texture.Get(), RECT{4, 4, 12, 12}, src.texture.Get(), RECT{0, 0, 2, 2},
                        FILTER_MIN_MAG_MIP_LINEAR);
  // The destination is used as a render target again after the blit.
  const RECT corner{0, 0, 2, 2};
  context()->ClearView(dst.rtv.Get(), blue, &corner, 1);
  auto img = ReadBack(dst.texture.Get());
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      const bool in = x >= 4 && x < 12 && y >= 4 && y < 12;
      const bool corn = x < 2 && y < 2;
      const auto p = img.RGBA8(x, y);
      ASSERT_EQ(p[0], in || corn ? 0 : 255) << x << "," << y;
      ASSERT_EQ(p[1], in ? 255 : 0) << x << "," << y;
      ASSERT_EQ(p[2], corn ? 255 : 0) << x << "," << y;
    }
  // The source can be sampled after being a blit source.
  auto out = MakeRenderTarget(4, 4);
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  Bind(out, 4, 4);
  DrawSampled(src.srv.Get(), smp.Get());
  EXPECT_EQ(ReadBack(out.texture.Get()).RGBA8(1, 1)[1], 255);
}

TEST_F(RhiBlit, RejectsBadArguments) {
  auto a = MakeRenderTarget(4, 4);
  auto b = MakeRenderTarget(4, 4);
  blit()->BlitRegion(a.texture.Get(), RECT{0, 0, 4, 4}, a.texture.Get(), RECT{0, 0, 2, 2},
                        FILTER_MIN_MAG_MIP_LINEAR);
  blit()->BlitRegion(a.texture.Get(), RECT{0, 0, 5, 4}, b.texture.Get(), RECT{0, 0, 2, 2},
                        FILTER_MIN_MAG_MIP_LINEAR);
  blit()->BlitRegion(a.texture.Get(), RECT{0, 0, 4, 4}, b.texture.Get(), RECT{1, 1, 1, 2},
                        FILTER_MIN_MAG_MIP_LINEAR);
  blit()->BlitRegion(nullptr, RECT{0, 0, 4, 4}, b.texture.Get(), RECT{0, 0, 2, 2},
                        FILTER_MIN_MAG_MIP_LINEAR);
  EXPECT_EQ(CountMessages(LogLevel::Error, "BlitRegion"), 4u);
}

}  // namespace
}  // namespace rhitest
