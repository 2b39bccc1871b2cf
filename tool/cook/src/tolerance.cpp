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
  // The bound keeps every tolerance, scaled to output units, within what the formats store.
  constexpr double kLargest = 1e9;
  if (number.empty() || end != number.c_str() + number.size() || !(value >= 0.0) ||
      !(value <= kLargest)) {
    throw UsageError("'" + text +
                     "' is not a tolerance: expected a number from 0 to 1e9 (input units) or a "
                     "percentage of the enclosing radius, e.g. 0.5 or 1%");
  }
  return relative ? Tolerance{value / 100.0, true} : Tolerance{value, false};
}

}  // namespace hullcook
