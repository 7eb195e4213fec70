// BC1 and BC3 textures of the Arena's DDS set (and random BC2/BC4/BC5 blocks) sampled on the device at every
// mip (one texel per pixel, unfiltered: a Load through a one-mip view) and read
// back, against the CPU decoder within 1 LSB; and the CPU fallback
// (DRR_BC_DECODE=cpu) that uploads the RGBA8 expansion instead. Under core and
// synchronization validation (drrtest::RenderTest).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

#include "RenderTest.h"
#include "scene/DdsBlocks.h"
#include "scene/DdsReader.h"
#include "scene/Scene.h"

using namespace drr;
using namespace d3dl;
namespace fs = std::filesystem;

namespace {

class DdsGpu : public drrtest::RenderTest {
 protected:
  // The texture with every mip of `tex` as initial data (rows of texels or of 4x4 blocks).
  ComPtr<Texture2D> Upload(const TextureData& tex) {
    TEXTURE2D_DESC d;
    d.Width = tex.Width(), d.Height = tex.Height(), d.MipLevels = UINT(tex.mips.size());
    d.Format = tex.format, d.Usage = USAGE_IMMUTABLE, d.BindFlags = BIND_SHADER_RESOURCE;
    std::vector<SUBRESOURCE_DATA> init(tex.mips.size());
    for (size_t i = 0; i < tex.mips.size(); ++i) {
      init[i].pSysMem = tex.mips[i].rgba.data();
      init[i].SysMemPitch = UINT(TextureRowPitch(tex.format, tex.mips[i].width));
    }
    ComPtr<Texture2D> t;
    EXPECT_EQ(device()->CreateTexture2D(&d, init.data(), t.GetAddressOf()), S_OK) << FormatName(tex.format);
    return t;
  }
  // Mip `mip` of `t` drawn texel for texel into an RGBA8 target and read back.
  Image DrawMip(Texture2D* t, uint32_t mip, uint32_t w, uint32_t h) {
    SHADER_RESOURCE_VIEW_DESC v;
    v.ViewDimension = SRV_DIMENSION_TEXTURE2D;
    v.Texture.MostDetailedMip = mip, v.Texture.MipLevels = 1;
    ComPtr<ShaderResourceView> srv;
    EXPECT_EQ(device()->CreateShaderResourceView(t, &v, srv.GetAddressOf()), S_OK);
    RenderTarget rt = MakeRenderTarget(w, h);
    auto vs = LoadVertexShader("rhi_fullscreen_vs.spv");
    auto ps = LoadPixelShader("rhi_fmt_load_ps.spv");
    RenderTargetView* rtv = rt.rtv.Get();
    context()->OMSetRenderTargets(1, &rtv, nullptr);
    SetViewport(w, h);
    context()->IASetInputLayout(nullptr);
    context()->IASetPrimitiveTopology(PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    context()->VSSetShader(vs.Get());
    context()->PSSetShader(ps.Get());
    ShaderResourceView* s = srv.Get();
    context()->PSSetShaderResources(0, 1, &s);
    context()->Draw(3, 0);
    ShaderResourceView* none = nullptr;
    context()->PSSetShaderResources(0, 1, &none);
    return ReadBack(rt.texture.Get());
  }
  // Every mip of `file` on the GPU against `expected` (RGBA8 per mip): largest channel difference.
  int LargestDifference(const TextureData& uploaded, const std::vector<std::vector<uint8_t>>& expected) {
    auto t = Upload(uploaded);
    int worst = 0;
    for (uint32_t m = 0; m < uploaded.mips.size(); ++m) {
      const uint32_t w = uploaded.mips[m].width, h = uploaded.mips[m].height;
      Image img = DrawMip(t.Get(), m, w, h);
      for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
          for (int c = 0; c < 4; ++c) {
            const int got = img.RGBA8(x, y)[c], want = expected[m][(size_t(y) * w + x) * 4 + c];
            worst = std::max(worst, std::abs(got - want));
            if (std::abs(got - want) > 1)
              ADD_FAILURE() << "mip " << m << " (" << x << "," << y << ") channel " << c << ": GPU " << got
                            << ", CPU " << want;
          }
    }
    return worst;
  }
};

TextureData LoadArena(const char* name) {
  TextureData t;
  std::string err;
  // Specular: the file's UNORM format, so that the read-back holds the stored values.
  EXPECT_TRUE(LoadTextureFile((fs::path(DRR_ARENA_DIR) / "dds" / name).string(), TextureKind::Specular, {}, &t, &err))
      << err;
  return t;
}

std::vector<std::vector<uint8_t>> CpuDecoded(const TextureData& t) {
  std::vector<std::vector<uint8_t>> mips;
  for (const auto& m : t.mips) {
    mips.emplace_back();
    EXPECT_TRUE(DecodeBcMip(t.format, m.rgba.data(), m.width, m.height, &mips.back()));
  }
  return mips;
}

}  // namespace

TEST_F(DdsGpu, Bc1AndBc3MatchTheCpuDecoderAtEveryMip) {
  for (const char* name : {"bc1_mips.dds", "bc3_mips.dds", "bc1_dx10.dds"}) {
    SCOPED_TRACE(name);
    const TextureData t = LoadArena(name);
    ASSERT_FALSE(t.mips.empty());
    ASSERT_TRUE(device()->CheckFormatSupport(t.format, BIND_SHADER_RESOURCE)) << "lavapipe samples BC formats";
    EXPECT_LE(LargestDifference(t, CpuDecoded(t)), 1);
  }
}

// BC2, BC4 and BC5 (UNORM) are not in the Arena's set: random blocks (every
// bit pattern is a valid block, both BC1 colour modes and both alpha modes
// occur) with a full chain from 16x16.
TEST_F(DdsGpu, RandomBc2Bc4Bc5BlocksMatchTheCpuDecoder) {
  std::mt19937 rng(11);
  for (DXGI_FORMAT f : {DXGI_FORMAT_BC2_UNORM, DXGI_FORMAT_BC4_UNORM, DXGI_FORMAT_BC5_UNORM}) {
    SCOPED_TRACE(FormatName(f));
    TextureData t;
    t.format = f;
    for (uint32_t side = 16; side >= 1; side /= 2) {
      TextureMip m;
      m.width = m.height = side;
      m.rgba.resize(TextureMipBytes(f, side, side));
      for (auto& b : m.rgba) b = uint8_t(rng());
      t.mips.push_back(std::move(m));
    }
    ASSERT_TRUE(device()->CheckFormatSupport(f, BIND_SHADER_RESOURCE));
    EXPECT_LE(LargestDifference(t, CpuDecoded(t)), 1);
  }
}

TEST_F(DdsGpu, ForcedCpuFallbackUploadsTheRgba8Expansion) {
  setenv("DRR_BC_DECODE", "cpu", 1);
  const auto bc = std::make_shared<const TextureData>(LoadArena("bc3_mips.dds"));
  std::string err;
  const auto expanded = TextureForDevice(bc, true, &err);
  unsetenv("DRR_BC_DECODE");
  ASSERT_TRUE(expanded) << err;
  EXPECT_EQ(expanded->format, DXGI_FORMAT_R8G8B8A8_UNORM);
  ASSERT_EQ(expanded->mips.size(), bc->mips.size());
  EXPECT_EQ(LargestDifference(*expanded, CpuDecoded(*bc)), 0);
}

// A scene whose material names a BC1 DDS diffuse map: the texture stays
// compressed on the GPU (the report's texture_bytes against
// texture_bytes_as_rgba8), and DRR_BC_DECODE=cpu uploads the RGBA8 expansion.
TEST_F(DdsGpu, SceneKeepsBc1CompressedUnlessTheFallbackIsForced) {
  const fs::path dir = fs::temp_directory_path() / ("drr_dds_scene_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::copy_file(fs::path(DRR_ARENA_DIR) / "dds" / "bc1_mips.dds", dir / "bc1_mips.dds",
                fs::copy_options::overwrite_existing);
  std::ofstream(dir / "quad.mtl") << "newmtl M\nKd 1 1 1\nmap_Kd bc1_mips.dds\n";
  std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                                     "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl M\nf 1/1/1 2/2/1 3/3/1 4/4/1\n";
  const uint64_t bc1Bytes = 1024 + 256 + 64 + 16 + 8 + 8 + 8, rgba8Bytes = 4 * (2048 + 512 + 128 + 32 + 8 + 2 + 1);
  for (bool forced : {false, true}) {
    SCOPED_TRACE(forced ? "DRR_BC_DECODE=cpu" : "BC on the GPU");
    if (forced) setenv("DRR_BC_DECODE", "cpu", 1);
    std::string err;
    auto scene = Scene::Load(device(), (dir / "quad.obj").string(), {}, &err);
    unsetenv("DRR_BC_DECODE");
    ASSERT_TRUE(scene) << err;
    const SceneStats st = scene->Stats();
    EXPECT_EQ(st.textureBytesAsRgba8 - st.textureBytes, forced ? 0 : rgba8Bytes - bc1Bytes);
    EXPECT_GE(st.textureBytesAsRgba8, rgba8Bytes);
  }
  fs::remove_all(dir);
}
