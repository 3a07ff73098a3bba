// tessera/terrain/detail/seam_feather.hpp: where render_terrain_frame blends colours across
// synthesis seams (paper 003, §2.3 step 3). The paper blends a triangle with a neighbour of other
// coordinates "at the shared boundary"; done per triangle, the blend would stop at the triangle's
// far edges, which on screen are only a few pixels away, and leave a step there. So the blend is
// done in image space instead: every pixel within `feather` pixels of a seam (a pixel boundary
// between two regions whose faces share a mesh edge) mixes in the other region's texture with a
// weight falling from 1/2 at the seam to 0 at `feather` pixels, which is continuous everywhere.
// Regions that only meet on screen (a hill in front of a far field) are never blended.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <utility>

#include "../../core/config.hpp"
#include "../prepare_terrain_mesh.hpp"
#include "../assign_scale_field.hpp"
#include "../project_mesh.hpp"
#include "../synthesize_triangles.hpp"
#include "visibility.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

struct seam_partner {
  std::int32_t face = -1;  ///< face whose texture is mixed in (-1: no blending)
  float weight = 0;        ///< its weight
};

/// Boundary pixels are those with a 4-neighbour of another, blendable label; each remembers its own
/// face and the face across. The blend weight of a pixel is 1/2 (1 - d / feather), d the Euclidean
/// distance to the nearest boundary pixel (found exactly within radius ceil(feather) by a row scan
/// and a (2R + 1)-row column search), so both pixels at a boundary mix 50/50.
class seam_feather {
 public:
  template <class E>
  seam_feather(const terrain_mesh& mesh, const screen_projection& proj, const scale_field& field,
               const triangle_synthesis& syn, const visibility_buffer& vb, double feather, E& exec)
      : vb_(vb),
        feather_(feather),
        radius_(std::min<index_t>(64, static_cast<index_t>(std::ceil(feather)))),
        region_(&syn.region),
        level_(&field.level) {
    const index_t w = vb.width, h = vb.height;
    auto label_of = [&](std::int32_t f) {
      return static_cast<std::int64_t>(syn.region[to_size(f)]) * 65536 + field.level[to_size(f)];
    };
    if (feather <= 0) return;
    for (const std::int32_t f : proj.visible)
      for (const std::int32_t n : mesh.neighbors[to_size(f)])
        if (n > f && is_face_index(n, mesh.num_faces()) && proj.state[to_size(n)] != 0 && label_of(n) != label_of(f))
          pairs_.push_back(key(label_of(f), label_of(n)));
    if (pairs_.empty()) return;
    std::sort(pairs_.begin(), pairs_.end());
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
    const auto n = to_size(w * h);
    std::vector<std::int64_t> label(n, -1);
    exec.parallel_for(0, h, [&](index_t y) {
      for (index_t x = 0; x < w; ++x) {
        const std::int32_t f = vb.face[to_size(y * w + x)];
        if (f >= 0) label[to_size(y * w + x)] = label_of(f);
      }
    });
    across_.assign(n, -1);
    row_dx_.assign(n, none);
    exec.parallel_for(0, h, [&](index_t y) {
      const std::int64_t* row = label.data() + y * w;
      for (index_t x = 0; x < w; ++x) {
        const std::int64_t a = row[x];
        if (a < 0) continue;
        const index_t nx[4] = {x + 1, x - 1, x, x}, ny[4] = {y, y, y + 1, y - 1};
        for (int k = 0; k < 4; ++k) {
          if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
          const auto q = to_size(ny[k] * w + nx[k]);
          if (label[q] >= 0 && label[q] != a && blends(a, label[q])) {
            across_[to_size(y * w + x)] = vb.face[q];
            break;
          }
        }
      }
      // nearest boundary pixel in this row within the radius, as a signed dx
      std::int8_t* dx = row_dx_.data() + y * w;
      const std::int32_t* acr = across_.data() + y * w;
      index_t last = -(radius_ + 1);
      for (index_t x = 0; x < w; ++x) {
        if (acr[x] >= 0) last = x;
        if (x - last <= radius_) dx[x] = static_cast<std::int8_t>(last - x);
      }
      last = w + radius_ + 1;
      for (index_t x = w - 1; x >= 0; --x) {
        if (acr[x] >= 0) last = x;
        if (last - x <= radius_ && (dx[x] == none || last - x < -dx[x])) dx[x] = static_cast<std::int8_t>(last - x);
      }
    });
  }

  /// The face to blend into pixel (x, y) and its weight. Thread-safe.
  [[nodiscard]] seam_partner partner(index_t x, index_t y) const noexcept {
    seam_partner p;
    if (row_dx_.empty()) return p;
    const std::int32_t own = vb_.face[to_size(y * vb_.width + x)];
    if (own < 0) return p;
    index_t best = (radius_ + 1) * (radius_ + 1), qx = 0, qy = 0;
    for (index_t dy = -radius_; dy <= radius_; ++dy) {
      const index_t yy = y + dy;
      if (yy < 0 || yy >= vb_.height || dy * dy >= best) continue;
      const std::int8_t dx = row_dx_[to_size(yy * vb_.width + x)];
      if (dx == none) continue;
      const index_t d2 = static_cast<index_t>(dx) * dx + dy * dy;
      if (d2 < best) {
        best = d2;
        qx = x + dx;
        qy = yy;
      }
    }
    if (best > radius_ * radius_) return p;
    const auto q = to_size(qy * vb_.width + qx);
    // the boundary pixel is on this side (its partner is across) or on the other side (it is the partner)
    const std::int32_t qf = vb_.face[q], other = same_label(qf, own) ? across_[q] : qf;
    if (other < 0 || same_label(other, own)) return p;
    p.weight = static_cast<float>(0.5 * std::clamp(1.0 - std::sqrt(static_cast<double>(best)) / feather_, 0.0, 1.0));
    if (p.weight > 0) p.face = other;
    return p;
  }

 private:
  static constexpr std::int8_t none = -128;
  static std::pair<std::int64_t, std::int64_t> key(std::int64_t a, std::int64_t b) noexcept {
    return {std::min(a, b), std::max(a, b)};
  }
  [[nodiscard]] bool blends(std::int64_t a, std::int64_t b) const noexcept {
    return std::binary_search(pairs_.begin(), pairs_.end(), key(a, b));
  }
  [[nodiscard]] bool same_label(std::int32_t f, std::int32_t g) const noexcept {
    return label_of_face(f) == label_of_face(g);
  }
  [[nodiscard]] std::int64_t label_of_face(std::int32_t f) const noexcept {
    return static_cast<std::int64_t>((*region_)[to_size(f)]) * 65536 + (*level_)[to_size(f)];
  }

  const visibility_buffer& vb_;
  double feather_;
  index_t radius_;
  const std::vector<std::int32_t>* region_ = nullptr;
  const std::vector<std::int32_t>* level_ = nullptr;
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs_;
  std::vector<std::int32_t> across_;  ///< per pixel: the face across a boundary, or -1
  std::vector<std::int8_t> row_dx_;   ///< per pixel: dx to the nearest boundary pixel in its row, or none
};

}  // namespace detail

TESSERA_NAMESPACE_END
