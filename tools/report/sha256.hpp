#pragma once

#include <string>
#include <string_view>

// SHA-256 (FIPS 180-4, from OpenSSL's libcrypto) of the input files a report names, so a reader can
// tell that the file on their disk is the one the report was made from.
namespace mrd::tools {

// Lower-case hex digest of `bytes`.
[[nodiscard]] std::string sha256_hex(std::string_view bytes);

// Of a file's contents; "" when it cannot be read.
[[nodiscard]] std::string sha256_file(const std::string& path);

}  // namespace mrd::tools
