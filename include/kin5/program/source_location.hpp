/// @file program/source_location.hpp
/// Where something in a program's text starts: its file (one shared string per file), 1-based
/// line and column.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace kin5::program {

/// The name of a program's file, shared by every location in it: copying one copies a pointer,
/// so the blocks of a long program hold one string, not one each. Reads as a `const std::string&`.
class file_name {
 public:
  file_name() = default;
  file_name(std::string name) : name_(std::make_shared<const std::string>(std::move(name))) {}
  file_name(const char* name) : file_name(std::string(name)) {}

  const std::string& str() const noexcept { return name_ ? *name_ : none(); }
  operator const std::string&() const noexcept { return str(); }
  bool empty() const noexcept { return str().empty(); }

  friend bool operator==(const file_name& a, const file_name& b) noexcept { return a.str() == b.str(); }
  friend std::string operator+(const file_name& a, std::string_view b) { return a.str() + std::string(b); }
  friend std::string operator+(const file_name& a, const char* b) { return a.str() + b; }

 private:
  static const std::string& none() noexcept {
    static const std::string empty_name;
    return empty_name;
  }
  std::shared_ptr<const std::string> name_;
};

/// Where a block or a word starts: 1-based line and column (columns count bytes).
struct source_location {
  file_name file;
  std::size_t line = 0;
  std::size_t column = 0;
  friend bool operator==(const source_location&, const source_location&) = default;
};

}  // namespace kin5::program
