// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test model: a box of layers between tilted grid surfaces whose quads are
// split along the diagonal CGAL's symbolic perturbation avoids.

#ifndef BUBBLE_MESH_3_TEST_TILTED_GRID_BOX_H
#define BUBBLE_MESH_3_TEST_TILTED_GRID_BOX_H

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

// A box of layers between grid surfaces z = levels[k] + x / 4 (tilted planes,
// so that the points of two surfaces are not cospherical in boxes, and the
// outer top is a plane of the convex hull that no axis holds: Steiner points
// on it are rounded), closed by vertical walls (one row of quads per layer).
// Region k+1 is the layer above surface k. Each quad (u,v)-(u+1,v+1) of a
// surface's parameter grid is a rectangle, except on the walls y = 0 and
// y = ny (parallelograms). The rectangles are split along the diagonal
// through their corners (u,v) and (u+1,v+1), which holds the
// lexicographically largest corner and is the one CGAL's perturbation avoids;
// the parallelograms along their shorter diagonal, the Delaunay one. With
// `mixed`, two quads in five of the layer surfaces take the other diagonal.
template <typename Model>
Model make_tilted_grid_box(int nx, int ny, const std::vector<double>& levels, bool mixed = false)
{
  typedef typename Model::Point_3 Point;
  Model m;
  const std::size_t nl = levels.size() - 1;
  for(std::size_t k = 0; k < nl; ++k) m.add_region("layer " + std::to_string(k));
  std::map<std::array<double, 3>, std::size_t> index;
  auto point = [&](const std::array<double, 3>& p) {
    auto it = index.find(p);
    if(it != index.end()) return it->second;
    const std::size_t i = m.add_point(Point(p[0], p[1], p[2]));
    index.emplace(p, i);
    return i;
  };
  // a grid surface f(u,v), u in [0,nu], v in [0,nv], in one patch whose
  // positive side (the normal of (f(0,0), f(1,0), f(1,1))) is region `pos`
  auto grid = [&](const std::string& name, int nu, int nv, std::size_t pos, std::size_t neg, bool other_diagonal,
                  bool mix, auto f) {
    const std::size_t patch = m.add_patch(name, pos, neg);
    for(int u = 0; u < nu; ++u)
      for(int v = 0; v < nv; ++v)
      {
        const std::size_t a = point(f(u, v)), b = point(f(u + 1, v));
        const std::size_t c = point(f(u + 1, v + 1)), d = point(f(u, v + 1));
        if(other_diagonal != (mix && (7 * u + 3 * v) % 5 < 2))
        {
          m.add_triangle(a, b, d, patch);
          m.add_triangle(b, c, d, patch);
        }
        else
        {
          m.add_triangle(a, b, c, patch);
          m.add_triangle(a, c, d, patch);
        }
      }
  };
  typedef std::array<double, 3> A3;
  auto z = [&](std::size_t k, double x) { return levels[k] + 0.25 * x; };
  for(std::size_t k = 0; k <= nl; ++k)
    // normal (1,0,1/4) x (0,1,0), upwards: the region above on the positive side
    grid("surface " + std::to_string(k), nx, ny, k < nl ? k + 1 : 0, k, false, mixed,
         [&](int u, int v) { return A3{{double(u), double(v), z(k, u)}}; });
  for(std::size_t k = 0; k < nl; ++k)
  {
    // y = 0 wall, parameters (x, s): normal -y, outwards
    grid("south " + std::to_string(k), nx, 1, 0, k + 1, true, false,
         [&](int u, int s) { return A3{{double(u), 0., z(k + s, u)}}; });
    grid("north " + std::to_string(k), nx, 1, k + 1, 0, true, false,
         [&](int u, int s) { return A3{{double(u), double(ny), z(k + s, u)}}; });
    // x = 0 wall, parameters (y, s): normal +x, inwards
    grid("west " + std::to_string(k), ny, 1, k + 1, 0, false, false,
         [&](int u, int s) { return A3{{0., double(u), z(k + s, 0)}}; });
    grid("east " + std::to_string(k), ny, 1, 0, k + 1, false, false,
         [&](int u, int s) { return A3{{double(nx), double(u), z(k + s, nx)}}; });
  }
  return m;
}

#endif // BUBBLE_MESH_3_TEST_TILTED_GRID_BOX_H
