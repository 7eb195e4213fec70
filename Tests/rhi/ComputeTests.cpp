// Compute and unordered access: dispatches, UAVs of textures and of
// structured/raw buffers, their clears, DispatchIndirect and pixel-shader
// UAVs, read back and compared with CPU computations. Every test runs under
// core + synchronization validation (RhiTest): the barriers between dependent
// dispatches and draws come from the RHI alone, never from the test.
#include <algorithm>
#include <cstring>

#include "ComputeTest.h"

namespace rhitest {
namespace {

// Deterministic pseudo-random bytes (a 32-bit LCG).
std::vector<uint8_t> NoiseBytes(size_t n, uint32_t seed) {
  std::vector<uint8_t> out(n);
  for (auto& b : out) {
    seed = seed * 1664525u + 1013904223u;
    b = static_cast<uint8_t>(seed >> 24);
  }
  return out;
}

// The blur of cs_blur.hlsli on the CPU, exact in integers: sum(w * c) / 16
// then / 255, stored as UNORM8 (round to nearest).
std::vector<uint8_t> CpuBlur(const std::vector<uint8_t>& src, int w, int h) {
  std::vector<uint8_t> out(src.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int qx = std::clamp(x + dx, 0, w - 1), qy = std::clamp(y + dy, 0, h - 1);
            sum += (2 - std::abs(dx)) * (2 - std::abs(dy)) * src[(size_t(qy) * w + qx) * 4 + c];
          }
        out[(size_t(y) * w + x) * 4 + c] = static_cast<uint8_t>((sum + 8) / 16);
      }
  return out;
}

class RhiCompute : public ComputeTest {};

// ---------------------------------------------------------------------------
TEST_F(RhiCompute, ComputeBlurEqualsPixelShaderBlurAndTheCpu) {
  const int W = 37, H = 29;  // not multiples of the 8x8 groups: the edge groups are partial
  const auto src = NoiseBytes(size_t(W) * H * 4, 7);
  auto input = MakeTexture(W, H, DXGI_FORMAT_R8G8B8A8_UNORM, src.data());
  auto inputSrv = MakeSRV(input.Get());
  const int size[4] = {W, H, 0, 0};
  auto cb = MakeCB(16, USAGE_DEFAULT, size);

  // Compute path: t0 + b0 in, u0 out.
  auto csOut = MakeUavTexture(W, H, DXGI_FORMAT_R8G8B8A8_UNORM);
  auto csUav = MakeUAV(csOut.Get());
  auto cs = LoadCS("rhi_cs_blur_cs.spv");
  context()->CSSetShader(cs.Get());
  context()->CSSetShaderResources(0, 1, inputSrv.GetAddressOf());
  context()->CSSetConstantBuffers(0, 1, cb.GetAddressOf());
  BindUav(csUav.Get());
  context()->Dispatch((W + 7) / 8, (H + 7) / 8, 1);

  // Pixel-shader path: the same function over a full-screen triangle.
  auto rt = MakeRenderTarget(W, H);
  Bind(rt, W, H);
  auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
  auto ps = LoadPixelShader("rhi_cs_blur_ps.spv");
  context()->IASetInputLayout(nullptr);
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  context()->VSSetShader(vs.Get());
  context()->PSSetShader(ps.Get());
  context()->PSSetShaderResources(0, 1, inputSrv.GetAddressOf());
  context()->PSSetConstantBuffers(0, 1, cb.GetAddressOf());
  context()->Draw(3, 0);

  const drrtest::Image fromCs = ReadBack(csOut.Get()), fromPs = ReadBack(rt.texture.Get());
  const auto cpu = CpuBlur(src, W, H);
  ASSERT_EQ(fromCs.pixels.size(), cpu.size());
  ASSERT_EQ(fromPs.pixels.size(), cpu.size());
  // Same float expression in both stages: bit-exact. Against the integer CPU
  // sum: 1 LSB, for the .5 ties of sum/16 that float rounding may send either way.
  EXPECT_EQ(fromCs.pixels, fromPs.pixels);
  int worst = 0;
  for (size_t i = 0; i < cpu.size(); ++i) worst = std::max(worst, std::abs(int(fromCs.pixels[i]) - int(cpu[i])));
  EXPECT_LE(worst, 1);
}

// A dispatch writes a texture through a UAV, a draw samples it through an
// SRV, a second dispatch overwrites it (after the draw's read) and a second
// draw samples the new contents: no barrier from the test.
TEST_F(RhiCompute, UavWriteThenSrvReadByADrawNeedsNoManualBarrier) {
  const UINT W = 24, H = 16;
  auto tex = MakeUavTexture(W, H, DXGI_FORMAT_R8G8B8A8_UNORM);
  auto uav = MakeUAV(tex.Get());
  auto srv = MakeSRV(tex.Get());
  auto cs = LoadCS("rhi_cs_pattern_cs.spv");
  auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
  const UINT salts[2] = {0x00, 0x5a};
  drrtest::RenderTarget rts[2] = {MakeRenderTarget(W, H), MakeRenderTarget(W, H)};
  for (int round = 0; round < 2; ++round) {
    const UINT salt[4] = {salts[round], 0, 0, 0};
    auto cb = MakeCB(16, USAGE_DEFAULT, salt);
    context()->CSSetShader(cs.Get());
    context()->CSSetConstantBuffers(1, 1, cb.GetAddressOf());
    BindUav(uav.Get());
    context()->Dispatch(W / 8, H / 8, 1);
    BindUav(nullptr);  // D3D11: a resource bound as a UAV cannot be an SRV
    Bind(rts[round], W, H);
    DrawSampled(srv.Get(), smp.Get());
  }
  for (int round = 0; round < 2; ++round) {
    const drrtest::Image img = ReadBack(rts[round].texture.Get());
    int bad = 0;
    for (UINT y = 0; y < H; ++y)
      for (UINT x = 0; x < W; ++x) {
        const auto p = img.RGBA8(x, y);
        const uint8_t want[4] = {uint8_t(x), uint8_t(y), uint8_t((x ^ y ^ salts[round]) & 255), 255};
        bad += std::memcmp(p.data(), want, 4) != 0;
      }
    EXPECT_EQ(bad, 0) << "round " << round;
  }
}

TEST_F(RhiCompute, BindingAUavUnbindsItsSrvs) {
  auto tex = MakeUavTexture(8, 8, DXGI_FORMAT_R8G8B8A8_UNORM);
  auto uav = MakeUAV(tex.Get());
  auto srv = MakeSRV(tex.Get());
  context()->PSSetShaderResources(0, 1, srv.GetAddressOf());
  BindUav(uav.Get());  // unbinds the PS SRV, as D3D11 does
  ShaderResourceView* raw = srv.Get();
  context()->CSSetShaderResources(0, 1, &raw);  // bound as null, with a warning
  EXPECT_EQ(CountMessages(LogLevel::Warning, "bound as a render target or UAV"), 1u);
  BindUav(nullptr);
}

// ---------------------------------------------------------------------------
struct Element {
  float value;
  uint32_t bits;
};

TEST_F(RhiCompute, StructuredBufferRoundTrip) {
  const UINT n = 100;  // two groups of 64, the second partial
  std::vector<Element> in(n);
  for (UINT i = 0; i < n; ++i) in[i] = {float(i) * 0.5f - 7.0f, i * 0x01010101u};
  auto inBuf = MakeViewBuffer(n * sizeof(Element), sizeof(Element), in.data());
  auto outBuf = MakeViewBuffer(n * sizeof(Element), sizeof(Element), nullptr);
  auto srv = MakeSRV(inBuf.Get());  // whole structured buffer: no description needed
  auto uav = MakeUAV(outBuf.Get());
  struct {
    uint32_t count;
    float scale;
    uint32_t pad[2];
  } params{n, 2.0f, {}};
  auto cb = MakeCB(16, USAGE_DEFAULT, &params);
  auto cs = LoadCS("rhi_cs_structured_cs.spv");
  context()->CSSetShader(cs.Get());
  context()->CSSetShaderResources(0, 1, srv.GetAddressOf());
  context()->CSSetConstantBuffers(0, 1, cb.GetAddressOf());
  BindUav(uav.Get());
  context()->Dispatch(2, 1, 1);
  const auto bytes = ReadBuffer(outBuf.Get());
  std::vector<Element> out(n);
  std::memcpy(out.data(), bytes.data(), n * sizeof(Element));
  for (UINT i = 0; i < n; ++i) {
    EXPECT_EQ(out[i].value, in[i].value * 2.0f + 1.0f) << i;  // exact: halves times 2 plus 1
    EXPECT_EQ(out[i].bits, in[i].bits ^ (i * 2654435761u)) << i;
  }
}

TEST_F(RhiCompute, RawBufferRoundTripThroughSlotsT1AndU2) {
  const UINT n = 128;
  std::vector<uint32_t> in(n);
  for (UINT i = 0; i < n; ++i) in[i] = i * 1000u + 3u;
  auto inBuf = MakeViewBuffer(n * 4, 0, in.data());
  auto outBuf = MakeViewBuffer(n * 4, 0, nullptr);
  SHADER_RESOURCE_VIEW_DESC sd;
  sd.Format = DXGI_FORMAT_R32_TYPELESS;
  sd.ViewDimension = SRV_DIMENSION_BUFFEREX;
  sd.BufferEx = {0, n, BUFFEREX_SRV_FLAG_RAW};
  ComPtr<ShaderResourceView> srv;
  ASSERT_EQ(device()->CreateShaderResourceView(inBuf.Get(), &sd, srv.ReleaseAndGetAddressOf()), S_OK);
  const auto ud = RawUavDesc(0, n);
  auto uav = MakeUAV(outBuf.Get(), &ud);
  auto cs = LoadCS("rhi_cs_raw_cs.spv");
  context()->CSSetShader(cs.Get());
  context()->CSSetShaderResources(1, 1, srv.GetAddressOf());
  BindUav(uav.Get(), 2);
  context()->Dispatch(n / 64, 1, 1);
  const auto out = ReadWords(outBuf.Get());
  for (UINT i = 0; i < n; ++i) EXPECT_EQ(out[i], in[i] * 3u + 7u) << i;
}

// D3D11 serialises dispatches that write the same UAV: three read-modify-write
// passes give 2^3 - 1 in every word (a missing barrier is a sync-validation
// hazard, and on a parallel GPU a wrong value).
TEST_F(RhiCompute, ConsecutiveDispatchesOnOneUavAreOrdered) {
  const UINT n = 256;
  auto buf = MakeViewBuffer(n * 4, 0, std::vector<uint32_t>(n, 0).data());
  const auto ud = RawUavDesc(0, n);
  auto uav = MakeUAV(buf.Get(), &ud);
  auto cs = LoadCS("rhi_cs_accumulate_cs.spv");
  context()->CSSetShader(cs.Get());
  BindUav(uav.Get());
  for (int i = 0; i < 3; ++i) context()->Dispatch(n / 64, 1, 1);
  const auto out = ReadWords(buf.Get());
  for (UINT i = 0; i < n; ++i) ASSERT_EQ(out[i], 7u) << i;
}

// ---------------------------------------------------------------------------
TEST_F(RhiCompute, ClearUnorderedAccessViewUintAndFloat) {
  auto rgba = MakeUavTexture(4, 4, DXGI_FORMAT_R8G8B8A8_UNORM);
  auto rgbaUav = MakeUAV(rgba.Get());
  const UINT bits[4] = {0x180, 0x7f, 0, 0xff};  // low 8 bits per channel: 0x80, 0x7f, 0, 0xff
  context()->ClearUnorderedAccessViewUint(rgbaUav.Get(), bits);
  const drrtest::Image afterUint = ReadBack(rgba.Get());
  const float floats[4] = {0.2f, 0.6f, 1.0f, 0.0f};  // 51, 153, 255, 0
  context()->ClearUnorderedAccessViewFloat(rgbaUav.Get(), floats);
  const drrtest::Image afterFloat = ReadBack(rgba.Get());
  EXPECT_EQ(afterUint.RGBA8(3, 3), (std::array<uint8_t, 4>{0x80, 0x7f, 0, 0xff}));
  EXPECT_EQ(afterFloat.RGBA8(1, 2), (std::array<uint8_t, 4>{51, 153, 255, 0}));

  auto r32 = MakeUavTexture(4, 4, DXGI_FORMAT_R32_FLOAT);
  auto r32Uav = MakeUAV(r32.Get());
  const UINT one[4] = {0x3f800000u, 0, 0, 0};  // the bits of 1.0f, copied as they are
  context()->ClearUnorderedAccessViewUint(r32Uav.Get(), one);
  EXPECT_EQ(ReadBack(r32.Get()).Float(2, 1), 1.0f);

  // Raw buffer: only the view's words [16, 24) take the first value.
  std::vector<uint32_t> init(32);
  for (UINT i = 0; i < 32; ++i) init[i] = i;
  auto buf = MakeViewBuffer(32 * 4, 0, init.data());
  const auto ud = RawUavDesc(16, 8);
  auto bufUav = MakeUAV(buf.Get(), &ud);
  const UINT fill[4] = {0xdeadbeefu, 1, 2, 3};
  context()->ClearUnorderedAccessViewUint(bufUav.Get(), fill);
  const auto words = ReadWords(buf.Get());
  for (UINT i = 0; i < 32; ++i) EXPECT_EQ(words[i], i >= 16 && i < 24 ? 0xdeadbeefu : i) << i;
}

// ---------------------------------------------------------------------------
// Arguments from the CPU, then arguments written by a dispatch (UAV write ->
// indirect read, ordered by the RHI).
TEST_F(RhiCompute, DispatchIndirectReadsGroupCountsFromABuffer) {
  const uint32_t args[8] = {3, 2, 1, 0, 0, 0, 0, 0};
  auto argBuf = MakeViewBuffer(sizeof(args), 0, args, RESOURCE_MISC_DRAWINDIRECT_ARGS);
  const auto argDesc = RawUavDesc(0, 8);
  auto argUav = MakeUAV(argBuf.Get(), &argDesc);
  auto counter = MakeViewBuffer(16, 0, std::vector<uint32_t>(4, 0).data());
  const auto cd = RawUavDesc(0, 4);
  auto counterUav = MakeUAV(counter.Get(), &cd);

  auto count = LoadCS("rhi_cs_count_cs.spv");
  context()->CSSetShader(count.Get());
  BindUav(counterUav.Get());
  context()->DispatchIndirect(argBuf.Get(), 0);  // 3 * 2 * 1 groups of 4
  EXPECT_EQ(ReadWords(counter.Get())[0], 24u);

  auto writeArgs = LoadCS("rhi_cs_args_cs.spv");
  context()->CSSetShader(writeArgs.Get());
  BindUav(argUav.Get());
  context()->Dispatch(1, 1, 1);  // writes (5, 2, 1) at byte 16
  context()->CSSetShader(count.Get());
  BindUav(counterUav.Get());
  context()->DispatchIndirect(argBuf.Get(), 16);
  EXPECT_EQ(ReadWords(counter.Get())[0], 24u + 5u * 2u * 4u);
}

// ---------------------------------------------------------------------------
// A pixel shader writes a UAV beside render target 0; two draws in a row
// read-modify-write it, so the second must see the first's writes.
TEST_F(RhiCompute, PixelShaderUavWritesAreOrderedBetweenDraws) {
  const UINT W = 16, H = 8;
  auto hits = MakeUavTexture(W, H, DXGI_FORMAT_R32_UINT, nullptr, 0);
  auto hitsUav = MakeUAV(hits.Get());
  const UINT five[4] = {5, 5, 5, 5};
  context()->ClearUnorderedAccessViewUint(hitsUav.Get(), five);
  auto rt = MakeRenderTarget(W, H);
  UnorderedAccessView* uavs[1] = {hitsUav.Get()};
  context()->OMSetRenderTargetsAndUnorderedAccessViews(1, rt.rtv.GetAddressOf(), nullptr, 1, 1, uavs, nullptr);
  SetViewport(W, H);
  auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
  auto ps = LoadPixelShader("rhi_cs_psuav_ps.spv");
  context()->IASetInputLayout(nullptr);
  context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
  context()->VSSetShader(vs.Get());
  context()->PSSetShader(ps.Get());
  context()->Draw(3, 0);
  context()->Draw(3, 0);
  context()->OMSetRenderTargetsAndUnorderedAccessViews(0, nullptr, nullptr, 0, 0, nullptr, nullptr);
  const drrtest::Image img = ReadBack(hits.Get());
  int bad = 0;
  for (UINT y = 0; y < H; ++y)
    for (UINT x = 0; x < W; ++x) {
      uint32_t v;
      std::memcpy(&v, img.At(x, y), 4);
      bad += v != (5u * 2u + x + 1u) * 2u + x + 1u;
    }
  EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace rhitest
