// --machine ID / --machine-file FILE (machine_option.hpp).
#include "machine_option.hpp"

#include <iostream>

#include <kin5/machines/every_machine.hpp>

#include "commands.hpp"

namespace kin5::tool {

void add_machine_options(CLI::App& sub, machine_choice& choice, std::string_view flag, std::string_view what) {
  choice.flag = std::string(flag);
  const std::string names = flag == "--machine" ? "--machine,-m" : std::string(flag);
  auto* id = sub.add_option(names, choice.id, std::string(what) + ": a bundled machine id (see `kin5 machines`)");
  auto* file = sub.add_option(std::string(flag) + "-file", choice.file,
                              std::string(what) + ": a machine file (TOML, docs/machine-files.md)");
  id->excludes(file);
  file->excludes(id);
}

const machine_model* find_bundled_machine(std::string_view id) {
  const machine_model* found = nullptr;
  kin5::machines::for_each_machine_in<kin5::machines::every_machine>([&]<class M>() {
    if (!found && M::id == id) found = &M::model;
  });
  return found;
}

std::string bundled_machine_ids() {
  std::string out;
  kin5::machines::for_each_machine_in<kin5::machines::every_machine>([&]<class M>() {
    if (!out.empty()) out += ", ";
    out += M::id;
  });
  return out;
}

std::optional<chosen_machine> resolve_machine(const machine_choice& choice, std::string_view command, int& exit_code) {
  if (choice.id.empty() == choice.file.empty()) {
    std::cerr << "kin5 " << command << ": give exactly one of " << choice.flag << " ID and " << choice.flag
              << "-file FILE\n";
    exit_code = exit_codes::usage;
    return std::nullopt;
  }
  if (!choice.file.empty()) {
    machine_file_result r = read_machine_file(choice.file);
    if (!r.ok()) {
      for (const auto& e : r.errors) std::cerr << e.to_string() << '\n';
      exit_code = exit_codes::input_error;
      return std::nullopt;
    }
    return chosen_machine(std::move(*r.machine));
  }
  if (const machine_model* m = find_bundled_machine(choice.id)) return chosen_machine(*m);
  std::cerr << "kin5 " << command << ": unknown machine '" << choice.id << "'; valid ids: " << bundled_machine_ids()
            << "; or give " << choice.flag << "-file FILE\n";
  exit_code = exit_codes::usage;
  return std::nullopt;
}

}  // namespace kin5::tool
