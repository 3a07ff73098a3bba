// tessera synth, shared by its translation units: the parsed request, and run_synth_format<T, C>
// (synth_run.hpp), instantiated for the 8-bit PNG formats in cmd_synth_8bit.cpp and for the 16-bit
// ones in cmd_synth_16bit.cpp, so the two halves of the command's heaviest code compile in parallel.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include <tessera/core/executor.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/image/metrics.hpp>
#include <tessera/image/patch_synthesis.hpp>

#include "cli.hpp"

namespace cli::synth {

using tessera::index_t;

/// What `tessera synth` was asked for (parsed and checked by cmd_synth.cpp).
struct request {
  std::string exemplar, out, source_map;
  index_t width = 0, height = 0, patch_w = 0, patch_h = 0, overlap = 0;
  tessera::texture_offset origin;
  tessera::seam_mode seams = tessera::seam_mode::feather;
  std::uint64_t seed = 1;
  int threads = 0, repeat = 1;
  bool stats = false;
};

/// Adds the quality figures of a synthesized crop to `line` (neighborhood_energy, seam_gradient_ratio
/// when there are seams, histogram_distance, repetition for crops of at least 32 pixels), given float
/// copies of the crop and the exemplar: the metrics convert to float themselves, so the figures are
/// those of the original pixels, and they are compiled for 4 channel counts in cmd_synth.cpp instead of
/// for 8 formats. A metric that fails is left out.
template <int C>
void add_quality(json_line& line, const tessera::image_buffer<float, C>& crop,
                 const tessera::image_buffer<float, C>& exemplar, std::span<const tessera::seam_segment> seams,
                 tessera::thread_pool_executor& pool);

/// Loads the exemplar as T x C, synthesizes, writes the outputs and prints; returns the exit code.
template <class T, int C>
int run_format(const arguments& args, const request& r);

}  // namespace cli::synth
