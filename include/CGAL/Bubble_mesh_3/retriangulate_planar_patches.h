// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_RETRIANGULATE_PLANAR_PATCHES_H
#define CGAL_BUBBLE_MESH_3_RETRIANGULATE_PLANAR_PATCHES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Bubble_mesh_3/internal/asked_edge_length.h>
#include <CGAL/Bubble_mesh_3/internal/planar_pieces.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <optional>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal_np {
enum planar_angle_bound_t { planar_angle_bound };
enum refine_tilted_pieces_t { refine_tilted_pieces };
enum tilted_size_factor_t { tilted_size_factor };
} // namespace internal_np

namespace parameters {
/// \ingroup PkgBubbleMesh3Ref
/// smallest triangle angle (degrees) `retriangulate_planar_patches()` aims at
/// on planar pieces that lie in an axis plane, with new points (which also
/// bring their edges to the median input edge); 0: no new points
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, planar_angle_bound)
/// \ingroup PkgBubbleMesh3Ref
/// whether `retriangulate_planar_patches()` also gives new points for size to
/// pieces off the axis planes and to single triangles of curved surfaces
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, refine_tilted_pieces)
/// \ingroup PkgBubbleMesh3Ref
/// how many times wider than the size wanted a triangle off the axis planes
/// must be for `retriangulate_planar_patches()` to give it new points inside
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, tilted_size_factor)
} // namespace parameters

/// \ingroup PkgBubbleMesh3Ref
/// default of the named parameter `tilted_size_factor`
constexpr double default_tilted_size_factor = 1.5;

/// \ingroup PkgBubbleMesh3Ref
/// the factor `make_bubble_mesh_3()` meshes again with when the surface
/// recovery fails with a smaller `tilted_size_factor`
constexpr double fallback_tilted_size_factor = 2.;

/*!
\ingroup PkgBubbleMesh3Ref

Copies `input` to `output` with every planar piece of a patch triangulated
anew. A planar piece is a largest set of coplanar (up to a thousand rounding
units of the largest coordinate: a tilted wall's rounded points), consistently
oriented triangles of one patch joined by edges that no other triangle uses.
Regions, patches and the surfaces as point sets are the same (on a tilted
piece up to that tolerance); only edges inside a piece change, and each
piece covers the same polygon as before.

- A piece gets the constrained Delaunay triangulation of its own points.
- A piece in an axis plane (x, y or z constant: the walls, top and bottom of
  most models), when `planar_angle_bound` is positive, is also refined:
  circumcentres of its triangles with an angle under the bound are added as
  new points, exactly on the plane, and so are circumcentres of triangles
  wider than the size wanted there: the spacing of the points on the
  piece's border and on the curves inside it, growing by half the distance
  from them, at most the median input edge of the model or the size asked
  for (`edge_length`, `relative_edge_length`; a wall or a bottom given as two
  huge triangles would stay bare: the bubbles beside it would have no
  neighbour on that side). The median suits models whose surfaces are
  triangulated alike; where a small, finely triangulated body (an ore lens,
  a tunnel) holds most of the edges, walls refined to its size make the
  whole box that fine, and a size asked for keeps them coarser (bench/README.md,
  session 37). An edge it shares only with pieces being
  refined is split at its midpoint (exactly on the edge) where a
  circumcentre would come too close to it. Edges shared with a triangle that
  is not refined (a needle of a fault, say, or with
  `refine_tilted_pieces(false)` any surface off the axis planes) are never
  split, so that surface does not change; circumcentres too close to them
  are not added.
- Every other piece, and every single triangle of a curved surface whose
  angles are all at least 20 degrees, when `refine_tilted_pieces` is true
  (the default) and `planar_angle_bound` is positive, is refined for size
  alone, where a triangle is more than `tilted_size_factor` (default 1.5)
  times as wide as the size above: a huge triangle of a curved horizon or
  fault is as bare a wall as a flat one (1.5 rather than 2: CloudSpin and
  modelA2 get far better meshes for 35 and 120 % more tetrahedra, and the
  input's own triangles near the median edge still stay; bench/README.md,
  session 34). Its new points are
  rounded onto its plane (within the coplanarity tolerance above); an edge
  whose triangles are all refined is split at its midpoint where a
  circumcentre comes too close to it, in every triangle on it, so the
  surfaces stay conforming; edges of a piece left as it is are not split.
  Small angles are not chased there: around the needles of a curved surface
  that would refine every triangle nearby.

Why: generated box walls and flat tops often come as fans of needles (edges
of kilometres meeting at a fraction of a degree), or as strips between a
horizon's trace and a top edge with no point on it. A tetrahedron on such a
triangle is poor whatever the bubbles do, and recovering it in the
tetrahedralization takes thousands of Steiner points.

A piece is left as it was when its triangulation cannot be checked to cover
it exactly (a point on one of its constraints, a boundary that crosses
itself, a triangle that flips in floating point); if that happens to a piece
being refined, that piece is left out of the refinement and it starts again
(after 16 such pieces, no piece is refined).

The model must be valid (`validate_geological_model()`).

\cgalNamedParamsBegin
  \cgalParamNBegin{planar_angle_bound}
    \cgalParamDescription{smallest angle (degrees) aimed at on axis-plane pieces; 0 re-triangulates without new points}
    \cgalParamType{`double`}
    \cgalParamDefault{10}
  \cgalParamNEnd
  \cgalParamNBegin{refine_tilted_pieces}
    \cgalParamDescription{whether pieces off the axis planes and single triangles of curved surfaces get new points for size}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{tilted_size_factor}
    \cgalParamDescription{how many times wider than the size wanted a triangle off the axis planes must be to get new points inside (an edge it shares with refined pieces may still be split, whatever the factor; `refine_tilted_pieces(false)` keeps those edges too)}
    \cgalParamType{`double`}
    \cgalParamDefault{`default_tilted_size_factor` (1.5)}
    \cgalParamExtra{at least 1}
  \cgalParamNEnd
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{the largest edge wanted on refined pieces, in model units (the parameter of `remesh_surfaces()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{the median input edge length}
  \cgalParamNEnd
  \cgalParamNBegin{relative_edge_length}
    \cgalParamDescription{the same as a fraction of the bounding-box diagonal (if `edge_length` is not given)}
    \cgalParamType{`double`}
    \cgalParamDefault{unused}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class GeomTraits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Planar_retriangulation_report retriangulate_planar_patches(const Geological_model_3<GeomTraits>& input,
                                                           Geological_model_3<GeomTraits>& output,
                                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double bound = choose_parameter(get_parameter(np, internal_np::planar_angle_bound), 10.);
  const bool tilted = choose_parameter(get_parameter(np, internal_np::refine_tilted_pieces), true);
  const double factor = choose_parameter(get_parameter(np, internal_np::tilted_size_factor), default_tilted_size_factor);
  CGAL_precondition_msg(factor >= 1., "tilted_size_factor must be at least 1");
  const std::optional<double> size = internal::asked_edge_length(input, np);
  CGAL_precondition_msg(!size || *size > 0., "the edge length asked for must be positive");
  internal::Planar_pieces<GeomTraits> pieces(input, bound, tilted, factor, size ? *size : 0.);
  return pieces.run(output);
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_RETRIANGULATE_PLANAR_PATCHES_H
