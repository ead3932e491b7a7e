// QGIS enum parameters over the core's tables of choices (choice_names.h): the options listed in
// the table's order, in the plugin's own words, and read back through the table, so that QGIS,
// the command line and the Python package name and order every choice alike.
#pragma once

#include <qgsprocessingalgorithm.h>
#include <qgsprocessingparameters.h>

#include <QStringList>

#include "core/method/choice_names.h"

namespace tsk::plugin {

// An enum parameter listing `table`'s choices, each worded by `label(value)`.
template <typename Enum, std::size_t N, typename Label>
QgsProcessingParameterEnum* choiceParameter(const QString& key, const QString& description,
                                            const ChoiceName<Enum> (&table)[N], Label label,
                                            Enum defaultValue) {
  QStringList options;
  for (const ChoiceName<Enum>& choice : table) options << label(choice.value);
  return new QgsProcessingParameterEnum(key, description, options, false,
                                        static_cast<int>(index_of(table, defaultValue)));
}

// The choice of `algorithm`'s enum parameter `key` over `table`.
template <typename Enum, std::size_t N>
Enum parameterAsChoice(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
                       const QString& key, QgsProcessingContext& context,
                       const ChoiceName<Enum> (&table)[N]) {
  const int index = QgsProcessingParameters::parameterAsEnum(algorithm.parameterDefinition(key),
                                                             parameters, context);
  return choice_at(table, index, key.toUtf8().constData());
}

}  // namespace tsk::plugin
