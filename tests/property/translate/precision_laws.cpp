// Output precision (translate/precision.hpp): the output keeps the source's decimals, never
// writes finer than the output controller reads, and --digits overrides both. Checked on the
// text the streaming driver writes, read back with the output dialect's own reader.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kin5.hpp>

#include "generators.hpp"

namespace {

using namespace kin5;
using program::dialect;

/// `v` rounded to `decimals` decimals.
double rounded(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

/// A Siemens program for the SAJO 12000P: T1 M6, TRAORI, then motions at `tips` with A and B written
/// with 3 decimals and X Y Z with `decimals`, then M30.
std::string siemens_text(const std::vector<vec3>& tips, int decimals) {
  std::string text = "N5 T1 M6\nN10 TRAORI\n";
  int n = 20;
  for (const vec3& t : tips) {
    text += "N" + std::to_string(n) + " G1 X" + translate_detail::fixed(t.x, decimals) + " Y" +
            translate_detail::fixed(t.y, decimals) + " Z" + translate_detail::fixed(t.z, decimals) +
            " A-30.125 B12.5 F500\n";
    n += 10;
  }
  return text + "N" + std::to_string(n) + " M30\n";
}

/// The translation of `text` (Siemens, sajo-12000p) to the same machine in dialect `out`,
/// written by the streaming driver; the output text, read back.
struct written {
  std::string text;
  program::read_result read;
  translation result;
};
written translate_text(const std::string& text, dialect out, std::optional<int> digits = std::nullopt) {
  translate_options options;
  options.output_dialect = out;
  options.common.digits = digits;
  const auto t = make_translator<machines::sajo_12000p, machines::sajo_12000p>(program::id_of<program::siemens::dialect>(), "p.mpf", options);
  written w;
  string_sink sink;
  const auto run = stream_text(*t, text, program::id_of<program::siemens::dialect>(), "p.mpf", out, sink);
  if (!run.ok(*t)) throw std::runtime_error("translation failed");
  w.text = sink.text;
  w.result = t->result();
  w.read = program::read(out, w.text, "out");
  return w;
}

constexpr dialect nc_dialects[] = {program::id_of<program::siemens::dialect>(), program::id_of<program::heidenhain::dialect>(), program::id_of<program::iso::dialect>()};

}  // namespace

TEST_CASE("the output keeps the source's decimals, finer than the output controller reads is refused") {
  rc::prop("X Y Z with 0 to 7 decimals, sajo-12000p to itself, every NC dialect", [] {
    const int decimals = *rc::gen::inRange(0, 8);
    const dialect out = *rc::gen::elementOf(std::vector<dialect>(std::begin(nc_dialects), std::end(nc_dialects)));
    const auto tips = *rc::gen::container<std::vector<vec3>>(*rc::gen::inRange<std::size_t>(1, 6), test::tip());
    const int finest = program::controller_of(out).finest.linear;
    if (decimals > finest) {  // rounding would move the machine: refused, naming --digits, nothing written
      const auto t = make_translator<machines::sajo_12000p, machines::sajo_12000p>(program::id_of<program::siemens::dialect>(), "p.mpf",
                                                                                  [out] {
                                                                                    translate_options o;
                                                                                    o.output_dialect = out;
                                                                                    return o;
                                                                                  }());
      string_sink sink;
      const auto run = stream_text(*t, siemens_text(tips, decimals), program::id_of<program::siemens::dialect>(), "p.mpf", out, sink);
      RC_ASSERT(!run.ok(*t));
      RC_ASSERT(sink.text.empty());
      RC_ASSERT(t->result().errors.size() == 1u);
      RC_ASSERT(t->result().errors[0].option == "--digits");
      RC_ASSERT(t->result().errors[0].message.find("positions with " + std::to_string(decimals) + " decimals") !=
                std::string::npos);
      return;
    }
    const auto w = translate_text(siemens_text(tips, decimals), out);
    RC_ASSERT(w.read.ok());
    const int expected = std::max(decimals, 3);
    // Every position is the source's, exactly: it has no more decimals than the controller reads.
    std::size_t k = 0;
    for (const auto& b : w.read.parsed.blocks) {
      if (!b.axes.x_mm) continue;
      RC_ASSERT(k < tips.size());
      const vec3 source{rounded(tips[k].x, decimals), rounded(tips[k].y, decimals), rounded(tips[k].z, decimals)};
      RC_ASSERT(std::abs(*b.axes.x_mm - source.x) < 1e-9);
      RC_ASSERT(std::abs(*b.axes.y_mm - source.y) < 1e-9);
      RC_ASSERT(std::abs(*b.axes.z_mm - source.z) < 1e-9);
      ++k;
    }
    RC_ASSERT(k == tips.size());
    RC_ASSERT(w.result.output_decimals.linear == expected);
    // Never finer than the controller reads.
    const auto written_resolution = program::scan_resolution(w.text, out);
    RC_ASSERT(written_resolution.linear_decimals.value_or(0) <= finest);
    RC_ASSERT(written_resolution.angle_decimals.value_or(0) <= program::controller_of(out).finest.angle);
  });
}

TEST_CASE("the option --digits sets the decimals of positions and angles, whatever the source and the dialect, and says what it rounds") {
  rc::prop("digits 0 to 6", [] {
    const int digits = *rc::gen::inRange(0, 7);
    const dialect out = *rc::gen::elementOf(std::vector<dialect>(std::begin(nc_dialects), std::end(nc_dialects)));
    const auto tips = *rc::gen::container<std::vector<vec3>>(*rc::gen::inRange<std::size_t>(1, 6), test::tip());
    const std::string text = siemens_text(tips, 6);
    const auto w = translate_text(text, out, digits);
    RC_ASSERT(w.read.ok());
    RC_ASSERT(w.result.output_decimals.linear == digits);
    RC_ASSERT(w.result.output_decimals.angle == digits);
    // Fewer decimals than the source writes are said, never done silently (--digits 0 moved a
    // 3-decimal position by up to 0.5 mm without a word).
    const auto source = program::scan_resolution(text, program::id_of<program::siemens::dialect>());
    const bool rounds = digits < source.linear_decimals.value_or(0) || digits < source.angle_decimals.value_or(0);
    bool warned = false;
    for (const auto& d : w.result.warnings) warned = warned || d.message.find("--digits") != std::string::npos;
    RC_ASSERT(warned == rounds);
    const auto r = program::scan_resolution(w.text, out);
    RC_ASSERT(r.linear_decimals.value_or(0) <= digits);
    RC_ASSERT(r.angle_decimals.value_or(0) <= digits);
    std::size_t k = 0;
    for (const auto& b : w.read.parsed.blocks)
      if (b.axes.x_mm) {  // the source's value on the grid of `digits` decimals (ties either way)
        const double scaled = *b.axes.x_mm * std::pow(10.0, digits);
        RC_ASSERT(std::abs(scaled - std::round(scaled)) < 1e-6);
        RC_ASSERT(std::abs(*b.axes.x_mm - rounded(tips[k++].x, 6)) <= 0.5 * std::pow(10.0, -digits) + 1e-9);
      }
  });
}

TEST_CASE("CL data posted: the vectors' resolution sets the angles', to the controller's resolution") {
  // GOTO vectors with 7 decimals: 1e-7 rad is 5.7e-6 deg, so 6 decimals of a degree; the TNC
  // reads 4 (and the run says so), Siemens 6.
  const std::string cl = "PARTNO P\nUNITS/MM\nFEDRAT/MMPM,500.0\nGOTO/0.0,0.0,10.0,0.1234567,0.0,0.9923567\n"
                         "GOTO/10.0,0.0,10.0,0.2345678,0.0,0.9720996\nFINI\n";
  for (const auto& [out, angle] : {std::pair{program::id_of<program::heidenhain::dialect>(), 4}, std::pair{program::id_of<program::siemens::dialect>(), 6}}) {
    const auto t = make_post<machines::dmu_80p>(program::id_of<program::apt::dialect>(), out, "p.cl");
    string_sink sink;
    const auto run = stream_text(*t, cl, program::id_of<program::apt::dialect>(), "p.cl", out, sink);
    const std::string& text = sink.text;
    REQUIRE(run.ok(*t));
    CHECK(t->result().output_decimals.angle == angle);
    bool warned = false;
    for (const auto& d : t->result().warnings) warned = warned || d.message.find("angles with 6 decimals") != std::string::npos;
    CHECK(warned == (angle < 6));
    CHECK(program::scan_resolution(text, out).angle_decimals.value_or(0) <= angle);
  }
}
