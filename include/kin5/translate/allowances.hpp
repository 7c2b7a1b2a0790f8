/// @file translate/allowances.hpp
/// Named refusals and the user's knowing consent to them. A construct kin5 cannot translate
/// faithfully is refused: an error at its block that names the construct and the option that
/// resolves it. Some refusals guard a guess rather than an impossibility; those have a name in
/// `allowable_refusals`, and `--allow NAME` (an `allowances` entry) turns that refusal into a
/// warning the run lists among its allowed constructs (`translation::allowed`): the user has
/// accepted the guess knowingly. Every other refusal stays an error whatever is allowed.
/// @code
///   kin5::allowances allow;
///   if (!allow.add("unset-rotary")) usage_error(kin5::allowable_names());
///   result.refuse({where, "rotary axis A has no value yet", "unset-rotary", "--allow unset-rotary"}, allow);
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "../program/block.hpp"

namespace kin5 {

/// One refusal the user may turn into a warning with `--allow NAME`.
struct allowable_refusal {
  std::string_view name;  ///< as `--allow` spells it
  std::string_view help;  ///< what is accepted, for a user
};

/// Every refusal `--allow` can demote, by name (docs/user-guide.md lists them).
inline constexpr std::array<allowable_refusal, 1> allowable_refusals{{
    {"unset-rotary", "a rotary axis the program has given no value yet is taken as 0 (the machine's zero pose)"},
}};

/// Whether `name` is in `allowable_refusals`.
constexpr bool is_allowable(std::string_view name) {
  for (const auto& r : allowable_refusals)
    if (r.name == name) return true;
  return false;
}

/// "unset-rotary, …": the names of `allowable_refusals`, in order.
inline std::string allowable_names() {
  std::string names;
  for (const auto& r : allowable_refusals) names += (names.empty() ? "" : ", ") + std::string(r.name);
  return names;
}

/// The named refusals a run turns into warnings.
class allowances {
 public:
  /// Allows refusal `name`; false (nothing changed) when no refusal has that name.
  bool add(std::string_view name) {
    if (!is_allowable(name)) return false;
    if (!allows(name)) names_.emplace_back(name);
    return true;
  }
  /// Whether refusal `name` is allowed.
  bool allows(std::string_view name) const { return std::find(names_.begin(), names_.end(), name) != names_.end(); }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::vector<std::string> names_;
};

}  // namespace kin5
