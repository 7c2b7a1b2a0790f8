/// @file law_translation.hpp
/// What the translating per-pair laws share. `law_program(from, file, blocks)` is the program
/// model a law writes as text of dialect `from`. `law_translator<M>(from, to, file, options)` is
/// the translator that text goes through on machine M to itself: `post` from CL data, `reverse`
/// into CL data, else `translate` with `options` and `to` as output dialect (the setup is the
/// identity unless `options` turns it); `options.common` (`--work-offset-map`, …) goes to all three.
///
///   const std::string text = write(from, law_program(from, "m", blocks));
///   const auto t = law_translator<machines::dmu_80p>(from, to, "m");
///   const auto run = stream_text(*t, text, from, "m", to, out);
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <kin5/kin5.hpp>

namespace kin5::test {

/// A program of dialect `from` named `file`, made of `blocks`.
inline program::program law_program(program::dialect from, std::string file, std::vector<program::block> blocks) {
  program::program p;
  p.language = from;
  p.file = std::move(file);
  p.blocks = std::move(blocks);
  return p;
}

/// The translator of `from` text named `file` into `to` on machine M to itself.
template <machine M>
std::unique_ptr<block_translator> law_translator(program::dialect from, program::dialect to, const std::string& file,
                                                 translate_options options = {}) {
  const auto cl = program::id_of<program::apt::dialect>();
  if (from == cl) return make_post<M>(from, to, file, report_detail::exceptions_only, options.common);
  if (to == cl) return make_reverse<M>(from, file, report_detail::exceptions_only, options.common);
  options.output_dialect = to;
  return make_translator<M, M>(from, file, options, report_detail::exceptions_only);
}

}  // namespace kin5::test
