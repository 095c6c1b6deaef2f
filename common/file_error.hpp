#pragma once

#include <string>

namespace mrd {

// Why PATH could not be opened for reading, as the system says it ("No such file or directory",
// "Permission denied"), or "is a folder, not a file": a reader opened as an std::ifstream turns
// a folder into an empty file. Call it right after the failed open (it reads errno).
[[nodiscard]] std::string open_failure_reason(const std::string& path);

// True and an empty reason when PATH is a regular file (or a device, a pipe) that opens;
// otherwise false with open_failure_reason's text.
[[nodiscard]] bool readable_file(const std::string& path, std::string& reason);

}  // namespace mrd
