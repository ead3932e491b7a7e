// A DEM file described before it is read: its band, georeferencing, CRS and the notes for the
// user (dem_notes.h), from GDAL.
#pragma once

#include <gdal_priv.h>

#include <string>

#include "io/read/dem_reader.h"

namespace tsk::io {

// Checks the band and the georeferencing of an open DEM and fills everything of a Dem but the
// heights and the view's frame. Throws Error on what it cannot read faithfully (a missing band,
// rotated or south-up georeferencing, no georeferencing without a cell size), DemRefused for a
// geographic CRS. `second`, when given, is the same file opened once more: the sample of the
// band's range reads half its windows through it, alongside `dataset` (read_alongside()).
Dem describe_dem(GDALDataset& dataset, const std::string& path, const DemOptions& options,
                 GDALDataset* second = nullptr);

}  // namespace tsk::io
