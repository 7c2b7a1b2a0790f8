/// @file translate/by_id.hpp
/// The translation for catalog machines named at run time by id ("sajo-12000p", "dmu-80p"):
/// `translate`, `reverse`, `post` and the `make_*` translators, each the template of the same
/// name for the machine (or pair) with that id (found by `machines::with_machine`, the one lookup
/// of a catalog machine by id), and an error naming the valid ids for an unknown one.
///
/// Opt-in (not included by `kin5.hpp`): every function here instantiates the pipeline for each
/// catalog machine, or each ordered pair of them for `translate` (7 × 7), which costs seconds of
/// compile time in every file that includes it.
/// @code
///   #include <kin5/translate/by_id.hpp>
///   const kin5::translation t = kin5::translate("sajo-12000p", "dmu-80p", nc, options);
///   if (!t.ok()) for (const auto& e : t.errors) std::cerr << e.to_string() << '\n';
/// @endcode
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "../machines/catalog.hpp"
#include "pipeline.hpp"
#include "translate.hpp"

namespace kin5 {

/// The ids of every catalog machine, in catalog order, separated by ", ".
inline std::string catalog_ids() {
  std::string ids;
  machines::for_each_machine([&]<class M>() { ids += (ids.empty() ? "" : ", ") + std::string(M::id); });
  return ids;
}

namespace translate_detail {
/// A `block_translator` that only counts blocks: for a machine id not in the catalog.
inline std::unique_ptr<block_translator> unknown_machine(const std::string& file, program::dialect language,
                                                         std::string_view id) {
  return std::make_unique<two_pass_translator<cl_source, cl_target>>(
      cl_target(language), file, language, report_detail::every_block,
      "unknown machine '" + std::string(id) + "'; known: " + catalog_ids());
}
}  // namespace translate_detail

/// `make_translator<From, To>` for catalog ids; for an unknown id, a translator whose result
/// holds that error.
inline std::unique_ptr<block_translator> make_translator(std::string_view from_id, std::string_view to_id,
                                                         program::dialect source_language, const std::string& file,
                                                         const translate_options& options,
                                                         report_detail detail = report_detail::every_block) {
  std::unique_ptr<block_translator> out;
  const bool from_known = machines::with_machine(from_id, [&]<class From>() {
    machines::with_machine(to_id, [&]<class To>() { out = make_translator<From, To>(source_language, file, options, detail); });
  });
  if (out) return out;
  return translate_detail::unknown_machine(file, options.output_dialect, from_known ? to_id : from_id);
}

/// `make_reverse<M>` for a catalog id; for an unknown id, a translator whose result holds that error.
inline std::unique_ptr<block_translator> make_reverse(std::string_view machine_id, program::dialect source_language,
                                                      const std::string& file,
                                                      report_detail detail = report_detail::every_block,
                                                      const common_options& common = {}) {
  std::unique_ptr<block_translator> out;
  machines::with_machine(machine_id, [&]<class M>() { out = make_reverse<M>(source_language, file, detail, common); });
  if (out) return out;
  return translate_detail::unknown_machine(file, program::dialect::apt, machine_id);
}

/// `make_post<M>` for a catalog id; for an unknown id, a translator whose result holds that error.
inline std::unique_ptr<block_translator> make_post(std::string_view machine_id, program::dialect source_language,
                                                   program::dialect output_dialect, const std::string& file,
                                                   report_detail detail = report_detail::every_block,
                                                   const common_options& common = {}) {
  std::unique_ptr<block_translator> out;
  machines::with_machine(machine_id, [&]<class M>() {
    out = make_post<M>(source_language, output_dialect, file, detail, common);
  });
  if (out) return out;
  return translate_detail::unknown_machine(file, output_dialect, machine_id);
}

/// `translate<From, To>` for catalog ids; an error for an unknown id.
inline translation translate(std::string_view from_id, std::string_view to_id, const program::program& nc,
                             const translate_options& options) {
  return translate_detail::run(*make_translator(from_id, to_id, nc.language, nc.file, options), nc);
}

/// `reverse<M>` for a catalog id; an error for an unknown id.
inline translation reverse(std::string_view machine_id, const program::program& nc) {
  return translate_detail::run(*make_reverse(machine_id, nc.language, nc.file), nc);
}

/// `post<M>` for a catalog id; an error for an unknown id.
inline translation post(std::string_view machine_id, const program::program& cl, program::dialect output_dialect) {
  return translate_detail::run(*make_post(machine_id, cl.language, output_dialect, cl.file), cl);
}

}  // namespace kin5
