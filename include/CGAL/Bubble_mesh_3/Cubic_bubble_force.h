// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_CUBIC_BUBBLE_FORCE_H
#define CGAL_BUBBLE_MESH_3_CUBIC_BUBBLE_FORCE_H

#include <CGAL/assertions.h>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The pair force of the clustering-based bubble method (paper, eq. 6):
\f[
  f(w) = k\,(1.25\,w^3 - 2.375\,w^2 + 1.125) \quad (0 \le w < 1.5), \qquad f(w) = 0 \quad (w \ge 1.5)
\f]
with \f$ w = l_{ij} / (r_i + r_j) \f$ the distance of the two centres over
the sum of the radii. \f$ f(0) = 1.125k \f$, \f$ f(1) = f(1.5) = 0 \f$ and
\f$ f'(1) = -k \f$: bubbles repel when they overlap and attract weakly
between 1 and 1.5 times the sum of their radii, so that they settle touching.

A positive value pushes the two bubbles apart. `relax_bubbles()` multiplies
the value by \f$ r_i + r_j \f$, which makes the pair behave at rest like a
spring of stiffness `k` whatever the scale of the model (see `relax_bubbles()`).

\cgalModels `BubbleForceLaw`
*/
class Cubic_bubble_force
{
public:
  /// the law with stiffness `k` (the slope \f$ -f'(1) \f$)
  explicit Cubic_bubble_force(double k = 1.) : k_(k)
  {
    CGAL_precondition(k > 0.);
  }

  /// the force at normalised distance `w >= 0`
  double operator()(double w) const
  {
    // Horner form of 1.25 w^3 - 2.375 w^2 + 1.125; a select, not a branch,
    // since the inner loop of the relaxation calls it in and out of reach
    const double f = k_ * ((1.25 * w - 2.375) * w * w + 1.125);
    return w < 1.5 ? f : 0.;
  }

  /// the normalised distance beyond which the force is zero
  double cutoff() const { return 1.5; }

  /// `k`, the slope of the law at rest
  double stiffness() const { return k_; }

private:
  double k_;
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_CUBIC_BUBBLE_FORCE_H
