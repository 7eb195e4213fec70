// The fixed-function blit row of --bench: the scale pass done by a linear
// vkCmdBlitImage instead of a pixel shader, timed with its own queries.
#pragma once

#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "DynamicResolutionRendering.h"
#include "Readback.h"
#include "d3dl/BlitExtension.h"

namespace drr {

// The fixed-function blit of the scale pass: BlitExtension::BlitRegion (a linear
// vkCmdBlitImage) of the viewport region of a dynamic-RT-sized texture holding
// the captured scene colour to a back-buffer-sized target, timed with its own
// timestamp queries on the sample's device (outside the sample's frames).
class FixedFunctionBlit {
 public:
  explicit FixedFunctionBlit(d3dl::Device* device) : device_(device) {
    device_->GetImmediateContext(ctx_.GetAddressOf());
    blit_ = d3dl::GetBlitExtension(ctx_.Get());  // null: a context without the Vulkan blit
    d3dl::QUERY_DESC d;
    d.Query = d3dl::QUERY_TIMESTAMP_DISJOINT;
    ok_ = blit_ && d3dl::SUCCEEDED(device_->CreateQuery(&d, disjoint_.GetAddressOf()));
    d.Query = d3dl::QUERY_TIMESTAMP;
    ok_ = ok_ && d3dl::SUCCEEDED(device_->CreateQuery(&d, begin_.GetAddressOf())) &&
          d3dl::SUCCEEDED(device_->CreateQuery(&d, end_.GetAddressOf()));
  }

  // Times `frames` blits of (0,0,vpW,vpH) of `scene` (the whole dynamic RT in
  // its own format: UNORM holds linear values, UNORM_SRGB encoded ones) to a
  // bbW x bbH sRGB target, as the scale pass writes the sRGB back buffer;
  // returns the times and the last image.
  bool Run(const Image& scene, uint32_t vpW, uint32_t vpH, uint32_t bbW, uint32_t bbH, int frames,
           std::vector<double>* ms, Image* image, std::string* error) {
    const bool rgba8 = scene.format == d3dl::DXGI_FORMAT_R8G8B8A8_UNORM ||
                       scene.format == d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
    if (!ok_ || scene.Empty() || !rgba8 || vpW == 0 || vpH == 0 || vpW > scene.width || vpH > scene.height) {
      *error = "fixed-function blit: no queries or no scene colour";
      return false;
    }
    d3dl::TEXTURE2D_DESC d;
    d.Width = scene.width;
    d.Height = scene.height;
    d.Format = scene.format;
    d.BindFlags = d3dl::BIND_SHADER_RESOURCE | d3dl::BIND_RENDER_TARGET;
    d3dl::SUBRESOURCE_DATA init{scene.pixels.data(), scene.width * 4, 0};
    d3dl::ComPtr<d3dl::Texture2D> src, dst;
    if (d3dl::FAILED(device_->CreateTexture2D(&d, &init, src.GetAddressOf()))) {
      *error = "fixed-function blit: cannot create the source texture";
      return false;
    }
    d.Width = bbW;
    d.Height = bbH;
    d.Format = d3dl::DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
    if (d3dl::FAILED(device_->CreateTexture2D(&d, nullptr, dst.GetAddressOf()))) {
      *error = "fixed-function blit: cannot create the destination texture";
      return false;
    }
    const d3dl::RECT srcRect{0, 0, int32_t(vpW), int32_t(vpH)};
    const d3dl::RECT dstRect{0, 0, int32_t(bbW), int32_t(bbH)};
    for (int i = 0; i < frames + 1; ++i) {  // the first one warms up
      ctx_->Begin(disjoint_.Get());
      ctx_->End(begin_.Get());
      blit_->BlitRegion(dst.Get(), dstRect, src.Get(), srcRect, d3dl::FILTER_MIN_MAG_MIP_LINEAR);
      ctx_->End(end_.Get());
      ctx_->End(disjoint_.Get());
      ctx_->Flush();
      d3dl::QUERY_DATA_TIMESTAMP_DISJOINT dj{};
      uint64_t t0 = 0, t1 = 0;
      if (!Wait(disjoint_.Get(), &dj, sizeof(dj)) || !Wait(begin_.Get(), &t0, sizeof(t0)) ||
          !Wait(end_.Get(), &t1, sizeof(t1))) {
        *error = "fixed-function blit: the timestamp queries did not complete";
        return false;
      }
      if (i > 0) {
        ms->push_back(!dj.Disjoint && dj.Frequency > 0 && t1 >= t0
                          ? double(t1 - t0) * 1000.0 / double(dj.Frequency)
                          : std::nan(""));
      }
    }
    std::string readError;
    if (!ReadBack(device_, ctx_.Get(), dst.Get(), 0, image, &readError)) {
      *error = "fixed-function blit: cannot read the image back: " + readError;
      return false;
    }
    return true;
  }

 private:
  bool Wait(d3dl::Query* q, void* data, uint32_t size) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    for (;;) {
      const d3dl::HRESULT hr = ctx_->GetData(q, data, size, 0);
      if (hr == d3dl::S_OK) return true;
      if (d3dl::FAILED(hr) || std::chrono::steady_clock::now() > until) return false;
      std::this_thread::yield();
    }
  }
  d3dl::BlitExtension* blit_ = nullptr;
  d3dl::Device* device_;
  d3dl::ComPtr<d3dl::DeviceContext> ctx_;
  d3dl::ComPtr<d3dl::Query> disjoint_, begin_, end_;
  bool ok_ = false;
};

}  // namespace drr
