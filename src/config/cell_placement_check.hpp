#pragma once
// The check that a case's cells fit: each inside the fluid domain (the box or the vessel's
// lumen) and overlapping no other, on their exact shapes before any meshing.
// Host-only: includes no Kokkos header.
#include "config/case_config.hpp"

namespace rouleau {

// Checks every cell of `config` before any work: its kind exists, it lies inside the
// fluid domain (every surface point inside the box, or the vessel's lumen and, unless
// vessel.allow_squeeze, no wider than its throat), and it does not overlap any other cell
// (no surface point of one inside the other). Throws InputError(config.source_file,
// "cells[I].center_um" / "cells[I].kind", reason naming the other cell) on the first fault.
// (A kind whose sizes make no body is reported with the key "cell_kinds.NAME". Surface
// samples 0.15 μm apart: cells 0.3 μm apart pass, overlaps deeper than about 0.01 μm fail.)
void check_cell_placement(const CaseConfig& config);

}  // namespace rouleau
