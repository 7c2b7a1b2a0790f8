// The one-scan reader of plain motion lines (`detail::read_plain_motion`) says exactly what the
// full word-by-word reader (`detail::line_reader::read_words`) says: on lines of N, G0-G3, axis
// and F words, written well or badly (lower case, words twice, signs, points, exponents, letters
// run together, stray text), after any modal motion, either it declines or both give the same
// block and the same modal state, and the full reader finds no problem.
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/siemens/dialect.hpp>

namespace {

using namespace kin5::program;
namespace sd = kin5::program::siemens::detail;

/// A number as programs write it (`-34.983`, `450.`, `.5`, `+5`, `-0`, `17`).
rc::Gen<std::string> number_text() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::inRange(-200000, 200000),
                   [](int v) { return (v < 0 ? "-" : "") + std::to_string(std::abs(v) / 1000) + "." + std::to_string(std::abs(v) % 1000); }),
      rc::gen::map(rc::gen::inRange(0, 100), [](int v) { return std::to_string(v); }),
      rc::gen::element<std::string>("0", "1.", ".5", "-.5", "+5", "-0", "4.5", "17", "999999999"));
}

/// A word for `letter`, nearly always well formed.
std::string clean_word(char letter) {
  // Mostly valid values; some that only the full reader may judge (N1.5, G4, F-1).
  if (letter == 'N') return "N" + *rc::gen::element<std::string>("0", "10", "7", "1999990", "00042", "1.5");
  if (letter == 'G') return "G" + *rc::gen::element<std::string>("0", "1", "0", "1", "2", "3", "00", "01", "1.", "+1", "4");
  if (letter == 'F') return "F" + *rc::gen::element<std::string>("1000", "250.5", "0", "-0", ".5", "-1");
  return std::string(1, letter) + *number_text();
}

/// Mostly well-formed plain motion lines; a third of them spoilt in one way.
rc::Gen<std::string> line() {
  return rc::gen::exec([] {
    std::vector<std::string> words;
    for (char letter : {'N', 'G', 'X', 'Y', 'Z', 'A', 'B', 'C', 'F'})
      if (*rc::gen::element(true, true, false)) words.push_back(clean_word(letter));  // uniform at any size
    if (words.empty()) words.push_back(clean_word('X'));
    if (*rc::gen::arbitrary<bool>()) std::swap(words.front(), words.back());
    std::string tail;
    switch (*rc::gen::element(0, 1, 2, 3, 4, 5, 6, 7, 8)) {
      case 0: words.push_back(words.front()); break;                          // a word twice
      case 1: words.back()[0] = static_cast<char>(words.back()[0] + 32); break;  // lower case
      case 2:  // a word the one-scan reader leaves to the full one
        words.push_back(*rc::gen::element<std::string>("M3", "I1", "S100", "G17", "X", "X1e5", "X1.2.3", "N1.5",
                                                        "F-1", "X99999999999", "X-", "G4.5"));
        break;
      case 3: tail = *rc::gen::element<std::string>(";c", "(c)", "=", "TRAORI", "$", "X=1"); break;
      default: break;
    }
    const bool run_together = *rc::gen::element(true, false, false, false, false, false);
    std::string s = *rc::gen::element<std::string>("", " ", "  ");
    for (const auto& w : words) s += w + (run_together ? "" : *rc::gen::element<std::string>(" ", "\t", "  "));
    return s + tail;
  });
}

}  // namespace

TEST_CASE("siemens: plain motion lines read in one scan as the full reader reads them") {
  rc::prop("any line of motion-like words, after any modal motion", [] {
    const std::string text = *line();
    sd::modal_state before;
    before.motion = *rc::gen::element(std::optional<motion_kind>{}, std::optional{motion_kind::rapid},
                                      std::optional{motion_kind::linear}, std::optional{motion_kind::arc_cw});
    if (*rc::gen::arbitrary<bool>()) before.position_mm = {1.0, 2.0, 3.0};

    block fast;
    fast.where = {"p.mpf", 7, 1};
    fast.text = text;
    sd::modal_state fast_state = before;
    const bool taken = sd::read_plain_motion(text, fast, fast_state);
    RC_CLASSIFY(taken, "read in one scan");
    if (!taken) {
      RC_ASSERT(fast_state.motion == before.motion);
      RC_ASSERT(fast_state.position_mm == before.position_mm);
      return;
    }
    block full;
    full.where = {"p.mpf", 7, 1};
    full.text = text;
    kin5::program::interp::parameter_store store{kin5::program::siemens::parameter_rules()};
    sd::line_reader reader("p.mpf", store);
    reader.state() = before;
    read_result diagnostics;
    full = reader.read_words(text_line{text, 7}, std::move(full), diagnostics);
    const sd::modal_state& full_state = reader.state();
    RC_ASSERT(diagnostics.errors.empty());
    RC_ASSERT(diagnostics.warnings.empty());
    RC_ASSERT(full == fast);
    RC_ASSERT(full_state.motion == fast_state.motion);
    RC_ASSERT(full_state.position_mm == fast_state.position_mm);
  });
}
