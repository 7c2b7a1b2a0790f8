/// @file machines/machine_file.hpp
/// Reading a machine file: TOML text (schema in docs/machine-files.md) → a `machine_model`, the
/// same value a catalog type holds, so a machine read at run time runs the same solver. Every
/// mistake is reported as `FILE:LINE:COL: error: …` naming the key and the rule broken (syntax,
/// unknown key, missing key, wrong type, not a unit direction, travel order, degenerate axes, …).
/// Needs toml++ (link `tomlplusplus::tomlplusplus`); the core does not include this header.
/// @code
///   kin5::machine_file_result r = kin5::read_machine_file("machines/ac-trunnion.toml");
///   if (!r.ok()) { for (const auto& d : r.errors) std::cerr << d.to_string() << '\n'; return 2; }
///   const kin5::machine_model& m = r.machine->model();
///   auto solutions = kin5::inverse(m, kin5::vec3{0, 0.6, 0.8});
/// @endcode
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "../kinematics/machine_model.hpp"
#include "toml_bounds.hpp"

namespace kin5 {

/// A machine read from a file: its model, with the id and structure text it points into.
/// Movable, not copyable (the model's string views point into this object's own storage).
class loaded_machine {
 public:
  loaded_machine(std::string id, std::string structure, machine_geometry g)
      : id_(std::make_unique<std::string>(std::move(id))), structure_(std::make_unique<std::string>(std::move(structure))) {
    g.id = *id_;
    g.structure = *structure_;
    model_ = machine_model::from(g);
  }
  const machine_model& model() const { return model_; }

 private:
  std::unique_ptr<std::string> id_, structure_;
  machine_model model_{};
};

/// One mistake in a machine file, at a line and column (1-based).
struct machine_file_error {
  std::string file;
  unsigned line = 1, column = 1;
  std::string message;
  /// "FILE:LINE:COL: error: MESSAGE"
  std::string to_string() const {
    return file + ':' + std::to_string(line) + ':' + std::to_string(column) + ": error: " + message;
  }
};

/// The machine, or every mistake found (the machine is empty then).
struct machine_file_result {
  std::optional<loaded_machine> machine;
  std::vector<machine_file_error> errors;
  bool ok() const { return machine.has_value(); }
};

namespace machine_file_detail {

/// Collects errors with positions while the file is read.
struct reader {
  std::string file;
  std::vector<machine_file_error> errors;

  void error(const toml::source_region& at, std::string message) {
    errors.push_back({file, at.begin.line, at.begin.column, std::move(message)});
  }
  void error(const toml::node& at, std::string message) { error(at.source(), std::move(message)); }

  /// Reports every key of `t` not in `allowed`.
  template <std::size_t N>
  void only_keys(const toml::table& t, const std::array<std::string_view, N>& allowed, std::string_view where) {
    for (auto&& [key, value] : t) {
      bool known = false;
      for (auto a : allowed) known = known || key.str() == a;
      if (!known) error(key.source(), "unknown key '" + std::string(key.str()) + "' in " + std::string(where));
    }
  }

  const toml::node* require(const toml::table& t, std::string_view key, std::string_view where) {
    const toml::node* n = t.get(key);
    if (!n) error(t, "missing key '" + std::string(key) + "' in " + std::string(where));
    return n;
  }

  std::optional<double> number(const toml::node& n, std::string_view what) {
    std::optional<double> v = n.is_integer() ? std::optional<double>(static_cast<double>(*n.value<std::int64_t>()))
                                             : n.value<double>();
    if (!v) error(n, std::string(what) + " must be a number");
    else if (!machine_rules::is_finite(*v)) {
      error(n, std::string(what) + ": " + std::string(machine_rules::message(machine_rules::rule::finite)));
      v.reset();
    }
    return v;
  }

  std::optional<std::string> text(const toml::node& n, std::string_view what) {
    auto v = n.value<std::string>();
    if (!v) error(n, std::string(what) + " must be a string");
    return v;
  }

  /// An array of exactly N numbers.
  template <std::size_t N>
  std::optional<std::array<double, N>> numbers(const toml::node& n, std::string_view what) {
    const toml::array* a = n.as_array();
    if (!a || a->size() != N) {
      error(n, std::string(what) + " must be an array of " + std::to_string(N) + " numbers");
      return std::nullopt;
    }
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
      const auto v = number((*a)[i], what);
      if (!v) return std::nullopt;
      out[i] = *v;
    }
    return out;
  }

  std::optional<vec3> point(const toml::node& n, std::string_view what) {
    const auto v = numbers<3>(n, what);
    return v ? std::optional<vec3>(vec3{(*v)[0], (*v)[1], (*v)[2]}) : std::nullopt;
  }

  std::optional<vec3> direction(const toml::node& n, std::string_view what) {
    const auto v = point(n, what);
    if (v && !machine_rules::is_unit(*v)) {
      error(n, std::string(what) + " is not a unit vector (length² " + std::to_string(squared_norm(*v)) + "): " +
                   std::string(machine_rules::message(machine_rules::rule::unit_directions)));
      return std::nullopt;
    }
    return v;
  }

  std::optional<mount> side(const toml::node& n, std::string_view what) {
    const auto s = text(n, what);
    if (s && *s == "table") return mount::table;
    if (s && *s == "head") return mount::head;
    if (s) error(n, std::string(what) + " must be \"table\" or \"head\", not \"" + *s + "\"");
    return std::nullopt;
  }

  std::optional<rotary_travel> travel(const toml::table& t, std::string_view where) {
    const toml::node* range = t.get("travel_deg");
    const toml::node* endless = t.get("continuous");
    if (endless) {
      const auto c = endless->value<bool>();
      if (!c) {
        error(*endless, "continuous must be true or false");
        return std::nullopt;
      }
      if (*c && range) {
        error(*range, "travel_deg and continuous = true exclude each other in " + std::string(where));
        return std::nullopt;
      }
      if (*c) return rotary_travel::endless();
    }
    if (!range) {
      error(t, "missing key 'travel_deg' (or continuous = true) in " + std::string(where));
      return std::nullopt;
    }
    const auto v = numbers<2>(*range, "travel_deg");
    if (!v) return std::nullopt;
    const rotary_travel out = rotary_travel::between(degrees{(*v)[0]}, degrees{(*v)[1]});
    if (!(out.lower.value <= out.upper.value) ||
        out.upper.value - out.lower.value > machine_rules::widest_bounded_travel_deg) {
      error(*range, "travel_deg [" + std::to_string((*v)[0]) + ", " + std::to_string((*v)[1]) +
                        "]: " + std::string(machine_rules::message(machine_rules::rule::travel_order)));
      return std::nullopt;
    }
    return out;
  }

  std::optional<linear_axis> linear(const toml::table& t, axis_letter letter) {
    const std::string where = std::string("[linear.") + to_char(letter) + "]";
    only_keys(t, std::array<std::string_view, 4>{"direction", "side", "travel_mm", "home_mm"}, where);
    const toml::node* d = require(t, "direction", where);
    const toml::node* s = require(t, "side", where);
    const toml::node* r = require(t, "travel_mm", where);
    if (!d || !s || !r) return std::nullopt;
    const auto dir = direction(*d, where + " direction");
    const auto sd = side(*s, where + " side");
    const auto range = numbers<2>(*r, where + " travel_mm");
    if (range && !((*range)[0] <= (*range)[1])) {
      error(*r, where + " travel_mm: " + std::string(machine_rules::message(machine_rules::rule::travel_order)));
      return std::nullopt;
    }
    std::optional<double> home_mm;
    if (const toml::node* h = t.get("home_mm")) {
      home_mm = number(*h, where + " home_mm");
      if (!home_mm) return std::nullopt;
      if (range && !((*range)[0] <= *home_mm && *home_mm <= (*range)[1])) {
        error(*h, where + " home_mm: the home lies outside travel_mm");
        return std::nullopt;
      }
    }
    if (!dir || !sd || !range) return std::nullopt;
    return linear_axis{letter, *sd, *dir, linear_travel::between((*range)[0], (*range)[1]), home_mm};
  }

  std::optional<rotary_axis> rotary(const toml::table& t, std::size_t index) {
    const std::string where = "[[rotary]] #" + std::to_string(index + 1);
    only_keys(t, std::array<std::string_view, 8>{"letter", "side", "direction", "point_mm", "sense", "travel_deg", "continuous",
                                                 "home_deg"},
              where);
    const toml::node* l = require(t, "letter", where);
    const toml::node* s = require(t, "side", where);
    const toml::node* d = require(t, "direction", where);
    const toml::node* c = require(t, "point_mm", where);
    const toml::node* g = require(t, "sense", where);
    if (!l || !s || !d || !c || !g) return std::nullopt;
    rotary_axis a{};
    const auto name = text(*l, where + " letter");
    if (name && (*name == "A" || *name == "B" || *name == "C")) a.letter = static_cast<axis_letter>((*name)[0]);
    else if (name) error(*l, where + " letter \"" + *name + "\": " + std::string(machine_rules::message(machine_rules::rule::rotary_letters)));
    const auto sd = side(*s, where + " side");
    const auto dir = direction(*d, where + " direction");
    const auto at = point(*c, where + " point_mm");
    const auto sense_text = text(*g, where + " sense");
    std::optional<angle_sense> sense;
    if (sense_text && *sense_text == "tool-relative") sense = angle_sense::tool_relative;
    else if (sense_text && *sense_text == "physical") sense = angle_sense::physical;
    else if (sense_text) error(*g, where + " sense must be \"tool-relative\" or \"physical\", not \"" + *sense_text + "\"");
    const auto tr = travel(t, where);
    if (a.letter == axis_letter::none || !sd || !dir || !at || !sense || !tr) return std::nullopt;
    a.side = *sd;
    a.direction = *dir;
    a.point_mm = *at;
    a.sense = *sense;
    a.travel = *tr;
    if (const toml::node* h = t.get("home_deg")) {
      const auto home = number(*h, where + " home_deg");
      if (!home) return std::nullopt;
      if (!a.travel.contains(to_radians(degrees{*home}))) {
        error(*h, where + " home_deg: the home lies outside travel_deg");
        return std::nullopt;
      }
      a.home_deg = degrees{*home};
    }
    return a;
  }
};

/// The geometry of the parsed document `doc`, or nothing (errors recorded in `r`).
inline std::optional<machine_geometry> geometry_of(const toml::table& doc, reader& r, std::string& id,
                                                   std::string& structure) {
  r.only_keys(doc, std::array<std::string_view, 6>{"kin5_machine", "id", "structure", "tool", "linear", "rotary"},
              "the top level");
  const toml::node* version = r.require(doc, "kin5_machine", "the top level");
  if (version && version->value<std::int64_t>() != std::optional<std::int64_t>(1))
    r.error(*version, "kin5_machine must be 1, the only schema version this kin5 reads");
  if (const toml::node* n = r.require(doc, "id", "the top level"))
    if (auto v = r.text(*n, "id")) id = *v;
  if (const toml::node* n = doc.get("structure"))
    if (auto v = r.text(*n, "structure")) structure = *v;

  machine_geometry g{};
  bool complete = true;
  const toml::node* tool_node = r.require(doc, "tool", "the top level");
  const toml::node* pivot = nullptr;
  if (tool_node && !tool_node->is_table()) r.error(*tool_node, "tool must be a table");
  if (tool_node && tool_node->is_table()) {
    const toml::table& t = *tool_node->as_table();
    r.only_keys(t, std::array<std::string_view, 2>{"reference", "pivot_length_mm"}, "[tool]");
    const toml::node* ref = r.require(t, "reference", "[tool]");
    pivot = r.require(t, "pivot_length_mm", "[tool]");
    const auto dir = ref ? r.direction(*ref, "[tool] reference") : std::nullopt;
    const auto len = pivot ? r.number(*pivot, "[tool] pivot_length_mm") : std::nullopt;
    if (len && *len < 0.0) r.error(*pivot, "[tool] pivot_length_mm: " + std::string(machine_rules::message(machine_rules::rule::finite)));
    complete = complete && dir && len && *len >= 0.0;
    if (dir && len) g.tool = {*dir, *len};
  } else complete = false;

  const toml::node* linear_node = r.require(doc, "linear", "the top level");
  const toml::node* z_direction = nullptr;
  if (linear_node && !linear_node->is_table()) r.error(*linear_node, "linear must be a table with [linear.X], [linear.Y], [linear.Z]");
  if (linear_node && linear_node->is_table()) {
    const toml::table& t = *linear_node->as_table();
    r.only_keys(t, std::array<std::string_view, 3>{"X", "Y", "Z"}, "[linear] (the linear axes are X, Y and Z)");
    constexpr std::array<axis_letter, 3> letters{axis_letter::X, axis_letter::Y, axis_letter::Z};
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string key(1, to_char(letters[i]));
      const toml::node* n = r.require(t, key, "[linear]");
      if (n && !n->is_table()) r.error(*n, "linear." + key + " must be a table");
      const auto a = (n && n->is_table()) ? r.linear(*n->as_table(), letters[i]) : std::nullopt;
      complete = complete && a.has_value();
      if (a) g.linear[i] = *a;
      if (i == 2 && n && n->is_table()) z_direction = n->as_table()->get("direction");
    }
  } else complete = false;

  const toml::node* rotary_node = r.require(doc, "rotary", "the top level");
  const toml::array* list = rotary_node ? rotary_node->as_array() : nullptr;
  std::array<const toml::node*, 2> rotary_directions{};
  if (rotary_node && (!list || list->empty() || list->size() > 2 || !list->is_array_of_tables())) {
    r.error(*rotary_node, "rotary must be one or two [[rotary]] tables: " +
                              std::string(machine_rules::message(machine_rules::rule::rotary_count)));
    list = nullptr;
  }
  if (list) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const toml::table& t = *(*list)[i].as_table();
      const auto a = r.rotary(t, i);
      complete = complete && a.has_value();
      if (a) g.rotary[i] = *a;
      rotary_directions[i] = t.get("direction");
      if (a && i == 1 && g.rotary[0].letter == a->letter)
        r.error(*t.get("letter"), "[[rotary]] #2 letter: " + std::string(machine_rules::message(machine_rules::rule::rotary_letters)));
    }
  } else complete = false;
  if (!complete || !r.errors.empty()) return std::nullopt;

  // Rules that relate several keys, reported at the key that completes the mistake.
  using machine_rules::rule;
  if (!machine_rules::holds(rule::linear_independent, g))
    r.error(z_direction ? *z_direction : *linear_node, "[linear.Z] direction: " + std::string(machine_rules::message(rule::linear_independent)));
  if (!machine_rules::holds(rule::moves_the_tool, g)) {
    const std::size_t last = list->size() - 1;
    r.error(*rotary_directions[last], "[[rotary]] #" + std::to_string(last + 1) + " direction: " +
                                          std::string(machine_rules::message(rule::moves_the_tool)));
  }
  for (rule broken : machine_rules::check(g))  // any rule not tied to a key above
    if (broken != rule::linear_independent && broken != rule::moves_the_tool)
      r.error(doc, std::string(machine_rules::message(broken)));
  if (!r.errors.empty()) return std::nullopt;
  return g;
}

}  // namespace machine_file_detail

/// Reads machine file text; `file` names it in error messages. Text beyond the bounds of
/// `toml_bounds.hpp` (size, key length, nesting) is refused before toml++ parses it.
inline machine_file_result parse_machine_file(std::string_view text, std::string file) {
  machine_file_result out{};
  machine_file_detail::reader r{file, {}};
  if (const auto v = toml_bounds_violation(text)) {  // before toml++, whose recursion it bounds
    r.errors.push_back({file, v->line, v->column, v->message});
    out.errors = std::move(r.errors);
    return out;
  }
  toml::table doc;
  try {
    doc = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    r.error(e.source(), "TOML syntax: " + std::string(e.description()));
    out.errors = std::move(r.errors);
    return out;
  }
  std::string id, structure;
  const auto g = machine_file_detail::geometry_of(doc, r, id, structure);
  if (g) out.machine.emplace(std::move(id), std::move(structure), *g);
  out.errors = std::move(r.errors);
  return out;
}

/// Reads the machine file at `path`; a directory, a read error or a file over 4 MiB is one
/// error, "cannot read the machine file: …" (`read_toml_file`).
inline machine_file_result read_machine_file(const std::string& path) {
  toml_file_text read = read_toml_file(path);
  if (!read.text) return {std::nullopt, {{path, 1, 1, "cannot read the machine file: " + read.error}}};
  return parse_machine_file(*read.text, path);
}

}  // namespace kin5
