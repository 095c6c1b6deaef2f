#include "tests/record/support/mat_writer.hpp"

#include <matio.h>

#include <cstdint>

namespace mrd::record::testing {

MatVar vector_var(std::string name, std::vector<double> data) {
  const std::size_t n = data.size();
  return {std::move(name), std::move(data), n};
}

MatVar scalar_var(std::string name, double value) { return {std::move(name), {value}, 1}; }

namespace {

bool write_one(mat_t* mat, const MatVar& v, matio_compression compression) {
  std::size_t dims[3] = {v.rows, v.columns, 2};
  std::vector<float> singles(v.data.begin(), v.data.end());
  std::vector<std::int16_t> shorts;
  for (const double d : v.data) shorts.push_back(static_cast<std::int16_t>(d));
  std::vector<double> imaginary(v.data.size(), 1.0);
  mat_complex_split_t split{const_cast<double*>(v.data.data()), imaginary.data()};
  std::string text = v.text;
  std::size_t text_dims[2] = {1, text.size()};
  matvar_t* var = nullptr;
  void* data = const_cast<double*>(v.data.data());
  switch (v.kind) {
    case MatVar::Kind::kDouble: var = Mat_VarCreate(v.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, data, 0); break;
    case MatVar::Kind::kThreeD:
      dims[1] = v.columns / 2;
      var = Mat_VarCreate(v.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 3, dims, data, 0);
      break;
    case MatVar::Kind::kSingle:
      var = Mat_VarCreate(v.name.c_str(), MAT_C_SINGLE, MAT_T_SINGLE, 2, dims, singles.data(), 0);
      break;
    case MatVar::Kind::kInt16:
      var = Mat_VarCreate(v.name.c_str(), MAT_C_INT16, MAT_T_INT16, 2, dims, shorts.data(), 0);
      break;
    case MatVar::Kind::kComplex:
      var = Mat_VarCreate(v.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, &split, MAT_F_COMPLEX);
      break;
    case MatVar::Kind::kText:
      var = Mat_VarCreate(v.name.c_str(), MAT_C_CHAR, MAT_T_UINT8, 2, text_dims, text.data(), 0);
      break;
  }
  if (var == nullptr) return false;
  const bool ok = Mat_VarWrite(mat, var, compression) == 0;
  Mat_VarFree(var);
  return ok;
}

}  // namespace

bool write_mat(const std::string& path, MatVersion version, const std::vector<MatVar>& vars) {
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, version == MatVersion::kV73 ? MAT_FT_MAT73 : MAT_FT_MAT5);
  if (mat == nullptr) return false;
  bool ok = true;
  for (const MatVar& v : vars)
    ok = ok && write_one(mat, v, version == MatVersion::kV5Compressed ? MAT_COMPRESSION_ZLIB : MAT_COMPRESSION_NONE);
  return Mat_Close(mat) == 0 && ok;
}

}  // namespace mrd::record::testing
