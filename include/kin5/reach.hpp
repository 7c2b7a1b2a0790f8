/// @file reach.hpp
/// kin5::reach: what a machine reaches and what a pair of machines can exchange. The closed
/// forms (latitude bands, pose regions, sphere maps) and their second derivation with Ipopt
/// (nearest reachable axis, reach cones, boundaries), the tables and maps written from them, and
/// the re-fixturing search. Needs Ipopt (target `kin5::reach`); the core does not include it.
/// How to read the results: docs/matchability.md.
#pragma once

#include "reach/boundary.hpp"
#include "reach/box_minimizer.hpp"
#include "reach/cone.hpp"
#include "reach/latitude.hpp"
#include "reach/nearest_tool_axis.hpp"
#include "reach/pair_check.hpp"
#include "reach/pair_geometry.hpp"
#include "reach/pair_regions.hpp"
#include "reach/pair_table.hpp"
#include "reach/sphere_map.hpp"
#include "reach/sphere_svg.hpp"
#include "reach/table_text.hpp"
