#pragma once
// Explicit instantiation of rouleau's class templates over execution spaces:
// ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(Template) instantiates Template<Space> for the
// device space in a device build (the host spaces cannot reach its memory), and for every
// host backend otherwise (so the tests can compare them).
#include <Kokkos_Core.hpp>

#if defined(KOKKOS_ENABLE_CUDA)
#define ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(Template) template class Template<Kokkos::Cuda>;
#elif defined(KOKKOS_ENABLE_HIP) && KOKKOS_VERSION >= 40000
#define ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(Template) template class Template<Kokkos::HIP>;
#elif defined(KOKKOS_ENABLE_HIP)  // Kokkos 3.x: HIP was still Experimental
#define ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(Template) template class Template<Kokkos::Experimental::HIP>;
#else
#if defined(KOKKOS_ENABLE_SERIAL)
#define ROULEAU_INSTANTIATE_FOR_SERIAL(Template) template class Template<Kokkos::Serial>;
#else
#define ROULEAU_INSTANTIATE_FOR_SERIAL(Template)
#endif
#if defined(KOKKOS_ENABLE_OPENMP)
#define ROULEAU_INSTANTIATE_FOR_OPENMP(Template) template class Template<Kokkos::OpenMP>;
#else
#define ROULEAU_INSTANTIATE_FOR_OPENMP(Template)
#endif
#if defined(KOKKOS_ENABLE_THREADS)
#define ROULEAU_INSTANTIATE_FOR_THREADS(Template) template class Template<Kokkos::Threads>;
#else
#define ROULEAU_INSTANTIATE_FOR_THREADS(Template)
#endif
#define ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(Template) \
  ROULEAU_INSTANTIATE_FOR_SERIAL(Template)                 \
  ROULEAU_INSTANTIATE_FOR_OPENMP(Template)                 \
  ROULEAU_INSTANTIATE_FOR_THREADS(Template)
#endif
