#include "plugin/stroke_features.h"

#include <qgsgeometry.h>
#include <qgslinestring.h>

#include <cmath>

#include "plugin/qgis_compat.h"

namespace tsk::plugin {

QgsFields strokeFields() {
  QgsFields fields;
  fields.append(makeField(QStringLiteral("class"), FieldKind::Text));
  fields.append(makeField(QStringLiteral("cells"), FieldKind::Integer));
  for (const StrokeRealField& f : stroke_real_fields()) {
    fields.append(makeField(QString::fromLatin1(f.name), FieldKind::Real));
  }
  return fields;
}

QgsGeometry lineGeometry(const std::vector<StrokePoint>& points, const std::vector<double>& m) {
  QVector<double> xs, ys, ms;
  xs.reserve(static_cast<int>(points.size()));
  ys.reserve(static_cast<int>(points.size()));
  for (const StrokePoint& p : points) {
    xs << p.x;
    ys << p.y;
  }
  for (double v : m) ms << v;
  return QgsGeometry(new QgsLineString(xs, ys, QVector<double>(), ms));
}

QgsFeature strokeFeature(const Stroke& stroke, const QgsFields& fields) {
  QgsFeature feature(fields);
  QgsAttributes attributes;
  attributes.reserve(fields.count());
  attributes << QString::fromLatin1(stroke_class_name(stroke.cls)) << stroke.cells;
  for (const StrokeRealField& f : stroke_real_fields()) {
    const double value = stroke.*(f.member);
    attributes << (std::isfinite(value) ? QVariant(value) : QVariant());
  }
  feature.setAttributes(attributes);
  feature.setGeometry(lineGeometry(stroke.points, stroke.weights));
  return feature;
}

}  // namespace tsk::plugin
