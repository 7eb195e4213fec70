// See DynamicResolution.h for the contract and the list of deviations (D1..D8)
// from the original sample.
#include "DynamicResolution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

// Smallest scale remembered while the object is invalid (D5); it becomes a
// 1-pixel viewport once a valid back buffer arrives.
constexpr float kMinPendingScale = 1.0f / 65536.0f;

struct AxisSetup {
  unsigned int dynamicSize = 1;
  float maxScaling = 1.0f;
  bool renderTargetClamped = false;
};

// Original: k = maxRT / bb (integer division); dyn = min(k, maxScaling) * bb
// when k > 1, else bb. D4: when k == 0 (bb > maxRT) dyn = maxRT.
AxisSetup SetupAxis(unsigned int backBuffer, unsigned int maxRT, float maxScaling) {
  AxisSetup a;
  const unsigned int k = maxRT / backBuffer;
  if (k > 1) {
    const double factor = std::min(static_cast<double>(k), static_cast<double>(maxScaling));
    // factor <= k, so factor * bb <= maxRT: no overflow.
    a.dynamicSize = static_cast<unsigned int>(std::floor(factor * static_cast<double>(backBuffer)));
  } else if (k == 1) {
    a.dynamicSize = backBuffer;
  } else {
    a.dynamicSize = maxRT;  // D4
    a.renderTargetClamped = true;
  }
  a.maxScaling = static_cast<float>(a.dynamicSize) / static_cast<float>(backBuffer);
  return a;
}

struct AxisResult {
  unsigned int current;
  float scale;
  ScaleStatus status;
};

// One axis of SetScale for a valid state. `previous` is the stored scale.
AxisResult ApplyAxis(float requested, float previous, unsigned int previousCurrent, unsigned int dyn,
                     float maxScaling, bool force) {
  ScaleStatus status = ScaleStatus::Ok;
  if (!std::isfinite(requested)) {  // D3: keep the previous value
    status |= ScaleStatus::RejectedNonFinite;
    if (!force) return {previousCurrent, previous, status};
    requested = previous;
  }
  if (!force && requested == previous) {  // D8: re-submitting the current scale is a no-op
    return {previousCurrent, previous, status};
  }
  float s = requested;
  if (s > maxScaling) {  // as the original: clamp from above only
    s = maxScaling;
    status |= ScaleStatus::ClampedHigh;
  }
  // Original arithmetic, in float: floor(dyn * s / maxScaling).
  float w = std::floor(static_cast<float>(dyn) * s / maxScaling);
  if (!(w >= 1.0f)) {  // D2 (also catches a negative product)
    w = 1.0f;
    status |= ScaleStatus::ClampedLow;
  }
  if (w > static_cast<float>(dyn)) w = static_cast<float>(dyn);  // D7: never above the RT
  const unsigned int current = static_cast<unsigned int>(w);
  // Original: the stored scale is recomputed from the integral viewport.
  const float scale = static_cast<float>(current) * maxScaling / static_cast<float>(dyn);
  return {current, scale, status};
}

// D5: while invalid only the (sanitised) request is remembered.
float SanitisePending(float requested, float previous, float maxScaling, ScaleStatus& status) {
  if (!std::isfinite(requested)) {
    status |= ScaleStatus::RejectedNonFinite;
    return previous;
  }
  if (requested > maxScaling) {
    status |= ScaleStatus::ClampedHigh;
    return maxScaling;
  }
  if (!(requested >= kMinPendingScale)) {
    status |= ScaleStatus::ClampedLow;
    return kMinPendingScale;
  }
  return requested;
}

}  // namespace

void DynamicResolution::Log(std::string_view message) const {
  if (m_Log) m_Log(message);
}

ScaleStatus DynamicResolution::InitializeResolutionParameters(unsigned int backBufferWidth,
                                                              unsigned int backBufferHeight,
                                                              unsigned int maxWidth, unsigned int maxHeight,
                                                              float maxScaling) {
  ScaleStatus status = ScaleStatus::Ok;
  if (!std::isfinite(maxScaling) || maxScaling < 1.0f) {  // D6
    char text[128];
    std::snprintf(text, sizeof text, "DynamicResolution: maxScaling %g is not a finite value >= 1; using 1",
                  static_cast<double>(maxScaling));
    Log(text);
    status |= ScaleStatus::BadMaxScaling;
    maxScaling = 1.0f;
  }
  m_BackBufferWidth = backBufferWidth;
  m_BackBufferHeight = backBufferHeight;
  m_MaxWidth = maxWidth;
  m_MaxHeight = maxHeight;
  m_RequestedMaxScaling = maxScaling;

  if (backBufferWidth == 0 || backBufferHeight == 0 || maxWidth == 0 || maxHeight == 0) {  // D5
    char text[160];
    std::snprintf(text, sizeof text,
                  "DynamicResolution: back buffer %ux%u / max RT %ux%u has a zero size; invalid until the next "
                  "initialisation",
                  backBufferWidth, backBufferHeight, maxWidth, maxHeight);
    Log(text);
    m_Valid = false;
    m_DynamicRTWidth = m_DynamicRTHeight = 1;
    m_CurrentWidth = m_CurrentHeight = 1;
    m_MaxScalingX = m_MaxScalingY = 1.0f;
    ScaleStatus dummy = ScaleStatus::Ok;
    m_ScaleX = SanitisePending(m_ScaleX, 1.0f, maxScaling, dummy);
    m_ScaleY = SanitisePending(m_ScaleY, 1.0f, maxScaling, dummy);
    m_LastStatus = status | ScaleStatus::InvalidBackBuffer;
    return m_LastStatus;
  }

  const AxisSetup x = SetupAxis(backBufferWidth, maxWidth, maxScaling);
  const AxisSetup y = SetupAxis(backBufferHeight, maxHeight, maxScaling);
  if (x.renderTargetClamped || y.renderTargetClamped) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "DynamicResolution: back buffer %ux%u exceeds the max RT %ux%u; dynamic RT clamped to %ux%u",
                  backBufferWidth, backBufferHeight, maxWidth, maxHeight, x.dynamicSize, y.dynamicSize);
    Log(text);
    status |= ScaleStatus::RenderTargetClamped;
  }
  m_DynamicRTWidth = x.dynamicSize;
  m_DynamicRTHeight = y.dynamicSize;
  m_MaxScalingX = x.maxScaling;
  m_MaxScalingY = y.maxScaling;
  m_Valid = true;
  // As the original: re-apply the current scale to the new sizes.
  status |= ApplyScale(m_ScaleX, m_ScaleY, /*force=*/true);
  m_LastStatus = status;
  return status;
}

ScaleStatus DynamicResolution::SetScale(float scaleX, float scaleY) {
  m_LastStatus = ApplyScale(scaleX, scaleY, /*force=*/false);
  return m_LastStatus;
}

ScaleStatus DynamicResolution::ApplyScale(float scaleX, float scaleY, bool force) {
  ScaleStatus status = ScaleStatus::Ok;
  if (!m_Valid) {
    status |= ScaleStatus::InvalidBackBuffer;
    m_ScaleX = SanitisePending(scaleX, m_ScaleX, m_RequestedMaxScaling, status);
    m_ScaleY = SanitisePending(scaleY, m_ScaleY, m_RequestedMaxScaling, status);
  } else {
    const AxisResult x = ApplyAxis(scaleX, m_ScaleX, m_CurrentWidth, m_DynamicRTWidth, m_MaxScalingX, force);
    const AxisResult y = ApplyAxis(scaleY, m_ScaleY, m_CurrentHeight, m_DynamicRTHeight, m_MaxScalingY, force);
    m_CurrentWidth = x.current;
    m_CurrentHeight = y.current;
    m_ScaleX = x.scale;
    m_ScaleY = y.scale;
    status |= x.status | y.status;
  }
  if (Has(status, ScaleStatus::RejectedNonFinite)) {
    char text[128];
    std::snprintf(text, sizeof text, "DynamicResolution: non-finite scale (%g, %g) rejected; keeping (%g, %g)",
                  static_cast<double>(scaleX), static_cast<double>(scaleY), static_cast<double>(m_ScaleX),
                  static_cast<double>(m_ScaleY));
    Log(text);
  }
  if (Has(status, ScaleStatus::ClampedLow)) {
    char text[128];
    std::snprintf(text, sizeof text, "DynamicResolution: scale (%g, %g) below one pixel; raised to (%g, %g)",
                  static_cast<double>(scaleX), static_cast<double>(scaleY), static_cast<double>(m_ScaleX),
                  static_cast<double>(m_ScaleY));
    Log(text);
  }
  return status;
}

float DynamicResolution::GetRTScaleX() const {
  if (!m_Valid) return 1.0f;  // D5: the 1x1 viewport fills the 1x1 RT
  // Original: scale / maxScaling. The min() only matters for the non-integral
  // maximum scaling of D4 (exact for 1 and 2).
  return std::min(1.0f, m_ScaleX / m_MaxScalingX);
}

float DynamicResolution::GetRTScaleY() const {
  if (!m_Valid) return 1.0f;
  return std::min(1.0f, m_ScaleY / m_MaxScalingY);
}

void DynamicResolution::GetViewport(DynamicViewport* viewport) const {
  if (!viewport) return;
  *viewport = GetViewport();
}

DynamicViewport DynamicResolution::GetViewport() const {
  DynamicViewport v;
  v.TopLeftX = 0.0f;
  v.TopLeftY = 0.0f;
  v.Width = static_cast<float>(m_CurrentWidth);
  v.Height = static_cast<float>(m_CurrentHeight);
  v.MinDepth = 0.0f;
  v.MaxDepth = 1.0f;
  return v;
}
