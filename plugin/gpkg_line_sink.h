// A feature sink that writes lines straight into a GeoPackage layer that QGIS created, through
// the gpkg library (gpkg_line_appender.h): QGIS makes the file, the layer and its fields as for
// any output, and the features go in without QGIS's and GDAL's per-feature work.
#pragma once

#include <qgsfeaturesink.h>
#include <qgsfields.h>

#include <QByteArray>
#include <QString>
#include <memory>
#include <vector>

#include "io/gpkg/gpkg_line_appender.h"

namespace tsk::plugin {

class GpkgLineSink : public QgsFeatureSink {
 public:
  // Layer `layer` of the GeoPackage at `path`, made by QGIS with `fields`, closed and still empty.
  GpkgLineSink(const QString& path, const QString& layer, const QgsFields& fields);
  ~GpkgLineSink() override;

  bool addFeature(QgsFeature& feature,
                  QgsFeatureSink::Flags flags = QgsFeatureSink::Flags()) override;
  bool addFeatures(QgsFeatureList& features,
                   QgsFeatureSink::Flags flags = QgsFeatureSink::Flags()) override;
  QString lastError() const override { return mError; }
  // Adds `stroke` with the attributes of strokeFields() without making a feature of it; false
  // (with lastError()) when it cannot, as addFeature.
  bool addStroke(const Stroke& stroke);

  // Writes the layer's extent, count, spatial index and description (when `note` is not empty)
  // and closes the file; throws tsk::Error. Without it, nothing of the features is kept.
  void finish(const QString& note);

 private:
  std::unique_ptr<io::GpkgFileAppender> mFile;
  std::vector<QByteArray> mTexts;  // text attributes of the feature being added
  std::vector<StrokePoint> mPoints;
  std::vector<double> mMeasures;
  QString mError;
};

}  // namespace tsk::plugin
