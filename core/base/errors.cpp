#include "core/base/errors.h"

#include <sstream>

namespace tsk {

std::string number_text(double value) {
  std::ostringstream text;
  text.precision(10);
  text << value;
  return text.str();
}

}  // namespace tsk
