#include "profile_plot.h"

#include "errors.h"

namespace tsk {

double lowest_height(const HeightGrid& z) {
  LowestHeight lowest;
  lowest.add(z.data(), z.size());
  return lowest.value();
}

std::vector<ProfileLine> profile_plot(const HeightGrid& oriented, const CellFlags& flags,
                                      const OrientedFrame& frame, const ViewParams& view,
                                      const GeoTransform& geotransform, std::size_t every_n,
                                      double z_ref) {
  if (every_n == 0) throw Error("the profile plot needs a step of at least one cross-section");
  const double cells_per_metre = view.ve / (view.base_slope() * frame.d);
  std::vector<ProfileLine> lines;
  for (std::size_t i = 0; i < frame.length; i += every_n) {
    ProfileLine piece;
    piece.cross_section = i;
    piece.distance = static_cast<double>(i) * frame.d;
    auto flush = [&] {
      if (piece.points.size() >= 2) lines.push_back(piece);
      piece.points.clear();
    };
    for (std::size_t p = 0; p < frame.profiles; ++p) {
      const std::uint8_t f = flags(p, i);
      if (!(f & cell::valid) || (f & cell::hidden)) {
        flush();
        continue;
      }
      const double shifted =
          static_cast<double>(i) + cells_per_metre * (static_cast<double>(oriented(p, i)) - z_ref);
      StrokePoint pt{};
      geotransform.apply(frame.to_pixel(static_cast<double>(p), shifted), pt.x, pt.y);
      piece.points.push_back(pt);
    }
    flush();
  }
  return lines;
}

}  // namespace tsk
