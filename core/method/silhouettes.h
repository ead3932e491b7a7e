// The whole method in order (SPEC 1.2-1.9 and 2), one named step per stage.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/base/flags.h"
#include "core/base/geotransform.h"
#include "core/base/memory_budget.h"
#include "core/base/parallel.h"
#include "core/method/adaptive_filter.h"
#include "core/method/dem_windows.h"
#include "core/method/orient.h"
#include "core/method/params.h"
#include "core/method/stage_stats.h"
#include "core/method/strokes.h"

namespace tsk {

struct BandSpec;    // bands.h
struct BandSketch;  // bands.h

struct SilhouetteResult {
  std::vector<Stroke> strokes;  // factual first, then formulated
  StageStats stats;
  StageTimings timings;
  CellFlags flags;      // the per-cell classification, for diagnostics and tests
  FilterReport filter;  // the slope filter used (ResolvedParams::filter)
  double z_ref = 0.0;   // the height plan-oblique geometry kept in place
  // Drawn for a scale far coarser than the DEM: the cells a side the DEM was averaged by before
  // the method ran on it (averaged_dem); 1 when it ran on the DEM as it is.
  std::size_t averaged = 1;
};

// Takes each stroke as soon as it is complete and every stroke of its class started before it has
// been handed on: factual and formulated strokes each in the order of SPEC 1.7's scan, the two
// classes interleaved. Called from a linking thread, one call at a time; what it throws ends the
// run.
using StrokeSink = std::function<void(Stroke&& stroke)>;

// Runs the stages on profiles delivered in strips, left to right, holding one strip at a time:
// for DEMs larger than memory. Memory beyond the strip is that of the strokes, unless a sink
// takes them as they complete. run_silhouettes is one strip.
class SilhouetteStream {
 public:
  // z_ref: the DEM's lowest height (plan-oblique geometry needs it before the first strip).
  // With a sink, strokes go to it and the result holds none.
  SilhouetteStream(const OrientedFrame& frame, const GeoTransform& geotransform,
                   const ResolvedParams& params, double z_ref, const ProgressFn& progress = {},
                   StrokeSink sink = {});
  // One band of a run split into bands (bands.h): its strips start at next_profile() and end
  // with its last profile; finish_band() ends it. Throws Error on drawn strokes or a band beyond
  // the grid.
  SilhouetteStream(const OrientedFrame& frame, const GeoTransform& geotransform,
                   const ResolvedParams& params, double z_ref, const BandSpec& band,
                   const ProgressFn& progress = {});
  ~SilhouetteStream();

  // The first profile of the next strip.
  std::size_t next_profile() const;

  // Profiles [first, first + count) with their neighbours for the row slope: `z` holds profiles
  // [first - 1, first + count + 1), without the ones beyond the grid's ends. Strips must follow
  // each other without gaps. keep_flags: hand this strip's classification to the result (for a
  // single strip covering the grid).
  void add_strip(const HeightGrid& z, std::size_t first, std::size_t count,
                 bool keep_flags = false);
  SilhouetteResult finish();
  BandSketch finish_band();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Reads oriented profiles [first, first + count) of the grid (a strip with its neighbours) into
// `strip`, which holds the previous strip: a reader may reuse its memory.
using ProfileReader = std::function<void(std::size_t first, std::size_t count, HeightGrid& strip)>;

// The whole method with the grid read `strip` profiles at a time through `read`, each strip with
// the neighbouring profiles the row slope needs. Equal to run_silhouettes on the whole grid.
// With a sink, strokes go to it as they complete and the result holds none.
SilhouetteResult run_in_strips(const OrientedFrame& frame, const GeoTransform& geotransform,
                               const ResolvedParams& params, double z_ref, std::size_t strip,
                               const ProfileReader& read, const ProgressFn& progress = {},
                               StrokeSink sink = {});

// Feeds `stream` its profiles from stream.next_profile() to `to` in strips of `strip` profiles
// read through `read`, reading the next strip while it works on one (on a thread of its own when
// `threads` > 1).
void stream_strips(SilhouetteStream& stream, const OrientedFrame& frame, std::size_t to,
                   std::size_t strip, const ProfileReader& read, unsigned threads);

// A DEM to read window by window (row 0 north, NaN for nodata), whatever the view: a raster file
// through GDAL, a QGIS layer through its provider, a grid in memory. The view's frame is made from
// the run's parameters (params.view), never from the source.
struct DemSource {
  DemGrid grid;
  GeoTransform geotransform;
  WindowReader read;
  // Optional: the same DEM through a reader of its own (a second dataset of its file), which may
  // read while `read` does; the adaptive filter's survey reads half its windows through it.
  WindowReader read_alongside = {};
};

// The whole method on a DEM read window by window, seen as params.view says: what the front ends
// call for the silhouettes. It decides the
// memory a run takes (strips of `strip` profiles, 0: strip_profiles()), reads the next strip while
// the stages work on this one, first reads a sample of the DEM (the whole DEM for local
// adaptivity) for an adaptive filter (adapt_filter), and for plan-oblique geometry reads the DEM
// once for its lowest height. Drawn for a scale coarser than the DEM (run_averaging), the DEM is
// read and averaged once, on two threads when it has a reader alongside, and held when the
// averaged DEM fits in a run's budget (within_run_budget); else each pass averages as it reads.
// Strokes go to `sink` as they complete (the result holds none) or, without one, into the result.
// Throws Error on bad parameters or what `read` throws, Cancelled when `progress` returns false.
SilhouetteResult sketch_silhouettes(const DemSource& dem, const SilhouetteParams& params,
                                    std::size_t strip = 0, const ProgressFn& progress = {},
                                    StrokeSink sink = {});

// Runs every stage on an oriented grid (see orient.h). z_ref is the DEM's lowest height, the
// plan-oblique reference; without it the grid's lowest height stands in (in oblique geometry),
// which is the DEM's for a cardinal view but may lie above it for a resampled one. Throws Error on
// bad parameters or a grid that does not match the frame, Cancelled when `progress` returns false.
// With a sink, strokes go to it as they complete and the result holds none.
SilhouetteResult run_silhouettes(const HeightGrid& oriented, const OrientedFrame& frame,
                                 const GeoTransform& geotransform, const ResolvedParams& params,
                                 const ProgressFn& progress = {},
                                 std::optional<double> z_ref = std::nullopt, StrokeSink sink = {});

}  // namespace tsk
