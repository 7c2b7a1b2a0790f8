/// @file program/block_store.hpp
/// A compact, append-only record of the blocks of one program, to be replayed in order: what a
/// second pass over a program reads instead of parsing the text again.
///
/// Each block is packed into a byte record: one word of flags (which fields are present; its last
/// bit says a byte of flags for the rarer fields follows), then only the fields present, numbers as their exact bytes, strings with their length. A motion
/// block `N… G1 X Y Z A B F` takes about 70 bytes, a quarter of `sizeof(block)` and without
/// its heap parts. Records go into chunks, so the store grows without copying: a record that
/// does not fit the rest of the last chunk starts a new one, of its own size if it is larger.
/// Chunks double from 64 KiB up to 1 MiB, so a short program does not take a whole 1 MiB.
/// `replay` gives back blocks equal (`==`) to those stored, except:
/// - `where.file` is the store's file name (one per program, not one per block);
/// - `text` is dropped where the caller asks (`keep_text`), for blocks whose consumer never
///   reads it: the translator does not read the text of a block it moves.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "block.hpp"

namespace kin5::program {

/// The blocks of one program as compact records, replayed in the order stored.
class block_store {
 public:
  /// Bytes of a chunk once the chunks have grown, unless a record needs more.
  static constexpr std::size_t default_chunk_bytes = std::size_t{1} << 20;
  /// Bytes of the first chunk; each next one doubles, up to the chunk size.
  static constexpr std::size_t default_first_chunk_bytes = std::size_t{1} << 16;

  explicit block_store(std::string file, std::size_t chunk_bytes = default_chunk_bytes,
                       std::size_t first_chunk_bytes = default_first_chunk_bytes)
      : file_(std::move(file)),
        chunk_bytes_(std::max<std::size_t>(chunk_bytes, 1)),
        next_chunk_bytes_(std::clamp<std::size_t>(first_chunk_bytes, 1, chunk_bytes_)) {}

  /// Appends `b` (without its text unless `keep_text`).
  void push(const block& b, bool keep_text = true) {
    encode(b, keep_text);
    record_.resize(static_cast<std::size_t>(write_ - record_.data()));
    if (chunks_.empty() || capacity_ - used_ < record_.size()) {  // used_ <= capacity_ always
      capacity_ = std::max(next_chunk_bytes_, record_.size());
      next_chunk_bytes_ = std::min(chunk_bytes_, 2 * next_chunk_bytes_);
      // Not zeroed: replay reads only the bytes push copied in (up to sizes_).
      chunks_.push_back(std::make_unique_for_overwrite<unsigned char[]>(capacity_));
      sizes_.push_back(0);
      used_ = 0;
    }
    std::memcpy(chunks_.back().get() + used_, record_.data(), record_.size());
    used_ += record_.size();
    sizes_.back() = used_;
    ++count_;
  }

  /// Calls `f(const block&)` for every stored block, in the order pushed. The store is
  /// unchanged. One block object is reused for all, so its strings keep their capacity.
  template <class F>
  void replay(F&& f) const {
    block b;
    b.where.file = file_;
    for (std::size_t c = 0; c < chunks_.size(); ++c) {
      const unsigned char* p = chunks_[c].get();
      const unsigned char* const end = p + sizes_[c];
      while (p < end) {
        p = decode(p, b);
        f(std::as_const(b));
      }
    }
  }

  std::size_t size() const { return count_; }
  /// Chunks allocated so far.
  std::size_t chunks() const { return chunks_.size(); }
  /// Bytes held by the records (chunks are allocated a chunk at a time).
  std::size_t bytes() const {
    std::size_t n = 0;
    for (std::size_t s : sizes_) n += s;
    return n;
  }

 private:
  // One bit per optional field or flag, in the order the fields follow the flags.
  enum flag : std::uint32_t {
    has_text = 1u << 0, has_number = 1u << 1, has_begin = 1u << 2, has_end = 1u << 3, has_comment = 1u << 4,
    has_tcp = 1u << 5, tcp_on = 1u << 6, has_feed_mode = 1u << 7, has_metric = 1u << 8, metric_on = 1u << 9,
    has_tool = 1u << 10, has_rpm = 1u << 11, has_m = 1u << 12, has_motion = 1u << 13, has_x = 1u << 14,
    has_y = 1u << 15, has_z = 1u << 16, has_a = 1u << 17, has_b = 1u << 18, has_c = 1u << 19,
    has_tool_axis = 1u << 20, has_arc = 1u << 21, arc_centre = 1u << 22, arc_radius = 1u << 23,
    has_feed = 1u << 24, feed_rapid = 1u << 25, machine_coordinates = 1u << 26, has_kept = 1u << 27,
    passthrough = 1u << 28, has_state = 1u << 29, framing = 1u << 30,
    has_more = 1u << 31,  // a byte of `more_fields` follows the flags
  };
  // The byte after the flags when `has_more` is set: the rarer fields and flags, so that the
  // common records keep one word of flags.
  enum more_fields : unsigned char { assignment = 1u << 0, has_alarm = 1u << 1, alarm_number = 1u << 2 };
  // The byte after the flags' `has_tool`: which of the tool's fields follow.
  enum tool_fields : unsigned char { tool_number = 1u << 0, tool_named = 1u << 1 };

  std::string file_;
  std::vector<std::unique_ptr<unsigned char[]>> chunks_;
  std::vector<std::size_t> sizes_;
  std::size_t chunk_bytes_;
  std::size_t next_chunk_bytes_;  // of the next chunk: doubles after each, up to chunk_bytes_
  std::size_t capacity_ = 0, used_ = 0, count_ = 0;  // of the last chunk: its size, bytes used
  std::vector<unsigned char> record_;  // the record being built
  unsigned char* write_ = nullptr;     // where `put` writes in it

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

  void encode(const block& b, bool keep_text) {
    std::uint32_t flags = 0;
    const auto set = [&](bool on, std::uint32_t bit) {
      if (on) flags |= bit;
    };
    set(keep_text && !b.text.empty(), has_text);
    set(b.number.has_value(), has_number);
    set(b.program_begin.has_value(), has_begin);
    set(b.program_end.has_value(), has_end);
    set(b.comment.has_value(), has_comment);
    set(b.tcp.has_value(), has_tcp);
    set(b.tcp.value_or(false), tcp_on);
    set(b.feed_mode.has_value(), has_feed_mode);
    set(b.metric.has_value(), has_metric);
    set(b.metric.value_or(false), metric_on);
    set(b.tool || b.tool_name, has_tool);  // then a byte says which: tool_number, tool_name
    set(b.spindle_rpm.has_value(), has_rpm);
    set(!b.m_codes.empty(), has_m);
    set(b.motion.has_value(), has_motion);
    set(b.axes.x_mm.has_value(), has_x);
    set(b.axes.y_mm.has_value(), has_y);
    set(b.axes.z_mm.has_value(), has_z);
    set(b.axes.a_deg.has_value(), has_a);
    set(b.axes.b_deg.has_value(), has_b);
    set(b.axes.c_deg.has_value(), has_c);
    set(b.axes.tool_axis.has_value(), has_tool_axis);
    set(b.arc.has_value(), has_arc);
    set(b.arc && b.arc->centre_mm, arc_centre);
    set(b.arc && b.arc->radius_mm, arc_radius);
    set(b.feed.has_value(), has_feed);
    set(b.feed_rapid, feed_rapid);
    set(b.machine_coordinates, machine_coordinates);
    set(!b.kept_words.empty(), has_kept);
    set(b.passthrough, passthrough);
    set(b.framing, framing);
    set(!b.state.empty(), has_state);
    unsigned char more = 0;
    if (b.assignment) more |= assignment;
    if (b.alarm) more |= has_alarm;
    if (b.alarm && b.alarm->number) more |= alarm_number;
    set(more != 0, has_more);
    // An upper bound of the record's size: the fixed part, then the strings and lists (a
    // LEB128 size takes at most 10 bytes).
    constexpr std::size_t leb = 10;
    std::size_t size = sizeof flags + 2 * leb + sizeof(long long) + sizeof(feed_unit) + 1 + sizeof(long long) +
                       sizeof(double) + sizeof(motion_kind) + 6 * sizeof(double) + sizeof(vec3) + sizeof(arc_plane) +
                       sizeof(vec3) + sizeof(double) + sizeof(double) + leb + sizeof(state_words) + 1 +
                       sizeof(long long);
    if (flags & has_text) size += leb + b.text.size();
    for (const auto* s : {&b.program_begin, &b.program_end, &b.comment, &b.tool_name})
      if (*s) size += leb + (*s)->size();
    size += leb + sizeof(int) * b.m_codes.size();
    for (const auto& w : b.kept_words) size += leb + w.size();
    if (b.alarm) size += leb + b.alarm->message.size();
    record_.resize(size);
    write_ = record_.data();
    put(flags);
    if (flags & has_more) put(more);
    put_size(b.where.line);
    put_size(b.where.column);
    if (flags & has_text) put_string(b.text);
    if (flags & has_number) put(*b.number);
    if (flags & has_begin) put_string(*b.program_begin);
    if (flags & has_end) put_string(*b.program_end);
    if (flags & has_comment) put_string(*b.comment);
    if (flags & has_feed_mode) put(*b.feed_mode);
    if (flags & has_tool) {
      put(static_cast<unsigned char>((b.tool ? tool_number : 0) | (b.tool_name ? tool_named : 0)));
      if (b.tool) put(*b.tool);
      if (b.tool_name) put_string(*b.tool_name);
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
    if (flags & has_kept) {
      put_size(b.kept_words.size());
      for (const auto& w : b.kept_words) put_string(w);
    }
    if (flags & has_state) put(b.state);  // trivially copyable (state_words.hpp)
    if (more & has_alarm) {
      put_string(b.alarm->message);
      if (more & alarm_number) put(*b.alarm->number);
    }
  }

  /// Reads one record into `b`, every field but `where.file` replaced.
  static const unsigned char* decode(const unsigned char* p, block& b) {
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
    std::uint32_t flags = 0;
    p = get(p, flags);
    unsigned char more = 0;
    if (flags & has_more) p = get(p, more);
    std::uint64_t v = 0;
    p = get_size(p, v);
    b.where.line = static_cast<std::size_t>(v);
    p = get_size(p, v);
    b.where.column = static_cast<std::size_t>(v);
    if (flags & has_text) p = get_string(p, b.text);
    p = get_optional(p, flags, has_number, b.number);
    if (flags & has_begin) p = get_string(p, b.program_begin.emplace());
    if (flags & has_end) p = get_string(p, b.program_end.emplace());
    if (flags & has_comment) p = get_string(p, b.comment.emplace());
    if (flags & has_tcp) b.tcp = (flags & tcp_on) != 0;
    p = get_optional(p, flags, has_feed_mode, b.feed_mode);
    if (flags & has_metric) b.metric = (flags & metric_on) != 0;
    if (flags & has_tool) {
      unsigned char which = 0;
      p = get(p, which);
      p = get_optional(p, which & tool_number ? flags : 0, has_tool, b.tool);
      if (which & tool_named) p = get_string(p, b.tool_name.emplace());
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
    b.machine_coordinates = (flags & machine_coordinates) != 0;
    if (flags & has_kept) {
      p = get_size(p, v);
      b.kept_words.resize(static_cast<std::size_t>(v));
      for (auto& w : b.kept_words) p = get_string(p, w);
    }
    if (flags & has_state) p = get(p, b.state);
    if (more & has_alarm) {
      alarm_stop& alarm = b.alarm.emplace();
      p = get_string(p, alarm.message);
      p = get_optional(p, more, alarm_number, alarm.number);
    }
    b.passthrough = (flags & passthrough) != 0;
    b.framing = (flags & framing) != 0;
    b.assignment = (more & assignment) != 0;
    return p;
  }
};

}  // namespace kin5::program
