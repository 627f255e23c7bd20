// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_NEIGHBOR_GRID_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_NEIGHBOR_GRID_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/*
A uniform grid of points over a fixed box (a region's bounding box: bubbles
are confined to their region, so the box does not change while they move).

`build()` files the points by cell with a counting sort that keeps index order
inside a cell, so every query visits the same points in the same order: the
force sums that use it do not depend on the thread count. Points added
afterwards with `insert()` are chained per cell and visited after the built
ones, in insertion order. Points outside the box go to the nearest border
cell, which keeps queries exact (the clamp is monotone).

Queries take any radius; the cell size is the interaction range, so the usual
query visits 27 cells.
*/
class Neighbor_grid
{
public:
  typedef std::uint32_t Index;
  static constexpr Index none = (std::numeric_limits<Index>::max)();

  Neighbor_grid() {}

  /// sets the box and the cell size; the number of cells is capped at `max_cells`
  /// (the cell size grows instead), so a huge box with few points stays small
  void set_domain(double xmin, double ymin, double zmin,
                  double xmax, double ymax, double zmax,
                  double cell_size, std::size_t max_cells)
  {
    CGAL_precondition(cell_size > 0.);
    origin_[0] = xmin; origin_[1] = ymin; origin_[2] = zmin;
    const double ext[3] = {(std::max)(xmax - xmin, 0.), (std::max)(ymax - ymin, 0.),
                           (std::max)(zmax - zmin, 0.)};
    double h = cell_size;
    for(;;)
    {
      std::size_t total = 1;
      for(int d = 0; d < 3; ++d)
      {
        dims_[d] = static_cast<std::size_t>(std::floor(ext[d] / h)) + 1;
        total *= dims_[d];
      }
      if(total <= (std::max<std::size_t>)(max_cells, 1)) break;
      h *= 1.25;
    }
    cell_size_ = h;
    inverse_cell_size_ = 1. / h;
    start_.assign(number_of_cells() + 1, 0);
    extra_head_.assign(number_of_cells(), none);
    extra_tail_.assign(number_of_cells(), none);
    items_.clear();
    extra_next_.clear();
  }

  double cell_size() const { return cell_size_; }
  std::size_t number_of_cells() const { return dims_[0] * dims_[1] * dims_[2]; }

  std::size_t cell_coordinate(double v, int d) const
  {
    // floor(t), clamped to [0, dims - 1]; for t >= 1 the conversion truncates, which
    // is the floor (and cheaper than a call to it: queries do this a few times a row)
    const double t = (v - origin_[d]) * inverse_cell_size_;
    if(!(t >= 1.)) return 0; // also catches NaN
    if(t >= double(dims_[d])) return dims_[d] - 1;
    return static_cast<std::size_t>(t);
  }

  std::size_t cell_of(double x, double y, double z) const
  {
    return (cell_coordinate(z, 2) * dims_[1] + cell_coordinate(y, 1)) * dims_[0] + cell_coordinate(x, 0);
  }

  /// files points `0..n-1` (coordinates in three arrays), under the names
  /// `ids[k]` if given (else k); forgets inserted points. With `r`, keeps a copy
  /// of each point and its `r` in cell order for `for_each_near_packed()`.
  void build(const double* x, const double* y, const double* z, std::size_t n, const Index* ids = nullptr,
             const double* r = nullptr)
  {
    CGAL_precondition(n < none);
    const std::size_t nc = number_of_cells();
    cell_.resize(n);
    std::fill(start_.begin(), start_.end(), 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      cell_[i] = static_cast<Index>(cell_of(x[i], y[i], z[i]));
      ++start_[cell_[i] + 1];
    }
    for(std::size_t c = 0; c < nc; ++c) start_[c + 1] += start_[c];
    items_.resize(n);
    std::vector<Index> fill(start_.begin(), start_.end() - 1);
    packed_.resize(r ? 4 * n : 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t s = fill[cell_[i]]++;
      items_[s] = ids ? ids[i] : static_cast<Index>(i);
      if(r)
      {
        double* q = &packed_[4 * s];
        q[0] = x[i]; q[1] = y[i]; q[2] = z[i]; q[3] = r[i];
      }
    }
    std::fill(extra_head_.begin(), extra_head_.end(), none);
    std::fill(extra_tail_.begin(), extra_tail_.end(), none);
    extra_next_.clear();
  }

  /// adds point `i` (a name not used by the last `build()`) at `(x,y,z)`
  void insert(std::size_t i, double x, double y, double z)
  {
    CGAL_precondition(i < none);
    if(extra_next_.size() <= i) extra_next_.resize(i + 1, none);
    const std::size_t c = cell_of(x, y, z);
    if(extra_tail_[c] == none) extra_head_[c] = static_cast<Index>(i);
    else extra_next_[extra_tail_[c]] = static_cast<Index>(i);
    extra_tail_[c] = static_cast<Index>(i);
    extra_next_[i] = none;
  }

  /// calls `f(j)` for every point whose cell meets the cube of half-side `radius` around `(x,y,z)`
  template <class F>
  void for_each_near(double x, double y, double z, double radius, const F& f) const
  {
    for_each_row(x, y, z, radius, [&](std::size_t c0, std::size_t c1) {
      for(std::size_t c = c0; c <= c1; ++c)
      {
        for(Index s = start_[c]; s < start_[c + 1]; ++s) f(std::size_t(items_[s]));
        for(Index e = extra_head_[c]; e != none; e = extra_next_[e]) f(std::size_t(e));
      }
    });
  }

  /// the same as `for_each_near()` with `f(j, q)`, `q` pointing to the copy of j's
  /// coordinates and radius: a cell's points are read from one block of memory.
  /// Needs a `build()` with radii, and no inserted points.
  template <class F>
  void for_each_near_packed(double x, double y, double z, double radius, const F& f) const
  {
    CGAL_precondition(packed_.size() == 4 * items_.size() && extra_next_.empty());
    // the cells of a row are consecutive: one range of items
    for_each_row(x, y, z, radius, [&](std::size_t c0, std::size_t c1) {
      for(Index s = start_[c0]; s < start_[c1 + 1]; ++s) f(std::size_t(items_[s]), &packed_[4 * std::size_t(s)]);
    });
  }

  /// the visit of `for_each_near_packed()`, less the cells that lie farther than `radius`
  /// from `(x,y,z)` (for callers that want only the points of that ball), a row of cells
  /// at a time: `g(items, q, count)` for `count` points, `items[s]` at `q + 4 * s`
  template <class G>
  void for_each_row_in_ball_packed(double x, double y, double z, double radius, const G& g) const
  {
    CGAL_precondition(packed_.size() == 4 * items_.size() && extra_next_.empty());
    // margins: a point may sit a rounding error outside its cell's bounds
    const double slack = 1e-6 * cell_size_ + 1e-13 * (std::abs(x) + std::abs(y) + std::abs(z));
    const double r2 = radius * radius * (1. + 1e-9);
    const std::size_t y0 = cell_coordinate(y - radius, 1), y1 = cell_coordinate(y + radius, 1);
    const std::size_t z0 = cell_coordinate(z - radius, 2), z1 = cell_coordinate(z + radius, 2);
    // the gaps to the slabs along y, once for all z (a query spans a few slabs)
    constexpr std::size_t few = 16;
    double gys[few];
    const bool hoist = y1 - y0 < few;
    if(hoist)
      for(std::size_t j = y0; j <= y1; ++j) gys[j - y0] = gap_to_slab(y, j, 1, slack);
    for(std::size_t k = z0; k <= z1; ++k)
    {
      const double gz = gap_to_slab(z, k, 2, slack);
      for(std::size_t j = y0; j <= y1; ++j)
      {
        const double gy = hoist ? gys[j - y0] : gap_to_slab(y, j, 1, slack), rest = r2 - gz * gz - gy * gy;
        if(rest < 0.) continue; // the row misses the ball
        const double w = std::sqrt(rest) + slack;
        const std::size_t row = (k * dims_[1] + j) * dims_[0];
        const std::size_t c0 = row + cell_coordinate(x - w, 0), c1 = row + cell_coordinate(x + w, 0);
        const Index s0 = start_[c0], s1 = start_[c1 + 1];
        if(s1 > s0) g(items_.data() + s0, packed_.data() + 4 * std::size_t(s0), std::size_t(s1 - s0));
      }
    }
  }

  /// The built cells in shells of growing Chebyshev distance around the cell of
  /// `(x,y,z)`, for a nearest-first search that stops early: before shell `k`,
  /// `stop(d)` is asked with `d` a lower bound of the distance from `(x,y,z)`
  /// to any of its cells (0 for the first two) and the walk ends if it says so;
  /// then `g(c, gap, q, count)` for each non-empty cell `c` of the shell, `gap`
  /// a lower bound of the distance to its box, its `count` points at `q + 4 * s`.
  /// Needs a `build()` with radii, and no inserted points.
  template <class Stop, class G>
  void for_each_cell_in_shells(double x, double y, double z, const Stop& stop, const G& g) const
  {
    CGAL_precondition(packed_.size() == 4 * items_.size() && extra_next_.empty());
    const double slack = 1e-6 * cell_size_ + 1e-13 * (std::abs(x) + std::abs(y) + std::abs(z));
    const std::size_t c0[3] = {cell_coordinate(x, 0), cell_coordinate(y, 1), cell_coordinate(z, 2)};
    const std::size_t largest = (std::max)(dims_[0], (std::max)(dims_[1], dims_[2]));
    auto visit = [&](std::size_t i, std::size_t j, std::size_t k, double gyz2) {
      const std::size_t c = (k * dims_[1] + j) * dims_[0] + i;
      const Index s0 = start_[c], s1 = start_[c + 1];
      if(s1 == s0) return;
      const double gx = gap_to_slab(x, i, 0, slack);
      g(c, std::sqrt(gx * gx + gyz2), packed_.data() + 4 * std::size_t(s0), std::size_t(s1 - s0));
    };
    for(std::size_t shell = 0; shell < largest; ++shell)
    {
      if(stop(shell > 1 ? double(shell - 1) * cell_size_ - slack : 0.)) return;
      std::size_t lo[3], hi[3];
      for(int d = 0; d < 3; ++d)
      {
        lo[d] = c0[d] >= shell ? c0[d] - shell : 0;
        hi[d] = (std::min)(c0[d] + shell, dims_[d] - 1);
      }
      for(std::size_t k = lo[2]; k <= hi[2]; ++k)
      {
        const double gz = gap_to_slab(z, k, 2, slack);
        const bool on_z = k + shell == c0[2] || k == c0[2] + shell;
        for(std::size_t j = lo[1]; j <= hi[1]; ++j)
        {
          const double gy = gap_to_slab(y, j, 1, slack), gyz2 = gy * gy + gz * gz;
          if(on_z || j + shell == c0[1] || j == c0[1] + shell)
            for(std::size_t i = lo[0]; i <= hi[0]; ++i) visit(i, j, k, gyz2); // a face of the shell: whole row
          else
          {
            // inside the shell's faces along y and z: only its two ends along x
            if(c0[0] >= shell) visit(c0[0] - shell, j, k, gyz2);
            if(shell > 0 && c0[0] + shell < dims_[0]) visit(c0[0] + shell, j, k, gyz2);
          }
        }
      }
    }
  }

  /// the built points in cell order (a cheap spatial sort)
  const std::vector<Index>& items_in_cell_order() const { return items_; }

private:
  // g(c0, c1) for each row of cells c0..c1 (along x) meeting the cube of half-side `radius` around (x,y,z)
  template <class G>
  void for_each_row(double x, double y, double z, double radius, const G& g) const
  {
    const std::size_t x0 = cell_coordinate(x - radius, 0), x1 = cell_coordinate(x + radius, 0);
    const std::size_t y0 = cell_coordinate(y - radius, 1), y1 = cell_coordinate(y + radius, 1);
    const std::size_t z0 = cell_coordinate(z - radius, 2), z1 = cell_coordinate(z + radius, 2);
    for(std::size_t k = z0; k <= z1; ++k)
      for(std::size_t j = y0; j <= y1; ++j)
      {
        const std::size_t row = (k * dims_[1] + j) * dims_[0];
        g(row + x0, row + x1);
      }
  }

  // distance from v to the slab of cells c along axis d, less `slack`, at least 0; the
  // border slabs reach to infinity (points outside the box are filed there)
  double gap_to_slab(double v, std::size_t c, int d, double slack) const
  {
    const double lo = origin_[d] + double(c) * cell_size_, hi = lo + cell_size_;
    double g = 0.;
    if(c > 0 && v < lo) g = lo - v;
    else if(c + 1 < dims_[d] && v > hi) g = v - hi;
    return (std::max)(0., g - slack);
  }

  double origin_[3] = {0., 0., 0.};
  std::size_t dims_[3] = {1, 1, 1};
  double cell_size_ = 1.;
  double inverse_cell_size_ = 1.;
  std::vector<Index> start_;      // cell c holds items_[start_[c] .. start_[c+1])
  std::vector<Index> items_;
  std::vector<Index> cell_;       // cell of each built point
  std::vector<double> packed_;    // x, y, z, r of the built points in cell order (if asked for)
  std::vector<Index> extra_head_, extra_tail_, extra_next_; // inserted points, chained per cell
};

/*
Neighbour search among balls of unequal radii: the pairs wanted are those
closer than `a + b * r_j` (a depends on the query bubble, b is a factor of
the other bubble's radius), so the reach depends on the largest radius
around. One grid sized for the largest radius would make a fine part of a
model, next to a few coarse surface triangles, scan whole regions; so balls
up to twice the median radius go in a grid sized for them, and the few larger
ones in a second, coarser grid. Balls under `fine_ratio` of the median (a
strip sampled at its width, a floor set low by hand), when they crowd the
median's cells, go in a third grid sized for them over their own box: in the
median's cells each of them scanned every other one of its cell, thousands
along CloudSpin's squeezed strip sampled at 0.3 m among bubbles of tens of
metres (the list rebuild was 41 % of the run). A query visits the small grid,
the large one, then the fine one if it has balls and the query meets their
box, each in its fixed order.
*/
class Bubble_grid
{
public:
  typedef Neighbor_grid::Index Index;

  /// balls under this share of the median radius go in the fine grid
  static constexpr double fine_ratio = 1. / 16.;

  /// files balls `0..n-1`; `reach_factor * (r_i + r_j)` is the largest reach that queries will ask for.
  /// With `packed`, the cells of the small grid are sized for two balls of the median radius,
  /// not of the largest small one (queries visit more, smaller cells: fewer points to test),
  /// and `for_each_near_packed()` may be used.
  void build(const double* x, const double* y, const double* z, const double* r, std::size_t n,
             const double box[6], double reach_factor, bool packed = false)
  {
    // (radii are only read here)
    std::vector<double> radii(r, r + n);
    double median = 0., largest = 0.;
    if(n > 0)
    {
      std::nth_element(radii.begin(), radii.begin() + n / 2, radii.end());
      median = radii[n / 2];
      largest = *std::max_element(r, r + n);
    }
    threshold_ = 2. * median;
    fine_threshold_ = 0.;
    r_small_ = r_fine_ = 0.;
    small_.clear();
    large_.clear();
    fine_.clear();
    for(std::size_t i = 0; i < n; ++i)
    {
      if(r[i] <= threshold_) { small_.push_back(Index(i)); r_small_ = (std::max)(r_small_, r[i]); }
      else large_.push_back(Index(i));
    }
    r_large_ = largest;
    const double small_cell = reach_factor * 2. * (std::max)(packed ? median : r_small_, 1e-300);
    setup(small_grid_, small_, x, y, z, packed ? r : nullptr, box, small_cell);
    setup(large_grid_, large_, x, y, z, packed ? r : nullptr, box, reach_factor * 2. * (std::max)(r_large_, 1e-300));
    if(!fine_balls_crowd(x, y, z, r, n, fine_ratio * median)) return;

    // the crowding balls leave the small grid for a grid of their own, sized for them over their box
    fine_threshold_ = fine_ratio * median;
    std::vector<Index> kept;
    std::vector<double> fine_radii;
    r_small_ = 0.;
    for(Index i : small_)
    {
      if(r[i] < fine_threshold_)
      {
        fine_.push_back(i);
        fine_radii.push_back(r[i]);
        r_fine_ = (std::max)(r_fine_, r[i]);
      }
      else { kept.push_back(i); r_small_ = (std::max)(r_small_, r[i]); }
    }
    small_.swap(kept);
    setup(small_grid_, small_, x, y, z, packed ? r : nullptr, box, small_cell);
    // (the cells fit two balls of the fine median when packed, of the largest fine ball if not)
    double cell_radius = r_fine_;
    if(packed)
    {
      std::nth_element(fine_radii.begin(), fine_radii.begin() + fine_radii.size() / 2, fine_radii.end());
      cell_radius = fine_radii[fine_radii.size() / 2];
    }
    for(int d = 0; d < 3; ++d)
    {
      fine_box_[d] = (std::numeric_limits<double>::max)();
      fine_box_[d + 3] = -(std::numeric_limits<double>::max)();
    }
    for(Index i : fine_) extend_fine_box(x[i], y[i], z[i]);
    setup(fine_grid_, fine_, x, y, z, packed ? r : nullptr, fine_box_,
          reach_factor * 2. * (std::max)(cell_radius, 1e-300));
  }

  /// adds ball `i` (a name beyond the `n` of `build()`) at `(x,y,z)` with radius `r`
  void insert(std::size_t i, double x, double y, double z, double r)
  {
    if(!fine_.empty() && r < fine_threshold_)
    {
      fine_grid_.insert(i, x, y, z);
      r_fine_ = (std::max)(r_fine_, r);
      extend_fine_box(x, y, z);
    }
    else if(r <= threshold_ || large_.empty())
    {
      small_grid_.insert(i, x, y, z);
      r_small_ = (std::max)(r_small_, r);
    }
    else
      large_grid_.insert(i, x, y, z);
  }

  /// calls `f(j)` for (at least) every ball j with |p - x_j| < a + b * r_j
  template <class F>
  void for_each_near(double x, double y, double z, double a, double b, const F& f) const
  {
    small_grid_.for_each_near(x, y, z, a + b * r_small_, f);
    if(!large_.empty())
      large_grid_.for_each_near(x, y, z, a + b * r_large_, f);
    if(meets_fine_box(x, y, z, a + b * r_fine_))
      fine_grid_.for_each_near(x, y, z, a + b * r_fine_, f);
  }

  /// the same as `for_each_near()` with `f(j, q)`, q pointing to x, y, z, r of ball j;
  /// needs a packed `build()` and no `insert()`
  template <class F>
  void for_each_near_packed(double x, double y, double z, double a, double b, const F& f) const
  {
    small_grid_.for_each_near_packed(x, y, z, a + b * r_small_, f);
    if(!large_.empty())
      large_grid_.for_each_near_packed(x, y, z, a + b * r_large_, f);
    if(meets_fine_box(x, y, z, a + b * r_fine_))
      fine_grid_.for_each_near_packed(x, y, z, a + b * r_fine_, f);
  }

  /// the visit of `for_each_near_packed()` for the balls j with |p - x_j| < a + b * r_j only
  /// (cells beyond that reach are skipped; the others are visited in the same order), a row
  /// of cells at a time (see `Neighbor_grid::for_each_row_in_ball_packed()`)
  template <class G>
  void for_each_row_in_reach_packed(double x, double y, double z, double a, double b, const G& g) const
  {
    small_grid_.for_each_row_in_ball_packed(x, y, z, a + b * r_small_, g);
    if(!large_.empty())
      large_grid_.for_each_row_in_ball_packed(x, y, z, a + b * r_large_, g);
    if(meets_fine_box(x, y, z, a + b * r_fine_))
      fine_grid_.for_each_row_in_ball_packed(x, y, z, a + b * r_fine_, g);
  }

  double largest_radius() const { return (std::max)({r_small_, r_large_, r_fine_}); }

  /// the number of balls `build()` put in the fine grid
  std::size_t number_of_fine_balls() const { return fine_.size(); }

private:
  static void setup(Neighbor_grid& grid, const std::vector<Index>& members, const double* x, const double* y,
                    const double* z, const double* r, const double box[6], double cell)
  {
    const std::size_t m = members.size();
    grid.set_domain(box[0] - cell, box[1] - cell, box[2] - cell, box[3] + cell, box[4] + cell, box[5] + cell,
                    cell, 4 * m + 64);
    std::vector<double> gx(m), gy(m), gz(m), gr(r ? m : 0);
    for(std::size_t k = 0; k < m; ++k) { gx[k] = x[members[k]]; gy[k] = y[members[k]]; gz[k] = z[members[k]]; }
    if(r)
      for(std::size_t k = 0; k < m; ++k) gr[k] = r[members[k]];
    grid.build(gx.data(), gy.data(), gz.data(), m, members.data(), r ? gr.data() : nullptr);
  }

  // Whether the balls under `below` crowd the cells of the small grid just built: their
  // scans of the cells they share would cost more than `crowding` candidates per ball
  // of the whole set, several times a query's usual scan (a few dozen). Fewer (a thin
  // layer's floor: modelA5 has at most 380 in 30,000, 221 in one cell; CloudSpin's
  // default mesh reaches 91 per ball) stay with the others, visited in the same order
  // as before the fine grid, so that those meshes do not change.
  bool fine_balls_crowd(const double* x, const double* y, const double* z, const double* r, std::size_t n,
                        double below) const
  {
    static constexpr double crowding = 256.;
    std::vector<std::size_t> cells;
    for(Index i : small_)
      if(r[i] < below) cells.push_back(small_grid_.cell_of(x[i], y[i], z[i]));
    const double bound = crowding * double(n);
    if(double(cells.size()) * double(cells.size()) <= bound) return false; // even all in one cell would not
    std::sort(cells.begin(), cells.end());
    double pairs = 0.; // the sum over cells of their count squared
    for(std::size_t k = 0; k < cells.size();)
    {
      std::size_t e = k;
      while(e < cells.size() && cells[e] == cells[k]) ++e;
      pairs += double(e - k) * double(e - k);
      k = e;
    }
    return pairs > bound;
  }

  void extend_fine_box(double x, double y, double z)
  {
    const double p[3] = {x, y, z};
    for(int d = 0; d < 3; ++d)
    {
      fine_box_[d] = (std::min)(fine_box_[d], p[d]);
      fine_box_[d + 3] = (std::max)(fine_box_[d + 3], p[d]);
    }
  }

  // whether the cube of half-side `radius` around (x,y,z) meets the box of the fine
  // balls (the margin covers rounding; the grid files a ball outside its domain in a
  // border cell, but no ball lies outside this box)
  bool meets_fine_box(double x, double y, double z, double radius) const
  {
    if(fine_.empty()) return false;
    const double p[3] = {x, y, z};
    for(int d = 0; d < 3; ++d)
    {
      const double slack = 1e-9 * (radius + std::abs(p[d]));
      if(p[d] + radius + slack < fine_box_[d] || p[d] - radius - slack > fine_box_[d + 3]) return false;
    }
    return true;
  }

  double threshold_ = 0., fine_threshold_ = 0., r_small_ = 0., r_large_ = 0., r_fine_ = 0.;
  double fine_box_[6] = {0., 0., 0., 0., 0., 0.};
  std::vector<Index> small_, large_, fine_;
  Neighbor_grid small_grid_, large_grid_, fine_grid_;
};

/*
The smallest value in each cell of a `Neighbor_grid` built with values (the
radii of `build()`), for the walk that seeks min_i (v_i + slope |x - x_i|) -
a size that grows at most `slope` per unit of distance from each point: a
cell whose smallest value plus the slope times its distance cannot lower the
minimum so far is skipped, and the walk ends where the smallest value of all
cannot. A minimum does not depend on the order of the walk, so the result is
the same bits as a scan of every point.
*/
class Cell_minima
{
public:
  /// `grid` was built from these `n` points and values
  void build(const Neighbor_grid& grid, const double* x, const double* y, const double* z, const double* v,
             std::size_t n)
  {
    cell_min_.assign(grid.number_of_cells(), (std::numeric_limits<double>::infinity)());
    smallest_ = (std::numeric_limits<double>::infinity)();
    for(std::size_t i = 0; i < n; ++i)
    {
      double& m = cell_min_[grid.cell_of(x[i], y[i], z[i])];
      m = (std::min)(m, v[i]);
      smallest_ = (std::min)(smallest_, v[i]);
    }
  }

  /// min(bound, min_i (v_i + slope |(x, y, z) - x_i|)) over the points of `grid`
  double cone_minimum(const Neighbor_grid& grid, double x, double y, double z, double slope, double bound) const
  {
    if(!(smallest_ < bound)) return bound;
    grid.for_each_cell_in_shells(
      x, y, z, [&](double gap) { return !(smallest_ + slope * gap < bound); },
      [&](std::size_t c, double gap, const double* q, std::size_t count) {
        if(!(cell_min_[c] + slope * gap < bound)) return;
        for(std::size_t k = 0; k < count; ++k, q += 4)
        {
          const double dx = x - q[0], dy = y - q[1], dz = z - q[2];
          bound = (std::min)(bound, q[3] + slope * std::sqrt(dx * dx + dy * dy + dz * dz));
        }
      });
    return bound;
  }

private:
  std::vector<double> cell_min_;
  double smallest_ = (std::numeric_limits<double>::infinity)();
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_NEIGHBOR_GRID_H
