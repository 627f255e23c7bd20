// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Tiny weights on the input points that make the input's diagonals of
// cocircular quadrilaterals the ones the regular triangulation picks.
//
// Two coplanar input triangles (a,c,b) and (c,a,d) whose four points are
// cocircular (rectangles of a planar grid) leave both diagonals of the quad
// Delaunay; CGAL breaks the tie by a symbolic perturbation that follows the
// lexicographic order of the points, not the input, so a whole grid can lose
// every diagonal and need Steiner points on each. Mesh_3's triangulation is a
// regular one: with weights, the tie goes to the diagonal whose ends weigh
// more. To first order, the power test of the quad against an apex only sees
// the four weights, through the linear form
//   area(bcd) w_a + area(abd) w_c - area(acd) w_b - area(abc) w_d
// (the apex's own coefficient is the orientation of the four coplanar points,
// zero): ac wins when it is positive. The weights come from a quadratic along
// the main direction of each connected set of such quads (a planar grid with
// all its diagonals one way is the regular triangulation of points lifted on
// a paraboloid squeezed along that direction), then from projections onto
// the constraints it still violates (grids with diagonals both ways). They
// are scaled so far below the squared input edge lengths that no point gets
// hidden and no other decision of the triangulation changes except ties;
// the triangulation stays a valid regular triangulation, so later insertions
// and removals (sliver removal) stay consistent with it.

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_COCIRCULAR_WEIGHTS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_COCIRCULAR_WEIGHTS_H


#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/union_find.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// One quad: diagonal (a,c) wanted over (b,d), with the linear form's coefficients.
struct Cocircular_quad
{
  std::array<std::size_t, 4> v; // a, c, b, d
  std::array<double, 4> coef;   // +, +, -, - (signs included)
  double margin;
};

/// the quads of coplanar, cocircular pairs of input triangles sharing an edge
template <class GeomTraits>
std::vector<Cocircular_quad> cocircular_quads(const Geological_model_3<GeomTraits>& model)
{
  typedef typename GeomTraits::Point_3 Point_3;
  std::vector<std::pair<std::uint64_t, std::size_t> > half; // (edge key, triangle)
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = model.triangle(t)[k], b = model.triangle(t)[(k + 1) % 3];
      half.emplace_back((std::uint64_t((std::min)(a, b)) << 32) | std::uint64_t((std::max)(a, b)), t);
    }
  std::sort(half.begin(), half.end());
  auto third = [&](std::size_t t, std::size_t a, std::size_t c) {
    for(std::size_t x : model.triangle(t))
      if(x != a && x != c) return x;
    return a;
  };
  auto area = [](const Point_3& p, const Point_3& q, const Point_3& r) {
    return std::sqrt(CGAL::to_double(CGAL::squared_area(p, q, r)));
  };
  std::vector<Cocircular_quad> quads;
  for(std::size_t i = 0; i < half.size();)
  {
    std::size_t j = i;
    while(j < half.size() && half[j].first == half[i].first) ++j;
    const std::size_t a = std::size_t(half[i].first >> 32), c = std::size_t(half[i].first & 0xffffffffu);
    for(std::size_t x = i; x < j; ++x)
      for(std::size_t y = x + 1; y < j; ++y)
      {
        const std::size_t b = third(half[x].second, a, c), d = third(half[y].second, a, c);
        if(b == d) continue;
        const Point_3 &pa = model.point(a), &pb = model.point(b), &pc = model.point(c), &pd = model.point(d);
        if(CGAL::orientation(pa, pb, pc, pd) != CGAL::COPLANAR) continue;
        if(CGAL::coplanar_orientation(pa, pc, pb, pd) != CGAL::NEGATIVE) continue; // b, d on both sides of ac
        if(CGAL::coplanar_side_of_bounded_circle(pa, pb, pc, pd) != CGAL::ON_BOUNDARY) continue;
        Cocircular_quad q;
        q.v = {{a, c, b, d}};
        q.coef = {{area(pb, pc, pd), area(pa, pb, pd), -area(pa, pc, pd), -area(pa, pb, pc)}};
        const double m = (std::max)({q.coef[0], q.coef[1], -q.coef[2], -q.coef[3]});
        for(double& k : q.coef) k /= m;
        q.margin = 0.;
        quads.push_back(q);
      }
    i = j;
  }
  return quads;
}

/*
Weights for the model's points (all zero when the input has no cocircular
quad): see the top of this file. Deterministic: it depends on the model only.
*/
template <class GeomTraits>
std::vector<double> cocircular_tie_weights(const Geological_model_3<GeomTraits>& model)
{
  const std::size_t np = model.number_of_points();
  std::vector<double> weights(np, 0.);
  std::vector<Cocircular_quad> quads = cocircular_quads(model);
  if(quads.empty()) return weights;
  auto coords = [&](std::size_t i) {
    const auto& p = model.point(i);
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };

  // connected sets of quads (union-find over their points)
  std::vector<std::size_t> parent = uf_singletons(np);
  for(const Cocircular_quad& q : quads)
    for(int k = 1; k < 4; ++k) uf_union(parent, q.v[0], q.v[k]);

  // per set: the main direction of its wanted diagonals (power iteration on
  // the sum of u u^T, from the first diagonal), and s = squared distance
  // along it, over the set's squared extent. One pass over the quads and
  // their points: a model can hold many small sets.
  std::vector<double> s(np, 0.);
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> slot(np, none); // set index of a root
  std::vector<std::size_t> roots;
  for(const Cocircular_quad& q : quads)
  {
    const std::size_t r = uf_find(parent, q.v[0]);
    if(slot[r] == none) { slot[r] = roots.size(); roots.push_back(r); }
  }
  auto set_of = [&](std::size_t v) { return slot[uf_find(parent, v)]; };
  std::vector<std::array<double, 9> > m(roots.size(), std::array<double, 9>{{0, 0, 0, 0, 0, 0, 0, 0, 0}});
  std::vector<std::array<double, 3> > dir(roots.size(), std::array<double, 3>{{0, 0, 0}});
  for(const Cocircular_quad& q : quads)
  {
    const std::size_t k = set_of(q.v[0]);
    const std::array<double, 3> a = coords(q.v[0]), c = coords(q.v[1]);
    std::array<double, 3> u = {{c[0] - a[0], c[1] - a[1], c[2] - a[2]}};
    const double l = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for(double& x : u) x /= l;
    if(dir[k][0] == 0. && dir[k][1] == 0. && dir[k][2] == 0.) dir[k] = u;
    for(int r = 0; r < 3; ++r)
      for(int j = 0; j < 3; ++j) m[k][3 * r + j] += u[r] * u[j];
  }
  for(std::size_t k = 0; k < roots.size(); ++k)
    for(int it = 0; it < 64; ++it)
    {
      std::array<double, 3> next = {{0, 0, 0}};
      for(int r = 0; r < 3; ++r)
        for(int j = 0; j < 3; ++j) next[r] += m[k][3 * r + j] * dir[k][j];
      const double l = std::sqrt(next[0] * next[0] + next[1] * next[1] + next[2] * next[2]);
      if(!(l > 0.)) break;
      for(int r = 0; r < 3; ++r) dir[k][r] = next[r] / l;
    }
  // the points of the sets are the quads' corners
  std::vector<std::size_t> members;
  for(const Cocircular_quad& q : quads) members.insert(members.end(), q.v.begin(), q.v.end());
  std::sort(members.begin(), members.end());
  members.erase(std::unique(members.begin(), members.end()), members.end());
  auto offset = [&](std::size_t i) {
    const std::array<double, 3> p = coords(i), o = coords(roots[set_of(i)]);
    return std::array<double, 3>{{p[0] - o[0], p[1] - o[1], p[2] - o[2]}};
  };
  std::vector<double> extent2(roots.size(), 0.);
  for(std::size_t i : members)
  {
    const std::array<double, 3> d = offset(i);
    double& e = extent2[set_of(i)];
    e = (std::max)(e, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
  for(std::size_t i : members)
  {
    const std::array<double, 3> d = offset(i);
    const std::array<double, 3>& u = dir[set_of(i)];
    const double along = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
    s[i] = along * along / extent2[set_of(i)];
  }
  // each quad asks for a margin of a thousandth of what a quad of its size
  // gets from a quadratic along its own diagonal
  for(Cocircular_quad& q : quads)
  {
    const std::array<double, 3> a = coords(q.v[0]), c = coords(q.v[1]);
    const double d2 = (c[0] - a[0]) * (c[0] - a[0]) + (c[1] - a[1]) * (c[1] - a[1]) + (c[2] - a[2]) * (c[2] - a[2]);
    q.margin = 1e-3 * d2 / extent2[set_of(q.v[0])];
  }

  // the quads the quadratic does not serve: projections onto their
  // constraints, in a fixed order, until all hold or the rounds run out
  auto form = [&](const Cocircular_quad& q) {
    double f = 0.;
    for(int k = 0; k < 4; ++k) f += q.coef[k] * s[q.v[k]];
    return f;
  };
  for(int round = 0; round < 200; ++round)
  {
    bool changed = false;
    for(const Cocircular_quad& q : quads)
    {
      const double f = form(q);
      if(f >= q.margin) continue;
      double n2 = 0.;
      for(double k : q.coef) n2 += k * k;
      const double step = (2. * q.margin - f) / n2;
      for(int k = 0; k < 4; ++k) s[q.v[k]] += step * q.coef[k];
      changed = true;
    }
    if(!changed) break;
  }

  // scale: the largest weight difference far below the shortest input edge
  // squared, so that no point hides another
  double shortest2 = std::numeric_limits<double>::infinity();
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    for(int k = 0; k < 3; ++k)
      shortest2 = (std::min)(shortest2, CGAL::to_double(CGAL::squared_distance(
                                          model.point(model.triangle(t)[k]), model.point(model.triangle(t)[(k + 1) % 3]))));
  // a weight added to a whole set changes nothing in it: the lightest point
  // of each set weighs zero, like the points of no set
  std::vector<double> lightest(np, std::numeric_limits<double>::infinity());
  for(const Cocircular_quad& q : quads)
    for(std::size_t v : q.v) lightest[uf_find(parent, v)] = (std::min)(lightest[uf_find(parent, v)], s[v]);
  double hi = 0.;
  for(const Cocircular_quad& q : quads)
    for(std::size_t v : q.v) hi = (std::max)(hi, s[v] - lightest[uf_find(parent, v)]);
  if(!(hi > 0.) || !(shortest2 > 0.) || !std::isfinite(shortest2)) return weights;
  const double scale = std::ldexp(shortest2, -40) / hi;
  for(const Cocircular_quad& q : quads)
    for(std::size_t v : q.v) weights[v] = (s[v] - lightest[uf_find(parent, v)]) * scale;
  return weights;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_COCIRCULAR_WEIGHTS_H
