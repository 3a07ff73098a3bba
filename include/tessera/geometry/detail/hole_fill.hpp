// tessera/geometry/detail/hole_fill.hpp: where single elements still fit after mesh quilting (an
// extension of paper 000 §3.3: the patch loop places whole exemplar patches, and an exemplar element
// that collides with what stands is dropped, leaving holes). A raster of the XY plane records what the
// elements' projections cover; its distance transform gives, for every free pixel, the radius of the
// largest empty disc centred there; the local maxima of that distance are the holes' centres, largest
// first. The quilt engine (quilt_engine.hpp) places an exemplar element whose footprint fits into each.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "../mesh_elements.hpp"
#include "xy_raster.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

/// Pixels of side `h` over [x0, x0 + w h] x [y0, y0 + rows h]; a pixel is covered when its centre
/// lies in the XY projection of some triangle (or a vertex lies in the pixel: thin slivers count).
class coverage_raster {
 public:
  explicit coverage_raster(const xy_raster& r)
      : grid_(r),
        x0_(r.window.x0),
        y0_(r.window.y0),
        h_(r.px),
        w_(static_cast<index_t>(r.nx)),
        rows_(static_cast<index_t>(r.ny)),
        covered_(r.nx * r.ny, 0) {}
  coverage_raster(double x0, double y0, double h, index_t w, index_t rows)
      : coverage_raster(xy_raster{{x0, y0, x0 + double(w) * h, y0 + double(rows) * h}, h, to_size(w), to_size(rows)}) {}

  [[nodiscard]] index_t width() const noexcept { return w_; }
  [[nodiscard]] index_t height() const noexcept { return rows_; }
  [[nodiscard]] bool covered(index_t i, index_t j) const noexcept { return covered_[to_size(j * w_ + i)] != 0; }
  void cover(index_t i, index_t j) noexcept {
    if (i >= 0 && j >= 0 && i < w_ && j < rows_) set(i, j);
  }
  /// Counts the covered pixels whose centres lie in `r` from now on (those covered already included).
  void count_in(const xy_rect& r) {
    ci0_ = std::max<index_t>(0, pixel_of_unit(std::ceil((r.x0 - x0_) / h_ - 0.5)));
    cj0_ = std::max<index_t>(0, pixel_of_unit(std::ceil((r.y0 - y0_) / h_ - 0.5)));
    ci1_ = std::min<index_t>(w_ - 1, pixel_of_unit(std::floor((r.x1 - x0_) / h_ - 0.5)));
    cj1_ = std::min<index_t>(rows_ - 1, pixel_of_unit(std::floor((r.y1 - y0_) / h_ - 0.5)));
    counted_ = 0;
    for (index_t j = cj0_; j <= cj1_; ++j)
      for (index_t i = ci0_; i <= ci1_; ++i) counted_ += covered(i, j);
  }
  /// Covered share of the pixels count_in() counts (0 before it is called).
  [[nodiscard]] double counted_share() const noexcept {
    const double n = static_cast<double>(std::max<index_t>(0, ci1_ - ci0_ + 1)) *
                     static_cast<double>(std::max<index_t>(0, cj1_ - cj0_ + 1));
    return n > 0 ? static_cast<double>(counted_) / n : 0.0;
  }
  /// Centre of pixel (i, j) in the plane.
  [[nodiscard]] vec3 centre(index_t i, index_t j) const noexcept {
    return {x0_ + (static_cast<double>(i) + 0.5) * h_, y0_ + (static_cast<double>(j) + 0.5) * h_, 0};
  }

  /// Covers the pixels of `m`'s XY projection; `owner` >= 0 is recorded in those no other owner holds.
  void add_mesh(const tri_mesh& m, index_t owner = -1) {
    if (owner >= 0 && owners_.empty()) owners_.assign(covered_.size(), -1);
    auto mark = [&](index_t i, index_t j) {
      if (i < 0 || j < 0 || i >= w_ || j >= rows_) return;
      set(i, j);
      if (owner >= 0 && owners_[to_size(j * w_ + i)] < 0) owners_[to_size(j * w_ + i)] = owner;
    };
    for (const vec3& p : m.positions) mark(pixel_of(p.x - x0_), pixel_of(p.y - y0_));
    for_each_covered_pixel(
        m, grid_, [&](std::size_t i, std::size_t j) { mark(static_cast<index_t>(i), static_cast<index_t>(j)); });
  }
  /// The owner recorded at pixel (i, j) (-1: none, or off the raster).
  [[nodiscard]] index_t owner(index_t i, index_t j) const noexcept {
    if (owners_.empty() || i < 0 || j < 0 || i >= w_ || j >= rows_) return -1;
    return owners_[to_size(j * w_ + i)];
  }
  /// Uncovers the pixels within `b` (XY) that `owner` holds (an element moved away).
  void remove_owner(index_t owner, const aabb& b) {
    if (owners_.empty()) return;
    const index_t i0 = std::max<index_t>(0, pixel_of(b.min.x - x0_) - 1),
                  i1 = std::min<index_t>(w_ - 1, pixel_of(b.max.x - x0_) + 1),
                  j0 = std::max<index_t>(0, pixel_of(b.min.y - y0_) - 1),
                  j1 = std::min<index_t>(rows_ - 1, pixel_of(b.max.y - y0_) + 1);
    for (index_t j = j0; j <= j1; ++j)
      for (index_t i = i0; i <= i1; ++i)
        if (owners_[to_size(j * w_ + i)] == owner) {
          owners_[to_size(j * w_ + i)] = -1;
          if (covered_[to_size(j * w_ + i)] != 0 && i >= ci0_ && i <= ci1_ && j >= cj0_ && j <= cj1_) --counted_;
          covered_[to_size(j * w_ + i)] = 0;
        }
  }
  /// True when a pixel within `r` of `p` (XY) is held by an owner other than those `ignore` accepts.
  template <class Ignore>
  [[nodiscard]] bool owned_near(vec3 p, double r, Ignore&& ignore) const {
    const double fx = (p.x - x0_) / h_, fy = (p.y - y0_) / h_, rr = r / h_;
    for (index_t j = pixel_of_unit(fy - rr); j <= pixel_of_unit(fy + rr); ++j)
      for (index_t i = pixel_of_unit(fx - rr); i <= pixel_of_unit(fx + rr); ++i) {
        const double dx = static_cast<double>(i) + 0.5 - fx, dy = static_cast<double>(j) + 0.5 - fy;
        const index_t o = owner(i, j);
        if (o >= 0 && dx * dx + dy * dy <= rr * rr && !ignore(o)) return true;
      }
    return false;
  }

  /// True when no covered pixel's centre lies in the square of half-side `a` about `c` (XY) and the
  /// square stays on the raster.
  [[nodiscard]] bool square_free(vec3 c, double a) const {
    const double fx = (c.x - x0_) / h_, fy = (c.y - y0_) / h_, aa = a / h_;
    const index_t i0 = pixel_of_unit(std::ceil(fx - aa - 0.5)), i1 = pixel_of_unit(std::floor(fx + aa - 0.5)),
                  j0 = pixel_of_unit(std::ceil(fy - aa - 0.5)), j1 = pixel_of_unit(std::floor(fy + aa - 0.5));
    if (i0 < 0 || j0 < 0 || i1 >= w_ || j1 >= rows_) return false;
    for (index_t j = j0; j <= j1; ++j)
      for (index_t i = i0; i <= i1; ++i)
        if (covered(i, j)) return false;
    return true;
  }
  /// True when no covered pixel's centre lies within `r` of `c` and the disc stays on the raster.
  [[nodiscard]] bool disc_free(vec3 c, double r) const {
    const double fx = (c.x - x0_) / h_, fy = (c.y - y0_) / h_, rr = r / h_;
    const index_t i0 = pixel_of_unit(fx - rr), i1 = pixel_of_unit(fx + rr), j0 = pixel_of_unit(fy - rr),
                  j1 = pixel_of_unit(fy + rr);
    if (i0 < 0 || j0 < 0 || i1 >= w_ || j1 >= rows_) return false;
    for (index_t j = j0; j <= j1; ++j)
      for (index_t i = i0; i <= i1; ++i) {
        const double dx = static_cast<double>(i) + 0.5 - fx, dy = static_cast<double>(j) + 0.5 - fy;
        if (dx * dx + dy * dy <= rr * rr && covered(i, j)) return false;
      }
    return true;
  }

 private:
  [[nodiscard]] index_t pixel_of(double d) const noexcept { return pixel_of_unit(d / h_); }
  [[nodiscard]] static index_t pixel_of_unit(double u) noexcept {
    // clamped before the conversion: a far vertex must not overflow index_t
    return static_cast<index_t>(std::floor(std::clamp(u, -2.0, 1e15)));
  }
  void set(index_t i, index_t j) noexcept {
    unsigned char& c = covered_[to_size(j * w_ + i)];
    if (c == 0 && i >= ci0_ && i <= ci1_ && j >= cj0_ && j <= cj1_) ++counted_;
    c = 1;
  }

  xy_raster grid_;
  double x0_, y0_, h_;
  index_t w_, rows_;
  std::vector<unsigned char> covered_;
  std::vector<index_t> owners_;  // per pixel, when add_mesh was given owners (else empty)
  index_t ci0_ = 0, cj0_ = 0, ci1_ = -1, cj1_ = -1, counted_ = 0;  // the window count_in() counts
};

/// Exact Euclidean distance (in pixels) from every pixel centre to the nearest covered pixel centre
/// (Felzenszwalb & Huttenlocher's two passes of lower envelopes of parabolas). With `outside_covered`
/// the pixels beyond the raster count as covered, so a hole is never centred against the raster's
/// edge; without, a raster with nothing covered is far (1e10 pixels) everywhere.
inline std::vector<float> distance_to_covered(const coverage_raster& r, bool outside_covered = true) {
  const index_t w = r.width(), h = r.height();
  constexpr double inf = 1e20;  // far (finite: differences of two stay defined)
  // the raster padded by one covered pixel on every side
  const index_t pw = w + 2, ph = h + 2;
  std::vector<double> f(to_size(pw * ph), inf);
  for (index_t j = 0; j < ph; ++j)
    for (index_t i = 0; i < pw; ++i)
      if (i == 0 || j == 0 || i == pw - 1 || j == ph - 1 ? outside_covered : r.covered(i - 1, j - 1))
        f[to_size(j * pw + i)] = 0;
  std::vector<double> line, out;
  std::vector<index_t> v;
  std::vector<double> z;
  // one 1D pass: squared distance transform of `line` (n samples) into `out`
  constexpr double open = std::numeric_limits<double>::infinity();
  auto pass = [&](index_t n) {
    v.assign(to_size(n), 0);
    z.assign(to_size(n + 1), 0);
    out.assign(to_size(n), 0);
    // where the parabolas from q and p cross
    auto cross = [&](index_t q, index_t p) {
      return ((line[to_size(q)] + double(q) * double(q)) - (line[to_size(p)] + double(p) * double(p))) /
             (2.0 * double(q - p));
    };
    index_t k = 0;
    z[0] = -open;
    z[1] = open;
    for (index_t q = 1; q < n; ++q) {
      double s = cross(q, v[to_size(k)]);
      while (s <= z[to_size(k)]) {
        --k;
        s = cross(q, v[to_size(k)]);
      }
      ++k;
      v[to_size(k)] = q;
      z[to_size(k)] = s;
      z[to_size(k + 1)] = open;
    }
    k = 0;
    for (index_t q = 0; q < n; ++q) {
      while (z[to_size(k + 1)] < double(q)) ++k;
      const index_t p = v[to_size(k)];
      out[to_size(q)] = double(q - p) * double(q - p) + line[to_size(p)];
    }
  };
  for (index_t i = 0; i < pw; ++i) {  // columns
    line.assign(to_size(ph), 0);
    for (index_t j = 0; j < ph; ++j) line[to_size(j)] = f[to_size(j * pw + i)];
    pass(ph);
    for (index_t j = 0; j < ph; ++j) f[to_size(j * pw + i)] = out[to_size(j)];
  }
  for (index_t j = 0; j < ph; ++j) {  // rows
    line.assign(f.begin() + j * pw, f.begin() + (j + 1) * pw);
    pass(pw);
    std::copy(out.begin(), out.end(), f.begin() + j * pw);
  }
  std::vector<float> d(to_size(w * h));
  for (index_t j = 0; j < h; ++j)
    for (index_t i = 0; i < w; ++i)
      d[to_size(j * w + i)] = static_cast<float>(std::sqrt(f[to_size((j + 1) * pw + i + 1)]));
  return d;
}

/// A hole: pixel (i, j) of the raster, the distance there to the nearest covered pixel (pixels).
struct hole_site {
  index_t i = 0, j = 0;
  float radius = 0;
};

/// The local maxima of the distance (not below any of the 8 neighbours) of at least `min_radius`
/// pixels, largest first (ties: row-major order, so the order is deterministic). Plateaus give
/// several sites; the caller checks each against what was placed since.
inline std::vector<hole_site> hole_sites(const std::vector<float>& d, index_t w, index_t h, float min_radius) {
  std::vector<hole_site> s;
  for (index_t j = 0; j < h; ++j)
    for (index_t i = 0; i < w; ++i) {
      const float v = d[to_size(j * w + i)];
      if (v < min_radius) continue;
      bool max = true;
      for (index_t dj = -1; dj <= 1 && max; ++dj)
        for (index_t di = -1; di <= 1; ++di) {
          const index_t a = i + di, b = j + dj;
          if ((di || dj) && a >= 0 && b >= 0 && a < w && b < h && d[to_size(b * w + a)] > v) {
            max = false;
            break;
          }
        }
      if (max) s.push_back({i, j, v});
    }
  std::stable_sort(s.begin(), s.end(), [](const hole_site& a, const hole_site& b) { return a.radius > b.radius; });
  return s;
}

/// Radius of an element's XY footprint about the centre of its box: the farthest vertex.
inline double footprint_radius(const texture_element& e) {
  const vec3 c = e.box.center();
  double r = 0;
  for (const vec3& p : e.mesh.positions) r = std::max(r, std::hypot(p.x - c.x, p.y - c.y));
  return r;
}

/// Area of an element's XY projection, as the upward-facing triangles' XY areas add up (exact for a
/// closed element every vertical line meets at most twice, as a stone).
inline double projected_area(const tri_mesh& m) {
  double a = 0;
  for (const auto& f : m.faces) {
    const vec3 p = m.positions[to_size(f[0])], q = m.positions[to_size(f[1])], r = m.positions[to_size(f[2])];
    a += std::max(0.0, 0.5 * ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x)));
  }
  return a;
}

/// The empty margin the exemplar keeps around its elements, as hole filling measures it: for each
/// element (not long) the distance from its box centre to the nearest pixel (side `h`) covered by
/// another element, less its footprint radius, and of those the `quantile` (0.25: a quarter of the
/// exemplar's elements stand closer to a neighbour). Elements with no neighbour within two
/// diameters do not count; 0 when none has one.
inline double exemplar_clearance(const std::vector<texture_element>& elements,
                                 const std::vector<unsigned char>& is_long, double h, double diameter,
                                 double quantile) {
  aabb all;
  for (const auto& e : elements) all.extend(e.box.min), all.extend(e.box.max);
  const auto w = static_cast<index_t>(std::ceil((all.max.x - all.min.x) / h)) + 1,
             rows = static_cast<index_t>(std::ceil((all.max.y - all.min.y) / h)) + 1;
  if (w < 1 || rows < 1 || double(w) * double(rows) > double(1 << 24)) return 0;
  // which element covers each pixel (-1: none; the first one drawn where two overlap in projection)
  std::vector<index_t> owner(to_size(w * rows), -1);
  for (std::size_t k = 0; k < elements.size(); ++k) {
    // the element drawn on a raster over its own box, aligned with the exemplar's pixels
    const auto i0 = std::max<index_t>(0, static_cast<index_t>((elements[k].box.min.x - all.min.x) / h) - 1),
               i1 = std::min<index_t>(w - 1, static_cast<index_t>((elements[k].box.max.x - all.min.x) / h) + 1),
               j0 = std::max<index_t>(0, static_cast<index_t>((elements[k].box.min.y - all.min.y) / h) - 1),
               j1 = std::min<index_t>(rows - 1, static_cast<index_t>((elements[k].box.max.y - all.min.y) / h) + 1);
    coverage_raster one(all.min.x + static_cast<double>(i0) * h, all.min.y + static_cast<double>(j0) * h, h,
                        i1 - i0 + 1, j1 - j0 + 1);
    one.add_mesh(elements[k].mesh);
    for (index_t j = j0; j <= j1; ++j)
      for (index_t i = i0; i <= i1; ++i)
        if (one.covered(i - i0, j - j0) && owner[to_size(j * w + i)] < 0)
          owner[to_size(j * w + i)] = static_cast<index_t>(k);
  }
  std::vector<double> gaps;
  const double reach = 2 * diameter;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    if (is_long[k]) continue;
    const vec3 c = elements[k].box.center();
    const double fx = (c.x - all.min.x) / h, fy = (c.y - all.min.y) / h, rr = reach / h;
    const auto i0 = std::max<index_t>(0, static_cast<index_t>(fx - rr)),
               i1 = std::min<index_t>(w - 1, static_cast<index_t>(fx + rr)),
               j0 = std::max<index_t>(0, static_cast<index_t>(fy - rr)),
               j1 = std::min<index_t>(rows - 1, static_cast<index_t>(fy + rr));
    double nearest = std::numeric_limits<double>::infinity();
    for (index_t j = j0; j <= j1; ++j)
      for (index_t i = i0; i <= i1; ++i) {
        const index_t o = owner[to_size(j * w + i)];
        if (o < 0 || o == static_cast<index_t>(k)) continue;
        nearest =
            std::min(nearest, std::hypot(static_cast<double>(i) + 0.5 - fx, static_cast<double>(j) + 0.5 - fy) * h);
      }
    if (nearest <= reach) gaps.push_back(std::max(0.0, nearest - footprint_radius(elements[k])));
  }
  if (gaps.empty()) return 0;
  const auto q = static_cast<std::size_t>(std::clamp(quantile, 0.0, 1.0) * static_cast<double>(gaps.size() - 1));
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(q), gaps.end());
  return gaps[q];
}

/// Share of the XY plane the exemplar's elements cover, on pixels of side `h`, inside its elements'
/// bounds inset by half an element diameter (its edges are sparser than its inside).
inline double exemplar_coverage(const std::vector<texture_element>& elements, double h, double diameter) {
  aabb all;
  for (const auto& e : elements) all.extend(e.box.min), all.extend(e.box.max);
  const double in = 0.5 * diameter;
  const xy_rect inner{all.min.x + in, all.min.y + in, all.max.x - in, all.max.y - in};
  if (!(inner.x1 > inner.x0) || !(inner.y1 > inner.y0)) return 0;
  coverage_raster r(make_xy_raster(inner, h, index_t{1} << 24));
  r.count_in(inner);
  for (const auto& e : elements) r.add_mesh(e.mesh);
  return r.counted_share();
}

}  // namespace detail
TESSERA_NAMESPACE_END
