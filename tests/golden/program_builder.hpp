/// @file program_builder.hpp
/// Building small dialect-neutral programs in tests: a TCP-on block, then motion blocks given
/// as numbers, each on its own line of a named file.
#pragma once

#include <optional>
#include <string>

#include <kin5/translate/translate.hpp>

namespace kin5::test {

struct motion_words {
  double x, y, z;
  std::optional<double> a, b, c;
  std::optional<double> f;
};

/// Appends one block on the next line of `p`.
inline program::block& add_block(program::program& p) {
  program::block b;
  b.where = {p.file, p.blocks.size() + 1, 1};
  p.blocks.push_back(b);
  return p.blocks.back();
}

/// Appends a linear (G1) motion block.
inline program::block& add_motion(program::program& p, const motion_words& w,
                                  program::motion_kind kind = program::motion_kind::linear) {
  program::block& b = add_block(p);
  b.motion = kind;
  b.axes.x_mm = w.x, b.axes.y_mm = w.y, b.axes.z_mm = w.z;
  b.axes.a_deg = w.a, b.axes.b_deg = w.b, b.axes.c_deg = w.c;
  b.feed = w.f;
  return b;
}

/// A program in `language` whose first block switches tool-tip tracking on; with `tool`, a
/// change to that tool comes first (ISO output needs it: `G43.4 H` is the tool's register).
inline program::program tcp_program(program::dialect language, std::string file = "test.nc",
                                     std::optional<long long> tool = std::nullopt) {
  program::program p;
  p.language = language;
  p.file = std::move(file);
  if (tool) {
    program::block& change = add_block(p);
    change.tool = *tool;
    change.state.tool_change = true;
  }
  add_block(p).tcp = true;
  return p;
}

/// Translation options, spelled positionally (keeps -Wextra quiet about the others).
inline translate_options options(feed_policy feed = feed_policy::tcp,
                                 program::dialect out = program::id_of<program::heidenhain::dialect>(),
                                 std::optional<rigid_transform> setup = std::nullopt) {
  translate_options o;
  o.feed = feed;
  o.output_dialect = out;
  o.setup = setup;
  return o;
}

}  // namespace kin5::test
