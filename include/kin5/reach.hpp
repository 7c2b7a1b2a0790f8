/// @file reach.hpp
/// kin5::reach: reach limits and per-block feasibility computed numerically with Ipopt, the
/// independent check of the closed-form reach (G5) and the matchability regions (docs/matchability.md).
/// Needs Ipopt (target `kin5::reach`); the core does not include this header.
#pragma once

#include "reach/boundary.hpp"
#include "reach/box_minimizer.hpp"
#include "reach/cone.hpp"
#include "reach/nearest_tool_axis.hpp"
