"""Regenerates resources/models/silhouettes_over_hillshade.model3 with PyQGIS.

Model: DEM (any CRS) -> gdal:warpreproject to a metric CRS -> native:hillshade and
terrainsketch:silhouettes on the reprojected DEM. Outputs: hillshade, factual, formulated.
    QT_QPA_PLATFORM=offscreen /usr/bin/python3 scripts/make_model.py \
        BUILD/qgis-plugin/terrain_sketch_plugin
"""
import ctypes
import os
import sys

from qgis.core import (QgsApplication, QgsCoordinateReferenceSystem, QgsProcessingModelAlgorithm,
                       QgsProcessingModelChildAlgorithm, QgsProcessingModelChildParameterSource,
                       QgsProcessingModelOutput, QgsProcessingModelParameter,
                       QgsProcessingParameterCrs, QgsProcessingParameterRasterLayer)

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "resources", "models", "silhouettes_over_hillshade.model3")


def child(model, alg_id, child_id, description, sources, outputs):
    c = QgsProcessingModelChildAlgorithm(alg_id)
    c.setChildId(child_id)
    c.setDescription(description)
    for name, source in sources.items():
        c.addParameterSources(name, [source])
    model_outputs = {}
    for output_name, label in outputs.items():
        o = QgsProcessingModelOutput(label)
        o.setChildOutputName(output_name)
        o.setChildId(child_id)
        model_outputs[label] = o
    c.setModelOutputs(model_outputs)
    model.addChildAlgorithm(c)


def main():
    app = QgsApplication([], False)
    app.initQgis()
    sys.path.append("/usr/share/qgis/python/plugins")
    from processing.core.Processing import Processing
    Processing.initialize()
    lib = ctypes.CDLL(os.path.join(sys.argv[1], "libterrain_sketch_provider.so"))
    lib.terrain_sketch_register_provider()

    model = QgsProcessingModelAlgorithm("Silhouettes over hillshade", "Terrain sketch")
    model.setHelpContent({"ALG_DESC": "Reprojects a DEM to a metric CRS, then draws its hillshade "
                                      "and its factual and formulated silhouettes."})
    fixed = QgsProcessingModelChildParameterSource.fromStaticValue
    model_param = QgsProcessingModelChildParameterSource.fromModelParameter
    from_child = QgsProcessingModelChildParameterSource.fromChildOutput

    model.addModelParameter(QgsProcessingParameterRasterLayer("dem", "DEM"),
                            QgsProcessingModelParameter("dem"))
    model.addModelParameter(QgsProcessingParameterCrs("crs", "Metric CRS",
                                                      QgsCoordinateReferenceSystem("EPSG:32616")),
                            QgsProcessingModelParameter("crs"))
    child(model, "gdal:warpreproject", "warp", "Reproject to a metric CRS",
          {"INPUT": model_param("dem"), "TARGET_CRS": model_param("crs"),
           "RESAMPLING": fixed(1), "OUTPUT": fixed("TEMPORARY_OUTPUT")}, {})
    child(model, "native:hillshade", "hillshade", "Hillshade",
          {"INPUT": from_child("warp", "OUTPUT"), "Z_FACTOR": fixed(2.5), "AZIMUTH": fixed(300),
           "V_ANGLE": fixed(40)}, {"OUTPUT": "Hillshade"})
    child(model, "terrainsketch:silhouettes", "silhouettes", "Silhouettes",
          {"INPUT": from_child("warp", "OUTPUT"), "BAND": fixed(1), "AZIMUTH": fixed(90),
           "GEOMETRY": fixed(0)},
          {"FACTUAL": "Factual silhouettes", "FORMULATED": "Formulated silhouettes"})
    if not model.toFile(OUT):
        print("could not write", OUT, file=sys.stderr)
        return 1
    print("wrote", os.path.normpath(OUT))
    return 0


if __name__ == "__main__":
    sys.exit(main())
