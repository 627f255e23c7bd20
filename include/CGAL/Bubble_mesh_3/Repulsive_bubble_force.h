// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_REPULSIVE_BUBBLE_FORCE_H
#define CGAL_BUBBLE_MESH_3_REPULSIVE_BUBBLE_FORCE_H

#include <CGAL/Bubble_mesh_3/Cubic_bubble_force.h>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The repulsive part of `Cubic_bubble_force`: the same cubic below
\f$ w = 1 \f$, nothing beyond,
\f[
  f(w) = k\,(1.25\,w^3 - 2.375\,w^2 + 1.125) \quad (0 \le w < 1), \qquad f(w) = 0 \quad (w \ge 1).
\f]
Bubbles that overlap are pushed apart exactly as under the paper's law, and
at rest they touch (\f$ f(1) = 0 \f$, \f$ f'(1) = -k \f$), but they are
never pulled together.

Why: the cubic law's repulsion is bounded (\f$ 1.125k \f$ at \f$ w = 0 \f$)
while its attraction (down to \f$ -0.146k \f$ at \f$ w = 1.27 \f$) adds up
over every neighbour between 1 and 1.5 times the sum of the radii. Where
the bubbles of a region are sparse or pressed by larger neighbours, they
then gather into stacks of a dozen bubbles closer than one radius, next to
empty space, and population control deletes and re-inserts them round after
round. Measured on modelA1's surfaces re-meshed (region 4, no population
control between): bubbles with an overlap ratio of 39 or more grew from 0 to
1851 of 7036 in 1200 steps under the cubic law and stayed at 0-1 under this
one. The gaps it leaves are population control's to fill. On the whole
pipeline it gives better tetrahedra on CloudSpin (mean smallest dihedral
37.6 against 30.9 degrees) and on modelA1 with its surfaces re-meshed (no
tetrahedron under 15 degrees, against a minimum of 4.2); see
bench/README.md.

\cgalModels `BubbleForceLaw`
*/
class Repulsive_bubble_force
{
public:
  /// the law with stiffness `k` (the slope \f$ -f'(1) \f$)
  explicit Repulsive_bubble_force(double k = 1.) : cubic_(k) {}

  /// the force at normalised distance `w >= 0`
  double operator()(double w) const
  {
    const double f = cubic_(w);
    return w < 1. ? f : 0.;
  }

  /// the normalised distance beyond which the force is zero
  double cutoff() const { return 1.; }

  /// `k`, the slope of the law at rest
  double stiffness() const { return cubic_.stiffness(); }

private:
  Cubic_bubble_force cubic_;
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_REPULSIVE_BUBBLE_FORCE_H
