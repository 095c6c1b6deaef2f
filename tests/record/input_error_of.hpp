#pragma once

#include <string>

#include "record/csv.hpp"

namespace mrd::record::testing {

// The InputError message `read` throws, or "" when it returns: the tests compare messages word
// for word.
template <typename Read>
std::string input_error_of(Read&& read) {
  try {
    read();
  } catch (const record::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace mrd::record::testing
