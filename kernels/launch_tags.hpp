#pragma once
// Launch tags shared by the force kernels: the forces alone (launched with parallel_for),
// or the forces and their energy (parallel_reduce into a double), so that the energy
// costs nothing when it is not asked for.
namespace rouleau {

struct ForcesOnly {};
struct ForcesAndEnergy {};

}  // namespace rouleau
