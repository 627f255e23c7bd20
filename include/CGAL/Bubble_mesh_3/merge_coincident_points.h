// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_MERGE_COINCIDENT_POINTS_H
#define CGAL_BUBBLE_MESH_3_MERGE_COINCIDENT_POINTS_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

// union-find with the smallest index as root, so the result does not depend
// on the order the unions are made in
inline std::size_t find_representative(std::vector<std::size_t>& parent, std::size_t i)
{
  std::size_t r = i;
  while(parent[r] != r) r = parent[r];
  while(parent[i] != r) { std::size_t n = parent[i]; parent[i] = r; i = n; }
  return r;
}

/*
 For each point, the index of the point that represents it: the smallest
 index among the points it is merged with. `relative_tolerance == 0` merges
 bitwise-equal coordinates only (sorted, O(n log n)); a positive tolerance
 merges points closer than `relative_tolerance` times the bounding-box
 diagonal (uniform hash grid, and transitively: chains of close points merge).
*/
template <class Point_3>
std::vector<std::size_t> coincident_point_representatives(const std::vector<Point_3>& points,
                                                          double relative_tolerance)
{
  const std::size_t n = points.size();
  std::vector<std::size_t> rep(n);
  std::iota(rep.begin(), rep.end(), std::size_t(0));
  if(!(relative_tolerance >= 0.) || !std::isfinite(relative_tolerance))
    throw Geological_model_error("merge tolerance must be a finite number >= 0, got " +
                                 std::to_string(relative_tolerance));
  if(n < 2) return rep;

  std::vector<std::array<double, 3>> p(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    p[i] = {{CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z())}};
    // (sorting needs a strict weak order, which NaN breaks)
    if(!std::isfinite(p[i][0]) || !std::isfinite(p[i][1]) || !std::isfinite(p[i][2]))
      throw Geological_model_error("point " + std::to_string(i) + " has a non-finite coordinate (" +
                                   std::to_string(p[i][0]) + ", " + std::to_string(p[i][1]) + ", " +
                                   std::to_string(p[i][2]) + ")");
  }

  if(relative_tolerance == 0.)
  {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    // ties broken by index: the first of a run of equal points is the smallest index
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return p[a] < p[b] || (p[a] == p[b] && a < b);
    });
    for(std::size_t k = 1; k < n; ++k)
      if(p[order[k]] == p[order[k - 1]]) rep[order[k]] = rep[order[k - 1]];
    return rep;
  }

  std::array<double, 3> lo = p[0], hi = p[0];
  for(const auto& q : p)
    for(int d = 0; d < 3; ++d) { lo[d] = (std::min)(lo[d], q[d]); hi[d] = (std::max)(hi[d], q[d]); }
  double diag2 = 0;
  for(int d = 0; d < 3; ++d) diag2 += (hi[d] - lo[d]) * (hi[d] - lo[d]);
  const double diag = std::sqrt(diag2);
  const double tol = relative_tolerance * diag;
  // below ~1e-14 of the diagonal, doubles cannot tell "close" from "equal"
  if(relative_tolerance < 1e-14 || !(tol > 0.) || !std::isfinite(tol))
    return coincident_point_representatives(points, 0.);
  if(tol >= diag)
  {
    std::fill(rep.begin(), rep.end(), std::size_t(0));  // everything is within reach
    return rep;
  }
  const double tol2 = tol * tol;

  // cells of side tol/2 (diagonal < tol): points sharing a cell always merge,
  // points within tol lie at most two cells apart
  const double cell_size = 0.5 * tol;
  auto cell_coord = [&](double x, int d) -> std::int64_t {
    return static_cast<std::int64_t>(std::floor((x - lo[d]) / cell_size));  // < 2e14: no overflow
  };
  struct Key_hash
  {
    std::size_t operator()(const std::array<std::int64_t, 3>& k) const
    {
      std::uint64_t h = 1469598103934665603ull;
      for(std::int64_t v : k) { h ^= static_cast<std::uint64_t>(v); h *= 1099511628211ull; }
      return static_cast<std::size_t>(h);
    }
  };
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<std::size_t>, Key_hash> grid;
  grid.reserve(n);
  std::vector<std::array<std::int64_t, 3>> cell(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    cell[i] = {{cell_coord(p[i][0], 0), cell_coord(p[i][1], 1), cell_coord(p[i][2], 2)}};
    grid[cell[i]].push_back(i);
  }
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto unite = [&](std::size_t i, std::size_t j) {
    const std::size_t a = find_representative(parent, i), b = find_representative(parent, j);
    if(a < b) parent[b] = a; else if(b < a) parent[a] = b;
  };
  for(const auto& c : grid)
    for(std::size_t k = 1; k < c.second.size(); ++k) unite(c.second[0], c.second[k]);
  for(std::size_t i = 0; i < n; ++i)
    for(std::int64_t dx = -2; dx <= 2; ++dx)
      for(std::int64_t dy = -2; dy <= 2; ++dy)
        for(std::int64_t dz = -2; dz <= 2; ++dz)
        {
          if(dx == 0 && dy == 0 && dz == 0) continue;
          auto it = grid.find({{cell[i][0] + dx, cell[i][1] + dy, cell[i][2] + dz}});
          if(it == grid.end()) continue;
          for(std::size_t j : it->second)
          {
            if(j <= i || find_representative(parent, i) == find_representative(parent, j)) continue;
            double d2 = 0;
            for(int d = 0; d < 3; ++d) d2 += (p[i][d] - p[j][d]) * (p[i][d] - p[j][d]);
            if(d2 <= tol2) unite(i, j);
          }
        }
  for(std::size_t i = 0; i < n; ++i) rep[i] = find_representative(parent, i);
  return rep;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3IO

Merges the points of `model` that coincide, renumbers the triangles onto the
kept points and removes the points no triangle uses any more.

With `relative_tolerance == 0` (the default) only points with identical
coordinates are merged. With a positive value, points closer than
`relative_tolerance` times the diagonal of the model's bounding box are merged
(transitively) into the one with the smallest index, whose coordinates are
kept; values below 1e-14 are taken as 0. The cost is O(n log n) (sorting, or
a hash grid of cells of half the tolerance), not quadratic.

Triangles that lose a vertex by the merge (two corners becoming one point) are
not removed: `validate_geological_model()` reports them.

\returns the number of points removed.
\throws Geological_model_error if the tolerance is negative or not finite, or a
point has a non-finite coordinate.
*/
template <class GeomTraits>
std::size_t merge_coincident_points(Geological_model_3<GeomTraits>& model, double relative_tolerance = 0.)
{
  const std::vector<std::size_t> rep =
    internal::coincident_point_representatives(model.points(), relative_tolerance);
  const std::size_t before = model.number_of_points();
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    typename Geological_model_3<GeomTraits>::Triangle tri = model.triangle(t);
    for(std::size_t& v : tri) v = rep[v];
    model.set_triangle(t, tri);
  }
  model.remove_unused_points();
  return before - model.number_of_points();
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_MERGE_COINCIDENT_POINTS_H
