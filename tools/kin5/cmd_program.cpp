// Placeholder until the program subcommands land.
#include "commands.hpp"
namespace kin5::tool {
void add_program_commands(CLI::App&, int&) {}
}  // namespace kin5::tool
