/// @file bad_inputs.hpp
/// A dialect's bad-input table, `<name>/errors.txt` next to its other tests, read by the law
/// "bad input gives exact diagnostics" (laws.cpp): one case a line, the input text and then,
/// each after a tab, every diagnostic reading it must give, in order (none: it reads without
/// error). In a field `\n`, `\r`, `\t`, `\f`, `\\` and `\xHH` stand for those bytes (a text that
/// starts with `#` spells it `\x23`); a line that starts with `#` is a comment. The tables are
/// data, so a dialect adds rows, not code: `bad_inputs_of<D>()` serves every entry of the list.
#pragma once

#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "contract.hpp"

namespace kin5::test {

/// `field` with its escapes (see the file comment) replaced by the bytes they stand for.
inline std::string unescape(std::string_view field) {
  std::string out;
  for (std::size_t i = 0; i < field.size(); ++i) {
    const char c = field[i];
    if (c != '\\' || i + 1 == field.size()) {
      out += c;
      continue;
    }
    const char e = field[++i];
    if (e == 'x') {
      if (i + 2 >= field.size()) throw std::invalid_argument("\\x needs two hex digits: " + std::string(field));
      out += static_cast<char>(std::stoi(std::string(field.substr(i + 1, 2)), nullptr, 16));
      i += 2;
    } else {
      out += e == 'n' ? '\n' : e == 'r' ? '\r' : e == 't' ? '\t' : e == 'f' ? '\f' : e;
    }
  }
  return out;
}

/// The cases of the table at `path` (see the file comment); throws if it cannot be read.
inline std::vector<bad_input> read_bad_inputs(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<bad_input> cases;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    bad_input c;
    std::size_t start = 0;
    for (std::size_t tab = line.find('\t'); start <= line.size(); tab = line.find('\t', start)) {
      const std::string field = unescape(std::string_view(line).substr(start, tab == std::string::npos ? tab : tab - start));
      if (start == 0) c.text = field;
      else c.errors.push_back(field);
      if (tab == std::string::npos) break;
      start = tab + 1;
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

/// Dialect D's bad-input table: `<D::name>/errors.txt` in the dialect tests' folder.
template <class D>
std::vector<bad_input> bad_inputs_of() {
  return read_bad_inputs(std::string(KIN5_DIALECT_TESTS_DIR) + "/" + std::string(D::name) + "/errors.txt");
}

}  // namespace kin5::test
