// Choosing a machine on the command line: `--machine ID` (a bundled machine) or
// `--machine-file FILE` (a machine file, docs/machine-files.md), exactly one of them. Any
// command can register the pair under its own names (translate: --from/--from-file,
// --to/--to-file) and resolve it to a `machine_model`, the value every kinematic function takes.
//
//   machine_choice from;
//   add_machine_options(*sub, from, "--from", "Source machine");
//   ...
//   std::optional<chosen_machine> m = resolve_machine(from, "translate", exit_code);
//   if (!m) return exit_code;      // the message is already on stderr
//   use(m->model());
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include <kin5/kinematics/machine_model.hpp>
#include <kin5/machines/machine_file.hpp>

namespace kin5::tool {

/// What the user gave: an id, a file, or (an error) both or neither.
struct machine_choice {
  std::string id;
  std::string file;
  std::string flag = "--machine";  ///< the id option's name, for messages
};

/// Registers `flag ID` and `flag-file FILE` on `sub`, exactly one of them required.
void add_machine_options(CLI::App& sub, machine_choice& choice, std::string_view flag = "--machine",
                         std::string_view what = "Machine");

/// A resolved machine: a bundled one (static storage) or one read from a file (owned).
class chosen_machine {
 public:
  explicit chosen_machine(const machine_model& bundled) : bundled_(&bundled) {}
  explicit chosen_machine(loaded_machine file) : file_(std::move(file)) {}
  const machine_model& model() const { return bundled_ ? *bundled_ : file_->model(); }

 private:
  const machine_model* bundled_ = nullptr;
  std::optional<loaded_machine> file_;
};

/// The bundled machine with this id, or null.
const machine_model* find_bundled_machine(std::string_view id);

/// The ids of every bundled machine, "a, b, c".
std::string bundled_machine_ids();

/// The machine `choice` names. On failure writes the message(s) to stderr ("kin5 COMMAND: …" for
/// an unknown id, "FILE:LINE:COL: error: …" per mistake in a file), sets `exit_code` (1 for
/// usage, 2 for a bad file) and returns nothing.
std::optional<chosen_machine> resolve_machine(const machine_choice& choice, std::string_view command, int& exit_code);

}  // namespace kin5::tool
