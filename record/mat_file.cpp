#include "record/mat_file.hpp"

#include <hdf5.h>
#include <matio.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>

#include "common/file_error.hpp"
#include "record/csv.hpp"
#include "record/mat_v5_check.hpp"

namespace mrd::record {

namespace {

// libmatio reports through a log function, by default on stderr; its last complaint goes into
// our message instead. HDF5 (v7.3 files) prints its own error stack unless told not to.
thread_local std::string last_complaint;

void keep_complaint(int level, char* message) {
  if (level <= MATIO_LOG_LEVEL_CRITICAL && message != nullptr) last_complaint = message;
}

void quiet_libraries() {
  static std::once_flag once;
  std::call_once(once, [] {
    Mat_LogInitFunc("mrd", keep_complaint);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  });
}

std::string complaint() {
  return last_complaint.empty() ? std::string() : " (libmatio: " + last_complaint + ")";
}

std::string what_it_is(const matvar_t& v) {
  switch (v.class_type) {
    case MAT_C_DOUBLE:
    case MAT_C_SINGLE:
    case MAT_C_INT8:
    case MAT_C_UINT8:
    case MAT_C_INT16:
    case MAT_C_UINT16:
    case MAT_C_INT32:
    case MAT_C_UINT32:
    case MAT_C_INT64:
    case MAT_C_UINT64: return v.isComplex ? "complex" : "";
    case MAT_C_CELL: return "a cell array";
    case MAT_C_STRUCT: return "a struct";
    case MAT_C_OBJECT: return "an object";
    case MAT_C_CHAR: return "text";
    case MAT_C_SPARSE: return "a sparse matrix";
    case MAT_C_FUNCTION: return "a function handle";
    case MAT_C_OPAQUE: return "an opaque object (a string, a table, ...)";
    case MAT_C_EMPTY: break;
  }
  return "of no class libmatio reads";
}

template <typename T>
void append_as_doubles(const void* data, std::size_t n, std::vector<double>& out) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    T value;
    std::memcpy(&value, bytes + i * sizeof(T), sizeof(T));
    out.push_back(static_cast<double>(value));
  }
}

struct VarDeleter {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using Var = std::unique_ptr<matvar_t, VarDeleter>;

}  // namespace

struct MatFile::Handle {
  mat_t* mat = nullptr;
  ~Handle() {
    if (mat != nullptr) Mat_Close(mat);
  }
};

MatFile::MatFile(const std::string& path) : path_(path), handle_(std::make_unique<Handle>()) {
  quiet_libraries();
  {
    if (std::string why; !readable_file(path, why)) throw InputError(path + ": cannot open the file: " + why);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path + ": cannot open the file: " + open_failure_reason(path));
    const std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    if (const std::string why = check_mat_v5_structure(bytes, kMaxMatElements * sizeof(double) + (1 << 20));
        !why.empty())
      throw InputError(path + ": a damaged .mat file: " + why);
  }
  last_complaint.clear();
  handle_->mat = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  if (handle_->mat == nullptr)
    throw InputError(path + ": not a MATLAB .mat file libmatio reads (v5 or v7.3)" + complaint());
  while (Var info{Mat_VarReadNextInfo(handle_->mat)}) {
    MatVariable v;
    v.name = info->name != nullptr ? info->name : "";
    if (info->dims != nullptr && info->rank > 0) v.dims.assign(info->dims, info->dims + info->rank);
    v.not_numeric = what_it_is(*info);
    variables_.push_back(std::move(v));
  }
}

MatFile::~MatFile() = default;

std::vector<double> MatFile::read(const MatVariable& v) const {
  const auto fail = [&](const std::string& why) {
    return InputError(path_ + ": variable '" + v.name + "': " + why + complaint());
  };
  const std::size_t n = v.elements();
  if (n > kMaxMatElements)
    throw fail("more than " + std::to_string(kMaxMatElements) + " elements: not a run this reader takes");
  last_complaint.clear();
  const Var var{Mat_VarRead(handle_->mat, v.name.c_str())};
  if (!var || var->data == nullptr) throw fail("cannot be read");
  if (!what_it_is(*var).empty()) throw fail("is " + what_it_is(*var) + ", not numbers");
  const std::size_t size = Mat_SizeOf(var->data_type);
  std::size_t read_n = 1;
  for (int i = 0; i < var->rank; ++i) read_n *= var->dims[i];
  if (read_n != n || size == 0 || var->nbytes / size < n) throw fail("its data does not match its size");
  std::vector<double> out;
  out.reserve(n);
  switch (var->data_type) {
    case MAT_T_DOUBLE: append_as_doubles<double>(var->data, n, out); break;
    case MAT_T_SINGLE: append_as_doubles<float>(var->data, n, out); break;
    case MAT_T_INT8: append_as_doubles<std::int8_t>(var->data, n, out); break;
    case MAT_T_UINT8: append_as_doubles<std::uint8_t>(var->data, n, out); break;
    case MAT_T_INT16: append_as_doubles<std::int16_t>(var->data, n, out); break;
    case MAT_T_UINT16: append_as_doubles<std::uint16_t>(var->data, n, out); break;
    case MAT_T_INT32: append_as_doubles<std::int32_t>(var->data, n, out); break;
    case MAT_T_UINT32: append_as_doubles<std::uint32_t>(var->data, n, out); break;
    case MAT_T_INT64: append_as_doubles<std::int64_t>(var->data, n, out); break;
    case MAT_T_UINT64: append_as_doubles<std::uint64_t>(var->data, n, out); break;
    default: throw fail("its data is not numbers");
  }
  return out;
}

}  // namespace mrd::record
