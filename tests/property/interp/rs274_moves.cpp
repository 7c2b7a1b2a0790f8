// An independent oracle for LinuxCNC moves: random programs mixing G90 and G91, G0 and G1, G2
// and G3 (with I J and with R, in each plane), in inches or millimetres, run by rs274
// (rs274_canonical.hpp) and read by kin5's LinuxCNC reader into canonical operations
// (program/canonical/): each of kin5's moves is rs274's canonical move of the same kind
// (rapid_move STRAIGHT_TRAVERSE, linear_move STRAIGHT_FEED, arc_move ARC_FEED, turning the same
// way), ends where it ends, to 1e-9, and an arc with I J (K) has rs274's centre. rs274 prints
// 4 decimals, so the programs use positions of 3 decimals, whose sums and arc ends on quarter
// turns stay on 3 decimals: rs274's printed value is then the exact one, and the comparison to
// 1e-9 means what it says. rs274 works in the program's unit (USE_LENGTH_UNITS); kin5's
// operations hold millimetres, divided by 25.4 after a `use_length_units` inch. The same with
// part of the moves in a subroutine of another file, `o<part> call`, which rs274 finds on its
// ini file's SUBROUTINE_PATH and kin5 in its include directory.
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/canonical/block_operations.hpp>
#include <kin5/program/linuxcnc/reader.hpp>
#include <kin5/program/number.hpp>
#include <kin5/program/read_limits.hpp>

#include <unistd.h>

#include "rs274_canonical.hpp"

namespace {

using namespace kin5::program;
namespace rs = kin5::test::rs274;
namespace can = kin5::program::canonical;

/// A position in thousandths as text.
std::string at(long long n) { return format_number(static_cast<double>(n) / 1000.0, 3); }

/// A drawn program and the unit it is in.
struct drawn {
  std::string text;
  bool inches = false;
};

/// Random moves after an absolute start of all six axes; positions in thousandths.
drawn draw_moves() {
  drawn d;
  d.inches = *rc::gen::arbitrary<bool>();
  std::array<long long, 6> pos{};
  for (int k = 0; k < 6; ++k) pos[k] = *rc::gen::inRange(-100000, 100000);
  const char* names = "XYZABC";
  d.text = d.inches ? "G20" : "G21";
  d.text += " G17 G90 G94 F100\nG0";
  for (int k = 0; k < 6; ++k) d.text += std::string(" ") + names[k] + at(pos[k]);
  d.text += "\n";
  bool g91 = false;
  int plane = 0;  // 0 XY, 1 XZ (G18), 2 YZ (G19)
  const int count = *rc::gen::inRange(1, 30);
  for (int i = 0; i < count; ++i) {
    std::string line;
    if (*rc::gen::inRange(0, 3) == 0) {
      g91 = *rc::gen::arbitrary<bool>();
      line += g91 ? "G91 " : "G90 ";
    }
    if (*rc::gen::inRange(0, 6) == 0) {
      plane = *rc::gen::inRange(0, 3);
      line += plane == 0 ? "G17 " : plane == 1 ? "G18 " : "G19 ";
    }
    std::array<long long, 6> to = pos;
    std::array<bool, 6> said{};
    const int kind = *rc::gen::inRange(0, 4);  // G0, G1, G2, G3
    line += "G" + std::to_string(kind);
    std::string arc_words;
    if (kind < 2) {
      for (int k = 0; k < 6; ++k)
        if (*rc::gen::inRange(0, 2) == 0) to[k] = *rc::gen::inRange(-100000, 100000), said[k] = true;
      // at least one axis word: rs274 runs a G0 or G1 without any as a move to where it stands,
      // kin5 reads no move there (nothing moves)
      if (said == std::array<bool, 6>{}) to[0] = *rc::gen::inRange(-100000, 100000), said[0] = true;
    } else {
      // plane coordinates p, q (X Y, Z X, Y Z as rs274 orders them) and the axis n
      const int p = plane == 0 ? 0 : plane == 1 ? 2 : 1, q = plane == 0 ? 1 : plane == 1 ? 0 : 2, n = 3 - p - q;
      if (*rc::gen::arbitrary<bool>()) {  // I J K: the centre; the end a quarter, half or three quarters on
        long long c[2] = {*rc::gen::inRange(-20000, 20000), *rc::gen::inRange(-20000, 20000)};
        if (std::llabs(c[0]) + std::llabs(c[1]) < 10) c[0] = 10;
        const long long vp = -c[0], vq = -c[1];  // centre to start
        const int turns = *rc::gen::inRange(1, 4);
        long long ep = vp, eq = vq;
        for (int t = 0; t < turns; ++t) {
          const long long r = ep;
          ep = -eq, eq = r;
        }
        to[p] = pos[p] + c[0] + ep, to[q] = pos[q] + c[1] + eq;
        said[p] = said[q] = true;
        const char letters[] = "IJK";
        arc_words += std::string(" ") + letters[p] + at(c[0]) + " " + letters[q] + at(c[1]);
      } else {  // R: at least half the chord
        to[p] = pos[p] + *rc::gen::inRange(-20000, 20000), to[q] = pos[q] + *rc::gen::inRange(-20000, 20000);
        if (std::llabs(to[p] - pos[p]) + std::llabs(to[q] - pos[q]) < 20) to[p] = pos[p] + 20;
        said[p] = said[q] = true;
        const double chord = std::hypot(double(to[p] - pos[p]), double(to[q] - pos[q]));
        const long long r = static_cast<long long>(std::ceil(chord / 2)) + *rc::gen::inRange(1, 20000);
        arc_words += " R" + at(*rc::gen::arbitrary<bool>() ? r : -r);
      }
      if (*rc::gen::inRange(0, 3) == 0) to[n] = *rc::gen::inRange(-100000, 100000), said[n] = true;  // a helix
    }
    for (int k = 0; k < 6; ++k)
      if (said[k]) line += std::string(" ") + names[k] + at(g91 ? to[k] - pos[k] : to[k]);
    d.text += line + arc_words + "\n";
    pos = to;
  }
  d.text += "M2\n";
  return d;
}

/// kin5's moves: its canonical operations of move kinds, each with the end of its move (X Y Z in
/// the unit of the last `use_length_units`, the program's), its kind, and an arc's direction and
/// centre.
struct kin5_move {
  rs::move_kind kind = rs::move_kind::feed;
  std::array<double, 6> end{};
  bool clockwise = false;
  std::optional<std::array<double, 3>> centre;
};

/// The moves among the canonical operations of `text` as kin5's LinuxCNC reader runs it. A move
/// keeps the axes it does not name where they were. A motion word without axis words sets the
/// mode only (rs274 runs it as a move to where the tool stands; the drawn programs have none).
std::vector<kin5_move> kin5_moves(const std::string& text, std::string& errors) {
  read_result r;
  std::vector<kin5_move> moves;
  std::array<double, 6> at;
  at.fill(NAN);
  double unit_mm = 1.0;
  std::optional<rs::move_kind> mode;
  std::vector<can::operation> operations;
  linuxcnc::read_blocks(text, "t.ngc", r, [&](block&& b) {
    operations.clear();
    can::append_operations(b, operations);
    for (const can::operation& op : operations) {
      if (const auto* u = std::get_if<can::use_length_units>(&op))
        unit_mm = u->unit == can::length_unit::inch ? 25.4 : 1.0;
      kin5_move k;
      const axis_words* to = nullptr;
      if (const auto* rapid = std::get_if<can::rapid_move>(&op)) {
        k.kind = rs::move_kind::traverse, to = &rapid->to;
      } else if (const auto* linear = std::get_if<can::linear_move>(&op)) {
        k.kind = rs::move_kind::feed, to = &linear->to;
      } else if (const auto* arc = std::get_if<can::arc_move>(&op)) {
        k.kind = rs::move_kind::arc, to = &arc->to, k.clockwise = arc->clockwise;
        if (arc->circle && arc->circle->centre_mm) {
          const kin5::vec3& c = *arc->circle->centre_mm;
          k.centre = std::array<double, 3>{c.x / unit_mm, c.y / unit_mm, c.z / unit_mm};
        }
      } else if (const auto* modal = std::get_if<can::modal_move>(&op)) {
        if (!mode) {
          errors += "a move without a motion mode\n";
          continue;
        }
        k.kind = *mode, to = &modal->to;
      } else {
        continue;
      }
      mode = k.kind;
      if (to->empty()) continue;
      const std::optional<double> v[6] = {to->x_mm, to->y_mm, to->z_mm, to->a_deg, to->b_deg, to->c_deg};
      for (int i = 0; i < 6; ++i)
        if (v[i]) at[i] = *v[i] / (i < 3 ? unit_mm : 1.0);
      k.end = at;
      moves.push_back(k);
    }
  });
  for (const diagnostic& d : r.errors) errors += d.to_string() + "\n";
  return moves;
}

}  // namespace

TEST_CASE("LinuxCNC moves: kin5 reads the end points rs274 runs to, G90 and G91, arcs, inches") {
  rc::prop("each move ends where rs274's canonical move ends, to 1e-9", [] {
    const drawn d = draw_moves();
    const rs::run theirs = rs::run_program(d.text);
    std::string errors;
    const std::vector<kin5_move> ours = kin5_moves(d.text, errors);
    RC_LOG() << d.text << "\n--- rs274:\n" << theirs.text << "\n";
    RC_ASSERT(errors == "");
    RC_ASSERT(theirs.status == 0);
    RC_ASSERT(theirs.moves.size() == ours.size());
    for (std::size_t i = 0; i < ours.size(); ++i) {
      const rs::canonical_move& t = theirs.moves[i];
      RC_LOG() << "move " << i << ": " << t.call << "\n";
      RC_ASSERT(t.inches == d.inches);
      RC_ASSERT(t.kind == ours[i].kind);
      if (t.kind == rs::move_kind::arc) RC_ASSERT((t.rotation < 0) == ours[i].clockwise);
      for (int k = 0; k < 6; ++k) RC_ASSERT(std::abs(ours[i].end[k] - t.end[k]) <= 1e-9);
      if (ours[i].centre) {
        const auto o = rs::arc_order(t.arc_plane);
        for (int k : {o[0], o[1]}) RC_ASSERT(std::abs((*ours[i].centre)[k] - t.centre[k]) <= 1e-9);
      }
    }
  });
}

TEST_CASE("LinuxCNC moves: a subroutine in another file runs as rs274 runs it from its SUBROUTINE_PATH") {
  const auto dir = std::filesystem::temp_directory_path() / ("kin5-rs274-calls-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string ini = (dir / "subroutines.ini").string();
  std::ofstream(ini) << "[RS274NGC]\nSUBROUTINE_PATH = " << dir.string() << "\n";
  read_limits limits;
  limits.include_dirs = {dir.string()};
  rc::prop("the moves of a program whose middle lines are a called file's end where rs274's do", [&] {
    const drawn d = draw_moves();
    std::vector<std::string> lines;  // the drawn lines before M2
    for (std::size_t at = 0, next; (next = d.text.find('\n', at)) != std::string::npos; at = next + 1)
      lines.push_back(d.text.substr(at, next + 1 - at));
    lines.pop_back();
    const auto from = *rc::gen::inRange<std::size_t>(1, lines.size() + 1);
    const auto to = *rc::gen::inRange<std::size_t>(from, lines.size() + 1);
    std::string main, called = "o<part> sub\n";
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (i == from) main += "o<part> call\n";
      (i >= from && i < to ? called : main) += lines[i];
    }
    if (from == lines.size()) main += "o<part> call\n";
    main += "M2\n";
    std::ofstream(dir / "part.ngc") << called << "o<part> endsub\nM2\n";
    const rs::run theirs = rs::run_program(main, "-i " + ini);
    std::string errors;
    std::vector<kin5_move> ours;
    {
      const read_limits_scope scope(limits);
      ours = kin5_moves(main, errors);
    }
    RC_LOG() << main << "\n--- part.ngc:\n" << called << "\n--- rs274:\n" << theirs.text << "\n";
    RC_ASSERT(errors == "");
    RC_ASSERT(theirs.status == 0);
    RC_ASSERT(theirs.moves.size() == ours.size());
    for (std::size_t i = 0; i < ours.size(); ++i)
      for (int k = 0; k < 6; ++k) RC_ASSERT(std::abs(ours[i].end[k] - theirs.moves[i].end[k]) <= 1e-9);
  });
  std::filesystem::remove_all(dir);
}

TEST_CASE("rs274's canonical calls are read in the plane's order and the unit in effect") {
  const rs::run r = rs::run_program("G20 G90 G0 X1 Y2 Z3 A4 B5 C6\nG18 G91 G2 X1 Z1 I0.5 K0.5 F10\nG19 G90 G3 Y3 Z5 R2\nM2\n");
  REQUIRE(r.status == 0);
  REQUIRE(r.moves.size() == 3);
  CHECK(r.moves[0].kind == rs::move_kind::traverse);
  CHECK(r.moves[0].inches);
  CHECK(r.moves[0].end == std::array<double, 6>{1, 2, 3, 4, 5, 6});
  CHECK(r.moves[1].kind == rs::move_kind::arc);
  CHECK(r.moves[1].arc_plane == rs::plane::xz);
  CHECK(r.moves[1].rotation == -1);
  CHECK(r.moves[1].end == std::array<double, 6>{2, 2, 4, 4, 5, 6});
  CHECK(r.moves[1].centre[0] == 1.5);
  CHECK(r.moves[1].centre[2] == 3.5);
  CHECK(std::isnan(r.moves[1].centre[1]));
  CHECK(r.moves[2].arc_plane == rs::plane::yz);
  CHECK(r.moves[2].rotation == 1);
  CHECK(r.moves[2].end[1] == 3);
  CHECK(r.moves[2].end[2] == 5);
}
