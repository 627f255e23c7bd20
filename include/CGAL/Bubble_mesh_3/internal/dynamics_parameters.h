// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_DYNAMICS_PARAMETERS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_DYNAMICS_PARAMETERS_H

// Named parameters of the bubble dynamics (relax_bubbles(),
// control_bubble_population()). Chain them with the two-argument form:
// `parameters::time_step(0.05, parameters::damping(3.))`, or append to a CGAL
// chain: `parameters::mass(2., CGAL::parameters::visitor(v))`.
// CGAL tag reused: `visitor` (progress figures). The step budget has its own
// tag, not CGAL's `number_of_iterations`: make_bubble_mesh_3() hands one
// parameter pack to every stage, and k-means, surface remeshing and sliver
// removal already read `number_of_iterations` as their own budgets.

#include <CGAL/Bubble_mesh_3/internal/named_parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <cstddef>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal_np {
enum force_law_t { force_law };
enum mass_t { mass };
enum damping_t { damping };
enum stiffness_t { stiffness };
enum time_step_t { time_step };
enum number_of_relaxation_steps_t { number_of_relaxation_steps };
enum number_of_round_relaxation_steps_t { number_of_round_relaxation_steps };
enum number_of_radius_update_steps_t { number_of_radius_update_steps };
enum displacement_tolerance_t { displacement_tolerance };
enum round_displacement_tolerance_t { round_displacement_tolerance };
enum min_overlap_ratio_t { min_overlap_ratio };
enum max_overlap_ratio_t { max_overlap_ratio };
enum solid_angle_overlap_ratio_t { solid_angle_overlap_ratio };
enum wall_overlap_ratio_t { wall_overlap_ratio };
enum number_of_population_rounds_t { number_of_population_rounds };
enum population_tolerance_t { population_tolerance };
enum insertion_clearance_t { insertion_clearance };
enum neighbor_skin_t { neighbor_skin };
enum max_step_ratio_t { max_step_ratio };
enum radius_update_ratio_t { radius_update_ratio };
enum resting_displacement_ratio_t { resting_displacement_ratio };
enum inertial_relaxation_t { inertial_relaxation };
enum diametral_ball_margin_t { diametral_ball_margin };
enum max_protected_ball_ratio_t { max_protected_ball_ratio };
enum surface_offset_ratio_t { surface_offset_ratio };
enum dynamics_threads_t { dynamics_threads };
} // namespace internal_np

namespace parameters {

using CGAL::parameters::default_values;
using CGAL::parameters::visitor;

/// mass m of a free bubble (default 1)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, mass)
/// viscous damping c (default 2 sqrt(m k): critical for one bubble bound by one spring)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, damping)
/// stiffness k of the default force law (default 1)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, stiffness)
/// integration time step (default 0.2 sqrt(m/k))
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, time_step)
/// step budget of a relaxation to the full tolerance (default 500)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_relaxation_steps)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_round_relaxation_steps)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_radius_update_steps)
/// convergence: largest displacement in one step over the local radius (default 1e-3)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, displacement_tolerance)
/// convergence of the relaxations between population passes, looser since more passes follow (default 1e-2)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, round_displacement_tolerance)
/// lower bound of the overlap ratio of interior bubbles (default 10)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, min_overlap_ratio)
/// upper bound of the overlap ratio of interior bubbles (default 14)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, max_overlap_ratio)
/// each interior neighbour's term of the overlap ratio weighted by the solid angle it
/// takes at rest distance, against an equal neighbour's (default `true`; `false`: METHOD.md's formula)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, solid_angle_overlap_ratio)
/// a surface triangle at least 6 radii long within 3 radii of an interior bubble counts in that bubble's
/// overlap ratio as the plane of equal bubbles it could hold (default `true`; `false`: METHOD.md's formula)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, wall_overlap_ratio)
/// most population-control rounds, each followed by a relaxation (default 12; 0 = none)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(std::size_t, number_of_population_rounds)
/// the population has settled when a round changes at most this share of it, or one bubble (default 0.005)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, population_tolerance)
/// least normalised distance l/(r_new + r_j) of an inserted bubble to the others (default 0.7)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, insertion_clearance)
/// extra reach of the neighbour lists, over r_i + r_j (default 0.35)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, neighbor_skin)
/// longest move of a bubble in one step, over its radius (default 0.125, at most 0.9 skin)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, max_step_ratio)
/// a bubble's radius is read again from the sizing field after it moved this share of it (default 0.1)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, radius_update_ratio)
/// a free bubble whose steps stay under this share of the relaxation's tolerance for 5 steps rests (is not
/// moved) until a bubble near it moves more, or the next of the full steps that come every 50 (default 0.25;
/// 0: every bubble moves at every step)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, resting_displacement_ratio)
/// relax with FIRE, the fast inertial relaxation engine: no damping, velocities turned towards the forces,
/// a longer step while the motion goes downhill, a stop when it goes uphill (default `true`; `false`:
/// METHOD.md's damped dynamics m x'' + c x' = F, integrated by Heun's scheme)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(bool, inertial_relaxation)
/// bubble centres stay farther than (1 + margin) times a diametral ball's radius from its centre (default 0.02)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, diametral_ball_margin)
/// diametral balls wider than this times the local surface-bubble radius are not protected (default 3)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, max_protected_ball_ratio)
/// a bubble put back inside its region lands this share of its radius off the surface (default 0.5)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, surface_offset_ratio)
/// number of threads of the dynamics (default 0: all cores)
CGAL_BUBBLE_MESH_3_NAMED_PARAMETER_WITH_TAG(std::size_t, number_of_threads, dynamics_threads)

/// the pair force law, a model of `BubbleForceLaw` (default `Cubic_bubble_force(stiffness)`)
template <class ForceLaw>
CGAL::Named_function_parameters<ForceLaw, internal_np::force_law_t>
force_law(const ForceLaw& law)
{
  return CGAL::Named_function_parameters<ForceLaw, internal_np::force_law_t>(law);
}

template <class ForceLaw, class T, class Tag, class Base>
CGAL::Named_function_parameters<ForceLaw, internal_np::force_law_t,
                                CGAL::Named_function_parameters<T, Tag, Base> >
force_law(const ForceLaw& law, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return CGAL::Named_function_parameters<ForceLaw, internal_np::force_law_t,
                                         CGAL::Named_function_parameters<T, Tag, Base> >(law, np);
}

} // namespace parameters
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_DYNAMICS_PARAMETERS_H
