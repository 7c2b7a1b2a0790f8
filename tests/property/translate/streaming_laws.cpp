// The streaming form agrees with the whole-program one: the streaming driver (`stream_blocks`:
// the two-pass `block_translator`, second pass over a `block_store`, a block-by-block writer)
// against `translate` + `write`.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kin5.hpp>
#include <kin5/program/io.hpp>
#include <kin5/translate/stream.hpp>

#include "generators.hpp"
#include "program_builder.hpp"

using namespace kin5;

TEST_CASE("two passes block by block write what translate + write produce, and count every class") {
  using From = machines::sajo_12000p;
  using To = machines::dmu_80p;
  rc::prop("SAJO programs with A over its whole travel, on the DMU 80P in every NC dialect", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 30);
    const program::dialect output = *rc::gen::element(program::id_of<program::siemens::dialect>(), program::id_of<program::heidenhain::dialect>(),
                                                      program::id_of<program::iso::dialect>());
    // ISO's G43.4 takes the loaded tool's H: a tool change comes first there.
    const bool iso = output == program::id_of<program::iso::dialect>();
    auto p = test::tcp_program(program::id_of<program::siemens::dialect>(), "random.mpf", iso ? std::optional<long long>(1) : std::nullopt);
    for (std::size_t k = 0; k < n; ++k) {
      const int kind = *rc::gen::inRange(0, 4);
      if (kind == 0) {
        auto& b = test::add_block(p);
        b.comment = "c" + std::to_string(k);
        b.state.coolant_flood = true;
        continue;
      }
      const double a = *test::uniform(-120.0, 10.0);
      RC_PRE(std::abs(a) > 1e-6);
      test::add_motion(p, {*test::uniform(-100, 100), *test::uniform(-100, 100), 50.0, a, *test::uniform(-180, 180),
                           std::nullopt, 700.0},
                       kind == 1 ? program::motion_kind::rapid : program::motion_kind::linear);
    }
    auto options = test::options();
    options.output_dialect = output;
    const translation whole = translate<From, To>(p, options);

    // As the tool runs it (stream.hpp): pass 2 over compact records without the text of moved
    // blocks, each output block written as it is made.
    const auto t = make_translator<From, To>(p.language, p.file, options, report_detail::exceptions_only);
    string_sink out;
    const block_source read = [&](program::read_result&, const program::block_sink& on_block) {
      for (program::block b : p.blocks) on_block(std::move(b));
    };
    const auto run = stream_blocks(*t, read, p.file, p.language, *options.output_dialect, out);
    const translation& streamed = t->result();
    RC_ASSERT(run.input.ok());
    RC_ASSERT(run.ok(*t) == whole.ok());

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
    if (whole.ok()) {  // the translated blocks, written as blocks read in the source's dialect
      program::block_writer writer(*options.output_dialect, p.language, p.file,
                                   write_settings_for(*options.output_dialect, whole.output_decimals));
      std::string expected;
      for (const program::block& b : whole.output.blocks) writer.write(expected, b);
      writer.finish(expected);
      RC_ASSERT(out.text == expected);
    }
  });
}

namespace {

/// A Siemens program for the SAJO 12000P: TRAORI, `lines` G1 blocks along a slow tilt, M30;
/// `bad_line`: the number of a G1 line written with a malformed number instead (0: none).
std::string siemens_program(std::size_t lines, std::size_t bad_line = 0) {
  std::string text = "N10 TRAORI\n";
  for (std::size_t k = 1; k <= lines; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(lines);
    auto number = [](double v) { return translate_detail::fixed(v, 4); };  // what the TNC output reads
    text += "N" + std::to_string(10 * (k + 1)) + " G1 X" + number(100.0 * t) + " Y" + number(-50.0 * t) + " Z50 A" +
            number(-20.0 - 40.0 * t) + " B" + number(-30.0 + 60.0 * t) + (k == bad_line ? " F7..0\n" : " F700\n");
  }
  return text + "N" + std::to_string(10 * (lines + 2)) + " M30\n";
}

/// A `text_sink` as a file is one: the buffer is written out (to `written`) once it holds
/// 1 MiB, and every flush after the `fail_at`-th fails.
struct chunked_sink {
  std::string pending, written;
  std::size_t calls = 0, flushes = 0, fail_at = static_cast<std::size_t>(-1);
  std::string& buffer() { return pending; }
  bool flush_if_full() {
    ++calls;
    if (pending.size() < (std::size_t{1} << 20)) return true;
    if (++flushes > fail_at) return false;
    written += pending;
    pending.clear();
    return true;
  }
};

}  // namespace

TEST_CASE("the streaming driver over text: the whole output, or nothing after an error") {
  using From = machines::sajo_12000p;
  using To = machines::dmu_80p;
  const auto options = test::options();
  const std::string text = siemens_program(30000);  // about 1.6 MB of Heidenhain output
  const auto read = program::read(program::id_of<program::siemens::dialect>(), text, "long.mpf");
  REQUIRE(read.ok());
  const translation whole = translate<From, To>(read.parsed, options);
  REQUIRE(whole.ok());
  // Written as blocks read in Siemens, as the driver writes them (a Siemens M30 is an M30 before
  // the closing END PGM, not END PGM itself).
  program::block_writer writer(*options.output_dialect, program::id_of<program::siemens::dialect>(), "long.mpf",
                               write_settings_for(*options.output_dialect, whole.output_decimals));
  std::string expected;
  for (const program::block& b : whole.output.blocks) writer.write(expected, b);
  writer.finish(expected);
  REQUIRE(expected.size() > (std::size_t{1} << 20));

  SECTION("a clean run gives the sink every byte, in order, across flushes") {
    const auto t = make_translator<From, To>(program::id_of<program::siemens::dialect>(), "long.mpf", options);
    chunked_sink out;
    const auto run = stream_text(*t, text, program::id_of<program::siemens::dialect>(), "long.mpf", *options.output_dialect, out);
    CHECK(run.ok(*t));
    CHECK(out.flushes >= 1);
    CHECK(out.written + out.pending == expected);
  }
  SECTION("a reader error: no second pass, nothing reaches the sink") {
    const auto t = make_translator<From, To>(program::id_of<program::siemens::dialect>(), "bad.mpf", options);
    chunked_sink out;
    const auto run = stream_text(*t, siemens_program(30000, 29000), program::id_of<program::siemens::dialect>(), "bad.mpf",
                                 *options.output_dialect, out);
    CHECK_FALSE(run.input.ok());
    CHECK_FALSE(run.ok(*t));
    CHECK(out.calls == 0);
    CHECK(out.pending.empty());
    CHECK(t->result().blocks_written == 0);
  }
  SECTION("a sink that fails is given nothing more") {
    const auto t = make_translator<From, To>(program::id_of<program::siemens::dialect>(), "long.mpf", options);
    chunked_sink out;
    out.fail_at = 0;
    const auto run = stream_text(*t, text, program::id_of<program::siemens::dialect>(), "long.mpf", *options.output_dialect, out);
    CHECK(run.sink_failed);
    CHECK_FALSE(run.ok(*t));
    CHECK(out.flushes == 1);
    CHECK(out.calls < 30000);
    CHECK(out.pending.size() < (std::size_t{1} << 20) + 200);  // one block past the 1 MiB mark
  }
  SECTION("a block the target cannot reach: nothing after it reaches the sink") {
    // A = +20° is outside the DMU 80P's reach (k_d = −sin A < 0): an error on the last motion.
    std::string unreachable = text;
    unreachable.insert(unreachable.rfind("N"), "N999999 G1 X0 Y0 Z50 A20 B0\n");
    const auto t = make_translator<From, To>(program::id_of<program::siemens::dialect>(), "far.mpf", options);
    string_sink out;
    const auto run = stream_text(*t, unreachable, program::id_of<program::siemens::dialect>(), "far.mpf", *options.output_dialect, out);
    CHECK(run.input.ok());
    CHECK_FALSE(run.ok(*t));
    CHECK(t->result().per_class[static_cast<std::size_t>(matchability::unreachable)] == 1);
    CHECK(out.text.size() < expected.size());  // at most the blocks before the error
    CHECK(expected.compare(0, out.text.size(), out.text) == 0);
  }
}
