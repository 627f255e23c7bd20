// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// Stages 3 and 4 with a force law of one's own: relax_bubbles() takes any
// model of the BubbleForceLaw concept through the named parameter
// `force_law`. Here a softer, purely repulsive law replaces the paper's cubic
// on the generated layered model (the bundled one), and the program prints
// what the relaxation did.
//
// Usage: custom_force_law [stiffness]

#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>
#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>
#include <CGAL/Bubble_mesh_3/relax_bubbles.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cassert>
#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Bubble<K> Bubble;
namespace BM = CGAL::Bubble_mesh_3;

// A model of BubbleForceLaw: f(w) = k (1 - w) below w = 1, nothing beyond.
// Compared with the cubic (f(0) = 1.125 k, weak attraction up to w = 1.5) it
// pushes less at deep overlaps and never pulls, so bubbles spread out
// instead of drawing together; population control fills the gaps this leaves.
struct Soft_linear_force
{
  double k = 1.;

  // positive repels; w = distance / (r_i + r_j)
  double operator()(double w) const { return w < 1. ? k * (1. - w) : 0.; }

  // pairs farther apart than cutoff() * (r_i + r_j) are not looked at
  double cutoff() const { return 1.; }

  // -f'(1): the integrator derives its default damping and time step from it
  double stiffness() const { return k; }
};

int main(int argc, char** argv)
{
  Soft_linear_force law;
  if(argc > 1) law.k = std::atof(argv[1]);
  if(!(law.k > 0.))
  {
    std::cerr << "Usage: custom_force_law [stiffness > 0]\n";
    return EXIT_FAILURE;
  }

  // the package's default layered model, generated
  BM::Geological_model_3<K> model;
  BM::make_layered_model(model);

  // stages 1 and 2: fixed surface bubbles, sizing field, initial interior bubbles
  const std::vector<Bubble> surface = BM::place_surface_bubbles(model);
  const BM::Surface_bubble_sizing_field<K> sizing(model, surface);
  std::vector<Bubble> interior = BM::place_initial_bubbles(model, surface, sizing);
  const std::size_t placed = interior.size();

  // stages 3 and 4 with the custom law; four population rounds instead of
  // twelve keep the example short, every other parameter keeps its default
  const BM::Relaxation_report report = BM::relax_bubbles(
    model, surface, interior, sizing,
    BM::parameters::force_law(law, BM::parameters::number_of_population_rounds(4)));

  std::cout << model.number_of_regions() << " regions, " << surface.size() << " surface bubbles, " << placed
            << " initial interior bubbles -> " << interior.size() << " after relaxation (" << report.added
            << " added, " << report.removed << " removed) in " << report.steps << " steps, " << report.seconds
            << " s\n";
  std::cout << "overlap ratio of the interior bubbles: " << report.below << " under 10, " << report.inside
            << " in [10,14], " << report.above << " over 14\n";
  for(const BM::Region_relaxation_report& r : report.regions)
    std::cout << "  region " << r.region << ": " << r.population << " bubbles, " << r.steps << " steps, "
              << (r.converged ? "converged" : "step budget reached") << "\n";

  // the relaxation left interior bubbles, all of them reported
  assert(!interior.empty() && report.population == interior.size());
  return EXIT_SUCCESS;
}
