// DynamicResolution: the dynamic viewport inside an oversized render target.
//
// Port of the sample's class of the same name (same public methods, same
// results for every valid input), written from the behaviour of the original's
// DynamicResolution.cpp. No graphics API is needed: the viewport
// is returned as a plain struct that the application copies field by field into
// d3dl::VIEWPORT.
//
// Deviations from the original (each one only changes results for inputs the
// original mishandles; see Docs/Controller.md, "DynamicResolution"):
//  D1  m_ScaleX/Y start at 1.0 (the original left them uninitialised but read
//      them in InitializeResolutionParameters).
//  D2  SetScale has a lower bound: the integral viewport is at least 1 pixel per
//      axis (scale 0, negative, 1e-7 ... give a 1-pixel viewport). Status bit
//      ClampedLow reports it.
//  D3  SetScale rejects NaN and +/-Inf per axis: that axis keeps its previous
//      value; status bit RejectedNonFinite and the optional log hook report it.
//  D4  A back buffer larger than the maximum render target (maxW / bbW == 0 in
//      integer division) gets a dynamic RT of exactly the maximum size and a
//      maximum scaling of max / bb < 1 (the original made an RT of bb size,
//      larger than the stated maximum).
//  D5  A zero-size back buffer (minimised window) or a zero-size maximum RT puts
//      the object in a defined "invalid" state: IsValid() == false, dynamic RT
//      1x1, viewport (0,0,1,1), GetRTScale == 1, maximum scaling 1. GetScale
//      keeps returning the last requested scale, and SetScale (sanitised as in
//      D2/D3) only records it; the next valid InitializeResolutionParameters
//      applies it, as the original re-applies m_Scale.
//  D6  maxScaling that is NaN, infinite or below 1 is treated as 1 (status bit
//      BadMaxScaling, log hook). The dynamic RT width is
//      floor(min(k, maxScaling) * bbW), which equals the original for the
//      integral maxScaling values the sample uses (1 and 2).
//  D7  The integral viewport is clamped to [1, dynamic RT size] before it is
//      converted to an integer, so no float-to-integer overflow can occur (a
//      scale of 1e9 is clamped to the maximum scaling first, as in the
//      original).
//  D8  SetScale(GetScaleX(), GetScaleY()) keeps the current viewport. In float
//      arithmetic floor(dyn * (w * m / dyn) / m) is w - 1 for about 3.8 % of the
//      (dyn, w) pairs up to 16384 (for example dyn 22, w 13), so a caller that
//      hands the current scale back would lose a pixel. The original's own calls
//      never do (InitializeResolutionParameters re-applies it with the original's
//      arithmetic); the port's laws and GUI do. Every other scale is computed
//      exactly as in the original.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>

// Plain viewport, field-compatible with d3dl::VIEWPORT / D3D11_VIEWPORT.
struct DynamicViewport {
  float TopLeftX = 0.0f;
  float TopLeftY = 0.0f;
  float Width = 1.0f;
  float Height = 1.0f;
  float MinDepth = 0.0f;
  float MaxDepth = 1.0f;
};

// Bit set returned by SetScale / InitializeResolutionParameters.
enum class ScaleStatus : std::uint32_t {
  Ok = 0,
  ClampedHigh = 1u << 0,        // a scale was above the maximum scaling and was clamped (as in the original)
  ClampedLow = 1u << 1,         // a scale gave less than one pixel and was raised to one pixel (D2)
  RejectedNonFinite = 1u << 2,  // a scale was NaN/Inf; that axis kept its previous value (D3)
  InvalidBackBuffer = 1u << 3,  // zero-size back buffer or max RT: invalid state (D5)
  BadMaxScaling = 1u << 4,      // maxScaling NaN/Inf/<1, treated as 1 (D6)
  RenderTargetClamped = 1u << 5 // back buffer larger than the max RT on some axis (D4)
};
constexpr ScaleStatus operator|(ScaleStatus a, ScaleStatus b) {
  return static_cast<ScaleStatus>(static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b));
}
constexpr ScaleStatus operator&(ScaleStatus a, ScaleStatus b) {
  return static_cast<ScaleStatus>(static_cast<std::uint32_t>(a) & static_cast<std::uint32_t>(b));
}
constexpr ScaleStatus& operator|=(ScaleStatus& a, ScaleStatus b) { return a = a | b; }
constexpr bool Any(ScaleStatus s) { return s != ScaleStatus::Ok; }
constexpr bool Has(ScaleStatus s, ScaleStatus bit) { return Any(s & bit); }

class DynamicResolution {
public:
  // Receives one line of text for every rejected or corrected input.
  using LogHook = std::function<void(std::string_view message)>;

  DynamicResolution() = default;

  // Per axis: k = maxW / bbW (integer division); dynamic RT = min(k, maxScaling) * bbW
  // when k > 1, else bbW (D4: else min(bbW, maxW)); maximum scaling = dyn / bb.
  // Then re-applies the current scale. Returns the status of that SetScale plus
  // InvalidBackBuffer / BadMaxScaling / RenderTargetClamped.
  ScaleStatus InitializeResolutionParameters(unsigned int backBufferWidth, unsigned int backBufferHeight,
                                             unsigned int maxWidth, unsigned int maxHeight,
                                             float maxScaling);

  // Scale per axis relative to the back buffer (1 = back-buffer size, 2 = twice).
  // Clamped from above to the maximum scaling; the viewport is
  // floor(dyn * s / maxScaling) (at least 1 px, D2) and the stored scale is
  // recomputed from that integral viewport.
  ScaleStatus SetScale(float scaleX, float scaleY);

  float GetScaleX() const { return m_ScaleX; }
  float GetScaleY() const { return m_ScaleY; }
  // Fraction of the dynamic RT in use = scale / maxScaling (what shaders get).
  float GetRTScaleX() const;
  float GetRTScaleY() const;
  float GetMaxScalingX() const { return m_MaxScalingX; }
  float GetMaxScalingY() const { return m_MaxScalingY; }
  unsigned int GetDynamicBufferWidth() const { return m_DynamicRTWidth; }
  unsigned int GetDynamicBufferHeight() const { return m_DynamicRTHeight; }
  unsigned int GetBackBufferWidth() const { return m_BackBufferWidth; }
  unsigned int GetBackBufferHeight() const { return m_BackBufferHeight; }
  // Integral viewport size in pixels (always >= 1).
  unsigned int GetViewportWidth() const { return m_CurrentWidth; }
  unsigned int GetViewportHeight() const { return m_CurrentHeight; }

  // (0, 0, currW, currH), depth 0..1.
  DynamicViewport GetViewport() const;
  void GetViewport(DynamicViewport* viewport) const;

  // False after a zero-size back buffer / max RT (D5) until the next valid init.
  bool IsValid() const { return m_Valid; }
  ScaleStatus GetLastStatus() const { return m_LastStatus; }

  void SetLogHook(LogHook hook) { m_Log = std::move(hook); }

private:
  ScaleStatus ApplyScale(float scaleX, float scaleY, bool force);
  void Log(std::string_view message) const;

  unsigned int m_BackBufferWidth = 0;
  unsigned int m_BackBufferHeight = 0;
  unsigned int m_MaxWidth = 0;
  unsigned int m_MaxHeight = 0;
  unsigned int m_DynamicRTWidth = 1;
  unsigned int m_DynamicRTHeight = 1;
  unsigned int m_CurrentWidth = 1;
  unsigned int m_CurrentHeight = 1;
  float m_ScaleX = 1.0f;  // D1
  float m_ScaleY = 1.0f;  // D1
  float m_MaxScalingX = 1.0f;
  float m_MaxScalingY = 1.0f;
  float m_RequestedMaxScaling = 1.0f;
  bool m_Valid = false;
  ScaleStatus m_LastStatus = ScaleStatus::InvalidBackBuffer;
  LogHook m_Log;
};
