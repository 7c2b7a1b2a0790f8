// translate/run_report.hpp: unreachable blocks grouped into runs of consecutive motion blocks,
// checked against runs found another way (maximal stretches of a list of flags), on made-up
// reports and on real translations whose unreachable blocks are known in advance; and every
// block of a run accounted for (block_accounting), against what each line was made to be.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/io.hpp>
#include <kin5/translate/run_report.hpp>
#include <kin5/translate/stream.hpp>
#include <kin5/translate/translate.hpp>

using namespace kin5;

namespace {

/// One motion block of a made-up run: its line, whether the target reaches it, its gap and excess.
struct motion {
  std::size_t line = 0;
  bool unreachable = false;
  int gap_tenths_deg = 0;
  int excess_tenths_mm = 0;
};

/// The maximal stretches of unreachable blocks of `m`, each as [first, last] indexes into `m`.
std::vector<std::pair<std::size_t, std::size_t>> stretches(const std::vector<motion>& m) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const bool starts = m[i].unreachable && (i == 0 || !m[i - 1].unreachable);
    if (!starts) continue;
    std::size_t j = i;
    while (j + 1 < m.size() && m[j + 1].unreachable) ++j;
    out.emplace_back(i, j);
  }
  return out;
}

/// The index of the worst block of m[first..last]: the first with the largest gap, or, when no
/// gap is above 0, the first with the largest excess.
std::size_t worst_of(const std::vector<motion>& m, std::size_t first, std::size_t last) {
  const auto begin = m.begin() + static_cast<std::ptrdiff_t>(first), end = m.begin() + static_cast<std::ptrdiff_t>(last) + 1;
  auto by_gap = std::max_element(begin, end, [](const motion& a, const motion& b) { return a.gap_tenths_deg < b.gap_tenths_deg; });
  if (by_gap->gap_tenths_deg > 0) return static_cast<std::size_t>(by_gap - m.begin());
  auto by_excess =
      std::max_element(begin, end, [](const motion& a, const motion& b) { return a.excess_tenths_mm < b.excess_tenths_mm; });
  return static_cast<std::size_t>(by_excess - m.begin());
}

/// A SAJO 12000P -> DMU 80P translator of Siemens text into Siemens, keeping the exceptions only.
auto sajo_to_dmu_in_siemens() {
  const auto siemens = program::id_of<program::siemens::dialect>();
  translate_options options;
  options.output_dialect = siemens;
  return make_translator<machines::sajo_12000p, machines::dmu_80p>(siemens, "p.mpf", options,
                                                                   report_detail::exceptions_only);
}

/// The runs found by the library are the stretches of `m`: same count, first and last lines,
/// block counts, worst block and its gap.
void check_runs(const std::vector<unreachable_range>& ranges, const std::vector<motion>& m) {
  const auto expected = stretches(m);
  RC_ASSERT(ranges.size() == expected.size());
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const auto [first, last] = expected[k];
    RC_ASSERT(ranges[k].first.line == m[first].line);
    RC_ASSERT(ranges[k].last.line == m[last].line);
    RC_ASSERT(ranges[k].blocks == last - first + 1);
    const std::size_t worst = worst_of(m, first, last);
    RC_ASSERT(ranges[k].worst.line == m[worst].line);
    RC_ASSERT(std::abs(ranges[k].worst_gap.value - m[worst].gap_tenths_deg / 10.0) < 1e-6);
  }
}

}  // namespace

TEST_CASE("unreachable runs are the maximal stretches of consecutive unreachable motion blocks") {
  rc::prop("made-up reports, as a translation keeps them (the exceptions only)", [] {
    const auto n = *rc::gen::inRange<std::size_t>(0, 60);
    std::vector<motion> m;
    std::size_t line = 1;
    for (std::size_t i = 0; i < n; ++i) {
      line += *rc::gen::inRange<std::size_t>(1, 4);  // other blocks between motion blocks
      const bool unreachable = *rc::gen::inRange(0, 3) > 0;
      const bool by_slide = *rc::gen::inRange(0, 4) == 0;
      m.push_back({line, unreachable, unreachable && !by_slide ? *rc::gen::inRange(0, 20) : 0,
                   unreachable ? *rc::gen::inRange(0, 20) : 0});
    }
    std::vector<block_report> reports;
    for (std::size_t i = 0; i < m.size(); ++i) {
      const bool other_branch = !m[i].unreachable && *rc::gen::inRange(0, 3) == 0;
      if (!m[i].unreachable && !other_branch) continue;  // direct: not kept
      block_report r;
      r.where = {"p.mpf", m[i].line, 1};
      r.match = m[i].unreachable ? matchability::unreachable : matchability::other_branch;
      r.gap = to_radians(degrees{m[i].gap_tenths_deg / 10.0});
      r.linear_excess_mm = m[i].excess_tenths_mm / 10.0;
      r.why = "block " + std::to_string(i);
      r.ordinal = i;
      reports.push_back(r);
    }
    const auto ranges = unreachable_ranges(reports);
    check_runs(ranges, m);
    const auto expected = stretches(m);
    for (std::size_t k = 0; k < ranges.size(); ++k) {
      const auto [first, last] = expected[k];
      RC_ASSERT(ranges[k].worst_why == "block " + std::to_string(worst_of(m, first, last)));
      int gap = 0, excess = 0;
      for (std::size_t i = first; i <= last; ++i)
        gap = std::max(gap, m[i].gap_tenths_deg), excess = std::max(excess, m[i].excess_tenths_mm);
      RC_ASSERT(std::abs(ranges[k].worst_gap.value - gap / 10.0) < 1e-9);
      RC_ASSERT(ranges[k].worst_excess_mm == excess / 10.0);
    }
  });

  rc::prop("SAJO 12000P programs on the DMU 80P: A > 0 is out of reach by A (docs/matchability.md)", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 40);
    std::string text = "N10 G17 G90 G94\nN20 TRAORI\n";
    std::size_t line = 2;
    std::vector<motion> m;
    for (std::size_t i = 0; i < n; ++i) {
      if (*rc::gen::inRange(0, 4) == 0) text += "; between\n", ++line;  // does not split a run
      const bool unreachable = *rc::gen::inRange(0, 3) > 0;
      const int a = unreachable ? *rc::gen::inRange(1, 30) : *rc::gen::element(-45, -30, -20);
      text += "G1 X" + std::to_string(i) + " Y0 Z50 A" + std::to_string(a) + " B30" + (i == 0 ? " F1000\n" : "\n");
      m.push_back({++line, unreachable, unreachable ? a * 10 : 0, 0});
    }
    text += "N90 TRAFOOF\nN100 M30\n";
    const auto siemens = program::id_of<program::siemens::dialect>();
    const auto t = sajo_to_dmu_in_siemens();
    string_sink out;
    (void)stream_text(*t, text, siemens, "p.mpf", siemens, out);
    check_runs(unreachable_ranges(t->result().reports), m);
  });
}

TEST_CASE("every block is counted once: translated, comment only or refused, as each line was made") {
  rc::prop("SAJO 12000P programs on the DMU 80P with comments, bad words, words the source lacks, unreachable poses", [] {
    enum kind { reachable, comment, unreachable, lacks_axis, bad_word };
    const auto kinds = *rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 5));
    const bool with_bad = *rc::gen::arbitrary<bool>();
    std::string text = "N10 G17 G90 G94\nN20 TRAORI\nG1 X0 Y0 Z50 A-45 B30 F1000\n";
    std::size_t read = 5, comments = 0, bad = 0, refused = 0;  // 5: the lines around
    for (int k : kinds) {
      ++read;
      if (k == bad_word && !with_bad) k = reachable;
      switch (k) {
        case reachable: text += "G1 X1 Y0 Z50 A-30 B30\n"; break;
        case comment: text += "; a comment\n", ++comments; break;
        case unreachable: text += "G1 X2 Y0 Z50 A12 B30\n", ++refused; break;
        case lacks_axis: text += "G1 X3 Y0 Z50 A-30 B30 C10\n", ++refused; break;
        default: text += "G1 X4 YY2\n", ++bad; break;
      }
    }
    text += "N90 TRAFOOF\nN100 M30\n";
    const auto siemens = program::id_of<program::siemens::dialect>();
    const auto t = sajo_to_dmu_in_siemens();
    string_sink out;
    block_accounting blocks;
    const auto run = stream_text(*t, text, siemens, "p.mpf", siemens, out, blocks.watch());
    const block_counts c = account_of(t->result(), run, blocks, "dmu-80p").blocks;
    RC_ASSERT(c.read == read);
    RC_ASSERT(c.read == c.translated + c.comment_only + c.refused);
    RC_ASSERT(c.comment_only == comments);
    RC_ASSERT(c.refused == (bad > 0 ? bad : refused));  // read errors: nothing else counts
  });
}
