#include "plugin/filter_diagram_algorithm.h"

#include <qgsprocessingfeedback.h>

#include <QFile>
#include <algorithm>

#include "core/base/errors.h"
#include "core/method/silhouettes.h"
#include "io/pages/filter_diagram_page.h"
#include "io/write/output_files.h"
#include "plugin/raster_grid.h"

namespace tsk::plugin {

QString FilterDiagramAlgorithm::name() const {
  return QStringLiteral("filterdiagram");
}
QString FilterDiagramAlgorithm::displayName() const {
  return tr("Slope filter diagram");
}

QString FilterDiagramAlgorithm::shortHelpString() const {
  return tr(
      "Plots, for every cell, the magnitude of its column slope (along the view) against "
      "its row slope (across the view): all cells grey, the candidate set red, the cells "
      "the slope filter keeps black, over the filter's removal region in grey with the "
      "control point circled. Run it with different filter parameters to see what they "
      "keep before drawing the silhouettes. The page opens in the Results Viewer.");
}

FilterDiagramAlgorithm* FilterDiagramAlgorithm::createInstance() const {
  return new FilterDiagramAlgorithm();
}

void FilterDiagramAlgorithm::initAlgorithm(const QVariantMap&) {
  addWithHelp(SharedParameters::dem());
  addWithHelp(SharedParameters::view(true));
  addWithHelp(SharedParameters::filter());
  addWithHelp(new QgsProcessingParameterFileDestination(
                  QStringLiteral("OUTPUT"), tr("Slope filter diagram"), tr("HTML files (*.html)")),
              tr("HTML page with the diagram as SVG."));
}

double FilterDiagramAlgorithm::readParameters(const QVariantMap& parameters,
                                              QgsProcessingContext& context) {
  mParams.view = SharedParameters::readView(*this, parameters, context);
  SharedParameters::readFilter(*this, parameters, context, mParams);
  mParams.validate();
  return mParams.view.azimuth_deg;
}

QVariantMap FilterDiagramAlgorithm::writeOutputs(const QVariantMap& parameters,
                                                 QgsProcessingContext& context,
                                                 QgsProcessingFeedback* feedback) {
  const RasterGrid& raster = readRaster(feedback, 40);
  const SilhouetteResult result = runSilhouettes(mParams, feedback, 40, 90);
  const std::string html = withCoreErrors([&] {
    return filter_diagram_html(slope_scatter_of(raster.oriented(), raster.frame(), result),
                               result.filter.cutoffs, tr("Slope filter").toStdString());
  });
  const QString path = parameterAsFileOutput(parameters, QStringLiteral("OUTPUT"), context);
  // Whole or not at all, as every file output (io/output_files.h).
  withCoreErrors([&] { io::write_text_file(QFile::encodeName(path).toStdString(), html); });
  releaseRaster();
  return {{QStringLiteral("OUTPUT"), path}};
}

}  // namespace tsk::plugin
