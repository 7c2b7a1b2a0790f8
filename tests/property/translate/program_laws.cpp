// Program-level laws: every block accounted for, unreachable blocks all listed with their gap,
// arcs mapped exactly and back, non-motion content kept in order.
#include <set>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kin5.hpp>

#include "generators.hpp"
#include "program_builder.hpp"

namespace {

using namespace kin5;
using machines::dmu_80p;
using machines::sajo_12000p;

/// The 24 proper rotations that permute the axes with signs: the setups under which every
/// principal plane maps to a principal plane.
std::vector<mat3> signed_permutations() {
  std::vector<mat3> out;
  const vec3 e[3] = {unit_x, unit_y, unit_z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        if (i == j || j == k || i == k) continue;
        for (int s = 0; s < 8; ++s) {
          const mat3 m = mat3::from_columns((s & 1 ? -1.0 : 1.0) * e[i], (s & 2 ? -1.0 : 1.0) * e[j],
                                            (s & 4 ? -1.0 : 1.0) * e[k]);
          if (determinant(m) > 0) out.push_back(m);
        }
      }
  return out;
}

/// How far past the DMU 80P's reach a SAJO tool axis may lie and count as on the edge, in
/// degrees: the tool-axis tolerance of a run over two rounded rotary angles at the default
/// angle tolerance (an in-memory program gives no resolution).
const double edge_slack_deg = to_degrees(tool_axis_tolerance(widest_default_angle_tolerance, 2)).value;

}  // namespace

TEST_CASE("every block is accounted for, and unreachable blocks are all listed with their gap") {
  rc::prop("SAJO programs with A over its whole travel on the DMU 80P", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 30);
    auto p = test::tcp_program(program::id_of<program::siemens::dialect>(), "random.mpf");
    std::set<std::size_t> unreachable_lines;
    std::vector<double> a_values, b_values;
    for (std::size_t k = 0; k < n; ++k) {
      const int kind = *rc::gen::inRange(0, 4);
      if (kind == 0) {  // a non-motion block: comment, M function or spindle speed
        auto& b = test::add_block(p);
        b.comment = "c" + std::to_string(k);
        b.m_codes = {8};
        continue;
      }
      // The DMU 80P reaches A <= 0 (the reach boundary S3 at A = 0). A value past it by no more
      // than the run's tool-axis tolerance is on the edge and reached (angle_tolerance.hpp); one
      // draw in eight lands near that band. Draws within 1e-6 of 0 or of the band's end, where
      // rounding decides, move past the band.
      double a = *rc::gen::inRange(0, 8) == 0 ? *test::uniform(-2 * edge_slack_deg, 2 * edge_slack_deg)
                                              : *test::uniform(-120.0, 30.0);
      if (std::abs(a) < 1e-6 || std::abs(a - edge_slack_deg) < 1e-6) a = 2 * edge_slack_deg;
      // B anywhere, each move the least way round: a move of 180° or more is a sweep, which the
      // DMU 80P may be unable to follow (round_trip_laws.cpp).
      const double b = b_values.empty() ? *test::uniform(-180.0, 180.0)
                                        : b_values.back() + *test::uniform(-179.0, 179.0);
      b_values.push_back(b);
      auto& m = test::add_motion(p, {*test::uniform(-100, 100), 0.0, 50.0, a, b, std::nullopt, 700.0},
                                 kind == 1 ? program::motion_kind::rapid : program::motion_kind::linear);
      if (a > edge_slack_deg) unreachable_lines.insert(m.where.line);
      a_values.push_back(a);
    }
    const auto t = translate<sajo_12000p, dmu_80p>(p, test::options());
    RC_ASSERT(t.angle_tolerance.value == widest_default_angle_tolerance.value);  // no resolution: the default
    RC_ASSERT(t.blocks_read == p.blocks.size());
    RC_ASSERT(t.ok() == unreachable_lines.empty());
    RC_ASSERT(t.blocks_written + unreachable_lines.size() == t.blocks_read);
    RC_ASSERT(t.reports.size() == a_values.size());
    std::set<std::size_t> error_lines;
    for (const auto& e : t.errors) error_lines.insert(e.where.line);
    RC_ASSERT(error_lines == unreachable_lines);
    for (std::size_t i = 0; i < t.reports.size(); ++i) {
      const auto& r = t.reports[i];
      RC_ASSERT((r.match == matchability::unreachable) == (a_values[i] > edge_slack_deg));
      if (a_values[i] > edge_slack_deg) RC_ASSERT(std::abs(to_degrees(r.gap).value - a_values[i]) <= 1e-9);  // P14
    }
    // Non-motion blocks are kept, in order, among the written ones.
    std::vector<std::string> in_comments, out_comments;
    for (const auto& b : p.blocks)
      if (b.comment) in_comments.push_back(*b.comment);
    for (const auto& b : t.output.blocks)
      if (b.comment) out_comments.push_back(*b.comment);
    RC_ASSERT(in_comments == out_comments);
  });
}

TEST_CASE("arcs map exactly under every axis-permuting setup and come back unchanged") {
  const auto setups = signed_permutations();
  REQUIRE(setups.size() == 24);
  rc::prop("arc on the SAJO -> SAJO under a signed permutation -> back", [&setups] {
    const mat3 R = setups[*rc::gen::inRange<std::size_t>(0, setups.size())];
    const rigid_transform d_T_s{R, *test::tip()};
    const auto plane = *rc::gen::element(program::arc_plane::xy, program::arc_plane::zx, program::arc_plane::yz);
    const auto direction = *rc::gen::element(program::motion_kind::arc_cw, program::motion_kind::arc_ccw);
    const vec3 start = *test::tip(), centre = *test::tip();
    const vec3 end = *test::tip();
    // Reachable tool axis after the setup: draw it on the target, map it back.
    const auto target = *test::angles_within<sajo_12000p>(1.0);
    const vec3 u_s = R.transposed() * tool_axis<sajo_12000p>(target);
    const auto source = inverse<sajo_12000p>(u_s).first_within_travel();
    RC_PRE(source.has_value());
    auto p = test::tcp_program(program::id_of<program::siemens::dialect>(), "arc.mpf");
    auto& first = test::add_motion(p, {start.x, start.y, start.z, std::nullopt, std::nullopt, std::nullopt, 300.0});
    test::set_rotary_words<sajo_12000p>(first.axes, *source);
    auto& arc = test::add_motion(p, {end.x, end.y, end.z, std::nullopt, std::nullopt, std::nullopt, std::nullopt},
                                 direction);
    arc.arc = program::arc_words{plane, centre, std::nullopt};
    const auto there = translate<sajo_12000p, sajo_12000p>(p, test::options(feed_policy::tcp, program::id_of<program::iso::dialect>(), d_T_s));
    RC_ASSERT(there.ok());
    const auto& mapped = there.output.blocks.back();
    // The plane's normal maps onto the target plane's normal, the direction flips with its sign.
    const vec3 n_s = plane == program::arc_plane::xy ? unit_z : plane == program::arc_plane::zx ? unit_y : unit_x;
    const vec3 n_d = R * n_s;
    const vec3 target_normal = mapped.arc->plane == program::arc_plane::xy ? unit_z
                               : mapped.arc->plane == program::arc_plane::zx ? unit_y
                                                                             : unit_x;
    RC_ASSERT(std::abs(std::abs(dot(n_d, target_normal)) - 1.0) <= 1e-12);
    RC_ASSERT((mapped.motion == direction) == (dot(n_d, target_normal) > 0));
    const auto back = translate<sajo_12000p, sajo_12000p>(
        there.output, test::options(feed_policy::tcp, program::id_of<program::siemens::dialect>(), d_T_s.inverse()));
    RC_ASSERT(back.ok());
    const auto& again = back.output.blocks.back();
    RC_ASSERT(again.motion == direction);
    RC_ASSERT(again.arc->plane == plane);
    // Centre: the in-plane part comes back; its normal part is the start's (a planar arc).
    vec3 expected_centre = centre;
    if (plane == program::arc_plane::xy) expected_centre.z = start.z;
    if (plane == program::arc_plane::zx) expected_centre.y = start.y;
    if (plane == program::arc_plane::yz) expected_centre.x = start.x;
    RC_ASSERT(norm(*again.arc->centre_mm - expected_centre) <= 1e-9);
    const vec3 e{again.axes.x_mm.value_or(start.x), again.axes.y_mm.value_or(start.y), again.axes.z_mm.value_or(start.z)};
    RC_ASSERT(norm(e - end) <= 1e-9);
  });
}

// The paper's SAJO ↔ DMU 80P setup is proper; a reflection and a stretch are not.
static_assert(is_proper_rotation(sajo_12000p_dmu_80p_setup.rotation));
static_assert(!is_proper_rotation(mat3{{vec3{-1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}}));
static_assert(!is_proper_rotation(mat3{{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1.000001}}}));

TEST_CASE("a setup rotation is accepted when proper, refused when stretched or reflected") {
  rc::prop("rotation(axis, angle) is proper; 1e-6 more on one entry, or −R, is not", [] {
    const vec3 axis{*test::uniform(-1, 1), *test::uniform(-1, 1), *test::uniform(-1, 1)};
    RC_PRE(norm(axis) > 0.1);
    const mat3 r = rotation(normalized(axis), radians{*test::uniform(-pi, pi)});
    RC_ASSERT(is_proper_rotation(r));
    RC_ASSERT(rotation_defect(r) <= 1e-14);
    const auto row = *rc::gen::inRange<std::size_t>(0, 3);
    const auto column = *rc::gen::inRange<std::size_t>(0, 3);
    mat3 bent = r;
    (column == 0 ? bent.row[row].x : column == 1 ? bent.row[row].y : bent.row[row].z) += 1e-6;
    RC_ASSERT(!is_proper_rotation(bent));
    mat3 reflected = r;
    for (auto& v : reflected.row) v = -1.0 * v;
    RC_ASSERT(!is_proper_rotation(reflected));
  });
}

// The feed policy table is the one list the library and the tool read: every name in it parses
// back to its own policy, and any other name is refused (empty), never mapped to a default.
static_assert([] {
  for (const auto& entry : kin5::feed_policies)
    if (kin5::parse_feed_policy(entry.name) != entry.policy || kin5::name(entry.policy) != entry.name) return false;
  return true;
}());
static_assert(!kin5::parse_feed_policy("") && !kin5::parse_feed_policy("fast") && !kin5::parse_feed_policy("TCP") &&
              !kin5::parse_feed_policy("block_time") && !kin5::parse_feed_policy("tcp "));

TEST_CASE("post: an understood APT statement is said in the NC dialect or not at all (never as its text)") {
  // Every statement here is read into the model; only the $$ and PPRINT text is a comment.
  const std::string cl =
      "PARTNO/TEST\nUNITS/MM\nMULTAX/ON\nLOADTL/3\nSELECT/TOOL,4\nSPINDL/RPM,8000,CLW\nCOOLNT/FLOOD\n"
      "FEDRAT/MMPM,500\nRAPID\nGOTO/10,0,5,0,0,1\nPPRINT/CHECK\nGOTO/0,10,5,0,0,1\n$$ note\nFINI\n";
  const program::dialect apt = program::id_of<program::apt::dialect>();
  for (const std::string_view name : {"iso", "siemens", "heidenhain", "linuxcnc", "haas"}) {
    CAPTURE(name);
    const program::dialect d = *program::parse_dialect(name);
    const auto t = make_post<machines::ac_trunnion>(apt, d, "t.cls");
    string_sink out;
    const auto run = stream_text(*t, cl, apt, "t.cls", d, out);  // as the tool runs it
    const std::string& text = out.text;
    CAPTURE(text);
    REQUIRE(run.ok(*t));
    CHECK(run.input.warnings.empty());
    CHECK(t->result().warnings.empty());
    CHECK(t->result().passed_through == 0);
    for (const char* statement : {"UNITS", "MULTAX", "LOADTL", "SELECT", "SPINDL", "COOLNT", "FEDRAT", "RAPID", "GOTO"})
      CHECK(text.find(statement) == std::string::npos);
    CHECK(text.find("CHECK") != std::string::npos);
    CHECK(text.find("note") != std::string::npos);
    // the selection: T4 alone after the change to T3 (ISO, Siemens, LinuxCNC), TOOL DEF 4 (Heidenhain)
    CHECK(text.find(name == "heidenhain" ? " TOOL DEF 4\n" : "\nT4\n") != std::string::npos);
    // no line without content (a bare block number or an empty line)
    CHECK(text.find("\n\n") == std::string::npos);
    for (std::size_t k = 0; k < 20; ++k) {  // appended, not `"\n" + …`: GCC 12 warns falsely (-Wrestrict)
      std::string bare(1, '\n');
      bare += std::to_string(k);
      bare += '\n';
      CHECK(text.find(bare) == std::string::npos);
    }
  }
}

TEST_CASE("translate: a tape mark and a parameter's number are understood, not passed through with a warning") {
  // One source per dialect that has them: framing text and a constant parameter used by a word.
  struct row {
    std::string_view dialect, text;
    std::size_t assignments;  // blocks that assign a parameter: still copied as text
  };
  const std::vector<row> rows = {
      {"iso", "%\nO1234\n#1=500.\nG90 G17 G21 G94\nT1 M6\nG43.4 H1\nG1 X10. Y0. Z5. B0. C0. F#1\nG49\nM30\n%\n", 1},
      {"linuxcnc", "%\n#1=500.\nG90 G17 G21 G94\nT1 M6\nG43 H1\nM428\nG1 X10 Y0 Z5 B0 C0 F#1\nM429\nM2\n%\n", 1},
      {"haas", "%\nO01234\n#1=500.\nG90 G17 G21 G94\nT1 M6\nG234 H1\nG1 X10. Y0. Z5. B0. C0. F#1\nG49\nM30\n%\n", 1},
      {"siemens", "%_N_P_MPF\n;$PATH=/_N_MPF_DIR\nR1=500\nT1 M6\nD1\nTRAORI\nG1 X10 Y0 Z5 B0 C0 F=R1\nTRAFOOF\nM30\n", 1},
      {"heidenhain", "0 BEGIN PGM P MM\n1 Q1 = 500\n2 TOOL CALL 1 Z S1000\n3 M128\n4 L X+10 Y+0 Z+5 B+0 C+0 FQ1\n"
                     "5 M129\n6 END PGM P MM\n", 1},
  };
  for (const row& r : rows) {
    const program::dialect from = *program::parse_dialect(r.dialect);
    for (const std::string_view to_name : {"iso", "siemens", "heidenhain", "linuxcnc", "haas"}) {
      CAPTURE(r.dialect, to_name);
      const program::dialect to = *program::parse_dialect(to_name);
      translate_options options;
      options.output_dialect = to;
      const auto t = make_translator<machines::dmu_50v, machines::dmu_50v>(from, "t", options);
      string_sink out;
      const auto run = stream_text(*t, std::string(r.text), from, "t", to, out);
      CAPTURE(out.text);
      REQUIRE(run.ok(*t));
      for (const auto& w : t->result().warnings) CHECK(w.message.find("not understood") == std::string::npos);
      CHECK(t->result().passed_through == r.assignments);
    }
  }
}
