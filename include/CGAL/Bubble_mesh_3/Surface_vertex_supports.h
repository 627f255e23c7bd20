// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_SURFACE_VERTEX_SUPPORTS_H
#define CGAL_BUBBLE_MESH_3_SURFACE_VERTEX_SUPPORTS_H

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

Which input triangles each surface vertex of a mesh lies on, and which
surface vertices are Steiner points of the recovery: what
`tetrahedralize_bubbles()` knows about its surface vertices, handed on to
`remove_slivers()` (both through the named parameter
`surface_vertex_supports`), which may then remove Steiner points again.

The *support* of a vertex is the set of input triangles whose closure holds
it: the triangles of a model point, of the input edge a Steiner point was put
on, or the one triangle a Steiner point lies inside. Collapsing a vertex `v`
onto a neighbour `u` keeps every input surface where it is when the support of
`v` is part of the support of `u`: the segment `uv` then lies on every
triangle the facets around `v` lie on.

Vertex handles are the key: the object is valid for the triangulation it was
filled for, as long as its surface vertices are not removed by anything else.

\tparam Tr the triangulation of the mesh (`Mesh_complex_3<K>::%Triangulation`)
*/
template <class Tr>
class Surface_vertex_supports
{
public:
  /// the triangulation's vertex handle
  typedef typename Tr::Vertex_handle Vertex_handle;

  /// forgets everything
  void clear()
  {
    entries_.clear();
    triangles_.clear();
    index_.clear();
    steiner_points_.clear();
  }

  /// records `v`, lying on the input triangles `[begin, end)`; `steiner`: added by the recovery
  template <class Iterator>
  void add(Vertex_handle v, bool steiner, Iterator begin, Iterator end)
  {
    Entry e;
    e.steiner = steiner;
    e.begin = triangles_.size();
    triangles_.insert(triangles_.end(), begin, end);
    std::sort(triangles_.begin() + e.begin, triangles_.end());
    triangles_.erase(std::unique(triangles_.begin() + e.begin, triangles_.end()), triangles_.end());
    e.end = triangles_.size();
    index_[v] = entries_.size();
    entries_.push_back(e);
    if(steiner) steiner_points_.push_back(v);
  }

  /// the Steiner points, in the order they were recorded (removed ones included: see `contains()`)
  const std::vector<Vertex_handle>& steiner_points() const { return steiner_points_; }

  /// whether `v` is recorded and not removed
  bool contains(Vertex_handle v) const { return index_.count(v) != 0; }

  /// whether `v` is a recorded Steiner point
  bool is_steiner_point(Vertex_handle v) const
  {
    const auto it = index_.find(v);
    return it != index_.end() && entries_[it->second].steiner;
  }

  /// whether the support of `v` is part of the support of `u` (both recorded)
  bool support_included(Vertex_handle v, Vertex_handle u) const
  {
    const auto iv = index_.find(v), iu = index_.find(u);
    if(iv == index_.end() || iu == index_.end()) return false;
    const Entry &ev = entries_[iv->second], &eu = entries_[iu->second];
    return std::includes(triangles_.begin() + eu.begin, triangles_.begin() + eu.end, triangles_.begin() + ev.begin,
                         triangles_.begin() + ev.end);
  }

  /// whether Steiner point `v` may be collapsed onto `u` without moving a surface
  bool may_collapse(Vertex_handle v, Vertex_handle u) const { return is_steiner_point(v) && support_included(v, u); }

  /// `v` left the mesh
  void erase(Vertex_handle v) { index_.erase(v); }

  /// number of recorded Steiner points still in the mesh
  std::size_t number_of_steiner_points() const
  {
    std::size_t n = 0;
    for(Vertex_handle v : steiner_points_) n += contains(v) ? 1 : 0;
    return n;
  }

  /// number of input triangles holding a Steiner point still in the mesh (the others are one facet each)
  std::size_t number_of_triangles_with_steiner_points() const
  {
    std::vector<std::size_t> split;
    for(Vertex_handle v : steiner_points_)
    {
      const auto it = index_.find(v);
      if(it == index_.end()) continue;
      const Entry& e = entries_[it->second];
      split.insert(split.end(), triangles_.begin() + e.begin, triangles_.begin() + e.end);
    }
    std::sort(split.begin(), split.end());
    return std::size_t(std::unique(split.begin(), split.end()) - split.begin());
  }

private:
  struct Entry
  {
    bool steiner = false;
    std::size_t begin = 0, end = 0; // in triangles_
  };
  std::vector<Entry> entries_;
  std::vector<std::size_t> triangles_;
  std::unordered_map<Vertex_handle, std::size_t> index_;
  std::vector<Vertex_handle> steiner_points_;
};

namespace internal_np {
enum surface_vertex_supports_t { surface_vertex_supports };
} // namespace internal_np

namespace parameters {

/// `tetrahedralize_bubbles()` fills the object, `remove_slivers()` reads it
/// and removes Steiner points (see `Surface_vertex_supports`)
template <class Tr>
CGAL::Named_function_parameters<Surface_vertex_supports<Tr>*, internal_np::surface_vertex_supports_t>
surface_vertex_supports(Surface_vertex_supports<Tr>* const& s)
{
  return CGAL::Named_function_parameters<Surface_vertex_supports<Tr>*, internal_np::surface_vertex_supports_t>(s);
}

template <class Tr, class T, class Tag, class Base>
CGAL::Named_function_parameters<Surface_vertex_supports<Tr>*, internal_np::surface_vertex_supports_t,
                                CGAL::Named_function_parameters<T, Tag, Base> >
surface_vertex_supports(Surface_vertex_supports<Tr>* const& s, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return CGAL::Named_function_parameters<Surface_vertex_supports<Tr>*, internal_np::surface_vertex_supports_t,
                                         CGAL::Named_function_parameters<T, Tag, Base> >(s, np);
}

} // namespace parameters
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_SURFACE_VERTEX_SUPPORTS_H
