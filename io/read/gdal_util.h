// Small GDAL helpers shared by the reader and writers.
#pragma once

#include <gdal_priv.h>

#include <memory>
#include <string>
#include <vector>

#include "core/base/errors.h"

namespace tsk::io {

// While alive, GDAL errors on this thread are kept quiet (from stderr and from QGIS's log) and
// kept for our own messages: the last one, and the first failure, which on a full disk is the
// cause ("File too large") where the last is libtiff's consequence of it. The one way both front
// ends catch GDAL's errors.
class GdalErrorCapture {
 public:
  GdalErrorCapture();
  ~GdalErrorCapture();
  GdalErrorCapture(const GdalErrorCapture&) = delete;
  GdalErrorCapture& operator=(const GdalErrorCapture&) = delete;
  // The last error GDAL reported ("unknown GDAL error" if none), shortened.
  std::string message() const;
  // The first failure (CE_Failure or worse) since the capture began, shortened; "" if none.
  const std::string& first_failure() const { return first_failure_; }

 private:
  static void CPL_STDCALL record(CPLErr type, CPLErrorNum number, const char* message);
  std::string first_failure_;
};

struct GdalCloser {
  void operator()(GDALDataset* ds) const { GDALClose(ds); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, GdalCloser>;

// While alive, GDAL's configuration option `key` is `value` for this thread; then it is what it
// was again. `key` is kept as given, so it must outlive the object (a string literal does).
class ThreadConfigOption {
 public:
  ThreadConfigOption(const char* key, const std::string& value);
  ~ThreadConfigOption();
  ThreadConfigOption(const ThreadConfigOption&) = delete;
  ThreadConfigOption& operator=(const ThreadConfigOption&) = delete;

 private:
  const char* key_;
  std::string before_;
  bool had_ = false;
};

// While alive, datasets this thread opens leave no .aux.xml beside them: a look into a file
// must not change what is there (GDAL 3.10 writes one for a GeoPackage raster it only opened).
class NoAuxFiles : ThreadConfigOption {
 public:
  NoAuxFiles() : ThreadConfigOption("GDAL_PAM_ENABLED", "NO") {}
};

// While alive, the SQLite databases (GeoPackages) this thread creates get pages of 16 KiB rather
// than 4 KiB, as strokes go into them in one bulk load: the 8000 x 8000 benchmark's 827 000 drawn
// strokes write a 6 % smaller file in about 5 % less time, and a small output grows by a few
// hundred KB. A page_size the user sets in OGR_SQLITE_PRAGMA comes after ours, and wins.
class BulkLoadPages : ThreadConfigOption {
 public:
  BulkLoadPages();
};

// Closes `dataset` and returns false when GDAL says the close failed. GDAL 3.7 and later say so
// when the cached blocks cannot be written as the file closes; GDAL 3.10's GeoTIFF driver
// reports a full disk no other way (libtiff prints it, no GDAL error is raised).
bool close_dataset(DatasetPtr& dataset);

// Throws Error, before GDAL opens it, when `path` names no file or one GDAL's open would hang on
// or misread: a named pipe, a socket or a device. Folders (an Arc/Info grid) and GDAL's virtual
// paths (/vsizip/..., NETCDF:"file":var) pass.
void check_input_path(const std::string& path);

// Throws Error naming the file when `files`, those read for the dataset at `path`
// (files_read_for), hold one that is not a regular file: a named pipe, a socket or a device,
// which GDAL's read would hang on or misread.
void check_sources_are_files(const std::string& path, const std::vector<std::string>& files);

// Opens `path` read-only as a raster or throws tsk::Error saying why not.
DatasetPtr open_raster(const std::string& path);

// The main file of the dataset `path` belongs to when that is another file (a shapefile's .shp for
// its .dbf); empty when `path` is a dataset's own main file, or no dataset GDAL opens.
std::string main_file_of_other_dataset(const std::string& path);

// Every file GDAL reads for the raster or vector dataset at `path` (a VRT's sources included);
// just `path` when GDAL cannot open it.
std::vector<std::string> dataset_files(const std::string& path);

// `path` and every file reading it reads, all the way down: a VRT's sources, the sources of a VRT
// it reads, and the files GDAL's virtual paths wrap (/vsisubfile/, /vsigzip/, archives). A source
// that is not a regular file is listed but never opened (GDAL's open would hang on a pipe).
std::vector<std::string> files_read_for(const std::string& path);

}  // namespace tsk::io
