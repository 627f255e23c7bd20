// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

/*!
\ingroup PkgBubbleMesh3Concepts
\cgalConcept

The bubble radius wanted at a point of a region: half the mesh edge length
wanted there. `place_initial_bubbles()` gives each candidate the radius the
field returns at its centre and derives its lattice's cell edge from the
field's values at the region's surface bubbles; the bubble dynamics read it
to grow or shrink bubbles and to decide where the population is too dense or
too sparse.

A model may grade the mesh however it likes (from the surface, from a
distance to a well, from a property in a grid...), but it should agree with
the surface bubbles near the surfaces, which never move: the surface
triangulation fixes the mesh size there.

A model must be copyable (copies may share data), and its call operator
must be safe to call from several threads at once.

\cgalHasModel `CGAL::Bubble_mesh_3::Surface_bubble_sizing_field`
*/
class BubbleSizingField
{
public:
  /// the point type, `GeomTraits::Point_3` of the geological model
  typedef unspecified_type Point_3;

  /*!
  the radius wanted at `p` inside region `region` (`region >= 1`); a value
  `<= 0` means "no bubble here" (the placement then skips the candidate)
  */
  double operator()(const Point_3& p, std::size_t region) const;
};
