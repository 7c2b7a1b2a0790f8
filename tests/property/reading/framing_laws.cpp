// Program framing and the program end between every ordered pair of dialects. A generated ISO
// program (`%`, `O` number, moves, `M30`, comment lines after it, `%`) is read, written in the
// source dialect and read back there (the source program), then written in the target dialect.
// The target text must open and close with the target's own frame exactly once (ISO `%`, `O…`
// … `%`; LinuxCNC `%` … `%`; Siemens `%_N_…_MPF`, `;$PATH=/_N_MPF_DIR`; Heidenhain BEGIN PGM …
// END PGM), never with a copy of another's (`(%)`, `; %`), and, read back by the target's
// reader, have no block with an effect after its end and one end only. A table then checks the
// other half of the rule (program/program_end.hpp): a block with an effect after the source's
// end is refused by every writer of another dialect, naming its line and the end's. A last table
// gives each writer a program whose source gives no end: it is closed once, by the target's end.
#include <cstddef>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/program/io.hpp>
#include <kin5/program/program_end.hpp>

#include "dialect_pairs.hpp"

using namespace kin5::program;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    out.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

std::size_t count_matching(const std::vector<std::string>& lines, const std::regex& r) {
  std::size_t n = 0;
  for (const std::string& l : lines) n += std::regex_match(l, r) ? 1 : 0;
  return n;
}

/// A framed ISO program (`%`, `O` and four digits, as a FANUC control writes it): moves, M30,
/// comment lines after it, `%`.
std::string draw_iso_text() {
  const std::string number = std::to_string(*rc::gen::inRange(1, 10000));
  std::string text = "%\nO" + std::string(4 - number.size(), '0') + number + "\nG90 G94 G21\n";
  const int n = *rc::gen::inRange(1, 10);
  for (int k = 0; k < n; ++k) text += "G1 X" + std::to_string(k + 1) + ". Y2.5 Z10. F500.\n";
  text += "M30\n";
  const int comments = *rc::gen::inRange(0, 3);
  for (int k = 0; k < comments; ++k) text += "(done " + std::to_string(k) + ")\n";
  return text + "%\n";
}

/// The frame dialect `d` opens and closes a program with, as whole-line patterns with the number
/// of lines each must match; none for APT (CL data have no frame).
struct frame {
  std::string first, second, last;  // "" when the dialect says nothing there
  std::vector<std::pair<std::string, std::size_t>> counts;
};

frame frame_of(dialect d) {
  const std::string n(name(d));
  if (n == "iso" || n == "haas") return {"%", "O[0-9]{4}( \\(.*\\))?", "%", {{"%", 2}, {"O[0-9]+.*", 1}, {".*\\(%\\).*", 0}}};
  if (n == "linuxcnc") return {"%", "", "%", {{"%", 2}, {".*\\(%\\).*", 0}}};
  if (n == "siemens")
    return {"%_N_[A-Za-z_][A-Za-z][A-Za-z0-9_]{0,22}_MPF", ";\\$PATH=/_N_MPF_DIR", "",
            {{"%.*", 1}, {";\\$PATH=.*", 1}, {";\\s*%.*", 0}}};
  if (n == "heidenhain")
    return {"0 BEGIN PGM [^ ]+ MM", "", "[0-9]+ END PGM [^ ]+ MM", {{".*BEGIN PGM.*", 1}, {".*END PGM.*", 1}, {".*;%.*", 0}}};
  return {"", "", "", {{".*%.*", 0}}};
}

/// Whether `text` opens and closes with `f` (see `frame`).
void check_frame(const std::string& text, const frame& f) {
  const std::vector<std::string> lines = lines_of(text);
  RC_ASSERT(lines.size() >= 2u);
  if (!f.first.empty()) RC_ASSERT(std::regex_match(lines[0], std::regex(f.first)));
  if (!f.second.empty()) RC_ASSERT(std::regex_match(lines[1], std::regex(f.second)));
  if (!f.last.empty()) RC_ASSERT(std::regex_match(lines.back(), std::regex(f.last)));
  for (const auto& [pattern, n] : f.counts) RC_ASSERT(count_matching(lines, std::regex(pattern)) == n);
}

/// Whether `blocks` have one program end (`program_end`; Heidenhain's M30 line counts as the run's
/// end, its END PGM as the text's) and nothing with an effect after the first.
void check_end(const std::vector<block>& blocks) {
  std::size_t ends = 0, m_ends = 0;
  bool ended = false;
  for (const block& b : blocks) {
    if (ended) RC_ASSERT(without_effect(b));
    ended = ended || ends_program(b);
    ends += b.program_end ? 1 : 0;
    for (int m : b.m_codes) m_ends += m == 2 || m == 30 ? 1 : 0;
  }
  RC_ASSERT(ended);
  RC_ASSERT(ends == 1u);
  RC_ASSERT(m_ends <= 1u);
}

}  // namespace

TEST_CASE("framing: every ordered pair of dialects frames its output once and ends it once") {
  using kin5::test::all_dialects;
  kin5::test::check_each_pair(all_dialects(), all_dialects(), [](dialect from, dialect to) {
    const read_result iso = read(id_of<iso::dialect>(), draw_iso_text(), "gen.nc");
    RC_ASSERT(iso.ok());
    const read_result source = read(from, write(from, iso.parsed), "source");
    RC_ASSERT(source.ok());
    const std::string target = write(to, source.parsed);
    check_frame(target, frame_of(to));
    const read_result back = read(to, target, "back");
    RC_ASSERT(back.ok());
    check_end(back.parsed.blocks);
    for (const block& b : iso.parsed.blocks)  // the comments after the end are kept
      if (b.comment) RC_ASSERT(target.find(*b.comment) != std::string::npos);
  });
}

TEST_CASE("framing: a block with an effect after the source's end is refused by every other writer") {
  struct row {
    std::string source, text;
    std::string refusal;  // what every writer of another dialect says
  };
  const std::vector<row> rows{
      {"iso", "%\nO1\nG1 X1. Y2. Z3. F100.\nM30\n(done)\nG0 X5.\n%\n",
       "src:6: block after the program end (line 4): the source control never runs it"},
      {"siemens", "%_N_P_MPF\n;$PATH=/_N_MPF_DIR\nG1 X1 Y2 Z3 F100\nM30\n; done\nM5 M2\n",
       "src:6: block after the program end (line 4): the source control never runs it"},
      {"heidenhain", "0 BEGIN PGM P MM\n1 L X+1 Y+2 Z+3 F100 M30\n2 ;done\n3 L Z+50 FMAX\n4 END PGM P MM\n",
       "src:4: block after the program end (line 2): the source control never runs it"},
      {"haas", "%\nO01000\nG1 X1. Y2. Z3. F100.\nM30\nG0 Z50.\n%\n",
       "src:5: block after the program end (line 4): the source control never runs it"},
      {"linuxcnc", "%\nG1 X1 Y2 Z3 F100\nM2\nG0 Z50\n%\n",
       "src:4: block after the program end (line 3): the source control never runs it"},
      {"apt", "PARTNO P\nFEDRAT/MMPM,100\nGOTO/1,2,3\nFINI\nGOTO/1,2,50\n",
       "src:5: block after the program end (line 4): the source control never runs it"},
  };
  for (const row& r : rows) {
    const dialect from = *parse_dialect(r.source);
    const read_result in = read(from, r.text, "src");
    INFO(r.source);
    REQUIRE(in.ok());
    CHECK_NOTHROW(write(from, in.parsed));  // its own dialect writes it as read
    for (std::size_t j = 0; j < dialect_count; ++j) {
      const dialect to{j};
      if (to == from) continue;
      INFO(name(to));
      try {
        write(to, in.parsed);
        FAIL("written");
      } catch (const std::invalid_argument& e) {
        CHECK(std::string(e.what()) == r.refusal);
      }
    }
  }
}

TEST_CASE("framing: a source that gives no end is ended once, as each target ends a program") {
  // ISO, Haas and LinuxCNC files may stop at their closing `%` without M2/M30 (the control ends
  // there). Each other writer closes such a program with its own end, written by hand here: ISO
  // and Haas `M30` then `%`, Siemens `M30`, Heidenhain `END PGM`, APT `FINI`, LinuxCNC the
  // closing `%` (a LinuxCNC file ends at it).
  const std::vector<std::pair<std::string, std::string>> sources{
      {"iso", "%\nO1\nG90 G94 G21\nG1 X1. Y2.5 Z10. F500.\n(done)\n%\n"},
      {"haas", "%\nO01000\nG90 G94 G21\nG1 X1. Y2.5 Z10. F500.\n(done)\n%\n"},
      {"linuxcnc", "%\nG90 G94 G21\nG1 X1 Y2.5 Z10 F500\n(done)\n%\n"}};
  const std::vector<std::pair<std::string, std::regex>> last_lines{
      {"iso", std::regex("[\\s\\S]*\nM30\n%\n")},
      {"haas", std::regex("[\\s\\S]*\nM30\n%\n")},
      {"siemens", std::regex("[\\s\\S]*\nM30\n")},
      {"heidenhain", std::regex("[\\s\\S]*\n[0-9]+ END PGM [^\n]+ MM\n")},
      {"apt", std::regex("[\\s\\S]*\nFINI\n")},
      {"linuxcnc", std::regex("[\\s\\S]*\n%\n")}};
  for (const auto& [source, text] : sources) {
    const dialect from = *parse_dialect(source);
    const read_result in = read(from, text, "src");
    INFO(source);
    REQUIRE(in.ok());
    for (const auto& [target, pattern] : last_lines) {
      const dialect to = *parse_dialect(target);
      if (to == from) continue;
      INFO(target);
      const std::string out = write(to, in.parsed);
      CHECK(std::regex_match(out, pattern));
      const read_result back = read(to, out, "back");
      REQUIRE(back.ok());
      std::size_t ends = 0;
      for (const block& b : back.parsed.blocks) ends += ends_program(b) ? 1 : 0;
      CHECK(ends == (to == id_of<linuxcnc::dialect>() ? 0u : 1u));  // LinuxCNC: its `%` ends the file
    }
  }
}
