// Laws of output in machine coordinates (G10), for every catalog machine: a TCP block written as
// the target's axis values ends where the source's tip and axis end, every piece ends on the
// source's straight path, the tip a controller moves between pieces (every axis interpolated
// linearly, taken from the Eigen chain of homogeneous transforms, not from kin5's forward) stays
// within --tolerance of that path, each block keeps its time, and the output read back as machine
// coordinates (G9) gives the source's tip path again.
#include <algorithm>
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
using test::to_segment;

/// The Eigen chain's tool pose for slides `x` and angles `rotary`.
template <machine M>
Eigen::Isometry3d chain(const vec3& x, const rotary_angles<M>& rotary, const run_inputs& in) {
  axis_position<M> q{};
  q.xyz_mm = x;
  q.rotary = rotary;
  return eigen::chain_work_T_tool<M>(q, in);
}
std::optional<double> rotary_deg_of(const program::axis_words& w, axis_letter letter) {
  return letter == axis_letter::A ? w.a_deg : letter == axis_letter::B ? w.b_deg : w.c_deg;
}

/// One written block in machine coordinates: its slides and angles, F and feed unit.
template <machine M>
struct joint_block {
  vec3 slides_mm{};
  rotary_angles<M> angles{};
  vec3 program_mm{};
  std::optional<double> feed;
  bool inverse_time = false;
};

template <machine M>
std::vector<joint_block<M>> joints_of(const translation& t, const run_inputs& in) {
  std::vector<joint_block<M>> out;
  bool inverse_time = false;
  for (const auto& b : t.output.blocks) {
    if (b.feed_mode) inverse_time = *b.feed_mode == program::feed_unit::inverse_time;
    if (!b.axes.has_linear()) continue;
    joint_block<M> j;
    j.program_mm = {*b.axes.x_mm, *b.axes.y_mm, *b.axes.z_mm};
    j.slides_mm = slides_for<M>(j.program_mm, in);
    for (std::size_t i = 0; i < rotary_count<M>; ++i) j.angles[i] = to_radians(degrees{*rotary_deg_of(b.axes, M::rotary[i].letter)});
    j.feed = b.feed;
    j.inverse_time = inverse_time;
    out.push_back(j);
  }
  return out;
}

/// A TCP program of M: tracking on, a rapid to (tip0, a0), a feed move to (tip1, a1).
template <machine M>
program::program tcp_program(const vec3& tip0, const rotary_angles<M>& a0, const vec3& tip1, const rotary_angles<M>& a1,
                             double feed_mm_per_min) {
  program::program nc;
  nc.language = *program::parse_dialect("iso");
  nc.file = "t.nc";
  program::block on;
  on.where = {"t.nc", 1, 1};
  on.tcp = true;
  nc.blocks.push_back(on);
  for (int k = 0; k < 2; ++k) {
    program::block b;
    b.where = {"t.nc", std::size_t(k + 2), 1};
    b.motion = k == 0 ? program::motion_kind::rapid : program::motion_kind::linear;
    const vec3& tip = k == 0 ? tip0 : tip1;
    b.axes.x_mm = tip.x, b.axes.y_mm = tip.y, b.axes.z_mm = tip.z;
    for (std::size_t i = 0; i < rotary_count<M>; ++i)
      translate_detail::rotary_word(b.axes, M::rotary[i].letter) = to_degrees((k == 0 ? a0 : a1)[i]).value;
    if (k == 1) b.feed = feed_mm_per_min;
    nc.blocks.push_back(b);
  }
  return nc;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("(G10) TCP blocks written in machine coordinates stay on the source's path", "[core][machine-output]",
                        kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("ends on the source's poses, pieces within --tolerance, time kept, read back as machine coordinates", [] {
    const auto q0 = *test::axis_values_within<M>();
    auto q1 = *test::axis_values_within<M>();
    if (*rc::gen::weightedOneOf<bool>({{1, rc::gen::just(true)}, {3, rc::gen::just(false)}})) q1.rotary = q0.rotary;
    run_inputs in = *test::run_inputs_any();
    in.work_offset.rotation = mat3::identity();  // a turned part would turn tool axes out of reach
    const double tolerance_mm = *rc::gen::element(0.005, 0.001, 0.05);
    const double feed_mm_per_min = *test::real_in(10, 20000);
    const bool inverse_time = *rc::gen::arbitrary<bool>();  // ISO has it; Heidenhain has not

    const vec3 tip0 = chain_tip<M>(q0.xyz_mm, q0.rotary, in), tip1 = chain_tip<M>(q1.xyz_mm, q1.rotary, in);
    const program::program nc = tcp_program<M>(tip0, q0.rotary, tip1, q1.rotary, feed_mm_per_min);
    translate_options options;
    options.setup = rigid_transform::identity();
    options.output_dialect = program::parse_dialect(inverse_time ? "iso" : "heidenhain");
    options.common.placement = in;
    options.common.coordinates = output_mode::machine;
    options.common.tolerance_mm = tolerance_mm;
    const translation t = translate(M::model, M::model, nc, options);
    // The tip on the path with the angles between two poses within travel may need a slide past its own.
    if (!t.ok() && t.errors.front().message.find("past its travel") != std::string::npos) RC_DISCARD("slides past travel");
    if (!t.ok()) RC_FAIL(t.errors.front().message);
    for (const auto& b : t.output.blocks) RC_ASSERT(!b.tcp.has_value());

    const auto w = joints_of<M>(t, in);
    RC_ASSERT(w.size() >= 2u);
    const std::size_t n = w.size() - 1;  // pieces of the feed move
    RC_ASSERT(t.blocks_added == n - 1);
    const auto tip = [&](std::size_t k) { return chain_tip<M>(w[k].slides_mm, w[k].angles, in); };
    RC_ASSERT(distance(tip(0), tip0) <= 1e-7);
    RC_ASSERT(distance(tip(n), tip1) <= 1e-7);
    const Eigen::Vector3d axis_end = chain<M>(w[n].slides_mm, w[n].angles, in).linear() * eigen::to_eigen(M::model.tool_reference());
    const Eigen::Vector3d axis_source = chain<M>(q1.xyz_mm, q1.rotary, in).linear() * eigen::to_eigen(M::model.tool_reference());
    // The plan may take an axis within the angle tolerance (0.0005°, per rounded angle) as on an edge.
    RC_ASSERT((axis_end - axis_source).norm() <= 2.0 * to_radians(degrees{0.0005}).value);
    for (std::size_t k = 0; k < n; ++k) {
      RC_ASSERT(to_segment(tip(k + 1), tip0, tip1) <= 1e-7);
      for (int j = 1; j < 40; ++j) {  // every axis interpolated linearly between two blocks
        const double s = j / 40.0;
        rotary_angles<M> a{};
        for (std::size_t i = 0; i < rotary_count<M>; ++i)
          a[i] = radians{w[k].angles[i].value + s * (w[k + 1].angles[i].value - w[k].angles[i].value)};
        const vec3 x = w[k].slides_mm + s * (w[k + 1].slides_mm - w[k].slides_mm);
        RC_ASSERT(to_segment(chain_tip<M>(x, a, in), tip0, tip1) <= tolerance_mm);
      }
    }

    // Time: the TCP source moves its tip at F, or over its (K16) degrees when the tip stands still.
    double source_length = distance(tip1, tip0);
    if (!(source_length > 0.0)) {
      double d2 = 0.0;
      for (std::size_t i = 0; i < rotary_count<M>; ++i) d2 += std::pow(to_degrees(q1.rotary[i] - q0.rotary[i]).value, 2);
      source_length = std::sqrt(d2);
    }
    const double source_time_min = source_length / feed_mm_per_min;
    double written_time_min = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      double l2 = squared_norm(w[k + 1].program_mm - w[k].program_mm);
      for (std::size_t i = 0; i < rotary_count<M>; ++i)
        l2 += std::pow(to_degrees(w[k + 1].angles[i] - w[k].angles[i]).value, 2);
      if (!(l2 > 0.0)) continue;
      RC_ASSERT(w[k + 1].feed.has_value());
      written_time_min += w[k + 1].inverse_time ? 1.0 / *w[k + 1].feed : std::sqrt(l2) / *w[k + 1].feed;
    }
    RC_ASSERT(std::abs(written_time_min - source_time_min) <= 1e-9 * source_time_min + 1e-15);
    if (inverse_time) return;

    // Read back as machine coordinates (G9) and written as TCP: the source's tips again.
    program::program back = t.output;
    translate_options read;
    read.setup = rigid_transform::identity();
    read.output_dialect = back.language;
    read.common.source_placement = in;
    read.common.tolerance_mm = tolerance_mm;
    const translation r = translate(M::model, M::model, back, read);
    if (!r.ok()) RC_FAIL(r.errors.front().message);
    std::vector<vec3> tips;
    for (const auto& b : r.output.blocks)
      if (b.axes.has_linear()) tips.push_back({*b.axes.x_mm, *b.axes.y_mm, *b.axes.z_mm});
    RC_ASSERT(tips.size() >= w.size());
    RC_ASSERT(distance(tips.front(), tip0) <= 1e-6);
    RC_ASSERT(distance(tips.back(), tip1) <= 1e-6);
    for (const vec3& p : tips) RC_ASSERT(to_segment(p, tip0, tip1) <= tolerance_mm);
  });
}
