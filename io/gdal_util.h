// Small GDAL helpers shared by the reader and writers.
#pragma once

#include <gdal_priv.h>

#include <memory>
#include <string>

#include "errors.h"

namespace tsk::io {

// While alive, GDAL errors on this thread are kept quiet and the last one is available for our
// own message.
class GdalErrorCapture {
 public:
  GdalErrorCapture();
  ~GdalErrorCapture();
  GdalErrorCapture(const GdalErrorCapture&) = delete;
  GdalErrorCapture& operator=(const GdalErrorCapture&) = delete;
  std::string message() const;
};

struct GdalCloser {
  void operator()(GDALDataset* ds) const { GDALClose(ds); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, GdalCloser>;

// Opens `path` read-only as a raster or throws tsk::Error saying why not.
DatasetPtr open_raster(const std::string& path);

}  // namespace tsk::io
