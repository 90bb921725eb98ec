#pragma once
// The resolved case: every key of a case with the value a run uses, as a TOML file.
// Host-only: includes no Kokkos header.
#include <string>

#include "config/case_config.hpp"

namespace rouleau {

// The case as TOML text in file units, every key written (defaults included), so that
// load_case() of the text gives an identical CaseConfig (source_file aside). A trailing
// [derived] table (scales, Reynolds number, the Stokes decision and its reason) documents
// what was derived; it is output-only and load_case() ignores it.
std::string resolved_case_toml(const CaseConfig& config, const DerivedQuantities& derived);

}  // namespace rouleau
