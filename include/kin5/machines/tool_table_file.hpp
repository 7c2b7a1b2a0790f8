/// @file machines/tool_table_file.hpp
/// Reading a tool-table file: TOML text (schema in docs/machine-files.md, "Tool tables") → a
/// `tool_table`. Every mistake is reported as `FILE:LINE:COL: error: …` naming the key and the
/// rule broken (syntax, unknown or missing key, wrong type, a number used twice, a negative or
/// infinite length). Needs toml++ (link `tomlplusplus::tomlplusplus`), like machine files.
/// @code
///   // kin5_tools = 1
///   // [[tool]]
///   // number = 5
///   // length_mm = 118.25
///   kin5::tool_table_result r = kin5::read_tool_table_file("tools.toml");
///   if (!r.ok()) for (const auto& e : r.errors) std::cerr << e.to_string() << '\n';
///   else use(r.table->find(5)->length_mm);
/// @endcode
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "../kinematics/tool_table.hpp"
#include "machine_file.hpp"
#include "toml_bounds.hpp"

namespace kin5 {

/// The table, or every mistake found (the table is empty then).
struct tool_table_result {
  std::optional<tool_table> table;
  std::vector<machine_file_error> errors;
  bool ok() const { return table.has_value(); }
};

namespace tool_table_detail {

/// A length of the entry: a finite number, 0 or more; empty (an error in `r`) when not.
inline std::optional<double> length_of(machine_file_detail::reader& r, const toml::node& n, const std::string& what) {
  const auto v = r.number(n, what);
  if (v && *v < 0.0) {
    r.error(n, what + " must be 0 or more");
    return std::nullopt;
  }
  return v;
}

/// Entry `index` (from 0) of the `[[tool]]` array into `out`, errors in `r`.
inline void read_entry(machine_file_detail::reader& r, const toml::table& t, std::size_t index, tool_table& out) {
  const std::string where = "[[tool]] #" + std::to_string(index + 1);
  r.only_keys(t, std::array<std::string_view, 3>{"number", "length_mm", "radius_mm"}, where);
  const toml::node* number = r.require(t, "number", where);
  const toml::node* length = r.require(t, "length_mm", where);
  std::optional<long long> n;
  if (number) {
    const auto v = number->value_exact<std::int64_t>();
    if (!v || *v < 0) r.error(*number, where + " number must be a whole number, 0 or more");
    else n = static_cast<long long>(*v);
  }
  const auto l = length ? length_of(r, *length, where + " length_mm") : std::nullopt;
  std::optional<double> radius;
  if (const toml::node* rn = t.get("radius_mm")) {
    radius = length_of(r, *rn, where + " radius_mm");
    if (!radius) return;
  }
  if (!n || !l) return;
  if (out.find(*n)) {
    r.error(*number, where + " number " + std::to_string(*n) + " is given twice");
    return;
  }
  out.entries[*n] = {*l, radius};
}

}  // namespace tool_table_detail

/// Reads tool-table text; `file` names it in error messages. Text beyond the bounds of
/// `toml_bounds.hpp` (size, key length, nesting) is refused before toml++ parses it.
inline tool_table_result parse_tool_table_file(std::string_view text, std::string file) {
  machine_file_detail::reader r{file, {}};
  if (const auto v = toml_bounds_violation(text))  // before toml++, whose recursion it bounds
    return {std::nullopt, {{file, v->line, v->column, v->message}}};
  toml::table doc;
  try {
    doc = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    r.error(e.source(), "TOML syntax: " + std::string(e.description()));
    return {std::nullopt, std::move(r.errors)};
  }
  r.only_keys(doc, std::array<std::string_view, 2>{"kin5_tools", "tool"}, "the top level");
  const toml::node* version = r.require(doc, "kin5_tools", "the top level");
  if (version && version->value_exact<std::int64_t>() != std::optional<std::int64_t>(1))
    r.error(*version, "kin5_tools must be 1, the only schema version this kin5 reads");
  tool_table table;
  const toml::node* tools = r.require(doc, "tool", "the top level");
  const toml::array* list = tools ? tools->as_array() : nullptr;
  if (tools && (!list || !list->is_array_of_tables()))
    r.error(*tools, "tool must be [[tool]] tables, one per tool");
  else if (list)
    for (std::size_t i = 0; i < list->size(); ++i) tool_table_detail::read_entry(r, *(*list)[i].as_table(), i, table);
  if (!r.errors.empty()) return {std::nullopt, std::move(r.errors)};
  return {std::move(table), {}};
}

/// Reads the tool-table file at `path`; a directory, a read error or a file over 4 MiB is one
/// error, "cannot read the tool-table file: …" (`read_toml_file`).
inline tool_table_result read_tool_table_file(const std::string& path) {
  toml_file_text read = read_toml_file(path);
  if (!read.text) return {std::nullopt, {{path, 1, 1, "cannot read the tool-table file: " + read.error}}};
  return parse_tool_table_file(*read.text, path);
}

}  // namespace kin5
