"""What the desktop tests' scripts (run inside QGIS with --code) share: the report written, and
QGIS left without a prompt."""
import json
import os

from qgis.core import QgsProject
from qgis.utils import iface


def finish(report):
    """Writes `report` to report.json in TSK_E2E_OUT and exits QGIS."""
    QgsProject.instance().setDirty(False)  # no "save project?" prompt on exit
    with open(os.path.join(os.environ["TSK_E2E_OUT"], "report.json"), "w") as f:
        json.dump(report, f, indent=2)
    iface.actionExit().trigger()
