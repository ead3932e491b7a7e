#include "core/applications/filter_diagram.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "core/method/candidates.h"
#include "core/method/slope_filter.h"

namespace tsk {

std::size_t SlopeScatter::bin(double col_pct, double row_pct) const {
  auto index = [&](double v) {
    return std::clamp(static_cast<int>(v / max_pct * bins), 0, bins - 1);
  };
  return static_cast<std::size_t>(index(row_pct) * bins + index(col_pct));
}

double diagram_range_pct(const FilterParams& filter) {
  return std::max(60.0, 2.5 * std::max(filter.row_cut_pct, filter.col_cut_pct));
}

SlopeScatter slope_scatter(const HeightGrid& z, const CellFlags& flags, double d, double w,
                           double max_pct, int bins) {
  if (!(max_pct > 0.0) || bins < 2 || bins > 2000) throw Error("bad scatter range or bin count");
  SlopeScatter s;
  s.bins = bins;
  s.max_pct = max_pct;
  const auto cells = static_cast<std::size_t>(bins) * static_cast<std::size_t>(bins);
  s.all.assign(cells, 0), s.candidate.assign(cells, 0), s.filtered.assign(cells, 0);
  for (std::size_t p = 0; p < z.rows(); ++p) {
    for (std::size_t i = 0; i < z.cols(); ++i) {
      const double gc = column_slope(z.row(p), z.cols(), i, d);
      if (!std::isfinite(gc)) continue;
      const double gr = row_slope(z, p, i, w);
      const std::size_t k = s.bin(std::fabs(gc) * 100.0, std::fabs(gr) * 100.0);
      ++s.all[k];
      if (flags(p, i) & cell::candidate) ++s.candidate[k];
      if (flags(p, i) & cell::filtered) ++s.filtered[k];
    }
  }
  return s;
}

SlopeScatter slope_scatter_of(const HeightGrid& oriented, const OrientedFrame& frame,
                              const SilhouetteResult& result) {
  return slope_scatter(oriented, result.flags, frame.d, frame.w,
                       diagram_range_pct(result.filter.cutoffs));
}

}  // namespace tsk
