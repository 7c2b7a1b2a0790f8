/// @file contract.hpp
/// What the dialect laws (laws.cpp) and the fuzz targets need to know of a dialect beyond its
/// entry in `program::dialects`: `contract<D>`, specialised in `<name>/contract.hpp` next to
/// that dialect's tables, generator and examples. The laws are written once, for every D of the
/// list; a dialect without a contract does not compile into the suite.
///
/// A contract has:
/// | member | what |
/// |---|---|
/// | `file` | the file name of generated and fuzzed text |
/// | `draw_program()` | generated text with the model it must read as (RapidCheck; `<name>/generator.cpp`) |
/// | `bad_file` | the file name the bad-input table (`<name>/errors.txt`, bad_inputs.hpp) is read as |
/// | `read_exactly` | how the reading of generated text matches the drawn model |
/// | `read_back` | how `read(write(model))` matches the model (a writer may renumber) |
/// | `numbers_from_zero` | whether the writer numbers blocks 0, 1, 2, … itself |
/// | `fuzz_options()`, `fuzz_read_back`, `fuzz_fixed_point` | how the fuzz target writes and compares |
/// | `writes_all_it_reads` | whether the writer must accept every program the reader accepts |
/// | `round_trips(p)` | whether a program read is inside the writer's round-trip contract |
/// | `transmission` | a short program that ends, the same without its end, a comment with an ETX (`transmission_texts`) |
///
/// `usual_contract<D>` holds what most dialects say; a contract derives from it and declares
/// only what differs.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <kin5/program/block.hpp>
#include <kin5/program/dialect_id.hpp>

#include "model_difference.hpp"

namespace kin5::test {

/// See the file comment; one specialisation per dialect.
template <class D>
struct contract;

/// Generated text and the model it must read as.
struct drawn_program {
  std::string text;
  program::program expected;
};

/// Generated `text` with the program it must read as in dialect D: the `expected` block of each
/// of `items`, in order, from the contract's `file`.
template <class D, class Item>
drawn_program drawn_from(std::string text, const std::vector<Item>& items) {
  drawn_program d{std::move(text), {}};
  d.expected.language = program::id_of<D>();
  d.expected.file = std::string(contract<D>::file);
  for (const Item& it : items) d.expected.blocks.push_back(it.expected);
  return d;
}

/// Texts in a dialect's own spelling for the transmission laws
/// (tests/property/reading/transmission_table.cpp), which fold over the list.
struct transmission_texts {
  std::string_view ending;          ///< a short program that ends: moves, then the dialect's end
  std::string_view open;            ///< the same motion without its end
  std::string_view etx_in_comment;  ///< one comment line with an ETX byte (0x03) inside it
};

/// What most contracts say: readings and read-backs compare to the last bit of a decimal, the
/// writer keeps the block numbers read and writes every program the reader accepts; the fuzz
/// target writes the default decimals (3 for lengths, 7 for vectors, 1 for feeds), so a first
/// read-back is within 0.05, and once written the text is a fixed point.
template <class D>
struct usual_contract {
  static constexpr comparison read_exactly{};
  static constexpr comparison read_back{};
  static constexpr bool numbers_from_zero = false;
  static typename D::write_options fuzz_options() { return {}; }
  static constexpr comparison fuzz_read_back{.tolerance = 0.05};
  static constexpr comparison fuzz_fixed_point{};
  static constexpr bool writes_all_it_reads = true;
  static bool round_trips(const program::program&) { return true; }
};

/// A text and the exact diagnostics (`FILE:LINE:COL: error: …`, in order) reading it gives.
struct bad_input {
  std::string text;
  std::vector<std::string> errors;
};

/// Whether dialect D has a contract (a complete `contract<D>`).
template <class D>
concept has_contract = requires { sizeof(contract<D>); };

/// `text` read by dialect D's reader, as from a file named `file` (by default the contract's).
template <class D>
program::read_result read_as(std::string_view text, std::string file = std::string(contract<D>::file)) {
  return program::read_whole(program::id_of<D>(), text, std::move(file), &D::read_blocks);
}

/// `p` written by dialect D's writer with its default options.
template <class D>
std::string write_as(const program::program& p) {
  return D::write(p, typename D::write_options{});
}

}  // namespace kin5::test
