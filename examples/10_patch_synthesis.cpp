// Patch synthesis (paper 002): from small exemplars to large textures, with the patch-size analysis
// that picks the patch and overlap, and feathering against minimum-error seam cuts.
//
// Writes into the output directory (default: the current directory):
//   10_<kind>.png              exemplar (left) and a 320 x 256 synthesized texture (right), per kind
//   10_bricks_feather_cut.png  bricks: the paper's feathering (left) and seam cuts (right), enlarged 2x
//   10_{bricks,grass}_{containment,periodicity,alignment}.png
//                              the patch-size measures over candidate shapes (heat maps, see docs)
// and prints the chosen sizes, the quality figures and the measures as a table.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include <tessera/core/executor.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/metrics.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_size.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/io/png.hpp>

namespace {

using tessera::index_t;
using rgb8 = tessera::image_buffer<std::uint8_t, 3>;

/// Copies `src` into `dst` at (x0, y0), each pixel as a `scale` x `scale` block.
void paste(rgb8& dst, const rgb8& src, index_t x0, index_t y0, index_t scale = 1) {
  for (index_t y = 0; y < src.height() * scale; ++y)
    for (index_t x = 0; x < src.width() * scale; ++x) dst.write(x0 + x, y0 + y, src.read(x / scale, y / scale));
}

/// Exemplar and result side by side on a white background.
rgb8 side_by_side(const rgb8& a, const rgb8& b, index_t scale = 1) {
  const index_t gap = 8;
  rgb8 out((a.width() + b.width()) * scale + gap, std::max(a.height(), b.height()) * scale, {255, 255, 255});
  paste(out, a, 0, 0, scale);
  paste(out, b, a.width() * scale + gap, 0, scale);
  return out;
}

/// A heat map of one measure over the candidate shapes (width to the right, height down), 24 pixels a
/// cell, dark blue (low) to yellow (high); the chosen shape framed in white.
rgb8 heat_map(const tessera::patch_size_analysis& a, double (*value)(const tessera::patch_size_measure&)) {
  std::vector<index_t> ws, hs;
  for (const auto& m : a.sizes) {
    if (std::find(ws.begin(), ws.end(), m.width) == ws.end()) ws.push_back(m.width);
    if (std::find(hs.begin(), hs.end(), m.height) == hs.end()) hs.push_back(m.height);
  }
  double lo = 1e300, hi = -1e300;
  for (const auto& m : a.sizes) lo = std::min(lo, value(m)), hi = std::max(hi, value(m));
  const index_t cell = 24;
  rgb8 out(static_cast<index_t>(ws.size()) * cell, static_cast<index_t>(hs.size()) * cell);
  for (const auto& m : a.sizes) {
    const index_t cx = std::find(ws.begin(), ws.end(), m.width) - ws.begin(),
                  cy = std::find(hs.begin(), hs.end(), m.height) - hs.begin();
    const double t = hi > lo ? (value(m) - lo) / (hi - lo) : 0.5;
    const tessera::pixel<std::uint8_t, 3> c{static_cast<std::uint8_t>(30 + 225 * t),
                                            static_cast<std::uint8_t>(40 + 190 * t),
                                            static_cast<std::uint8_t>(120 - 90 * t)};
    const bool chosen = m.width == a.patch_width && m.height == a.patch_height;
    for (index_t y = 0; y < cell; ++y)
      for (index_t x = 0; x < cell; ++x) {
        const bool frame = chosen && (x < 2 || y < 2 || x >= cell - 2 || y >= cell - 2);
        out.write(cx * cell + x, cy * cell + y, frame ? tessera::pixel<std::uint8_t, 3>{255, 255, 255} : c);
      }
  }
  return out;
}

int fail(const tessera::status& s) {
  std::fprintf(stderr, "10_patch_synthesis: %s\n", s.to_string().c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  tessera::thread_pool_executor pool;
  std::printf("%-7s %9s %7s %10s %9s %8s %10s\n", "kind", "patch", "overlap", "energy", "seams", "hist", "repetition");
  for (tessera::exemplar_kind kind : tessera::all_exemplar_kinds) {
    const std::string name(tessera::to_string(kind));
    auto ex = tessera::make_exemplar<std::uint8_t, 3>(kind, {.width = 128, .height = 128});
    if (!ex) return fail(ex.error());
    // preprocessing: size analysis, patches at every phase, compatible sets (keep the model around)
    auto model = tessera::build_patch_model(*ex, {}, pool);
    if (!model) return fail(model.error());
    rgb8 out(320, 256);
    auto stats = tessera::synthesize(*model, out, {.seed = 7}, pool);
    if (!stats) return fail(stats.error());
    if (auto s = tessera::write_png(dir + "/10_" + name + ".png", side_by_side(*ex, out)); !s) return fail(s);

    const double energy = tessera::neighborhood_energy(out, *ex, {.window = 5, .sample_step = 3}, pool).value_or(-1);
    const auto lines = tessera::patch_seam_lines(*model, out.width(), out.height());
    const double seams = tessera::seam_gradient_ratio(out, lines, *ex).value_or(-1);
    const double hist = tessera::histogram_distance(out, *ex).value_or(-1);
    const double rep = tessera::repetition_score(out, 16).value_or(-1);
    std::printf("%-7s %4td x %-3td %7td %10.4f %9.2f %8.3f %10.2f\n", name.c_str(), model->patch_width(),
                model->patch_height(), model->overlap(), energy, seams, hist, rep);

    const auto& a = *model->analysis();
    auto map = [&](const char* what, double (*f)(const tessera::patch_size_measure&)) {
      return tessera::write_png(dir + "/10_" + name + "_" + what + ".png", heat_map(a, f));
    };
    if (kind == tessera::exemplar_kind::bricks || kind == tessera::exemplar_kind::grass) {
      if (auto s = map("containment", [](const tessera::patch_size_measure& m) { return m.containment; }); !s)
        return fail(s);
      if (auto s = map("periodicity", [](const tessera::patch_size_measure& m) { return m.periodicity; }); !s)
        return fail(s);
      if (auto s = map("alignment", [](const tessera::patch_size_measure& m) { return m.alignment; }); !s)
        return fail(s);
      std::printf(
          "  square candidates of %s: side, containment (share within tolerance / p90), periodicity (mean count / "
          "hits), alignment\n",
          name.c_str());
      for (const auto& m : a.sizes)
        if (m.width == m.height)
          std::printf("    %3td  %.2f / %.2f   %6.1f / %.2f   %5.2f%s\n", m.width, m.containment, m.containment_p90,
                      m.periodicity, m.periodicity_hits, m.alignment,
                      m.width == a.patch_width && m.height == a.patch_height ? "  <- chosen" : "");
      std::printf("  overlap discrimination:");
      for (const auto& o : a.overlaps) std::printf(" %td:%.2f", o.overlap, o.discrimination);
      std::printf("  -> %td\n", a.overlap);
    }
  }

  // feathering (paper 002) against minimum-error seams (its named improvement) on a structured texture
  auto bricks = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::bricks, {.width = 128, .height = 128});
  if (!bricks) return fail(bricks.error());
  auto model =
      tessera::build_patch_model(*bricks, {.patch_width = 40, .patch_height = 40, .overlap = 12, .seams = true}, pool);
  if (!model) return fail(model.error());
  rgb8 feather(160, 160), cut(160, 160);
  if (auto s = tessera::synthesize(*model, feather, {.seed = 3}, pool); !s) return fail(s.error());
  if (auto s = tessera::synthesize(*model, cut, {.seed = 3, .seams = tessera::seam_mode::cut}, pool); !s)
    return fail(s.error());
  if (auto s = tessera::write_png(dir + "/10_bricks_feather_cut.png", side_by_side(feather, cut, 2)); !s)
    return fail(s);
  std::printf("bricks 40 x 40, overlap 12: neighbourhood energy feather %.4f, cut %.4f\n",
              tessera::neighborhood_energy(feather, *bricks).value_or(-1),
              tessera::neighborhood_energy(cut, *bricks).value_or(-1));
  std::printf(
      "wrote %s/10_<kind>.png, 10_bricks_feather_cut.png and "
      "10_{bricks,grass}_{containment,periodicity,alignment}.png\n",
      dir.c_str());
  return 0;
}
