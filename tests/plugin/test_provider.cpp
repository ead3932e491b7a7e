// The provider: help for every algorithm and parameter, the German translation.
#include <map>

#include "plugin/shared_parameters.h"
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("every algorithm and parameter has help, and numbers show what they can take",
          "[plugin]") {
  algorithm();  // registers the provider
  const QgsProcessingProvider* provider =
      QgsApplication::processingRegistry()->providerById(QStringLiteral("terrainsketch"));
  REQUIRE(provider != nullptr);
  REQUIRE(provider->algorithms().size() == 8);
  for (const QgsProcessingAlgorithm* alg : provider->algorithms()) {
    CAPTURE(alg->id().toStdString());
    CHECK(alg->shortHelpString().size() > 100);
    for (const QgsProcessingParameterDefinition* parameter : alg->parameterDefinitions()) {
      CAPTURE(parameter->name().toStdString());
      CHECK(parameter->help().size() > 10);
      const auto* number = dynamic_cast<const QgsProcessingParameterNumber*>(parameter);
      if (!number || number->dataType() != plugin::kDoubleNumber) continue;
      // The widget rounds to its decimals: both the default and the minimum must survive.
      const int decimals = number->metadata()
                               .value(QStringLiteral("widget_wrapper"))
                               .toMap()
                               .value(QStringLiteral("decimals"), 6)
                               .toInt();
      CHECK(decimals <= 3);
      const double scale = std::pow(10.0, decimals);
      for (const double value : {number->defaultValue().toDouble(), number->minimum()})
        CHECK(std::round(value * scale) / scale == Approx(value).margin(1e-12));
    }
  }
}

TEST_CASE("every enum lists the core's choices in their order, wherever it appears", "[plugin]") {
  algorithm();  // registers the provider
  const QgsProcessingProvider* provider =
      QgsApplication::processingRegistry()->providerById(QStringLiteral("terrainsketch"));
  REQUIRE(provider != nullptr);
  // The first words of each choice's label, in the tables' order (core/choice_names.h).
  const std::map<QString, QStringList> starts = {
      {QStringLiteral("FILTER"), {QStringLiteral("Adapted"), QStringLiteral("Fixed")}},
      {QStringLiteral("ADAPT"), {QStringLiteral("The whole"), QStringLiteral("Each")}},
      {QStringLiteral("STROKES"), {QStringLiteral("Drawn"), QStringLiteral("Exact")}},
      {QStringLiteral("GEOMETRY"), {QStringLiteral("Map"), QStringLiteral("Plan oblique")}},
      {QStringLiteral("PLACEMENT"), {QStringLiteral("Far end"), QStringLiteral("Near and far")}}};
  int seen = 0;
  for (const QgsProcessingAlgorithm* alg : provider->algorithms()) {
    for (const QgsProcessingParameterDefinition* parameter : alg->parameterDefinitions()) {
      const auto* choice = dynamic_cast<const QgsProcessingParameterEnum*>(parameter);
      if (!choice) continue;
      CAPTURE(alg->id().toStdString(), parameter->name().toStdString());
      REQUIRE(starts.count(parameter->name()) == 1);
      const QStringList& expected = starts.at(parameter->name());
      REQUIRE(choice->options().size() == expected.size());
      for (int k = 0; k < expected.size(); ++k) CHECK(choice->options()[k].startsWith(expected[k]));
      ++seen;
    }
  }
  CHECK(seen >= 12);  // the filter's two in six algorithms, strokes, geometry and placement
}

TEST_CASE("the German translation loads for the de locale", "[plugin][i18n]") {
  // The code under test is linked into this binary, so name the built plugin's i18n folder.
  const QString folder = QStringLiteral(TSK_PLUGIN_DIR "/i18n");
  REQUIRE(plugin::installTranslation(QStringLiteral("de"), folder));
  const plugin::TerrainSketchProvider provider;
  CHECK(provider.name() == QStringLiteral("Geländeskizze"));
  std::unique_ptr<QgsProcessingAlgorithm> alg(algorithm());
  CHECK(alg->displayName() == QStringLiteral("Silhouetten (faktisch und formuliert)"));
  CHECK(alg->parameterDefinition("VE")->description() == QStringLiteral("Überhöhung"));
  plugin::removeTranslation();
  CHECK(provider.name() == QStringLiteral("Terrain sketch"));
  CHECK_FALSE(plugin::installTranslation(QStringLiteral("xx"), folder));
}

TEST_CASE("numbers in the log are written as the user's locale writes them", "[plugin][i18n]") {
  // German users read "23.9 %" with an English decimal point.
  const QString folder = QStringLiteral(TSK_PLUGIN_DIR "/i18n");
  REQUIRE(plugin::installTranslation(QStringLiteral("de"), folder));
  const QLocale before;
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  FilterReport report;
  report.choice.mode = FilterMode::adaptive;
  report.median_slope_pct = 23.9;
  report.scale = 0.996;
  report.cutoffs.row_cut_pct = 19.9;
  RecordingFeedback feedback;
  plugin::SharedParameters::logFilter(report, &feedback);
  QLocale::setDefault(before);
  plugin::removeTranslation();
  REQUIRE(feedback.infos.size() == 1);
  CHECK(feedback.infos[0].contains(QStringLiteral("Hangneigung ist 23,9 %")));
  CHECK(feedback.infos[0].contains(QStringLiteral("Zeile 19,9 %")));
}

TEST_CASE("the plugin speaks the language QGIS was started in", "[plugin][i18n]") {
  // `qgis --lang de` sets QGIS's translation, which the profile's locale does not show.
  const QString before = QgsApplication::instance()->translation();
  QgsApplication::setTranslation(QStringLiteral("de"));
  CHECK(plugin::qgisLanguage() == QStringLiteral("de"));
  QgsApplication::setTranslation(before);
  if (before.isEmpty()) CHECK(plugin::qgisLanguage() == QgsApplication::locale());
}

TEST_CASE("the Silhouettes help names every stage figure and the units of every field",
          "[plugin]") {
  const std::unique_ptr<QgsProcessingAlgorithm> alg(algorithm()->create());
  const QString help = alg->shortHelpString();
  for (const char* figure :
       {"HIDDEN_PCT", "OCCLUDING_PCT", "CSET_PCT", "FSET_PCT", "TSET_PCT", "GSET_PCT",
        "FACTUAL_STROKES", "FORMULATED_STROKES", "candidate set", "filtered set", "thinned set",
        "generalised set", "mean_dist (ground distance", "mean_z (m)"}) {
    CAPTURE(figure);
    CHECK(help.contains(QString::fromLatin1(figure)));
  }
}
