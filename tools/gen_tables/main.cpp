// kin5-gen-tables: the matchability tables and maps of docs/tables/, for every ordered pair of
// catalog machines, and the reach cones of every machine — each boundary and gap computed in
// closed form and again with Ipopt (kin5::reach), side by side.
//
//   kin5-gen-tables write DIR                    (re)write every file in DIR
//   kin5-gen-tables check DIR [--shard K/N]      regenerate in memory and compare with DIR
//   kin5-gen-tables check DIR --index            the same for README.md, reach.md, stale files
//   kin5-gen-tables pair --from ID --to ID [--format md|csv|svg|json]   one pair to stdout
//   kin5-gen-tables reach                        the reach cones to stdout
//
// `check` exits 4 when a file differs (words exactly, numbers to --tolerance) or when Ipopt
// and the closed form disagree by more than 1e-6° (cosines at degenerate points).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <kin5/kin5.hpp>
#include <kin5/reach.hpp>
#include <kin5/translate/setup.hpp>

#include "compare.hpp"
#include "pages.hpp"

namespace {

using namespace kin5;
namespace fs = std::filesystem;

/// One generated file: its name in DIR and its text.
struct generated {
  std::string name, text;
};

/// Calls f(from, to, index) for every ordered pair of catalog machines, in catalog order.
template <class F>
void for_each_pair(F&& f) {
  std::size_t index = 0;
  for (const machine_model* from : machines::catalog_models)
    for (const machine_model* to : machines::catalog_models) f(*from, *to, index++);
}

reach::pair_table table_of(const machine_model& from, const machine_model& to, bool with_ipopt) {
  const rigid_transform setup = default_setup(from.geometry.id, to.geometry.id);
  return reach::make_pair_table(from, to, setup, true, with_ipopt);
}

/// Ipopt checks that disagree with the closed form by more than 1e-6°.
std::vector<std::string> disagreements(const reach::pair_table& t) {
  constexpr double tolerance = 1e-6 * pi / 180.0;
  std::vector<std::string> out;
  auto look = [&](const reach::value_check& c) {
    if (!reach::agrees(c, tolerance))
      out.push_back(t.from + " -> " + t.to + ": " + c.what + " closed form " + std::to_string(c.closed * 180 / pi) +
                    " deg, Ipopt " + (c.found ? std::to_string(c.numeric * 180 / pi) : std::string("none")));
  };
  for (const auto& c : t.branch_checks) look(c);
  for (const auto& row : t.checks)
    for (const auto& c : row) look(c);
  return out;
}

std::vector<generated> pair_files(const reach::pair_table& t) {
  const std::string stem = "match-" + t.from + "-to-" + t.to;
  return {{stem + ".md", reach::markdown(t)}, {stem + ".csv", reach::csv(t)}, {stem + ".svg", gen_tables::map_svg(t)}};
}

int write_all(const fs::path& dir) {
  fs::create_directories(dir);
  std::vector<reach::pair_table> tables;
  for_each_pair([&](const machine_model& from, const machine_model& to, std::size_t) {
    tables.push_back(table_of(from, to, true));
  });
  std::vector<generated> files{{"reach.md", gen_tables::reach_page()}, {"README.md", gen_tables::index_page(tables)}};
  for (const auto& t : tables)
    for (auto& f : pair_files(t)) files.push_back(std::move(f));
  for (const auto& f : files) std::ofstream(dir / f.name, std::ios::binary) << f.text;
  std::printf("kin5-gen-tables: wrote %zu files to %s\n", files.size(), dir.string().c_str());
  return 0;
}

/// Compares one generated file with DIR's; prints and counts a difference.
bool same_as_committed(const fs::path& dir, const generated& f, double tolerance) {
  std::ifstream in(dir / f.name, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "%s: missing; run the regen_tables target\n", (dir / f.name).string().c_str());
    return false;
  }
  std::stringstream committed;
  committed << in.rdbuf();
  const auto d = gen_tables::compare(committed.str(), f.text, tolerance);
  if (!d.found) return true;
  std::fprintf(stderr, "%s:%zu: differs from the regenerated text\n  committed:   %s\n  regenerated: %s\n",
               (dir / f.name).string().c_str(), d.line, d.expected.c_str(), d.actual.c_str());
  return false;
}

int check_pairs(const fs::path& dir, std::size_t shard, std::size_t shards, double tolerance) {
  int failures = 0, pairs = 0;
  for_each_pair([&](const machine_model& from, const machine_model& to, std::size_t index) {
    if (index % shards != shard) return;
    ++pairs;
    const auto t = table_of(from, to, true);
    for (const auto& f : pair_files(t)) failures += same_as_committed(dir, f, tolerance) ? 0 : 1;
    for (const auto& d : disagreements(t)) {
      std::fprintf(stderr, "closed form and Ipopt disagree: %s\n", d.c_str());
      ++failures;
    }
  });
  std::printf("kin5-gen-tables: %d pairs checked, %d problems\n", pairs, failures);
  return failures ? 4 : 0;
}

int check_index(const fs::path& dir, double tolerance) {
  std::vector<reach::pair_table> tables;
  std::set<std::string> expected{"README.md", "reach.md"};
  for_each_pair([&](const machine_model& from, const machine_model& to, std::size_t) {
    tables.push_back(table_of(from, to, false));
    for (const auto& ext : {".md", ".csv", ".svg"})
      expected.insert("match-" + std::string(from.geometry.id) + "-to-" + std::string(to.geometry.id) + ext);
  });
  int failures = 0;
  failures += same_as_committed(dir, {"README.md", gen_tables::index_page(tables)}, tolerance) ? 0 : 1;
  failures += same_as_committed(dir, {"reach.md", gen_tables::reach_page()}, tolerance) ? 0 : 1;
  if (!gen_tables::reach_page_agrees()) {
    std::fprintf(stderr, "reach.md: closed form and Ipopt disagree by more than 1e-6 deg\n");
    ++failures;
  }
  for (const auto& entry : fs::directory_iterator(dir))
    if (!expected.count(entry.path().filename().string())) {
      std::fprintf(stderr, "%s: not generated by kin5-gen-tables; remove it\n", entry.path().string().c_str());
      ++failures;
    }
  std::printf("kin5-gen-tables: index checked, %d problems\n", failures);
  return failures ? 4 : 0;
}

int print_pair(const std::string& from, const std::string& to, const std::string& format) {
  bool found = false;
  for_each_pair([&](const machine_model& f, const machine_model& t_model, std::size_t) {
    if (f.geometry.id != from || t_model.geometry.id != to) return;
    found = true;
    const auto t = table_of(f, t_model, true);
    const std::string text = format == "csv" ? reach::csv(t)
                             : format == "svg" ? gen_tables::map_svg(t)
                             : format == "json" ? reach::json(t)
                                                : reach::markdown(t);
    std::fwrite(text.data(), 1, text.size(), stdout);
  });
  if (!found) std::fprintf(stderr, "kin5-gen-tables: no catalog pair %s -> %s\n", from.c_str(), to.c_str());
  return found ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"kin5-gen-tables: matchability tables and maps, closed form beside Ipopt"};
  app.require_subcommand(1);
  std::string dir, from, to, format = "md", shard_text = "0/1";
  bool index = false;
  double tolerance = 1.5e-6;
  auto* write_cmd = app.add_subcommand("write", "write every table, map and index into DIR");
  write_cmd->add_option("dir", dir, "output directory (docs/tables)")->required();
  auto* check_cmd = app.add_subcommand("check", "regenerate in memory and compare with DIR");
  check_cmd->add_option("dir", dir, "directory of committed tables")->required();
  check_cmd->add_option("--shard", shard_text, "check only pairs whose index is K modulo N")->capture_default_str();
  check_cmd->add_flag("--index", index, "check README.md, reach.md and that DIR holds nothing else");
  check_cmd->add_option("--tolerance", tolerance, "largest difference allowed between numbers")->capture_default_str();
  auto* pair_cmd = app.add_subcommand("pair", "one pair's table or map to stdout");
  pair_cmd->add_option("--from", from, "source machine id")->required();
  pair_cmd->add_option("--to", to, "target machine id")->required();
  pair_cmd->add_option("--format", format, "md, csv, svg or json")->check(CLI::IsMember({"md", "csv", "svg", "json"}));
  auto* reach_cmd = app.add_subcommand("reach", "the reach cones of every machine to stdout");
  CLI11_PARSE(app, argc, argv);

  if (write_cmd->parsed()) return write_all(dir);
  if (pair_cmd->parsed()) return print_pair(from, to, format);
  if (reach_cmd->parsed()) {
    const std::string text = gen_tables::reach_page();
    std::fwrite(text.data(), 1, text.size(), stdout);
    return gen_tables::reach_page_agrees() ? 0 : 4;
  }
  if (index) return check_index(dir, tolerance);
  std::size_t shard = 0, shards = 1;
  if (std::sscanf(shard_text.c_str(), "%zu/%zu", &shard, &shards) != 2 || shards == 0 || shard >= shards) {
    std::fprintf(stderr, "kin5-gen-tables: --shard wants K/N with K < N\n");
    return 1;
  }
  return check_pairs(dir, shard, shards, tolerance);
}
