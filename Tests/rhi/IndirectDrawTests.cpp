// DrawInstancedIndirect and DrawIndexedInstancedIndirect draw the pixels that
// DrawInstanced and DrawIndexedInstanced draw with the same arguments, on the
// immediate context and in a command list. The arguments are written by
// UpdateSubresource just before the draws that read them, and rewritten after,
// so the copy -> indirect read barrier and its reverse run under
// synchronization validation with no barrier from the test.
#include <algorithm>
#include <array>
#include <functional>

#include "RhiTest.h"

namespace rhitest {
namespace {

constexpr int kSize = 64;
const float kBlack[4] = {0, 0, 0, 1};

struct Corner {
  float pos[2];  // clip space
};
struct Instance {  // slot 1 of instance_vs.hlsl
  float offset[2];
  float color[4];
};

Corner At(int x, int y) { return {{float(x) * 2.0f / kSize - 1.0f, 1.0f - float(y) * 2.0f / kSize}}; }

// The vertex buffer: vertices 0..5 a large square (drawn only if
// StartVertexLocation were ignored), 6..11 the square [4,12)^2, 12..15 the
// corners of the square [20,28) x [4,12) for the indexed draws.
std::vector<Corner> MakeCorners() {
  std::vector<Corner> v;
  for (auto [x0, y0, x1, y1] : {std::array<int, 4>{0, 0, 24, 24}, std::array<int, 4>{4, 4, 12, 12}})
    for (Corner c : {At(x0, y0), At(x1, y0), At(x0, y1), At(x1, y0), At(x1, y1), At(x0, y1)}) v.push_back(c);
  for (Corner c : {At(20, 4), At(28, 4), At(20, 12), At(28, 12)}) v.push_back(c);
  return v;
}
// Indices 0..3 a triangle drawn only if StartIndexLocation were ignored;
// 4..9 the two triangles of a square.
const uint16_t kIndices[10] = {3, 2, 1, 0, 0, 1, 2, 1, 3, 2};

// Instance i moves its shape by (32, 0), (0, 32) or (32, 32) pixels.
std::vector<Instance> MakeInstances() {
  const float colors[4][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
  std::vector<Instance> v;
  for (int i = 0; i < 4; ++i) {
    const Corner shift = At(32 * (i & 1), 32 * (i >> 1));
    v.push_back({{shift.pos[0] + 1.0f, shift.pos[1] - 1.0f}, {colors[i][0], colors[i][1], colors[i][2], colors[i][3]}});
  }
  return v;
}

// D3D11's argument records.
struct DrawArgs {
  UINT vertexCount, instanceCount, startVertex, startInstance;
};
struct DrawIndexedArgs {
  UINT indexCount, instanceCount, startIndex;
  int32_t baseVertex;
  UINT startInstance;
};
struct ArgSet {
  DrawArgs draw;
  DrawIndexedArgs indexed;
};
// Instances 1 and 2 of the small square; instances 2 and 3 of the indexed square.
constexpr ArgSet kFirst{{6, 2, 6, 1}, {6, 2, 4, 12, 2}};
// Instances 0..2 of the small square; one triangle of the indexed square, instance 3.
constexpr ArgSet kSecond{{6, 3, 6, 0}, {3, 1, 7, 12, 3}};
// Where the records lie in the argument buffer: not at its start, and the
// indexed one not 16-byte aligned.
constexpr UINT kDrawOffset = 4, kIndexedOffset = 24, kArgsBytes = 48;

class RhiIndirectDraw : public RhiTest {
 protected:
  void SetUp() override {
    RhiTest::SetUp();
    const auto code = LoadSpirv("rhi_instance_vs.spv");
    vs_ = LoadVertexShader("rhi_instance_vs.spv");
    ps_ = LoadPixelShader("rhi_color_ps.spv");
    INPUT_ELEMENT_DESC e[3];
    e[0].SemanticName = "POSITION";
    e[0].Format = DXGI_FORMAT_R32G32_FLOAT;
    e[1].SemanticName = "OFFSET";
    e[1].Format = DXGI_FORMAT_R32G32_FLOAT;
    e[2].SemanticName = "COLOR";
    e[2].Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    for (int i = 1; i < 3; ++i) {
      e[i].InputSlot = 1;
      e[i].InputSlotClass = INPUT_PER_INSTANCE_DATA;
      e[i].InstanceDataStepRate = 1;
    }
    ASSERT_EQ(device()->CreateInputLayout(e, 3, code.data(), code.size() * 4, layout_.ReleaseAndGetAddressOf()), S_OK);
    const auto corners = MakeCorners();
    const auto instances = MakeInstances();
    vertices_[0] = MakeBuffer(BIND_VERTEX_BUFFER, corners.data(), UINT(corners.size() * sizeof(Corner)));
    vertices_[1] = MakeBuffer(BIND_VERTEX_BUFFER, instances.data(), UINT(instances.size() * sizeof(Instance)));
    indices_ = MakeBuffer(BIND_INDEX_BUFFER, kIndices, sizeof(kIndices));
    RASTERIZER_DESC rd;
    rd.CullMode = CULL_NONE;
    ASSERT_EQ(device()->CreateRasterizerState(&rd, rs_.ReleaseAndGetAddressOf()), S_OK);
    BUFFER_DESC ad;
    ad.ByteWidth = kArgsBytes;
    ad.MiscFlags = RESOURCE_MISC_DRAWINDIRECT_ARGS;
    ASSERT_EQ(device()->CreateBuffer(&ad, nullptr, args_.ReleaseAndGetAddressOf()), S_OK);
    rt_ = MakeRenderTarget(kSize, kSize);
  }
  void TearDown() override {
    vs_ = {};
    ps_ = {};
    layout_ = {};
    vertices_[0] = {};
    vertices_[1] = {};
    indices_ = {};
    args_ = {};
    rs_ = {};
    rt_.Release();
    RhiTest::TearDown();
  }

  // Everything the draws need (a deferred context starts from the defaults).
  void BindState(DeviceContext* ctx) {
    ctx->OMSetRenderTargets(1, rt_.rtv.GetAddressOf(), nullptr);
    const VIEWPORT vp{0, 0, float(kSize), float(kSize), 0, 1};
    ctx->RSSetViewports(1, &vp);
    ctx->RSSetState(rs_.Get());
    const UINT strides[2] = {sizeof(Corner), sizeof(Instance)}, offsets[2] = {0, 0};
    Buffer* const buffers[2] = {vertices_[0].Get(), vertices_[1].Get()};
    ctx->IASetVertexBuffers(0, 2, buffers, strides, offsets);
    ctx->IASetIndexBuffer(indices_.Get(), DXGI_FORMAT_R16_UINT, 0);
    ctx->IASetInputLayout(layout_.Get());
    ctx->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    ctx->VSSetShader(vs_.Get());
    ctx->PSSetShader(ps_.Get());
  }

  // The argument buffer: both records of `a` between words that are not arguments.
  void WriteArgs(const ArgSet& a) {
    UINT words[kArgsBytes / 4];
    std::fill(std::begin(words), std::end(words), 0xdeadu);
    std::memcpy(reinterpret_cast<uint8_t*>(words) + kDrawOffset, &a.draw, sizeof(a.draw));
    std::memcpy(reinterpret_cast<uint8_t*>(words) + kIndexedOffset, &a.indexed, sizeof(a.indexed));
    context()->UpdateSubresource(args_.Get(), 0, nullptr, words, 0, 0);
  }

  void RecordIndirect(DeviceContext* ctx) {
    BindState(ctx);
    ctx->DrawInstancedIndirect(args_.Get(), kDrawOffset);
    ctx->DrawIndexedInstancedIndirect(args_.Get(), kIndexedOffset);
  }

  // The image of the draws of `sets`, in order, with their arguments given directly.
  drrtest::Image DrawDirect(const std::vector<const ArgSet*>& sets) {
    context()->ClearRenderTargetView(rt_.rtv.Get(), kBlack);
    BindState(context());
    for (const ArgSet* a : sets) {
      const DrawArgs& d = a->draw;
      const DrawIndexedArgs& i = a->indexed;
      context()->DrawInstanced(d.vertexCount, d.instanceCount, d.startVertex, d.startInstance);
      context()->DrawIndexedInstanced(i.indexCount, i.instanceCount, i.startIndex, i.baseVertex, i.startInstance);
    }
    return ReadBack(rt_.texture.Get());
  }

  // `drawIndirect` run once per argument set, each set written just before,
  // in one frame: the first set alone, the second alone, then both (the
  // second written after the first set's draws read the buffer). Each image
  // must equal the direct draws'.
  void ExpectDirectImages(const std::function<void()>& drawIndirect, const char* what) {
    const std::vector<std::vector<const ArgSet*>> runs = {{&kFirst}, {&kSecond}, {&kFirst, &kSecond}};
    std::vector<drrtest::Image> direct;
    for (const auto& sets : runs) direct.push_back(DrawDirect(sets));
    ExpectFirstArgumentsDrawn(direct[0]);
    ASSERT_NE(direct[0].pixels, direct[1].pixels);
    const uint64_t before = DrawCalls();
    for (size_t r = 0; r < runs.size(); ++r) {
      context()->ClearRenderTargetView(rt_.rtv.Get(), kBlack);
      for (const ArgSet* a : runs[r]) {
        WriteArgs(*a);
        drawIndirect();
      }
      EXPECT_TRUE(ReadBack(rt_.texture.Get()).pixels == direct[r].pixels)
          << what << ", run " << r << ": indirect and direct draws differ";
    }
    EXPECT_EQ(DrawCalls() - before, 8u);
  }

  // The direct draws of kFirst put each shape where its arguments say, so
  // that comparing images compares the arguments' effect.
  static void ExpectFirstArgumentsDrawn(const drrtest::Image& img) {
    const std::array<uint8_t, 4> black{0, 0, 0, 255}, green{0, 255, 0, 255}, blue{0, 0, 255, 255},
        white{255, 255, 255, 255};
    EXPECT_EQ(img.RGBA8(40, 8), green);   // small square, instance 1
    EXPECT_EQ(img.RGBA8(8, 40), blue);    // small square, instance 2
    EXPECT_EQ(img.RGBA8(24, 40), blue);   // indexed square, instance 2
    EXPECT_EQ(img.RGBA8(56, 40), white);  // indexed square, instance 3
    EXPECT_EQ(img.RGBA8(8, 8), black);    // StartInstanceLocation 1: no instance 0
    EXPECT_EQ(img.RGBA8(50, 18), black);  // StartVertexLocation 6: not the large square
    EXPECT_EQ(img.RGBA8(40, 40), black);  // InstanceCount 2: no instance 3 of the small square
  }

  uint64_t DrawCalls() const {
    DEVICE_STATS st;
    device()->GetStats(&st);
    return st.DrawCalls;
  }

  ComPtr<VertexShader> vs_;
  ComPtr<PixelShader> ps_;
  ComPtr<InputLayout> layout_;
  ComPtr<Buffer> vertices_[2], indices_, args_;
  ComPtr<RasterizerState> rs_;
  drrtest::RenderTarget rt_;
};

TEST_F(RhiIndirectDraw, ImmediateIndirectDrawsMatchDirectDraws) {
  ExpectDirectImages([&] { RecordIndirect(context()); }, "immediate context");
}

// A list reads the arguments when it runs, not when it is recorded: one
// list, executed after each write of other arguments, draws every image.
TEST_F(RhiIndirectDraw, CommandListReadsTheArgumentsAtExecution) {
  ComPtr<DeviceContext> deferred;
  ASSERT_EQ(device()->CreateDeferredContext(0, deferred.ReleaseAndGetAddressOf()), S_OK);
  RecordIndirect(deferred.Get());
  ComPtr<CommandList> list;
  ASSERT_EQ(deferred->FinishCommandList(0, list.ReleaseAndGetAddressOf()), S_OK);
  deferred = {};  // the list holds the argument buffer and the state it draws with
  ExpectDirectImages([&] { context()->ExecuteCommandList(list.Get(), 0); }, "command list");
}

}  // namespace
}  // namespace rhitest
