// Drawing for a map scale (DrawnParams::scale), as generalisation does for other map features:
// what a stroke needs on paper, and how much relief a stroke must outline to matter. Relief
// weights every drawn stroke, so that the big landforms lead and the small ones recede; at a given
// scale the strokes outlining too little vanish.
#pragma once

#include <cstddef>

#include "core/base/geotransform.h"
#include "core/method/frame.h"
#include "core/method/strokes.h"

namespace tsk {

struct DrawingSetup;

// On paper at the scale drawn for, millimetres.
constexpr double kLeastStrokeMm = 2.0;  // the shortest stroke kept
constexpr double kJoinGapMm = 0.75;     // ends this close join
constexpr double kSmoothMm = 0.5;       // Gaussian sigma along a stroke
constexpr double kToleranceMm = 0.4;    // farthest a drawn point moves from its cell
// What a scale may ask of a grid, in cells, at most: beyond, the DEM is far finer than the scale
// and is better averaged to a coarser grid first (the join gap's reach holds strokes open).
constexpr double kMostScaleGapCells = 20.0;
constexpr double kMostScaleSmoothCells = 20.0;
constexpr double kMostScaleToleranceCells = 5.0;
// The DEM's own scale when none is given: 1:2500 per map unit of its cells (0.4 mm a cell).
constexpr double kOwnScalePerCell = 2500.0;
// The relief drawn at full weight at 1:N is N / kFullReliefPerScale metres: 50 m at 1:50 000,
// 1 km at 1:1 000 000 (a few contour intervals). Strokes outlining less than kVanishingShare of it
// vanish when a scale is given; those outlining kLeastReliefShare of it or less draw at
// kLeastReliefWeight.
constexpr double kFullReliefPerScale = 1000.0;
constexpr double kVanishingShare = 0.1;
constexpr double kLeastReliefShare = 1.0 / 30.0;
constexpr double kLeastReliefWeight = 0.4;

// The shorter side, in cells, that averaging for a scale leaves a DEM at least.
constexpr std::size_t kLeastAveragedSide = 32;

// The DEM's own scale, 1:N of its map units: kOwnScalePerCell times its shorter cell side.
double own_scale(const GeoTransform& geotransform);

// The cells a side that a DEM is averaged by (averaged_dem) before it is drawn for 1:scale: as
// many as make cells of about 0.4 mm on paper (kOwnScalePerCell), when that is 2 or more, so
// that a DEM finer than the scale needs and the same DEM averaged give one sketch; no more than
// leaves kLeastAveragedSide cells on the shorter side. 1 without a scale (scale 0).
std::size_t scale_averaging(double scale, const DemGrid& grid, const GeoTransform& geotransform);

// Sets setup's relief at full weight, and for a given scale its vanishing relief and its smallest
// stroke, smoothing, tolerance and join gap raised to what the scale needs (never lowered), from
// setup.cell and setup.drawn.scale.
void fit_to_scale(DrawingSetup& setup);

// The relief a stroke outlines, metres: a factual stroke's deepest hidden zone (the height it
// hides); a formulated one's slope times its length (steepness and extent together: the height a
// slope that steep gains over that run).
double stroke_relief(const Stroke& stroke);

// The weight of a stroke outlining `relief`: kLeastReliefWeight up to kLeastReliefShare of
// `full`, rising with the logarithm of the relief to 1 at `full` and beyond. 1 when `full` is 0.
double relief_weight(double relief, double full);

}  // namespace tsk
