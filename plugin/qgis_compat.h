// The few QGIS API names that differ between QGIS 3.22 (Qt5) and QGIS 3.36+/4 (Qt6).
#pragma once

#include <qgsconfig.h>
#include <qgsfield.h>
#include <qgsprocessing.h>
#include <qgsprocessingparameters.h>
#include <qgsrasterbandstats.h>
#include <qgsrasterminmaxorigin.h>
#include <qgssymbollayer.h>
#include <qgsunittypes.h>

namespace tsk::plugin {

#if _QGIS_VERSION_INT >= 33600
inline const auto kRangeStatistics =
    Qgis::RasterBandStatistic::Min | Qgis::RasterBandStatistic::Max;
constexpr auto kLineLayer = Qgis::ProcessingSourceType::VectorLine;
constexpr auto kPointLayer = Qgis::ProcessingSourceType::VectorPoint;
constexpr auto kAnyField = Qgis::ProcessingFieldParameterDataType::Any;
constexpr auto kLineString = Qgis::WkbType::LineString;
constexpr auto kLineStringM = Qgis::WkbType::LineStringM;
constexpr auto kDoubleNumber = Qgis::ProcessingNumberParameterType::Double;
constexpr auto kIntegerNumber = Qgis::ProcessingNumberParameterType::Integer;
constexpr auto kAdvanced = Qgis::ProcessingParameterFlag::Advanced;
constexpr auto kOptional = Qgis::ProcessingParameterFlag::Optional;
#else
constexpr int kRangeStatistics = QgsRasterBandStats::Min | QgsRasterBandStats::Max;
constexpr auto kLineLayer = QgsProcessing::TypeVectorLine;
constexpr auto kPointLayer = QgsProcessing::TypeVectorPoint;
constexpr auto kAnyField = QgsProcessingParameterField::Any;
constexpr auto kLineString = QgsWkbTypes::LineString;
constexpr auto kLineStringM = QgsWkbTypes::LineStringM;
constexpr auto kDoubleNumber = QgsProcessingParameterNumber::Double;
constexpr auto kIntegerNumber = QgsProcessingParameterNumber::Integer;
constexpr auto kAdvanced = QgsProcessingParameterDefinition::FlagAdvanced;
constexpr auto kOptional = QgsProcessingParameterDefinition::FlagOptional;
#endif

// A raster renderer's stretch over the cumulative cut of its values (the range limit became an
// enum of Qgis in 3.42).
#if _QGIS_VERSION_INT >= 34200
constexpr auto kCumulativeCut = Qgis::RasterRangeLimit::CumulativeCut;
#else
constexpr auto kCumulativeCut = QgsRasterMinMaxOrigin::CumulativeCut;
#endif

// The metre as the unit of a CRS (QgsCoordinateReferenceSystem::mapUnits()).
#if _QGIS_VERSION_INT >= 33000
constexpr auto kMetres = Qgis::DistanceUnit::Meters;
#else
constexpr auto kMetres = QgsUnitTypes::DistanceMeters;
#endif

// Symbol layers' data-defined properties, as keys of their property collection (an enum class of
// QgsSymbolLayer from 3.30).
#if _QGIS_VERSION_INT >= 33000
constexpr int kStrokeWidthProperty = static_cast<int>(QgsSymbolLayer::Property::StrokeWidth);
constexpr int kStrokeColorProperty = static_cast<int>(QgsSymbolLayer::Property::StrokeColor);
#else
constexpr int kStrokeWidthProperty = QgsSymbolLayer::PropertyStrokeWidth;
constexpr int kStrokeColorProperty = QgsSymbolLayer::PropertyStrokeColor;
#endif

enum class FieldKind { Text, Integer, Real };

// A field of the given kind (QVariant::Type in 3.x, QMetaType::Type from 3.38).
inline QgsField makeField(const QString& name, FieldKind kind) {
#if _QGIS_VERSION_INT >= 33800
  const QMetaType::Type type = kind == FieldKind::Text      ? QMetaType::QString
                               : kind == FieldKind::Integer ? QMetaType::Int
                                                            : QMetaType::Double;
#else
  const QVariant::Type type = kind == FieldKind::Text      ? QVariant::String
                              : kind == FieldKind::Integer ? QVariant::Int
                                                           : QVariant::Double;
#endif
  return QgsField(name, type);
}

}  // namespace tsk::plugin
