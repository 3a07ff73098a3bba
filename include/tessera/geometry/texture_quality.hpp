// tessera/geometry/texture_quality.hpp: does a synthesized geometric texture (a quilt, a tiled plane of
// geometric Wang tiles) look like its exemplar? Paper 000 §3 asks for whole elements, no element across
// a tile corner and seamless tile borders; these figures measure that, each against the exemplar:
// element density, projected covered area per unit area, the rate of partial or open elements (a ring
// cut into a "C"), density in bands along tile borders and around tile corners against the density
// inside tiles, the rate of empty cells (cells of 1.5 element diameters holding no geometry), and the
// nearest-neighbour spacing of element centres against the exemplar's spread. check_geometric_texture
// (next door) checks validity; this header checks likeness.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "detail/xy_raster.hpp"
#include "mesh_elements.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of the quality figures.
struct texture_quality_options {
  /// > 0: the texture is a plane of tiles of this side, the grid starting at the domain's (x0, y0);
  /// the border-band and corner figures are computed. 0: no tile grid (a quilt, an exemplar).
  double tile_size = 0;
  double band_fraction = 0.15;        ///< border bands: within this fraction of tile_size of a tile side
  double empty_cell_diameters = 1.5;  ///< side of the empty-cell grid, in element diameters
  double partial_fraction = 0.9;      ///< partial: surface area below this fraction of the exemplar's smallest element
  double margin_diameters = 1.0;      ///< figures are taken in the domain shrunk by this many element diameters
  double pixels_per_diameter = 12;    ///< resolution of the projected-coverage raster
  index_t max_pixels = index_t{1} << 24;  ///< the raster gets coarser rather than larger than this
  int histogram_bins = 16;                ///< nearest-neighbour histogram over [0, 2 x exemplar median)
};

/// What the exemplar sets as the reference (quality_reference).
struct texture_quality_reference {
  double diameter = 0;          ///< median of the elements' smaller XY extent
  double smallest_area = 0;     ///< surface area of the exemplar's smallest whole element (0 when none)
  std::vector<int> euler;       ///< Euler characteristics of its whole elements (sorted, unique)
  double nn_median = 0;         ///< median nearest-neighbour distance of element centres
  double nn_lo = 0, nn_hi = 0;  ///< the spread: 5th and 95th percentile, widened by 5 % of the median
};

/// The figures of one texture.
struct texture_quality {
  index_t elements = 0;         ///< connected components
  index_t whole_elements = 0;   ///< elements clear of the domain's outer border (the partial rate's base)
  index_t window_elements = 0;  ///< element centres inside the measuring window
  double density = 0;           ///< element centres per unit area (smoothed, see band_density)
  double covered_fraction = 0;  ///< projected (XY) covered area per unit area in the window
  double partial_rate = 0;      ///< whole elements that are open, too small or of a foreign topology
  double empty_cell_rate = 0;   ///< cells of empty_cell_diameters with no geometry
  index_t cells = 0;            ///< cells counted
  /// Tile grid only (options.tile_size > 0): smoothed centre density (Gaussian of sigma = half the
  /// exemplar's nearest-neighbour median, so a lattice's phase does not count) in border bands, in
  /// corner squares and inside tiles; covered fractions likewise.
  double band_density = 0, corner_density = 0, interior_density = 0;
  /// Covered fractions (unsmoothed) in border bands, corner squares and inside tiles.
  double band_coverage = 0, corner_coverage = 0, interior_coverage = 0;
  double nn_median = 0;               ///< median nearest-neighbour distance of centres in the window
  double nn_outside = 0;              ///< fraction of those distances outside the reference spread
  std::vector<index_t> nn_histogram;  ///< counts over [0, 2 nn_median of the reference), last bin open
};

/// A texture against its exemplar: both figure sets and the differences the goals are stated in.
struct texture_quality_comparison {
  /// The exemplar's figures (over its XY bounds, no tile grid) and the output's.
  texture_quality exemplar, output;
  /// What the exemplar set as the reference.
  texture_quality_reference reference;
  double density_ratio = 0;      ///< output / exemplar density
  double coverage_ratio = 0;     ///< output / exemplar covered fraction
  double partial_excess = 0;     ///< output - exemplar partial rate (fractions, not percent)
  double empty_cell_excess = 0;  ///< output - exemplar empty-cell rate
  double band_ratio = 0;         ///< output band / interior density (tile grid only, else 0)
  double corner_ratio = 0;       ///< output corner / interior density (tile grid only, else 0)
  double nn_outside_excess = 0;  ///< output - exemplar fraction of spacings outside the spread
};

namespace detail {

/// Per-element figures of a mesh: area, area-weighted XY centroid, XY box, Euler characteristic,
/// open edges.
struct element_figures {
  std::vector<double> area;
  std::vector<vec3> centre;
  std::vector<aabb> box;
  std::vector<int> euler;
  std::vector<index_t> open_edges;
};

inline element_figures measure_elements(const tri_mesh& m) {
  const mesh_components comp = connected_components(m);
  const auto n = to_size(comp.count);
  element_figures r;
  r.area.assign(n, 0);
  r.centre.assign(n, vec3{});
  r.box.assign(n, aabb{});
  r.open_edges.assign(n, 0);
  std::vector<long long> v(n, 0), e(n, 0), f(n, 0);
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    if (comp.vertex_component[i] >= 0) {
      ++v[to_size(comp.vertex_component[i])];
      r.box[to_size(comp.vertex_component[i])].extend(m.positions[i]);
    }
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const auto c = to_size(comp.face_component[i]);
    const vec3 a = m.positions[to_size(m.faces[i][0])], b = m.positions[to_size(m.faces[i][1])],
               d = m.positions[to_size(m.faces[i][2])];
    const double ar = 0.5 * norm(cross(b - a, d - a));
    r.area[c] += ar;
    r.centre[c] += (a + b + d) * (ar / 3.0);
    ++f[c];
  }
  for (const mesh_edge& ed : mesh_edges(m)) {
    const auto c = to_size(comp.vertex_component[to_size(ed.v0)]);
    ++e[c];
    if (ed.faces.size() == 1) ++r.open_edges[c];
  }
  r.euler.resize(n);
  for (std::size_t c = 0; c < n; ++c) {
    r.centre[c] = r.area[c] > 0 ? r.centre[c] / r.area[c] : r.box[c].center();
    r.centre[c].z = 0;
    r.euler[c] = static_cast<int>(v[c] - e[c] + f[c]);
  }
  return r;
}

/// True when the element's XY box reaches the domain's outer border (or beyond).
inline bool reaches_border(const aabb& b, const xy_rect& d, double tol) {
  return b.min.x <= d.x0 + tol || b.min.y <= d.y0 + tol || b.max.x >= d.x1 - tol || b.max.y >= d.y1 - tol;
}

/// Nearest-neighbour distance of each query centre among all centres (a uniform grid of side `h`).
inline std::vector<double> nearest_neighbour_distances(std::span<const vec3> all, std::span<const std::size_t> query,
                                                       double h) {
  std::vector<double> out;
  if (all.size() < 2 || !(h > 0)) return out;
  aabb b;
  for (const vec3& p : all) b.extend(p);
  const double ext = std::max(b.extent().x, b.extent().y);
  h = std::max(h, ext / 2048.0);  // at most 2048² buckets
  const auto nx = static_cast<std::size_t>(b.extent().x / h) + 1, ny = static_cast<std::size_t>(b.extent().y / h) + 1;
  std::vector<std::size_t> start(nx * ny + 1, 0), items(all.size());
  auto cell = [&](const vec3& p) {
    const auto cx = std::min(nx - 1, static_cast<std::size_t>((p.x - b.min.x) / h));
    const auto cy = std::min(ny - 1, static_cast<std::size_t>((p.y - b.min.y) / h));
    return std::pair{cx, cy};
  };
  for (const vec3& p : all) {
    const auto [cx, cy] = cell(p);
    ++start[cy * nx + cx + 1];
  }
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto [cx, cy] = cell(all[i]);
    items[fill[cy * nx + cx]++] = i;
  }
  out.reserve(query.size());
  for (std::size_t q : query) {
    const auto [cx, cy] = cell(all[q]);
    double best = INFINITY;
    // grow rings of buckets until the best distance is certainly inside the searched square
    for (std::size_t r = 0; r < std::max(nx, ny); ++r) {
      const std::size_t x0 = cx >= r ? cx - r : 0, x1 = std::min(nx - 1, cx + r), y0 = cy >= r ? cy - r : 0,
                        y1 = std::min(ny - 1, cy + r);
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) {
          if (r > 0 && x != x0 && x != x1 && y != y0 && y != y1) continue;  // ring only
          for (std::size_t k = start[y * nx + x]; k < start[y * nx + x + 1]; ++k)
            if (items[k] != q) best = std::min(best, norm(all[items[k]] - all[q]));
        }
      if (best <= double(r) * h) break;
    }
    out.push_back(best);
  }
  return out;
}

inline double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const auto k = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * double(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

/// Median of the elements' smaller XY extent (as quilt_exemplar::element_diameter).
inline double median_diameter(const element_figures& f) {
  std::vector<double> d;
  for (const aabb& b : f.box) d.push_back(std::min(b.extent().x, b.extent().y));
  return percentile(std::move(d), 0.5);
}

/// Marks the pixels whose centre lies in the XY projection of some triangle (rasters of the
/// coverage and band figures: detail/xy_raster.hpp).
inline std::vector<unsigned char> rasterize_coverage(const tri_mesh& m, const xy_raster& r) {
  std::vector<unsigned char> cov(r.nx * r.ny, 0);
  for_each_covered_pixel(m, r, [&](std::size_t x, std::size_t y) { cov[y * r.nx + x] = 1; });
  return cov;
}

/// 0 inside a tile, 1 in a border band, 2 in a corner square (tile grid from the domain's origin).
inline int tile_region(const vec3& p, const xy_rect& domain, double w, double band) {
  const double u = std::fmod(p.x - domain.x0, w), v = std::fmod(p.y - domain.y0, w);
  const bool bu = std::min(u, w - u) < band, bv = std::min(v, w - v) < band;
  return bu && bv ? 2 : (bu || bv ? 1 : 0);
}

}  // namespace detail

/// The exemplar's reference figures: element diameter, smallest whole element, topologies, and the
/// spread of centre spacings. Elements reaching the exemplar's XY bounds count as cut, not whole.
/// Errors: invalid mesh, a mesh without faces.
template <Mesh M>
result<texture_quality_reference> quality_reference(const M& exemplar) {
  auto tm = to_tri_mesh(exemplar, "quality_reference: exemplar");
  if (!tm) return tm.error();
  if (tm->faces.empty()) return status::invalid_argument("quality_reference: the exemplar has no faces");
  const auto f = detail::measure_elements(*tm);
  const aabb b = bounding_box(*tm);
  const xy_rect d{b.min.x, b.min.y, b.max.x, b.max.y};
  texture_quality_reference ref;
  ref.diameter = detail::median_diameter(f);
  if (!(ref.diameter > 0)) return status::invalid_argument("quality_reference: elements have no XY extent");
  const double tol = 1e-6 * ref.diameter;
  std::vector<std::size_t> all;
  for (std::size_t e = 0; e < f.area.size(); ++e) {
    all.push_back(e);
    if (detail::reaches_border(f.box[e], d, tol) || f.open_edges[e] > 0) continue;
    ref.smallest_area = ref.smallest_area == 0 ? f.area[e] : std::min(ref.smallest_area, f.area[e]);
    ref.euler.push_back(f.euler[e]);
  }
  std::sort(ref.euler.begin(), ref.euler.end());
  ref.euler.erase(std::unique(ref.euler.begin(), ref.euler.end()), ref.euler.end());
  const auto nn = detail::nearest_neighbour_distances(f.centre, all, ref.diameter);
  ref.nn_median = detail::percentile(nn, 0.5);
  ref.nn_lo = std::max(0.0, detail::percentile(nn, 0.05) - 0.05 * ref.nn_median);
  ref.nn_hi = detail::percentile(nn, 0.95) + 0.05 * ref.nn_median;
  return ref;
}

/// The quality figures of `texture` over `domain` (its XY extent when empty) against `ref`. Figures
/// are taken in the domain shrunk by margin_diameters element diameters, so that elements cut by the
/// texture's outer border do not count; an element is partial when it has open edges, a surface area
/// below partial_fraction x ref.smallest_area, or an Euler characteristic none of the exemplar's
/// whole elements has (a ring cut into a capped "C" has 2, a ring 0).
/// Errors: invalid mesh, a bad reference or options, a window left empty by the margin.
/// O(F (1 + pixels per face) + pixels + elements).
template <Mesh M>
result<texture_quality> measure_texture_quality(const M& texture, const texture_quality_reference& ref,
                                                xy_rect domain = {}, const texture_quality_options& o = {}) {
  auto tm = to_tri_mesh(texture, "measure_texture_quality: texture");
  if (!tm) return tm.error();
  const tri_mesh& m = *tm;
  if (!(ref.diameter > 0) || !std::isfinite(ref.diameter))
    return status::invalid_argument("measure_texture_quality: the reference has no element diameter");
  if (!(o.band_fraction > 0 && o.band_fraction < 0.5) || !(o.empty_cell_diameters > 0) || !(o.partial_fraction >= 0) ||
      !(o.margin_diameters >= 0) || !(o.pixels_per_diameter > 0) || o.histogram_bins < 1 || !(o.tile_size >= 0) ||
      !std::isfinite(o.tile_size))
    return status::invalid_argument("measure_texture_quality: options out of range");
  if (!(domain.x1 > domain.x0 && domain.y1 > domain.y0)) {
    const aabb b = bounding_box(m);
    domain = {b.min.x, b.min.y, b.max.x, b.max.y};
  }
  const double margin = o.margin_diameters * ref.diameter;
  const xy_rect win{domain.x0 + margin, domain.y0 + margin, domain.x1 - margin, domain.y1 - margin};
  if (!(win.x1 > win.x0 && win.y1 > win.y0) || !std::isfinite(win.width() * win.height()))
    return status::invalid_argument(detail::cat("measure_texture_quality: a domain of ", domain.width(), " x ",
                                                domain.height(), " leaves no window inside a margin of ", margin));
  const auto f = detail::measure_elements(m);
  texture_quality q;
  q.elements = static_cast<index_t>(f.area.size());
  const double tol = 1e-6 * ref.diameter;

  // density (centres in the window) and the partial rate (elements clear of the outer border)
  index_t partial = 0;
  std::vector<std::size_t> in_window, all;
  for (std::size_t e = 0; e < f.area.size(); ++e) {
    all.push_back(e);
    if (win.contains(f.centre[e])) in_window.push_back(e);
    if (detail::reaches_border(f.box[e], domain, tol)) continue;
    ++q.whole_elements;
    const bool open = f.open_edges[e] > 0, small = f.area[e] < o.partial_fraction * ref.smallest_area;
    const bool foreign = !ref.euler.empty() && !std::binary_search(ref.euler.begin(), ref.euler.end(), f.euler[e]);
    if (open || small || foreign) ++partial;
  }
  q.window_elements = static_cast<index_t>(in_window.size());
  q.partial_rate = q.whole_elements > 0 ? double(partial) / double(q.whole_elements) : 0.0;

  // element density: centres smoothed by a Gaussian of sigma = half the exemplar's spacing (a
  // lattice's phase against the window then does not count), averaged over the window
  const double sigma = 0.5 * (ref.nn_median > 0 ? ref.nn_median : ref.diameter);
  // the density field is read this far inside the domain, so that the missing neighbours beyond a
  // texture's outer border do not thin it (an exemplar's edge would otherwise read 20-30 % low)
  const double dm = std::max(margin, 2.5 * sigma);
  const xy_rect dwin = dm * 2 < std::min(domain.width(), domain.height())
                           ? xy_rect{domain.x0 + dm, domain.y0 + dm, domain.x1 - dm, domain.y1 - dm}
                           : win;
  // projected coverage over the whole domain; the covered fraction is its average under a window
  // with Gaussian edges (dwin below, blurred by sigma: a lattice's phase against the window then
  // does not count, as for the density); empty cells are counted inside `win`
  const auto r = detail::make_xy_raster(domain, ref.diameter / o.pixels_per_diameter, o.max_pixels);
  const auto cov = detail::rasterize_coverage(m, r);
  {
    auto soft = [&](double p, double lo, double hi) {
      return 0.5 * (std::erf((hi - p) / (std::sqrt(2.0) * sigma)) - std::erf((lo - p) / (std::sqrt(2.0) * sigma)));
    };
    std::vector<double> wx(r.nx), wy(r.ny);
    for (std::size_t x = 0; x < r.nx; ++x) wx[x] = soft(r.centre(x, 0).x, dwin.x0, dwin.x1);
    for (std::size_t y = 0; y < r.ny; ++y) wy[y] = soft(r.centre(0, y).y, dwin.y0, dwin.y1);
    double hit = 0, all = 0;
    for (std::size_t y = 0; y < r.ny; ++y)
      for (std::size_t x = 0; x < r.nx; ++x) {
        all += wx[x] * wy[y];
        if (cov[y * r.nx + x]) hit += wx[x] * wy[y];
      }
    q.covered_fraction = all > 0 ? hit / all : 0.0;
  }
  const double cs = o.empty_cell_diameters * ref.diameter;
  const auto cx = static_cast<std::size_t>(win.width() / cs), cy = static_cast<std::size_t>(win.height() / cs);
  if (cx > 0 && cy > 0 && cx * cy <= cov.size()) {
    std::vector<unsigned char> full(cx * cy, 0);
    for (std::size_t y = 0; y < r.ny; ++y)
      for (std::size_t x = 0; x < r.nx; ++x) {
        const vec3 p = r.centre(x, y);
        if (!cov[y * r.nx + x] || p.x < win.x0 || p.y < win.y0) continue;
        const auto i = static_cast<std::size_t>((p.x - win.x0) / cs), j = static_cast<std::size_t>((p.y - win.y0) / cs);
        if (i < cx && j < cy) full[j * cx + i] = 1;
      }
    q.cells = static_cast<index_t>(full.size());
    q.empty_cell_rate = double(std::count(full.begin(), full.end(), 0)) / double(full.size());
  }

  const auto d = detail::make_xy_raster(dwin, 0.5 * sigma, o.max_pixels);
  std::vector<double> dens(d.nx * d.ny, 0.0);
  const double gauss = 1.0 / (2 * 3.14159265358979323846 * sigma * sigma);
  const auto reach = static_cast<std::ptrdiff_t>(std::ceil(3 * sigma / d.px));
  for (std::size_t e = 0; e < f.area.size(); ++e) {
    const vec3 c = f.centre[e];
    const auto ix = static_cast<std::ptrdiff_t>(std::floor((c.x - dwin.x0) / d.px)),
               iy = static_cast<std::ptrdiff_t>(std::floor((c.y - dwin.y0) / d.px));
    for (std::ptrdiff_t y = std::max<std::ptrdiff_t>(0, iy - reach);
         y <= std::min<std::ptrdiff_t>(std::ptrdiff_t(d.ny) - 1, iy + reach); ++y)
      for (std::ptrdiff_t x = std::max<std::ptrdiff_t>(0, ix - reach);
           x <= std::min<std::ptrdiff_t>(std::ptrdiff_t(d.nx) - 1, ix + reach); ++x) {
        const vec3 p = d.centre(detail::to_size(x), detail::to_size(y));
        const double r2 = (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
        dens[detail::to_size(y) * d.nx + detail::to_size(x)] += gauss * std::exp(-r2 / (2 * sigma * sigma));
      }
  }
  {
    double sum = 0;
    for (double v : dens) sum += v;
    q.density = sum / double(dens.size());
  }

  // tile grid: smoothed centre density and coverage by region (band, corner, inside)
  if (o.tile_size > 0) {
    const double w = o.tile_size, band = o.band_fraction * w;
    std::array<double, 3> cov_sum{}, cov_n{};
    for (std::size_t y = 0; y < r.ny; ++y)
      for (std::size_t x = 0; x < r.nx; ++x) {
        if (!win.contains(r.centre(x, y))) continue;
        const int k = detail::tile_region(r.centre(x, y), domain, w, band);
        cov_sum[detail::to_size(k)] += cov[y * r.nx + x];
        cov_n[detail::to_size(k)] += 1;
      }
    std::array<double, 3> den_sum{}, den_n{};
    for (std::size_t y = 0; y < d.ny; ++y)
      for (std::size_t x = 0; x < d.nx; ++x) {
        const int k = detail::tile_region(d.centre(x, y), domain, w, band);
        den_sum[detail::to_size(k)] += dens[y * d.nx + x];
        den_n[detail::to_size(k)] += 1;
      }
    auto avg = [](double s, double n) { return n > 0 ? s / n : 0.0; };
    q.interior_density = avg(den_sum[0], den_n[0]);
    q.band_density = avg(den_sum[1], den_n[1]);
    q.corner_density = avg(den_sum[2], den_n[2]);
    q.interior_coverage = avg(cov_sum[0], cov_n[0]);
    q.band_coverage = avg(cov_sum[1], cov_n[1]);
    q.corner_coverage = avg(cov_sum[2], cov_n[2]);
  }

  // nearest-neighbour spacing of the window's centres against the reference spread
  const auto nn = detail::nearest_neighbour_distances(f.centre, in_window, ref.diameter);
  q.nn_median = detail::percentile(nn, 0.5);
  q.nn_histogram.assign(detail::to_size(o.histogram_bins), 0);
  const double top = 2 * (ref.nn_median > 0 ? ref.nn_median : ref.diameter);
  index_t outside = 0;
  for (double x : nn) {
    if (!std::isfinite(x)) continue;
    ++q.nn_histogram[std::min(detail::to_size(o.histogram_bins) - 1,
                              static_cast<std::size_t>(x / top * o.histogram_bins))];
    if (x < ref.nn_lo || x > ref.nn_hi) ++outside;
  }
  q.nn_outside = nn.empty() ? 0.0 : double(outside) / double(nn.size());
  return q;
}

/// Measures `exemplar` (over its XY bounds, no tile grid) and `output` (over `domain`, with
/// options.tile_size's grid) against the exemplar's reference, and the differences the quality
/// goals are stated in. Errors: those of quality_reference and measure_texture_quality.
template <Mesh A, Mesh B>
result<texture_quality_comparison> compare_texture_quality(const A& exemplar, const B& output,
                                                           const xy_rect& domain = {},
                                                           const texture_quality_options& o = {}) {
  auto ref = quality_reference(exemplar);
  if (!ref) return ref.error();
  texture_quality_options eo = o;
  eo.tile_size = 0;
  auto ex = measure_texture_quality(exemplar, *ref, {}, eo);
  if (!ex) return ex.error();
  auto out = measure_texture_quality(output, *ref, domain, o);
  if (!out) return out.error();
  texture_quality_comparison c;
  c.reference = std::move(*ref);
  c.exemplar = std::move(*ex);
  c.output = std::move(*out);
  auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  c.density_ratio = ratio(c.output.density, c.exemplar.density);
  c.coverage_ratio = ratio(c.output.covered_fraction, c.exemplar.covered_fraction);
  c.partial_excess = c.output.partial_rate - c.exemplar.partial_rate;
  c.empty_cell_excess = c.output.empty_cell_rate - c.exemplar.empty_cell_rate;
  if (o.tile_size > 0) {
    c.band_ratio = ratio(c.output.band_density, c.output.interior_density);
    c.corner_ratio = ratio(c.output.corner_density, c.output.interior_density);
  }
  c.nn_outside_excess = c.output.nn_outside - c.exemplar.nn_outside;
  return c;
}

TESSERA_NAMESPACE_END
