// Inch programs, text → model → text: the model holds millimetres (×25.4 exactly for positions,
// arc data and per-minute feeds; inverse-time feeds and angles unchanged), and the writer of an
// inch program says inch and writes the values back in inches. One table per dialect that reads
// inch programs; a unit change after motion is refused.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/io.hpp>

using namespace kin5::program;

namespace {
bool near(std::optional<double> a, double b) { return a && std::abs(*a - b) <= 1e-9 * (1 + std::abs(b)); }

std::vector<std::string> errors_of(dialect d, const std::string& text) {
  std::vector<std::string> out;
  for (const diagnostic& e : read(d, text, "t").errors) out.push_back(e.to_string());
  return out;
}

// Reads `text`, writes it in `d`, reads that again: the two models' blocks agree, text aside.
void round_trip(dialect from, const std::string& text, dialect to, const std::string& written) {
  const read_result first = read(from, text, "t");
  REQUIRE(first.ok());
  const std::string out = write(to, first.parsed);
  CHECK(out == written);
  const read_result again = read(to, out, "t");
  REQUIRE(again.ok());
  REQUIRE(write(to, again.parsed) == out);
}
}  // namespace

TEST_CASE("units: ISO G20 programs are read in millimetres and written back in inches") {
  const std::string text =
      "%\nO1000\nG20 G17\nG0 X1.2345 Y-.5 Z2.\nG1 X2. F9.8\nG2 X3. Y-.5 I.5 J0. F10.\nG93 G1 X4. F2.5\nM30\n%\n";
  const read_result r = read(id_of<iso::dialect>(), text, "t");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 9);
  CHECK(b[2].metric == false);
  CHECK(near(b[3].axes.x_mm, 31.3563));
  CHECK(near(b[3].axes.y_mm, -12.7));
  CHECK(near(b[3].axes.z_mm, 50.8));
  CHECK(near(b[4].feed, 248.92));
  REQUIRE((b[5].arc && b[5].arc->centre_mm));
  CHECK((near(b[5].arc->centre_mm->x, 63.5) && near(b[5].arc->centre_mm->y, -12.7) && near(b[5].arc->centre_mm->z, 50.8)));
  CHECK(near(b[5].feed, 254.0));
  CHECK(near(b[6].feed, 2.5));  // inverse time: 1/min, not a length
  CHECK(near(b[6].axes.x_mm, 101.6));
  round_trip(id_of<iso::dialect>(), text, id_of<iso::dialect>(),
             "%\nO1000\nG17 G20\nG0 X1.2345 Y-0.5 Z2.\nG1 X2. F9.8\nG2 X3. Y-0.5 I0.5 J0. F10.\nG1 G93 X4. F2.5\nM30\n%\n");
}

TEST_CASE("units: APT UNITS/INCHES and FEDRAT/IPM are read in millimetres and written back in inches") {
  const std::string text =
      "PARTNO P\nUNITS/INCHES\nFEDRAT/9.8\nGOTO/1.2345,-.5,2.\nFEDRAT/IPM,10\nFEDRAT/MMPM,254\nGOTO/2,0,0\n"
      "FEDRAT/INVERS,2.5\nGOTO/3,0,0\nFINI\n";
  const read_result r = read(id_of<apt::dialect>(), text, "t");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 10);
  CHECK(b[1].metric == false);
  CHECK(near(b[2].feed, 248.92));
  CHECK(near(b[3].axes.x_mm, 31.3563));
  CHECK(near(b[4].feed, 254.0));
  CHECK(near(b[5].feed, 254.0));
  CHECK(near(b[7].feed, 2.5));
  round_trip(id_of<apt::dialect>(), text, id_of<apt::dialect>(),
             "PARTNO P\nUNITS/INCHES\nFEDRAT/IPM,9.8\nGOTO/1.2345,-0.5,2\nFEDRAT/IPM,10\nFEDRAT/IPM,10\nGOTO/2,0,0\n"
             "FEDRAT/INVERS,2.5\nGOTO/3,0,0\nFINI\n");
  const read_result mm = read(id_of<apt::dialect>(), "UNITS/MM\nFEDRAT/IPM,10\n", "t");
  REQUIRE(mm.ok());
  CHECK(near(mm.parsed.blocks[1].feed, 254.0));
}

TEST_CASE("units: an inch ISO program written as APT stays in inches") {
  round_trip(id_of<iso::dialect>(), "G20\nG1 X1. Y2. Z3. F10.\n", id_of<apt::dialect>(),
             "UNITS/INCHES\nFEDRAT/IPM,10\nGOTO/1,2,3\nFINI\n");
}

TEST_CASE("units: a unit change after motion is refused at the unit word") {
  CHECK(errors_of(id_of<iso::dialect>(), "G21\nG1 X1. F100.\nG20\n") ==
        std::vector<std::string>{"t:3:1: error: G20 after motion: a unit change inside a program is not supported"});
  CHECK(errors_of(id_of<iso::dialect>(), "G20\nG1 X1. F10.\nG20 X2.\n").empty());
}

TEST_CASE("units: Siemens G700 and G70 blocks are read in millimetres, F only under G700") {
  const std::string text =
      "%_N_P_MPF\nN10 G700 G17\nN20 G0 X1.2345 Y-.5 Z2\nN30 G1 X2 F9.8\nN40 G2 X3 Y-.5 I.5 J0 F10\n"
      "N50 G93 G1 X4 F2.5\nN60 G94 G70 X5\nN70 G710 X25.4 F254\nN80 G70 CR=1 G3 X6 Y-.5\nM30\n";
  const read_result r = read(id_of<siemens::dialect>(), text, "t");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 10);
  CHECK(b[1].metric == false);
  CHECK(near(b[2].axes.x_mm, 31.3563));
  CHECK(near(b[2].axes.y_mm, -12.7));
  CHECK(near(b[2].axes.z_mm, 50.8));
  CHECK(near(b[3].feed, 248.92));
  REQUIRE((b[4].arc && b[4].arc->centre_mm));
  CHECK((near(b[4].arc->centre_mm->x, 63.5) && near(b[4].arc->centre_mm->y, -12.7) && near(b[4].arc->centre_mm->z, 50.8)));
  CHECK(near(b[4].feed, 254.0));
  CHECK(near(b[5].feed, 2.5));  // inverse time: 1/min, not a length
  CHECK(near(b[5].axes.x_mm, 101.6));
  CHECK(b[6].metric == false);  // G70: lengths in inches
  CHECK(near(b[6].axes.x_mm, 127.0));
  CHECK(b[7].metric == true);
  CHECK(near(b[7].axes.x_mm, 25.4));
  CHECK(near(b[7].feed, 254.0));
  REQUIRE((b[8].arc && b[8].arc->radius_mm));
  CHECK(near(*b[8].arc->radius_mm, 25.4));  // G70 applies to its own block, written after CR=
  CHECK(near(b[8].axes.x_mm, 152.4));
  // Written back with the forms that also set F's unit: G700 for G70, G710 for G71.
  round_trip(id_of<siemens::dialect>(), text, id_of<siemens::dialect>(),
             "%_N_P_MPF\nN10 G700 G17\nN20 G0 X1.2345 Y-0.5 Z2\nN30 G1 X2 F9.8\nN40 G2 X3 Y-0.5 I0.5 J0 F10\n"
             "N50 G93 G1 X4 F2.5\nN60 G700 G94 X5\nN70 G710 X25.4 F254\nN80 G700 G3 X6 Y-0.5 CR=1\nM30\n");
}

TEST_CASE("units: a Siemens F under G70 is refused: it is in the control's basic system") {
  const std::string why = "F under G70 is in the control's basic unit system, which the program does not say "
                          "(G700 gives F in inch/min)";
  CHECK(errors_of(id_of<siemens::dialect>(), "G70\nG1 X1 F10\n") == std::vector<std::string>{"t:2:7: error: " + why});
  CHECK(errors_of(id_of<siemens::dialect>(), "G1 F10 G70 X1\n") == std::vector<std::string>{"t:1:4: error: " + why});
  CHECK(errors_of(id_of<siemens::dialect>(), "G70\nG93 G1 X1 F2\n").empty());  // inverse time: no unit
  CHECK(errors_of(id_of<siemens::dialect>(), "G700\nG1 X1 F10\nG70 X2\n").empty());
}

TEST_CASE("units: Heidenhain INCH programs are read in millimetres, F in 1/10 inch/min") {
  const std::string text =
      "0 BEGIN PGM P INCH\n1 TOOL CALL 5 Z S6000 F20\n2 L X+1.2345 Y-0.5 Z+2 R0 FMAX\n3 L X+2 F98\n"
      "4 CC X+2.5 Y-0.5\n5 C X+3 Y-0.5 DR- F100\n6 CR X+4 Y-0.5 R+0.5 DR+\n7 END PGM P INCH\n";
  const read_result r = read(id_of<heidenhain::dialect>(), text, "t");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 8);
  CHECK(b[0].metric == false);
  CHECK(near(b[1].feed, 50.8));
  CHECK(near(b[2].axes.x_mm, 31.3563));
  CHECK(near(b[2].axes.y_mm, -12.7));
  CHECK(near(b[2].axes.z_mm, 50.8));
  CHECK(near(b[3].feed, 248.92));  // F98 = 9.8 inch/min
  REQUIRE((b[5].arc && b[5].arc->centre_mm));
  CHECK((near(b[5].arc->centre_mm->x, 63.5) && near(b[5].arc->centre_mm->y, -12.7) && near(b[5].arc->centre_mm->z, 50.8)));
  CHECK(near(b[5].feed, 254.0));
  REQUIRE((b[6].arc && b[6].arc->radius_mm));
  CHECK(near(*b[6].arc->radius_mm, 12.7));
  round_trip(id_of<heidenhain::dialect>(), text, id_of<heidenhain::dialect>(),
             "0 BEGIN PGM P INCH\n1 TOOL CALL 5 Z S6000 F20\n2 L X+1.2345 Y-0.5 Z+2 R0 FMAX\n3 L X+2 F98\n"
             "4 CC X+2.5 Y-0.5\n5 C X+3 Y-0.5 DR- F100\n6 CR X+4 Y-0.5 R+0.5 DR+\n7 END PGM P INCH\n");
  CHECK(errors_of(id_of<heidenhain::dialect>(), "BEGIN PGM P INCH\nEND PGM P MM\n") ==
        std::vector<std::string>{"t:2:11: error: END PGM unit MM differs from BEGIN PGM's INCH"});
}

TEST_CASE("units: inch programs between dialects keep their inch values") {
  // Heidenhain INCH → ISO G20: F98 (1/10 inch/min) is F9.8 inch/min.
  round_trip(id_of<heidenhain::dialect>(), "0 BEGIN PGM P INCH\n1 L X+1.2345 Y-0.5 Z+2 F98\n2 END PGM P INCH\n",
             id_of<iso::dialect>(), "%\nO0001 (P)\nN0 G20\nN1 G1 X1.2345 Y-0.5 Z2. F9.8\nN2 G20 M30\n%\n");
  round_trip(id_of<iso::dialect>(), "G20\nG1 X1.2345 Y2. Z3. F10.\n", id_of<siemens::dialect>(),
             "%_N_PGM_MPF\n;$PATH=/_N_MPF_DIR\nG700\nG1 X1.2345 Y2 Z3 F10\nM30\n");
  // The unit Siemens states after its header is the BEGIN PGM's (program_unit).
  round_trip(id_of<siemens::dialect>(), "%_N_P_MPF\nG700\nG1 X1.2345 Y2 Z3 F10\nM30\n", id_of<heidenhain::dialect>(),
             "0 BEGIN PGM P INCH\n1 ;G700\n2 L X+1.2345 Y+2 Z+3 F100\n3 M30\n4 END PGM P INCH\n");
}

TEST_CASE("units: an inch program without a header of its own is framed BEGIN PGM … INCH") {
  const read_result iso_inch = read(id_of<iso::dialect>(), "G20\nG1 X1. F10.\n", "t");
  REQUIRE(iso_inch.ok());
  CHECK(write(id_of<heidenhain::dialect>(), iso_inch.parsed) ==
        "0 BEGIN PGM PGM INCH\n1 ;G20\n2 L X+1 F100\n3 END PGM PGM INCH\n");
}

namespace {
/// Each move of `blocks`: the point it moves to and its feed, in the model's mm and mm/min.
std::vector<std::vector<double>> moves_mm(const std::vector<block>& blocks) {
  std::vector<std::vector<double>> out;
  double x = 0, y = 0, z = 0, feed = 0;
  for (const block& b : blocks) {
    x = b.axes.x_mm.value_or(x), y = b.axes.y_mm.value_or(y), z = b.axes.z_mm.value_or(z);
    if (b.feed) feed = *b.feed;
    if (b.moves()) out.push_back({x, y, z, feed});
  }
  return out;
}
}  // namespace

// A Siemens program may switch units anywhere (G700 / G710, from its block on); ISO, Haas and
// LinuxCNC take a unit only before the first move, a TNC only in BEGIN PGM. Those writers write
// the whole program in the unit said before the first move, the blocks after a switch converted
// from the model's millimetres (a switch back to that unit is written: it changes nothing), and
// their own readers read back the same moves.
TEST_CASE("units: a Siemens unit switch after motion is written in the program's unit, and reads back") {
  const std::string text = "%_N_P_MPF\nG710\nG1 X1 Y2 Z3 F100\nG700 X2 F10\nG1 Y1.2345 Z0.5\nG710 X20 F254\nM30\n";
  const read_result source = read(id_of<siemens::dialect>(), text, "t");
  REQUIRE(source.ok());
  const auto expected = moves_mm(source.parsed.blocks);
  REQUIRE(expected.size() == 4);
  struct row {
    dialect to;
    std::string written;
  };
  const std::vector<row> table{
      {id_of<iso::dialect>(),
       "%\nO0001 (P)\nG21\nG1 X1. Y2. Z3. F100.\nX50.8 F254.\nG1 Y31.356 Z12.7\nG21 X20. F254.\nM30\n%\n"},
      {id_of<haas::dialect>(),
       "%\nO0001 (P)\nG21\nG1 X1. Y2. Z3. F100.\nX50.8 F254.\nG1 Y31.356 Z12.7\nG21 X20. F254.\nM30\n%\n"},
      {id_of<linuxcnc::dialect>(),
       "%\n(PROGRAM P)\nG21\nG1 X1 Y2 Z3 F100\nX50.8 F254\nG1 Y31.356 Z12.7\nG21 X20 F254\nM30\n%\n"},
      {id_of<heidenhain::dialect>(),
       "0 BEGIN PGM P MM\n1 ;G710\n2 L X+1 Y+2 Z+3 F100\n3 L X+50.8 F254\n4 L Y+31.356 Z+12.7\n"
       "5 L X+20 F254\n6 M30\n7 END PGM P MM\n"},
  };
  for (const row& r : table) {
    INFO("into " << name(r.to));
    const std::string out = write(r.to, source.parsed);
    CHECK(out == r.written);
    const read_result again = read(r.to, out, "t");
    REQUIRE(again.ok());
    const auto moves = moves_mm(again.parsed.blocks);
    REQUIRE(moves.size() == expected.size());
    for (std::size_t k = 0; k < moves.size(); ++k)
      for (std::size_t c = 0; c < 4; ++c) CHECK(std::abs(moves[k][c] - expected[k][c]) <= 0.0005);
  }
  // An inch program switching to mm is written in inches throughout.
  const read_result inch = read(id_of<siemens::dialect>(), "G700\nG1 X1 Y2 Z3 F10\nG710 X25.4 F254\nM30\n", "t");
  REQUIRE(inch.ok());
  const std::string out = write(id_of<iso::dialect>(), inch.parsed);
  CHECK(out == "%\nO0001\nG20\nG1 X1. Y2. Z3. F10.\nX1. F10.\nM30\n%\n");
  REQUIRE(read(id_of<iso::dialect>(), out, "t").ok());
}
