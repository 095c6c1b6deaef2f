#pragma once

#include <string>
#include <string_view>

namespace mrd::record {

// Checks the element structure of a v5 .mat file before libmatio reads it. libmatio allocates
// what a tag declares before it reads the bytes behind it: a dimensions tag of 4 GB is a rank of
// 2^30 and an 8 GB allocation, a cell array of 2^31 cells 16 GB of pointers. Here every element
// must fit inside the one that holds it (compressed ones are inflated, up to `max_inflated`
// bytes), a rank is at most 32, an array other than a sparse one has at least a byte per
// element it declares, and a cell array or struct holds as many elements as its dimensions say. "" when the file passes, else what is wrong ("element at byte 128: ...").
// Files of other versions (v7.3 is HDF5) pass unchecked.
[[nodiscard]] std::string check_mat_v5_structure(std::string_view file, std::size_t max_inflated);

}  // namespace mrd::record
