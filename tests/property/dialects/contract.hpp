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
/// | `bad_inputs()` | texts and the exact diagnostics each gives (`<name>/errors.cpp`) |
/// | `read_exactly` | how the reading of generated text matches the drawn model |
/// | `read_back` | how `read(write(model))` matches the model (a writer may renumber) |
/// | `numbers_from_zero` | whether the writer numbers blocks 0, 1, 2, … itself |
/// | `fuzz_options()`, `fuzz_read_back`, `fuzz_fixed_point` | how the fuzz target writes and compares |
/// | `writes_all_it_reads` | whether the writer must accept every program the reader accepts |
/// | `round_trips(p)` | whether a program read is inside the writer's round-trip contract |
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <kin5/program/block.hpp>

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
