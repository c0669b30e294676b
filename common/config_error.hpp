#pragma once
#include <stdexcept>
#include <string>

namespace hil {

// A scenario or machine file that cannot be used; the message names the field.
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace hil
