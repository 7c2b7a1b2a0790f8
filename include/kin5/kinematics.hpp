/// @file kinematics.hpp
/// The kinematics core of kin5: units, constexpr maths, rigid transforms, axes and machines,
/// forward and inverse kinematics, branch choice, matchability of one pose, and the machine
/// catalog. Needs the C++20 standard library only, and pulls in nothing of programs or
/// translation (a compile test holds it to that). `kin5.hpp` adds programs and translation.
#pragma once

#include "core/math.hpp"
#include "core/rigid.hpp"
#include "core/units.hpp"
#include "core/vec.hpp"
#include "core/version.hpp"
#include "kinematics/axis.hpp"
#include "kinematics/branch.hpp"
#include "kinematics/forward.hpp"
#include "kinematics/inverse.hpp"
#include "kinematics/inverse_pose.hpp"
#include "kinematics/machine.hpp"
#include "kinematics/machine_model.hpp"
#include "kinematics/matchability.hpp"
#include "kinematics/solver.hpp"
#include "machines/catalog.hpp"
