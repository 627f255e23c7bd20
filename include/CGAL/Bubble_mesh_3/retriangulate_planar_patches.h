// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_RETRIANGULATE_PLANAR_PATCHES_H
#define CGAL_BUBBLE_MESH_3_RETRIANGULATE_PLANAR_PATCHES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/mesh_quality.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

What `retriangulate_planar_patches()` did. Angles are in degrees.
*/
struct Planar_retriangulation_report
{
  std::size_t number_of_pieces = 0;          ///< planar pieces of two or more triangles found
  std::size_t number_of_retriangulated_pieces = 0; ///< of those, the pieces given a new triangulation
  std::size_t number_of_triangles_in_pieces = 0;   ///< triangles of the re-triangulated pieces (same before and after)
  double min_angle_before = 180.;            ///< smallest triangle angle of the re-triangulated pieces, before
  double min_angle_after = 180.;             ///< the same, after
};

namespace internal {

template <class Point_3>
double smallest_triangle_angle(const Point_3& a, const Point_3& b, const Point_3& c)
{
  auto xyz = [](const Point_3& p) {
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  return smallest_triangle_angle(xyz(a), xyz(b), xyz(c)); // mesh_quality.h
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Copies `input` to `output` with every planar piece of a patch given the
constrained Delaunay triangulation of its own points. A planar piece is a
largest set of exactly coplanar, consistently oriented triangles of one patch
joined by edges that no other triangle uses. Points, regions and patches are
the same; each piece covers the same part of its plane with as many
triangles as before, and only edges inside a piece change. Triangles of
other pieces keep their index order and source.

Why: generated box walls and flat tops often come as fans of needles (edges
of kilometres meeting at a fraction of a degree). A tetrahedron on such a
triangle is poor whatever the bubbles do, and recovering it in the
tetrahedralization takes thousands of Steiner points. The surface itself,
as a set of points of space, is kept exactly.

A piece is left as it was when its triangulation cannot be checked to cover
it exactly (a point on one of its constraints, a boundary that crosses
itself, a triangle that flips in floating point).

The model must be valid (`validate_geological_model()`).
*/
template <class GeomTraits>
Planar_retriangulation_report retriangulate_planar_patches(const Geological_model_3<GeomTraits>& input,
                                                           Geological_model_3<GeomTraits>& output)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename GeomTraits::Point_2 Point_2;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, GeomTraits>         Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<GeomTraits>                      Cfb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, GeomTraits, Cfb>              Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb>                                 Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<GeomTraits, Tds, CGAL::No_constraint_intersection_tag> CDT;

  Planar_retriangulation_report report;
  const std::size_t nt = input.number_of_triangles(), np = input.number_of_points();

  // the edges: triangles of each (by sorted point pair)
  auto key = [np](std::size_t a, std::size_t b) {
    if(a > b) std::swap(a, b);
    return std::uint64_t(a) * std::uint64_t(np) + std::uint64_t(b);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t> > edge_triangles;
  for(std::size_t t = 0; t < nt; ++t)
    for(int k = 0; k < 3; ++k)
      edge_triangles[key(input.triangle(t)[k], input.triangle(t)[(k + 1) % 3])].push_back(t);

  // whether `t` runs from a to b (else from b to a)
  auto runs = [&](std::size_t t, std::size_t a, std::size_t b) {
    const auto& tri = input.triangle(t);
    for(int k = 0; k < 3; ++k)
      if(tri[k] == a && tri[(k + 1) % 3] == b) return true;
    return false;
  };
  // edges inside a piece: two triangles of one patch, coplanar, oriented alike
  auto is_free = [&](std::size_t a, std::size_t b, const std::vector<std::size_t>& ts) {
    if(ts.size() != 2) return false;
    const std::size_t t1 = ts[0], t2 = ts[1];
    if(input.patch_of_triangle(t1) != input.patch_of_triangle(t2)) return false;
    if(runs(t1, a, b) == runs(t2, a, b)) return false;
    const auto& u = input.triangle(t1);
    for(std::size_t x : input.triangle(t2))
      if(CGAL::orientation(input.point(u[0]), input.point(u[1]), input.point(u[2]), input.point(x)) != CGAL::COPLANAR)
        return false;
    return true;
  };

  std::vector<std::size_t> parent(nt);
  for(std::size_t t = 0; t < nt; ++t) parent[t] = t;
  auto find = [&](std::size_t t) {
    while(parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  std::unordered_map<std::uint64_t, char> free_edge;
  for(std::size_t t = 0; t < nt; ++t)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = input.triangle(t)[k], b = input.triangle(t)[(k + 1) % 3];
      const std::uint64_t e = key(a, b);
      if(free_edge.count(e)) continue;
      const std::vector<std::size_t>& ts = edge_triangles[e];
      const bool f = is_free(a, b, ts);
      free_edge[e] = f;
      if(!f) continue;
      const std::size_t r1 = find(ts[0]), r2 = find(ts[1]);
      if(r1 != r2) parent[(std::max)(r1, r2)] = (std::min)(r1, r2);
    }
  std::vector<std::vector<std::size_t> > pieces(nt); // by root, in triangle order
  for(std::size_t t = 0; t < nt; ++t) pieces[find(t)].push_back(t);

  // the triangles that replace piece `ts`, or nothing if the check fails
  auto retriangulate = [&](const std::vector<std::size_t>& ts, std::vector<std::array<std::size_t, 3> >& out) {
    out.clear();
    const auto& t0 = input.triangle(ts[0]);
    const Point_3& o = input.point(t0[0]);
    const Vector_3 n = CGAL::cross_product(input.point(t0[1]) - o, input.point(t0[2]) - o);
    // exact orientation test: the projection dropping the normal's largest coordinate
    int axis = 0;
    for(int i = 1; i < 3; ++i)
      if(std::abs(CGAL::to_double(n[i])) > std::abs(CGAL::to_double(n[axis]))) axis = i;
    auto project = [axis](const Point_3& p) {
      return Point_2(p[(axis + 1) % 3], p[(axis + 2) % 3]);
    };
    const CGAL::Orientation up = CGAL::orientation(project(o), project(input.point(t0[1])), project(input.point(t0[2])));
    // an orthonormal frame of the plane for the Delaunay criterion (the
    // projection above would stretch a tilted plane)
    const Vector_3 e1 = (input.point(t0[1]) - o) / std::sqrt(CGAL::to_double((input.point(t0[1]) - o).squared_length()));
    Vector_3 e2 = CGAL::cross_product(n, e1);
    e2 = e2 / std::sqrt(CGAL::to_double(e2.squared_length()));

    std::vector<std::size_t> pts;
    for(std::size_t t : ts) pts.insert(pts.end(), input.triangle(t).begin(), input.triangle(t).end());
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    CDT cdt;
    std::unordered_map<std::size_t, typename CDT::Vertex_handle> vh;
    for(std::size_t p : pts)
    {
      const Vector_3 d = input.point(p) - o;
      const typename CDT::Vertex_handle v = cdt.insert(Point_2(d * e1, d * e2));
      if(cdt.number_of_vertices() != vh.size() + 1) return false;
      v->info() = p;
      vh[p] = v;
    }
    // constraints: the piece's edges other triangles also use or that bound it
    std::unordered_map<std::uint64_t, int> boundary; // edge -> 1 on the piece's boundary, 0 inside
    for(std::size_t t : ts)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t a = input.triangle(t)[k], b = input.triangle(t)[(k + 1) % 3];
        const std::uint64_t e = key(a, b);
        if(free_edge[e]) continue;
        auto it = boundary.find(e);
        if(it == boundary.end()) boundary.emplace(e, 1);
        else it->second = 0; // two triangles of the piece on it
      }
    try
    {
      for(const auto& eb : boundary)
        cdt.insert_constraint(vh[std::size_t(eb.first / np)], vh[std::size_t(eb.first % np)]);
    }
    catch(...) { return false; } // constraints that cross each other
    if(cdt.number_of_vertices() != pts.size()) return false;

    // inside: across a boundary edge the side changes, across any other it does not
    for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::vector<typename CDT::Face_handle> stack(1, cdt.infinite_face());
    cdt.infinite_face()->info() = 0;
    while(!stack.empty())
    {
      const typename CDT::Face_handle f = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i)
      {
        int side = f->info();
        if(cdt.is_constrained(std::make_pair(f, i)))
        {
          const std::size_t a = f->vertex(cdt.cw(i))->info(), b = f->vertex(cdt.ccw(i))->info();
          auto it = boundary.find(key(a, b));
          if(it == boundary.end()) return false; // a point on a constraint split it
          side ^= it->second;
        }
        const typename CDT::Face_handle g = f->neighbor(i);
        if(g->info() == -1) { g->info() = side; stack.push_back(g); }
        else if(g->info() != side) return false;
      }
    }
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    {
      if(f->info() != 1) continue;
      const std::array<std::size_t, 3> tri = {{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}};
      if(CGAL::orientation(project(input.point(tri[0])), project(input.point(tri[1])), project(input.point(tri[2]))) != up)
        return false;
      out.push_back(tri);
    }
    return out.size() == ts.size();
  };

  output = Geological_model_3<GeomTraits>();
  output.set_file_name(input.file_name());
  for(std::size_t r = 1; r < input.regions().size(); ++r) output.add_region(input.region(r).name);
  for(const auto& p : input.patches()) output.add_patch(p.name, p.positive_region, p.negative_region);
  for(std::size_t i = 0; i < np; ++i) output.add_point(input.point(i), input.point_source(i));
  std::vector<std::array<std::size_t, 3> > tris;
  for(std::size_t t = 0; t < nt; ++t)
  {
    const std::vector<std::size_t>& ts = pieces[find(t)];
    if(ts.size() == 1)
    {
      output.add_triangle(input.triangle(t)[0], input.triangle(t)[1], input.triangle(t)[2],
                          input.patch_of_triangle(t), input.triangle_source(t));
      continue;
    }
    if(ts.front() != t) continue; // the piece is written at its first triangle
    ++report.number_of_pieces;
    if(!retriangulate(ts, tris))
    {
      for(std::size_t u : ts)
        output.add_triangle(input.triangle(u)[0], input.triangle(u)[1], input.triangle(u)[2],
                            input.patch_of_triangle(u), input.triangle_source(u));
      continue;
    }
    ++report.number_of_retriangulated_pieces;
    report.number_of_triangles_in_pieces += ts.size();
    for(std::size_t u : ts)
      report.min_angle_before = (std::min)(report.min_angle_before,
                                           internal::smallest_triangle_angle(input.point(input.triangle(u)[0]),
                                                                             input.point(input.triangle(u)[1]),
                                                                             input.point(input.triangle(u)[2])));
    for(const auto& tri : tris)
    {
      report.min_angle_after = (std::min)(report.min_angle_after,
                                          internal::smallest_triangle_angle(input.point(tri[0]), input.point(tri[1]),
                                                                            input.point(tri[2])));
      // errors name the piece's first triangle's source
      output.add_triangle(tri[0], tri[1], tri[2], input.patch_of_triangle(t), input.triangle_source(t));
    }
  }
  return report;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_RETRIANGULATE_PLANAR_PATCHES_H
