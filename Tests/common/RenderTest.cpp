#include "RenderTest.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

using namespace d3dl;

namespace drrtest {
namespace {
float HalfToFloat(uint16_t h) {
  uint32_t s = (h >> 15) & 1, e = (h >> 10) & 0x1f, m = h & 0x3ff;
  float v;
  if (e == 0) v = std::ldexp(float(m), -24);
  else if (e == 31) v = m ? NAN : INFINITY;
  else v = std::ldexp(float(m | 0x400), int(e) - 25);
  return s ? -v : v;
}
}  // namespace

std::array<uint8_t, 4> Image::RGBA8(uint32_t x, uint32_t y) const {
  const uint8_t* p = At(x, y);
  if (format == DXGI_FORMAT_B8G8R8A8_UNORM || format == DXGI_FORMAT_B8G8R8A8_UNORM_SRGB) return {p[2], p[1], p[0], p[3]};
  return {p[0], p[1], p[2], p[3]};
}

float Image::Float(uint32_t x, uint32_t y, uint32_t c) const {
  const uint8_t* p = At(x, y);
  switch (format) {
    case DXGI_FORMAT_R32_FLOAT:
    case DXGI_FORMAT_R32G32_FLOAT:
    case DXGI_FORMAT_R32G32B32A32_FLOAT:
    case DXGI_FORMAT_D32_FLOAT:
    case DXGI_FORMAT_R32_TYPELESS: {
      float f;
      std::memcpy(&f, p + 4 * c, 4);
      return f;
    }
    case DXGI_FORMAT_R16_FLOAT:
    case DXGI_FORMAT_R16G16_FLOAT:
    case DXGI_FORMAT_R16G16B16A16_FLOAT: {
      uint16_t h;
      std::memcpy(&h, p + 2 * c, 2);
      return HalfToFloat(h);
    }
    default:
      return RGBA8(x, y)[c] / 255.0f;
  }
}

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
  std::string full = (!path.empty() && path[0] == '/') ? path : ShaderDir() + "/" + path;
  std::ifstream in(full, std::ios::binary | std::ios::ate);
  if (!in) {
    ADD_FAILURE() << "cannot open shader " << full;
    return {};
  }
  size_t size = static_cast<size_t>(in.tellg());
  std::vector<uint32_t> words(size / 4);
  in.seekg(0);
  in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
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

void RenderTest::SetViewport(uint32_t w, uint32_t h) {
  VIEWPORT vp;
  vp.Width = float(w);
  vp.Height = float(h);
  context_->RSSetViewports(1, &vp);
}

Image RenderTest::ReadBack(Texture2D* texture, uint32_t mip) {
  Image img;
  if (!texture) {
    ADD_FAILURE() << "ReadBack: null texture";
    return img;
  }
  TEXTURE2D_DESC d;
  texture->GetDesc(&d);
  if (mip >= d.MipLevels) {
    ADD_FAILURE() << "ReadBack: mip " << mip << " out of range";
    return img;
  }
  TEXTURE2D_DESC sd;
  sd.Width = std::max(1u, d.Width >> mip);
  sd.Height = std::max(1u, d.Height >> mip);
  sd.Format = d.Format;
  sd.Usage = USAGE_STAGING;
  sd.CPUAccessFlags = CPU_ACCESS_READ;
  ComPtr<Texture2D> staging;
  HRESULT hr = device_->CreateTexture2D(&sd, nullptr, staging.ReleaseAndGetAddressOf());
  if (hr != S_OK) {
    ADD_FAILURE() << "ReadBack: staging texture: " << HResultName(hr);
    return img;
  }
  context_->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, texture, CalcSubresource(mip, 0, d.MipLevels), nullptr);
  MAPPED_SUBRESOURCE m;
  hr = context_->Map(staging.Get(), 0, MAP_READ, 0, &m);
  if (hr != S_OK) {
    ADD_FAILURE() << "ReadBack: Map: " << HResultName(hr);
    return img;
  }
  img.width = sd.Width;
  img.height = sd.Height;
  img.format = d.Format == DXGI_FORMAT_R32_TYPELESS ? DXGI_FORMAT_R32_FLOAT : d.Format;
  const uint32_t row = img.width * FormatBytesPerElement(img.format);
  img.data.resize(size_t(row) * img.height);
  for (uint32_t y = 0; y < img.height; ++y)
    std::memcpy(img.data.data() + size_t(y) * row, static_cast<const uint8_t*>(m.pData) + size_t(y) * m.RowPitch, row);
  context_->Unmap(staging.Get(), 0);
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
