#include "plugin/gpkg_line_sink.h"

#include <qgsfeature.h>
#include <qgsgeometry.h>
#include <qgslinestring.h>

namespace tsk::plugin {

GpkgLineSink::GpkgLineSink(const QString& path, const QString& layer, const QgsFields& fields)
    : mFile(std::make_unique<io::GpkgFileAppender>(path.toStdString(), layer.toStdString())),
      mTexts(static_cast<std::size_t>(fields.count())) {}

GpkgLineSink::~GpkgLineSink() = default;

bool GpkgLineSink::addFeature(QgsFeature& feature, QgsFeatureSink::Flags) {
  try {
    io::GpkgLineAppender& lines = mFile->lines();
    const QgsAttributes attributes = feature.attributes();
    for (int k = 0; k < attributes.count() && k < static_cast<int>(mTexts.size()); ++k) {
      const QVariant& value = attributes.at(k);
      switch (value.isValid() && !value.isNull() ? value.userType() : QMetaType::UnknownType) {
        case QMetaType::QString:
          mTexts[static_cast<std::size_t>(k)] = value.toString().toUtf8();
          lines.set(k, mTexts[static_cast<std::size_t>(k)].constData());
          break;
        case QMetaType::Int:
        case QMetaType::LongLong:
          lines.set(k, static_cast<std::int64_t>(value.toLongLong()));
          break;
        case QMetaType::Double:
          lines.set(k, value.toDouble());
          break;
        default:
          lines.set_null(k);
      }
    }
    const QgsGeometry geometry = feature.geometry();
    const auto* line = qgsgeometry_cast<const QgsLineString*>(geometry.constGet());
    if (!line) throw Error("a feature without a line");
    mPoints.resize(static_cast<std::size_t>(line->numPoints()));
    mMeasures.resize(line->isMeasure() ? mPoints.size() : 0);
    for (int k = 0; k < line->numPoints(); ++k) {
      mPoints[static_cast<std::size_t>(k)] = {line->xAt(k), line->yAt(k)};
      if (line->isMeasure()) mMeasures[static_cast<std::size_t>(k)] = line->mAt(k);
    }
    lines.add(mPoints, mMeasures);
    return true;
  } catch (const Error& e) {
    mError = QString::fromStdString(e.what());
    return false;
  }
}

bool GpkgLineSink::addStroke(const Stroke& stroke) {
  try {
    io::GpkgLineAppender& lines = mFile->lines();
    set_stroke_attributes(lines, stroke);
    lines.add(stroke.points, stroke.weights);
    return true;
  } catch (const Error& e) {
    mError = QString::fromStdString(e.what());
    return false;
  }
}

bool GpkgLineSink::addFeatures(QgsFeatureList& features, QgsFeatureSink::Flags flags) {
  for (QgsFeature& feature : features)
    if (!addFeature(feature, flags)) return false;
  return true;
}

void GpkgLineSink::finish(const QString& note) {
  mFile->finish(note.toStdString());
}

}  // namespace tsk::plugin
