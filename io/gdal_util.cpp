#include "gdal_util.h"

#include <cpl_error.h>

namespace tsk::io {

namespace {

// Some messages quote whole SQL scripts; their start and the reason at their end are enough.
std::string shortened(const std::string& text) {
  constexpr std::size_t kEnd = 150;
  if (text.size() <= 3 * kEnd) return text;
  return text.substr(0, kEnd) + " [...] " + text.substr(text.size() - kEnd);
}

}  // namespace

GdalErrorCapture::GdalErrorCapture() {
  CPLPushErrorHandlerEx(&GdalErrorCapture::record, this);
  CPLErrorReset();
}

void CPL_STDCALL GdalErrorCapture::record(CPLErr type, CPLErrorNum, const char* message) {
  auto* self = static_cast<GdalErrorCapture*>(CPLGetErrorHandlerUserData());
  if (type >= CE_Failure && self->first_failure_.empty())
    self->first_failure_ = shortened(message && *message ? message : "unknown GDAL error");
}

GdalErrorCapture::~GdalErrorCapture() {
  CPLPopErrorHandler();
}

std::string GdalErrorCapture::message() const {
  const char* msg = CPLGetLastErrorMsg();
  if (!msg || !*msg) return "unknown GDAL error";
  return shortened(msg);
}

DatasetPtr open_raster(const std::string& path) {
  GDALAllRegister();
  GdalErrorCapture capture;
  DatasetPtr dataset(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  if (!dataset) throw Error("cannot open '" + path + "' as a raster: " + capture.message());
  if (dataset->GetRasterXSize() < 1 || dataset->GetRasterYSize() < 1) {
    throw Error("'" + path + "' has no cells");
  }
  return dataset;
}

}  // namespace tsk::io
