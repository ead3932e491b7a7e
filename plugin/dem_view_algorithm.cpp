#include "plugin/dem_view_algorithm.h"

#include <qgsprocessing.h>
#include <qgsprocessingfeedback.h>
#include <qgsprocessingparameters.h>
#include <qgsproviderregistry.h>
#include <qgsrasterlayer.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QIcon>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "io/write/output_set.h"
#include "io/write/path_clashes.h"
#include "plugin/line_output.h"
#include "plugin/plugin_paths.h"
#include "plugin/qgis_compat.h"
#include "plugin/raster_grid.h"

namespace tsk::plugin {

DemViewAlgorithm::DemViewAlgorithm() = default;
DemViewAlgorithm::~DemViewAlgorithm() = default;

QIcon DemViewAlgorithm::icon() const {
  return QIcon(iconPath());
}
QString DemViewAlgorithm::svgIconPath() const {
  return iconPath();
}

void DemViewAlgorithm::addWithHelp(QgsProcessingParameterDefinition* parameter, const QString& help,
                                   bool advanced) {
  parameter->setHelp(help);
  if (advanced) parameter->setFlags(parameter->flags() | kAdvanced);
  addParameter(parameter);
}

void DemViewAlgorithm::addWithHelp(const HelpedParameter& parameter) {
  addWithHelp(parameter.definition, parameter.help, parameter.advanced);
}

void DemViewAlgorithm::addWithHelp(const std::vector<HelpedParameter>& parameters) {
  for (const HelpedParameter& parameter : parameters) addWithHelp(parameter);
}

namespace {

std::string localPath(const QString& path) {
  return QFile::encodeName(path).toStdString();
}

QString qtPath(const std::string& path) {
  return QDir::toNativeSeparators(QFile::decodeName(path.c_str()));
}

}  // namespace

void DemViewAlgorithm::refuseClashingOutputs(const QVariantMap& parameters,
                                             QgsProcessingContext& context) const {
  std::vector<io::NamedFile> outputs, inputs;
  for (const QgsProcessingParameterDefinition* output : destinationParameterDefinitions()) {
    // A temporary output is a new file, named with the output's default extension: read as a
    // target it would be yet another new file (and folder), which no run writes.
    const bool temporary = isTemporaryOutput(*this, parameters, output->name());
    const auto* destination = dynamic_cast<const QgsProcessingDestinationParameter*>(output);
    const QString target = temporary
                               ? QStringLiteral("%1.%2").arg(
                                     QgsProcessing::TEMPORARY_OUTPUT,
                                     destination ? destination->defaultFileExtension() : QString())
                               : outputTarget(*this, parameters, output->name(), context);
    // As on the command line: other formats lose the colour tables, or change the values.
    const QString suffix = QFileInfo(target).suffix().toLower();
    if (output->type() == QgsProcessingParameterRasterDestination::typeName() &&
        !target.isEmpty() && suffix != QLatin1String("tif") && suffix != QLatin1String("tiff")) {
      throw QgsProcessingException(tr("%1 must be a GeoTIFF (.tif): %2 is another format.")
                                       .arg(output->description(), target));
    }
    if (temporary) continue;  // a new file clashes with nothing
    // A plain path is written whole; "ogr:..." adds a layer to the file.
    outputs.push_back({output->description().toStdString(), localPath(destinationFile(target)),
                       !target.startsWith(QLatin1String("ogr:"))});
  }
  for (const QgsProcessingParameterDefinition* input : parameterDefinitions()) {
    if (input->type() != QgsProcessingParameterRasterLayer::typeName()) continue;
    const QgsRasterLayer* layer = parameterAsRasterLayer(parameters, input->name(), context);
    if (!layer) continue;
    const QString path = QgsProviderRegistry::instance()
                             ->decodeUri(layer->providerType(), layer->source())
                             .value(QStringLiteral("path"))
                             .toString();
    inputs.push_back({input->description().toStdString(), localPath(path)});
  }
  // Refuses too a source GDAL would hang on (a pipe behind a VRT), before any read.
  const std::optional<io::PathClash> clash =
      withCoreErrors([&] { return io::find_clash(outputs, inputs); });
  if (!clash) return;
  const QString output = QString::fromStdString(clash->output.name);
  const QString other = QString::fromStdString(clash->other.name);
  if (clash->with_input) {
    throw QgsProcessingException(
        tr("%1 would be written into %2, the file of %3, which this algorithm reads; choose "
           "another file.")
            .arg(output, qtPath(clash->file), other));
  }
  throw QgsProcessingException(
      tr("%1 and %2 would both be written to %3, one over the other; choose different files, "
         "or save both to one GeoPackage with a layer name each.")
          .arg(other, output, qtPath(clash->file)));
}

bool DemViewAlgorithm::checkParameterValues(const QVariantMap& parameters,
                                            QgsProcessingContext& context, QString* message) const {
  if (!QgsProcessingAlgorithm::checkParameterValues(parameters, context, message)) return false;
  const LayersToLoadKept kept(context);  // the run lists what it writes
  try {
    refuseClashingOutputs(parameters, context);
    // The parameters the widgets cannot check alone (the control point below the column
    // cut-off), read by a fresh instance since reading keeps them.
    const std::unique_ptr<QgsProcessingAlgorithm> probe(create());
    withCoreErrors(
        [&] { return static_cast<DemViewAlgorithm&>(*probe).readParameters(parameters, context); });
    // A DEM the run would refuse (a geographic CRS, a colour image) is refused before the run,
    // where the dialog shows it (it was said in the log after Run).
    if (QgsRasterLayer* layer =
            parameterAsRasterLayer(parameters, QStringLiteral("INPUT"), context)) {
      const RasterGrid probeGrid(layer, parameterAsInt(parameters, QStringLiteral("BAND"), context),
                                 context.transformContext());
    }
  } catch (const QgsProcessingException& e) {
    if (message) *message = e.what();
    return false;
  }
  return true;
}

bool DemViewAlgorithm::prepareAlgorithm(const QVariantMap& parameters,
                                        QgsProcessingContext& context,
                                        QgsProcessingFeedback* feedback) {
  mAzimuth = withCoreErrors([&] { return readParameters(parameters, context); });
  refuseClashingOutputs(parameters, context);
  QgsRasterLayer* layer = parameterAsRasterLayer(parameters, QStringLiteral("INPUT"), context);
  if (!layer) throw QgsProcessingException(invalidRasterError(parameters, QStringLiteral("INPUT")));
  const int band = parameterAsInt(parameters, QStringLiteral("BAND"), context);
  mRaster = std::make_unique<RasterGrid>(layer, band, context.transformContext());
  mDemName = tr("%1, band %2").arg(layer->name()).arg(band);
  for (const QString& note : mRaster->notes()) {
    if (feedback) feedback->pushWarning(note);
  }
  return true;
}

QVariantMap DemViewAlgorithm::processAlgorithm(const QVariantMap& parameters,
                                               QgsProcessingContext& context,
                                               QgsProcessingFeedback* feedback) {
  io::OutputSet outputs(LineOutput::waitingOn(feedback));
  const QVariantMap results = writeOutputs(parameters, context, feedback);
  withCoreErrors([&] { outputs.commit(); });
  return results;
}

void DemViewAlgorithm::addWithProgress(LineOutput& output, QgsFeature& feature,
                                       QgsProcessingFeedback* feedback, std::size_t total,
                                       double from) {
  output.add(feature);
  if (feedback && ++mWritten % 500 == 0) {
    if (feedback->isCanceled()) throw QgsProcessingException(tr("Cancelled."));
    feedback->setProgress(from + (100.0 - from) * static_cast<double>(mWritten) /
                                     static_cast<double>(std::max<std::size_t>(1, total)));
  }
}

RasterGrid& DemViewAlgorithm::readRaster(QgsProcessingFeedback* feedback, double progressTo) {
  mWritten = 0;
  mRaster->read(mAzimuth, feedback, 0.0, progressTo);
  return *mRaster;
}

ProgressFn DemViewAlgorithm::progressBetween(QgsProcessingFeedback* feedback, double from,
                                             double to) {
  return [feedback, from, to](double fraction) {
    if (!feedback) return true;
    feedback->setProgress(from + (to - from) * fraction);
    return !feedback->isCanceled();
  };
}

SilhouetteResult DemViewAlgorithm::runSilhouettes(const SilhouetteParams& params,
                                                  QgsProcessingFeedback* feedback, double from,
                                                  double to) {
  return withCoreErrors([&] {
    SilhouetteResult result =
        sketch_held_dem(mRaster->held(), params, progressBetween(feedback, from, to));
    SharedParameters::logFilter(result.filter, feedback);
    return result;
  });
}

void DemViewAlgorithm::releaseRaster() {
  mRaster.reset();
}

}  // namespace tsk::plugin
