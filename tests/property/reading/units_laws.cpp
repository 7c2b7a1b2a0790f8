// Inch programs between every ordered pair of dialects. A generated inch program (positions on
// the 0.0001 inch grid, feeds in 0.1 inch/min), as the source dialect's own reader gives it, is
// written by the target's writer and read back by the target's own reader: every move keeps its
// unit, its position and its feed (the same model), or the target refuses with its documented
// message (Heidenhain states the unit in BEGIN PGM only). Its mm twin — the same numerals in
// millimetres — gives a model exactly 25.4 times smaller, within the output's resolution.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/program/io.hpp>

#include "dialect_pairs.hpp"

using namespace kin5::program;

namespace {

/// What a program says at one move: the unit in force, the point and the feed (mm, mm/min).
struct at_move {
  bool inch = false;
  double x = 0, y = 0, z = 0;
  std::optional<double> feed;
};

std::vector<at_move> moves_of(const std::vector<block>& blocks) {
  std::vector<at_move> out;
  bool inch = false;
  std::optional<double> feed;
  for (const block& b : blocks) {
    if (b.metric) inch = !*b.metric;
    if (b.feed) feed = b.feed;
    if (b.moves()) out.push_back({inch, *b.axes.x_mm, *b.axes.y_mm, *b.axes.z_mm, feed});
  }
  return out;
}

/// A program of `n` moves whose numerals are `numerals` (positions, then the feed per move),
/// in inches (`inch`) or millimetres, framed as every dialect frames one.
program make_program(dialect d, const std::vector<double>& numerals, bool inch) {
  const double unit = inch ? 25.4 : 1.0;
  program p;
  p.language = d;
  p.file = "gen";
  block begin;
  begin.program_begin = "P";
  begin.metric = !inch;
  p.blocks.push_back(begin);
  for (std::size_t k = 0; k + 3 < numerals.size(); k += 4) {
    block b;
    b.motion = motion_kind::linear;
    b.axes.x_mm = numerals[k] * unit, b.axes.y_mm = numerals[k + 1] * unit, b.axes.z_mm = numerals[k + 2] * unit;
    b.feed = numerals[k + 3] * unit;
    p.blocks.push_back(b);
  }
  block end;
  end.program_end = "P";
  p.blocks.push_back(end);
  return p;
}

/// Numerals of a program: positions to 4 decimals, feeds to 1 decimal, 1 to 20 moves.
std::vector<double> draw_numerals() {
  std::vector<double> out;
  const int n = *rc::gen::inRange(1, 21);
  for (int k = 0; k < n; ++k) {
    for (int a = 0; a < 3; ++a) out.push_back(*rc::gen::inRange(-400000, 400001) / 1e4);
    out.push_back(*rc::gen::inRange(1, 4000) / 10.0);
  }
  return out;
}

/// The program as `d`'s own reader gives it back from `d`'s text.
std::optional<program> as_read(dialect d, const program& p) {
  const read_result r = read(d, write(d, p), "src");
  if (!r.ok()) return std::nullopt;
  return r.parsed;
}

/// `p` written in `to` and read back by `to`'s reader; nothing when `to` refuses (the message in `why`).
std::optional<program> through(dialect to, const program& p, std::string& why) {
  std::string text;
  try {
    text = write(to, p);
  } catch (const std::invalid_argument& e) {
    why = e.what();
    return std::nullopt;
  }
  const read_result r = read(to, text, "back");
  RC_ASSERT(r.ok());
  return r.parsed;
}

}  // namespace

TEST_CASE("units: an inch program keeps its unit, positions and feeds between every pair of dialects") {
  using kin5::test::all_dialects;
  kin5::test::check_each_pair(all_dialects(), all_dialects(), [](dialect from, dialect to) {
    const auto source = as_read(from, make_program(from, draw_numerals(), true));
    RC_ASSERT(source.has_value());
    std::string why;
    const auto back = through(to, *source, why);  // Heidenhain too: BEGIN PGM … INCH frames any source
    RC_ASSERT(back.has_value());
    const auto want = moves_of(source->blocks), got = moves_of(back->blocks);
    RC_ASSERT(got.size() == want.size());
    for (std::size_t k = 0; k < want.size(); ++k) {
      RC_ASSERT(want[k].inch);
      RC_ASSERT(got[k].inch);
      RC_ASSERT(std::abs(got[k].x - want[k].x) < 1e-6);
      RC_ASSERT(std::abs(got[k].y - want[k].y) < 1e-6);
      RC_ASSERT(std::abs(got[k].z - want[k].z) < 1e-6);
      RC_ASSERT(got[k].feed.has_value());
      RC_ASSERT(std::abs(*got[k].feed - *want[k].feed) < 1e-6);
    }
  });
}

TEST_CASE("units: an inch program and its mm twin differ by 25.4 in every target, within its resolution") {
  using kin5::test::all_dialects;
  kin5::test::check_each_pair(all_dialects(), all_dialects(), [](dialect from, dialect to) {
    const std::vector<double> numerals = draw_numerals();
    const auto inch = as_read(from, make_program(from, numerals, true));
    const auto mm = as_read(from, make_program(from, numerals, false));
    RC_ASSERT(inch.has_value() && mm.has_value());
    std::string why;
    const auto inch_back = through(to, *inch, why), mm_back = through(to, *mm, why);
    RC_ASSERT(mm_back.has_value());
    if (!inch_back) return;  // the refusal is the law above's
    const auto a = moves_of(inch_back->blocks), b = moves_of(mm_back->blocks);
    RC_ASSERT(a.size() == b.size());
    // The mm twin is written to 3 decimals (its numerals have 4): half a unit of the last
    // decimal, times 25.4; feeds likewise to their last decimal.
    const double position = 25.4 * 0.5e-3 + 1e-9;
    for (std::size_t k = 0; k < a.size(); ++k) {
      RC_ASSERT(a[k].inch && !b[k].inch);
      RC_ASSERT(std::abs(a[k].x - 25.4 * b[k].x) <= position);
      RC_ASSERT(std::abs(a[k].y - 25.4 * b[k].y) <= position);
      RC_ASSERT(std::abs(a[k].z - 25.4 * b[k].z) <= position);
      RC_ASSERT(std::abs(*a[k].feed - 25.4 * *b[k].feed) <= 25.4 * 0.05 + 1e-9);
    }
  });
}
