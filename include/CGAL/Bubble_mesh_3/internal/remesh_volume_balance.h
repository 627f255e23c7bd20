// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_VOLUME_BALANCE_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_VOLUME_BALANCE_H

// Region volumes kept after re-meshing. A re-meshed triangle whose points lie
// on a curved (faceted) input patch is a chord across the input's creases: it
// cuts off a little volume on one side of the patch and adds it on the other.
// Summed over a region's boundary that leaves a relative error of about 1e-4
// on real horizons. Sliding a free point along the input surface keeps it on
// the surface but changes how much each of its triangles cuts off, so the
// free points can trade those errors until every region's volume is the
// input's again: a Newton iteration on the region volumes, where each step is
// the smallest move (in the least-squares sense) of the free points along
// their input triangles' planes that corrects every region at once, projected
// back onto the patch. The local deviation (a chord's distance to the input)
// stays what the size allows; what is kept is each region's volume, that is,
// its weight in a stability analysis. Curve points do not move, so the curves
// keep their distance to the input polylines, nor do the points near curves
// and near poor triangles (see `frozen` below). Each region aims at what it
// can reach (see `reach` below: where the outer walls are flat, the regions
// share what a region no point can change lost). A step that brings no region
// nearer is undone and ends the iteration (where the patches lie flat the
// solve has nothing to hold on to). `remesh_surfaces()` runs it on
// request (`keep_region_volumes(true)`): it keeps every median of the
// tetrahedra but moves the single worst cell either way (bench/README.md,
// session 57).

#include <CGAL/Bubble_mesh_3/internal/centred_coordinates.h>
#include <CGAL/Bubble_mesh_3/internal/union_find.h>
#include <CGAL/Bubble_mesh_3/internal/vertex_angle.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

struct Volume_balance_result
{
  double error_before = 0.;       // largest relative region volume error, before
  double error_after = 0.;        // and after
  std::size_t iterations = 0;     // Newton steps taken
  std::size_t moved_points = 0;   // free points that moved
  double largest_move = 0.;       // largest distance a point moved, over its local size
  std::vector<double> relative_errors; // |volume - target| / |target| of each region at the end (entry 0: 0)
  // the same against what the region can reach (below), and the largest of them
  std::vector<double> residual_errors;
  double residual_after = 0.;
  std::vector<char> immovable;         // regions none of whose points may move
};

// Solves `m x = b` (n x n, symmetric positive semi-definite) by Gaussian
// elimination with partial pivoting; a pivot under `floor` (a region whose
// volume no free point can change) leaves its unknown at 0.
inline std::vector<double> solve_small_system(std::vector<std::vector<double> > m, std::vector<double> b, double floor)
{
  const std::size_t n = b.size();
  std::vector<std::size_t> pivot_col(n, n);
  std::size_t row = 0;
  for(std::size_t col = 0; col < n && row < n; ++col)
  {
    std::size_t best = row;
    for(std::size_t r = row + 1; r < n; ++r)
      if(std::abs(m[r][col]) > std::abs(m[best][col])) best = r;
    if(!(std::abs(m[best][col]) > floor)) continue;
    std::swap(m[best], m[row]);
    std::swap(b[best], b[row]);
    for(std::size_t r = 0; r < n; ++r)
    {
      if(r == row || m[r][col] == 0.) continue;
      const double f = m[r][col] / m[row][col];
      for(std::size_t c = col; c < n; ++c) m[r][c] -= f * m[row][c];
      b[r] -= f * b[row];
    }
    pivot_col[row] = col;
    ++row;
  }
  std::vector<double> x(n, 0.);
  for(std::size_t r = 0; r < row; ++r) x[pivot_col[r]] = b[r] / m[r][pivot_col[r]];
  return x;
}

// `patch_triangles[p]` are the re-meshed triangles of patch p (indices into
// `points`), oriented as the patch; `sides[p]` is (negative, positive) region
// of p (0: outside); `target[r]` the volume region r must have (entry 0
// unused) when `balanced[r]` is set; the other regions count as the outside. `project(q, p)` returns the closest point of input patch p to q and
// the unit normal of the input triangle it lies on; `size(q, p)` the local
// target edge length. Points with `fixed` set never move. A move is kept only
// when no triangle around the point turns over and the smallest angle around
// it stays at least min(its old value, `angle_bound`); each step moves no
// point farther than `max_step` times its local size.
template <class Point_3, class Project, class Size>
Volume_balance_result balance_region_volumes(std::vector<Point_3>& points,
                                             const std::vector<std::vector<std::array<std::size_t, 3> > >& patch_triangles,
                                             const std::vector<char>& fixed,
                                             const std::vector<std::pair<std::size_t, std::size_t> >& sides,
                                             const std::vector<double>& target, const std::vector<char>& balanced,
                                             const Centred_point& centre,
                                             const Project& project, const Size& size, double angle_bound,
                                             double tolerance = 1e-9, double max_step = 0.1,
                                             std::size_t max_iterations = 50)
{
  typedef std::array<double, 3> Vec;
  typedef std::array<std::size_t, 3> Triangle;
  Volume_balance_result result;
  const std::size_t n = target.size();
  auto sub = [](const Vec& a, const Vec& b) { return Vec{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; };
  auto cross = [](const Vec& a, const Vec& b) {
    return Vec{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  };
  auto dot = [](const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto c_of = [&](std::size_t v) { return centred(points[v], centre); };

  // the sides that count: a region left out is the outside here
  std::vector<std::pair<std::size_t, std::size_t> > kept(sides.size());
  for(std::size_t p = 0; p < sides.size(); ++p)
    kept[p] = std::make_pair(balanced[sides[p].first] ? sides[p].first : 0,
                             balanced[sides[p].second] ? sides[p].second : 0);
  // the triangles around each free point of a patch between two balanced
  // regions, or one and the outside (a fault inside one region encloses nothing)
  std::vector<std::size_t> patch_of(points.size(), std::size_t(-1));
  std::vector<std::vector<std::size_t> > around(points.size());
  for(std::size_t p = 0; p < patch_triangles.size(); ++p)
  {
    if(kept[p].first == kept[p].second) continue;
    for(std::size_t t = 0; t < patch_triangles[p].size(); ++t)
      for(std::size_t v : patch_triangles[p][t])
        if(!fixed[v])
        {
          patch_of[v] = p;
          around[v].push_back(t);
        }
  }
  std::vector<std::size_t> free_points;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(patch_of[v] != std::size_t(-1)) free_points.push_back(v);
  // Where two patches meet (a curve) they come closest, and near a triangle
  // under the angle bound (a strip narrower than the size, between curve
  // points) the tetrahedra are as fragile as they get: the surface recovery
  // then needs its Steiner points there. On modelA5, slides next to its fault
  // strips made the recovery split curve edges and left a cell of 0.15
  // degrees. The points within two edges of a curve point or of such a
  // triangle stay where the re-meshing put them.
  std::vector<char> frozen(fixed.begin(), fixed.end());
  frozen.resize(points.size(), 0);
  for(const auto& tris : patch_triangles)
    for(const Triangle& t : tris)
      if(min_angle_degrees(points[t[0]], points[t[1]], points[t[2]]) < angle_bound)
        for(std::size_t v : t) frozen[v] = 1;
  for(int ring = 0; ring < 2; ++ring)
  {
    std::vector<char> grown = frozen;
    for(const auto& tris : patch_triangles)
      for(const Triangle& t : tris)
        if(frozen[t[0]] || frozen[t[1]] || frozen[t[2]])
          for(std::size_t v : t) grown[v] = 1;
    frozen.swap(grown);
  }
  // the unit normal of the input triangle under each free point
  std::vector<Vec> normal(points.size(), Vec{{0., 0., 0.}});
  auto set_normal = [&](std::size_t v, const auto& nrm) {
    normal[v] = Vec{{CGAL::to_double(nrm.x()), CGAL::to_double(nrm.y()), CGAL::to_double(nrm.z())}};
  };
  for(std::size_t v : free_points) set_normal(v, project(points[v], patch_of[v]).second);

  auto volumes = [&]() {
    std::vector<double> vol(n, 0.);
    for(std::size_t p = 0; p < patch_triangles.size(); ++p)
    {
      if(sides[p].first == sides[p].second) continue;
      double sum = 0.;
      for(const Triangle& t : patch_triangles[p]) sum += signed_volume(c_of(t[0]), c_of(t[1]), c_of(t[2]));
      vol[sides[p].first] += sum;
      vol[sides[p].second] -= sum;
    }
    return vol;
  };
  // What each region can reach. Regions linked by free points form groups; a
  // group that no free point links to the outside (a model whose outer walls
  // are flat) keeps its total volume whatever the slides, and its targets may
  // not add up to it: a region none of whose points may move (a coarse lens
  // between curves and needles, bench/make_graben_model.py) keeps what its
  // chords cut off, and that volume went to its neighbours. What the group's
  // targets miss is shared among its regions in proportion to their volumes,
  // so that none is off by more than needed and none holds back the others.
  std::vector<double> reach(target.begin(), target.end());
  // |volume - aim| / |target| of region r, and the largest over the balanced regions
  auto relative_error = [&](const std::vector<double>& vol, std::size_t r, const std::vector<double>& aim) {
    return target[r] != 0. ? std::abs(vol[r] - aim[r]) / std::abs(target[r]) : 0.;
  };
  auto worst_error = [&](const std::vector<double>& vol, const std::vector<double>& aim) {
    double e = 0.;
    for(std::size_t r = 1; r < n; ++r)
      if(balanced[r]) e = (std::max)(e, relative_error(vol, r, aim));
    return e;
  };
  result.immovable.assign(n, 0);
  auto fan_min_angle = [&](std::size_t v) {
    double a = 180.;
    for(std::size_t t : around[v])
    {
      const Triangle& tri = patch_triangles[patch_of[v]][t];
      a = (std::min)(a, min_angle_degrees(points[tri[0]], points[tri[1]], points[tri[2]]));
    }
    return a;
  };
  auto area_vector = [&](const Triangle& tri) {
    const Vec a = c_of(tri[0]);
    const Vec n2 = cross(sub(c_of(tri[1]), a), sub(c_of(tri[2]), a));
    return Vec{{0.5 * n2[0], 0.5 * n2[1], 0.5 * n2[2]}};
  };

  std::vector<double> vol = volumes();
  result.error_before = result.error_after = result.residual_after = worst_error(vol, target);
  std::vector<Vec> gradient(points.size());
  std::vector<double> moved(points.size(), 0.);
  for(; result.iterations < max_iterations; ++result.iterations)
  {
    // d(volume of the negative side)/d(point), within the input triangle's
    // plane: a third of the fan's area vector (the fan is closed around a
    // free point), less its normal part
    std::vector<std::vector<double> > m(n, std::vector<double>(n, 0.));
    for(std::size_t v : free_points)
    {
      gradient[v] = Vec{{0., 0., 0.}};
      if(frozen[v]) continue;
      Vec g{{0., 0., 0.}};
      for(std::size_t t : around[v])
      {
        const Vec a = area_vector(patch_triangles[patch_of[v]][t]);
        for(int k = 0; k < 3; ++k) g[k] += a[k] / 3.;
      }
      const Vec& u = normal[v];
      const double gn = dot(g, u);
      for(int k = 0; k < 3; ++k) g[k] -= gn * u[k];
      gradient[v] = g;
      const double c = dot(g, g);
      const std::size_t a = kept[patch_of[v]].first, b = kept[patch_of[v]].second;
      m[a][a] += c;
      m[b][b] += c;
      m[a][b] -= c;
      m[b][a] -= c;
    }
    double largest = 0.;
    for(std::size_t r = 1; r < n; ++r) largest = (std::max)(largest, m[r][r]);
    if(!(largest > 0.)) break;
    const double link = 1e-12 * largest;
    std::vector<std::size_t> group = uf_singletons(n);
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = a + 1; b < n; ++b)
        if(std::abs(m[a][b]) > link) uf_union(group, a, b);
    std::vector<double> missed(n, 0.), weight(n, 0.);
    std::vector<std::size_t> anchor(n, 0);
    for(std::size_t r = 1; r < n; ++r)
    {
      result.immovable[r] = balanced[r] && !(m[r][r] > link);
      if(!balanced[r]) continue;
      const std::size_t g = uf_find(group, r);
      missed[g] += target[r] - vol[r];
      weight[g] += std::abs(target[r]);
      if(anchor[g] == 0 || m[r][r] > m[anchor[g]][anchor[g]]) anchor[g] = r;
    }
    const std::size_t outside = uf_find(group, 0);
    // the region whose multiplier is 0 in a group apart from the outside
    auto is_anchor = [&](std::size_t r) {
      const std::size_t g = uf_find(group, r);
      return g != outside && anchor[g] == r;
    };
    for(std::size_t r = 1; r < n; ++r)
    {
      const std::size_t g = uf_find(group, r);
      reach[r] = (!balanced[r] || g == outside || !(weight[g] > 0.)) ? target[r]
                                                                       : target[r] - missed[g] * std::abs(target[r]) / weight[g];
    }
    const double residual_before = worst_error(vol, reach);
    result.residual_after = residual_before;
    if(!(residual_before > tolerance)) break;
    // the outside (region 0) is not kept: its row and column go; a group apart
    // from it has its anchor's multiplier at 0 (only differences move points)
    std::vector<std::vector<double> > m1(n - 1, std::vector<double>(n - 1, 0.));
    std::vector<double> rhs(n - 1, 0.);
    for(std::size_t r = 1; r < n; ++r)
    {
      if(is_anchor(r))
      {
        m1[r - 1][r - 1] = 1.;
        continue;
      }
      rhs[r - 1] = balanced[r] ? reach[r] - vol[r] : 0.;
      for(std::size_t s = 1; s < n; ++s)
        if(!is_anchor(s)) m1[r - 1][s - 1] = m[r][s];
    }
    const std::vector<double> lambda1 = solve_small_system(m1, rhs, link);
    std::vector<double> lambda(n, 0.);
    for(std::size_t r = 1; r < n; ++r) lambda[r] = lambda1[r - 1];

    // the step, shortened so that no point moves farther than max_step sizes
    double scale = 1.;
    for(std::size_t v : free_points)
    {
      const double f = lambda[kept[patch_of[v]].first] - lambda[kept[patch_of[v]].second];
      const double d = std::abs(f) * std::sqrt(dot(gradient[v], gradient[v]));
      if(d == 0.) continue;
      const double h = size(points[v], patch_of[v]);
      if(d > max_step * h) scale = (std::min)(scale, max_step * h / d);
    }
    std::size_t moves = 0;
    const std::vector<Point_3> before_step = points;
    const std::vector<Vec> normals_before_step = normal;
    const std::vector<double> moved_before_step = moved;
    for(std::size_t v : free_points)
    {
      const double f = scale * (lambda[kept[patch_of[v]].first] - lambda[kept[patch_of[v]].second]);
      const Vec& g = gradient[v];
      if(f == 0. || dot(g, g) == 0.) continue;
      const Point_3 old = points[v];
      const double before = fan_min_angle(v);
      std::vector<Vec> normals;
      for(std::size_t t : around[v]) normals.push_back(area_vector(patch_triangles[patch_of[v]][t]));
      const Point_3 wanted(CGAL::to_double(old.x()) + f * g[0], CGAL::to_double(old.y()) + f * g[1],
                           CGAL::to_double(old.z()) + f * g[2]);
      const auto landed = project(wanted, patch_of[v]);
      points[v] = landed.first;
      bool ok = fan_min_angle(v) >= (std::min)(before, angle_bound);
      for(std::size_t i = 0; ok && i < around[v].size(); ++i)
        ok = dot(normals[i], area_vector(patch_triangles[patch_of[v]][around[v][i]])) > 0.;
      if(!ok)
      {
        points[v] = old;
        frozen[v] = 1; // the solve counts on every point it moves: leave this one out from now on
        continue;
      }
      set_normal(v, landed.second);
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(old, points[v])));
      moved[v] += d / size(points[v], patch_of[v]);
      ++moves;
    }
    const std::vector<double> vol_after = volumes();
    // A step that brings no region nearer what it can reach is undone, and the
    // balance ends: where the patches lie flat (a faceted body's, between its
    // kept creases) slides change no volume, and the solve's steps there would
    // only wander
    if(!(worst_error(vol_after, reach) < residual_before))
    {
      points = before_step;
      normal = normals_before_step;
      moved = moved_before_step;
      break;
    }
    vol = vol_after;
    result.error_after = worst_error(vol, target);
    result.residual_after = worst_error(vol, reach);
    if(moves == 0) break;
  }
  result.relative_errors.assign(n, 0.);
  result.residual_errors.assign(n, 0.);
  for(std::size_t r = 1; r < n; ++r)
  {
    result.relative_errors[r] = relative_error(vol, r, target);
    result.residual_errors[r] = relative_error(vol, r, reach);
  }
  for(std::size_t v : free_points)
    if(moved[v] > 0.)
    {
      ++result.moved_points;
      result.largest_move = (std::max)(result.largest_move, moved[v]);
    }
  return result;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_VOLUME_BALANCE_H
