/// @file program/siemens/parameter_rules.hpp
/// SINUMERIK R parameters and user variables for the interpreter (../interp/parameter_store.hpp;
/// 840D sl Programming Manual Fundamentals, "Arithmetic parameters (R)"; Job Planning, "Local
/// User Data"): R0–R999 are global (the number configured by machine data; 100 by default) and
/// keep their values from earlier programs, so reading one the program has not assigned is
/// refused, naming it. A name is a variable the program declares (`DEF REAL _X=…`, local to its
/// program; a `DEF` without a value gives 0, which the statement layer assigns).
#pragma once

#include <string>

#include "../interp/parameter_store.hpp"

namespace kin5::program::siemens {

inline interp::parameter_rules parameter_rules() {
  using interp::parameter_scope;
  interp::parameter_rules r;
  r.numbered = {{"R", 0, 999, parameter_scope::global}};
  r.named_scope = [](const std::string&) { return parameter_scope::local; };
  return r;
}

}  // namespace kin5::program::siemens
