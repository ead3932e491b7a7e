#include "io/read/gdal_util.h"

#include <cpl_error.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>

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

void check_input_path(const std::string& path) {
  // GDAL's virtual file systems, and subdatasets named DRIVER:..., are not plain paths.
  if (path.rfind("/vsi", 0) == 0) return;
  const std::size_t colon = path.find(':');
  if (colon != std::string::npos && colon > 1 && path.find('/') > colon) return;
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) {
    throw Error("cannot open '" + path + "': " + std::strerror(errno));
  }
  if (!S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode)) {
    throw Error("'" + path + "' is not a file (a pipe, a socket or a device); give a raster file");
  }
}

DatasetPtr open_raster(const std::string& path) {
  check_input_path(path);
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

NoAuxFiles::NoAuxFiles() {
  const char* before = CPLGetThreadLocalConfigOption("GDAL_PAM_ENABLED", nullptr);
  had_ = before != nullptr;
  if (had_) before_ = before;
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", "NO");
}

NoAuxFiles::~NoAuxFiles() {
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", had_ ? before_.c_str() : nullptr);
}

bool close_dataset(DatasetPtr& dataset) {
#if GDAL_VERSION_NUM >= GDAL_COMPUTE_VERSION(3, 7, 0)
  return GDALClose(dataset.release()) == CE_None;
#else
  dataset.reset();
  return true;
#endif
}

std::vector<std::string> dataset_files(const std::string& path) {
  GDALAllRegister();
  GdalErrorCapture quiet;
  const NoAuxFiles no_aux;
  DatasetPtr dataset(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr,
                 nullptr)));
  if (!dataset) return {path};
  std::vector<std::string> files;
  char** list = dataset->GetFileList();
  for (char** f = list; f && *f; ++f) files.emplace_back(*f);
  CSLDestroy(list);
  if (files.empty()) files.push_back(path);
  return files;
}

}  // namespace tsk::io
