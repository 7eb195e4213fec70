// Shared gtest fixture for rendering tests on D3DLikeRHI.
//
//   class MyTest : public drrtest::RenderTest {};
//   TEST_F(MyTest, Something) {
//     auto vs = LoadVertexShader("fullscreen_vs.spv");   // relative to ShaderDir()
//     ... draw into a texture ...
//     drrtest::Image img = ReadBack(texture.Get());
//     EXPECT_EQ(img.RGBA8(3, 4)[0], 255);
//   }
//
// SetUp creates a device and its immediate context with
// ValidationMode::FromEnvironment (ctest sets D3DL_VALIDATION=sync, so
// VK_LAYER_KHRONOS_validation with synchronization validation is on) and
// records every log message. TearDown clears the context state, waits for the
// GPU, releases the device and expects zero validation messages (they are
// printed when there are any). Tests that expect RHI errors can inspect
// Messages()/CountMessages(). Stable API: used by the rhi, scene and sample tests.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "Readback.h"
#include "RenderTargets.h"
#include "d3dl/D3DLike.h"

namespace drrtest {

// The sample's image and render-target types (DynamicResolutionRendering/
// Readback.h, RenderTargets.h): pixels of one subresource in its format, and
// a texture with its views.
using Image = drr::Image;
using RenderTarget = drr::RenderTarget;
// A depth texture and its view (MakeDepthTarget).
struct DepthTarget {
  d3dl::ComPtr<d3dl::Texture2D> texture;
  d3dl::ComPtr<d3dl::DepthStencilView> dsv;
};

class RenderTest : public ::testing::Test {
 public:
  struct LogEntry {
    d3dl::LogLevel level;
    std::string text;
  };

  // Directory of the compiled test shaders (env D3DL_TEST_SHADER_DIR overrides).
  static std::string ShaderDir();
  // Reads a SPIR-V file (a failure if it cannot be opened); a relative path is
  // taken relative to ShaderDir().
  static std::vector<uint32_t> LoadSpirv(const std::string& path);

 protected:
  void SetUp() override;
  void TearDown() override;

  d3dl::Device* device() const { return device_.Get(); }
  d3dl::DeviceContext* context() const { return context_.Get(); }

  // Copies mip `mip` of `texture` into a STAGING texture and maps it (READ).
  Image ReadBack(d3dl::Texture2D* texture, uint32_t mip = 0);

  d3dl::ComPtr<d3dl::VertexShader> LoadVertexShader(const std::string& path);
  d3dl::ComPtr<d3dl::PixelShader> LoadPixelShader(const std::string& path);
  template <class T>
  d3dl::ComPtr<T> LoadShader(const std::string& path);

  // width x height render target (+SRV) of `format`, optionally with a full mip chain.
  RenderTarget MakeRenderTarget(uint32_t width, uint32_t height,
                                d3dl::DXGI_FORMAT format = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM);
  // width x height D32_FLOAT depth texture and its view.
  DepthTarget MakeDepthTarget(uint32_t width, uint32_t height);
  // Sets a full-target viewport for width x height.
  void SetViewport(uint32_t width, uint32_t height);

  // Log captured since SetUp (or ClearMessages).
  std::vector<LogEntry> Messages() const;
  size_t CountMessages(d3dl::LogLevel level, const std::string& contains = "") const;
  void ClearMessages();
  uint64_t ValidationMessageCount() const;

  // Set to false in a test that intentionally provokes validation messages.
  bool expectNoValidation_ = true;

 private:
  static void LogThunk(d3dl::LogLevel level, const char* message, void* user);
  mutable std::mutex mutex_;
  std::vector<LogEntry> log_;
  d3dl::ComPtr<d3dl::Device> device_;
  d3dl::ComPtr<d3dl::DeviceContext> context_;
};

template <>
inline d3dl::ComPtr<d3dl::VertexShader> RenderTest::LoadShader<d3dl::VertexShader>(const std::string& path) {
  return LoadVertexShader(path);
}
template <>
inline d3dl::ComPtr<d3dl::PixelShader> RenderTest::LoadShader<d3dl::PixelShader>(const std::string& path) {
  return LoadPixelShader(path);
}

}  // namespace drrtest
