/// @file translate/stream.hpp
/// The streaming driver: a `block_translator` run over a whole program of any length, in two
/// passes, with the output text going to a sink the caller provides (a file, a string):
///
///     pass 1: read_blocks → plan(b), and each block kept as a compact record (block_store);
///             the input text is freed after this pass
///     pass 2: replay the records → write(b) → block_writer of the output dialect → sink
///
/// The records take at most `read_limits::max_memory_bytes` of memory; the rest wait in a
/// temporary file (block_store.hpp), and a failure to use it is an input error, never a partial
/// output. A diagnostic about a block run inside a call says where it was called from
/// (`diagnostic::called_from`, from the reader's `call_chains`).
///
/// The output is written only while the run is clean: once any error is known (a reader error
/// stops before pass 2; a translation error; a block the output dialect cannot say; the sink
/// failing), nothing more reaches the sink, so the sink holds the whole program exactly when
/// `ok` holds. A program with no block at all (empty, or blank lines only) is an input error:
/// there is nothing to translate, and an empty output would pass for one. Input read as APT CL
/// data that is an NC program (recognised by its markers, or with no GOTO/ and statements that
/// are not APT) is an input error too, not a program of comments. `stream_text` scans the text
/// for its resolution first (`program::scan_resolution`), for the default angle tolerance and
/// the output's decimals (precision.hpp); a caller of `stream_blocks` gives it to the translator
/// (`block_translator::source_resolution`). A text that breaks the translator's
/// `read_limits` (`common_options::limits`) is refused with one error at its place, before any
/// reader runs. The `kin5` tool and the laws run this same code.
/// @code
///   auto t = kin5::make_translator<From, To>(source_language, "part.mpf", options);
///   kin5::string_sink out;  // or the tool's output file: any `text_sink`
///   const auto run = kin5::stream_text(*t, std::move(text), source_language, "part.mpf",
///                                      kin5::output_dialect_of(options, To::id), out);
///   if (!run.ok(*t)) { /* run.input.errors, t->result().errors, run.writer_error */ }
/// @endcode
#pragma once

#include <concepts>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "../program/address_words.hpp"
#include "../program/units.hpp"
#include "../program/block.hpp"
#include "../program/block_store.hpp"
#include "../program/io.hpp"
#include "../program/program_name.hpp"
#include "pipeline.hpp"

namespace kin5 {

/// Where the driver writes the output text: it appends each block's text to `buffer()`, then
/// calls `flush_if_full()`, which may write the buffer out and empty it (the tool's output file
/// does once it holds 1 MiB); false stops the writing (e.g. the file cannot be written).
template <class S>
concept text_sink = requires(S& sink) {
  { sink.buffer() } -> std::same_as<std::string&>;
  { sink.flush_if_full() } -> std::same_as<bool>;
};

/// A `text_sink` that keeps the whole output in a string.
struct string_sink {
  std::string text;
  std::string& buffer() { return text; }
  bool flush_if_full() { return true; }
};

/// Reads a program: gives every block to the sink in file order, diagnostics to the result.
using block_source = std::function<void(program::read_result& diagnostics, const program::block_sink& on_block)>;

/// Sees each block once the first pass has planned it, with what the reader and the translation
/// have found so far (e.g. `block_accounting`, run_report.hpp, which counts the refused blocks).
using block_watch =
    std::function<void(const program::block& b, const program::read_result& input, const translation& so_far)>;

/// What a streamed run found besides the translator's own result.
struct stream_result {
  program::read_result input;              ///< the reader's errors and warnings (`parsed` stays empty)
  /// The first block the output dialect cannot say (a construct, or a number no NC program can
  /// hold), at that block.
  std::optional<program::diagnostic> writer_error;
  bool sink_failed = false;                ///< `flush_if_full` failed
  std::size_t record_chunks = 0;           ///< chunks the block store took for the first pass
  /// Whether the whole output reached the sink: no error anywhere.
  bool ok(block_translator& t) const {
    return input.ok() && t.result().ok() && !writer_error && !sink_failed;
  }
};

/// Whether block `b` says nothing: blanks only (a reader may pass a blank line on as text).
inline bool blank(const program::block& b) {
  if (b.text.find_first_not_of(" \t\f\v\r\n") != std::string::npos) return false;
  program::block content = b;
  content.where = {};
  content.call_chain = 0;
  content.text.clear();
  content.passthrough = false;
  return content == program::block{};
}

/// How a file given as APT CL data was seen to be NC: by its markers, or because an NC
/// dialect's reader finds fewer errors in it than the APT reader and no GOTO/ moves the tool.
enum class nc_evidence { markers, reader };

/// Why a file read as APT CL data is not: it moves the tool nowhere and `not_understood` of its
/// statements are not APT, or it is NC in dialect `looks_like` (an NC program given to `post`
/// would otherwise become comments, or an error per line).
inline std::string not_cl_data(std::size_t not_understood, std::optional<program::dialect> looks_like = {},
                               nc_evidence by = nc_evidence::markers) {
  std::string why = "not APT CL data: ";
  why += looks_like ? "it reads as an NC program in the " + std::string(program::name(*looks_like)) + " dialect" +
                          (by == nc_evidence::markers ? " (by its markers)" : " (no GOTO/, and its reader finds fewer errors)")
                    : "no GOTO/ moves the tool and " + std::to_string(not_understood) +
                          (not_understood == 1 ? " statement is" : " statements are") + " not APT";
  return why + "; post reads CL data, translate and reverse read NC programs";
}

/// The NC dialect whose reader finds the fewest errors in `text`, fewer than `cl_errors` (the
/// first in `program::dialects` on a tie); none when no NC reader does better than APT's.
/// `limits`: the ones the text was read within.
inline std::optional<program::dialect> closest_nc_dialect(std::string_view text, std::size_t cl_errors,
                                                          const program::read_limits& limits = {}) {
  std::optional<program::dialect> best;
  std::size_t fewest = cl_errors;
  for (const program::dialect d : program::nc_dialect_ids()) {
    program::read_result r;
    program::read_blocks(d, text, "", r, [](program::block&&) {}, limits);
    if (r.error_count() < fewest) fewest = r.error_count(), best = d;
  }
  return best;
}

/// Both passes of `t` over the blocks `read` gives (see the file comment); output blocks are
/// written in `output_language` to `sink` with the writer settings `chosen` (decimals from the
/// translation; `chosen.program_name` names a program whose source names none, Heidenhain's
/// BEGIN PGM); `watch`, if given, sees each block of the first pass.
template <text_sink Sink>
stream_result stream_blocks(block_translator& t, const block_source& read, const std::string& file,
                            program::dialect source_language, program::dialect output_language, Sink& sink,
                            const block_watch& watch = {}, const program::write_settings& chosen = {}) {
  stream_result run;
  program::block_store records(file);
  records.memory_bytes(t.limits().max_memory_bytes);
  // The calls of the block being translated, for its diagnostics: looked up when the chain changes.
  std::uint32_t chain = 0;
  std::vector<program::source_location> calls;
  const auto calls_of = [&](const program::block& b) -> const std::vector<program::source_location>& {
    if (b.call_chain != chain) {
      chain = b.call_chain;
      calls = chain != 0 && chain <= run.input.calls.size() ? run.input.calls.sites(chain)
                                                            : std::vector<program::source_location>{};
    }
    return calls;
  };
  bool says_something = false;  // a block with more than blanks
  std::size_t moving = 0, not_understood = 0;
  program::program_unit unit;  // for writers that state the unit and name at the top
  program::program_name name;
  read(run.input, [&](program::block&& b) {
    says_something = says_something || !blank(b);
    unit.take(b);
    name.take(b);
    moving += b.moves() ? 1 : 0;
    not_understood += b.passthrough && !b.framing && !b.assignment ? 1 : 0;
    const calls_scope called_from(calls_of(b));
    t.plan(b);
    if (watch) watch(b, run.input, t.result());
    records.push(b, second_pass_reads_text(b));
  });
  run.record_chunks = records.chunks();
  if (!records.error().empty()) run.input.errors.push_back(translate_detail::file_error(file, records.error()));
  if (run.input.ok() && !says_something)
    run.input.errors.push_back(translate_detail::file_error(file, "empty program: no block to translate"));
  if (run.input.ok() && program::capabilities_of(source_language).cl_data && moving == 0 && not_understood > 0)
    run.input.errors.push_back(translate_detail::file_error(file, not_cl_data(not_understood)));
  if (!run.input.ok()) return run;

  program::write_settings settings = write_settings_for(output_language, t.result().output_decimals, chosen);
  settings.program_metric = unit.metric;
  settings.program_name = name.name();
  if (!settings.program_name) settings.program_name = chosen.program_name;
  program::block_writer writer(output_language, source_language, file, settings);
  const program::block_sink emit = [&](program::block&& o) {
    if (run.writer_error || run.sink_failed || !t.result().ok()) return;
    try {
      writer.write(sink.buffer(), o);
    } catch (const std::invalid_argument& e) {  // a number or a construct: at its block
      std::string_view why = e.what();
      const std::string line = o.where.file.str() + ":" + std::to_string(o.where.line) + ": ";
      if (why.starts_with(line)) why.remove_prefix(line.size());  // the writer named the block
      run.writer_error = called(program::diagnostic{o.where, std::string(why)});
      return;
    }
    run.sink_failed = !sink.flush_if_full();
  };
  const bool replayed = records.replay([&](const program::block& b) {
    const calls_scope called_from(calls_of(b));
    t.write(b, emit);
  });
  if (!replayed) {  // nothing more reaches the sink, and the run is not ok
    run.input.errors.push_back(translate_detail::file_error(file, records.error()));
    return run;
  }
  if (!run.writer_error && !run.sink_failed && t.result().ok()) {
    writer.finish(sink.buffer());
    run.sink_failed = !sink.flush_if_full();
  }
  return run;
}

/// Both passes of `t` over the program `text` in `source_language` (`file` names it in
/// diagnostics); `text` is freed after the first pass. Output, `watch` and `chosen` as
/// `stream_blocks`.
template <text_sink Sink>
stream_result stream_text(block_translator& t, std::string text, program::dialect source_language,
                          const std::string& file, program::dialect output_language, Sink& sink,
                          const block_watch& watch = {}, const program::write_settings& chosen = {}) {
  const program::number_resolution resolution = program::scan_resolution(text, source_language);
  t.source_resolution(resolution);
  const block_source read = [&](program::read_result& diagnostics, const program::block_sink& on_block) {
    const bool cl_data = program::capabilities_of(source_language).cl_data;
    if (cl_data)  // the limits before the markers are looked for (read_blocks checks them too)
      if (auto broken = program::check_limits(text, t.limits(), file)) {
        diagnostics.add_error(std::move(*broken));
        std::string().swap(text);
        return;
      }
    const auto guessed = cl_data ? program::guess_dialect(text) : std::nullopt;
    if (guessed && *guessed != source_language) {  // NC given as CL data: refused before reading
      diagnostics.errors.push_back(translate_detail::file_error(file, not_cl_data(0, guessed)));
      return;
    }
    std::size_t moving = 0;
    const program::block_sink counting = [&](program::block&& b) {
      moving += b.moves() ? 1 : 0;
      on_block(std::move(b));
    };
    program::read_blocks(source_language, text, file, diagnostics, cl_data ? counting : on_block, t.limits());
    if (cl_data && moving == 0 && !diagnostics.ok()) {  // NC without markers: one error, not one per line
      if (const auto nc = closest_nc_dialect(text, diagnostics.error_count(), t.limits())) {
        diagnostics = {};
        diagnostics.errors.push_back(translate_detail::file_error(file, not_cl_data(0, nc, nc_evidence::reader)));
      }
    }
    if (diagnostics.resolution.empty()) diagnostics.resolution = resolution;
    std::string().swap(text);  // freed (assigning an empty string would keep the capacity)
  };
  return stream_blocks(t, read, file, source_language, output_language, sink, watch, chosen);
}

}  // namespace kin5
