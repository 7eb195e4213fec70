#include "ResolveFilters.h"

#include <iterator>

namespace drr {

namespace {
constexpr FilterInfo kUnknown{"?", "?", filter_row::kPoint, nullptr, "ResolvePoint", "ResolvePoint", false,
                               FilterKind::Spatial};
}  // namespace

const FilterInfo& GetFilterInfo(Filter f) {
  const auto i = static_cast<size_t>(f);
  return i < std::size(kFilters) ? kFilters[i] : kUnknown;
}

namespace {
constexpr ScreenPercentageRange kRanges[] = {
    {0.0, 50.0, "below the document's table: detail is lost faster than TAAU can recover it"},
    {50.0, 71.0, "the cheapest range: TAAU targeting 4K on desktops and consoles"},
    {71.0, 100.0, "rendering at ordinary DPI on desktops and consoles"},
    {100.0, 200.01, "super sampling, as far as render-target memory allows"},
};
}  // namespace

const ScreenPercentageRange& ScreenPercentageRangeOf(double scale) {
  const double percent = scale * 100.0;
  for (const ScreenPercentageRange& r : kRanges)
    if (percent < r.highPercent) return r;
  return kRanges[std::size(kRanges) - 1];
}

}  // namespace drr
