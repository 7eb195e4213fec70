// Helpers of the sample: Utility::RenderTarget (texture + RTV + SRV (+ DSV)),
// SPIR-V loading and image files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "d3dl/D3DLike.h"

namespace drr::Utility {

struct RenderTarget {
  d3dl::ComPtr<d3dl::Texture2D> texture;
  d3dl::ComPtr<d3dl::RenderTargetView> rtv;
  d3dl::ComPtr<d3dl::ShaderResourceView> srv;
  d3dl::ComPtr<d3dl::DepthStencilView> dsv;
  uint32_t width = 0, height = 0;
  d3dl::DXGI_FORMAT format = d3dl::DXGI_FORMAT_UNKNOWN;

  // Colour formats get an RTV and an SRV; D32_FLOAT gets a DSV only.
  d3dl::HRESULT Create(d3dl::Device* device, uint32_t w, uint32_t h, d3dl::DXGI_FORMAT fmt,
                       const char* name);
  void Release();
  bool Valid() const { return texture.Get() != nullptr; }
  uint64_t Bytes() const {
    return Valid() ? uint64_t(width) * height * d3dl::FormatBytesPerElement(format) : 0;
  }
};

bool ReadFile(const std::string& path, std::vector<uint32_t>* words, std::string* error);

// Writes 8-bit RGBA (or linear float RGBA for .exr/.hdr) through ImageFile.h.
bool SaveImageRGBA8(const std::string& path, uint32_t w, uint32_t h, const uint8_t* rgba,
                    std::string* error);
bool LoadImageRGBA8(const std::string& path, uint32_t* w, uint32_t* h, std::vector<uint8_t>* rgba,
                    std::string* error);

// Loads <dir>/<name>.spv and creates the shader.
d3dl::HRESULT LoadVertexShader(d3dl::Device* device, const std::string& dir, const std::string& name,
                               d3dl::VertexShader** vs, std::vector<uint32_t>* bytecode,
                               std::string* error);
d3dl::HRESULT LoadPixelShader(d3dl::Device* device, const std::string& dir, const std::string& name,
                              d3dl::PixelShader** ps, std::string* error);

}  // namespace drr::Utility
