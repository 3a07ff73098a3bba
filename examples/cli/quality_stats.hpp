// The likeness figures of geometry/texture_quality.hpp in a --stats line (mesh-quilt, geo-wang build,
// geo-wang tile): the output against its exemplar.
#pragma once

#include <string>

#include <tessera/geometry/texture_quality.hpp>

#include "cli.hpp"

namespace cli {

/// Adds the comparison's figures to `line` (rates as fractions; band/corner only with a tile grid).
inline void add_quality(json_line& line, const tessera::texture_quality_comparison& c, bool tiled) {
  line.add("density_ratio", c.density_ratio)
      .add("coverage_ratio", c.coverage_ratio)
      .add("partial_rate", c.output.partial_rate)
      .add("exemplar_partial_rate", c.exemplar.partial_rate)
      .add("empty_cell_rate", c.output.empty_cell_rate)
      .add("exemplar_empty_cell_rate", c.exemplar.empty_cell_rate)
      .add("nn_median_ratio", c.reference.nn_median > 0 ? c.output.nn_median / c.reference.nn_median : 0.0)
      .add("nn_outside", c.output.nn_outside)
      .add("exemplar_nn_outside", c.exemplar.nn_outside);
  if (tiled) line.add("band_ratio", c.band_ratio).add("corner_ratio", c.corner_ratio);
  std::string h = "[";
  for (std::size_t i = 0; i < c.output.nn_histogram.size(); ++i) {
    if (i) h += ',';  // appended one at a time: GCC 12 at -O3 warns (-Wrestrict) on "," + to_string(...)
    h += std::to_string(c.output.nn_histogram[i]);
  }
  line.raw("nn_histogram", h + "]");
}

}  // namespace cli
