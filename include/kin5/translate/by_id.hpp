/// @file translate/by_id.hpp
/// The translation for catalog machines named at run time by id ("sajo-12000p", "dmu-80p"):
/// `translate`, `reverse`, `post` and the `make_*` translators, each the function of the same
/// name for the machine value with that id (`machines::find_machine`, the one lookup of a catalog
/// machine's model by id), and an error naming the valid ids for an unknown one.
///
/// Opt-in (not included by `kin5.hpp`), as it includes the whole catalog. The pipeline runs on
/// machine values, so this is one instantiation for every machine and pair (it used to be one
/// per ordered pair of catalog machines).
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
      cl_source{}, cl_target(language), file, language, report_detail::every_block,
      "unknown machine '" + std::string(id) + "'; known: " + catalog_ids());
}
}  // namespace translate_detail

/// `make_translator(from, to, …)` for catalog ids; for an unknown id, a translator whose result
/// holds that error.
inline std::unique_ptr<block_translator> make_translator(std::string_view from_id, std::string_view to_id,
                                                         program::dialect source_language, const std::string& file,
                                                         const translate_options& options,
                                                         report_detail detail = report_detail::every_block) {
  const machine_model* from = machines::find_machine(from_id);
  const machine_model* to = machines::find_machine(to_id);
  if (from && to) return make_translator(*from, *to, source_language, file, options, detail);
  return translate_detail::unknown_machine(file, output_dialect_of(options, to_id), from ? to_id : from_id);
}

/// `make_reverse(m, …)` for a catalog id; for an unknown id, a translator whose result holds that error.
inline std::unique_ptr<block_translator> make_reverse(std::string_view machine_id, program::dialect source_language,
                                                      const std::string& file,
                                                      report_detail detail = report_detail::every_block,
                                                      const common_options& common = {}) {
  if (const machine_model* m = machines::find_machine(machine_id))
    return make_reverse(*m, source_language, file, detail, common);
  return translate_detail::unknown_machine(file, program::cl_data_dialect(), machine_id);
}

/// `make_post(m, …)` for a catalog id; for an unknown id, a translator whose result holds that error.
inline std::unique_ptr<block_translator> make_post(std::string_view machine_id, program::dialect source_language,
                                                   program::dialect output_dialect, const std::string& file,
                                                   report_detail detail = report_detail::every_block,
                                                   const common_options& common = {}) {
  if (const machine_model* m = machines::find_machine(machine_id))
    return make_post(*m, source_language, output_dialect, file, detail, common);
  return translate_detail::unknown_machine(file, output_dialect, machine_id);
}

/// `translate(from, to, …)` for catalog ids; an error for an unknown id.
inline translation translate(std::string_view from_id, std::string_view to_id, const program::program& nc,
                             const translate_options& options) {
  return translate_detail::run(*make_translator(from_id, to_id, nc.language, nc.file, options), nc);
}

/// `reverse(m, …)` for a catalog id; an error for an unknown id.
inline translation reverse(std::string_view machine_id, const program::program& nc) {
  return translate_detail::run(*make_reverse(machine_id, nc.language, nc.file), nc);
}

/// `post(m, …)` for a catalog id; an error for an unknown id.
inline translation post(std::string_view machine_id, const program::program& cl, program::dialect output_dialect) {
  return translate_detail::run(*make_post(machine_id, cl.language, output_dialect, cl.file), cl);
}

}  // namespace kin5
