#include "Utility.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "imageio/ImageFile.h"
#include "imageio/Srgb.h"

namespace drr::Utility {

d3dl::HRESULT RenderTarget::Create(d3dl::Device* device, uint32_t w, uint32_t h,
                                   d3dl::DXGI_FORMAT fmt, const char* name) {
  Release();
  const bool depth = fmt == d3dl::DXGI_FORMAT_D32_FLOAT;
  d3dl::TEXTURE2D_DESC d;
  d.Width = w;
  d.Height = h;
  d.MipLevels = 1;
  d.Format = fmt;
  d.BindFlags = depth ? d3dl::BIND_DEPTH_STENCIL
                      : (d3dl::BIND_RENDER_TARGET | d3dl::BIND_SHADER_RESOURCE);
  d3dl::HRESULT hr = device->CreateTexture2D(&d, nullptr, texture.ReleaseAndGetAddressOf());
  if (d3dl::FAILED(hr)) return hr;
  texture->SetDebugName(name);
  if (depth) {
    hr = device->CreateDepthStencilView(texture.Get(), nullptr, dsv.ReleaseAndGetAddressOf());
  } else {
    hr = device->CreateRenderTargetView(texture.Get(), nullptr, rtv.ReleaseAndGetAddressOf());
    if (d3dl::SUCCEEDED(hr))
      hr = device->CreateShaderResourceView(texture.Get(), nullptr, srv.ReleaseAndGetAddressOf());
  }
  if (d3dl::FAILED(hr)) {
    Release();
    return hr;
  }
  width = w;
  height = h;
  format = fmt;
  return d3dl::S_OK;
}

void RenderTarget::Release() {
  dsv = nullptr;
  srv = nullptr;
  rtv = nullptr;
  texture = nullptr;
  width = height = 0;
  format = d3dl::DXGI_FORMAT_UNKNOWN;
}

bool ReadFile(const std::string& path, std::vector<uint32_t>* words, std::string* error) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) {
    if (error) *error = "cannot open " + path;
    return false;
  }
  const std::streamsize size = f.tellg();
  if (size <= 0 || size % 4 != 0) {
    if (error) *error = path + ": not a SPIR-V file (size " + std::to_string(size) + ")";
    return false;
  }
  words->resize(size_t(size) / 4);
  f.seekg(0);
  f.read(reinterpret_cast<char*>(words->data()), size);
  return bool(f);
}

bool SaveImageRGBA8(const std::string& path, uint32_t w, uint32_t h, const uint8_t* rgba,
                    std::string* error) {
  std::string ext = path.substr(path.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext != "exr" && ext != "hdr") return WriteImageFile(path, w, h, 4, rgba, error);
  // The back buffer holds sRGB-encoded values; EXR/HDR store linear light.
  std::vector<float> f(size_t(w) * h * 4);
  for (size_t i = 0; i < f.size(); ++i) {
    const float c = rgba[i] / 255.0f;
    f[i] = (i % 4 == 3) ? c : SrgbToLinear(c);
  }
  return WriteImageFileFloat(path, w, h, 4, f.data(), error);
}

bool LoadImageRGBA8(const std::string& path, uint32_t* w, uint32_t* h, std::vector<uint8_t>* rgba,
                    std::string* error) {
  ImageFileData img;
  if (!ReadImageFile(path, &img, error)) return false;
  if (img.isFloat) {
    if (error) *error = path + ": expected an 8-bit image";
    return false;
  }
  *w = img.width;
  *h = img.height;
  rgba->assign(size_t(*w) * *h * 4, 255);
  for (size_t p = 0; p < size_t(*w) * *h; ++p)
    for (uint32_t c = 0; c < img.channels; ++c) (*rgba)[p * 4 + c] = img.u8[p * img.channels + c];
  return true;
}

d3dl::HRESULT LoadVertexShader(d3dl::Device* device, const std::string& dir, const std::string& name,
                               d3dl::VertexShader** vs, std::vector<uint32_t>* bytecode,
                               std::string* error) {
  std::vector<uint32_t> words;
  if (!ReadFile(dir + "/" + name + ".spv", &words, error)) return d3dl::E_FAIL;
  d3dl::HRESULT hr = device->CreateVertexShader(words.data(), words.size() * 4, vs);
  if (d3dl::FAILED(hr) && error) *error = "CreateVertexShader(" + name + ") failed";
  if (bytecode) *bytecode = std::move(words);
  return hr;
}

d3dl::HRESULT LoadPixelShader(d3dl::Device* device, const std::string& dir, const std::string& name,
                              d3dl::PixelShader** ps, std::string* error) {
  std::vector<uint32_t> words;
  if (!ReadFile(dir + "/" + name + ".spv", &words, error)) return d3dl::E_FAIL;
  d3dl::HRESULT hr = device->CreatePixelShader(words.data(), words.size() * 4, ps);
  if (d3dl::FAILED(hr) && error) *error = "CreatePixelShader(" + name + ") failed";
  return hr;
}

}  // namespace drr::Utility
