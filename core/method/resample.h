// Bilinear resampling of the DEM onto the line-of-sight grid of a non-cardinal view (SPEC 1.1),
// written for the x86-64 baseline and, where the processor has it, for AVX2, bit for bit alike.
#pragma once

#include <cstddef>

#include "core/base/grid.h"
#include "core/method/dem_windows.h"
#include "core/method/frame.h"

namespace tsk {

// Bilinear height at a DEM pixel position; NaN outside the cell centres' hull or next to nodata.
float sample_bilinear(const HeightGrid& dem, PixelPoint px);

// sample_bilinear at the positions start + i * step, i in [0, count), into out[i]: four or
// eight at a time where the processor has AVX2 or AVX-512, bit for bit as one at a time.
void sample_line(const HeightGrid& dem, PixelPoint start, PixelPoint step, std::size_t count,
                 float* out);

// Resamples profiles [first, first + count) of a resampled frame into `out` (rows = profiles),
// reusing its memory when it already has that shape: for streaming a view strip by strip.
void resample_profiles(const HeightGrid& dem, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads = 0);

// resample_profiles from the band of those profiles (DemBand::load), with the same heights;
// throws Error for profiles the band was not laid out for.
void resample_profiles(const DemBand& band, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads = 0);

}  // namespace tsk
