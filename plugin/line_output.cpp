#include "plugin/line_output.h"

#include <gdal.h>
#include <ogr_api.h>
#include <qgsdatasourceuri.h>
#include <qgsprocessing.h>
#include <qgsprocessingparameters.h>
#include <qgsproviderregistry.h>
#include <qgsvectorfilewriter.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <optional>

#include "io/read/gdal_util.h"
#include "io/write/output_set.h"
#include "io/write/vector_writer.h"
#include "plugin/core_errors.h"
#include "plugin/gpkg_line_sink.h"
#include "plugin/qgis_compat.h"
#include "plugin/stroke_features.h"

namespace tsk::plugin {
namespace {

// QGIS's own messages for a sink that cannot be made or written, which it keeps protected for the
// algorithms: reached through a class of its own, never made, rather than a friend.
struct SinkErrors : QgsProcessingAlgorithm {
  using QgsProcessingAlgorithm::invalidSinkError;
  using QgsProcessingAlgorithm::writeFeatureError;
};

// Where an output destination puts its layer on disk: see destinationFile().
struct FileTarget {
  QString path;            // empty: not a file
  bool addsLayer = false;  // to a file that existed before
};

FileTarget fileTarget(const QString& target) {
  const QString path = destinationFile(target);
  return {path, target.startsWith(QLatin1String("ogr:")) && QFileInfo(path).isFile()};
}

// The OGR driver QGIS writes a file at `path` with, named by its extension.
QString driverOf(const QString& path) {
  return QgsVectorFileWriter::driverForExtension(QFileInfo(path).suffix());
}

// Drawn strokes' weights are their M values: a file format that keeps none loses them, and the
// styles then draw every stroke at one width. Said before the run, where the user can change it.
void warnOfLostWeights(const QString& path, bool measured, QgsProcessingFeedback* feedback) {
  if (!measured || path.isEmpty() || !feedback) return;
  const QString driver = driverOf(path);
  if (driver.isEmpty() || io::keeps_m_values(driver.toStdString())) return;
  feedback->pushWarning(
      LineOutput::tr("%1 keeps no M values, so the drawn strokes' weights (their taper and depth, "
                     "which the styles draw) are left out; GeoPackage, FlatGeobuf, Shapefile or "
                     "CSV keep them.")
          .arg(driver));
}

// The options QGIS creates a new file at `path` and its layer with: io's writer's for its format
// (a SQLite file made SpatiaLite, so that its measured layer reads back as LineStringM, its layer
// then told so: QGIS's own default for SQLite, FORMAT=WKB, is refused there).
struct NewFileOptions {
  QStringList file, layer;
};
NewFileOptions newFileOptions(const QString& path) {
  NewFileOptions options;
  for (const std::string& option : io::new_file_options(driverOf(path).toStdString()))
    options.file << QString::fromStdString(option);
  if (options.file.contains(QStringLiteral("SPATIALITE=YES")))
    options.layer << QStringLiteral("FORMAT=SPATIALITE");
  return options;
}

// The files beside `path` named after it: those its format keeps with it (a shapefile's .shx and
// .dbf, GML's .xsd, a GeoPackage's -journal), and the file itself.
QStringList filesNamedAfter(const QString& path) {
  const QFileInfo info(path);
  return info.dir().entryList({info.completeBaseName() + QStringLiteral(".*")},
                              QDir::Files | QDir::Hidden);
}

// Whether `path`, written whole by QGIS, ends as its format ends. The GDAL drivers of GeoJSON,
// KML, GML and CSV ignore writes that fail, so on a full disk they leave a file cut short that
// QGIS reports as written; the drivers of other formats report them.
bool endsWhole(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  const bool geojson = suffix == QLatin1String("geojson") || suffix == QLatin1String("json");
  if (!geojson && suffix != QLatin1String("kml") && suffix != QLatin1String("gml") &&
      suffix != QLatin1String("csv")) {
    return true;
  }
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return false;
  file.seek(std::max<qint64>(0, file.size() - 64));
  const QByteArray tail = file.readAll();
  if (suffix == QLatin1String("csv")) return tail.endsWith('\n');
  if (!geojson) {
    return tail.trimmed().endsWith(suffix == QLatin1String("kml") ? "</kml>"
                                                                  : "FeatureCollection>");
  }
  // Without white space, the last feature (or none) and the end of the list and the collection:
  // no feature holds "}]}", as "]" follows only coordinates in it.
  QByteArray compact;
  for (const char c : tail)
    if (!std::isspace(static_cast<unsigned char>(c))) compact += c;
  return compact.endsWith("}]}") || compact.endsWith("[]}");
}

// The value of an output parameter that writes to `path` instead, as the dialog's definition
// (with its project and options) or as a plain path.
QVariant redirected(const QVariant& value, const QString& path) {
  if (value.userType() != qMetaTypeId<QgsProcessingOutputLayerDefinition>()) return path;
  QgsProcessingOutputLayerDefinition definition = value.value<QgsProcessingOutputLayerDefinition>();
  definition.sink = QgsProperty::fromValue(path);
  return QVariant::fromValue(definition);
}

// The layer `context` is to load as `from` on completion loaded as `to` instead.
void moveLayerToLoad(QgsProcessingContext& context, const QString& from, const QString& to) {
  QMap<QString, QgsProcessingContext::LayerDetails> layers = context.layersToLoadOnCompletion();
  if (!layers.contains(from)) return;
  layers.insert(to, layers.take(from));
  context.setLayersToLoadOnCompletion(layers);
}

void dropLayer(const QString& path, const QString& layer) {
  GDALDatasetH dataset = GDALOpenEx(QFile::encodeName(path).constData(),
                                    GDAL_OF_VECTOR | GDAL_OF_UPDATE, nullptr, nullptr, nullptr);
  if (!dataset) return;
  for (int k = 0; k < GDALDatasetGetLayerCount(dataset); ++k) {
    if (layer == QString::fromUtf8(OGR_L_GetName(GDALDatasetGetLayer(dataset, k)))) {
      GDALDatasetDeleteLayer(dataset, k);
      break;
    }
  }
  GDALClose(dataset);
}

}  // namespace

QString LineOutput::stagedFile(const QString& path) {
  io::OutputSet* set = io::OutputSet::current();
  if (!set) throw QgsProcessingException(tr("Internal error: no output set for %1.").arg(path));
  return withCoreErrors(
      [&] { return QFile::decodeName(set->stage(QFile::encodeName(path).toStdString()).c_str()); });
}

io::OutputSet::Waiting LineOutput::waitingOn(QgsProcessingFeedback* feedback) {
  const auto waiting = [feedback](const std::filesystem::path& destination) {
    if (feedback) {
      feedback->pushInfo(
          tr("Waiting for another run writing %1.").arg(QFile::decodeName(destination.c_str())));
    }
  };
  const auto stop = [feedback] {
    if (feedback && feedback->isCanceled()) throw Cancelled();
  };
  return {waiting, stop};
}

std::unique_ptr<io::DestinationLock> LineOutput::lockDestination(const QString& path,
                                                                 QgsProcessingFeedback* feedback) {
  const std::filesystem::path destination = QFile::encodeName(path).toStdString();
  const io::OutputSet::Waiting wait = waitingOn(feedback);
  return withCoreErrors([&] {
    return std::make_unique<io::DestinationLock>(
        destination, [&] { wait.waiting(destination); }, wait.stop);
  });
}

void deleteDataset(const QString& path) {
  const QByteArray file = QFile::encodeName(path);
  if (GDALDeleteDataset(nullptr, file.constData()) != CE_None) QFile::remove(path);
}

QString outputTarget(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
                     const QString& key, QgsProcessingContext& context) {
  const LayersToLoadKept kept(context);
  return QgsProcessingParameters::parameterAsOutputLayer(algorithm.parameterDefinition(key),
                                                         parameters, context);
}

bool isTemporaryOutput(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
                       const QString& key) {
  QVariant value = parameters.value(key);
  if (!value.isValid()) {
    const QgsProcessingParameterDefinition* definition = algorithm.parameterDefinition(key);
    if (definition) value = definition->defaultValue();
  }
  if (value.userType() == qMetaTypeId<QgsProcessingOutputLayerDefinition>())
    value = value.value<QgsProcessingOutputLayerDefinition>().sink.staticValue();
  return value.toString() == QgsProcessing::TEMPORARY_OUTPUT;
}

QString destinationFile(const QString& target) {
  if (target.startsWith(QLatin1String("ogr:"))) return QgsDataSourceUri(target.mid(4)).database();
  static const QRegularExpression providerPrefix(QStringLiteral("^[A-Za-z_]{2,}:"));
  if (target.isEmpty() || providerPrefix.match(target).hasMatch()) return {};
  return target;
}

LineOutput::LineOutput(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
                       const QString& key, QgsProcessingContext& context, const QgsFields& fields,
                       const QgsCoordinateReferenceSystem& crs, QgsProcessingFeedback* feedback,
                       bool measured)
    : mParameters(parameters),
      mKey(key),
      mFields(fields),
      mExceptionsAtStart(std::uncaught_exceptions()) {
  const QgsProcessingParameterDefinition* definition = algorithm.parameterDefinition(key);
  const QString target = outputTarget(algorithm, parameters, key, context);
  const FileTarget file = fileTarget(target);
  warnOfLostWeights(file.path, measured, feedback);
  // A file written whole is staged, and put in place with the run's other outputs when the run has
  // done (DemViewAlgorithm::processAlgorithm): one that fails leaves the earlier file whole. A
  // layer added to a file is written there, one run at a time, and dropped if the run fails.
  const bool staged = !file.path.isEmpty() && !target.startsWith(QLatin1String("ogr:"));
  QVariantMap sinkParameters = parameters;
  QString stagedPath;
  if (staged) {
    stagedPath = stagedFile(file.path);
    sinkParameters.insert(key, redirected(parameters.value(key), stagedPath));
  } else if (!file.path.isEmpty()) {
    mLock = lockDestination(file.path, feedback);
    if (!file.addsLayer) mFilesBefore = filesNamedAfter(file.path);
  }
  mStaged = staged;
  const bool gpkg = !file.addsLayer && target.endsWith(QLatin1String(".gpkg"), Qt::CaseInsensitive);
  std::optional<io::BulkLoadPages> pages;  // QGIS creates the file, in this thread
  if (gpkg) pages.emplace();
  NewFileOptions options = file.addsLayer ? NewFileOptions() : newFileOptions(file.path);
  if (gpkg)
    options.layer << QStringLiteral("SPATIAL_INDEX=NO");  // GpkgLineSink builds it at the end
  mSink.reset(QgsProcessingParameters::parameterAsSink(
      definition, sinkParameters, fields, measured ? kLineStringM : kLineString, crs, context,
      mDestination, QgsFeatureSink::SinkFlags(), QVariantMap(), options.file, options.layer));
  pages.reset();
  if (!mSink) throw QgsProcessingException(SinkErrors::invalidSinkError(parameters, key));
  const QVariantMap parts =
      QgsProviderRegistry::instance()->decodeUri(QStringLiteral("ogr"), mDestination);
  if (!file.path.isEmpty()) {
    mFile = parts.value(QStringLiteral("path")).toString();
    if (file.addsLayer) mAddedLayer = parts.value(QStringLiteral("layerName")).toString();
  }
  if (staged) {
    // QGIS loads, and the results name, the file where it will be.
    const QString staging = mDestination;
    mDestination.replace(stagedPath, file.path);
    moveLayerToLoad(context, staging, mDestination);
  }
  if (!gpkg) return;
  // QGIS made the file and its empty layer; closed, the lines go in through SQLite.
  mSink.reset();
  try {
    auto sink = withCoreErrors([&] {
      return std::make_unique<GpkgLineSink>(
          mFile, parts.value(QStringLiteral("layerName")).toString(), fields);
    });
    mGpkg = sink.get();
    mSink = std::move(sink);
  } catch (...) {
    discard();  // no destructor runs for an output whose constructor throws
    throw;
  }
}

LineOutput::~LineOutput() {
  if (!mFinished || std::uncaught_exceptions() > mExceptionsAtStart) discard();
}

void LineOutput::add(QgsFeature& feature) {
  if (!mSink->addFeature(feature, QgsFeatureSink::FastInsert)) failWriting();
}

void LineOutput::add(const Stroke& stroke) {
  if (!mGpkg) {
    QgsFeature feature = strokeFeature(stroke, mFields);
    add(feature);
  } else if (!mGpkg->addStroke(stroke)) {
    failWriting();
  }
}

void LineOutput::finish(const QString& note) {
  if (mGpkg) withCoreErrors([&] { mGpkg->finish(note); });
  mGpkg = nullptr;
  closeSink();
  if (!mFile.isEmpty() && mAddedLayer.isEmpty() && !endsWhole(mFile)) {
    throw QgsProcessingException(
        tr("Could not write %1 whole: the file ends cut short. Is the disk full?").arg(mFile));
  }
  mFinished = true;
}

// QGIS's writer flushes and closes the file. A driver may tell of a write that failed as it closes
// only to GDAL's error handler, which QGIS logs: FlatGeobuf, which then copies its features from
// a temporary file, wrote a file cut short and the run succeeded.
void LineOutput::closeSink() {
  std::string failure;
  {
    const io::GdalErrorCapture capture;
    mSink.reset();
    failure = capture.first_failure();
  }
  if (failure.empty()) return;
  throw QgsProcessingException(
      tr("Could not write %1 whole: %2")
          .arg(mFile.isEmpty() ? mDestination : mFile, QString::fromStdString(failure)));
}

void LineOutput::failWriting() const {
  throw QgsProcessingException(SinkErrors::writeFeatureError(mSink.get(), mParameters, mKey));
}

void LineOutput::discard() noexcept {
  mGpkg = nullptr;
  mSink.reset();  // rolls a GeoPackage's rows back; closes QGIS's writer
  // A staged file goes with its staging folder, when the run's output set does.
  if (mStaged || mFile.isEmpty() || !QFileInfo(mFile).isFile()) return;
  if (mAddedLayer.isEmpty()) {
    // QGIS made the file, or wrote it over: it goes, with the files made beside it that GDAL
    // does not count as the dataset's (GML's .xsd, the journal that a write which failed on a
    // full disk leaves beside a GeoPackage).
    deleteDataset(mFile);
    const QDir folder = QFileInfo(mFile).dir();
    for (const QString& name : filesNamedAfter(mFile))
      if (!mFilesBefore.contains(name)) QFile::remove(folder.filePath(name));
  } else {
    dropLayer(mFile, mAddedLayer);
  }
}

}  // namespace tsk::plugin
