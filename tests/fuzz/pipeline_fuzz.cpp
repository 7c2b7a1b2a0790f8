// libFuzzer target for the whole pipeline, as the tool runs it: read → plan → block store →
// translate → write, in memory (translate/stream.hpp), SAJO 12000P ↔ DMU 80P.
//
// Input: byte 0 picks the direction, the source and output dialects and the feed policy; byte 1
// how many times the rest is repeated: once below 0xF0, else 16, 64, … 4^(byte − 0xEE) times,
// at most 1.25 MiB in all, so that small inputs reach the block store's full 1 MiB chunks (its
// chunks double from 64 KiB; a repeated text without a line end is one huge block) while most
// runs stay short; the rest is
// the program. Large inputs reach it directly: run with -max_len=1310720 (docs/reliability.md).
//
// By hand (docs/reliability.md): KIN5_PIPELINE_FUZZ_MAX_TEXT=N caps the repeated text at N bytes
// instead, for a long run of small programs; KIN5_PIPELINE_FUZZ_STATS=1 prints at exit how many
// runs filled more than one chunk of the block store (the first is 64 KiB), and the longest text.
//
// Besides what the sanitizers catch: a run without errors has given the sink the whole program,
// and that program reads back without errors in the output dialect (faithful or refused: the
// tool never writes what it cannot read).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include <kin5/machines/dmu_80p.hpp>
#include <kin5/machines/sajo_12000p.hpp>
#include <kin5/program/io.hpp>
#include <kin5/translate/pipeline.hpp>
#include <kin5/translate/stream.hpp>

namespace {

using kin5::program::dialect;

constexpr auto nc_dialects = kin5::program::nc_dialect_ids();  // every dialect but CL data
constexpr std::size_t nc_count = nc_dialects.size();
constexpr kin5::feed_policy feeds[] = {kin5::feed_policy::tcp, kin5::feed_policy::block_time,
                                       kin5::feed_policy::inverse_time};
constexpr std::size_t max_text = std::size_t{5} << 18;  // 1.25 MiB: into the first full 1 MiB chunk

// KIN5_PIPELINE_FUZZ_MAX_TEXT and KIN5_PIPELINE_FUZZ_STATS (see the file comment).
std::size_t text_cap = max_text;
std::size_t runs = 0, runs_past_a_chunk = 0, longest_text = 0;

void print_stats() {
  std::fprintf(stderr, "pipeline_fuzz: %zu runs, %zu filled more than one block-store chunk, longest text %zu bytes\n",
               runs, runs_past_a_chunk, longest_text);
}

template <class From, class To>
void run(std::string text, dialect from, dialect to, kin5::feed_policy feed) {
  kin5::translate_options options;
  options.feed = feed;
  options.output_dialect = to;
  options.common.limits.max_executed_lines = 100'000;  // an input that loops for ever stops in milliseconds
  const auto translator = kin5::make_translator<From, To>(from, "fuzz", options, kin5::report_detail::exceptions_only);
  kin5::string_sink out;
  const std::size_t length = text.size();
  const kin5::stream_result r = kin5::stream_text(*translator, std::move(text), from, "fuzz", to, out);
  ++runs;
  runs_past_a_chunk += r.record_chunks > 1 ? 1 : 0;
  longest_text = std::max(longest_text, length);
  if (!r.ok(*translator)) return;
  kin5::program::read_result back;
  kin5::program::read_blocks(to, out.text, "out", back, [](kin5::program::block&&) {});
  if (!back.ok()) __builtin_trap();  // written, but not readable: neither faithful nor refused
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* cap = std::getenv("KIN5_PIPELINE_FUZZ_MAX_TEXT")) text_cap = std::strtoull(cap, nullptr, 10);
  if (const char* s = std::getenv("KIN5_PIPELINE_FUZZ_STATS"); s && *s == '1') std::atexit(print_stats);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const unsigned choice = data[0];
  const dialect from = nc_dialects[choice % nc_count];
  const dialect to = nc_dialects[(choice / nc_count) % nc_count];
  const kin5::feed_policy feed = feeds[(choice / (nc_count * nc_count)) % 3];
  const bool backwards = (choice / (nc_count * nc_count * 3)) % 2 != 0;
  const std::size_t copies = data[1] < 0xF0 ? 1 : std::size_t{1} << std::min(2 * (data[1] - 0xEE), 22);
  const std::string_view program(reinterpret_cast<const char*>(data + 2), size - 2);
  std::string text;
  if (!program.empty()) {
    const std::size_t n = std::max<std::size_t>(1, std::min(copies, text_cap / program.size()));
    text.reserve(n * program.size());
    for (std::size_t k = 0; k < n; ++k) text.append(program);
  }
  if (backwards)
    run<kin5::machines::dmu_80p, kin5::machines::sajo_12000p>(std::move(text), from, to, feed);
  else
    run<kin5::machines::sajo_12000p, kin5::machines::dmu_80p>(std::move(text), from, to, feed);
  return 0;
}
