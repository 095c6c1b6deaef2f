#include "record/mat_v5_check.hpp"

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

namespace mrd::record {

namespace {

constexpr std::uint32_t kInt32 = 5, kMatrix = 14, kCompressed = 15;
constexpr std::uint32_t kCellClass = 1, kStructClass = 2, kObjectClass = 3, kSparseClass = 5;
constexpr std::size_t kHeader = 128, kMaxRank = 32, kMaxDepth = 16;

class V5Checker {
 public:
  V5Checker(bool swap, std::size_t max_inflated) : swap_(swap), max_inflated_(max_inflated) {}

  // The top level: a sequence of (possibly compressed) matrices.
  std::string check_file(std::string_view data) {
    for (std::size_t at = kHeader; at < data.size();) {
      const auto tag = read_tag(data, at);
      if (!tag || tag->small) return where(at) + "a truncated or malformed tag";
      if (tag->size > data.size() - at - 8) return where(at) + "its size runs past the end of the file";
      const std::string_view body = data.substr(at + 8, tag->size);
      std::string why;
      if (tag->type == kCompressed) {
        std::string inflated;
        why = inflate(body, inflated);
        if (why.empty()) why = check_elements(inflated, 0, nullptr);
      } else if (tag->type == kMatrix) {
        why = check_matrix(body, 0);
      }
      if (!why.empty()) return where(at) + why;
      at += 8 + tag->size;
    }
    return "";
  }

 private:
  struct Tag {
    std::uint32_t type = 0;
    std::uint32_t size = 0;  // of the data
    bool small = false;      // type and size share 4 bytes, the data is the next 4
  };

  static std::string where(std::size_t at) { return "element at byte " + std::to_string(at) + ": "; }

  std::uint32_t u32(std::string_view data, std::size_t at) const {
    std::uint32_t v = 0;
    std::memcpy(&v, data.data() + at, 4);
    return swap_ ? __builtin_bswap32(v) : v;
  }

  std::optional<Tag> read_tag(std::string_view data, std::size_t at) const {
    if (data.size() < 8 || at > data.size() - 8) return std::nullopt;
    const std::uint32_t first = u32(data, at);
    if ((first >> 16) != 0) return Tag{first & 0xFFFF, first >> 16, true};
    return Tag{first, u32(data, at + 4), false};
  }

  // The elements of `data`, one after another, each fitting; matrices checked inside.
  std::string check_elements(std::string_view data, std::size_t depth, std::size_t* matrices) {
    for (std::size_t at = 0; at < data.size();) {
      const auto tag = read_tag(data, at);
      if (!tag) return "a truncated tag";
      if (tag->small) {
        if (tag->size > 4) return "a small element of more than 4 bytes";
        at += 8;
        continue;
      }
      if (tag->size > data.size() - at - 8) return "an element runs past the one that holds it";
      if (tag->type == kMatrix) {
        if (const std::string why = check_matrix(data.substr(at + 8, tag->size), depth); !why.empty()) return why;
        if (matrices != nullptr) ++*matrices;
      }
      at += 8 + tag->size + (tag->type == kCompressed ? 0 : (8 - tag->size % 8) % 8);
    }
    return "";
  }

  // A matrix: array flags, dimensions, name, then what its class holds.
  std::string check_matrix(std::string_view body, std::size_t depth) {
    if (body.empty()) return "";  // an empty matrix element is an empty variable
    if (depth > kMaxDepth) return "cells or structs nested more than " + std::to_string(kMaxDepth) + " deep";
    std::size_t at = 0;
    const auto flags = read_tag(body, at);
    if (!flags || flags->small || flags->size != 8 || body.size() < 16) return "no array flags";
    const std::uint32_t cls = u32(body, 8) & 0xFF;
    at = 16;
    const auto dims = read_tag(body, at);
    if (!dims || dims->type != kInt32) return "no dimensions";
    const std::size_t rank = dims->size / 4;
    const std::size_t dims_at = at + (dims->small ? 4 : 8);
    if (rank < 1 || rank > kMaxRank || dims_at + dims->size > body.size())
      return "a rank of " + std::to_string(rank) + " (1 to " + std::to_string(kMaxRank) + " fit)";
    std::size_t elements = 1;
    std::string shape;
    for (std::size_t i = 0; i < rank; ++i) {
      const std::uint32_t d = u32(body, dims_at + 4 * i);
      if (i > 0) shape.push_back('x');
      shape.append(std::to_string(d));
      if (d != 0 && elements > body.size() / d) elements = body.size() + 1;  // only compared below
      else elements *= d;
    }
    at = dims_at + dims->size + (dims->small ? 0 : (8 - dims->size % 8) % 8);
    const std::string_view rest = body.substr(std::min(at, body.size()));
    std::size_t holds = 0;
    if (const std::string why = check_elements(rest, depth + 1, &holds); !why.empty()) return why;
    const bool holds_matrices = cls == kCellClass || cls == kStructClass || cls == kObjectClass;
    // Any other array but a sparse one stores each element in at least one byte (MATLAB may store
    // doubles as uint8), and libmatio allocates the full class size for every declared element.
    if (!holds_matrices && cls != kSparseClass && elements > rest.size())
      return "a " + shape + " array in " + std::to_string(rest.size()) + " bytes";
    // Each cell, and each field of each struct element, is a matrix element of its own.
    if (holds_matrices) {
      const std::size_t per_element = cls == kCellClass ? 1 : fields_of(rest, cls == kObjectClass);
      if (per_element != 0 && elements > holds / per_element)
        return "a cell array or struct of " + std::to_string(elements) + " elements holds " + std::to_string(holds) +
               " matrices";
    }
    return "";
  }

  // A struct's fields: after its name (and an object's class name), the length of a field name
  // and the names, all of that length. check_elements has seen that these elements fit.
  std::size_t fields_of(std::string_view rest, bool object) const {
    std::size_t at = 0;
    std::uint32_t value = 0;  // of the last 4-byte element skipped
    const auto skip = [&] {
      const auto tag = read_tag(rest, at);
      if (!tag) return std::optional<Tag>();
      const std::size_t data_at = at + (tag->small ? 4 : 8);
      at = tag->small ? at + 8 : at + 8 + tag->size + (8 - tag->size % 8) % 8;
      if (tag->size == 4 && data_at + 4 <= rest.size()) value = u32(rest, data_at);
      return tag;
    };
    if (!skip() || (object && !skip())) return 0;  // the name, the class name
    const auto length = skip();
    if (!length || length->size != 4 || value == 0) return 0;
    const std::uint32_t name_length = value;
    const auto names = skip();
    return names ? names->size / name_length : 0;
  }

  std::string inflate(std::string_view compressed, std::string& out) const {
    z_stream z{};
    if (inflateInit(&z) != Z_OK) return "zlib cannot start";
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
    z.avail_in = static_cast<uInt>(compressed.size());
    std::vector<char> chunk(std::size_t{64} << 10);
    int status = Z_OK;
    while (status == Z_OK && out.size() <= max_inflated_) {
      z.next_out = reinterpret_cast<Bytef*>(chunk.data());
      z.avail_out = static_cast<uInt>(chunk.size());
      status = ::inflate(&z, Z_NO_FLUSH);
      out.append(chunk.data(), chunk.size() - z.avail_out);
      if (status == Z_BUF_ERROR && z.avail_in == 0) break;  // no more input: a truncated stream
    }
    inflateEnd(&z);
    if (out.size() > max_inflated_) return "inflates to more than " + std::to_string(max_inflated_) + " bytes";
    if (status != Z_STREAM_END && status != Z_BUF_ERROR) return "a damaged compressed element";
    return "";
  }

  bool swap_;
  std::size_t max_inflated_;
};

}  // namespace

std::string check_mat_v5_structure(std::string_view file, std::size_t max_inflated) {
  if (file.size() < kHeader) return "shorter than a .mat header (128 bytes)";
  const std::string_view endian = file.substr(126, 2);
  const std::uint16_t version = static_cast<std::uint16_t>(static_cast<unsigned char>(file[124]) |
                                                           static_cast<unsigned char>(file[125]) << 8);
  const bool swap = endian == "MI";
  if (endian != "IM" && !swap) return "";  // not v5: libmatio decides
  if ((swap ? static_cast<std::uint16_t>(version >> 8 | version << 8) : version) != 0x0100) return "";
  return V5Checker(swap, max_inflated).check_file(file);
}

}  // namespace mrd::record
