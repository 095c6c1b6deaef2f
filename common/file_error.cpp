#include "common/file_error.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sys/stat.h>

namespace mrd {

std::string open_failure_reason(const std::string& path) {
  const int error = errno;
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) return "is a folder, not a file";
  return error != 0 ? std::strerror(error) : "cannot be read";
}

bool readable_file(const std::string& path, std::string& reason) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
    reason = "is a folder, not a file";
    return false;
  }
  errno = 0;
  const std::ifstream file(path, std::ios::binary);
  if (file) {
    reason.clear();
    return true;
  }
  reason = open_failure_reason(path);
  return false;
}

}  // namespace mrd
