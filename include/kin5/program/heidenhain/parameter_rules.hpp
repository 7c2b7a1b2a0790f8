/// @file program/heidenhain/parameter_rules.hpp
/// Heidenhain Q parameters for the interpreter (../interp/parameter_store.hpp; TNC 640 User's
/// Manual, "Programming: Q parameters", "Principle and overview"): Q0–Q99, Q200–Q1999 are the
/// program's, global to every program it calls; QL0–QL499 local to one program; QR0–QR499 kept
/// through power-off. Q100–Q199 are set by the control (Q108 the tool radius, Q120–Q122 by
/// PLANE … STAY), the same range the reader refuses (control_q.hpp). Every Q
/// keeps its value from before the program, so reading one the program has not assigned is
/// refused, naming it.
#pragma once

#include "../interp/parameter_store.hpp"
#include "control_q.hpp"

namespace kin5::program::heidenhain {

inline interp::parameter_rules parameter_rules() {
  using interp::parameter_scope;
  interp::parameter_rules r;
  r.numbered = {
      {"Q", 0, first_control_q - 1, parameter_scope::global},
      {"Q", first_control_q, last_control_q, parameter_scope::reserved, false,
       "set by the control (Q100-Q199), not a value of this program"},
      {"Q", last_control_q + 1, 1999, parameter_scope::global},
      {"QL", 0, 499, parameter_scope::local},
      {"QR", 0, 499, parameter_scope::global},
  };
  return r;
}

}  // namespace kin5::program::heidenhain
