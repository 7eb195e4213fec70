#include "RenderTest.h"

#include "ValidationInForce.h"

#include "d3dl/ShaderCompiler.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

using namespace d3dl;

namespace drrtest {
void RenderTest::LogThunk(LogLevel level, const char* message, void* user) {
  auto* self = static_cast<RenderTest*>(user);
  std::lock_guard<std::mutex> lock(self->mutex_);
  self->log_.push_back({level, message ? message : ""});
  if (level != LogLevel::Info && std::getenv("DRR_TEST_VERBOSE"))
    std::fprintf(stderr, "[log %d] %s\n", int(level), message);
}

void RenderTest::SetUp() {
  DEVICE_CREATE_DESC desc;
  desc.Validation = ValidationMode::FromEnvironment;
  desc.Log = &RenderTest::LogThunk;
  desc.LogUser = this;
  desc.ApplicationName = "drr-tests";
  HRESULT hr = CreateDevice(&desc, device_.ReleaseAndGetAddressOf(), context_.ReleaseAndGetAddressOf());
  ASSERT_EQ(hr, S_OK) << "CreateDevice failed: " << HResultName(hr);
  ASSERT_TRUE(device_ && context_);
  // Without the layer a test asked to run under validation would pass
  // without anything checked.
  DEVICE_STATS stats;
  device_->GetStats(&stats);
  ASSERT_EQ(stats.Validation, stats.ValidationRequested) << kValidationLayerMissing;
}

void RenderTest::TearDown() {
  if (context_) context_->ClearState();
  if (device_) device_->WaitIdle();
  context_.Reset();
  device_.Reset();  // validation messages of the shutdown are still captured
  if (!expectNoValidation_) return;
  std::string all;
  size_t n = 0;
  for (const auto& e : Messages())
    if (e.level == LogLevel::Validation) {
      ++n;
      all += "  " + e.text + "\n";
    }
  EXPECT_EQ(n, 0u) << "validation messages:\n" << all;
}

std::string RenderTest::ShaderDir() {
  if (const char* env = std::getenv("D3DL_TEST_SHADER_DIR")) return env;
  return DRR_TEST_SHADER_DIR;
}

std::vector<uint32_t> RenderTest::LoadSpirv(const std::string& path) {
  const std::string full = (!path.empty() && path[0] == '/') ? path : ShaderDir() + "/" + path;
  std::vector<uint32_t> words;
  std::string error;
  if (FAILED(ReadSpirvFile(full, &words, &error))) ADD_FAILURE() << "cannot load shader: " << error;
  return words;
}

ComPtr<VertexShader> RenderTest::LoadVertexShader(const std::string& path) {
  auto code = LoadSpirv(path);
  ComPtr<VertexShader> s;
  HRESULT hr = device_->CreateVertexShader(code.data(), code.size() * 4, s.ReleaseAndGetAddressOf());
  EXPECT_EQ(hr, S_OK) << "CreateVertexShader(" << path << ")";
  return s;
}

ComPtr<PixelShader> RenderTest::LoadPixelShader(const std::string& path) {
  auto code = LoadSpirv(path);
  ComPtr<PixelShader> s;
  HRESULT hr = device_->CreatePixelShader(code.data(), code.size() * 4, s.ReleaseAndGetAddressOf());
  EXPECT_EQ(hr, S_OK) << "CreatePixelShader(" << path << ")";
  return s;
}

RenderTarget RenderTest::MakeRenderTarget(uint32_t w, uint32_t h, DXGI_FORMAT format) {
  RenderTarget rt;
  TEXTURE2D_DESC td;
  td.Width = w;
  td.Height = h;
  td.Format = format;
  td.BindFlags = BIND_RENDER_TARGET | BIND_SHADER_RESOURCE;
  EXPECT_EQ(device_->CreateTexture2D(&td, nullptr, rt.texture.ReleaseAndGetAddressOf()), S_OK);
  if (!rt.texture) return rt;
  EXPECT_EQ(device_->CreateRenderTargetView(rt.texture.Get(), nullptr, rt.rtv.ReleaseAndGetAddressOf()), S_OK);
  EXPECT_EQ(device_->CreateShaderResourceView(rt.texture.Get(), nullptr, rt.srv.ReleaseAndGetAddressOf()), S_OK);
  return rt;
}

DepthTarget RenderTest::MakeDepthTarget(uint32_t w, uint32_t h) {
  DepthTarget d;
  TEXTURE2D_DESC td;
  td.Width = w;
  td.Height = h;
  td.Format = DXGI_FORMAT_D32_FLOAT;
  td.BindFlags = BIND_DEPTH_STENCIL;
  EXPECT_EQ(device_->CreateTexture2D(&td, nullptr, d.texture.ReleaseAndGetAddressOf()), S_OK);
  if (!d.texture) return d;
  EXPECT_EQ(device_->CreateDepthStencilView(d.texture.Get(), nullptr, d.dsv.ReleaseAndGetAddressOf()), S_OK);
  return d;
}

void RenderTest::SetViewport(uint32_t w, uint32_t h) {
  VIEWPORT vp;
  vp.Width = float(w);
  vp.Height = float(h);
  context_->RSSetViewports(1, &vp);
}

Image RenderTest::ReadBack(Texture2D* texture, uint32_t mip) {
  Image img;
  std::string error;
  if (!texture) ADD_FAILURE() << "ReadBack: null texture";
  else if (!drr::ReadBack(device_.Get(), context_.Get(), texture, mip, &img, &error))
    ADD_FAILURE() << "ReadBack of mip " << mip << ": " << error;
  return img;
}

std::vector<RenderTest::LogEntry> RenderTest::Messages() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return log_;
}

size_t RenderTest::CountMessages(LogLevel level, const std::string& contains) const {
  std::lock_guard<std::mutex> lock(mutex_);
  size_t n = 0;
  for (const auto& e : log_)
    if (e.level == level && (contains.empty() || e.text.find(contains) != std::string::npos)) ++n;
  return n;
}

void RenderTest::ClearMessages() {
  std::lock_guard<std::mutex> lock(mutex_);
  log_.clear();
}

uint64_t RenderTest::ValidationMessageCount() const { return CountMessages(LogLevel::Validation); }

}  // namespace drrtest
