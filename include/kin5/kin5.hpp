/// @file kin5.hpp
/// The core of kin5: units, constexpr maths, axes and machines, forward and inverse kinematics,
/// branch choice, and the machine catalog. Needs the C++20 standard library only.
#pragma once

#include "axis.hpp"
#include "branch.hpp"
#include "feed.hpp"
#include "forward.hpp"
#include "inverse.hpp"
#include "machine.hpp"
#include "machines.hpp"
#include "matchability.hpp"
#include "math.hpp"
#include "rigid.hpp"
#include "setup.hpp"
#include "solver.hpp"
#include "translate.hpp"
#include "units.hpp"
#include "vec.hpp"
#include "version.hpp"
