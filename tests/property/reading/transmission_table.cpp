// Transmission bytes, one row per dialect: a UTF-8 byte-order mark at offset 0 and an ETX byte
// after the program end are skipped (text → model → text equals the program without them); an
// ETX before the end, or followed by more text, is refused at its place.
#include <algorithm>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>

#include <catch2/catch.hpp>

#include <kin5/program/io.hpp>

using namespace kin5::program;

namespace {
// A short program that ends, in each dialect's own spelling.
const std::map<std::string_view, std::string> ending_program = {
    {"siemens", "G0 X10 Y20 Z30\nM30\n"},
    {"heidenhain", "BEGIN PGM T MM\nL X+10 Y+20 Z+30 FMAX\nEND PGM T MM\n"},
    {"iso", "%\nO1000\nG0 X10. Y20. Z30.\nM30\n%\n"},
    {"apt", "PARTNO T\nGOTO/10,20,30\nFINI\n"},
};
// The same motion without its end.
const std::map<std::string_view, std::string> open_program = {
    {"siemens", "G0 X10 Y20 Z30\n"},
    {"heidenhain", "BEGIN PGM T MM\nL X+10 Y+20 Z+30 FMAX\n"},
    {"iso", "%\nO1000\nG0 X10. Y20. Z30.\n"},
    {"apt", "PARTNO T\nGOTO/10,20,30\n"},
};

std::size_t line_count(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

template <class F>
void each_dialect(F&& f) {
  for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t) {
    INFO(D::name);
    REQUIRE(ending_program.count(D::name) == 1);  // every dialect has its row
    REQUIRE(open_program.count(D::name) == 1);
    f(kin5::program::id_of<D>(), ending_program.at(D::name), open_program.at(D::name));
  });
}
}  // namespace

TEST_CASE("transmission: a byte-order mark at offset 0 is skipped by every reader") {
  each_dialect([](dialect d, const std::string& text, const std::string&) {
    const read_result plain = read(d, text, "p");
    const read_result marked = read(d, "\xEF\xBB\xBF" + text, "p");
    REQUIRE(plain.ok());
    REQUIRE(marked.ok());
    CHECK(marked.parsed.blocks == plain.parsed.blocks);
    CHECK(write(d, marked.parsed) == write(d, plain.parsed));
  });
}

TEST_CASE("transmission: a byte-order mark after offset 0 is an error at its place, in every reader") {
  each_dialect([](dialect d, const std::string& text, const std::string&) {
    for (const std::string lead : {std::string("\x0c"), std::string(" "), text}) {
      const read_result r = read(d, lead + "\xEF\xBB\xBF" + text, "p");
      REQUIRE(!r.ok());
      CHECK(r.errors.front().message.find("byte-order mark inside the program") != std::string::npos);
      CHECK(r.errors.front().where.line == 1 + line_count(lead));
    }
  });
}

TEST_CASE("transmission: an ETX after the program end is skipped, with line ends after it") {
  each_dialect([](dialect d, const std::string& text, const std::string&) {
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
  each_dialect([](dialect d, const std::string&, const std::string& open) {
    const read_result r = read(d, open + "\x03\n", "p");
    REQUIRE(r.errors.size() == 1);
    CHECK(r.errors[0].to_string() == "p:" + std::to_string(line_count(open) + 1) +
                                         ":1: error: end-of-transmission byte 0x03 before the end of the program");
  });
}

// A comment in each dialect's own spelling, with an ETX inside it (found by fuzzing: the
// comment was read, and written back as a final ETX its own reader refused).
const std::map<std::string_view, std::string> etx_in_comment = {
    {"siemens", "; a\x03~\n"},
    {"heidenhain", "* - a\x03~\n"},
    {"iso", "(a\x03~)\n"},
    {"apt", "PPRINT a\x03~\n"},
};

TEST_CASE("transmission: an ETX inside a comment is refused at its place") {
  for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t) {
    INFO(D::name);
    REQUIRE(etx_in_comment.count(D::name) == 1);
    const std::string& text = ending_program.at(D::name);
    const std::size_t first_line_end = text.find('\n') + 1;
    const std::string program = text.substr(0, first_line_end) + etx_in_comment.at(D::name) + text.substr(first_line_end);
    const read_result r = read(id_of<D>(), program, "p");
    REQUIRE(r.errors.size() == 1);
    const std::size_t column = etx_in_comment.at(D::name).find('\x03') + 1;
    CHECK(r.errors[0].to_string() == "p:2:" + std::to_string(column) +
                                         ": error: end-of-transmission byte 0x03 inside the program (one is allowed only after its end)");
  });
}

TEST_CASE("transmission: text after the ETX is program text, and the ETX in it is refused") {
  each_dialect([](dialect d, const std::string& text, const std::string&) {
    const read_result r = read(d, text + "\x03\nG0 X1\n", "p");
    REQUIRE_FALSE(r.ok());
    CHECK(r.errors[0].where.line == line_count(text) + 1);
  });
}
