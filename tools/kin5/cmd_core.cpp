// Placeholder until the core subcommands land.
#include "commands.hpp"
namespace kin5::tool {
void add_machines_command(CLI::App&, int&) {}
void add_solve_command(CLI::App&, int&) {}
void add_fk_command(CLI::App&, int&) {}
}  // namespace kin5::tool
