#pragma once

#include <stdexcept>
#include <string>

namespace tsk {

// Bad input or parameters: the message is meant for the user.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// `value` as a person writes it in a message: 45, 22.5, 0.001, 1e+300, nan (where std::to_string
// gives 45.000000).
std::string number_text(double value);

// The caller's progress callback asked to stop.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace tsk
