// Machine files: every bundled machine's file (machines/<id>.toml) reads back to exactly the
// compile-time geometry and gives bit-identical forward, inverse and pose-inverse results over
// 10,000 draws per machine; any valid geometry survives write → read unchanged; and every broken
// rule is reported at its file, line and column.
#include <array>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <tuple>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kin5.hpp>
#include <kin5/machines/every_machine.hpp>
#include <kin5/machines/machine_file.hpp>
#include <kin5/machines/machine_file_writer.hpp>
#include <kin5/machines/tool_table_file.hpp>
#include <kin5/machines/toml_bounds.hpp>

#include "generators.hpp"

namespace {

using namespace kin5;

constexpr int draws_per_case = 100;  // × RapidCheck's 100 cases = 10,000 draws per machine

bool same_travel(const rotary_travel& a, const rotary_travel& b) {
  return a.continuous == b.continuous && (a.continuous || (a.lower.value == b.lower.value && a.upper.value == b.upper.value));
}

/// Every field of two geometries, compared exactly.
bool same_geometry(const machine_geometry& a, const machine_geometry& b) {
  bool same = a.id == b.id && a.structure == b.structure && a.tool.reference == b.tool.reference &&
              a.tool.pivot_length_mm == b.tool.pivot_length_mm;
  for (std::size_t i = 0; i < 3; ++i) {
    const linear_axis &x = a.linear[i], &y = b.linear[i];
    same = same && x.letter == y.letter && x.side == y.side && x.direction == y.direction &&
           x.travel.lower_mm == y.travel.lower_mm && x.travel.upper_mm == y.travel.upper_mm;
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const rotary_axis &x = a.rotary[i], &y = b.rotary[i];
    same = same && x.letter == y.letter;
    if (x.letter == axis_letter::none) continue;
    same = same && x.side == y.side && x.direction == y.direction && x.sense == y.sense &&
           same_travel(x.travel, y.travel) && x.point_mm == y.point_mm;
  }
  return same;
}

std::string file_of(std::string_view id) { return std::string(KIN5_SOURCE_DIR) + "/machines/" + std::string(id) + ".toml"; }

template <machine M>
axis_values as_values(const axis_position<M>& q) {
  axis_values v{q.xyz_mm, {}};
  for (std::size_t i = 0; i < rotary_count<M>; ++i) v.rotary[i] = q.rotary[i];
  return v;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("the bundled machine file is the compile-time machine", "[core][machine-file]",
                        kin5::machines::every_machine) {
  using M = TestType;
  const machine_file_result r = read_machine_file(file_of(M::id));
  for (const auto& e : r.errors) INFO(e.to_string());
  REQUIRE(r.ok());
  const machine_model& m = r.machine->model();
  CHECK(same_geometry(m.geometry, M::model.geometry));
  CHECK(m.rotary_count == M::model.rotary_count);

  rc::prop("forward, inverse and the pose inverse are bit-identical (10,000 draws)", [&] {
    for (int k = 0; k < draws_per_case; ++k) {
      const auto q = *rc::gen::oneOf(test::axis_values_within<M>(), test::axis_values_anywhere<M>());
      const run_inputs in = *test::run_inputs_any();
      const tool_pose a = forward<M>(q, in), b = forward(m, as_values<M>(q), in);
      RC_ASSERT(a.tip_mm == b.tip_mm);
      RC_ASSERT(a.axis == b.axis);
      const auto ra = inverse<M>(a.axis);
      const auto rb = inverse(m, a.axis);
      RC_ASSERT(ra.size() == rb.size());
      RC_ASSERT(ra.status == rb.status);
      RC_ASSERT(ra.gap.value == rb.gap.value);
      for (std::size_t s = 0; s < ra.size(); ++s) {
        RC_ASSERT(ra[s].within_travel == rb[s].within_travel);
        for (std::size_t i = 0; i < rotary_count<M>; ++i) RC_ASSERT(ra[s].angles[i] == rb[s].angles[i]);
      }
      const auto pa = inverse<M>(a, in);
      const auto pb = inverse(m, a, in);
      RC_ASSERT(pa.size() == pb.size());
      RC_ASSERT(pa.linear_excess_mm == pb.linear_excess_mm);
      for (std::size_t s = 0; s < pa.size(); ++s) {
        RC_ASSERT(pa[s].joints.xyz_mm == pb[s].joints.xyz_mm);
        RC_ASSERT(pa[s].within_travel == pb[s].within_travel);
      }
    }
  });
}

TEMPLATE_LIST_TEST_CASE("the bundled machine file is what the writer writes", "[core][machine-file]",
                        kin5::machines::every_machine) {
  using M = TestType;
  std::ifstream in(file_of(M::id));
  REQUIRE(in);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text == to_machine_file(M::model.geometry));
}

namespace {

/// A valid random geometry: random unit directions (linear axes a sheared frame), points,
/// travels and senses; redrawn until it passes every rule.
rc::Gen<machine_geometry> any_geometry() {
  return rc::gen::suchThat(
      rc::gen::exec([] {
        machine_geometry g{};
        g.id = "random";
        g.structure = "drawn \"by\" the law \\ suite";
        g.tool = {*test::unit_vector(), *test::real_in(0, 500)};
        constexpr std::array<axis_letter, 3> xyz{axis_letter::X, axis_letter::Y, axis_letter::Z};
        for (std::size_t i = 0; i < 3; ++i) {
          const double lo = *test::real_in(-2000, 0), width = *test::real_in(0, 3000);
          g.linear[i] = {xyz[i], *rc::gen::arbitrary<bool>() ? mount::head : mount::table, *test::unit_vector(),
                         linear_travel::between(lo, lo + width)};
        }
        const std::size_t n = *rc::gen::inRange<std::size_t>(1, 3);
        constexpr std::array<axis_letter, 3> abc{axis_letter::A, axis_letter::B, axis_letter::C};
        const std::size_t first = *rc::gen::inRange<std::size_t>(0, 3);
        for (std::size_t i = 0; i < n; ++i) {
          rotary_axis& a = g.rotary[i];
          a.letter = abc[(first + i) % 3];
          a.side = *rc::gen::arbitrary<bool>() ? mount::head : mount::table;
          a.direction = *test::unit_vector();
          a.point_mm = {*test::real_in(-500, 500), *test::real_in(-500, 500), *test::real_in(-500, 500)};
          a.sense = *rc::gen::arbitrary<bool>() ? angle_sense::physical : angle_sense::tool_relative;
          const double lo = *test::real_in(-540, 0), width = *test::real_in(0, 1080);
          a.travel = *rc::gen::arbitrary<bool>() ? rotary_travel::endless()
                                                 : rotary_travel::between(degrees{lo}, degrees{lo + width});
        }
        return g;
      }),
      [](const machine_geometry& g) { return machine_rules::check(g).ok(); });
}

}  // namespace

TEST_CASE("write → read keeps any valid geometry bit for bit", "[core][machine-file]") {
  rc::prop("random geometries", [] {
    const machine_geometry g = *any_geometry();
    const machine_file_result r = parse_machine_file(to_machine_file(g), "random.toml");
    RC_ASSERT(r.errors.empty());
    RC_ASSERT(same_geometry(r.machine->model().geometry, g));
  });
}

namespace {

/// A correct file to break: a B/C trunnion.
constexpr std::string_view good = R"(kin5_machine = 1
id = "test"
structure = "B table about +Y carrying C"

[tool]
reference = [0, 0, 1]
pivot_length_mm = 0

[linear.X]
direction = [1, 0, 0]
side = "table"
travel_mm = [-300, 300]

[linear.Y]
direction = [0, 1, 0]
side = "table"
travel_mm = [-300, 300]

[linear.Z]
direction = [0, 0, 1]
side = "head"
travel_mm = [-400, 0]

[[rotary]]
letter = "C"
side = "table"
direction = [0, 0, 1]
point_mm = [0, 0, -150]
sense = "tool-relative"
continuous = true

[[rotary]]
letter = "B"
side = "table"
direction = [0, 1, 0]
point_mm = [0, 0, -150]
sense = "tool-relative"
travel_deg = [-120, 120]
)";

/// `good` with the first occurrence of `from` (after `after`) replaced by `to`.
std::string broken(std::string_view from, std::string_view to, std::string_view after = "") {
  std::string s(good);
  const std::size_t start = after.empty() ? 0 : s.find(after);
  const std::size_t at = s.find(from, start);
  REQUIRE(start != std::string::npos);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

struct error_case {
  std::string text;
  unsigned line, column;
  std::string_view says;
};

}  // namespace

TEST_CASE("machine file errors name file, line, column and the rule", "[core][machine-file]") {
  {
    const auto r = parse_machine_file(good, "good.toml");
    for (const auto& e : r.errors) INFO(e.to_string());
    REQUIRE(r.ok());
    CHECK(r.machine->model().rotary_count == 2);
  }
  const error_case cases[] = {
      {broken("pivot_length_mm = 0", "pivot_length_mm = "), 7, 19, "TOML syntax"},
      {broken("structure =", "struture ="), 3, 1, "unknown key 'struture' in the top level"},
      {broken("side = \"table\"\ntravel_mm", "sides = \"table\"\ntravel_mm"), 11, 1, "unknown key 'sides' in [linear.X]"},
      {broken("side = \"table\"\ntravel_mm", "side = \"tabel\"\ntravel_mm"), 11, 8, "must be \"table\" or \"head\""},
      {broken("reference = [0, 0, 1]", "reference = [0, 0, 2]"), 6, 13, "must be unit vectors"},
      {broken("direction = [0, 1, 0]\nside = \"table\"\ntravel", "direction = [0.6, 0.8, 0.1]\nside = \"table\"\ntravel"),
       15, 13, "[linear.Y] direction is not a unit vector"},
      {broken("travel_mm = [-400, 0]", "travel_mm = [0, -400]"), 22, 13, "lower <= upper"},
      {broken("travel_deg = [-120, 120]", "travel_deg = [120, -120]"), 38, 14, "lower <= upper"},
      {broken("travel_deg = [-120, 120]", "travel_deg = [-720, 720]"), 38, 14, "at most 1080 degrees"},
      {broken("direction = [0, 1, 0]\npoint", "direction = [0, 0, 1]\npoint"), 35, 13, "degenerate machine (S1)"},
      {broken("direction = [0, 0, 1]\nside = \"head\"", "direction = [0, 1, 0]\nside = \"head\""), 20, 13,
       "must not lie in one plane"},
      {broken("letter = \"B\"", "letter = \"C\""), 33, 10, "each letter at most once"},
      {broken("letter = \"B\"", "letter = \"U\""), 33, 10, "named A, B or C"},
      {broken("point_mm = [0, 0, -150]", "point_mm = [0, 0]"), 28, 12, "array of 3 numbers"},
      {broken("point_mm = [0, 0, -150]", "point_mm = [0, 0, nan]"), 28, 19, "must be finite"},
      {broken("pivot_length_mm = 0", "pivot_length_mm = -5"), 7, 19, "pivot length not negative"},
      {broken("sense = \"tool-relative\"\ncontinuous", "sense = \"iso\"\ncontinuous"), 29, 9, "\"tool-relative\" or \"physical\""},
      {broken("continuous = true", "continuous = true\ntravel_deg = [0, 10]"), 31, 14, "exclude each other"},
      {broken("continuous = true\n", ""), 24, 1, "missing key 'travel_deg'"},
      {broken("kin5_machine = 1", "kin5_machine = 2"), 1, 16, "schema version"},
      {broken("letter = \"C\"\n", ""), 24, 1, "missing key 'letter' in [[rotary]] #1"},
      {broken("[linear.Z]", "[linear.W]"), 19, 9, "unknown key 'W'"},
      {broken("travel_deg = [-120, 120]\n", "travel_deg = [-120, 120]\n\n[[rotary]]\nletter = \"A\"\n"), 24, 1,
       "one or two rotary axes"},
      {broken("travel_mm = [-400, 0]", "travel_mm = [-400, 0]\nhome_mm = 10"), 23, 11, "[linear.Z] home_mm: the home lies outside travel_mm"},
      {broken("travel_mm = [-400, 0]", "travel_mm = [-400, 0]\nhome_mm = \"top\""), 23, 11, "home_mm must be a number"},
      {broken("travel_deg = [-120, 120]", "travel_deg = [-120, 120]\nhome_deg = 130"), 39, 12, "home_deg: the home lies outside travel_deg"},
  };
  for (const error_case& c : cases) {
    const auto r = parse_machine_file(c.text, "m.toml");
    INFO(c.text);
    REQUIRE_FALSE(r.ok());
    REQUIRE_FALSE(r.errors.empty());
    const machine_file_error& e = r.errors.front();
    INFO(e.to_string());
    CHECK(e.file == "m.toml");
    CHECK(e.line == c.line);
    CHECK(e.column == c.column);
    CHECK(e.message.find(c.says) != std::string::npos);
    CHECK(e.to_string().rfind("m.toml:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": error: ", 0) == 0);
  }
}

namespace {

/// `n` parts joined by dots: "a.a.a".
std::string dotted(std::size_t n) {
  std::string key = "a";
  for (std::size_t i = 1; i < n; ++i) key += ".a";
  return key;
}

/// A document nested `n` levels deep as `toml_bounds_violation` counts them, in one of four
/// forms: a dotted key, a table name, inline tables, arrays.
std::string nested(int form, std::size_t n) {
  switch (form) {
    case 0: return "kin5_machine = 1\n" + dotted(n) + " = 1\n";
    case 1: return "kin5_machine = 1\n[" + dotted(n) + "]\n";
    case 2: {  // x = {a = {a = 1}}: the key x, then a key in each of n - 1 inline tables
      std::string s = "x = ";
      for (std::size_t i = 1; i < n; ++i) s += "{a = ";
      return s + "1" + std::string(n - 1, '}') + "\n";
    }
    default:  // x = [[[1]]]: n arrays, the outermost the key x's value
      return "x = " + std::string(n, '[') + "1" + std::string(n, ']') + "\n";
  }
}

}  // namespace

TEST_CASE("machine files and tool tables nest at most 32 deep and keep keys short, before toml++ parses them",
          "[core][machine-file]") {
  // A 40,000-part dotted key or table name overflowed the stack inside toml++ (SIGSEGV).
  for (int form = 0; form < 4; ++form)
    for (std::size_t n : {std::size_t{1}, std::size_t{3}, std::size_t{32}, std::size_t{33}, std::size_t{40000}}) {
      const std::string text = nested(form, n);
      INFO("form " << form << ", depth " << n);
      const auto v = toml_bounds_violation(text);
      CHECK(v.has_value() == (n > toml_bounds::max_nesting));
      const machine_file_result m = parse_machine_file(text, "m.toml");
      const tool_table_result t = parse_tool_table_file(text, "t.toml");
      REQUIRE_FALSE(m.errors.empty());
      REQUIRE_FALSE(t.errors.empty());
      if (n > toml_bounds::max_nesting) {
        CHECK(m.errors.front().message.find("nested more than 32 levels") != std::string::npos);
        CHECK(t.errors.front().message.find("nested more than 32 levels") != std::string::npos);
        CHECK(m.errors.front().line == (form < 2 ? 2u : 1u));  // at the key, table name or bracket
      }
    }
  // Keys: 256 bytes pass, 257 do not; at the key's line and column.
  CHECK_FALSE(toml_bounds_violation("x = 1\n" + std::string(256, 'k') + " = 1\n"));
  const auto long_key = toml_bounds_violation("x = 1\n  " + std::string(257, 'k') + " = 1\n");
  REQUIRE(long_key);
  CHECK(long_key->line == 2);
  CHECK(long_key->column == 3);
  CHECK(long_key->message.find("longer than 256 bytes") != std::string::npos);
  CHECK(toml_bounds_violation("[\"" + std::string(300, 'k') + "\"]\n"));
  // Brackets, dots and '=' inside strings and comments count for nothing.
  CHECK_FALSE(toml_bounds_violation("s = \"" + std::string(100, '[') + dotted(100) + "\" # " + std::string(100, '{') +
                                    "\nt = '''\n" + std::string(100, '[') + "\n'''\nu = \"\"\"a\\\"\"\"\"\n"));
  // Non-ASCII outside strings and comments, or first after a backslash in a string: toml++ 3.3
  // reached TOML_UNREACHABLE on them (undefined behaviour; found by machine_file_fuzz).
  for (const auto& [text, line, column] : {std::tuple{std::string("_\xcf\xa9"), 1u, 2u},
                                           std::tuple{std::string("\xcc\xaa"), 1u, 1u},
                                           std::tuple{std::string("1=-c1'\xcc\x87'"), 1u, 7u},
                                           std::tuple{std::string("A=9['\xc7\x9c/"), 1u, 6u},
                                           std::tuple{std::string("7=7=\".\xef\xbb\xbb"), 1u, 7u},
                                           std::tuple{std::string("\"\"\"\\\xef\xbb\xa2\x10"), 1u, 5u},
                                           std::tuple{std::string("s = \"\"\"\\\n\xc2\xa7\"\"\"\n"), 2u, 1u}}) {
    const auto v = toml_bounds_violation(text);
    REQUIRE(v);
    CHECK(v->line == line);
    CHECK(v->column == column);
    CHECK(v->message.find("non-ASCII") != std::string::npos);
    CHECK(parse_machine_file(text, "m.toml").errors.front().message.find("non-ASCII") != std::string::npos);
  }
  CHECK_FALSE(toml_bounds_violation("s = \"\xc2\xa7\" # \xcf\xa9\nt = '\xcf\xa9'\n"));
  // Size: 4 MiB of text, and no more.
  CHECK(toml_bounds_violation(std::string(toml_bounds::max_file_bytes + 1, '\n')));
  CHECK_FALSE(toml_bounds_violation(std::string(toml_bounds::max_file_bytes, '\n')));
  // Every bundled machine file is within the bounds (they are read in the cases above).
  CHECK_FALSE(toml_bounds_violation(good));
}

TEST_CASE("machine file homes: read when given, absent otherwise, and written back", "[core][machine-file]") {
  const auto none = parse_machine_file(good, "good.toml");
  REQUIRE(none.ok());
  for (const auto& a : none.machine->model().geometry.linear) CHECK_FALSE(a.home_mm);
  CHECK_FALSE(none.machine->model().rotary(1).home_deg);
  std::string text(good);
  text.replace(text.find("travel_mm = [-400, 0]"), 21, "travel_mm = [-400, 0]\nhome_mm = -12.5");
  text.replace(text.find("travel_deg = [-120, 120]"), 24, "travel_deg = [-120, 120]\nhome_deg = -90");
  const auto homes = parse_machine_file(text, "homes.toml");
  REQUIRE(homes.ok());
  const machine_geometry& g = homes.machine->model().geometry;
  CHECK(g.linear[2].home_mm == -12.5);
  CHECK_FALSE(g.linear[0].home_mm);
  CHECK(g.rotary[1].home_deg->value == -90.0);
  const auto again = parse_machine_file(to_machine_file(g), "again.toml");
  REQUIRE(again.ok());
  CHECK(again.machine->model().geometry.linear[2].home_mm == -12.5);
  CHECK(again.machine->model().geometry.rotary[1].home_deg->value == -90.0);
  CHECK_FALSE(again.machine->model().geometry.rotary[0].home_deg);
}
