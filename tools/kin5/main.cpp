// kin5: command-line front end. Thin: every subcommand is a few calls into the headers.
#include <exception>
#include <iostream>
#include <new>

#include <kin5/core/version.hpp>

#include "commands.hpp"
#include "output_file.hpp"

int main(int argc, char** argv) {
  kin5::tool::ignore_write_signals();  // a closed pipe or a file-size limit: exit 2, not a death
  CLI::App app{"kin5: 5-axis CNC kinematics and NC program translation between machines"};
  app.set_version_flag("--version", std::string("kin5 ") + kin5::version_string);
  app.require_subcommand(1);
  int exit_code = kin5::tool::exit_codes::ok;
  kin5::tool::add_machines_command(app, exit_code);
  kin5::tool::add_solve_command(app, exit_code);
  kin5::tool::add_fk_command(app, exit_code);
  kin5::tool::add_program_commands(app, exit_code);
  kin5::tool::add_match_command(app, exit_code);
  // A command's failure that no code path turned into a message (memory exhausted, a stream
  // that threw): exit 2 with a message, never std::terminate. Caught here, the stack unwinds,
  // so every output_file is abandoned and no temporary file is left.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help/version (code 0) or the error message
    return code == 0 ? 0 : kin5::tool::exit_codes::usage;
  } catch (const std::bad_alloc&) {
    std::cerr << "kin5: out of memory\n";
    return kin5::tool::exit_codes::input_error;
  } catch (const std::exception& e) {
    std::cerr << "kin5: " << e.what() << "\n";
    return kin5::tool::exit_codes::input_error;
  }
  if (!(std::cout << std::flush)) {
    std::cerr << "kin5: cannot write to stdout\n";
    return kin5::tool::exit_codes::input_error;
  }
  return exit_code;
}
