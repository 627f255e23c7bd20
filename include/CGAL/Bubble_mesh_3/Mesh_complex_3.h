// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_MESH_COMPLEX_3_H
#define CGAL_BUBBLE_MESH_3_MESH_COMPLEX_3_H

#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

// Mesh_triangulation_3 only reads these index types from its mesh domain, so
// no domain object is needed (CGAL's Tetrahedral_remeshing does the same).
struct Mesh_domain_index_types
{
  typedef int Subdomain_index;     // region of a cell, 0 = outside
  typedef int Surface_patch_index; // patch + 1 of a facet, 0 = none
  typedef int Index;               // vertex index: region (dimension 3) or patch + 1 (dimension 2)
};

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

The triangulation of the output mesh: CGAL's Mesh_3 triangulation (a regular
triangulation, all weights zero here, hence Delaunay) with `int` subdomain and
surface patch indices.
*/
template <class GeomTraits>
using Mesh_complex_triangulation_3 =
  typename CGAL::Mesh_triangulation_3<internal::Mesh_domain_index_types, GeomTraits>::type;

/*!
\ingroup PkgBubbleMesh3Ref

The output mesh of `tetrahedralize_bubbles()`: a
`CGAL::Mesh_complex_3_in_triangulation_3`, so that CGAL's writers, checks and
optimisers accept it.

- a cell in the complex carries its region as subdomain index (`1` ...
  `number_of_regions()`); cells outside the model are not in the complex;
- a facet on an input triangle of patch `p` is in the complex with surface
  patch index `p + 1` (`0` means "none" in CGAL); this includes facets of
  surfaces inside a region (both sides have the same subdomain index) and the
  outer boundary;
- vertices on input surfaces have dimension 2 and index `p + 1` of one of
  their patches; the others have dimension 3 and their region as index.
*/
template <class GeomTraits>
using Mesh_complex_3 =
  CGAL::Mesh_complex_3_in_triangulation_3<Mesh_complex_triangulation_3<GeomTraits>, int, int>;

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_MESH_COMPLEX_3_H
