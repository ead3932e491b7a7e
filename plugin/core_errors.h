// Turns the core's exceptions into QgsProcessingException with a message for the QGIS log.
#pragma once

#include <qgsexception.h>

#include <QCoreApplication>
#include <new>

#include "core/base/errors.h"

namespace tsk::plugin {

class CoreErrors {
  Q_DECLARE_TR_FUNCTIONS(CoreErrors)

 public:
  // Runs `work`, rethrowing the core's errors, cancellation and memory exhaustion as
  // QgsProcessingException.
  template <typename Work>
  static auto run(Work&& work) -> decltype(work()) {
    try {
      return work();
    } catch (const Cancelled&) {
      throw QgsProcessingException(tr("Cancelled."));
    } catch (const Error& e) {
      throw QgsProcessingException(QString::fromStdString(e.what()));
    } catch (const std::bad_alloc&) {
      throw QgsProcessingException(tr("Not enough memory for this raster."));
    }
  }
};

template <typename Work>
auto withCoreErrors(Work&& work) -> decltype(work()) {
  return CoreErrors::run(std::forward<Work>(work));
}

}  // namespace tsk::plugin
