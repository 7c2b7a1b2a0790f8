// Parameters and variables assigned a number and used as word values, one row per spelling and
// dialect, then the same over drawn names and numbers: the text with the parameter reads as the
// same blocks, and writes as the same text, as the text with the number written in its place.
// (Heidenhain's Q parameters: heidenhain_table.cpp; the refusals, with their messages: each
// dialect's errors.txt and tests/bad.)
#include <cctype>
#include <functional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/program/lexing.hpp>
#include <kin5/program/number.hpp>

#include <kin5/program/iso/dialect.hpp>
#include <kin5/program/linuxcnc/dialect.hpp>
#include <kin5/program/siemens/dialect.hpp>

using namespace kin5::program;

namespace {
struct row {
  std::string with_parameter, with_number;
};

using read_fn = std::function<read_result(const std::string&)>;
using write_fn = std::function<std::string(const program&)>;

// How the text `with` a parameter and the text `without` it (the number in its place) differ:
// empty when both read without error to blocks equal apart from their text, written the same.
std::string reading_difference(const std::string& with, const std::string& without, const read_fn& read,
                               const write_fn& write) {
  const read_result a = read(with), b = read(without);
  if (!a.errors.empty()) return "with the parameter: " + a.errors.front().to_string();
  if (!b.errors.empty()) return "with the number: " + b.errors.front().to_string();
  std::vector<block> x = a.parsed.blocks, y = b.parsed.blocks;
  if (x.size() != y.size()) return "block counts differ";
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i].text = y[i].text = "";
    if (!(x[i] == y[i])) return "block " + std::to_string(i) + " differs";
  }
  return write(a.parsed) == write(b.parsed) ? "" : "written texts differ";
}

// Each pair reads and writes alike (`reading_difference`).
void same_reading(const std::vector<row>& rows, const read_fn& read, const write_fn& write) {
  for (const row& r : rows) {
    INFO(r.with_parameter);
    CHECK(reading_difference(r.with_parameter, r.with_number, read, write) == "");
  }
}
}  // namespace

TEST_CASE("iso: a parameter assigned a number reads as the number in the words that use it") {
  const std::vector<row> rows = {
      {"#1 = 1200. (XY FEED)\nG1 X10. F#1\n", "#1 = 1200. (XY FEED)\nG1 X10. F1200.\n"},
      {"N5 #2=-5.25\nG1 X#2 Y-#2 Z+#2\n", "N5 #2=-5.25\nG1 X-5.25 Y5.25 Z-5.25\n"},
      {"#3=30\nG43.4 H1\nG1 X0 A#3 C-#3 F100.\n", "#3=30\nG43.4 H1\nG1 X0 A30. C-30. F100.\n"},
      {"#4=7\nT#4 M6\nG43.4 H#4\n", "#4=7\nT7 M6\nG43.4 H7\n"},
      {"#1=5\nG1 X#1\n#1=6\nG1 X#1\n", "#1=5\nG1 X5.\n#1=6\nG1 X6.\n"},  // the last assignment before the use
      {"#500=12000\nS#500 M3\n", "#500=12000\nS12000 M3\n"},
  };
  same_reading(
      rows, [](const std::string& t) { return iso::read(t, "t.nc"); }, [](const program& p) { return iso::write(p); });
}

TEST_CASE("linuxcnc: a numbered parameter assigned a number reads as the number in the words that use it") {
  const std::vector<row> rows = {
      {"#31 = 800 (FEED)\nG1 X10 F#31\n", "#31 = 800 (FEED)\nG1 X10 F800\n"},
      {"#1=2.5\nG0 X#1 Y-#1 Z25\n", "#1=2.5\nG0 X2.5 Y-2.5 Z25\n"},
      {"#5000=45\nG1 X#5000 F100\n", "#5000=45\nG1 X45 F100\n"},
      {"#<feed> = 800\nG1 X10 F#<feed>\n", "#<feed> = 800\nG1 X10 F800\n"},
      {"#<Z Safe>=2.5\nG0 X#<zsafe> Y-#<ZSAFE> Z25\n", "#<Z Safe>=2.5\nG0 X2.5 Y-2.5 Z25\n"},
      {"#<_clear> = 45\n#<_CLEAR> = 50\nG1 Z#<_clear> F100\n", "#<_clear> = 45\n#<_CLEAR> = 50\nG1 Z50 F100\n"},
      {"#1 = 5\n#<1> = 6\nG1 X#1 Y#<1>\n", "#1 = 5\n#<1> = 6\nG1 X5 Y6\n"},  // a name is not a number
  };
  same_reading(
      rows, [](const std::string& t) { return linuxcnc::read(t, "t.ngc"); },
      [](const program& p) { return linuxcnc::write(p); });
}

TEST_CASE("siemens: an R parameter assigned a number reads as the number in the words that use it") {
  const std::vector<row> rows = {
      {"N10 R1=1200 ; FEED\nN20 G1 X10 F=R1\n", "N10 R1=1200 ; FEED\nN20 G1 X10 F1200\n"},
      {"R2 = -5.25\nG1 X=R2 Y=-R2 Z=+R2\n", "R2 = -5.25\nG1 X-5.25 Y5.25 Z-5.25\n"},
      {"R3=30\nTRAORI\nG1 X0 A=R3 B=-R3 F100\n", "R3=30\nTRAORI\nG1 X0 A30 B-30 F100\n"},
      {"R4=12000\nS=R4 M3\n", "R4=12000\nS12000 M3\n"},
      {"R5=5\nG0 X0 Y0 Z0\nG2 X10 Y0 CR=R5 F100\n", "R5=5\nG0 X0 Y0 Z0\nG2 X10 Y0 CR=5 F100\n"},
      {"R1=5\nG1 X=R1\nR1=6\nG1 X=R1\n", "R1=5\nG1 X5\nR1=6\nG1 X6\n"},
      {"N10 DEF REAL _F_CUT=1850.5, _Z\nN20 G1 Z=_Z F=_F_CUT\n", "N10 DEF REAL _F_CUT=1850.5, _Z\nN20 G1 Z0 F1850.5\n"},
      {"DEF INT _N=3\nDEF REAL Depth=-2.5\nG1 X=DEPTH Y=-depth A=_n\n",
       "DEF INT _N=3\nDEF REAL Depth=-2.5\nG1 X-2.5 Y2.5 A3\n"},
      {"N20 _X_HOME=-365. _Y_HOME=224. R1=3 ; homes\nG1 X=_X_HOME Y=_y_home Z=R1 F=_Y_HOME\n",
       "N20 _X_HOME=-365. _Y_HOME=224. R1=3 ; homes\nG1 X-365. Y224. Z3 F224.\n"},
  };
  same_reading(
      rows, [](const std::string& t) { return siemens::read(t, "t.mpf"); },
      [](const program& p) { return siemens::write(p); });
}

namespace {
/// A drawn name: a letter then letters, digits and underscores (3 to 12 characters).
std::string draw_name() {
  const std::string first = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
  const std::string rest = first + "0123456789_";
  std::string name(1, first[*rc::gen::inRange<std::size_t>(0, first.size())]);
  const int n = *rc::gen::inRange(2, 12);
  for (int k = 0; k < n; ++k) name += rest[*rc::gen::inRange<std::size_t>(0, rest.size())];
  return name;
}

/// A drawn number on the 0.0001 grid, written with its decimals ("-12.5", "3").
std::string draw_number() {
  const long long units = *rc::gen::inRange(-9999999LL, 10000000LL);
  return format_number(static_cast<double>(units) / 1e4, 4);
}
}  // namespace

TEST_CASE("linuxcnc: a drawn named parameter, in any case and with blanks, reads as its number") {
  REQUIRE(rc::check([] {
    const std::string name = draw_name(), value = draw_number();
    // The use spells the name in another case, with a blank inserted: LinuxCNC reads one name.
    std::string use;
    for (char c : name) use += static_cast<char>(std::isupper(static_cast<unsigned char>(c)) ? std::tolower(c) : std::toupper(c));
    use.insert(*rc::gen::inRange<std::size_t>(0, use.size() + 1), " ");
    const std::string set = "#<" + name + "> = " + value + "\n";
    const std::string minus = value[0] == '-' ? value.substr(1) : "-" + value;
    RC_ASSERT(reading_difference(set + "G1 X#<" + use + "> Y-#<" + use + "> F100\n",
                                 set + "G1 X" + value + " Y" + minus + " F100\n",
                                 [](const std::string& t) { return linuxcnc::read(t, "t.ngc"); },
                                 [](const program& p) { return linuxcnc::write(p); }) == "");
  }));
}

TEST_CASE("siemens: a drawn user variable, assigned or declared, reads as its number") {
  REQUIRE(rc::check([] {
    const std::string name = "_" + draw_name(), value = draw_number();
    const bool declared = *rc::gen::arbitrary<bool>();
    const std::string set = declared ? "DEF REAL " + name + "=" + value + "\n" : "N10 " + name + "=" + value + "\n";
    const std::string minus = value[0] == '-' ? value.substr(1) : "-" + value;
    std::string use = lexing::upper(name);
    if (*rc::gen::arbitrary<bool>()) use = name;
    RC_ASSERT(reading_difference(set + "G1 X=" + use + " Y=-" + use + " F100\n",
                                 set + "G1 X" + value + " Y" + minus + " F100\n",
                                 [](const std::string& t) { return siemens::read(t, "t.mpf"); },
                                 [](const program& p) { return siemens::write(p); }) == "");
  }));
}
