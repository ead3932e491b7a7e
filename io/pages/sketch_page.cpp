#include "io/pages/sketch_page.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "core/base/errors.h"
#include "core/method/plan_oblique.h"
#include "core/method/resample.h"
#include "io/write/output_files.h"

namespace tsk::io {
namespace {

// Full widths of the classes' strokes: exact strokes have them throughout, drawn strokes at a
// weight of 1. Pixels of the 1600 px picture, and millimetres on a page.
struct ClassWidths {
  double factual, formulated;
};
constexpr ClassWidths kExactPx{2.2, 1.1}, kDrawnPx{3.4, 1.9};
constexpr ClassWidths kExactMm{0.5, 0.25}, kDrawnMm{0.8, 0.45};
constexpr double kMarginPx = 10.0, kMarginMm = 10.0;
// A pixel of the picture without a page size, as vector art reads it (96 to the inch).
constexpr double kCssPixelMm = 25.4 / 96.0;

// The heights' range and the size of the sketch before it is put on the page, ground units: as
// wide as the profiles, as tall as the farthest cell lifted by the highest height.
struct PlotExtent {
  double z_min = 0.0, z_max = 0.0, width = 0.0, height = 0.0;
};

PlotExtent plot_extent(const HeightGrid& z, const OrientedFrame& frame, const ViewParams& view,
                       std::optional<HeightRange> averaged) {
  PlotExtent e;
  e.z_min = std::numeric_limits<double>::infinity();
  e.z_max = -e.z_min;
  if (averaged) {
    e.z_min = averaged->lowest;
    e.z_max = averaged->highest;
  } else {
    for (std::size_t k = 0; k < z.size(); ++k) {
      if (!is_data(z.data()[k])) continue;
      e.z_min = std::min(e.z_min, static_cast<double>(z.data()[k]));
      e.z_max = std::max(e.z_max, static_cast<double>(z.data()[k]));
    }
  }
  if (!std::isfinite(e.z_min) || !std::isfinite(e.z_max)) e.z_min = e.z_max = 0.0;
  const PlanObliqueShift shift(view, frame.d, e.z_min);
  e.width = std::max(frame.w, static_cast<double>(frame.profiles) * frame.w);
  e.height = shift(static_cast<double>(frame.length), e.z_max) * frame.d;
  return e;
}

// Where the sketch lies before it is put on the page: x across the view and y up the
// plan-oblique position along it, ground units, from the view's left and lowest height.
class Plot {
 public:
  Plot(const HeightGrid& z, const OrientedFrame& frame, const GeoTransform& geotransform,
       const ViewParams& view, Geometry geometry, std::optional<HeightRange> averaged)
      : z_(z),
        frame_(frame),
        geotransform_(geotransform),
        geometry_(geometry),
        extent_(plot_extent(z, frame, view, averaged)),
        shift_(view, frame.d, extent_.z_min) {}
  double width() const { return extent_.width; }
  double height() const { return extent_.height; }
  Geometry geometry() const { return geometry_; }

  StrokePoint cell(const ChainCell& c) const {
    const double zc =
        static_cast<double>(z_(static_cast<std::size_t>(c.p), static_cast<std::size_t>(c.i)));
    return {(c.p + 0.5) * frame_.w, shift_(c.i + 0.5, zc) * frame_.d};
  }
  // A drawn stroke's point, in the run's geometry, carried back to its profile: x across the view
  // and y the position along the profile, in cells. In map geometry that is the place (`plot`
  // makes it ground units); in plan-oblique geometry the point was shifted from the run's
  // reference height, which `lift` adds once the run has said it.
  StrokePoint carry(StrokePoint at) const {
    double p = 0.0, s = 0.0;
    frame_.from_pixel(geotransform_.to_pixel(at.x, at.y), p, s);
    double along = s + 0.5;
    if (geometry_ == Geometry::map) along = shift_(s + 0.5, height_at(p, s));
    return {(p + 0.5) * frame_.w, along};
  }
  StrokePoint plot(StrokePoint carried) const { return {carried.x, carried.y * frame_.d}; }
  StrokePoint lift(StrokePoint carried, double z_ref) const {
    return plot({carried.x, carried.y + shift_(0.0, z_ref)});
  }

 private:
  // The height at a place along a profile: bilinear between cells; next to nodata or the grid's
  // edge, the nearest cell's that holds one.
  double height_at(double p, double s) const {
    const float between = sample_bilinear(z_, {s + 0.5, p + 0.5});
    return is_data(between) ? between : nearest_height(p, s);
  }
  // The height of the cell nearest (p, s) that holds one, within kNearestReach cells; the lowest
  // height if none does. A drawn point lies within its tolerance of its cell, which may put it on
  // a nodata cell beside the DEM's edge: taken at the lowest height, it fell to the foot of the
  // page as a spike.
  double nearest_height(double p, double s) const {
    constexpr long kNearestReach = 8;
    const long last_row = static_cast<long>(z_.rows()) - 1,
               last_col = static_cast<long>(z_.cols()) - 1;
    const long row = std::clamp(std::lround(p), 0L, last_row);
    const long col = std::clamp(std::lround(s), 0L, last_col);
    double best = std::numeric_limits<double>::infinity(), height = extent_.z_min;
    for (long r = std::max(0L, row - kNearestReach); r <= std::min(last_row, row + kNearestReach);
         ++r) {
      for (long c = std::max(0L, col - kNearestReach); c <= std::min(last_col, col + kNearestReach);
           ++c) {
        const float z = z_(static_cast<std::size_t>(r), static_cast<std::size_t>(c));
        const double dp = static_cast<double>(r) - p, ds = static_cast<double>(c) - s;
        if (is_data(z) && dp * dp + ds * ds < best) best = dp * dp + ds * ds, height = z;
      }
    }
    return height;
  }

  const HeightGrid& z_;
  const OrientedFrame& frame_;
  const GeoTransform& geotransform_;
  Geometry geometry_;
  PlotExtent extent_;
  PlanObliqueShift shift_;
};

// How plot coordinates become page coordinates.
struct Placement {
  double scale, left, bottom, height;
  StrokePoint place(StrokePoint plot) const {
    return {left + plot.x * scale, height - bottom - plot.y * scale};
  }
};

// The picture's width in pixels without a page size.
int picture_width(const PageOptions& options) {
  return std::clamp(options.width_px, 64, 20000);
}

// Pixels a ground unit on the picture without a page size.
double pixel_scale(double plot_width, const PageOptions& options) {
  return (picture_width(options) - 2.0 * kMarginPx) / plot_width;
}

// A page of paper turned to suit a sketch `plot_width` by `plot_height` ground units, and the
// millimetres a ground unit it is drawn at: the scale asked for, or the one that fits the sketch
// inside the margins. Throws Error when the sketch at the scale asked for does not fit.
struct Paper {
  double width, height, mm_per_unit;
};

Paper lay_paper(double plot_width, double plot_height, const PageOptions& options) {
  const PageSize size = parse_page_size(options.size);
  const double short_side = std::min(size.width_mm, size.height_mm);
  const double long_side = std::max(size.width_mm, size.height_mm);
  const bool landscape = plot_width >= plot_height;
  Paper paper{landscape ? long_side : short_side, landscape ? short_side : long_side, 0.0};
  const double room_w = paper.width - 2 * kMarginMm, room_h = paper.height - 2 * kMarginMm;
  const double fit = std::min(room_w / plot_width, room_h / plot_height);
  paper.mm_per_unit = options.scale > 0.0 ? 1000.0 / options.scale : fit;
  if (paper.mm_per_unit > fit * (1.0 + 1e-9)) {
    throw Error("at 1:" + number_text(options.scale) + " the sketch is " +
                number_text(std::round(plot_width * paper.mm_per_unit)) + " x " +
                number_text(std::round(plot_height * paper.mm_per_unit)) +
                " mm, larger than the page's " + number_text(room_w) + " x " + number_text(room_h) +
                " mm inside its margins; give --page-scale " +
                number_text(std::ceil(1000.0 / fit)) + " or more, or a larger --page");
  }
  return paper;
}

// The 1600 px picture (the preview before pages): as tall as the sketch needs.
Placement pixel_placement(const Plot& plot, const PageOptions& options, SketchPage& page) {
  page.width = picture_width(options);
  const double scale = pixel_scale(plot.width(), options);
  page.height = std::clamp(
      static_cast<int>(std::ceil(plot.height() * scale)) + 2 * static_cast<int>(kMarginPx), 64,
      20000);
  return {scale, kMarginPx, kMarginPx, page.height};
}

// A page of paper: turned to suit the sketch, which is fitted or drawn at the scale asked for
// and centred.
Placement paper_placement(const Plot& plot, const PageOptions& options, SketchPage& page) {
  const Paper paper = lay_paper(plot.width(), plot.height(), options);
  page.width = paper.width;
  page.height = paper.height;
  page.millimetres = true;
  const double scale = paper.mm_per_unit;
  return {scale, (page.width - plot.width() * scale) / 2, (page.height - plot.height() * scale) / 2,
          page.height};
}

}  // namespace

PageSize parse_page_size(const std::string& text) {
  static const std::map<std::string, PageSize> named = {
      {"a4", {210, 297}},         {"a3", {297, 420}},  {"a2", {420, 594}},
      {"a1", {594, 841}},         {"a0", {841, 1189}}, {"letter", {215.9, 279.4}},
      {"tabloid", {279.4, 431.8}}};
  std::string lower;
  for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (const auto found = named.find(lower); found != named.end()) return found->second;
  const std::size_t x = lower.find('x');
  try {
    std::size_t used_w = 0, used_h = 0;
    if (x == std::string::npos) throw std::invalid_argument("no x");
    const double w = std::stod(lower.substr(0, x), &used_w);
    const double h = std::stod(lower.substr(x + 1), &used_h);
    if (used_w == x && used_h == lower.size() - x - 1 && w >= 50 && w <= 5000 && h >= 50 &&
        h <= 5000)
      return {w, h};
  } catch (const std::exception&) {
  }
  throw Error(
      "--page must be A4, A3, A2, A1, A0, letter, tabloid or WIDTHxHEIGHT in millimetres "
      "(each 50 to 5000), got '" +
      text + "'");
}

double preview_scale(const HeightGrid& z, const OrientedFrame& frame, const ViewParams& view,
                     const PageOptions& options, std::optional<HeightRange> averaged) {
  const PlotExtent plot = plot_extent(z, frame, view, averaged);
  if (!(plot.width > 0.0) || !(plot.height > 0.0)) return 0.0;
  if (!options.size.empty())
    return 1000.0 / lay_paper(plot.width, plot.height, options).mm_per_unit;
  return 1000.0 / (pixel_scale(plot.width, options) * kCssPixelMm);
}

struct SketchLayout::Parts {
  Parts(const HeightGrid& z, const OrientedFrame& frame, const GeoTransform& geotransform,
        const ViewParams& view, Geometry geometry, const PageOptions& options,
        std::optional<HeightRange> averaged)
      : plot(z, frame, geotransform, view, geometry, averaged),
        at(options.size.empty() ? pixel_placement(plot, options, page)
                                : paper_placement(plot, options, page)),
        cells_on_grid(!averaged) {}
  Plot plot;
  SketchPage page;
  Placement at;
  bool cells_on_grid;                 // whether exact strokes' cells index the plot's heights
  std::vector<std::size_t> unlifted;  // paths of strokes whose points wait for z_ref
};

SketchLayout::SketchLayout(const HeightGrid& z, const OrientedFrame& frame,
                           const GeoTransform& geotransform, const ViewParams& view,
                           Geometry geometry, const PageOptions& options,
                           std::optional<HeightRange> averaged)
    : parts_(std::make_unique<Parts>(z, frame, geotransform, view, geometry, options, averaged)) {}

SketchLayout::~SketchLayout() = default;

void SketchLayout::add(const Stroke& s) {
  SketchPage& page = parts_->page;
  const bool drawn = !s.weights.empty();
  const ClassWidths widths =
      page.millimetres ? (drawn ? kDrawnMm : kExactMm) : (drawn ? kDrawnPx : kExactPx);
  const double full = s.cls == StrokeClass::factual ? widths.factual : widths.formulated;
  PagePath path{s.cls, {}, {}};
  const Plot& plot = parts_->plot;
  if (drawn || !parts_->cells_on_grid) {
    const bool lifted_later = plot.geometry() == Geometry::oblique;
    path.points.reserve(s.points.size());
    path.widths.reserve(s.points.size());
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const StrokePoint carried = plot.carry(s.points[k]);
      path.points.push_back(lifted_later ? carried : parts_->at.place(plot.plot(carried)));
      path.widths.push_back(drawn ? full * s.weights[k] : full);
    }
    if (lifted_later) parts_->unlifted.push_back(page.paths.size());
  } else {
    path.points.reserve(s.chain.size());
    for (const ChainCell& c : s.chain) path.points.push_back(parts_->at.place(plot.cell(c)));
    path.widths.assign(path.points.size(), full);
  }
  page.paths.push_back(std::move(path));
}

SketchPage SketchLayout::take_page(double z_ref) {
  SketchPage& page = parts_->page;
  for (const std::size_t k : parts_->unlifted) {
    for (StrokePoint& point : page.paths[k].points)
      point = parts_->at.place(parts_->plot.lift(point, z_ref));
  }
  parts_->unlifted.clear();
  return std::move(page);
}

}  // namespace tsk::io
