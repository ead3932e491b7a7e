// The sketch laid out on a page for the previews: every stroke as a path of page points with a
// width at each, far side up, as the raised viewer sees it (the thesis's profile plot).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/method/silhouettes.h"

namespace tsk::io {

struct PageOptions {
  int width_px = 1600;   // without a page size: the picture's width in pixels
  std::string size;      // A4, A3, A2, A1, A0, letter, tabloid or WxH in millimetres; empty: none
  double scale = 0.0;    // the page at 1:scale of the ground; 0: the sketch fits the page
  bool plotter = false;  // single-line paths for a pen plotter (vector art only)
  std::string description;  // of the run (run_note.h), kept in vector art
};

// A page size in millimetres, portrait; throws Error naming what is wrong.
struct PageSize {
  double width_mm, height_mm;
};
PageSize parse_page_size(const std::string& text);

struct PagePath {
  StrokeClass cls;
  std::vector<StrokePoint> points;  // page units, y down
  std::vector<double> widths;       // page units, at each point
  double ink = 1.0;  // share of the class's colour over white: far panorama strokes are lighter
};

// A label with its leader: a line from `from` to `to`, the text on from `to`, in page units.
struct PageLabel {
  StrokePoint from, to;
  std::string text;  // UTF-8
};

struct SketchPage {
  double width = 0.0, height = 0.0;  // page units: millimetres with a page size, else pixels
  bool millimetres = false;
  std::vector<PagePath> paths;    // in the order of the strokes
  std::vector<PageLabel> labels;  // a panorama's peaks
  std::string description;        // of the run (run_note.h): the vector art's <desc>
  double label_size() const { return millimetres ? 3.0 : 13.0; }  // the text's height
};

// A DEM's own lowest and highest heights, which averaging its cells narrows.
struct HeightRange {
  double lowest, highest;
};

// The scale 1:N of the frame's ground units at which the preview shows the sketch: a page's
// (options.scale, or the one that fits the sketch inside the page's margins), or, without a page
// size, the picture's, its pixels taken at 96 to the inch as vector art reads them. 0 for a sketch
// of no extent. Throws Error, as SketchLayout would, when the sketch at the page's scale does
// not fit it: a front end can refuse it before the run.
// `averaged` as SketchLayout takes it.
double preview_scale(const HeightGrid& z, const OrientedFrame& frame, const ViewParams& view,
                     const PageOptions& options, std::optional<HeightRange> averaged = {});

// Lays a run's strokes out on the page one at a time, as the run hands them on, so that they need
// not be held till it ends: the page's size and scale follow from the DEM alone. Exact strokes are
// drawn through their cells' centres; drawn strokes through their points, carried back into the
// view (the DEM's heights between cells for map geometry), with their weights as widths. Drawn
// strokes in plan-oblique geometry are finished when the page is taken, with the run's reference
// height (SilhouetteResult::z_ref), which a run states at its end. `z`, `frame` and
// `geotransform` are read until then: they must outlive the layout. They are the run's own grid,
// or, given the DEM's own range of heights as `averaged`, the DEM averaged for its page (a DEM too
// large to hold: page_heights.h). Over that, exact strokes are placed by their points, as drawn
// ones are, since their cells index the run's grid. Throws Error when the sketch at the scale
// asked for does not fit the page.
class SketchLayout {
 public:
  SketchLayout(const HeightGrid& z, const OrientedFrame& frame, const GeoTransform& geotransform,
               const ViewParams& view, Geometry geometry, const PageOptions& options,
               std::optional<HeightRange> averaged = {});
  ~SketchLayout();
  SketchLayout(const SketchLayout&) = delete;
  SketchLayout& operator=(const SketchLayout&) = delete;

  void add(const Stroke& stroke);  // its path, after those added before
  SketchPage take_page(double z_ref);

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace tsk::io
