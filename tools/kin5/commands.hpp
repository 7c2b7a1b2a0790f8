// The subcommands of the kin5 tool. Each registers itself on the CLI11 app and returns the
// exit code through `exit_code` once parsed. Exit codes: 0 success, 1 usage, 2 input error,
// 3 unreachable / no solution.
#pragma once

#include <CLI/CLI.hpp>

namespace kin5::tool {

struct exit_codes {
  static constexpr int ok = 0;
  static constexpr int usage = 1;
  static constexpr int input_error = 2;
  static constexpr int unreachable = 3;
};

// Core kinematics (issue: core): machines, solve, fk.
void add_machines_command(CLI::App& app, int& exit_code);
void add_solve_command(CLI::App& app, int& exit_code);
void add_fk_command(CLI::App& app, int& exit_code);
// Programs (issue: NC programs): translate, reverse, post.
void add_program_commands(CLI::App& app, int& exit_code);
// Matchability: a pair's table, a program's report and setup search (needs kin5::reach).
void add_match_command(CLI::App& app, int& exit_code);

}  // namespace kin5::tool
