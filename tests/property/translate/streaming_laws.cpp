// The streaming form agrees with the whole-program one: the two-pass `block_translator` (second
// pass over a `block_store`) with a block-by-block writer against `translate` + `write`.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kin5.hpp>
#include <kin5/program/block_store.hpp>
#include <kin5/program/io.hpp>

#include "generators.hpp"
#include "program_builder.hpp"

using namespace kin5;

TEST_CASE("two passes block by block write what translate + write produce, and count every class") {
  using From = machines::sajo_12000p;
  using To = machines::dmu_80p;
  rc::prop("SAJO programs with A over its whole travel, on the DMU 80P in every NC dialect", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 30);
    auto p = test::tcp_program(program::dialect::siemens, "random.mpf");
    for (std::size_t k = 0; k < n; ++k) {
      const int kind = *rc::gen::inRange(0, 4);
      if (kind == 0) {
        auto& b = test::add_block(p);
        b.comment = "c" + std::to_string(k);
        b.m_codes = {8};
        continue;
      }
      const double a = *test::uniform(-120.0, 10.0);
      RC_PRE(std::abs(a) > 1e-6);
      test::add_motion(p, {*test::uniform(-100, 100), *test::uniform(-100, 100), 50.0, a, *test::uniform(-180, 180),
                           std::nullopt, 700.0},
                       kind == 1 ? program::motion_kind::rapid : program::motion_kind::linear);
    }
    auto options = test::options();
    options.output_dialect = *rc::gen::element(program::dialect::siemens, program::dialect::heidenhain,
                                                program::dialect::iso);
    const translation whole = translate<From, To>(p, options);

    // As the tool runs it: pass 2 over compact records without the text of moved blocks.
    const auto t = make_translator<From, To>(p.language, p.file, options, report_detail::exceptions_only);
    program::block_store records(p.file);
    for (const auto& b : p.blocks) {
      t->plan(b);
      records.push(b, second_pass_reads_text(b));
    }
    std::string text;
    program::block_writer writer(options.output_dialect, p.language, p.file);
    const program::block_sink emit = [&](program::block&& o) { writer.write(text, o); };
    records.replay([&](const program::block& b) { t->write(b, emit); });
    const translation& streamed = t->result();

    RC_ASSERT(streamed.blocks_read == whole.blocks_read);
    RC_ASSERT(streamed.blocks_written == whole.blocks_written);
    RC_ASSERT(streamed.errors.size() == whole.errors.size());
    for (std::size_t i = 0; i < whole.errors.size(); ++i)
      RC_ASSERT(streamed.errors[i].to_string() == whole.errors[i].to_string());
    RC_ASSERT(streamed.per_class == whole.per_class);
    std::array<std::size_t, 3> counted{};
    std::vector<std::size_t> exception_lines;
    for (const auto& r : whole.reports) {
      ++counted[static_cast<std::size_t>(r.match)];
      if (r.match != matchability::direct) exception_lines.push_back(r.where.line);
    }
    RC_ASSERT(counted == whole.per_class);
    RC_ASSERT(streamed.reports.size() == exception_lines.size());
    for (std::size_t i = 0; i < exception_lines.size(); ++i) RC_ASSERT(streamed.reports[i].where.line == exception_lines[i]);
    if (whole.ok()) RC_ASSERT(text == program::write(options.output_dialect, whole.output));
  });
}
