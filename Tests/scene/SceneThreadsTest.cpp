// Scene::Render on deferred contexts (Docs/Threads.md), under core +
// synchronization validation: every chunk on its worker's deferred context
// (callerTakesLateChunks off, so the lists are always used), against the
// immediate context: the same colour and velocity bytes over moving frames,
// a paused frame, TAA's biased sampler and TAAU's per-material samplers
// (created on the calling thread before the split).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "RenderTest.h"
#include "scene/RecordingThreads.h"
#include "scene/Scene.h"

using namespace drr;

namespace {

constexpr uint32_t kW = 128, kH = 72;

class SceneThreads : public drrtest::RenderTest {
 protected:
  struct Frame {
    drrtest::Image colour, velocity;
    std::vector<drrtest::Image> gbuffer;  // specular, normal (the G-buffer path; colour is its diffuse)
    SceneStats stats;
  };
  // The port's other scene paths, recorded on the lists the same way.
  enum class Path { Forward, Tessellated, GBuffer };
  // drr_scene_record_bench --contention's frames: equal chunks, the caller's
  // drawn after the workers'.
  bool measurementSplit_ = false;

  // Whether two frames have the same colour and velocity bytes; a failure
  // says which image differs.
  static ::testing::AssertionResult SameColourAndVelocity(const Frame& a, const Frame& b) {
    if (a.colour.pixels != b.colour.pixels) return ::testing::AssertionFailure() << "colour differs";
    if (a.velocity.pixels != b.velocity.pixels) return ::testing::AssertionFailure() << "velocity differs";
    return ::testing::AssertionSuccess();
  }

  // Six frames of the cinematic camera on `threads`, from a reset matrix
  // history: three with TAA's sampler, three with TAAU's; the third of each
  // paused.
  std::vector<Frame> Render(Scene* scene, int threads, Path path = Path::Forward) {
    drrtest::RenderTarget colour = MakeRenderTarget(kW, kH, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);
    drrtest::RenderTarget specular = MakeRenderTarget(kW, kH, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);
    drrtest::RenderTarget normal = MakeRenderTarget(kW, kH, d3dl::DXGI_FORMAT_R10G10B10A2_UNORM);
    drrtest::RenderTarget velocity = MakeRenderTarget(kW, kH, d3dl::DXGI_FORMAT_R16G16_FLOAT);
    const drrtest::DepthTarget depth = MakeDepthTarget(kW, kH);
    std::vector<Frame> frames;
    for (int i = 0; i < 6; ++i) {
      const bool taau = i >= 3;
      scene->Update(2.0 + 0.25 * i);
      const CameraPose pose = scene->Camera(0);
      SceneRenderParams p;
      p.view = pose.view;
      p.proj = glm::perspectiveRH_ZO(pose.fovY, float(kW) / kH, pose.nearZ, pose.farZ);
      p.jitterNdc = glm::vec2(i & 1 ? 0.5f / kW : 0.f, 0.f);
      p.mipBiasSampler = !taau;
      if (taau) {
        p.viewMipBias = -0.5f - 0.25f * float(i);  // a new biased sampler each frame
        p.mipBiasOptOut = {"decal"};
      }
      p.resetHistory = i == 0;
      p.paused = i % 3 == 2;
      p.target = i & 1;
      p.recordingThreads = threads;
      p.viewport = d3dl::VIEWPORT{0, 0, float(kW), float(kH), 0, 1};
      p.callerTakesLateChunks = false;
      p.evenChunks = p.callerDrawsAfterWorkers = measurementSplit_;
      p.gbuffer = path == Path::GBuffer;
      if (path == Path::Tessellated) {
        p.tessellation.enabled = true;
        p.tessellation.pixelsPerEdge = 4.f;
        p.tessellation.maxFactor = 16.f;
        p.tessellation.viewportHeight = float(kH);
      }
      const float clear[4] = {0.f, 0.1f, 0.1f, 1.f}, zero[4] = {};
      context()->ClearRenderTargetView(colour.rtv.Get(), clear);
      context()->ClearRenderTargetView(velocity.rtv.Get(), zero);
      context()->ClearDepthStencilView(depth.dsv.Get(), d3dl::CLEAR_DEPTH, 1.f, 0);
      context()->ClearRenderTargetView(specular.rtv.Get(), zero);
      context()->ClearRenderTargetView(normal.rtv.Get(), zero);
      d3dl::RenderTargetView* forward[2] = {colour.rtv.Get(), velocity.rtv.Get()};
      d3dl::RenderTargetView* gbuffer[4] = {colour.rtv.Get(), specular.rtv.Get(), normal.rtv.Get(), velocity.rtv.Get()};
      if (p.gbuffer) context()->OMSetRenderTargets(4, gbuffer, depth.dsv.Get());
      else context()->OMSetRenderTargets(2, forward, depth.dsv.Get());
      SetViewport(kW, kH);
      scene->Render(context(), p);
      context()->OMSetRenderTargets(0, nullptr, nullptr);
      Frame f{ReadBack(colour.texture.Get()), ReadBack(velocity.texture.Get()), {}, scene->Stats()};
      if (p.gbuffer) f.gbuffer = {ReadBack(specular.texture.Get()), ReadBack(normal.texture.Get())};
      frames.push_back(std::move(f));
    }
    return frames;
  }
};

}  // namespace

TEST_F(SceneThreads, DeferredChunksGiveTheImmediateContextsBytes) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_DIR "/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  const std::vector<Frame> one = Render(scene.get(), 1);
  ASSERT_EQ(one.size(), 6u);
  EXPECT_EQ(one[0].stats.recordingThreads, 1u);
  for (int threads : {2, 3}) {
    const std::vector<Frame> many = Render(scene.get(), threads);
    ASSERT_EQ(many.size(), 6u);
    for (size_t i = 0; i < many.size(); ++i) {
      const SceneStats& s = many[i].stats;
      EXPECT_EQ(s.recordingThreads, uint32_t(threads));
      EXPECT_EQ(s.callerChunks, 1u);
      ASSERT_EQ(s.drawsPerThread.size(), size_t(threads));
      for (uint32_t n : s.drawsPerThread) EXPECT_GT(n, 0u) << "every chunk on its own thread";
      EXPECT_EQ(s.drawsIssued, one[i].stats.drawsIssued);
      EXPECT_TRUE(SameColourAndVelocity(many[i], one[i])) << threads << " threads, frame " << i;
    }
  }
}

// The contention measurement's frames (equal chunks, the caller's chunk
// recorded after the worker's list is finished) give the same bytes, and the
// chunks are equal after frames that taught the balance the threads' speeds
// (the immediate context records faster: it would give the caller more).
TEST_F(SceneThreads, EqualChunksRecordedOneAfterAnotherGiveTheSameBytes) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_PROPS_DIR "/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  const std::vector<Frame> one = Render(scene.get(), 1);
  ASSERT_EQ(one.size(), 6u);
  const std::vector<Frame> balanced = Render(scene.get(), 2);
  const std::vector<uint32_t>& learned = balanced.back().stats.drawsPerThread;
  ASSERT_EQ(learned.size(), 2u);
  std::printf("balanced split after six frames: %u + %u\n", learned[0], learned[1]);
  measurementSplit_ = true;
  const std::vector<Frame> many = Render(scene.get(), 2);
  ASSERT_EQ(many.size(), 6u);
  for (size_t i = 0; i < many.size(); ++i) {
    const SceneStats& s = many[i].stats;
    ASSERT_EQ(s.drawsPerThread.size(), 2u);
    const auto [lo, hi] = std::minmax_element(s.drawsPerThread.begin(), s.drawsPerThread.end());
    EXPECT_LE(*hi - *lo, 1u) << "frame " << i;
    EXPECT_EQ(s.callerChunks, 1u);
    EXPECT_TRUE(SameColourAndVelocity(many[i], one[i])) << "frame " << i;
  }
}

// The many-object Arena (about 3000 draws, one per prop): four lists, each
// chunk on its worker, give the immediate context's bytes; the automatic
// mode sizes each frame by the previous frame's draws, with the same bytes.
TEST_F(SceneThreads, ManyObjectArenaOnFourListsGivesTheImmediateContextsBytes) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_PROPS_DIR "/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  const std::vector<Frame> one = Render(scene.get(), 1);
  const std::vector<Frame> four = Render(scene.get(), 4);
  const std::vector<Frame> automatic = Render(scene.get(), 0);
  ASSERT_EQ(four.size(), one.size());
  ASSERT_EQ(automatic.size(), one.size());
  for (size_t i = 0; i < one.size(); ++i) {
    EXPECT_GT(one[i].stats.drawsIssued, 2000u);
    EXPECT_EQ(four[i].stats.recordingThreads, 4u);
    for (uint32_t n : four[i].stats.drawsPerThread) EXPECT_GT(n, 0u) << "every chunk on its own thread";
    EXPECT_TRUE(SameColourAndVelocity(four[i], one[i])) << "frame " << i;
    const uint32_t previous = i > 0 ? automatic[i - 1].stats.drawsIssued : four.back().stats.drawsIssued;
    EXPECT_EQ(automatic[i].stats.recordingThreads, uint32_t(AutoRecordingThreads(previous))) << "frame " << i;
    EXPECT_TRUE(automatic[i].colour.pixels == one[i].colour.pixels) << "frame " << i;
  }
}

// Tessellated draws (hull and domain stages, their constants mapped per
// draw on each list) and the G-buffer (four targets read back for the
// lists): every chunk on its worker, the immediate context's bytes.
TEST_F(SceneThreads, TessellatedAndGBufferChunksGiveTheImmediateContextsBytes) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_DIR "/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  for (Path path : {Path::Tessellated, Path::GBuffer}) {
    const std::vector<Frame> one = Render(scene.get(), 1, path);
    const std::vector<Frame> two = Render(scene.get(), 2, path);
    ASSERT_EQ(one.size(), two.size());
    for (size_t i = 0; i < two.size(); ++i) {
      const SceneStats& s = two[i].stats;
      EXPECT_EQ(s.callerChunks, 1u);
      for (uint32_t n : s.drawsPerThread) EXPECT_GT(n, 0u) << "every chunk on its own thread";
      if (path == Path::Tessellated) {
        EXPECT_GT(s.tessellatedDraws, 0u);
        EXPECT_EQ(s.patchesSubmitted, one[i].stats.patchesSubmitted);
      }
      EXPECT_TRUE(SameColourAndVelocity(two[i], one[i])) << int(path) << ", frame " << i;
      ASSERT_EQ(two[i].gbuffer.size(), one[i].gbuffer.size());
      for (size_t k = 0; k < two[i].gbuffer.size(); ++k)
        EXPECT_TRUE(two[i].gbuffer[k].pixels == one[i].gbuffer[k].pixels) << "G-buffer target " << k << ", frame " << i;
    }
  }
}

// Without a viewport the lists could not set one: the scene records on the
// caller's context alone.
TEST_F(SceneThreads, WithoutAViewportOneThread) {
  std::string err;
  auto scene = Scene::Load(device(), DRR_ARENA_DIR "/scene_description.txt", {}, &err);
  ASSERT_TRUE(scene) << err;
  drrtest::RenderTarget colour = MakeRenderTarget(kW, kH, d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);
  context()->OMSetRenderTargets(1, colour.rtv.GetAddressOf(), nullptr);
  SetViewport(kW, kH);
  SceneRenderParams p;
  p.writeVelocity = false;
  p.recordingThreads = 2;
  scene->Render(context(), p);
  EXPECT_EQ(scene->Stats().recordingThreads, 1u);
  context()->OMSetRenderTargets(0, nullptr, nullptr);
}
