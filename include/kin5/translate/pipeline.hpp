/// @file translate/pipeline.hpp
/// The two-pass pipeline every translation runs: a `block_translator` joins a source side
/// (`source_walk.hpp`) to a target side (`nc_target.hpp`, `cl_target.hpp`) and is fed the
/// program's blocks twice, in file order:
///
///     plan(b)   for every block — source errors, reach, branch planning (first pass)
///     write(b)  for every block — each output block to the sink as soon as it is made
///
/// Nothing is stored per block but the planner's candidates, so programs of any length run in
/// little memory (`stream.hpp` runs it over a file's text). `make_translator(from, to, …)`,
/// `make_reverse(m, …)` and `make_post(m, …)` make one for machine values (`machine_model`: a
/// catalog type's `M::model` or a machine file's), the same code for every machine and pair;
/// `make_translator<From, To>` etc. forward to them. `run` runs both passes over a program in memory.
/// @code
///   auto t = kin5::make_translator(From::model, To::model, nc.language, nc.file, options);
///   for (const auto& b : nc.blocks) t->plan(b);
///   for (const auto& b : nc.blocks) t->write(b, emit);  // emit: void(program::block&&)
///   if (!t->result().ok()) { /* the output must not be used */ }
/// @endcode
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "../program/address_words.hpp"
#include "../program/block.hpp"
#include "../program/dialect.hpp"
#include "angle_tolerance.hpp"
#include "cl_target.hpp"
#include "feed.hpp"
#include "nc_target.hpp"
#include "options.hpp"
#include "precision.hpp"
#include "setup.hpp"
#include "source_walk.hpp"

namespace kin5 {

/// A translation, reverse or post run in two passes over the blocks of one program, for
/// programs of any length: call `plan` with every block in file order, then `write` with the
/// same blocks in the same order. Each output block goes to the sink given to `write` as soon
/// as it is made; nothing is stored per block but the branch planner's candidates (tens of
/// bytes per motion block). Make one with `make_translator`, `make_reverse` or `make_post`.
///
/// The first pass finds the source's errors and the blocks the target cannot reach; the second
/// finds what can only be seen while writing (arcs the setup cannot map, feeds the dialect
/// cannot say). Either way, any error in `result()` means the output must not be used.
class block_translator {
 public:
  virtual ~block_translator() = default;
  /// First pass: the next block of the program.
  virtual void plan(const program::block& b) = 0;
  /// Second pass: the next block of the same program (after every `plan`); output to `emit`.
  virtual void write(const program::block& b, const program::block_sink& emit) = 0;
  /// Counts, reports, errors and warnings so far (`output` stays empty: blocks go to `emit`).
  translation& result() { return result_; }
  /// How finely the program writes its numbers, for the default angle tolerance
  /// (angle_tolerance.hpp); before the first `plan`. Not given: 0.0005°.
  void source_resolution(const program::number_resolution& r) { resolution_ = r; }
  /// What `stream_text` reads of a text (`common_options::limits`).
  const program::read_limits& limits() const { return limits_; }

 protected:
  translation result_;
  program::number_resolution resolution_;
  program::read_limits limits_;
};

/// Whether a `block_translator`'s second pass reads the source text of `b`: not for a block it
/// moves, whose text it replaces; so a `program::block_store` kept for that pass may drop it.
inline bool second_pass_reads_text(const program::block& b) {
  return !b.moves() || b.passthrough || b.machine_coordinates;
}

namespace translate_detail {

/// An error about the whole file (line 0).
inline program::diagnostic file_error(const std::string& file, std::string message) {
  return {program::source_location{file, 0, 0}, std::move(message)};
}

/// The tool lengths of the source (`source_placement`) and of the target (`placement`) in `c`.
inline tool_lengths source_lengths(const common_options& c) {
  const bool single = c.source_placement && c.source_placement_has_length;
  return {c.tools, single ? std::optional<double>(c.source_placement->tool_length_mm) : std::nullopt};
}
inline tool_lengths target_lengths(const common_options& c) {
  const bool single = c.placement && c.placement_has_length;
  return {c.tools, single ? std::optional<double>(c.placement->tool_length_mm) : std::nullopt};
}

/// `block_translator` for one source side and one target side.
template <class Source, class Target>
class two_pass_translator final : public block_translator {
 public:
  /// `refusal`: a reason not to run at all (an error for the whole file); blocks are then only
  /// counted. `source`: the program's dialect and the option naming its machine (the context's
  /// tolerance and `out` are set at the first `plan`); `common`: tolerance, allowed refusals, digits.
  two_pass_translator(Source source_side, Target target, const std::string& file, program::dialect output_language,
                      report_detail detail, std::optional<std::string> refusal = std::nullopt,
                      source_context source = {}, common_options common = {})
      : target_(std::move(target)),
        detail_(detail),
        refused_(refusal.has_value()),
        source_(source),
        common_(std::move(common)),
        first_(source_side),
        second_(std::move(source_side)) {
    result_.output.language = output_language;
    result_.output.file = file;
    limits_ = common_.limits;
    if (refusal) result_.errors.push_back(file_error(file, std::move(*refusal)));
  }

  void plan(const program::block& source_block) override {
    std::optional<program::block> numbered;  // the user's tool numbers for tool names, when they apply
    const program::block& b = numbered_tools(source_block, common_.tool_numbers, numbered);
    ++result_.blocks_read;
    if (refused_) return;
    if (result_.blocks_read == 1) configure();
    if (!precise_ && b.metric) inch_ = !*b.metric;
    if (!precise_ && b.moves()) configure_precision();  // the unit is fixed from the first move on
    // The source kinematics (tool axis, branch) run once per block: in the pass that uses them.
    const source_step s = first_.next(b, &result_, Target::plans_with_tool_axis);
    if (Target::plans_with_tool_axis && s.what == source_step::kind::motion) principal_.push_back(s.principal);
    target_.plan(s);
  }

  void write(const program::block& source_block, const program::block_sink& emit) override {
    if (refused_) return;
    std::optional<program::block> numbered;
    const program::block& b = numbered_tools(source_block, common_.tool_numbers, numbered);
    if (!precise_) configure_precision();
    if (!planned_) target_.finish_plan(), planned_ = true;
    source_step s = second_.next(b, nullptr, !Target::plans_with_tool_axis);
    if (Target::plans_with_tool_axis && s.what == source_step::kind::motion) s.principal = principal_[motion_++];
    std::optional<program::block> mapped;  // with the user's M and work-offset mappings, when they apply
    if (!common_.m_codes.empty() && program::says_m_function(b) && source_.language != source_.output) {
      mapped = b;
      map_m_codes(*mapped, common_.m_codes);
    }
    if (b.state.work_offset) {  // refused in the first pass when it cannot be written
      const auto t = work_offset_into(*b.state.work_offset, source_.language, source_.output, common_.work_offsets);
      if (t.written != b.state.work_offset) {
        if (!mapped) mapped = b;
        mapped->state.work_offset = t.written;
      }
    }
    target_.write(
        mapped ? *mapped : b, s, result_,
        [&](program::block&& o) {
          ++result_.blocks_written;
          emit(std::move(o));
        },
        [&](block_report&& r) {
          r.ordinal = result_.per_class[0] + result_.per_class[1] + result_.per_class[2];
          ++result_.per_class[static_cast<std::size_t>(r.match)];
          if (detail_ == report_detail::every_block || r.match != matchability::direct) {
            r.source_angles = angles_text(s);
            result_.reports.push_back(std::move(r));
          }
        });
  }

 private:
  Target target_;
  report_detail detail_;
  bool refused_;
  source_context source_;
  common_options common_;
  bool planned_ = false;
  bool precise_ = false;  // the output's decimals are chosen
  bool inch_ = false;     // the program's lengths are inches (the unit its blocks said before the first move)
  source_walker<Source> first_, second_;
  std::vector<bool> principal_;  // per motion block when the first pass classified it: on branch 0
  std::size_t motion_ = 0;       // motion blocks written so far

  /// The output's decimals, in the program's unit (precision.hpp): once its unit is known, at
  /// its first move (or before the second pass).
  void configure_precision() {
    precise_ = true;
    precision_notes notes;
    result_.output_decimals = output_decimals(resolution_, result_.output.language, common_.digits, &notes,
                                              program::capabilities_of(source_.language).cl_data, inch_);
    if (!notes.rounded.empty()) result_.warnings.push_back(file_error(result_.output.file, notes.rounded));
    if (!notes.refused.empty()) {
      program::diagnostic d = file_error(result_.output.file, notes.refused);
      d.construct = "precision", d.option = "--digits";
      result_.errors.push_back(std::move(d));
    }
  }

  /// The angle tolerance, from the options or the program's resolution, to both sides.
  void configure() {
    source_.tolerance = common_.angle_tolerance.value_or(default_angle_tolerance(resolution_));
    source_.output = result_.output.language;
    source_.linear_decimals = resolution_.linear_decimals;
    source_.m_codes = &common_.m_codes;
    source_.work_offsets = &common_.work_offsets;
    result_.angle_tolerance = source_.tolerance;
    first_.configure(source_, common_.allow);
    second_.configure(source_, common_.allow);
    target_.set_tool_axis_tolerance(tool_axis_tolerance(source_.tolerance, first_.source().rounded_values()));
    target_.set_placement(common_.placement, target_lengths(common_));
    if constexpr (requires { target_.set_output(common_.coordinates, common_.tolerance_mm); })
      target_.set_output(common_.coordinates, common_.tolerance_mm);
  }
};

/// Whether `d` is cutter-location data (tool tip and axis, no machine axes), not an NC dialect.
constexpr bool is_cl_data(program::dialect d) { return program::capabilities_of(d).cl_data; }

/// Why `translate` cannot run on a program in `source_language` written in `output_dialect`
/// with feed policy `feed`, if it cannot.
inline std::optional<std::string> translate_refusal(program::dialect source_language, feed_policy feed,
                                                    program::dialect output_dialect) {
  if (is_cl_data(source_language)) return "APT CL data names no machine axes: use post, not translate";
  if (is_cl_data(output_dialect)) return "translate writes NC; for APT CL data use reverse";
  return feed_refusal(feed, output_dialect);
}

/// Why motion cannot be written as `common` asks in `output_dialect`, if it cannot: machine
/// coordinates depend on where the part sits and on the tool length.
inline std::optional<std::string> output_mode_refusal(const common_options& common, program::dialect output_dialect) {
  if (common.coordinates.value_or(default_output_mode(output_dialect)) != output_mode::machine || common.placement)
    return std::nullopt;
  return "--output-mode machine writes the target's axis values, which depend on where the part sits and on the "
         "tool length: give --work-offset (and --tool-length)";
}

/// Both passes of `t` over a whole program; the output program collects the emitted blocks.
/// The program's resolution is scanned from its blocks' text.
inline translation run(block_translator& t, const program::program& in) {
  program::number_resolution resolution;
  for (const program::block& b : in.blocks) resolution.merge(program::scan_resolution(b.text, in.language));
  t.source_resolution(resolution);
  for (const program::block& b : in.blocks) t.plan(b);
  std::vector<program::block> output;
  const program::block_sink emit = [&](program::block&& o) { output.push_back(std::move(o)); };
  for (const program::block& b : in.blocks) t.write(b, emit);
  translation out = std::move(t.result());
  out.output.blocks = std::move(output);
  return out;
}

}  // namespace translate_detail

using program::dialect_names;

/// "a, b or c" from a list of names.
inline std::string one_of(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += std::string(i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(names[i]);
  return out;
}

/// `c` with the reference angles of `from`'s rotary axes (`home_deg`) for its reader
/// (`read_limits::rotary_home_deg`): the positions a home move leaves them at.
inline common_options with_source_homes(common_options c, const machine_model& from) {
  for (std::size_t i = 0; i < from.rotary_count; ++i) {
    const rotary_axis& a = from.rotary(i);
    const auto letter = static_cast<char>(a.letter);
    if (a.home_deg && letter >= 'A' && letter <= 'C')
      c.limits.rotary_home_deg[static_cast<std::size_t>(letter - 'A')] = a.home_deg->value;
  }
  return c;
}

/// The two passes of a translation from machine `from` to machine `to` (see
/// `block_translator`), for a program read in `source_language` from `file`. The setup is
/// `options.setup`, else `default_setup(from.geometry.id, to.geometry.id)`.
inline std::unique_ptr<block_translator> make_translator(const machine_model& from, const machine_model& to,
                                                         program::dialect source_language, const std::string& file,
                                                         const translate_options& options = {},
                                                         report_detail detail = report_detail::every_block) {
  using namespace translate_detail;
  const program::dialect out = output_dialect_of(options, to.geometry.id);
  return std::make_unique<two_pass_translator<nc_source, nc_target>>(
      nc_source{from, options.common.source_placement, options.common.tolerance_mm, source_lengths(options.common)},
      nc_target(to, options.setup.value_or(default_setup(from.geometry.id, to.geometry.id)), options.feed,
                source_language, out, false),
      file, out, detail,
      translate_refusal(source_language, options.feed, out) ? translate_refusal(source_language, options.feed, out)
                                                            : output_mode_refusal(options.common, out),
      source_context{source_language, {}, nullptr, "--from"}, with_source_homes(options.common, from));
}

/// The two passes of `reverse` for a program of machine `m` (see `block_translator`).
inline std::unique_ptr<block_translator> make_reverse(const machine_model& m, program::dialect source_language,
                                                      const std::string& file,
                                                      report_detail detail = report_detail::every_block,
                                                      const common_options& common = {}) {
  using namespace translate_detail;
  return std::make_unique<two_pass_translator<nc_source, cl_target>>(
      nc_source{m, common.source_placement, common.tolerance_mm, source_lengths(common)}, cl_target(source_language), file, program::cl_data_dialect(), detail,
      translate_detail::is_cl_data(source_language)
          ? std::optional<std::string>("the input is already APT CL data")
      : common.coordinates == output_mode::machine
          ? std::optional<std::string>("reverse writes APT CL data, the tool tip and axis: it has no machine "
                                       "coordinates (--output-mode machine is for translate and post)")
          : std::nullopt,
      source_context{source_language, {}, nullptr, "--machine"}, with_source_homes(common, m));
}

/// The two passes of `post` for machine `m` (see `block_translator`).
inline std::unique_ptr<block_translator> make_post(const machine_model& m, program::dialect source_language,
                                                   program::dialect output_dialect, const std::string& file,
                                                   report_detail detail = report_detail::every_block,
                                                   const common_options& common = {}) {
  using namespace translate_detail;
  return std::make_unique<two_pass_translator<cl_source, nc_target>>(
      cl_source{}, nc_target(m, rigid_transform::identity(), feed_policy::tcp, source_language, output_dialect, true),
      file, output_dialect, detail,
      translate_detail::is_cl_data(output_dialect)
          ? std::optional<std::string>("post writes NC: choose " +
                                       one_of(dialect_names([](const program::capabilities& can) { return !can.cl_data; })))
          : output_mode_refusal(common, output_dialect),
      source_context{source_language, {}, nullptr, "--machine"}, common);
}

/// `make_translator(From::model, To::model, …)`.
template <machine From, machine To>
std::unique_ptr<block_translator> make_translator(program::dialect source_language, const std::string& file,
                                                  const translate_options& options = {},
                                                  report_detail detail = report_detail::every_block) {
  return make_translator(From::model, To::model, source_language, file, options, detail);
}

/// `make_reverse(M::model, …)`.
template <machine M>
std::unique_ptr<block_translator> make_reverse(program::dialect source_language, const std::string& file,
                                               report_detail detail = report_detail::every_block,
                                               const common_options& common = {}) {
  return make_reverse(M::model, source_language, file, detail, common);
}

/// `make_post(M::model, …)`.
template <machine M>
std::unique_ptr<block_translator> make_post(program::dialect source_language, program::dialect output_dialect,
                                            const std::string& file,
                                            report_detail detail = report_detail::every_block,
                                            const common_options& common = {}) {
  return make_post(M::model, source_language, output_dialect, file, detail, common);
}

}  // namespace kin5
