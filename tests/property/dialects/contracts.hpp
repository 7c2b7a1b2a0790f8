/// @file contracts.hpp
/// Every dialect's contract (contract.hpp), one include per folder: the dialect laws and the fuzz
/// targets see them all. laws.cpp fails to compile for a dialect of `program::dialects` whose
/// folder is missing here.
#pragma once

#include "apt/contract.hpp"
#include "heidenhain/contract.hpp"
#include "iso/contract.hpp"
#include "siemens/contract.hpp"
