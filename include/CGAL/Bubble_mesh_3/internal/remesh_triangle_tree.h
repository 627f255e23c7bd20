// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_TRIANGLE_TREE_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_TRIANGLE_TREE_H

// An AABB tree over a subset of the model's triangles that answers with the
// model's triangle indices: the re-meshing projects onto one patch (or one
// chart) at a time and asks which input triangle a point lies on.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

template <class GeomTraits>
class Remesh_triangle_tree
{
public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Triangle_3 Triangle_3;
  typedef typename std::vector<Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<GeomTraits, Iterator> Primitive;
  typedef CGAL::AABB_traits<GeomTraits, Primitive> Traits;
  typedef CGAL::AABB_tree<Traits> Tree;

  Remesh_triangle_tree() {}
  // the tree points into triangles_: a move keeps the buffer, a copy would not
  Remesh_triangle_tree(const Remesh_triangle_tree&) = delete;
  Remesh_triangle_tree& operator=(const Remesh_triangle_tree&) = delete;
  Remesh_triangle_tree(Remesh_triangle_tree&&) = default;
  Remesh_triangle_tree& operator=(Remesh_triangle_tree&&) = default;

  template <class Range>
  Remesh_triangle_tree(const Geological_model_3<GeomTraits>& model, const Range& triangles)
  {
    for(std::size_t t : triangles)
    {
      const auto& tri = model.triangle(t);
      triangles_.push_back(Triangle_3(model.point(tri[0]), model.point(tri[1]), model.point(tri[2])));
      ids_.push_back(t);
    }
    tree_.reset(new Tree(triangles_.begin(), triangles_.end()));
    tree_->accelerate_distance_queries();
  }

  bool empty() const { return triangles_.empty(); }
  const Tree& tree() const { return *tree_; }
  const std::vector<Triangle_3>& triangles() const { return triangles_; }

  /// model triangle index of a primitive id
  std::size_t model_triangle(Iterator it) const { return ids_[std::size_t(it - triangles_.begin())]; }
  std::size_t local_index(Iterator it) const { return std::size_t(it - triangles_.begin()); }

  /// the closest point of these triangles to `p`
  Point_3 closest_point(const Point_3& p) const { return tree_->closest_point(p); }

  /// the closest point and the local index (in the range given) of its triangle
  std::pair<Point_3, std::size_t> closest_point_and_local_triangle(const Point_3& p) const
  {
    const auto pp = tree_->closest_point_and_primitive(p);
    return std::make_pair(pp.first, local_index(pp.second));
  }

  /// the closest point and the model index of its triangle
  std::pair<Point_3, std::size_t> closest_point_and_triangle(const Point_3& p) const
  {
    const auto pp = tree_->closest_point_and_primitive(p);
    return std::make_pair(pp.first, model_triangle(pp.second));
  }

private:
  std::vector<Triangle_3> triangles_;
  std::vector<std::size_t> ids_;
  std::unique_ptr<Tree> tree_;
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_REMESH_TRIANGLE_TREE_H
