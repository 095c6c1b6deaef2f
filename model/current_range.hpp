#pragma once

namespace mrd::model {

// A closed interval of coil currents [A]: what a driver may command this period, or what can
// flow by the end of it.
struct CurrentRange {
  double lowest = 0.0;   // [A]
  double highest = 0.0;  // [A]
};

}  // namespace mrd::model
