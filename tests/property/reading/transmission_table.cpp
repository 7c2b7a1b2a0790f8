// Transmission bytes, for every dialect of the list: a UTF-8 byte-order mark at offset 0 and an
// ETX byte after the program end are skipped (text → model → text equals the program without
// them); an ETX before the end, or followed by more text, is refused at its place. Each
// dialect's texts (a short program that ends, the same without its end, a comment with an ETX)
// are in its test folder's contract (`transmission`, tests/property/dialects/<name>/contract.hpp).
#include <algorithm>
#include <cstddef>
#include <string>
#include <type_traits>

#include <catch2/catch.hpp>

#include <kin5/program/dialect.hpp>
#include <kin5/program/io.hpp>

#include "../dialects/contracts.hpp"

using namespace kin5::program;

namespace {

std::size_t line_count(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

/// `f(id, texts)` for every dialect D of the list, with its contract's transmission texts.
template <class F>
void each_dialect(F&& f) {
  for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t) {
    static_assert(kin5::test::has_contract<D>, "every dialect needs tests/property/dialects/<name>/contract.hpp");
    INFO(D::name);
    f(id_of<D>(), kin5::test::contract<D>::transmission);
  });
}

}  // namespace

TEST_CASE("transmission: a byte-order mark at offset 0 is skipped by every reader") {
  each_dialect([](dialect d, const kin5::test::transmission_texts& t) {
    const std::string text(t.ending);
    const read_result plain = read(d, text, "p");
    const read_result marked = read(d, "\xEF\xBB\xBF" + text, "p");
    REQUIRE(plain.ok());
    REQUIRE(marked.ok());
    CHECK(marked.parsed.blocks == plain.parsed.blocks);
    CHECK(write(d, marked.parsed) == write(d, plain.parsed));
  });
}

TEST_CASE("transmission: a byte-order mark after offset 0 is an error at its place, in every reader") {
  each_dialect([](dialect d, const kin5::test::transmission_texts& t) {
    const std::string text(t.ending);
    for (const std::string& lead : {std::string("\x0c"), std::string(" "), text}) {
      const read_result r = read(d, lead + "\xEF\xBB\xBF" + text, "p");
      REQUIRE(!r.ok());
      CHECK(r.errors.front().message.find("byte-order mark inside the program") != std::string::npos);
      CHECK(r.errors.front().where.line == 1 + line_count(lead));
    }
  });
}

TEST_CASE("transmission: an ETX after the program end is skipped, with line ends after it") {
  each_dialect([](dialect d, const kin5::test::transmission_texts& t) {
    const std::string text(t.ending);
    const read_result plain = read(d, text, "p");
    for (const std::string tail : {"\x03", "\x03\n", "\x03\r\n  \n"}) {
      const read_result framed = read(d, "\xEF\xBB\xBF" + text + tail, "p");
      REQUIRE(framed.ok());
      CHECK(framed.parsed.blocks == plain.parsed.blocks);
      CHECK(write(d, framed.parsed) == write(d, plain.parsed));
    }
  });
}

TEST_CASE("transmission: an ETX before the program end is refused at its place") {
  each_dialect([](dialect d, const kin5::test::transmission_texts& t) {
    const std::string open(t.open);
    const read_result r = read(d, open + "\x03\n", "p");
    REQUIRE(r.errors.size() == 1);
    CHECK(r.errors[0].to_string() == "p:" + std::to_string(line_count(open) + 1) +
                                         ":1: error: end-of-transmission byte 0x03 before the end of the program");
  });
}

TEST_CASE("transmission: an ETX inside a comment is refused at its place") {
  // Found by fuzzing: the comment was read, and written back as a final ETX its own reader refused.
  each_dialect([](dialect d, const kin5::test::transmission_texts& t) {
    const std::string text(t.ending);
    const std::string comment(t.etx_in_comment);
    const std::size_t first_line_end = text.find('\n') + 1;
    const std::string program = text.substr(0, first_line_end) + comment + text.substr(first_line_end);
    const read_result r = read(d, program, "p");
    REQUIRE(r.errors.size() == 1);
    const std::size_t column = comment.find('\x03') + 1;
    CHECK(r.errors[0].to_string() == "p:2:" + std::to_string(column) +
                                         ": error: end-of-transmission byte 0x03 inside the program (one is allowed only after its end)");
  });
}

TEST_CASE("transmission: text after the ETX is program text, and the ETX in it is refused") {
  each_dialect([](dialect d, const kin5::test::transmission_texts& t) {
    const std::string text(t.ending);
    const read_result r = read(d, text + "\x03\nG0 X1\n", "p");
    REQUIRE_FALSE(r.ok());
    CHECK(r.errors[0].where.line == line_count(text) + 1);
  });
}
