/// @file program/call_chain.hpp
/// Where an executed block was called from: the chain of call sites open when it ran, outermost
/// first, innermost last. A program's chains are interned in one `call_chains` table, so a block
/// carries only a 32-bit id into it (`block::call_chain`; 0: the top level, no call open). Each
/// entry is one call site and the id of the chain it was called in, so a chain costs one entry
/// whatever its depth, and a loop that calls a subprogram 10^6 times from one place adds one
/// entry, not 10^6: the same site in the same chain is the same id.
/// @code
///   kin5::program::call_chains calls;
///   const std::uint32_t in_sub = calls.enter(0, {"part.h", 12, 1});  // CALL LBL 3 at line 12
///   calls.enter(0, {"part.h", 12, 1}) == in_sub;                      // interned
///   calls.outer(in_sub) == 0;                                         // back at the top level
///   calls.sites(in_sub);                                              // {part.h:12:1}
/// @endcode
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "source_location.hpp"

namespace kin5::program {

/// The interned call chains of one program run (see the file comment).
class call_chains {
 public:
  /// The id of the chain `outer` with the call at `site` open inside it (a new id the first
  /// time that chain is entered).
  std::uint32_t enter(std::uint32_t outer, const source_location& site) {
    if (const auto found = ids_.find(key{outer, site.file.str(), site.line, site.column}); found != ids_.end())
      return found->second;
    if (entries_.size() >= max_chains) throw std::length_error("more than 2^32 - 1 distinct call chains");
    entries_.push_back({outer, site});
    const auto id = static_cast<std::uint32_t>(entries_.size());  // entry i has id i + 1
    // The key views the entry's file name, whose string stays where it is while the entry lives.
    ids_.emplace(key{outer, entries_.back().site.file.str(), site.line, site.column}, id);
    return id;
  }

  /// The chain `id` is called in: the caller's chain (0 at the top level).
  std::uint32_t outer(std::uint32_t id) const { return id == 0 ? 0 : entries_.at(id - 1).outer; }
  /// The innermost call site of chain `id` (not 0).
  const source_location& site(std::uint32_t id) const { return entries_.at(id - 1).site; }
  /// The calls open in chain `id`, outermost first; none for 0.
  std::vector<source_location> sites(std::uint32_t id) const {
    std::size_t depth = 0;
    for (std::uint32_t c = id; c != 0; c = outer(c)) ++depth;
    std::vector<source_location> out(depth);
    for (std::uint32_t c = id; c != 0; c = outer(c)) out[--depth] = site(c);
    return out;
  }
  /// Distinct chains entered so far (0 not counted).
  std::size_t size() const { return entries_.size(); }

  friend bool operator==(const call_chains& a, const call_chains& b) { return a.entries_ == b.entries_; }

  call_chains() = default;
  call_chains(const call_chains& other) : entries_(other.entries_) { index(); }
  call_chains& operator=(const call_chains& other) {
    if (this != &other) entries_ = other.entries_, index();
    return *this;
  }
  call_chains(call_chains&&) noexcept = default;
  call_chains& operator=(call_chains&&) noexcept = default;

 private:
  static constexpr std::size_t max_chains = 0xFFFF'FFFFu;
  struct entry {
    std::uint32_t outer;
    source_location site;
    friend bool operator==(const entry&, const entry&) = default;
  };
  struct key {
    std::uint32_t outer;
    std::string_view file;
    std::size_t line, column;
    friend bool operator==(const key&, const key&) = default;
  };
  struct key_hash {
    std::size_t operator()(const key& k) const noexcept {
      std::size_t h = std::hash<std::string_view>{}(k.file);
      for (const std::size_t v : {std::size_t{k.outer}, k.line, k.column}) h = h * 1'000'003u ^ v;
      return h;
    }
  };
  /// The index of a copy, whose keys view its own entries' file names.
  void index() {
    ids_.clear();
    for (std::size_t i = 0; i < entries_.size(); ++i)
      ids_.emplace(key{entries_[i].outer, entries_[i].site.file.str(), entries_[i].site.line, entries_[i].site.column},
                   static_cast<std::uint32_t>(i + 1));
  }
  std::vector<entry> entries_;
  std::unordered_map<key, std::uint32_t, key_hash> ids_;
};

}  // namespace kin5::program
