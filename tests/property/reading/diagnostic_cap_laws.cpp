// Reading keeps at most `max_kept_diagnostics` errors and counts the rest, whatever the input:
// memory per read is bounded (4 MiB of NUL bytes were 4,194,304 kept errors, 1.8 GB). The
// count stays exact, and the kept errors are the first found, so the tool prints the same first
// 100 and the same totals.
#include <algorithm>
#include <string>
#include <vector>
#include <type_traits>

#include <catch2/catch.hpp>

#include <kin5/program/io.hpp>
#include <kin5/translate/diagnostic_list.hpp>
#include <kin5/translate/run_report.hpp>

using namespace kin5::program;

namespace {
std::string repeated(std::string_view piece, std::size_t k) {
  std::string s;
  for (std::size_t i = 0; i < k; ++i) s += piece;
  return s;
}
}  // namespace

TEST_CASE("reading: k lines of a bad byte keep the first errors and count all k") {
  for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t) {
    INFO(D::name);
    const std::size_t per_line = read(id_of<D>(), "\x01\n", "t").error_count();
    REQUIRE(per_line >= 1);
    for (std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{999}, std::size_t{1000}, std::size_t{1001},
                          std::size_t{2600}}) {
      INFO("k = " << k);
      const read_result r = read(id_of<D>(), repeated("\x01\n", k), "t");
      CHECK(r.error_count() == k * per_line);
      CHECK(r.errors.size() == std::min(k * per_line, max_kept_diagnostics));
      CHECK(r.errors_not_kept == k * per_line - r.errors.size());
      if (!r.errors.empty())  // the first found are kept: the last kept is on the line it was found on
        CHECK(r.errors.back().where.line == (r.errors.size() + per_line - 1) / per_line);
    }
  });
}

TEST_CASE("reading: one line of 5000 NUL bytes keeps at most the cap") {
  for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t) {
    INFO(D::name);
    const read_result r = read(id_of<D>(), std::string(5000, '\0') + "\n", "t");
    CHECK(r.errors.size() <= max_kept_diagnostics);
    CHECK(r.errors.size() == std::min(r.error_count(), max_kept_diagnostics));
    CHECK(r.warnings.size() <= max_kept_diagnostics);
    if (id_of<D>() == id_of<siemens::dialect>() || id_of<D>() == id_of<heidenhain::dialect>()) CHECK(r.error_count() >= 5000);  // one per byte
  });
}

TEST_CASE("translation: a diagnostic_list holds the first 1,000 in source order and counts every one") {
  // Two passes' worth of errors, each pass in source order, the second interleaved with the
  // first's lines (as the plan and write passes of a translation add them), and ties.
  for (std::size_t n : {std::size_t{0}, std::size_t{999}, std::size_t{1999}, std::size_t{2000}, std::size_t{7321}}) {
    INFO("n = " << n);
    std::vector<diagnostic> all;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t line = i < n / 2 ? 2 * i + 3 : 2 * (i - n / 2) + (i % 3 == 0 ? 3 : 4);
      all.push_back({{file_name("t"), line, 1 + i % 2}, "error " + std::to_string(i)});
    }
    kin5::diagnostic_list list;
    for (const diagnostic& d : all) list.push_back(d);
    CHECK(list.count() == n);
    CHECK(list.size() < 2 * max_kept_diagnostics);
    CHECK(list.not_kept() == n - list.size());
    for (std::size_t i = 0; i < n; ++i) CHECK(list.line(i) == all[i].where.line);
    std::size_t more_all = 0, more_held = 0;
    const auto first_of_all = kin5::first_in_source_order(all, more_all);
    const auto first_held = kin5::first_in_source_order(list, more_held);
    REQUIRE(first_held.size() == first_of_all.size());
    for (std::size_t i = 0; i < first_held.size(); ++i) CHECK(first_held[i].message == first_of_all[i].message);
    CHECK(more_held + list.not_kept() == more_all);
  }
}
