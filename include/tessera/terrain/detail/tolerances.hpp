// tessera/terrain/detail/tolerances.hpp: the rounding tolerances shared by several terrain headers
// (the scale pyramid, the scale field, the session and the frame renderers), named once with what
// they guard. Tolerances used by one header only live at the top of that header.
#pragma once

#include "../../core/config.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Relative slack when one computed scale (or distance) is checked against another that went
/// through a different rounding path (logs, powers, float storage): the pyramid's min_scale against
/// the session's or the scale field's, the smallest near_distance against itself.
inline constexpr double scale_match_slack = 1e-9;
/// Subtracted from a ratio before std::ceil turns it into a level count, so a ratio that is an
/// integer up to rounding does not gain a level.
inline constexpr double level_count_rounding = 1e-9;
/// A pyramid position (level of detail) this close to an integer level samples that level alone
/// instead of blending with the next one (a stepped scale field matched to the pyramid, scales
/// stored as float).
inline constexpr double single_level_snap = 1e-3;
/// Relative slack of the float lower bound on a face's scale (scales are stored as float).
inline constexpr float float_scale_slack = 1e-6f;

}  // namespace detail
TESSERA_NAMESPACE_END
