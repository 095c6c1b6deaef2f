#pragma once

#include <string>
#include <string_view>

// The few JSON pieces the tools' reports write by hand.
namespace mrd::tools {

// %.9g, or null when not finite (JSON has no NaN or Inf).
std::string json_number(double x);
// Quoted, with quotes, backslashes and control characters escaped.
std::string json_string(std::string_view text);

}  // namespace mrd::tools
