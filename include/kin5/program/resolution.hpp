/// @file program/resolution.hpp
/// How finely a program writes its numbers: the largest number of decimals seen per word class
/// (linear X Y Z I J K R, angle A B C, tool-axis vector components, feed F, speed S). A
/// value written with d decimals is known to within half a unit of its last place, 0.5·10⁻ᵈ:
/// the translation keeps at least this many decimals in its output and takes half a unit of the
/// angular resolution as the default angle tolerance (`translate/angle_tolerance.hpp`).
/// @code
///   kin5::program::number_resolution r;   // X10.1234 A30.5 → linear 4, angle 1
///   r.angle_decimals = 3;
///   r.merge(other);                        // the larger count per class
/// @endcode
#pragma once

#include <optional>

namespace kin5::program {

/// Decimals a writer uses per word class (each dialect's `write_options` has these four).
struct word_decimals {
  int linear = 3;  ///< X Y Z, I J K, R
  int angle = 3;   ///< A B C
  int feed = 1;    ///< F and S
  int vector = 7;  ///< tool-axis vector components
  friend bool operator==(const word_decimals&, const word_decimals&) = default;
};

/// Largest number of decimals written per word class; empty where the program writes none.
struct number_resolution {
  std::optional<int> linear_decimals;  ///< X Y Z, arc centres I J K, radius R (mm or inch as written)
  std::optional<int> angle_decimals;   ///< A B C, degrees
  std::optional<int> vector_decimals;  ///< tool-axis vector components (APT GOTO i,j,k)
  std::optional<int> feed_decimals;    ///< F
  std::optional<int> speed_decimals;   ///< S

  friend bool operator==(const number_resolution&, const number_resolution&) = default;

  /// Whether no class has been seen.
  bool empty() const { return *this == number_resolution{}; }

  /// Takes, per class, the larger count of `this` and `other`.
  void merge(const number_resolution& other) {
    auto take = [](std::optional<int>& mine, const std::optional<int>& theirs) {
      if (theirs && (!mine || *theirs > *mine)) mine = theirs;
    };
    take(linear_decimals, other.linear_decimals);
    take(angle_decimals, other.angle_decimals);
    take(vector_decimals, other.vector_decimals);
    take(feed_decimals, other.feed_decimals);
    take(speed_decimals, other.speed_decimals);
  }
};

}  // namespace kin5::program
