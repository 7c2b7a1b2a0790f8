/// @file translate/diagnostic_list.hpp
/// The diagnostics of one severity a translation collects, in bounded memory: a list that always
/// holds the first `program::max_kept_diagnostics` (1,000) in source order — every one the tool
/// prints (100) or the JSON report lists (1,000) — and counts the others (`not_kept`), so that
/// `count()` stays exact. 500,000 refused blocks kept 500,000 diagnostics before (about 440 MB
/// at peak); now at most twice the bound are held at any time. It reads as the
/// `std::vector<program::diagnostic>` it replaces (`size`, `[]`, iteration, conversion). The line
/// of every diagnostic added is kept (`line(i)`, 8 bytes each), for the exact count of refused
/// blocks (run_report.hpp, `block_accounting`). A diagnostic added while a `calls_scope` lives
/// says where its block was called from (`diagnostic::called_from`), unless it says so itself.
/// @code
///   kin5::diagnostic_list errors;
///   errors.push_back({where, "cannot reach this block"});
///   std::size_t all = errors.count();   // kept + not_kept, exact
///   for (const auto& e : errors) { /* a superset of the first 1,000 in source order */ }
/// @endcode
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "../program/block.hpp"

namespace kin5 {

namespace detail {
inline thread_local const std::vector<program::source_location>* block_calls = nullptr;
}  // namespace detail

/// Makes `calls` (outermost first) the calls open at the block being translated on this thread
/// while it lives: the diagnostics added meanwhile were called from there (`called_from`).
class calls_scope {
 public:
  explicit calls_scope(const std::vector<program::source_location>& calls) : saved_(detail::block_calls) {
    detail::block_calls = calls.empty() ? nullptr : &calls;
  }
  ~calls_scope() { detail::block_calls = saved_; }
  calls_scope(const calls_scope&) = delete;
  calls_scope& operator=(const calls_scope&) = delete;

 private:
  const std::vector<program::source_location>* saved_;
};

/// `d`, with the calls of the block being translated (`calls_scope`) unless it names its own.
inline program::diagnostic called(program::diagnostic d) {
  if (detail::block_calls && d.called_from.empty()) d.called_from = *detail::block_calls;
  return d;
}

/// Diagnostics in bounded memory (see the file comment).
class diagnostic_list {
 public:
  using value_type = program::diagnostic;
  using const_iterator = std::vector<program::diagnostic>::const_iterator;

  /// Adds `d`; when twice the bound are held, keeps the first `max_kept_diagnostics` in source
  /// order (line, then column; ties in the order added) and counts the rest.
  void push_back(program::diagnostic d) {
    lines_.push_back(d.where.line);
    kept_.push_back(called(std::move(d)));
    if (kept_.size() >= 2 * program::max_kept_diagnostics) prune();
  }

  /// Every diagnostic added: those held and those only counted.
  std::size_t count() const { return kept_.size() + not_kept_; }
  /// Diagnostics added but no longer held (none of them among the first in source order).
  std::size_t not_kept() const { return not_kept_; }
  /// The line of the `i`-th diagnostic added (0: about the whole file), `i` < `count()`.
  std::size_t line(std::size_t i) const { return lines_[i]; }

  std::size_t size() const { return kept_.size(); }
  bool empty() const { return kept_.empty(); }
  const program::diagnostic& operator[](std::size_t i) const { return kept_[i]; }
  const program::diagnostic& at(std::size_t i) const { return kept_.at(i); }
  const program::diagnostic& front() const { return kept_.front(); }
  const program::diagnostic& back() const { return kept_.back(); }
  const_iterator begin() const { return kept_.begin(); }
  const_iterator end() const { return kept_.end(); }
  /// The diagnostics held, in the order added (after a prune: source order, then the later ones).
  operator const std::vector<program::diagnostic>&() const { return kept_; }  // NOLINT: reads as the vector

 private:
  std::vector<program::diagnostic> kept_;
  std::vector<std::size_t> lines_;  // of every diagnostic added, in the order added
  std::size_t not_kept_ = 0;

  void prune() {
    std::stable_sort(kept_.begin(), kept_.end(), [](const program::diagnostic& a, const program::diagnostic& b) {
      return a.where.line != b.where.line ? a.where.line < b.where.line : a.where.column < b.where.column;
    });
    not_kept_ += kept_.size() - program::max_kept_diagnostics;
    kept_.resize(program::max_kept_diagnostics);
  }
};

}  // namespace kin5
