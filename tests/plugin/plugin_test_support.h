// What the plugin's headless tests share: running an algorithm of the provider on a raster with
// its outputs in a folder, feedback that keeps what it was told, a file size limit standing in for
// a full disk, and the core's result to compare with.
#pragma once

#include <gdal.h>
#include <gdal_utils.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>
#include <qgsapplication.h>
#include <qgsfeatureiterator.h>
#include <qgsprocessingcontext.h>
#include <qgsprocessingfeedback.h>
#include <qgsprocessingparameters.h>
#include <qgsprocessingprovider.h>
#include <qgsprocessingregistry.h>
#include <qgsprocessingutils.h>
#include <qgsrasterblock.h>
#include <qgsrasterdataprovider.h>
#include <qgsrasterlayer.h>
#include <qgsrasterrange.h>
#include <qgsvectorlayer.h>
#include <sys/resource.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <functional>
#include <memory>

#include "catch_compat.h"
#include "core/applications/diagnostics.h"
#include "core/applications/drape.h"
#include "core/applications/profile_plot.h"
#include "core/applications/pstrokes.h"
#include "core/method/plan_oblique.h"
#include "core/method/silhouettes.h"
#include "core/method/visibility.h"
#include "gdal_test_support.h"
#include "gpkg_index_check.h"
#include "io/read/dem_reader.h"
#include "plugin/provider.h"
#include "plugin/qgis_compat.h"
#include "plugin/raster_grid.h"
#include "plugin/translation.h"

namespace tsk::plugin_test {

using namespace tsk;

// Oriented profiles of a raster for a view, read window by window as a run reads them.
struct ViewStrips {
  DemSource source;
  OrientedFrame frame;
  StripLoader loader;
  ViewStrips(plugin::RasterGrid& grid, double azimuth)
      : source(grid.source()),
        frame(make_frame(source.grid, azimuth)),
        loader(frame, source.read) {}
};

// Whether two grids hold the same heights, NaN where either has none.
inline bool sameHeights(const HeightGrid& a, const HeightGrid& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const float x = a.data()[k], y = b.data()[k];
    if (!(x == y || (std::isnan(x) && std::isnan(y)))) return false;
  }
  return true;
}

// The heights of a raster's profiles for a view, read whole.
inline HeightGrid viewHeights(plugin::RasterGrid& grid, double azimuth) {
  ViewStrips strips(grid, azimuth);
  HeightGrid heights;
  strips.loader.load(0, strips.frame.profiles, heights);
  return heights;
}

// The lowest height of a raster read window by window, as a plan-oblique run reads it first.
inline double lowestOf(plugin::RasterGrid& grid) {
  const DemSource dem = grid.source();
  return dem_lowest_height(dem.grid.rows, dem.grid.cols, dem.read);
}

inline const QString kData = QStringLiteral(TSK_TEST_DATA);

inline QgsProcessingAlgorithm* algorithm() {
  static bool registered = false;
  if (!registered) {
    QgsApplication::processingRegistry()->addProvider(new plugin::TerrainSketchProvider());
    registered = true;
  }
  const QgsProcessingAlgorithm* alg = QgsApplication::processingRegistry()->algorithmById(
      QStringLiteral("terrainsketch:silhouettes"));
  REQUIRE(alg != nullptr);
  return alg->create();
}

// Keeps what the algorithm writes to the log.
class RecordingFeedback : public QgsProcessingFeedback {
 public:
  void reportError(const QString& error, bool fatal) override {
    errors << error;
    QgsProcessingFeedback::reportError(error, fatal);
  }
  void pushWarning(const QString& warning) override { warnings << warning; }
  void pushInfo(const QString& info) override { infos << info; }
  QStringList errors;
  QStringList warnings;
  QStringList infos;
};

struct Run {
  bool ok = false;
  QVariantMap results;
  QString error;
};

// Runs algorithm `id` with `extra` parameters on top of INPUT/BAND and outputs in `dir`.
// A memory output's layer stays in `context`, if given.
inline Run runAlgorithm(const QString& input, const QVariantMap& extra, const QTemporaryDir& dir,
                        RecordingFeedback* feedback = nullptr,
                        const QString& id = QStringLiteral("silhouettes"),
                        QgsProcessingContext* context = nullptr) {
  algorithm();  // registers the provider
  std::unique_ptr<QgsProcessingAlgorithm> alg(
      QgsApplication::processingRegistry()->algorithmById("terrainsketch:" + id)->create());
  QVariantMap params{{"INPUT", input},
                     {"BAND", 1},
                     {"FACTUAL", dir.filePath("factual.gpkg")},
                     {"FORMULATED", dir.filePath("formulated.gpkg")},
                     {"OUTPUT", dir.filePath(id == "profileplot" ? "out.gpkg" : "out.tif")}};
  for (auto it = extra.begin(); it != extra.end(); ++it) params.insert(it.key(), it.value());
  QgsProcessingContext ownContext;
  RecordingFeedback defaultFeedback;
  RecordingFeedback* log = feedback ? feedback : &defaultFeedback;
  Run run;
  run.results = alg->run(params, context ? *context : ownContext, log, &run.ok);
  run.error = log->errors.join('\n');
  return run;
}

// While alive, this process's files are limited to `bytes`: writes past it fail (EFBIG) as they
// would on a full disk, SIGXFSZ ignored meanwhile.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    REQUIRE(getrlimit(RLIMIT_FSIZE, &mBefore) == 0);
    mHandler = std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{bytes, mBefore.rlim_max};
    REQUIRE(setrlimit(RLIMIT_FSIZE, &limit) == 0);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &mBefore);
    std::signal(SIGXFSZ, mHandler);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit mBefore{};
  void (*mHandler)(int) = SIG_DFL;
};

// Both line outputs in `dir`, as files of `format` ("gpkg", "shp", ...).
inline QVariantMap outputsAs(const QTemporaryDir& dir, const char* format) {
  return {{"FACTUAL", dir.filePath(QStringLiteral("factual.%1").arg(format))},
          {"FORMULATED", dir.filePath(QStringLiteral("formulated.%1").arg(format))}};
}

// Runs algorithm `id` as runAlgorithm does and requires it to succeed.
inline Run runOk(const QString& input, const QVariantMap& extra, const QTemporaryDir& dir,
                 const QString& id) {
  Run run = runAlgorithm(input, extra, dir, nullptr, id);
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  return run;
}

// The DEM as the core reads it for the view from `azimuth`.
inline io::Dem coreDem(const QString& file, double azimuth = 90) {
  return io::read_dem(file.toStdString(), io::DemOptions(), azimuth);
}

// Runs the core directly on the same file through io's GDAL reader, as the command line does,
// with the algorithms' defaults: the filter adapted to the DEM (read window by window for it),
// drawn strokes.
inline SilhouetteResult coreResult(const QString& file, double azimuth, Geometry geometry) {
  const io::Dem dem = coreDem(file, azimuth);
  SilhouetteParams params;
  params.view.azimuth_deg = azimuth;
  params.geometry = geometry;
  params.adaptive.mode = FilterMode::adaptive;  // the algorithm's defaults
  params.strokes.mode = StrokeMode::drawn;
  const ResolvedParams run = adapt_filter(
      params, dem.grid, io::DemFile(file.toStdString(), io::DemOptions()).source().read);
  return run_silhouettes(dem.oriented, dem.frame, dem.geotransform, run, {}, dem.lowest_height);
}

// Cancels the run once progress reaches `at` percent.
class CancelAt : public RecordingFeedback {
 public:
  explicit CancelAt(double at, std::function<void()> onCancel = {}) {
    connect(this, &QgsFeedback::progressChanged, this, [this, at, onCancel](double progress) {
      if (progress < at || isCanceled()) return;
      if (onCancel) onCancel();
      cancel();
    });
  }
};

// The layer names of a vector file.
inline QStringList layerNames(const QString& path) {
  QStringList names;
  GDALDatasetH ds =
      GDALOpenEx(path.toUtf8().constData(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr);
  if (!ds) return names;
  for (int k = 0; k < GDALDatasetGetLayerCount(ds); ++k)
    names << QString::fromUtf8(OGR_L_GetName(GDALDatasetGetLayer(ds, k)));
  GDALClose(ds);
  return names;
}

}  // namespace tsk::plugin_test
