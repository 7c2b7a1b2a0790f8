// Lines: `for_each_line` splits any text as a byte-by-byte reading of its rule does — a line
// ends at LF, CR or CRLF (one ending), a final ending starts no empty line — with 1-based line
// numbers, and each line a view into the text.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/text.hpp>

namespace {

using kin5::program::text_line;

/// The rule, byte by byte: the lines of `text` as (offset, length, number).
std::vector<std::vector<std::size_t>> lines_by_bytes(std::string_view text) {
  std::vector<std::vector<std::size_t>> lines;
  std::size_t start = 0, number = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || text[i] == '\r') {
      lines.push_back({start, i - start, number++});
      if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  if (start < text.size()) lines.push_back({start, text.size() - start, number});
  return lines;
}

}  // namespace

TEST_CASE("for_each_line: lines end at LF, CR or CRLF, as read byte by byte") {
  rc::prop("texts of line endings, NULs and other bytes", [] {
    // Every piece as likely at any size (inRange alone favours the first ones on small sizes).
    static const std::vector<std::string> pieces{"\n", "\r", "\r\n", "\n\r", "a", "G1 X1.5", std::string(1, '\0'), " ", "\xff"};
    const auto piece = rc::gen::resize(100, rc::gen::inRange<std::size_t>(0, pieces.size()));
    std::string text;
    for (std::size_t k : *rc::gen::container<std::vector<std::size_t>>(piece)) text += pieces[k];
    std::vector<std::vector<std::size_t>> lines;
    kin5::program::for_each_line(text, [&](const text_line& line) {
      lines.push_back({static_cast<std::size_t>(line.text.data() - text.data()), line.text.size(), line.number});
    });
    RC_ASSERT(lines == lines_by_bytes(text));
  });
  std::size_t count = 0;
  kin5::program::for_each_line(std::string(100000, '\r'), [&](const text_line&) { ++count; });
  CHECK(count == 100000);
}
