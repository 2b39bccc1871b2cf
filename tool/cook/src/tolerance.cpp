#include "hullcook/cook/cook.h"
#include "hullcook/core/error.h"

#include <cmath>
#include <cstdlib>

namespace hullcook {

Tolerance Tolerance::parse(const std::string& text) {
  std::string number = text;
  bool relative = false;
  if (!number.empty() && number.back() == '%') {
    relative = true;
    number.pop_back();
  } else if (number.size() > 2 && number.compare(number.size() - 2, 2, "px") == 0) {
    number.resize(number.size() - 2);
  }
  char* end = nullptr;
  double value = number.empty() ? NAN : std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value) ||
      value < 0) {
    throw UsageError("'" + text +
                     "' is not a tolerance: expected a non-negative number (input units) or a "
                     "percentage of the enclosing radius, e.g. 0.5 or 1%");
  }
  return relative ? Tolerance{value / 100.0, true} : Tolerance{value, false};
}

}  // namespace hullcook
