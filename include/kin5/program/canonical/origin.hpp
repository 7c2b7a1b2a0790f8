/// @file program/canonical/origin.hpp
/// What every canonical operation carries of the block that caused it: where its statement
/// stands in the source (file, line, column) and the calls it ran in (`block::call_chain`). The
/// operations of one block share one origin.
///
/// `origin_fields` pairs each field of `block` an origin holds with its place there; the
/// mapping (`origin_of`, `place_origin`) and the field count of block_operations.hpp read the
/// list, so a field of the block that every operation should carry is one member here and one
/// pair in the list.
/// @code
///   kin5::program::block b;
///   b.where = {"part.ngc", 12, 1};
///   kin5::program::canonical::origin o = kin5::program::canonical::origin_of(b);   // o.where.line == 12
/// @endcode
#pragma once

#include <cstdint>
#include <string_view>
#include <tuple>
#include <utility>

#include "../block.hpp"

namespace kin5::program::canonical {

/// The block an operation comes from (see the file comment).
struct origin {
  source_location where;  ///< the first character of the block's statement
  std::uint32_t call_chain = 0;  ///< the calls it ran in: an id of the run's table (call_chain.hpp); 0: none
  friend bool operator==(const origin&, const origin&) = default;
};

/// Each field of `block` an `origin` holds, with the member that holds it.
inline constexpr auto origin_fields = std::make_tuple(std::pair{&block::where, &origin::where},
                                                      std::pair{&block::call_chain, &origin::call_chain});

/// The origin of every operation of `b`.
inline origin origin_of(const block& b) {
  origin o;
  std::apply([&](auto... field) { ((o.*field.second = b.*field.first), ...); }, origin_fields);
  return o;
}

/// Puts the fields of `o` back into `b`.
inline void place_origin(block& b, const origin& o) {
  std::apply([&](auto... field) { ((b.*field.first = o.*field.second), ...); }, origin_fields);
}

}  // namespace kin5::program::canonical
