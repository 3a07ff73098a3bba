// tessera/surface/detail/tolerances.hpp: the rounding tolerances shared by several polycube headers,
// named once with what they guard. Tolerances used by one header only live at the top of that header.
#pragma once

#include "../../core/config.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// In tile units: a polycube coordinate within this of a tile-grid line counts as on it (chart
/// rectangles snap to the grid, edge intervals that meet up to rounding are merged).
inline constexpr double tile_grid_rounding = 1e-9;
/// A face whose signed area in its chart plane is at or below this times tile_size^2 counts as
/// flipped or degenerate.
inline constexpr double min_chart_area_fraction = 1e-12;

}  // namespace detail
TESSERA_NAMESPACE_END
