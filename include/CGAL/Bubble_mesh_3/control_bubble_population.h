// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_CONTROL_BUBBLE_POPULATION_H
#define CGAL_BUBBLE_MESH_3_CONTROL_BUBBLE_POPULATION_H

#include <CGAL/Bubble_mesh_3/Bubble.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/Neighbor_grid.h>
#include <CGAL/Bubble_mesh_3/internal/confine_to_region.h>
#include <CGAL/Bubble_mesh_3/internal/dynamics_parameters.h>
#include <CGAL/Bubble_mesh_3/internal/parallel_loops.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/// \ingroup PkgBubbleMesh3Ref
/// What one pass of population control did.
struct Population_change
{
  std::size_t added = 0;   ///< interior bubbles inserted next to under-populated ones
  std::size_t removed = 0; ///< over-populated interior bubbles deleted
};

/// \ingroup PkgBubbleMesh3Ref
/// default of the named parameter `number_of_population_rounds` of `relax_bubbles()`
constexpr std::size_t default_number_of_population_rounds = 12;

/// \ingroup PkgBubbleMesh3Ref
/// default of the named parameter `population_tolerance` of `relax_bubbles()`.
/// 0.002 until session 55: 0.005 spares big regions rounds that trade under half a
/// percent of their bubbles (re-meshed CloudSpin: relaxation 20 % shorter) for an
/// aspect-ratio median 0.002 higher (bench/README.md, sessions 53 and 55)
constexpr double default_population_tolerance = 0.005;

namespace internal {

// ---- deterministic parallel loops -------------------------------------------

// (Runs_in_parallel and for_each_block: internal/parallel_loops.h)

// fixed blocks whatever the thread count: partial results are combined in block order
constexpr std::size_t reduction_block = 2048;

/// N per-index values reduced over [0, n): slot k summed, or its largest kept where
/// `largest[k]` (from 0: the values are not negative), bit-identical for any number of threads
template <class ConcurrencyTag, std::size_t N, class F>
std::array<double, N> deterministic_reduce(std::size_t n, const F& values, const std::array<bool, N>& largest)
{
  const auto add = [&largest](std::array<double, N>& s, const std::array<double, N>& v) {
    for(std::size_t k = 0; k < N; ++k) s[k] = largest[k] ? (std::max)(s[k], v[k]) : s[k] + v[k];
  };
  const std::size_t nb = (n + reduction_block - 1) / reduction_block;
  std::vector<std::array<double, N> > partial(nb);
  for_each_block<ConcurrencyTag>(nb, 1, [&](std::size_t b0, std::size_t b1) {
    for(std::size_t b = b0; b < b1; ++b)
    {
      std::array<double, N> s{};
      const std::size_t e = (std::min)(n, (b + 1) * reduction_block);
      for(std::size_t i = b * reduction_block; i < e; ++i) add(s, values(i));
      partial[b] = s;
    }
  });
  std::array<double, N> s{};
  for(std::size_t b = 0; b < nb; ++b) add(s, partial[b]);
  return s;
}

// ---- settings -----------------------------------------------------------------

struct Dynamics_settings
{
  double mass = 1.;
  double damping = 2.;
  double time_step = 0.2;
  double tolerance = 1e-3;
  double round_tolerance = 1e-2;
  std::size_t step_budget = 500;
  std::size_t round_step_budget = 300;
  std::size_t radius_update_steps = 300;
  double min_overlap = 10.;
  double max_overlap = 14.;
  bool solid_angle_overlap = true;
  bool wall_overlap = true;
  std::size_t population_rounds = default_number_of_population_rounds;
  double population_tolerance = default_population_tolerance;
  double insertion_clearance = 0.7;
  double skin = 0.35;
  double max_step = 0.125;
  double radius_update = 0.1;
  double rest_ratio = 0.25;
  bool inertial = true;
  std::size_t threads = 0;
  Confinement_settings confinement;
};

/// reads the named parameters; `stiffness` is the force law's, for the defaults of c and dt
template <class NP>
Dynamics_settings dynamics_settings(const NP& np, double stiffness)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Dynamics_settings s; // its members hold the defaults
  s.mass = choose_parameter(get_parameter(np, internal_np::mass), s.mass);
  CGAL_precondition(s.mass > 0. && stiffness > 0.);
  s.damping = choose_parameter(get_parameter(np, internal_np::damping), 2. * std::sqrt(s.mass * stiffness));
  s.time_step = choose_parameter(get_parameter(np, internal_np::time_step), 0.2 * std::sqrt(s.mass / stiffness));
  s.tolerance = choose_parameter(get_parameter(np, internal_np::displacement_tolerance), s.tolerance);
  s.round_tolerance = choose_parameter(get_parameter(np, internal_np::round_displacement_tolerance), s.round_tolerance);
  s.step_budget = choose_parameter(get_parameter(np, internal_np::number_of_relaxation_steps), s.step_budget);
  s.round_step_budget = choose_parameter(get_parameter(np, internal_np::number_of_round_relaxation_steps), s.round_step_budget);
  s.radius_update_steps = choose_parameter(get_parameter(np, internal_np::number_of_radius_update_steps), s.radius_update_steps);
  s.min_overlap = choose_parameter(get_parameter(np, internal_np::min_overlap_ratio), s.min_overlap);
  s.max_overlap = choose_parameter(get_parameter(np, internal_np::max_overlap_ratio), s.max_overlap);
  s.solid_angle_overlap = choose_parameter(get_parameter(np, internal_np::solid_angle_overlap_ratio), s.solid_angle_overlap);
  s.wall_overlap = choose_parameter(get_parameter(np, internal_np::wall_overlap_ratio), s.wall_overlap);
  s.population_rounds = choose_parameter(get_parameter(np, internal_np::number_of_population_rounds), s.population_rounds);
  s.population_tolerance = choose_parameter(get_parameter(np, internal_np::population_tolerance), s.population_tolerance);
  s.rest_ratio = choose_parameter(get_parameter(np, internal_np::resting_displacement_ratio), s.rest_ratio);
  s.inertial = choose_parameter(get_parameter(np, internal_np::inertial_relaxation), s.inertial);
  s.insertion_clearance = choose_parameter(get_parameter(np, internal_np::insertion_clearance), s.insertion_clearance);
  s.skin = choose_parameter(get_parameter(np, internal_np::neighbor_skin), s.skin);
  s.max_step = choose_parameter(get_parameter(np, internal_np::max_step_ratio), s.max_step);
  s.radius_update = choose_parameter(get_parameter(np, internal_np::radius_update_ratio), s.radius_update);
  s.threads = choose_parameter(get_parameter(np, internal_np::dynamics_threads), s.threads);
  s.confinement.ball_margin = choose_parameter(get_parameter(np, internal_np::diametral_ball_margin), s.confinement.ball_margin);
  s.confinement.max_ball_ratio = choose_parameter(get_parameter(np, internal_np::max_protected_ball_ratio), s.confinement.max_ball_ratio);
  s.confinement.offset_ratio = choose_parameter(get_parameter(np, internal_np::surface_offset_ratio), s.confinement.offset_ratio);
  CGAL_precondition(s.time_step > 0. && s.damping >= 0. && s.skin > 0.);
  CGAL_precondition(s.min_overlap <= s.max_overlap);
  CGAL_precondition(s.rest_ratio >= 0. && s.rest_ratio < 1.);
  // the predicted positions must stay inside the neighbour lists' reach
  s.max_step = (std::min)(s.max_step, 0.9 * s.skin);
  return s;
}

// ---- the bubbles of one region --------------------------------------------------

/*
The bubbles of one region in arrays (structure of arrays, for the inner loops):
the free (interior) bubbles first, then the fixed surface bubbles on the
region's surfaces. `key` orders the free bubbles for output (input order, then
insertion order) and gives the surface-bubble index of a fixed one.
*/
template <class K>
struct Bubble_system
{
  typedef Region_confinement<K> Confinement;

  std::size_t region = 0;
  std::shared_ptr<const Confinement> confinement;
  std::size_t n_free = 0;
  std::vector<double> x, y, z, r;            // all bubbles
  std::vector<std::size_t> key;              // all bubbles
  std::vector<double> vx, vy, vz;            // free: velocity
  std::vector<double> cx, cy, cz, clearance; // free: last checked position, free ball radius around it
  std::vector<double> sx, sy, sz;            // free: where the radius was last read from the sizing field
  std::size_t next_key = 0;
  std::size_t input_population = 0;
  std::size_t rejected = 0;                  // removed because no valid position was found
  double box[6] = {0., 0., 0., 0., 0., 0.};  // where the bubbles may be (the region's bounding box)

  std::size_t size() const { return x.size(); }

  double max_radius() const
  {
    double m = 0.;
    for(double v : r) m = (std::max)(m, v);
    return m;
  }

  // keeps the free bubbles with keep[i], appends the new ones, keeps the fixed ones
  void replace_free(const std::vector<char>& keep, const std::vector<double>& nx, const std::vector<double>& ny,
                    const std::vector<double>& nz, const std::vector<double>& nr,
                    const std::vector<double>& nclear)
  {
    Bubble_system s;
    s.region = region;
    s.confinement = confinement;
    s.next_key = next_key;
    s.input_population = input_population;
    s.rejected = rejected;
    std::copy(box, box + 6, s.box);
    for(std::size_t i = 0; i < n_free; ++i)
      if(keep[i])
      {
        s.push_free(x[i], y[i], z[i], r[i], key[i], clearance[i]);
        const std::size_t j = s.n_free - 1;
        s.vx[j] = vx[i]; s.vy[j] = vy[i]; s.vz[j] = vz[i];
        s.cx[j] = cx[i]; s.cy[j] = cy[i]; s.cz[j] = cz[i];
        s.sx[j] = sx[i]; s.sy[j] = sy[i]; s.sz[j] = sz[i];
      }
    for(std::size_t k = 0; k < nx.size(); ++k) s.push_free(nx[k], ny[k], nz[k], nr[k], s.next_key++, nclear[k]);
    for(std::size_t i = n_free; i < size(); ++i) s.push_fixed(x[i], y[i], z[i], r[i], key[i]);
    *this = std::move(s);
  }

  void push_free(double px, double py, double pz, double pr, std::size_t k, double clear)
  {
    CGAL_precondition(size() == n_free); // free bubbles go before the fixed ones
    x.push_back(px); y.push_back(py); z.push_back(pz); r.push_back(pr); key.push_back(k);
    vx.push_back(0.); vy.push_back(0.); vz.push_back(0.);
    cx.push_back(px); cy.push_back(py); cz.push_back(pz); clearance.push_back(clear);
    sx.push_back(px); sy.push_back(py); sz.push_back(pz);
    ++n_free;
  }

  void push_fixed(double px, double py, double pz, double pr, std::size_t k)
  {
    x.push_back(px); y.push_back(py); z.push_back(pz); r.push_back(pr); key.push_back(k);
  }

  // files every bubble in `grid`, for queries reaching at most `reach` times the sum of radii
  void fill_grid(Bubble_grid& grid, double reach) const
  {
    grid.build(x.data(), y.data(), z.data(), r.data(), size(), box, reach);
  }

  // orders the free bubbles along the grid's cells, so that neighbours sit close in memory
  void sort_free_spatially(double cell)
  {
    Neighbor_grid grid;
    grid.set_domain(box[0], box[1], box[2], box[3], box[4], box[5], cell, 4 * n_free + 64);
    grid.build(x.data(), y.data(), z.data(), n_free);
    const std::vector<Neighbor_grid::Index>& order = grid.items_in_cell_order();
    auto permute = [&](std::vector<double>& v) {
      std::vector<double> w(v.size());
      for(std::size_t i = 0; i < n_free; ++i) w[i] = v[order[i]];
      for(std::size_t i = n_free; i < v.size(); ++i) w[i] = v[i];
      v.swap(w);
    };
    for(std::vector<double>* v : {&x, &y, &z, &r, &vx, &vy, &vz, &cx, &cy, &cz, &clearance, &sx, &sy, &sz})
      permute(*v);
    std::vector<std::size_t> k2(key.size());
    for(std::size_t i = 0; i < n_free; ++i) k2[i] = key[order[i]];
    for(std::size_t i = n_free; i < key.size(); ++i) k2[i] = key[i];
    key.swap(k2);
  }
};

// the radius of the surface bubble at each model point (0 where there is none),
// as `Region_confinement` takes them
template <class K>
std::vector<double> surface_point_radii(const Geological_model_3<K>& model, const std::vector<Bubble<K> >& surface_bubbles)
{
  std::vector<double> radius(model.number_of_points(), 0.);
  for(const Bubble<K>& b : surface_bubbles)
    if(b.surface_point < radius.size()) radius[b.surface_point] = b.radius;
  return radius;
}

// regions of each model point (those whose constraint surfaces use it)
template <class K>
std::vector<std::vector<std::size_t> > regions_of_points(const Geological_model_3<K>& model)
{
  std::vector<std::vector<std::size_t> > pr(model.number_of_points());
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    const auto& patch = model.patch(model.patch_of_triangle(t));
    for(std::size_t v : model.triangle(t))
      for(std::size_t reg : {patch.positive_region, patch.negative_region})
        if(reg != 0 && std::find(pr[v].begin(), pr[v].end(), reg) == pr[v].end()) pr[v].push_back(reg);
  }
  return pr;
}

template <class K, class SizingField>
double sizing_at(const SizingField& sizing, double x, double y, double z, std::size_t region)
{
  return sizing(typename K::Point_3(x, y, z), region);
}

/*
One system per region that has interior bubbles. Radii are read from the
sizing field; start positions that lie outside the region or in a protected
diametral ball are mended, or the bubble is dropped (counted in `rejected`).
Regions of interior bubbles that are not regions of the model are left out
(`skipped` gets their indices).
*/
template <class ConcurrencyTag, class K, class SizingField>
std::vector<Bubble_system<K> >
make_bubble_systems(const Geological_model_3<K>& model, const std::vector<Bubble<K> >& surface_bubbles,
                    const std::vector<Bubble<K> >& interior_bubbles, const SizingField& sizing,
                    const Dynamics_settings& settings, std::vector<std::size_t>& skipped)
{
  const std::size_t nr = model.number_of_regions();
  std::vector<std::vector<std::size_t> > members(nr + 1);
  for(std::size_t i = 0; i < interior_bubbles.size(); ++i)
  {
    const std::size_t reg = interior_bubbles[i].region;
    if(reg == 0 || reg > nr) skipped.push_back(i);
    else members[reg].push_back(i);
  }
  const std::vector<double> point_radius = surface_point_radii(model, surface_bubbles);
  const std::vector<std::vector<std::size_t> > pr = regions_of_points(model);

  std::vector<std::size_t> active;
  for(std::size_t reg = 1; reg <= nr; ++reg)
    if(!members[reg].empty()) active.push_back(reg);
  std::vector<Bubble_system<K> > systems(active.size());
  const Confinement_settings& cs = settings.confinement;

  for_each_block<ConcurrencyTag>(active.size(), 1, [&](std::size_t a0, std::size_t a1) {
    for(std::size_t a = a0; a < a1; ++a)
    {
      const std::size_t reg = active[a];
      Bubble_system<K>& s = systems[a];
      s.region = reg;
      s.confinement = std::make_shared<const Region_confinement<K> >(model, reg, point_radius, cs);
      const std::array<double, 6>& bb = s.confinement->bbox();
      std::copy(bb.begin(), bb.end(), s.box);
      const std::vector<std::size_t>& m = members[reg];
      s.input_population = m.size();
      std::vector<double> px(m.size()), py(m.size()), pz(m.size()), prad(m.size()), pclear(m.size());
      std::vector<char> ok(m.size(), 0);
      for_each_block<ConcurrencyTag>(m.size(), 64, [&](std::size_t b, std::size_t e) {
        for(std::size_t k = b; k < e; ++k)
        {
          const auto& c = interior_bubbles[m[k]].center;
          double p[3] = {CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z())};
          const double rad = sizing_at<K>(sizing, p[0], p[1], p[2], reg);
          if(!(rad > 0.)) continue;
          const Confinement_result placed = s.confinement->place(p, rad);
          if(placed == Confinement_result::REJECTED) continue;
          px[k] = p[0]; py[k] = p[1]; pz[k] = p[2];
          // a bubble left where it was keeps the radius just read there
          prad[k] = placed == Confinement_result::UNCHANGED ? rad : sizing_at<K>(sizing, p[0], p[1], p[2], reg);
          pclear[k] = s.confinement->clearance(p, prad[k]);
          ok[k] = prad[k] > 0.;
        }
      });
      for(std::size_t k = 0; k < m.size(); ++k)
      {
        if(ok[k]) s.push_free(px[k], py[k], pz[k], prad[k], m[k], pclear[k]);
        else ++s.rejected;
      }
      s.next_key = interior_bubbles.size();
      for(std::size_t b = 0; b < surface_bubbles.size(); ++b)
      {
        const std::size_t v = surface_bubbles[b].surface_point;
        if(v >= pr.size() || std::find(pr[v].begin(), pr[v].end(), reg) == pr[v].end()) continue;
        const auto& c = surface_bubbles[b].center;
        s.push_fixed(CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z()),
                     surface_bubbles[b].radius, b);
      }
    }
  });
  return systems;
}

// ---- overlap ratio --------------------------------------------------------------

/*
Overlap ratio of each free bubble (METHOD.md, stage 4):
  alpha_i = (1/r_i) sum_j max(0, 2 r_i + r_j - l_ij)
over all other bubbles j of the region, surface bubbles included. A
neighbour at rest distance l = r_i + r_j adds exactly 1 whatever the radii, a
closer one more, a farther one less, down to 0 at l = 2 r_i + r_j (1.5 times
the rest distance for equal radii: the reach of the force law). alpha thus
counts neighbours weighted by closeness; a perfect face-centred cubic packing
at rest gives 12 + 6 (3 - 2 sqrt 2) = 13.03 (the 6 second neighbours at
2 sqrt 2 r still add 0.17 each), a random close packing about 11.

Counting neighbours is right only where they are as large as the bubble:
in a graded field a small bubble has room for fewer large neighbours and a
large one for more small ones, so the paper's ratio calls the small bubbles
of a gradient sparse and the large ones crowded, and population control
trades bubbles there round after round (modelA1 re-meshed: about 1,200 each
way per round until the cycle guard stops it; with the weights below its
relaxation takes 66 s instead of 78 s). With `solid_angle` each term
between free bubbles is weighted by the solid angle a neighbour of radius
r_j takes from bubble i's centre at rest distance, over an equal neighbour's:
sin t = r_j / (r_i + r_j), w = (1 - cos t) / (1 - cos 30 deg). Equal radii
give w = 1, so a uniform packing has the same ratios either way. A surface
bubble counts as in the paper: its radius is the surface triangulation's
(with the surfaces kept, the input's own edges), not the packing's, and
weighting it too left bubbles against finely triangulated surfaces that the
paper's count keeps away (modelA5 kept: aspect-ratio median 2.30 -> 2.32,
against 2.28 with the surface terms as they are).
*/
// bubble j's term in bubble i's overlap ratio (METHOD.md, stage 4), times r_i:
// max(0, 2 r_i + r_j - l_ij), from the squared distance l_ij^2, weighted by the solid angle if asked
// (the callers ask for it between free bubbles only)
inline double overlap_share(double l2, double ri, double rj, bool solid_angle)
{
  const double reach = 2. * ri + rj;
  if(!(l2 < reach * reach)) return 0.;
  const double share = reach - std::sqrt(l2);
  if(!solid_angle || rj == ri) return share;
  const double sin_t = rj / (ri + rj);
  return share * (1. - std::sqrt(1. - sin_t * sin_t)) / (1. - 0.5 * std::sqrt(3.));
}

// What a plane at distance d = t r covered with bubbles of radius r (a
// hexagonal lattice at rest spacing 2r) adds to a bubble of radius r's ratio:
// the integral of max(0, 3r - l) / r over the plane at the lattice's density
// 1 / (2 sqrt(3) r^2), (pi / sqrt 3)(4.5 - 1.5 t^2 + t^3 / 3) for t < 3.
inline double plane_overlap(double t)
{
  if(!(t < 3.)) return 0.;
  return 1.8137993642342178 * (4.5 - 1.5 * t * t + t * t * t / 3.);
}

// The wall term of a bubble at (x, y, z) of radius r whose surface neighbours
// add `surface_sum` (times r), next to a bare wall (the nearest triangle at
// least 6r long, three times the packing's spacing): what that surface would
// add if its bubbles were as large as this one, less what they do add. Next
// to smaller triangles the term is 0, so the lattice of their bubbles is not
// second-guessed (with 3r, the term also touched walls whose bubbles nearly
// cover them, and made modelA5's mesh worse; bench/README.md, session 44).
template <class K>
double wall_term(const Bubble_system<K>& s, double x, double y, double z, double r, double surface_sum)
{
  if(!s.confinement || !s.confinement->has_surfaces()) return 0.;
  const double p[3] = {x, y, z};
  double longest = 0.;
  const double d = s.confinement->distance_to_surfaces(p, 3. * r, longest);
  if(longest < 6. * r) return 0.;
  return (std::max)(0., plane_overlap(d / r) - surface_sum / r);
}

template <class ConcurrencyTag, class K>
std::vector<double> overlap_ratios(const Bubble_system<K>& s, const Bubble_grid& grid, bool solid_angle, bool wall)
{
  std::vector<double> alpha(s.n_free, 0.);
  for_each_block<ConcurrencyTag>(s.n_free, 256, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      const double xi = s.x[i], yi = s.y[i], zi = s.z[i], ri = s.r[i];
      double sum = 0., surf = 0.;
      grid.for_each_near(xi, yi, zi, 2. * ri, 1., [&](std::size_t j) {
        if(j == i) return;
        const double dx = s.x[j] - xi, dy = s.y[j] - yi, dz = s.z[j] - zi;
        const double sh = overlap_share(dx * dx + dy * dy + dz * dz, ri, s.r[j], solid_angle && j < s.n_free);
        sum += sh;
        if(j >= s.n_free) surf += sh;
      });
      alpha[i] = sum / ri + (wall ? wall_term(s, xi, yi, zi, ri, surf) : 0.);
    }
  });
  return alpha;
}

template <class ConcurrencyTag, class K>
std::vector<double> overlap_ratios(const Bubble_system<K>& s, bool solid_angle, bool wall)
{
  Bubble_grid grid;
  s.fill_grid(grid, 1.5);
  return overlap_ratios<ConcurrencyTag>(s, grid, solid_angle, wall);
}

// 32 directions spread evenly over the sphere (golden-angle spiral), the candidate gaps
inline const std::vector<std::array<double, 3> >& gap_directions()
{
  static const std::vector<std::array<double, 3> > dirs = [] {
    std::vector<std::array<double, 3> > d;
    const std::size_t n = 32;
    const double golden = 3.14159265358979323846 * (3. - std::sqrt(5.));
    for(std::size_t k = 0; k < n; ++k)
    {
      const double zz = 1. - (2. * double(k) + 1.) / double(n);
      const double rho = std::sqrt((std::max)(0., 1. - zz * zz));
      d.push_back({{rho * std::cos(golden * double(k)), rho * std::sin(golden * double(k)), zz}});
    }
    return d;
  }();
  return dirs;
}

/*
One pass of population control on one region, sequential and in a fixed
order (it is cheap next to relaxation, and the order makes it deterministic).

Deletion: the free bubbles above the upper bound, most crowded first; each
deletion lowers its neighbours' ratios at once, so a crowded cluster loses
just enough bubbles and not all of them.

Insertion: next to each free bubble below the lower bound, least crowded
first, in the largest gap: among 32 directions, the touching position whose
nearest neighbour is farthest (distance over the sum of radii). It is used if
that clearance reaches `insertion_clearance` and the position is valid (no
surface crossed from the parent, outside protected balls). Bubbles whose
neighbour was just deleted are skipped: relaxation first closes that gap,
and refilling it at once is how add/delete cycles start. A new bubble with
less than half the lower bound is a parent in its turn, later in the same
pass (it stands at the edge of an empty part).
*/
template <class ConcurrencyTag, class K, class SizingField>
Population_change population_pass(Bubble_system<K>& s, const SizingField& sizing, const Dynamics_settings& settings)
{
  const double upper = settings.max_overlap;
  Population_change change;
  const std::size_t n = s.n_free, total = s.size();
  if(n == 0) return change;
  Bubble_grid grid;
  s.fill_grid(grid, 1.5);
  const bool solid_angle = settings.solid_angle_overlap;
  std::vector<double> alpha = overlap_ratios<ConcurrencyTag>(s, grid, solid_angle, settings.wall_overlap);

  // -- deletion
  std::vector<char> keep(n, 1), near_deleted(n, 0);
  std::vector<std::size_t> order;
  for(std::size_t i = 0; i < n; ++i)
    if(alpha[i] > upper) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return alpha[a] > alpha[b]; });
  for(std::size_t i : order)
  {
    if(!(alpha[i] > upper)) continue;
    keep[i] = 0;
    ++change.removed;
    grid.for_each_near(s.x[i], s.y[i], s.z[i], s.r[i], 2., [&](std::size_t j) {
      if(j == i || j >= n || !keep[j]) return;
      const double dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i], dz = s.z[j] - s.z[i];
      const double share = overlap_share(dx * dx + dy * dy + dz * dz, s.r[j], s.r[i], solid_angle);
      if(share > 0.)
      {
        alpha[j] -= share / s.r[j];
        near_deleted[j] = 1;
      }
    });
  }

  // -- insertion
  std::vector<double> nx, ny, nz, nr, nclear;
  auto px = [&](std::size_t j) { return j < total ? s.x[j] : nx[j - total]; };
  auto py = [&](std::size_t j) { return j < total ? s.y[j] : ny[j - total]; };
  auto pz = [&](std::size_t j) { return j < total ? s.z[j] : nz[j - total]; };
  auto pr = [&](std::size_t j) { return j < total ? s.r[j] : nr[j - total]; };
  auto alive = [&](std::size_t j) { return j >= n || keep[j]; }; // fixed and new ones always are
  order.clear();
  for(std::size_t i = 0; i < n; ++i)
    if(keep[i] && !near_deleted[i] && alpha[i] < settings.min_overlap) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return alpha[a] < alpha[b]; });
  const std::vector<std::array<double, 3> >& dirs = gap_directions();
  // a gap next to the bubble may open a little nearer or farther than touching
  const double gap_distances[3] = {1., 0.85, 1.2};
  std::vector<double> nalpha; // the new bubbles' ratios
  std::vector<std::array<double, 4> > near; // a parent's neighbours: x, y, z, r
  auto ratio = [&](std::size_t j) -> double& { return j < total ? alpha[j] : nalpha[j - total]; };
  for(std::size_t o = 0; o < order.size(); ++o)
  {
    const std::size_t i = order[o];
    if(!(ratio(i) < settings.min_overlap)) continue;
    const double xi = px(i), yi = py(i), zi = pz(i), ri = pr(i);
    std::vector<std::pair<double, std::size_t> > candidates;
    std::vector<std::array<double, 4> > spots;
    // the field varies on the scale of the mesh size: the parent's radius is
    // good enough to compare gaps; the chosen one reads its own radius
    const double rn = ri;
    // The bubbles that can bound a spot's clearance (closer than 1.5 (rn + r_j)
    // to a spot at most 1.2 (ri + rn) away), gathered once for all 96 spots: in
    // a graded region the grid's cells are sized for the median radius, and a
    // small parent's queries each scanned whole cells of small bubbles.
    near.clear();
    const double near_a = (1.2 * (ri + rn) + 1.5 * rn) * (1. + 1e-9), near_b = 1.5 * (1. + 1e-9);
    grid.for_each_near(xi, yi, zi, near_a, near_b, [&](std::size_t j) {
      if(!alive(j)) return;
      const double dx = px(j) - xi, dy = py(j) - yi, dz = pz(j) - zi, lim = near_a + near_b * pr(j);
      if(dx * dx + dy * dy + dz * dz < lim * lim) near.push_back({{px(j), py(j), pz(j), pr(j)}});
    });
    for(std::size_t d = 0; d < dirs.size(); ++d)
    {
      for(double reach : gap_distances)
      {
        const double q[3] = {xi + reach * (ri + rn) * dirs[d][0], yi + reach * (ri + rn) * dirs[d][1],
                             zi + reach * (ri + rn) * dirs[d][2]};
        double clear = 1.5;
        // (a spot already nearer than insertion_clearance is out, and a neighbour
        // that cannot lower the minimum needs no square root: the spots kept and
        // their clearances are the same, bit for bit, as with every term taken)
        for(const std::array<double, 4>& b : near)
        {
          if(clear < settings.insertion_clearance) break;
          const double dx = b[0] - q[0], dy = b[1] - q[1], dz = b[2] - q[2], sum = rn + b[3];
          const double d2 = dx * dx + dy * dy + dz * dz, bound = clear * sum;
          if(d2 > bound * bound * (1. + 1e-9)) continue;
          clear = (std::min)(clear, std::sqrt(d2) / sum);
        }
        if(clear >= settings.insertion_clearance)
        {
          candidates.push_back(std::make_pair(clear, spots.size()));
          spots.push_back({{q[0], q[1], q[2], rn}});
        }
      }
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const std::pair<double, std::size_t>& a, const std::pair<double, std::size_t>& b) {
                       return a.first > b.first;
                     });
    const double from[3] = {xi, yi, zi};
    for(const auto& c : candidates)
    {
      std::array<double, 4>& q = spots[c.second];
      q[3] = sizing_at<K>(sizing, q[0], q[1], q[2], s.region);
      if(!(q[3] > 0.) || !s.confinement->accepts(from, q.data(), q[3])) continue;
      const std::size_t id = total + nx.size();
      nx.push_back(q[0]); ny.push_back(q[1]); nz.push_back(q[2]); nr.push_back(q[3]);
      nclear.push_back(s.confinement->clearance(q.data(), q[3]));
      // the new bubble counts for its free neighbours at once, and they for it
      double own = 0., surf = 0.;
      grid.for_each_near(q[0], q[1], q[2], 2. * q[3], 2., [&](std::size_t j) {
        if(!alive(j)) return;
        const double dx = px(j) - q[0], dy = py(j) - q[1], dz = pz(j) - q[2];
        const double l2 = dx * dx + dy * dy + dz * dz;
        const double sh = overlap_share(l2, q[3], pr(j), solid_angle && (j < n || j >= total));
        own += sh / q[3];
        if(j >= n && j < total) surf += sh;
        if(j < n || j >= total) ratio(j) += overlap_share(l2, pr(j), q[3], solid_angle) / pr(j);
      });
      grid.insert(id, q[0], q[1], q[2], q[3]);
      if(settings.wall_overlap) own += wall_term(s, q[0], q[1], q[2], q[3], surf);
      nalpha.push_back(own);
      // A bubble inserted at the edge of an empty part of the region (the
      // placement's lattice is coarser than the bubbles near fine surfaces)
      // has fewer than half the neighbours wanted: it takes its turn as a
      // parent in the same pass, so that the part fills at once and not by one
      // layer of bubbles per round of a few hundred steps.
      if(own < 0.5 * settings.min_overlap) order.push_back(id);
      ++change.added;
      break;
    }
  }
  if(change.added + change.removed > 0) s.replace_free(keep, nx, ny, nz, nr, nclear);
  return change;
}

template <class K>
void write_back(const std::vector<Bubble_system<K> >& systems, const std::vector<Bubble<K> >& input,
                const std::vector<std::size_t>& skipped, std::vector<Bubble<K> >& output)
{
  std::vector<Bubble<K> > out;
  for(const Bubble_system<K>& s : systems)
  {
    std::vector<std::size_t> order(s.n_free);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.key[a] < s.key[b]; });
    for(std::size_t i : order)
      out.push_back(Bubble<K>(typename K::Point_3(s.x[i], s.y[i], s.z[i]), s.r[i], s.region, no_index, false));
  }
  for(std::size_t i : skipped) out.push_back(input[i]);
  output.swap(out);
}

// runs f() in an arena of `threads` threads (0: the default, all cores)
template <class ConcurrencyTag, class F>
void run_with_threads(std::size_t threads, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(Runs_in_parallel<ConcurrencyTag>::value && threads > 0)
  {
    tbb::task_arena arena{int(threads)};
    arena.execute([&] { f(); });
    return;
  }
#endif
  CGAL_USE(threads);
  f();
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Overlap ratio of every interior bubble (METHOD.md, stage 4), over the other
interior bubbles of its region and the surface bubbles on the region's
surfaces:
\f[ \alpha_i = \frac{1}{r_i} \sum_j \max(0,\; 2 r_i + r_j - l_{ij}). \f]
A neighbour at rest distance \f$ l_{ij} = r_i + r_j \f$ adds exactly 1, a
closer one more, a farther one less, down to 0 at \f$ 2 r_i + r_j \f$ (the
reach of the force law for equal radii); so \f$ \alpha \f$ counts neighbours
weighted by closeness. The ideal in a volume is 12; a perfect face-centred
cubic packing at rest gives 13.03, because its 6 second neighbours at
\f$ 2\sqrt 2\, r \f$ still add 0.17 each.

By default each term between two interior bubbles is weighted by the solid
angle the neighbour takes, against an equal neighbour's, as population
control does (named parameter `solid_angle_overlap_ratio`, see
`relax_bubbles()`); surface bubbles count as in the formula above, and so do
equal radii.

A bubble next to a bare wall, a surface triangle at least 6 radii long (with
the surfaces kept, a wide input triangle), has no surface bubbles to count on
that side: the formula calls it sparse however it is packed, and population
control keeps adding bubbles beside it. By default (named parameter
`wall_overlap_ratio`) such a bubble counts the wall as the plane of bubbles of
its own radius, at rest spacing, that it could hold, less what the surface
bubbles near it already add. At distance \f$ d = t\,r_i \f$ that plane adds
\f$ \frac{\pi}{\sqrt 3}(4.5 - 1.5 t^2 + t^3/3) \f$ for \f$ t < 3 \f$: 8.2 at
the surface, 3.5 for a bubble resting on a hexagonal layer of equal bubbles
(which add 3.5 too). Next to smaller triangles the surface bubbles count
alone.

The radii are taken as they are in the bubbles. Entry `i` belongs to
`interior_bubbles[i]`; a bubble whose region is not a region of the model gets 0.

\cgalNamedParamsBegin
  \cgalParamNBegin{solid_angle_overlap_ratio}
    \cgalParamDescription{weight each term between interior bubbles by the neighbour's solid angle (`false`: METHOD.md's formula as it stands)}
    \cgalParamType{`bool`} \cgalParamDefault{`true`} \cgalParamNEnd
  \cgalParamNBegin{wall_overlap_ratio}
    \cgalParamDescription{count a bare wall near a bubble as the plane of equal bubbles it could hold (`false`: METHOD.md's formula as it stands)}
    \cgalParamType{`bool`} \cgalParamDefault{`true`} \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class K,
          class NP = CGAL::parameters::Default_named_parameters>
std::vector<double> overlap_ratios(const Geological_model_3<K>& model, const std::vector<Bubble<K> >& surface_bubbles,
                                   const std::vector<Bubble<K> >& interior_bubbles,
                                   const NP& np = parameters::default_values())
{
  const bool solid_angle = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::solid_angle_overlap_ratio), true);
  const bool wall = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::wall_overlap_ratio), true);
  const std::vector<std::vector<std::size_t> > pr = internal::regions_of_points(model);
  const std::vector<double> point_radius = internal::surface_point_radii(model, surface_bubbles);
  const std::size_t nreg = model.number_of_regions();
  std::vector<internal::Bubble_system<K> > systems(nreg + 1);
  std::vector<std::vector<std::size_t> > members(nreg + 1);
  for(std::size_t i = 0; i < interior_bubbles.size(); ++i)
  {
    const Bubble<K>& b = interior_bubbles[i];
    if(b.region == 0 || b.region > nreg) continue;
    members[b.region].push_back(i);
    systems[b.region].push_free(CGAL::to_double(b.center.x()), CGAL::to_double(b.center.y()),
                                CGAL::to_double(b.center.z()), b.radius, i, 0.);
  }
  for(std::size_t k = 0; k < surface_bubbles.size(); ++k)
  {
    const Bubble<K>& b = surface_bubbles[k];
    if(b.surface_point >= pr.size()) continue;
    for(std::size_t reg : pr[b.surface_point])
      if(!members[reg].empty())
        systems[reg].push_fixed(CGAL::to_double(b.center.x()), CGAL::to_double(b.center.y()),
                                CGAL::to_double(b.center.z()), b.radius, k);
  }
  std::vector<double> alpha(interior_bubbles.size(), 0.);
  for(std::size_t reg = 1; reg <= nreg; ++reg)
  {
    internal::Bubble_system<K>& s = systems[reg];
    if(s.n_free == 0) continue;
    const std::vector<double>* coords[3] = {&s.x, &s.y, &s.z};
    for(int d = 0; d < 3; ++d)
    {
      s.box[d] = *std::min_element(coords[d]->begin(), coords[d]->end());
      s.box[d + 3] = *std::max_element(coords[d]->begin(), coords[d]->end());
    }
    // the wall term measures distances to the region's surfaces
    if(wall)
      s.confinement = std::make_shared<const internal::Region_confinement<K> >(model, reg, point_radius,
                                                                                internal::Confinement_settings());
    const std::vector<double> a = internal::overlap_ratios<ConcurrencyTag>(s, solid_angle, wall);
    for(std::size_t k = 0; k < members[reg].size(); ++k) alpha[members[reg][k]] = a[k];
  }
  return alpha;
}

/*!
\ingroup PkgBubbleMesh3Ref

One pass of adaptive population control (METHOD.md, stage 4) over every
region, without relaxation: interior bubbles whose overlap ratio (see
`overlap_ratios()`) exceeds the upper bound are deleted, most crowded first,
each deletion lowering its neighbours' ratios at once; next to interior
bubbles below the lower bound a new bubble is inserted in the largest gap
(the touching position, among 32 directions, farthest from all other
bubbles), if that gap is wide enough and the position is inside the region
and outside the protected diametral balls of its surfaces (see
`relax_bubbles()`); a new bubble with less than half the lower bound stands
at the edge of an empty part of the region and gets a neighbour of its own
in the same pass. Radii are first read from the sizing field.

`relax_bubbles()` alternates this pass with relaxation; call it alone to
study or script the method. The output is grouped by region; inside a region
the surviving bubbles keep their order and the new ones follow.

\tparam ConcurrencyTag `CGAL::Parallel_tag` runs the regions concurrently (with TBB);
        the result does not depend on it.
\tparam SizingField a model of `BubbleSizingField`.

\cgalNamedParamsBegin
  \cgalParamNBegin{min_overlap_ratio} \cgalParamDescription{lower bound of the overlap ratio}
    \cgalParamType{`double`} \cgalParamDefault{10} \cgalParamNEnd
  \cgalParamNBegin{max_overlap_ratio} \cgalParamDescription{upper bound of the overlap ratio}
    \cgalParamType{`double`} \cgalParamDefault{14} \cgalParamNEnd
  \cgalParamNBegin{insertion_clearance} \cgalParamDescription{least distance, over the sum of radii,
    from an inserted bubble to every other bubble}
    \cgalParamType{`double`} \cgalParamDefault{0.85} \cgalParamNEnd
  \cgalParamNBegin{diametral_ball_margin, max_protected_ball_ratio, surface_offset_ratio}
    \cgalParamDescription{see `relax_bubbles()`} \cgalParamNEnd
  \cgalParamNBegin{number_of_threads} \cgalParamDescription{threads used (0: all cores)}
    \cgalParamType{`std::size_t`} \cgalParamDefault{0} \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class K, class SizingField,
          class NP = CGAL::parameters::Default_named_parameters>
Population_change control_bubble_population(const Geological_model_3<K>& model,
                                            const std::vector<Bubble<K> >& surface_bubbles,
                                            std::vector<Bubble<K> >& interior_bubbles, const SizingField& sizing,
                                            const NP& np = parameters::default_values())
{
  const internal::Dynamics_settings settings = internal::dynamics_settings(np, 1.);
  Population_change total;
  internal::run_with_threads<ConcurrencyTag>(settings.threads, [&] {
    std::vector<std::size_t> skipped;
    std::vector<internal::Bubble_system<K> > systems =
      internal::make_bubble_systems<ConcurrencyTag>(model, surface_bubbles, interior_bubbles, sizing, settings,
                                                    skipped);
    std::vector<Population_change> changes(systems.size());
    internal::for_each_block<ConcurrencyTag>(systems.size(), 1, [&](std::size_t a, std::size_t b) {
      for(std::size_t k = a; k < b; ++k)
        changes[k] = internal::population_pass<ConcurrencyTag>(systems[k], sizing, settings);
    });
    for(std::size_t k = 0; k < systems.size(); ++k)
    {
      total.added += changes[k].added;
      total.removed += changes[k].removed + systems[k].rejected;
    }
    internal::write_back(systems, interior_bubbles, skipped, interior_bubbles);
  });
  return total;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_CONTROL_BUBBLE_POPULATION_H
