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
  // The dialect's own reader, without `read`'s limits (which refuse the first NUL byte).
  for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t) {
    INFO(D::name);
    const read_result r = read_whole(id_of<D>(), std::string(5000, '\0') + "\n", "t", &D::read_blocks);
    CHECK(r.errors.size() <= max_kept_diagnostics);
    CHECK(r.errors.size() == std::min(r.error_count(), max_kept_diagnostics));
    CHECK(r.warnings.size() <= max_kept_diagnostics);
    if (id_of<D>() == id_of<siemens::dialect>() || id_of<D>() == id_of<heidenhain::dialect>()) CHECK(r.error_count() >= 5000);  // one per byte
  });
}

// The read limits (program/read_limits.hpp): a text that breaks one is refused, in every dialect,
// with one error at the first byte or word past it, before any lexer runs; one at the limit is read.
TEST_CASE("reading: a text past a read limit is refused at its place, one at the limit is read") {
  const read_limits small{.max_file_bytes = 64, .max_line_bytes = 20, .max_block_words = 4};
  const std::string line20 = std::string(20, 'c') + "\n";
  struct row {
    std::string text;
    std::size_t line, column;   // 0: read, no limit error
    std::string_view says;
  };
  const std::vector<row> rows{
      {"G1 X1 Y2\nG1 X1\n", 0, 0, ""},
      {"G1 X1\nG1 X1 Y2 Z3 F4\n", 2, 13, "words-per-block limit of 4; --max-block-words"},
      {"G1 X1\r\nX1Y2Z3A4B5\r\n", 2, 9, "words-per-block limit of 4"},         // a letter after a digit
      {"G1 X1\n(AB CD EF GH IJ)\n", 2, 11, "words-per-block limit of 4"},          // comments count
      {std::string(20, 'c') + "\nG1\n", 0, 0, ""},                                   // exactly the line limit
      {"G1\n" + std::string(21, 'c') + "\n", 2, 21, "line-length limit of 20 bytes; --max-line-bytes"},
      {"G1 X1\nG1 X" + std::string(1, '\0') + "\n", 2, 5, "a NUL byte (0x00): binary data"},
      {"G1\r" + std::string(1, '\0'), 2, 1, "a NUL byte"},
      {std::string(4, '\0') + std::string(30, 'c'), 1, 1, "a NUL byte"},              // before the long line
      {std::string(30, 'c') + std::string(4, '\0'), 1, 21, "line-length limit"},      // after it
      {"G1 X1 Y1\n" + line20 + line20 + std::string(13, 'c'), 0, 0, ""},            // 64 bytes
      {"G1 X1 Y1\n" + line20 + line20 + std::string(20, 'c'), 4, 14, "file-size limit of 64 bytes; --max-file-bytes"},
      {std::string(63, '\n') + "\r\n", 64, 2, "file-size limit of 64 bytes"},      // the stop between CR and LF
  };
  for (const row& r : rows) {
    INFO("text: " << r.text.substr(0, 40));
    for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t) {
      INFO(D::name);
      const read_result got = read(id_of<D>(), r.text, "t", small);
      const auto found = check_limits(r.text, small, "t");
      if (r.line == 0) {
        CHECK_FALSE(found);
        for (const diagnostic& e : got.errors) CHECK(e.message.find("--max-") == std::string::npos);
        return;
      }
      REQUIRE(got.error_count() == 1);
      CHECK(got.parsed.blocks.empty());
      CHECK(got.errors[0].where.line == r.line);
      CHECK(got.errors[0].where.column == r.column);
      CHECK(got.errors[0].message.find(r.says) != std::string::npos);
      read_result streamed;
      std::size_t blocks = 0;
      read_blocks(id_of<D>(), r.text, "t", streamed, [&](block&&) { ++blocks; }, small);
      CHECK(blocks == 0);
      REQUIRE(streamed.error_count() == 1);
      CHECK(streamed.errors[0].to_string() == got.errors[0].to_string());
    });
  }
}

TEST_CASE("reading: the default limits refuse a NUL byte and the 100,001st word, and read a 1 MiB comment") {
  CHECK(read(id_of<iso::dialect>(), std::string(1 << 20, '\0'), "t").error_count() == 1);
  const std::string words = "G1" + repeated(" X1.2.", 100'000);  // 100,001 words: the last one past
  const auto r = read(id_of<iso::dialect>(), words + "\n", "t");
  REQUIRE(r.error_count() == 1);
  CHECK(r.errors[0].where.column == 4 + 6 * 99'999);
  CHECK(r.errors[0].message.find("--max-block-words") != std::string::npos);
  const auto comment = read(id_of<iso::dialect>(), "G1 X1. (" + std::string(1 << 20, 'c') + ")\nM30\n", "t");
  CHECK(comment.ok());
  CHECK(comment.parsed.blocks.size() == 2);
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
