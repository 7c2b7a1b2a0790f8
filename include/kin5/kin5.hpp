/// @file kin5.hpp
/// Everything in kin5 that needs only the C++20 standard library: the kinematics core
/// (`kinematics.hpp`) and the whole-program branch plan, NC and CL programs (readers, writers,
/// modal state) and the translation between machines, in memory and streamed over a file's text.
/// Not included: the translation by machine id (`translate/by_id.hpp`, opt-in: it instantiates
/// every pair of catalog machines), Eigen interop (`eigen.hpp`) and the Ipopt reach analysis
/// (`reach.hpp`), which have targets of their own.
#pragma once

#include "kinematics.hpp"
#include "kinematics/branch_plan.hpp"
#include "program/io.hpp"
#include "translate/feed.hpp"
#include "translate/setup.hpp"
#include "translate/stream.hpp"
#include "translate/run_report.hpp"
#include "translate/translate.hpp"
