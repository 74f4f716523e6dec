#pragma once
//! Numeric constants shared across meshquilt.

#include <numbers>

namespace meshquilt {

inline constexpr double kPi = std::numbers::pi;

}  // namespace meshquilt
