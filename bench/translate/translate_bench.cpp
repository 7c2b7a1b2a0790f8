// The translation benchmark in process: the library's streaming driver (translate/stream.hpp)
// translating the spiral program (spiral.hpp) from the SAJO 12000P (Siemens) to the DMU 80P
// (Heidenhain), machines named by id as the kin5 tool names them, against the parse+format
// floor (reformat.hpp) on the same text. No file I/O on either side: the difference is the
// translation. bench/translate/gbench.sh runs it and prints the ratio.
//
//   kin5_bench_translate [--blocks=N] [Google Benchmark flags]    (N default 20000)
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include <kin5/translate/by_id.hpp>
#include <kin5/translate/stream.hpp>

#include "reformat.hpp"
#include "spiral.hpp"

namespace {

long blocks = 20000;

/// One whole translation of `text`; the output in `out`. False, with the first error on
/// stderr, if anything in it failed (the benchmark must time a clean run).
bool translate_once(const std::string& text, kin5::string_sink& out) {
  kin5::translate_options options;
  options.output_dialect = kin5::program::id_of<kin5::program::heidenhain::dialect>();
  // The program's G54 is preset 1 on the TNC, as bench/translate/run.sh maps it for the tool.
  options.common.work_offsets.add("G54=1");
  const auto t = kin5::make_translator("sajo-12000p", "dmu-80p", kin5::program::id_of<kin5::program::siemens::dialect>(), "spiral.mpf",
                                       options, kin5::report_detail::exceptions_only);
  const auto run = kin5::stream_text(*t, text, kin5::program::id_of<kin5::program::siemens::dialect>(), "spiral.mpf",
                                     kin5::program::id_of<kin5::program::heidenhain::dialect>(), out);
  if (run.ok(*t) && t->result().blocks_written > static_cast<std::size_t>(blocks)) return true;
  std::fprintf(stderr, "translation failed: %zu input errors, %zu errors, %zu blocks written\n",
               run.input.errors.size(), t->result().errors.size(), t->result().blocks_written);
  const kin5::program::diagnostic* first = !run.input.errors.empty()     ? &run.input.errors.front()
                                           : !t->result().errors.empty() ? &t->result().errors.front()
                                           : run.writer_error            ? &*run.writer_error
                                                                         : nullptr;
  if (first) std::fprintf(stderr, "%s\n", first->to_string().c_str());
  return false;
}

void translate_by_id(benchmark::State& state, const std::string& text) {
  for (auto _ : state) {
    kin5::string_sink out;
    if (!translate_once(text, out)) {
      state.SkipWithError("translation failed");
      break;
    }
    benchmark::DoNotOptimize(out.text.data());
  }
  state.SetItemsProcessed(state.iterations() * blocks);
}

void parse_baseline(benchmark::State& state, const std::string& text) {
  for (auto _ : state) {
    std::string out;
    benchmark::DoNotOptimize(kin5_bench::reformat_numbers(text, out));
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * blocks);
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--blocks=", 9) == 0) blocks = std::strtol(argv[i] + 9, nullptr, 10);
  if (blocks <= 0) {
    std::fprintf(stderr, "--blocks must be a positive number\n");
    return 1;
  }
  static const std::string text = kin5_bench::spiral_program(blocks);
  // One run before timing: a translation that fails stops the program here, with its error,
  // rather than timing nothing.
  if (kin5::string_sink out; !translate_once(text, out)) return 1;
  benchmark::RegisterBenchmark("translate/sajo-12000p/dmu-80p", translate_by_id, text)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("parse_baseline", parse_baseline, text)->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
