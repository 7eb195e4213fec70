// Compute on deferred contexts: dispatches, UAV clears and DispatchIndirect
// recorded into command lists (on worker threads where it matters) and
// executed on the immediate context, compared with the immediate context and
// with CPU computations; and the reuse of a context's recordings. Every test
// runs under core + synchronization validation (RhiTest): the barriers at
// ExecuteCommandList and inside a list come from the RHI alone.
#include <cstring>
#include <thread>

#include "ComputeTest.h"

namespace rhitest {
namespace {

struct Element {  // cs_structured_cs.hlsl
  float value;
  uint32_t bits;
};
struct StructuredParams {
  uint32_t count;
  float scale;
  uint32_t pad[2];
};

// The texel cs_pattern_cs.hlsl writes at (x, y).
void PatternTexel(uint32_t x, uint32_t y, uint32_t salt, uint8_t out[4]) {
  out[0] = uint8_t(x);
  out[1] = uint8_t(y);
  out[2] = uint8_t((x ^ y ^ salt) & 255);
  out[3] = 255;
}

class RhiDeferredCompute : public ComputeTest {
 protected:
  ComPtr<DeviceContext> MakeDeferred() {
    ComPtr<DeviceContext> ctx;
    EXPECT_EQ(device()->CreateDeferredContext(0, ctx.ReleaseAndGetAddressOf()), S_OK);
    return ctx;
  }
  static void WriteConstants(DeviceContext* ctx, Buffer* cb, const void* data, size_t size) {
    MAPPED_SUBRESOURCE m;
    ASSERT_EQ(ctx->Map(cb, 0, MAP_WRITE_DISCARD, 0, &m), S_OK);
    std::memcpy(m.pData, data, size);
    ctx->Unmap(cb, 0);
  }
  static ComPtr<CommandList> Finish(DeviceContext* ctx) {
    ComPtr<CommandList> list;
    EXPECT_EQ(ctx->FinishCommandList(0, list.ReleaseAndGetAddressOf()), S_OK);
    return list;
  }
  // What the recording-reuse tests record, list after list: a deferred
  // context, cs_accumulate_cs (every word w = w * 2 + 1 per dispatch) over 64
  // zeroed words behind a raw UAV, and a 16-byte dynamic constant buffer.
  struct Accumulate {
    ComPtr<Buffer> words, cb;
    ComPtr<UnorderedAccessView> uav;
    ComPtr<ComputeShader> cs;
    ComPtr<DeviceContext> deferred;
  };
  Accumulate MakeAccumulate() {
    constexpr UINT kWords = 64;
    Accumulate a;
    a.words = MakeViewBuffer(kWords * 4, 0, std::vector<uint32_t>(kWords, 0).data());
    const auto ud = RawUavDesc(0, kWords);
    a.uav = MakeUAV(a.words.Get(), &ud);
    a.cs = LoadCS("rhi_cs_accumulate_cs.spv");
    a.cb = MakeCB(16);
    a.deferred = MakeDeferred();
    return a;
  }
  // Texels of `tex` that differ from cs_pattern_cs's pattern with `salt`,
  // sampled by a draw into a new target (the read after the UAV write).
  int SampledPatternMismatches(ShaderResourceView* srv, uint32_t w, uint32_t h, uint32_t salt) {
    auto smp = MakeSampler(FILTER_MIN_MAG_MIP_POINT);
    drrtest::RenderTarget rt = MakeRenderTarget(w, h);
    Bind(rt, w, h);
    DrawSampled(srv, smp.Get());
    const drrtest::Image img = ReadBack(rt.texture.Get());
    int bad = 0;
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        uint8_t want[4];
        PatternTexel(x, y, salt, want);
        bad += std::memcmp(img.RGBA8(x, y).data(), want, 4) != 0;
      }
    return bad;
  }
};

// The same dispatch (structured buffer in, structured UAV out, constants from
// a Map(WRITE_DISCARD)) on the immediate context and in a list recorded on a
// worker thread: equal outputs, equal to the CPU. The list alone keeps the
// shader, views and constant buffer alive (FinishCommandList(0) unbinds
// them and the test drops its references before the execution).
TEST_F(RhiDeferredCompute, DispatchInAListMatchesTheImmediateContextAndTheCpu) {
  const UINT n = 100;  // two groups of 64, the second partial
  std::vector<Element> in(n);
  for (UINT i = 0; i < n; ++i) in[i] = {float(i) * 0.25f - 9.0f, i * 0x01030507u};
  const StructuredParams params{n, 4.0f, {}};
  auto outImmediate = MakeViewBuffer(n * sizeof(Element), sizeof(Element), nullptr);
  auto outDeferred = MakeViewBuffer(n * sizeof(Element), sizeof(Element), nullptr);
  auto deferred = MakeDeferred();
  DEVICE_STATS before;
  device()->GetStats(&before);
  ComPtr<CommandList> list;
  {
    auto inBuf = MakeViewBuffer(n * sizeof(Element), sizeof(Element), in.data());
    auto srv = MakeSRV(inBuf.Get());
    auto cs = LoadCS("rhi_cs_structured_cs.spv");
    auto cb = MakeCB(sizeof(params));
    auto record = [&](DeviceContext* ctx, Buffer* out) {
      auto uav = MakeUAV(out);
      WriteConstants(ctx, cb.Get(), &params, sizeof(params));
      ctx->CSSetShader(cs.Get());
      ctx->CSSetShaderResources(0, 1, srv.GetAddressOf());
      ctx->CSSetConstantBuffers(0, 1, cb.GetAddressOf());
      UnorderedAccessView* u = uav.Get();
      ctx->CSSetUnorderedAccessViews(0, 1, &u, nullptr);
      ctx->Dispatch(2, 1, 1);
    };
    record(context(), outImmediate.Get());
    std::thread worker([&] {
      record(deferred.Get(), outDeferred.Get());
      list = Finish(deferred.Get());
    });
    worker.join();
    context()->ClearState();
  }
  DEVICE_STATS held;
  device()->GetStats(&held);
  EXPECT_GE(held.LiveObjects, before.LiveObjects + 5) << "the list holds itself, the shader, the views and the CB";
  context()->ExecuteCommandList(list.Get(), 0);
  list = nullptr;  // released right after execution: still valid for the GPU
  DEVICE_STATS after;
  device()->GetStats(&after);
  EXPECT_EQ(after.LiveObjects, before.LiveObjects);
  const auto immediate = ReadBuffer(outImmediate.Get());
  const auto fromList = ReadBuffer(outDeferred.Get());
  ASSERT_EQ(immediate.size(), fromList.size());
  EXPECT_EQ(std::memcmp(immediate.data(), fromList.data(), immediate.size()), 0);
  std::vector<Element> out(n);
  std::memcpy(out.data(), fromList.data(), n * sizeof(Element));
  for (UINT i = 0; i < n; ++i) {
    ASSERT_EQ(out[i].value, in[i].value * 4.0f + 1.0f) << i;  // exact in float
    ASSERT_EQ(out[i].bits, in[i].bits ^ (i * 2654435761u)) << i;
  }
}

// A list writes a texture through a UAV; after ExecuteCommandList the
// immediate context samples it in a draw, with no barrier from the test.
// Twice, with two lists recorded at the same time on two threads: the second
// execution brings the texture back from SHADER_READ to the UAV's GENERAL.
TEST_F(RhiDeferredCompute, UavWrittenByAListIsSampledAfterExecuteWithoutAManualBarrier) {
  const UINT W = 24, H = 16;
  auto tex = MakeUavTexture(W, H, DXGI_FORMAT_R8G8B8A8_UNORM);
  auto uav = MakeUAV(tex.Get());
  auto srv = MakeSRV(tex.Get());
  auto cs = LoadCS("rhi_cs_pattern_cs.spv");
  auto cb = MakeCB(16);
  const uint32_t salts[2] = {0x00, 0x5a};
  ComPtr<DeviceContext> deferred[2] = {MakeDeferred(), MakeDeferred()};
  ComPtr<CommandList> lists[2];
  auto record = [&](int i) {
    DeviceContext* ctx = deferred[i].Get();
    const uint32_t salt[4] = {salts[i], 0, 0, 0};
    WriteConstants(ctx, cb.Get(), salt, sizeof(salt));
    ctx->CSSetShader(cs.Get());
    ctx->CSSetConstantBuffers(1, 1, cb.GetAddressOf());
    UnorderedAccessView* u = uav.Get();
    ctx->CSSetUnorderedAccessViews(0, 1, &u, nullptr);
    ctx->Dispatch(W / 8, H / 8, 1);
    lists[i] = Finish(ctx);
  };
  std::thread first(record, 0), second(record, 1);
  first.join();
  second.join();
  for (int i = 0; i < 2; ++i) {
    context()->ExecuteCommandList(lists[i].Get(), 0);
    EXPECT_EQ(SampledPatternMismatches(srv.Get(), W, H, salts[i]), 0) << "list " << i;
  }
}

// Inside a list, dependent dispatches are ordered (read-modify-write three
// times), and so are the list and the immediate context's work around it:
// a clear and a dispatch before, the same list executed twice.
TEST_F(RhiDeferredCompute, DispatchesAreOrderedInsideAListAndAroundItsExecutions) {
  const UINT n = 256;
  auto buf = MakeViewBuffer(n * 4, 0, nullptr);
  const auto ud = RawUavDesc(0, n);
  auto uav = MakeUAV(buf.Get(), &ud);
  auto cs = LoadCS("rhi_cs_accumulate_cs.spv");
  auto deferred = MakeDeferred();
  deferred->CSSetShader(cs.Get());
  UnorderedAccessView* u = uav.Get();
  deferred->CSSetUnorderedAccessViews(0, 1, &u, nullptr);
  for (int i = 0; i < 3; ++i) deferred->Dispatch(n / 64, 1, 1);
  auto list = Finish(deferred.Get());

  const UINT one[4] = {1, 0, 0, 0};
  context()->ClearUnorderedAccessViewUint(uav.Get(), one);  // 1
  context()->CSSetShader(cs.Get());
  BindUav(uav.Get());
  context()->Dispatch(n / 64, 1, 1);              // 3
  context()->ExecuteCommandList(list.Get(), 1);  // 7, 15, 31
  context()->ExecuteCommandList(list.Get(), 1);  // 63, 127, 255
  const auto out = ReadWords(buf.Get());
  for (UINT i = 0; i < n; ++i) ASSERT_EQ(out[i], 255u) << i;
}

// A list clears a counter, writes indirect arguments with one dispatch and
// reads them with DispatchIndirect: the UAV write -> indirect read barrier
// is inside the list.
TEST_F(RhiDeferredCompute, IndirectArgumentsWrittenInAListAreReadByItsDispatchIndirect) {
  const uint32_t args[8] = {3, 2, 1, 0, 0, 0, 0, 0};
  auto argBuf = MakeViewBuffer(sizeof(args), 0, args, RESOURCE_MISC_DRAWINDIRECT_ARGS);
  const auto argDesc = RawUavDesc(0, 8);
  auto argUav = MakeUAV(argBuf.Get(), &argDesc);
  auto counter = MakeViewBuffer(16, 0, nullptr);
  const auto cd = RawUavDesc(0, 4);
  auto counterUav = MakeUAV(counter.Get(), &cd);
  auto count = LoadCS("rhi_cs_count_cs.spv");
  auto writeArgs = LoadCS("rhi_cs_args_cs.spv");

  auto deferred = MakeDeferred();
  const UINT zero[4] = {};
  deferred->ClearUnorderedAccessViewUint(counterUav.Get(), zero);
  UnorderedAccessView* u = argUav.Get();
  deferred->CSSetShader(writeArgs.Get());
  deferred->CSSetUnorderedAccessViews(0, 1, &u, nullptr);
  deferred->Dispatch(1, 1, 1);  // writes (5, 2, 1) at byte 16
  u = counterUav.Get();
  deferred->CSSetShader(count.Get());
  deferred->CSSetUnorderedAccessViews(0, 1, &u, nullptr);
  deferred->DispatchIndirect(argBuf.Get(), 0);   // 3 * 2 * 1 groups of 4
  deferred->DispatchIndirect(argBuf.Get(), 16);  // 5 * 2 * 1 groups of 4
  auto list = Finish(deferred.Get());
  context()->ExecuteCommandList(list.Get(), 0);
  EXPECT_EQ(ReadWords(counter.Get())[0], 24u + 40u);
}

// Once the frames that executed them have completed, released lists' command
// pools, descriptor pools and ring chunks serve the context's next lists:
// after a warm-up, recording, executing and releasing a list per frame hands
// nothing more to the deferred destruction.
TEST_F(RhiDeferredCompute, ReleasedListsAreRecycledNotDestroyed) {
  const Accumulate a = MakeAccumulate();
  DeviceContext* deferred = a.deferred.Get();
  auto frame = [&] {
    const uint32_t unused[4] = {};
    WriteConstants(deferred, a.cb.Get(), unused, sizeof(unused));  // a ring slice
    deferred->CSSetShader(a.cs.Get());
    deferred->CSSetConstantBuffers(0, 1, a.cb.GetAddressOf());  // a descriptor set
    UnorderedAccessView* u = a.uav.Get();
    deferred->CSSetUnorderedAccessViews(0, 1, &u, nullptr);
    deferred->Dispatch(1, 1, 1);
    auto list = Finish(deferred);
    context()->ExecuteCommandList(list.Get(), 0);
    context()->Flush();
  };
  for (int i = 0; i < 8; ++i) frame();
  DEVICE_STATS before;
  device()->GetStats(&before);
  for (int i = 0; i < 8; ++i) frame();
  DEVICE_STATS after;
  device()->GetStats(&after);
  EXPECT_EQ(after.ObjectsDestroyed + after.DeferredDestructionsPending,
            before.ObjectsDestroyed + before.DeferredDestructionsPending);
  const auto out = ReadWords(a.words.Get());
  EXPECT_EQ(out[0], 0xffffu);  // 16 read-modify-writes, in order
}

// A deferred context takes its next list's recording (a released list's,
// reset for reuse) when that list starts, at its first bind or command, not
// in FinishCommandList: the reset runs while the application sets up the
// next list (the scene's workers do it while the main thread builds the draw
// list). A list finished with nothing in it still executes.
TEST_F(RhiDeferredCompute, TheNextListTakesItsRecordingAtItsFirstBindNotInFinish) {
  const Accumulate a = MakeAccumulate();
  DeviceContext* deferred = a.deferred.Get();
  const auto resets = [&] {
    DEVICE_STATS s;
    device()->GetStats(&s);
    return s.CommandPoolResets;
  };
  const auto recordAfterShader = [&] {
    deferred->CSSetConstantBuffers(0, 1, a.cb.GetAddressOf());
    UnorderedAccessView* u = a.uav.Get();
    deferred->CSSetUnorderedAccessViews(0, 1, &u, nullptr);
    deferred->Dispatch(1, 1, 1);
    return Finish(deferred);
  };
  {  // executed, completed and released: its recording waits for reuse
    deferred->CSSetShader(a.cs.Get());
    auto first = recordAfterShader();
    context()->ExecuteCommandList(first.Get(), 0);
    context()->Flush();
    device()->WaitIdle();
  }
  const uint64_t before = resets();
  deferred->CSSetShader(a.cs.Get());  // the second list's first bind
  EXPECT_EQ(resets(), before + 1) << "the first bind takes the released list's recording";
  auto second = recordAfterShader();
  EXPECT_EQ(resets(), before + 1) << "FinishCommandList takes no recording";
  auto empty = Finish(deferred);
  ASSERT_TRUE(empty);
  context()->ExecuteCommandList(second.Get(), 0);
  context()->ExecuteCommandList(empty.Get(), 0);
  EXPECT_EQ(ReadWords(a.words.Get())[0], 0x3u);  // two read-modify-writes
}

}  // namespace
}  // namespace rhitest
