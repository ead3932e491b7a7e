#include "core/applications/profile_plot.h"

#include "core/base/errors.h"
#include "core/method/plan_oblique.h"

namespace tsk {

std::vector<ProfileLine> profile_plot(const HeightGrid& oriented, const CellFlags& flags,
                                      const OrientedFrame& frame, const ViewParams& view,
                                      const GeoTransform& geotransform, std::size_t every_n,
                                      double z_ref) {
  if (every_n == 0) throw Error("the profile plot needs a step of at least one cross-section");
  const PlanObliqueShift shift(view, frame.d, z_ref);
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
      const double shifted = shift(static_cast<double>(i), static_cast<double>(oriented(p, i)));
      StrokePoint pt{};
      geotransform.apply(frame.to_pixel(static_cast<double>(p), shifted), pt.x, pt.y);
      piece.points.push_back(pt);
    }
    flush();
  }
  return lines;
}

}  // namespace tsk
