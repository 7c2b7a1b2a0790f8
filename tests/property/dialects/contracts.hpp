/// @file contracts.hpp
/// Every dialect's contract (contract.hpp), one per folder: the dialect laws and the fuzz targets
/// see them all. The build generates the includes from the folders
/// (cmake/kin5_dialect_contracts.cmake), so a new dialect's folder needs no line here; laws.cpp
/// fails to compile for a dialect of `program::dialects` that has no folder.
#pragma once

#include "kin5_dialect_contracts.hpp"
