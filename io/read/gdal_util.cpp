#include "io/read/gdal_util.h"

#include <cpl_error.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace tsk::io {

namespace {

// Some messages quote whole SQL scripts; their start and the reason at their end are enough.
std::string shortened(const std::string& text) {
  constexpr std::size_t kEnd = 150;
  if (text.size() <= 3 * kEnd) return text;
  return text.substr(0, kEnd) + " [...] " + text.substr(text.size() - kEnd);
}

// Our page size, then the user's pragmas: SQLite takes the last page_size it is given.
std::string bulk_load_pragmas() {
  const char* user = CPLGetConfigOption("OGR_SQLITE_PRAGMA", nullptr);
  return std::string("page_size=16384") + (user && *user ? std::string(",") + user : "");
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
    throw Error("'" + path + "' is not a file (a pipe, a socket or a device); name a file on disk");
  }
}

void check_sources_are_files(const std::string& path, const std::vector<std::string>& files) {
  for (const std::string& file : files) {
    if (file == path || file.rfind("/vsi", 0) == 0) continue;
    struct stat info {};
    if (stat(file.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode)) {
      throw Error("'" + path + "' reads '" + file +
                  "', which is not a file (a pipe, a socket or a device); give a raster whose "
                  "sources are files");
    }
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

ThreadConfigOption::ThreadConfigOption(const char* key, const std::string& value) : key_(key) {
  const char* before = CPLGetThreadLocalConfigOption(key, nullptr);
  had_ = before != nullptr;
  if (had_) before_ = before;
  CPLSetThreadLocalConfigOption(key, value.c_str());
}

ThreadConfigOption::~ThreadConfigOption() {
  CPLSetThreadLocalConfigOption(key_, had_ ? before_.c_str() : nullptr);
}

BulkLoadPages::BulkLoadPages() : ThreadConfigOption("OGR_SQLITE_PRAGMA", bulk_load_pragmas()) {}

bool close_dataset(DatasetPtr& dataset) {
#if GDAL_VERSION_NUM >= GDAL_COMPUTE_VERSION(3, 7, 0)
  return GDALClose(dataset.release()) == CE_None;
#else
  dataset.reset();
  return true;
#endif
}

namespace {

// The file a GDAL virtual path reads, its wrappers taken off one by one: /vsisubfile/O_S,FILE,
// /vsigzip/FILE, and the archive of /vsizip/, /vsitar/, /vsi7z/ and /vsirar/ paths (with or
// without {braces}); the path itself when it wraps nothing on this machine.
std::string underlying_file(std::string path) {
  for (int depth = 0; depth < 16 && path.rfind("/vsi", 0) == 0; ++depth) {
    const std::size_t slash = path.find('/', 1);
    const std::string kind = path.substr(0, slash + 1);
    std::string rest = slash == std::string::npos ? "" : path.substr(slash + 1);
    if (kind == "/vsisubfile/") {
      const std::size_t comma = rest.find(',');
      if (comma == std::string::npos) return path;
      path = rest.substr(comma + 1);
    } else if (kind == "/vsigzip/") {
      path = rest;
    } else if (kind == "/vsizip/" || kind == "/vsitar/" || kind == "/vsi7z/" ||
               kind == "/vsirar/") {
      if (!rest.empty() && rest[0] == '{') {
        const std::size_t close = rest.find('}');
        if (close == std::string::npos) return path;
        path = rest.substr(1, close - 1);
        continue;
      }
      // The archive: the longest leading part of the path that is a file.
      std::string archive;
      for (std::size_t at = rest.find('/');; at = rest.find('/', at + 1)) {
        const std::string part = rest.substr(0, at);
        struct stat info {};
        if (stat(part.c_str(), &info) == 0 && S_ISREG(info.st_mode)) archive = part;
        if (at == std::string::npos) break;
      }
      if (archive.empty()) return path;
      path = archive;
    } else {
      return path;  // a network or memory file system: no file on this machine
    }
  }
  return path;
}

// The files GDAL lists for the dataset at `path`, or nothing when it cannot open it.
std::vector<std::string> listed_files(const std::string& path) {
  GdalErrorCapture quiet;
  const NoAuxFiles no_aux;
  DatasetPtr dataset(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr,
                 nullptr)));
  std::vector<std::string> files;
  if (!dataset) return files;
  char** list = dataset->GetFileList();
  for (char** f = list; f && *f; ++f) files.emplace_back(*f);
  CSLDestroy(list);
  return files;
}

}  // namespace

std::string main_file_of_other_dataset(const std::string& path) {
  GDALAllRegister();
  const std::vector<std::string> files = listed_files(path);
  if (files.empty()) return {};
  // Named alike, they are one file: comparing inodes alone, read one after the other, took a file
  // that another run renamed over in between for two.
  const auto normal = [](const std::string& p) {
    return std::filesystem::absolute(p).lexically_normal();
  };
  if (normal(files.front()) == normal(path)) return {};
  std::error_code ec;
  return std::filesystem::equivalent(files.front(), path, ec) || ec ? std::string() : files.front();
}

std::vector<std::string> dataset_files(const std::string& path) {
  GDALAllRegister();
  std::vector<std::string> files = listed_files(path);
  if (files.empty()) files.push_back(path);
  return files;
}

std::vector<std::string> files_read_for(const std::string& path) {
  GDALAllRegister();
  // Followed all the way down: a VRT of a VRT lists the VRT it reads, not that one's sources.
  std::vector<std::string> files, to_visit{path};
  std::set<std::string> seen;
  while (!to_visit.empty() && seen.size() < 4096) {
    const std::string next = to_visit.back();
    to_visit.pop_back();
    if (!seen.insert(next).second) continue;
    files.push_back(next);
    const std::string under = underlying_file(next);
    if (under != next) to_visit.push_back(under);
    // A source that is a plain, regular file is opened to list what it reads in turn; a pipe or
    // a device is listed but never opened (GDAL's open would hang on a FIFO).
    struct stat info {};
    const bool plain = next.rfind("/vsi", 0) != 0;
    if (next != path && plain && (stat(next.c_str(), &info) != 0 || !S_ISREG(info.st_mode)))
      continue;
    for (const std::string& file : listed_files(next)) to_visit.push_back(file);
  }
  return files;
}

}  // namespace tsk::io
