/// @file program/block_store.hpp
/// A compact, append-only record of the blocks of one program, to be replayed in order: what a
/// second pass over a program reads instead of parsing the text again.
///
/// Each block is packed into a byte record: a word of flags (which fields are present), then
/// only the fields present, numbers as their exact bytes, strings with their length. The fields a
/// motion block rarely has (program name and end, comment, modes, tool, kept words, the alarm
/// stop and the block's kinds) are one group and the state words another: each group has a word of its own
/// with a bit per field, written only when the group says anything. A motion block
/// `N… G1 X Y Z A B F` takes about 70 bytes, a quarter of `sizeof(block)` and without
/// its heap parts. Records go into chunks, so the store grows without copying: a record that
/// does not fit the rest of the last chunk starts a new one, of its own size if it is larger.
/// Chunks double from 64 KiB up to 1 MiB, so a short program does not take a whole 1 MiB.
///
/// Memory is bounded: once the chunks held would pass the store's budget of bytes
/// (`memory_bytes`, 256 MiB by default; the tool's `--max-memory-bytes`), the full chunks are
/// written to an anonymous temporary file (`std::tmpfile`, removed when the store goes) and
/// freed; `replay` reads them back in order, a chunk at a time, before those in memory. The
/// budget is looked at once per new chunk, never per record. A failure to write or read that file
/// is an `error()`: no block is pushed after it, and `replay` stops there and returns false, so
/// a caller never takes a partial replay for a whole one.
/// Every field of `block` and of `state_words` has its codec here: the field counts are checked
/// at compile time (`field_count`), and `block_store_laws` draws every field.
/// `replay` gives back blocks equal (`==`) to those stored, except:
/// - `where.file` is the store's file name where the block's was the same string (one per
///   program, not one per block); a block of another file (one a call ran) gets its own back;
/// - `text` is dropped where the caller asks (`keep_text`), for blocks whose consumer never
///   reads it: the translator does not read the text of a block it moves.
#pragma once

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "../core/field_count.hpp"
#include "block.hpp"
#include "state_words.hpp"

namespace kin5::program {

namespace detail {
/// Bits of a state field in the store's state word: an `optional<bool>` two, present and value;
/// a `bool` one, its value; any other `optional` one, present.
template <class T>
constexpr unsigned state_bits_of() {
  return std::is_same_v<T, std::optional<bool>> ? 2 : 1;
}
}  // namespace detail

/// The blocks of one program as compact records, replayed in the order stored.
class block_store {
 public:
  /// Bytes of a chunk once the chunks have grown, unless a record needs more.
  static constexpr std::size_t default_chunk_bytes = std::size_t{1} << 20;
  /// Bytes of the first chunk; each next one doubles, up to the chunk size.
  static constexpr std::size_t default_first_chunk_bytes = std::size_t{1} << 16;
  /// Bytes of chunks held in memory before the full ones go to the temporary file.
  static constexpr std::size_t default_memory_bytes = std::size_t{256} << 20;

  explicit block_store(std::string file, std::size_t chunk_bytes = default_chunk_bytes,
                       std::size_t first_chunk_bytes = default_first_chunk_bytes)
      : file_(file_name(std::move(file))),
        chunk_bytes_(std::max<std::size_t>(chunk_bytes, 1)),
        next_chunk_bytes_(std::clamp<std::size_t>(first_chunk_bytes, 1, chunk_bytes_)) {}

  /// Sets the bytes of chunks held in memory (at least the chunk being filled is).
  void memory_bytes(std::size_t bytes) { memory_bytes_ = bytes; }
  std::size_t memory_bytes() const { return memory_bytes_; }

  /// Appends `b` (without its text unless `keep_text`); nothing after an `error()`.
  void push(const block& b, bool keep_text = true) {
    if (!error_.empty()) return;
    encode(b, keep_text);
    record_.resize(static_cast<std::size_t>(write_ - record_.data()));
    if (chunks_.empty() || capacity_ - used_ < record_.size()) {  // used_ <= capacity_ always
      capacity_ = std::max(next_chunk_bytes_, record_.size());
      next_chunk_bytes_ = std::min(chunk_bytes_, 2 * next_chunk_bytes_);
      if (held_bytes_ + capacity_ > memory_bytes_ && !spill()) return;  // the full chunks go to the file
      // Not zeroed: replay reads only the bytes push copied in (up to sizes_).
      chunks_.push_back(std::make_unique_for_overwrite<unsigned char[]>(capacity_));
      sizes_.push_back(0);
      held_bytes_ += capacity_;
      used_ = 0;
    }
    std::memcpy(chunks_.back().get() + used_, record_.data(), record_.size());
    used_ += record_.size();
    sizes_.back() = used_;
    ++count_;
  }

  /// Calls `f(const block&)` for every stored block, in the order pushed; true when it did for
  /// all, false when an `error()` (before or while reading the temporary file) stopped it. The
  /// store is unchanged. One block object is reused for all, so its strings keep their capacity.
  template <class F>
  bool replay(F&& f) const {
    if (!error_.empty()) return false;
    block b;
    b.where.file = file_;
    std::uint64_t file_index = 0;  // of b.where.file: 0 the store's, else files_[file_index - 1]
    std::vector<unsigned char> spilled;  // a chunk read back from the file
    if (spilled_ > 0 && std::fseek(spill_.get(), 0, SEEK_SET) != 0) return failed("cannot go back to the start of");
    for (std::size_t c = 0; c < chunks_.size(); ++c) {
      const unsigned char* p = chunks_[c].get();
      if (c < spilled_) {
        spilled.resize(sizes_[c]);
        if (std::fread(spilled.data(), 1, sizes_[c], spill_.get()) != sizes_[c]) return failed("cannot read");
        p = spilled.data();
      }
      const unsigned char* const end = p + sizes_[c];
      while (p < end) {
        p = decode(p, b, file_index);
        f(std::as_const(b));
      }
    }
    return true;
  }

  /// Why the store failed (its temporary file could not be written or read); empty while it has not.
  const std::string& error() const { return error_; }

  std::size_t size() const { return count_; }
  /// Chunks allocated so far.
  std::size_t chunks() const { return chunks_.size(); }
  /// Chunks written to the temporary file and freed: the first ones.
  std::size_t spilled_chunks() const { return spilled_; }
  /// Bytes held by the records (chunks are allocated a chunk at a time).
  std::size_t bytes() const {
    std::size_t n = 0;
    for (std::size_t s : sizes_) n += s;
    return n;
  }

 private:
  // The record's first word: one bit per field a motion block may have, in the order the fields
  // follow the flags, and one per group that has a word of its own.
  enum flag : std::uint32_t {
    has_text = 1u << 0, has_number = 1u << 1, has_rpm = 1u << 2, has_m = 1u << 3, has_motion = 1u << 4,
    has_x = 1u << 5, has_y = 1u << 6, has_z = 1u << 7, has_a = 1u << 8, has_b = 1u << 9, has_c = 1u << 10,
    has_tool_axis = 1u << 11, has_arc = 1u << 12, arc_centre = 1u << 13, arc_radius = 1u << 14,
    has_feed = 1u << 15, feed_rapid = 1u << 16,
    has_other = 1u << 17,  // an `other` word follows
    has_state = 1u << 18,  // a word of `state_words` follows
    has_call_chain = 1u << 19,  // the block's call chain follows the location (LEB128)
    other_file = 1u << 20,      // the block's file, an index into files_ from 1, follows (LEB128)
  };
  // The word of the fields a motion block rarely has, after the flags' `has_other`.
  enum other : std::uint32_t {
    has_begin = 1u << 0, has_end = 1u << 1, has_comment = 1u << 2, has_tcp = 1u << 3, tcp_on = 1u << 4,
    has_feed_mode = 1u << 5, has_metric = 1u << 6, metric_on = 1u << 7, has_tool = 1u << 8, has_tool_name = 1u << 9,
    has_kept = 1u << 10, machine_coordinates = 1u << 11, passthrough = 1u << 12, framing = 1u << 13,
    assignment = 1u << 14, has_alarm = 1u << 15, alarm_number = 1u << 16,
  };
  static_assert(field_count<block>() == 27,
                "a field of `block` has no codec: give it one in block_store.hpp and draw it in block_store_laws");
  static_assert(field_count<axis_words>() == 7 && field_count<arc_words>() == 3,
                "a field of `axis_words` or `arc_words` has no codec: give it one in block_store.hpp and draw it "
                "in block_store_laws");

  // The state words, one codec for all: each field in this list takes bits of the state's word
  // in turn (a `bool` one, its value; an `optional<bool>` two, present and value; any other
  // `optional` one, present, and then its value's bytes).
  static constexpr auto state_fields = std::tuple{
      &state_words::tool_change,          &state_words::tool_spindle_axis,   &state_words::tool_length_delta_mm,
      &state_words::tool_radius_delta_mm, &state_words::length_compensation, &state_words::length_register,
      &state_words::radius_compensation,  &state_words::radius_register,     &state_words::cutting_edge,
      &state_words::spindle,              &state_words::coolant_flood,       &state_words::coolant_mist,
      &state_words::work_offset,          &state_words::working_plane,       &state_words::distance,
      &state_words::dwell_s,              &state_words::stop};
  static_assert(field_count<state_words>() == std::tuple_size_v<decltype(state_fields)>,
                "a field of `state_words` has no codec: add it to block_store::state_fields and draw it in "
                "block_store_laws");

  struct closes_file {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };

  file_name file_;
  std::vector<file_name> files_;  // of the blocks not in file_, in the order first seen
  file_name last_file_{std::string()};  // of the last block pushed (at first no block's), and its index
  std::uint64_t last_file_index_ = 0;
  std::vector<std::unique_ptr<unsigned char[]>> chunks_;  // the first spilled_ freed, their bytes in spill_
  std::vector<std::size_t> sizes_;
  std::size_t chunk_bytes_;
  std::size_t next_chunk_bytes_;  // of the next chunk: doubles after each, up to chunk_bytes_
  std::size_t capacity_ = 0, used_ = 0, count_ = 0;  // of the last chunk: its size, bytes used
  std::vector<unsigned char> record_;  // the record being built
  unsigned char* write_ = nullptr;     // where `put` writes in it
  std::size_t memory_bytes_ = default_memory_bytes;
  std::size_t held_bytes_ = 0;   // of the chunks in memory
  std::size_t spilled_ = 0;      // chunks in the temporary file
  std::unique_ptr<std::FILE, closes_file> spill_;
  mutable std::string error_;

  /// Writes the chunks in memory, all full, to the end of the temporary file and frees them;
  /// false after an error.
  bool spill() {
    if (!spill_) {
      spill_.reset(std::tmpfile());
      if (!spill_) return failed("cannot create");
    }
    if (spilled_ > 0 && std::fseek(spill_.get(), 0, SEEK_END) != 0) return failed("cannot go to the end of");
    for (; spilled_ < chunks_.size(); ++spilled_) {
      if (std::fwrite(chunks_[spilled_].get(), 1, sizes_[spilled_], spill_.get()) != sizes_[spilled_])
        return failed("cannot write");
      chunks_[spilled_].reset();
    }
    if (std::fflush(spill_.get()) != 0) return failed("cannot write");
    held_bytes_ = 0;
    return true;
  }

  bool failed(const char* what) const {
    const int why = errno;
    error_ = std::string(what) + " the temporary file that holds the executed blocks beyond " +
             std::to_string(memory_bytes_) + " bytes (--max-memory-bytes)" +
             (why ? std::string(": ") + std::strerror(why) : std::string());
    return false;
  }

  /// The index of `f` for a record: 0 for the store's file, else in files_ from 1. A reader
  /// gives the blocks of a file one shared name, so the name of the last block, held (its string
  /// cannot be freed and another take its place), answers with one comparison of pointers.
  std::uint64_t file_index(const file_name& f) {
    if (&f.str() == &last_file_.str()) return last_file_index_;
    last_file_ = f;
    last_file_index_ = [&]() -> std::uint64_t {
      if (f.str() == file_.str()) return 0;
      for (std::size_t i = files_.size(); i > 0; --i)  // the latest first: blocks of one file come together
        if (f.str() == files_[i - 1].str()) return i;
      files_.push_back(f);
      return files_.size();
    }();
    return last_file_index_;
  }

  void put_bytes(const void* bytes, std::size_t n) {
    std::memcpy(write_, bytes, n);
    write_ += n;
  }
  template <class T>
  void put(const T& v) {
    put_bytes(&v, sizeof v);
  }
  void put_size(std::uint64_t v) {  // LEB128
    do {
      const auto low = static_cast<unsigned char>(v & 0x7f);
      v >>= 7;
      *write_++ = v ? static_cast<unsigned char>(low | 0x80) : low;
    } while (v);
  }
  void put_string(std::string_view s) {
    put_size(s.size());
    put_bytes(s.data(), s.size());
  }

  template <class T>
  static const unsigned char* get(const unsigned char* p, T& v) {
    std::memcpy(&v, p, sizeof v);
    return p + sizeof v;
  }
  static const unsigned char* get_size(const unsigned char* p, std::uint64_t& v) {
    v = 0;
    for (int shift = 0;; shift += 7) {
      const unsigned char byte = *p++;
      v |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
      if (!(byte & 0x80)) return p;
    }
  }
  static const unsigned char* get_string(const unsigned char* p, std::string& s) {
    std::uint64_t n = 0;
    p = get_size(p, n);
    s.assign(reinterpret_cast<const char*>(p), static_cast<std::size_t>(n));
    return p + n;
  }
  template <class T>
  static const unsigned char* get_optional(const unsigned char* p, std::uint32_t flags, std::uint32_t bit,
                                           std::optional<T>& v) {
    if (!(flags & bit)) return p;
    T value{};
    p = get(p, value);
    v = value;
    return p;
  }

  // The state words' codec (`state_fields`).
  static constexpr unsigned state_bit_count = std::apply(
      [](auto... field) { return (detail::state_bits_of<std::remove_cvref_t<decltype(state_words{}.*field)>>() + ...); },
      state_fields);
  static_assert(state_bit_count <= 32, "the state words' word has a bit for each");
  static_assert(std::is_trivially_copyable_v<state_words>, "state values are kept as their bytes");

  template <class T>
  static void state_bit(const T& v, std::uint32_t& bits, unsigned& bit) {
    if constexpr (std::is_same_v<T, std::optional<bool>>) {
      if (v) bits |= 1u << bit;
      if (v.value_or(false)) bits |= 1u << (bit + 1);
    } else if (v) {  // a bool's value, or an optional's presence
      bits |= 1u << bit;
    }
    bit += detail::state_bits_of<T>();
  }
  template <class T>
  void put_state_value(const T& v) {
    if constexpr (!std::is_same_v<T, bool> && !std::is_same_v<T, std::optional<bool>>)
      if (v) put(*v);
  }
  void put_state(const state_words& s) {
    std::uint32_t bits = 0;
    unsigned bit = 0;
    std::apply([&](auto... field) { (state_bit(s.*field, bits, bit), ...); }, state_fields);
    put(bits);
    std::apply([&](auto... field) { (put_state_value(s.*field), ...); }, state_fields);
  }
  template <class T>
  static const unsigned char* get_state_field(const unsigned char* p, std::uint32_t bits, unsigned& bit, T& v) {
    const bool on = (bits >> bit & 1u) != 0;
    if constexpr (std::is_same_v<T, bool>) {
      v = on;
    } else if constexpr (std::is_same_v<T, std::optional<bool>>) {
      if (on) v = (bits >> (bit + 1) & 1u) != 0;
    } else if (on) {
      typename T::value_type value{};
      p = get(p, value);
      v = value;
    }
    bit += detail::state_bits_of<T>();
    return p;
  }
  static const unsigned char* get_state(const unsigned char* p, state_words& s) {
    std::uint32_t bits = 0;
    p = get(p, bits);
    unsigned bit = 0;
    std::apply([&](auto... field) { ((p = get_state_field(p, bits, bit, s.*field)), ...); }, state_fields);
    return p;
  }

  void encode(const block& b, bool keep_text) {
    std::uint32_t flags = 0, others = 0;
    const auto set = [](std::uint32_t& word, bool on, std::uint32_t bit) {
      if (on) word |= bit;
    };
    set(flags, keep_text && !b.text.empty(), has_text);
    set(flags, b.number.has_value(), has_number);
    set(flags, b.spindle_rpm.has_value(), has_rpm);
    set(flags, !b.m_codes.empty(), has_m);
    set(flags, b.motion.has_value(), has_motion);
    set(flags, b.axes.x_mm.has_value(), has_x);
    set(flags, b.axes.y_mm.has_value(), has_y);
    set(flags, b.axes.z_mm.has_value(), has_z);
    set(flags, b.axes.a_deg.has_value(), has_a);
    set(flags, b.axes.b_deg.has_value(), has_b);
    set(flags, b.axes.c_deg.has_value(), has_c);
    set(flags, b.axes.tool_axis.has_value(), has_tool_axis);
    set(flags, b.arc.has_value(), has_arc);
    set(flags, b.arc && b.arc->centre_mm, arc_centre);
    set(flags, b.arc && b.arc->radius_mm, arc_radius);
    set(flags, b.feed.has_value(), has_feed);
    set(flags, b.feed_rapid, feed_rapid);
    set(flags, !b.state.empty(), has_state);
    set(flags, b.call_chain != 0, has_call_chain);
    const std::uint64_t file = file_index(b.where.file);
    set(flags, file != 0, other_file);
    set(others, b.program_begin.has_value(), has_begin);
    set(others, b.program_end.has_value(), has_end);
    set(others, b.comment.has_value(), has_comment);
    set(others, b.tcp.has_value(), has_tcp);
    set(others, b.tcp.value_or(false), tcp_on);
    set(others, b.feed_mode.has_value(), has_feed_mode);
    set(others, b.metric.has_value(), has_metric);
    set(others, b.metric.value_or(false), metric_on);
    set(others, b.tool.has_value(), has_tool);
    set(others, b.tool_name.has_value(), has_tool_name);
    set(others, !b.kept_words.empty(), has_kept);
    set(others, b.machine_coordinates, machine_coordinates);
    set(others, b.passthrough, passthrough);
    set(others, b.framing, framing);
    set(others, b.assignment, assignment);
    set(others, b.alarm.has_value(), has_alarm);
    set(others, b.alarm && b.alarm->number, alarm_number);
    set(flags, others != 0, has_other);
    // An upper bound of the record's size: the fixed part, then the strings and lists (a
    // LEB128 size takes at most 10 bytes).
    constexpr std::size_t leb = 10;
    std::size_t size = sizeof flags + sizeof others + 4 * leb + sizeof(long long) + sizeof(feed_unit) +
                       sizeof(long long) + sizeof(double) + sizeof(motion_kind) + 6 * sizeof(double) + sizeof(vec3) +
                       sizeof(arc_plane) + sizeof(vec3) + sizeof(double) + sizeof(double) + leb + sizeof(std::uint32_t) +
                       sizeof(state_words) + sizeof(long long) + sizeof(machine_position);
    if (flags & has_text) size += leb + b.text.size();
    if (b.alarm) size += leb + b.alarm->message.size();
    for (const auto* s : {&b.program_begin, &b.program_end, &b.comment, &b.tool_name})
      if (*s) size += leb + (*s)->size();
    size += leb + sizeof(int) * b.m_codes.size();
    for (const auto& w : b.kept_words) size += leb + w.size();
    record_.resize(size);
    write_ = record_.data();
    put(flags);
    put_size(b.where.line);
    put_size(b.where.column);
    if (flags & has_call_chain) put_size(b.call_chain);
    if (flags & other_file) put_size(file);
    if (flags & has_text) put_string(b.text);
    if (flags & has_number) put(*b.number);
    if (flags & has_other) {
      put(others);
      if (others & has_begin) put_string(*b.program_begin);
      if (others & has_end) put_string(*b.program_end);
      if (others & has_comment) put_string(*b.comment);
      if (others & has_feed_mode) put(*b.feed_mode);
      if (others & has_tool) put(*b.tool);
      if (others & has_tool_name) put_string(*b.tool_name);
      if (others & has_kept) {
        put_size(b.kept_words.size());
        for (const auto& w : b.kept_words) put_string(w);
      }
      if (others & has_alarm) {
        put_string(b.alarm->message);
        if (others & alarm_number) put(*b.alarm->number);
      }
      if (others & machine_coordinates) put(b.machine_reference);  // what the words name
    }
    if (flags & has_rpm) put(*b.spindle_rpm);
    if (flags & has_m) {
      put_size(b.m_codes.size());
      for (int m : b.m_codes) put(m);
    }
    if (flags & has_motion) put(*b.motion);
    if (flags & has_x) put(*b.axes.x_mm);
    if (flags & has_y) put(*b.axes.y_mm);
    if (flags & has_z) put(*b.axes.z_mm);
    if (flags & has_a) put(*b.axes.a_deg);
    if (flags & has_b) put(*b.axes.b_deg);
    if (flags & has_c) put(*b.axes.c_deg);
    if (flags & has_tool_axis) put(*b.axes.tool_axis);
    if (flags & has_arc) put(b.arc->plane);
    if (flags & arc_centre) put(*b.arc->centre_mm);
    if (flags & arc_radius) put(*b.arc->radius_mm);
    if (flags & has_feed) put(*b.feed);
    if (flags & has_state) put_state(b.state);
  }

  /// Reads one record into `b`, every field replaced; `file`: the index of `b.where.file` (see
  /// `file_index`), kept from record to record so that the name is copied only when it changes.
  const unsigned char* decode(const unsigned char* p, block& b, std::uint64_t& file) const {
    b.text.clear();
    b.number.reset();
    b.program_begin.reset();
    b.program_end.reset();
    b.comment.reset();
    b.tcp.reset();
    b.feed_mode.reset();
    b.metric.reset();
    b.tool.reset();
    b.tool_name.reset();
    b.spindle_rpm.reset();
    b.m_codes.clear();
    b.motion.reset();
    b.axes = {};
    b.arc.reset();
    b.feed.reset();
    b.kept_words.clear();
    b.state = {};
    b.alarm.reset();
    b.machine_reference = machine_position::machine_zero;
    std::uint32_t flags = 0, others = 0;
    p = get(p, flags);
    std::uint64_t v = 0;
    p = get_size(p, v);
    b.where.line = static_cast<std::size_t>(v);
    p = get_size(p, v);
    b.where.column = static_cast<std::size_t>(v);
    b.call_chain = 0;
    if (flags & has_call_chain) {
      p = get_size(p, v);
      b.call_chain = static_cast<std::uint32_t>(v);
    }
    v = 0;
    if (flags & other_file) p = get_size(p, v);
    if (v != file) {
      file = v;
      b.where.file = file == 0 ? file_ : files_[static_cast<std::size_t>(file - 1)];
    }
    if (flags & has_text) p = get_string(p, b.text);
    p = get_optional(p, flags, has_number, b.number);
    if (flags & has_other) {
      p = get(p, others);
      if (others & has_begin) p = get_string(p, b.program_begin.emplace());
      if (others & has_end) p = get_string(p, b.program_end.emplace());
      if (others & has_comment) p = get_string(p, b.comment.emplace());
      if (others & has_tcp) b.tcp = (others & tcp_on) != 0;
      p = get_optional(p, others, has_feed_mode, b.feed_mode);
      if (others & has_metric) b.metric = (others & metric_on) != 0;
      p = get_optional(p, others, has_tool, b.tool);
      if (others & has_tool_name) p = get_string(p, b.tool_name.emplace());
      if (others & has_kept) {
        p = get_size(p, v);
        b.kept_words.resize(static_cast<std::size_t>(v));
        for (auto& w : b.kept_words) p = get_string(p, w);
      }
      if (others & has_alarm) {
        alarm_stop& alarm = b.alarm.emplace();
        p = get_string(p, alarm.message);
        p = get_optional(p, others, alarm_number, alarm.number);
      }
      if (others & machine_coordinates) p = get(p, b.machine_reference);
    }
    p = get_optional(p, flags, has_rpm, b.spindle_rpm);
    if (flags & has_m) {
      p = get_size(p, v);
      b.m_codes.resize(static_cast<std::size_t>(v));
      for (int& m : b.m_codes) p = get(p, m);
    }
    p = get_optional(p, flags, has_motion, b.motion);
    p = get_optional(p, flags, has_x, b.axes.x_mm);
    p = get_optional(p, flags, has_y, b.axes.y_mm);
    p = get_optional(p, flags, has_z, b.axes.z_mm);
    p = get_optional(p, flags, has_a, b.axes.a_deg);
    p = get_optional(p, flags, has_b, b.axes.b_deg);
    p = get_optional(p, flags, has_c, b.axes.c_deg);
    p = get_optional(p, flags, has_tool_axis, b.axes.tool_axis);
    if (flags & has_arc) {
      arc_words& arc = b.arc.emplace();
      p = get(p, arc.plane);
      p = get_optional(p, flags, arc_centre, arc.centre_mm);
      p = get_optional(p, flags, arc_radius, arc.radius_mm);
    }
    p = get_optional(p, flags, has_feed, b.feed);
    b.feed_rapid = (flags & feed_rapid) != 0;
    b.machine_coordinates = (others & machine_coordinates) != 0;
    b.passthrough = (others & passthrough) != 0;
    b.framing = (others & framing) != 0;
    b.assignment = (others & assignment) != 0;
    if (flags & has_state) p = get_state(p, b.state);
    return p;
  }
};

}  // namespace kin5::program
