#pragma once
// A named choice: an enum value with the word a case file spells it as, which messages and
// descriptions quote too. Each enum has one table of them (cell_geometry.hpp,
// vessel_profile.hpp, config/case_file_names.hpp): the parser, the writer of the resolved
// case and the case-file reference all read that table.
// Host-only: includes no Kokkos header.
#include <array>
#include <cstddef>

namespace rouleau {

template <class Enum>
struct NamedChoice {
  Enum value;
  const char* name;
};

// The name of `value` in `choices` ("?" for a value the table lacks).
template <class Enum, std::size_t N>
constexpr const char* name_of(const std::array<NamedChoice<Enum>, N>& choices, Enum value) {
  for (const NamedChoice<Enum>& choice : choices)
    if (choice.value == value) return choice.name;
  return "?";
}

}  // namespace rouleau
