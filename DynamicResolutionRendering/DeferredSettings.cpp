#include "DeferredSettings.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace drr {

namespace {
struct Named {
  const char* option;
  const char* gui;
};
constexpr Named kRenderers[] = {{"forward", "Forward"}, {"deferred", "Deferred"}};
constexpr Named kShadowLaws[] = {{"fixed", "Fixed"}, {"main", "Follows main scale"}};
static_assert(std::size(kRenderers) == size_t(Renderer::Count));
static_assert(std::size(kShadowLaws) == size_t(ShadowLaw::Count));
}  // namespace

const char* RendererOption(Renderer r) { return kRenderers[int(r)].option; }
const char* RendererName(Renderer r) { return kRenderers[int(r)].gui; }
const char* ShadowLawOption(ShadowLaw l) { return kShadowLaws[int(l)].option; }
const char* ShadowLawName(ShadowLaw l) { return kShadowLaws[int(l)].gui; }

float ShadowMapScale(ShadowLaw law, float optionScale, float mainScale) {
  float s = optionScale;
  if (law == ShadowLaw::Main) s *= std::isfinite(mainScale) ? mainScale : 1.0f;
  return std::clamp(s, kMinShadowScale, 1.0f);
}

}  // namespace drr
