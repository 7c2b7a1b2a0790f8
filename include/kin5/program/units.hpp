/// @file program/units.hpp
/// Inch programs: the model holds millimetres, so a reader multiplies every length an inch
/// program writes by 25.4 (exact by definition of the inch) and a writer of an inch program
/// divides by it again. Lengths are the block's X Y Z, its arc centre and radius, and F while
/// feeds are per minute (in/min → mm/min); angles, tool-axis vectors and inverse-time F are not
/// lengths. A block's `metric` says which unit word the program gave.
#pragma once

#include <optional>

#include "block.hpp"

namespace kin5::program {

/// Millimetres in one inch.
inline constexpr double mm_per_inch = 25.4;

namespace detail {
/// Applies `f` to every length of `b` (F only when `per_minute`).
template <class F>
void each_length(block& b, bool per_minute, F f) {
  for (std::optional<double>* v : {&b.axes.x_mm, &b.axes.y_mm, &b.axes.z_mm})
    if (*v) **v = f(**v);
  if (b.arc && b.arc->centre_mm) *b.arc->centre_mm = {f(b.arc->centre_mm->x), f(b.arc->centre_mm->y), f(b.arc->centre_mm->z)};
  if (b.arc && b.arc->radius_mm) *b.arc->radius_mm = f(*b.arc->radius_mm);
  if (b.feed && per_minute) *b.feed = f(*b.feed);
}
}  // namespace detail

/// The lengths of `b`, written in inches, in millimetres (F only when `per_minute`).
inline void inches_to_mm(block& b, bool per_minute) {
  detail::each_length(b, per_minute, [](double v) { return v * mm_per_inch; });
}

/// The lengths of `b` in inches, to write an inch program (F only when `per_minute`).
inline void mm_to_inches(block& b, bool per_minute) {
  detail::each_length(b, per_minute, [](double v) { return v / mm_per_inch; });
}

/// The unit a program states before its first move (the `metric` of the first block that says
/// one), taken block by block: what a dialect that states its unit once at the top (Heidenhain's
/// `BEGIN PGM … MM|INCH`) writes there when the source says it a few blocks later (`G700`).
struct program_unit {
  std::optional<bool> metric;  ///< empty: no unit said before the first move
  bool moved = false;

  void take(const block& b) {
    if (!metric && !moved && b.metric) metric = b.metric;
    moved = moved || b.moves();
  }
};

}  // namespace kin5::program
