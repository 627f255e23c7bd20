// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_UNION_FIND_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_UNION_FIND_H

// Union-find over indices 0..n-1 in a plain vector (`parent[i] == i` for a
// root): the one the validation, the recovery's plane groups, the cocircular
// weights and the planar pieces share.

#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// n singletons
inline std::vector<std::size_t> uf_singletons(std::size_t n)
{
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  return parent;
}

/// the root of `i`, halving the path on the way
inline std::size_t uf_find(std::vector<std::size_t>& parent, std::size_t i)
{
  while(parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/// joins the sets of `a` and `b`
inline void uf_union(std::vector<std::size_t>& parent, std::size_t a, std::size_t b)
{
  a = uf_find(parent, a);
  b = uf_find(parent, b);
  // the smaller root wins, so that the result does not depend on the union order
  if(a < b) parent[b] = a;
  else if(b < a) parent[a] = b;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_UNION_FIND_H
