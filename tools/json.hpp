#pragma once

#include <nlohmann/json.hpp>
#include <string>

// The tools' JSON documents are built with nlohmann-json: numbers round-trip (shortest form
// that reads back to the same double), NaN and Inf become null, strings are escaped UTF-8.
namespace mrd::tools {

// Keys in the order the writer inserts them, as docs/CLOSING-THE-LOOP.md lists them.
using Json = nlohmann::ordered_json;

// Two-space indented, newline-terminated. Bytes that are not UTF-8 (a file name in Latin-1)
// become U+FFFD instead of failing the whole document.
inline std::string json_text(const Json& document) {
  return document.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace mrd::tools
