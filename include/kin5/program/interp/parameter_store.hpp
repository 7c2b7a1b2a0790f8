/// @file program/interp/parameter_store.hpp
/// The parameters of a running program, for every dialect: numbered ones by family and number
/// (`#1`, `R1`, `Q1`, `QL1`), named ones by the name the dialect reads (`#<feed>`, `_F_CUT`),
/// global or local to a subprogram call. A dialect says which numbers exist and what they are
/// (`parameter_rules`, from `program/<dialect>/parameter_rules.hpp`): the program's own, local
/// to a call (LinuxCNC `o… call` #1–#30, FANUC `G65` #1–#33), or set by the control (a
/// `reserved` range: reading or setting one is refused, naming it, because its value is the
/// machine's). Reading a parameter the program has not assigned is refused, naming it, unless the
/// dialect defines the value (LinuxCNC's numbered parameters read 0).
/// @code
///   kin5::program::interp::parameter_store p{kin5::program::linuxcnc::parameter_rules()};
///   p.assign({"#", 1}, 2.5);
///   p.enter_call();  p.assign({"#", 1}, 7);  // o100 call [7]
///   // p.read({"#", 1}).value == 7
///   p.leave_call();                           // p.read({"#", 1}).value == 2.5
/// @endcode
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kin5::program::interp {

/// A parameter: numbered (`prefix` and `number`) when `name` is empty, else named.
struct parameter_key {
  std::string prefix;
  long number = 0;
  std::string name{};

  /// As the program writes it: "#1", "QL3", "#<feed>".
  std::string shown() const { return name.empty() ? prefix + std::to_string(number) : name; }
  friend auto operator<=>(const parameter_key&, const parameter_key&) = default;
};

enum class parameter_scope : unsigned char {
  global,    ///< one value for the whole program and every call
  local,     ///< a value per call (and one for the main program)
  reserved,  ///< set by the control: neither read nor set by kin5 (`why` says what it is)
};

/// Numbers `first` … `last` of family `prefix`, and what they are.
struct numbered_range {
  std::string prefix;
  long first = 0, last = 0;
  parameter_scope scope = parameter_scope::global;
  bool reads_zero = false;  ///< the dialect defines an unassigned one as 0
  std::string why{};        ///< reserved: follows "#5221 is ": "set by the control (a work offset)"
};

/// What a dialect's parameters are: the numbered ranges (a number in none does not exist), and
/// the scope of a named parameter (null: the dialect has none).
struct parameter_rules {
  std::vector<numbered_range> numbered;
  std::function<parameter_scope(const std::string&)> named_scope{};
};

/// A parameter's value, or why it has none.
struct parameter_read {
  std::optional<double> value;
  std::string why{};  ///< when there is no value: "parameter #5 is not assigned …"
};

/// The parameters of one running program (see the file comment).
class parameter_store {
 public:
  /// Subprogram calls nested deeper than this are refused by `enter_call` (LinuxCNC allows 10
  /// levels, FANUC G65 4; a deeper program is no real one).
  static constexpr std::size_t max_call_depth = 64;

  explicit parameter_store(parameter_rules rules) : rules_(std::move(rules)), frames_(1) {}

  /// The value of `p`, or why there is none.
  parameter_read read(const parameter_key& p) const {
    const auto kind = classify(p);
    if (!kind.why.empty()) return {std::nullopt, kind.why};
    const auto& values = kind.scope == parameter_scope::local ? frames_.back() : globals_;
    if (const auto it = values.find(p); it != values.end()) return {it->second};
    if (kind.reads_zero) return {0.0};
    return {std::nullopt, "parameter " + p.shown() + " is read before it is assigned" +
                              (kind.scope != parameter_scope::local ? std::string(": its value is the machine's")
                               : call_depth() == 0                  ? std::string(" in the main program")
                                                                    : std::string(" in this call"))};
  }

  /// Whether `p` holds a value the program gave it (LinuxCNC `EXISTS`).
  bool holds(const parameter_key& p) const {
    const auto kind = classify(p);
    if (!kind.why.empty()) return false;
    const auto& values = kind.scope == parameter_scope::local ? frames_.back() : globals_;
    return values.count(p) > 0;
  }

  /// Sets `p` to `value`; why it may not be set, when it may not.
  std::optional<std::string> assign(const parameter_key& p, double value) {
    const auto kind = classify(p);
    if (!kind.why.empty()) return kind.why;
    (kind.scope == parameter_scope::local ? frames_.back() : globals_)[p] = value;
    return std::nullopt;
  }

  /// A subprogram call begins: its locals start unassigned (the caller then assigns the
  /// arguments). False, nothing changed, past `max_call_depth`.
  bool enter_call() {
    if (frames_.size() > max_call_depth) return false;
    frames_.emplace_back();
    return true;
  }

  /// The call ends: the caller's locals are back. False when no call is open.
  bool leave_call() {
    if (frames_.size() <= 1) return false;
    frames_.pop_back();
    return true;
  }

  /// Calls open now (0 in the main program).
  std::size_t call_depth() const { return frames_.size() - 1; }

 private:
  struct kind_of {
    parameter_scope scope = parameter_scope::global;
    bool reads_zero = false;
    std::string why{};  // not empty: the parameter cannot be read or set
  };

  kind_of classify(const parameter_key& p) const {
    if (!p.name.empty()) {
      if (!rules_.named_scope)
        return {parameter_scope::reserved, false, "parameter " + p.name + " is not a parameter of this dialect"};
      const parameter_scope s = rules_.named_scope(p.name);
      if (s == parameter_scope::reserved)
        return {s, false, "parameter " + p.name + " is set by the control: its value is the machine's"};
      return {s, false, {}};
    }
    for (const numbered_range& r : rules_.numbered)
      if (r.prefix == p.prefix && p.number >= r.first && p.number <= r.last) {
        if (r.scope == parameter_scope::reserved) return {r.scope, false, "parameter " + p.shown() + " is " + r.why};
        return {r.scope, r.reads_zero, {}};
      }
    return {parameter_scope::reserved, false, "parameter " + p.shown() + " does not exist in this dialect"};
  }

  parameter_rules rules_;
  std::map<parameter_key, double> globals_;
  std::vector<std::map<parameter_key, double>> frames_;  // [0]: the main program's locals
};

}  // namespace kin5::program::interp
