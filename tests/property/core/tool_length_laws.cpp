// Laws of per-tool lengths, for every catalog machine: a program without tool-tip tracking that
// changes tools is read as machine coordinates (G9) with each tool's own length from the tool
// table, and written in machine coordinates (G10) with each tool's own length again. The tips are
// taken from the Eigen chain of homogeneous transforms, not from kin5's forward.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/eigen.hpp>
#include <kin5/kin5.hpp>
#include <kin5/machines/every_machine.hpp>

#include "chain_oracle.hpp"
#include "generators.hpp"
#include "segment_distance.hpp"

namespace {

using namespace kin5;

using test::distance;
using test::chain_tip;
using test::slides_for;

std::optional<double>& rotary_word(program::axis_words& w, axis_letter letter) {
  return letter == axis_letter::A ? w.a_deg : letter == axis_letter::B ? w.b_deg : w.c_deg;
}

/// `T n M6` on a line of its own.
program::block tool_change(long long n, std::size_t line) {
  program::block b;
  b.where = {"t.nc", line, 1};
  b.tool = n;
  b.state.tool_change = true;
  return b;
}

/// A rapid to the untracked program point of slides `q` (the chain's tip with every rotary
/// axis at zero, with the tool length of `in`) and q's angles in degrees.
template <machine M>
program::block rapid_to(const axis_position<M>& q, const run_inputs& in, std::size_t line) {
  program::block b;
  b.where = {"t.nc", line, 1};
  b.motion = program::motion_kind::rapid;
  const vec3 p = chain_tip<M>(q.xyz_mm, rotary_angles<M>{}, in);
  b.axes.x_mm = p.x, b.axes.y_mm = p.y, b.axes.z_mm = p.z;
  for (std::size_t i = 0; i < rotary_count<M>; ++i) rotary_word(b.axes, M::rotary[i].letter) = to_degrees(q.rotary[i]).value;
  return b;
}

/// Two tools of different lengths, a section in machine coordinates with each, its placement
/// with each tool's length, and the tool table.
template <machine M>
struct two_tools {
  axis_position<M> q1, q2;
  run_inputs in1, in2;
  tool_table tools;
  program::program nc;
};

template <machine M>
rc::Gen<two_tools<M>> two_tool_programs() {
  return rc::gen::exec([] {
    two_tools<M> t;
    t.q1 = *test::axis_values_within<M>();
    t.q2 = *test::axis_values_within<M>();
    t.in1 = *test::run_inputs_any();
    t.in1.work_offset.rotation = mat3::identity();  // the same frame as the target's: no turned tool axes
    t.in2 = t.in1;
    t.in1.tool_length_mm = *test::real_in(0, 300);
    t.in2.tool_length_mm = t.in1.tool_length_mm + *test::real_in(1, 200);
    const long long first = *rc::gen::inRange(1, 100), second = first + *rc::gen::inRange(1, 100);
    t.tools.entries[first] = {t.in1.tool_length_mm, std::nullopt};
    t.tools.entries[second] = {t.in2.tool_length_mm, 4.0};
    t.nc.language = *program::parse_dialect("iso");
    t.nc.file = "t.nc";
    t.nc.blocks = {tool_change(first, 1), rapid_to<M>(t.q1, t.in1, 2), tool_change(second, 3), rapid_to<M>(t.q2, t.in2, 4)};
    return t;
  });
}

/// Options that read the source in machine coordinates with the tool table and no single length.
translate_options with_table(const run_inputs& placement, const tool_table& tools) {
  translate_options options;
  options.output_dialect = program::parse_dialect("iso");
  options.setup = rigid_transform::identity();
  options.common.source_placement = placement;
  options.common.source_placement_has_length = false;
  options.common.tools = tools;
  return options;
}

/// The motion blocks of an output.
std::vector<program::block> motions(const translation& t) {
  std::vector<program::block> out;
  for (const auto& b : t.output.blocks)
    if (b.axes.has_linear()) out.push_back(b);
  return out;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("(G9) a program that changes tools is read with each tool's own length", "[core][tools]",
                        kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("each section's TCP tips are the chain's with that section's tool length", [] {
    const two_tools<M> t = *two_tool_programs<M>();
    const translation out = translate(M::model, M::model, t.nc, with_table(t.in1, t.tools));
    if (!out.ok()) RC_FAIL(out.errors.front().to_string());
    const auto m = motions(out);
    RC_ASSERT(m.size() == 2u);
    RC_ASSERT(distance(vec3{*m[0].axes.x_mm, *m[0].axes.y_mm, *m[0].axes.z_mm}, chain_tip<M>(t.q1.xyz_mm, t.q1.rotary, t.in1)) <= 1e-7);
    RC_ASSERT(distance(vec3{*m[1].axes.x_mm, *m[1].axes.y_mm, *m[1].axes.z_mm}, chain_tip<M>(t.q2.xyz_mm, t.q2.rotary, t.in2)) <= 1e-7);
  });
}

TEMPLATE_LIST_TEST_CASE("(G10) machine-coordinate output uses each tool's own length", "[core][tools]",
                        kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("each written block's slides and angles put that tool's tip where the source's was", [] {
    const two_tools<M> t = *two_tool_programs<M>();
    translate_options options = with_table(t.in1, t.tools);
    options.common.coordinates = output_mode::machine;
    options.common.placement = t.in1;
    options.common.placement_has_length = false;
    const translation out = translate(M::model, M::model, t.nc, options);
    if (!out.ok() && out.errors.front().message.find("past its travel") != std::string::npos) RC_DISCARD("slides past travel");
    if (!out.ok()) RC_FAIL(out.errors.front().to_string());
    const auto m = motions(out);
    RC_ASSERT(m.size() == 2u);
    const std::array<const run_inputs*, 2> in{&t.in1, &t.in2};
    const std::array<const axis_position<M>*, 2> q{&t.q1, &t.q2};
    for (std::size_t k = 0; k < 2; ++k) {
      rotary_angles<M> angles{};
      program::axis_words w = m[k].axes;
      for (std::size_t i = 0; i < rotary_count<M>; ++i) angles[i] = to_radians(degrees{*rotary_word(w, M::rotary[i].letter)});
      const vec3 slides = slides_for<M>({*w.x_mm, *w.y_mm, *w.z_mm}, *in[k]);
      RC_ASSERT(distance(chain_tip<M>(slides, angles, *in[k]), chain_tip<M>(q[k]->xyz_mm, q[k]->rotary, *in[k])) <= 1e-6);
    }
  });
}

TEST_CASE("a tool with no known length is refused at its first motion, naming the option", "[core][tools]") {
  using M = kin5::machines::ac_head;  // head axes: the tool length moves the tip
  axis_position<M> q{};
  q.xyz_mm = {10, 20, 30};
  run_inputs in;
  in.tool_length_mm = 100.0;
  tool_table tools;
  tools.entries[1] = {100.0, std::nullopt};
  program::program nc;
  nc.language = *program::parse_dialect("iso");
  nc.file = "t.nc";
  nc.blocks = {tool_change(1, 1), rapid_to<M>(q, in, 2), tool_change(2, 3), rapid_to<M>(q, in, 4)};
  const translation out = translate(M::model, M::model, nc, with_table(in, tools));
  REQUIRE(out.errors.size() == 1u);
  CHECK(out.errors[0].where.line == 4u);
  CHECK(out.errors[0].message.find("tool 2 has no entry in the tool table") != std::string::npos);
  CHECK(out.errors[0].message.find("--tool-table") != std::string::npos);
  // With one length given and no table, the second tool is refused as a guess.
  translate_options single = with_table(in, tools);
  single.common.tools.reset();
  single.common.source_placement_has_length = true;
  const translation guessed = translate(M::model, M::model, nc, single);
  REQUIRE(guessed.errors.size() == 1u);
  CHECK(guessed.errors[0].where.line == 4u);
  CHECK(guessed.errors[0].message.find("--source-tool-length gives one tool's, tool 1's") != std::string::npos);
}
