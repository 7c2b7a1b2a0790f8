// Laws of motion without tool-tip tracking read as machine coordinates (G9), for every catalog
// machine: the tool-tip path a translation writes as TCP stays within --tolerance of the path the
// source machine cuts when it interpolates its axes linearly (taken from the Eigen chain of
// homogeneous transforms, not from kin5's forward); a block whose rotary axes stand still is
// written as one block; and every block keeps its time, (K15) over the (K16) machine-axis length.
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
using test::to_segment;

/// The source machine at parameter s of a block from slides x0, angles a0 to x1, a1: every axis
/// interpolated linearly, as the controller does.
template <machine M>
vec3 source_tip(const axis_position<M>& q0, const axis_position<M>& q1, double s, const run_inputs& in) {
  rotary_angles<M> a{};
  for (std::size_t i = 0; i < rotary_count<M>; ++i)
    a[i] = radians{q0.rotary[i].value + s * (q1.rotary[i].value - q0.rotary[i].value)};
  return chain_tip<M>(q0.xyz_mm + s * (q1.xyz_mm - q0.xyz_mm), a, in);
}

/// One block of the program: the untracked program point of slides `q` (the chain's tip with
/// every rotary axis at zero) and q's angles in degrees.
template <machine M>
program::block block_at(const axis_position<M>& q, const run_inputs& in, bool rapid, double feed_mm_per_min,
                        std::size_t line) {
  program::block b;
  b.where = {"u.nc", line, 1};
  b.motion = rapid ? program::motion_kind::rapid : program::motion_kind::linear;
  const vec3 p = chain_tip<M>(q.xyz_mm, rotary_angles<M>{}, in);
  b.axes.x_mm = p.x, b.axes.y_mm = p.y, b.axes.z_mm = p.z;
  for (std::size_t i = 0; i < rotary_count<M>; ++i)
    translate_detail::rotary_word(b.axes, M::rotary[i].letter) = to_degrees(q.rotary[i]).value;
  if (!rapid) b.feed = feed_mm_per_min;
  return b;
}

/// The angle written for rotary axis `letter`, degrees.
std::optional<double> rotary_deg_of(const program::axis_words& w, axis_letter letter) {
  return letter == axis_letter::A ? w.a_deg : letter == axis_letter::B ? w.b_deg : w.c_deg;
}

/// The written tips (mm) and F of every motion block of `t`'s output.
struct written {
  std::vector<vec3> tip_mm;
  std::vector<std::optional<double>> feed;
  std::vector<bool> inverse_time;  ///< the block's F is 1 / its time
  std::vector<std::array<double, 2>> rotary_deg;
};
template <machine M>
written motions_of(const translation& t) {
  written w;
  bool inverse_time = false;
  for (const auto& b : t.output.blocks) {
    if (b.feed_mode) inverse_time = *b.feed_mode == program::feed_unit::inverse_time;
    if (b.axes.has_linear()) {
      w.tip_mm.push_back({*b.axes.x_mm, *b.axes.y_mm, *b.axes.z_mm});
      w.feed.push_back(b.feed);
      w.inverse_time.push_back(inverse_time);
      std::array<double, 2> r{};
      for (std::size_t i = 0; i < rotary_count<M>; ++i)
        r[i] = rotary_deg_of(b.axes, M::rotary[i].letter).value_or(0.0);  // none in CL data
      w.rotary_deg.push_back(r);
    }
  }
  return w;
}

/// (K15): the source controller reads F over the (K16) length of its axis values: the time (min)
/// of the second block of `nc`, from q0 to q1.
template <machine M>
double source_time(const program::program& nc, const axis_position<M>& q0, const axis_position<M>& q1,
                   double feed_mm_per_min) {
  const vec3 p0{*nc.blocks[0].axes.x_mm, *nc.blocks[0].axes.y_mm, *nc.blocks[0].axes.z_mm};
  const vec3 p1{*nc.blocks[1].axes.x_mm, *nc.blocks[1].axes.y_mm, *nc.blocks[1].axes.z_mm};
  double l2 = squared_norm(p1 - p0);
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    const double d = to_degrees(q1.rotary[i]).value - to_degrees(q0.rotary[i]).value;
    l2 += d * d;
  }
  return std::sqrt(l2) / feed_mm_per_min;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("(G9) untracked blocks written as TCP follow the source's interpolated tip", "[core][untracked]",
                        kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("within --tolerance of every piece's chord; one block when the rotary axes stand still; time kept", [] {
    const auto q0 = *test::axis_values_within<M>();
    auto q1 = *test::axis_values_within<M>();
    const bool still = *rc::gen::weightedOneOf<bool>({{1, rc::gen::just(true)}, {2, rc::gen::just(false)}});
    if (still) q1.rotary = q0.rotary;
    // The target is the same machine with the same frame: a work offset that turns the part
    // would turn tool axes out of its reach, so the part is only shifted here.
    run_inputs in = *test::run_inputs_any();
    in.work_offset.rotation = mat3::identity();
    const double tolerance_mm = *rc::gen::element(0.005, 0.001, 0.05);
    const double feed_mm_per_min = *test::real_in(10, 20000);
    const bool inverse_time = *rc::gen::arbitrary<bool>();  // the source block in G93, F = 1 / its time

    program::program nc;
    nc.language = *program::parse_dialect("iso");
    nc.file = "u.nc";
    nc.blocks = {block_at<M>(q0, in, true, 0.0, 1), block_at<M>(q1, in, false, feed_mm_per_min, 2)};
    const double source_time_min = source_time<M>(nc, q0, q1, feed_mm_per_min);
    if (inverse_time) {
      if (!(source_time_min > 0.0)) RC_DISCARD("a block of no length has no inverse time");
      nc.blocks[1].feed_mode = program::feed_unit::inverse_time, nc.blocks[1].feed = 1.0 / source_time_min;
    }
    translate_options options;
    options.output_dialect = program::parse_dialect("iso");
    options.setup = rigid_transform::identity();
    options.common.source_placement = in;
    options.common.tolerance_mm = tolerance_mm;
    const translation t = translate(M::model, M::model, nc, options);
    if (!t.ok()) RC_FAIL(t.errors.front().message);

    const written w = motions_of<M>(t);
    RC_ASSERT(w.tip_mm.size() >= 2u);
    const std::size_t n = w.tip_mm.size() - 1;  // pieces of the second block
    RC_ASSERT(t.blocks_added == n - 1);
    if (still) RC_ASSERT(n == 1u);
    RC_ASSERT(distance(w.tip_mm.front(), source_tip<M>(q0, q1, 0.0, in)) <= 1e-7);
    RC_ASSERT(distance(w.tip_mm.back(), source_tip<M>(q0, q1, 1.0, in)) <= 1e-7);
    for (std::size_t k = 0; k < n; ++k) {
      RC_ASSERT(distance(w.tip_mm[k + 1], source_tip<M>(q0, q1, double(k + 1) / double(n), in)) <= 1e-7);
      for (int j = 1; j < 40; ++j) {
        const double s = (double(k) + j / 40.0) / double(n);
        RC_ASSERT(to_segment(source_tip<M>(q0, q1, s, in), w.tip_mm[k], w.tip_mm[k + 1]) <= tolerance_mm);
      }
    }

    double written_time_min = 0.0;
    std::optional<double> f;
    for (std::size_t k = 0; k < n; ++k) {
      if (w.feed[k + 1]) f = w.feed[k + 1];
      if (w.inverse_time[k + 1]) {
        RC_ASSERT(w.feed[k + 1].has_value());
        written_time_min += 1.0 / *w.feed[k + 1];
        continue;
      }
      double length = distance(w.tip_mm[k + 1], w.tip_mm[k]);
      if (!(length > 1e-9)) {  // the tip stands still: timed over the rotary degrees (K16)
        double d2 = 0.0;
        for (std::size_t i = 0; i < rotary_count<M>; ++i) d2 += std::pow(w.rotary_deg[k + 1][i] - w.rotary_deg[k][i], 2);
        length = std::sqrt(d2);
      }
      if (length > 0.0) {
        RC_ASSERT(f.has_value());
        written_time_min += length / *f;
      }
    }
    RC_ASSERT(std::abs(written_time_min - source_time_min) <= 1e-9 * source_time_min + 1e-15);
  });
}

TEMPLATE_LIST_TEST_CASE("(G9) reverse writes an untracked rotary feed move as CL pieces that keep its time",
                        "[core][untracked]", kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("GOTO pieces on the source's interpolated tip, FEDRAT/INVERS adding up to the block's time", [] {
    const auto q0 = *test::axis_values_within<M>();
    const auto q1 = *test::axis_values_within<M>();
    RC_PRE(q0.rotary != q1.rotary);
    run_inputs in = *test::run_inputs_any();
    in.work_offset.rotation = mat3::identity();
    const double feed_mm_per_min = *test::real_in(10, 20000);
    program::program nc;
    nc.language = *program::parse_dialect("iso");
    nc.file = "u.nc";
    nc.blocks = {block_at<M>(q0, in, true, 0.0, 1), block_at<M>(q1, in, false, feed_mm_per_min, 2)};
    const double source_time_min = source_time<M>(nc, q0, q1, feed_mm_per_min);
    if (*rc::gen::arbitrary<bool>())
      nc.blocks[1].feed_mode = program::feed_unit::inverse_time, nc.blocks[1].feed = 1.0 / source_time_min;
    common_options common;
    common.source_placement = in;
    const translation t = translate_detail::run(*make_reverse(M::model, nc.language, nc.file, report_detail::every_block, common), nc);
    if (!t.ok()) RC_FAIL(t.errors.front().message);
    const written w = motions_of<M>(t);
    const std::size_t n = w.tip_mm.size() - 1;
    RC_ASSERT(n >= 1u);
    double written_time_min = 0.0;
    for (std::size_t k = 1; k <= n; ++k) {
      RC_ASSERT(distance(w.tip_mm[k], source_tip<M>(q0, q1, double(k) / double(n), in)) <= 1e-7);
      RC_ASSERT(w.inverse_time[k]);
      RC_ASSERT(w.feed[k].has_value());
      written_time_min += 1.0 / *w.feed[k];
    }
    RC_ASSERT(std::abs(written_time_min - source_time_min) <= 1e-9 * source_time_min);
  });
}
