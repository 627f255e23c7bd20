// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_POINT_INDEX_TREE_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_POINT_INDEX_TREE_H

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/*
A kd-tree over indices into a vector of points that stays where it is (the
points are not copied): "which of these points lie in this ball?", as the
confinement asks of the model points around a protected ball and the
tetrahedralization of the points around an input edge or triangle.

A query reports every point of the ball and maybe some up to 1e-9 of the
radius beyond it: the search sphere is that much larger, so that rounding in
the tree never loses a point of the closed ball, and the caller decides with
an exact predicate (inside, or on the sphere too, as it needs).
The tree is built in the constructor, so const queries may run concurrently.
*/
template <class K>
class Point_index_tree
{
  typedef typename K::Point_3 Point_3;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<K> > Traits;
  typedef CGAL::Kd_tree<Traits> Tree;

public:
  /// all of `points`
  explicit Point_index_tree(const std::vector<Point_3>& points)
    : map_(CGAL::make_property_map(points)), tree_(typename Tree::Splitter(), Traits(map_))
  {
    for(std::size_t i = 0; i < points.size(); ++i) tree_.insert(i);
    if(!points.empty()) tree_.build();
  }

  /// the points of `points` whose indices are in [first, last)
  template <class IndexIterator>
  Point_index_tree(const std::vector<Point_3>& points, IndexIterator first, IndexIterator last)
    : map_(CGAL::make_property_map(points)), tree_(first, last, typename Tree::Splitter(), Traits(map_))
  {
    if(first != last) tree_.build();
  }

  /// replaces `found` by the indices of the points in the ball (see above)
  void points_in_ball(const Point_3& center, double radius, std::vector<std::size_t>& found) const
  {
    found.clear();
    if(tree_.empty()) return;
    tree_.search(std::back_inserter(found), CGAL::Fuzzy_sphere<Traits>(center, radius * (1. + 1e-9), 0., Traits(map_)));
  }

private:
  Point_map map_;
  Tree tree_;
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_POINT_INDEX_TREE_H
