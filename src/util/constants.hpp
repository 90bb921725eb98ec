#pragma once
// Constants that several files need, defined once (C++17 has no std::numbers).
#include <array>

namespace rouleau {

inline constexpr double pi = 3.14159265358979323846;

// The axes' names in messages: axis_names[0] is "x".
inline constexpr std::array<const char*, 3> axis_names{"x", "y", "z"};

}  // namespace rouleau
