// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

/*!
\ingroup PkgBubbleMesh3Concepts
\cgalConcept

The pair force between two bubbles, as a function of their normalised
distance \f$ w = l_{ij} / (r_i + r_j) \f$. `relax_bubbles()` applies to
bubble \f$ i \f$ the force \f$ f(w)\,(r_i + r_j)\,(x_i - x_j)/l_{ij} \f$ for
each neighbour \f$ j \f$ closer than `cutoff()` times \f$ r_i + r_j \f$: a
positive value pushes the bubbles apart. The factor \f$ r_i + r_j \f$ makes the
rest stiffness \f$ -f'(1) \f$ a stiffness in force per length at any scale.

For the bubbles to settle touching, a law should be repulsive below
\f$ w = 1 \f$, zero at \f$ w = 1 \f$, and zero or weakly attractive above.
The integrator derives its default damping and time step from `stiffness()`.

A model must be cheap to copy and safe to call from several threads at once
(the call operator is `const` and has no side effects): it runs in the inner
loop of the relaxation, once per neighbour and per force evaluation.

\cgalHasModel `CGAL::Bubble_mesh_3::Cubic_bubble_force`
\cgalHasModel `CGAL::Bubble_mesh_3::Repulsive_bubble_force`
*/
class BubbleForceLaw
{
public:
  /// the force at normalised distance `w >= 0`; positive repels
  double operator()(double w) const;

  /// the normalised distance at and beyond which the force is zero
  double cutoff() const;

  /// the slope at rest, \f$ -f'(1) > 0 \f$
  double stiffness() const;
};
