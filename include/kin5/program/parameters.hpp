/// @file program/parameters.hpp
/// Parameters used as constants, one table for every reader that reads them (Heidenhain
/// `Q1 = 5000`, Siemens `R1=5000` and `_F_CUT=5000`, ISO and LinuxCNC `#1=5000`, LinuxCNC
/// `#<feed> = 5000`): numbered parameters by number, named ones by the name the dialect
/// reads them as (`#<feed>`, `_F_CUT`). An assignment of a number
/// records the number as written; a later word whose value is the parameter (`FQ1`, `X=R1`,
/// `X#1`) reads as that number. The use is refused, with the reason, when the parameter was
/// never assigned in the file (its value is the machine's), was assigned anything but a number
/// (the line is named), is one the control sets (a `reserved` range), or the program has
/// control flow (its value would depend on the path taken). How an assignment is spelled, and
/// which assignments a dialect refuses outright, is each reader's; a use of a parameter whose
/// assignment was refused (`refuse`) is refused with no reason of its own (`why` empty): the
/// assignment's error is the one to read.
/// @code
///   kin5::program::parameter_table q{"Q"};
///   q.assign(1, kin5::program::parameter_literal{5000, "5000"}, 12);  // line 12: Q1 = 5000
///   std::string why;
///   if (const auto* v = q.value(1, why)) { /* v->value == 5000, v->written == "5000" */ }
/// @endcode
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "text.hpp"

namespace kin5::program {

/// A named parameter's name as LinuxCNC reads it: lower case, blanks removed, between
/// `#<` and `>` (`#<Feed Cut>` is `#<feedcut>`: LinuxCNC User Manual, "G-code Overview", "Named
/// Parameters"); `written` is what stands between them.
inline std::string named_parameter(std::string_view written) {
  std::string name = "#<";
  for (char c : written)
    if (!is_space(c)) name += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return name + ">";
}

/// A number assigned to a parameter: its value and its text as written (`+5000.50`).
struct parameter_literal {
  double value = 0;
  std::string written;

  /// The same number negated (`X-Q1`), its text with the sign turned.
  parameter_literal negated() const {
    std::string w = written;
    if (!w.empty() && w[0] == '-') w.erase(0, 1);
    else if (!w.empty() && w[0] == '+') w[0] = '-';
    else w.insert(0, 1, '-');
    return {-value, std::move(w)};
  }
};

/// Parameters a control sets itself: numbers `first` … `last`, and why they are no constant.
struct reserved_parameters {
  long first = 0, last = 0;
  std::string why;  ///< follows "parameter Q120 is ": "set by the control (Q100-Q199), …"
};

/// What a file has assigned to each parameter so far (see the file comment).
struct parameter_table {
  struct assignment {
    std::optional<parameter_literal> literal;  ///< the number, when one was assigned
    std::size_t line = 0;                      ///< where it was assigned
    bool refused = false;                      ///< the assignment itself was refused
  };

  std::string prefix;  ///< how a parameter is named: "Q" (Q1), "R" (R1), "#" (#1)
  std::vector<reserved_parameters> reserved;
  std::map<long, assignment> assigned;
  std::map<std::string, assignment, std::less<>> named;  ///< by name as the dialect reads it
  std::string control_flow;  ///< the first control-flow statement of the file ("CALL LBL"), if any
  std::size_t control_flow_line = 0;

  explicit parameter_table(std::string name_prefix = {}, std::vector<reserved_parameters> control_set = {})
      : prefix(std::move(name_prefix)), reserved(std::move(control_set)) {}

  /// The parameter's name as the program writes it: "Q1", "#100".
  std::string name(long n) const { return prefix + std::to_string(n); }

  /// Records at `line` that parameter `n` was assigned `literal`, or something else (nullopt).
  void assign(long n, std::optional<parameter_literal> literal, std::size_t line) {
    assigned[n] = {std::move(literal), line};
  }

  /// Records at `line` that an assignment to parameter `n` was refused (an error names it).
  void refuse(long n, std::size_t line) { assigned[n] = {std::nullopt, line, true}; }

  /// The named parameter `name` (as the dialect reads it: `#<feed>`, `_F_CUT`): as `assign`.
  void assign(const std::string& name, std::optional<parameter_literal> literal, std::size_t line) {
    named[name] = {std::move(literal), line};
  }

  /// The named parameter `name`: as `refuse`.
  void refuse(const std::string& name, std::size_t line) { named[name] = {std::nullopt, line, true}; }

  /// The number parameter `n` holds for a word that uses it, or null with the reason in `why`
  /// (empty when the assignment was refused).
  const parameter_literal* value(long n, std::string& why) const {
    const std::string p = "parameter " + name(n);
    why.clear();
    if (depends_on_path(p, why)) return nullptr;
    for (const reserved_parameters& r : reserved)
      if (n >= r.first && n <= r.last) {
        why = p + " is " + r.why;
        return nullptr;
      }
    const auto it = assigned.find(n);
    return held(it == assigned.end() ? nullptr : &it->second, p, why);
  }

  /// The number the named parameter `name` holds: as `value(n, why)`, calling it `noun`.
  const parameter_literal* value(std::string_view name, std::string& why, std::string_view noun = "parameter") const {
    const std::string p = std::string(noun) + " " + std::string(name);
    why.clear();
    if (depends_on_path(p, why)) return nullptr;
    const auto it = named.find(name);
    return held(it == named.end() ? nullptr : &it->second, p, why);
  }

 private:
  bool depends_on_path(const std::string& p, std::string& why) const {
    if (control_flow_line == 0) return false;
    why = p + " in a program with control flow (" + control_flow + " at line " + std::to_string(control_flow_line) +
          "): its value depends on the path";
    return true;
  }

  /// What assignment `a` (null: none) leaves parameter `p` holding.
  static const parameter_literal* held(const assignment* a, const std::string& p, std::string& why) {
    if (!a) why = p + " is not assigned earlier in this file: its value is the machine's";
    else if (a->refused) return nullptr;
    else if (!a->literal)
      why = p + " is computed at line " + std::to_string(a->line) + "; only a parameter assigned a number is read";
    else return &*a->literal;
    return nullptr;
  }
};

}  // namespace kin5::program
