// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_RELAX_BUBBLES_H
#define CGAL_BUBBLE_MESH_3_RELAX_BUBBLES_H

#include <CGAL/Bubble_mesh_3/Bubble.h>
#include <CGAL/Bubble_mesh_3/Cubic_bubble_force.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/control_bubble_population.h>
#include <CGAL/Bubble_mesh_3/internal/Neighbor_grid.h>
#include <CGAL/Bubble_mesh_3/internal/confine_to_region.h>
#include <CGAL/Bubble_mesh_3/internal/dynamics_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref
The figures a visitor of `relax_bubbles()` receives, after every step and at
the end of every population round of a region.
*/
struct Relaxation_progress
{
  std::size_t region = 0;        ///< the region relaxing
  std::size_t round = 0;         ///< population round (0: the first relaxation)
  std::size_t step = 0;          ///< step within the round
  std::size_t total_steps = 0;   ///< steps of this region so far
  double kinetic_energy = 0.;    ///< \f$ \frac{m}{2} \sum v_i^2 \f$ over the free bubbles
  double max_displacement = 0.;  ///< largest move in the last step over the bubble's radius
  std::size_t added = 0;         ///< bubbles inserted by this round's population control
  std::size_t removed = 0;       ///< bubbles deleted by this round's population control
  std::size_t population = 0;    ///< interior bubbles of the region
  std::size_t moving = 0;        ///< of those, the ones moved in the last step (the others rest, see `resting_displacement_ratio`)
  bool end_of_round = false;     ///< true for the call that closes a round
};

/*!
\ingroup PkgBubbleMesh3Ref
What `relax_bubbles()` did in one region.
*/
struct Region_relaxation_report
{
  /// the region
  std::size_t region = 0;
  std::size_t input_population = 0;   ///< interior bubbles given
  std::size_t population = 0;         ///< interior bubbles returned
  std::size_t surface_bubbles = 0;    ///< fixed bubbles on the region's surfaces
  std::size_t steps = 0;              ///< integration steps, all rounds
  double bubble_steps = 0.;           ///< sum over steps of the free bubbles moved (resting ones not counted)
  std::size_t list_rebuilds = 0;      ///< rebuilds of the neighbour lists, all rounds
  std::size_t rounds = 0;             ///< population rounds done
  std::size_t added = 0;              ///< inserted by population control
  std::size_t removed = 0;            ///< deleted by population control
  std::size_t rejected = 0;           ///< dropped: no valid start position inside the region
  bool converged = false;             ///< the last relaxation met the displacement tolerance
  bool population_settled = false;    ///< the last population pass changed (almost) nothing
  bool stopped_cycling = false;       ///< population control stopped by the add/delete-cycle guard
  bool interrupted = false;           ///< the visitor asked to stop
  double kinetic_energy = 0.;         ///< at the end
  double max_displacement = 0.;       ///< of the last step, over the local radius
  /// final overlap ratios against the bounds: bubbles below, inside, above them
  ///@{
  std::size_t below = 0, inside = 0, above = 0; ///< final overlap ratios against the bounds
  ///@}
  std::vector<std::size_t> overlap_histogram;   ///< bin k counts k <= alpha < k+1; the last bin is open
  /// time spent on the region
  double seconds = 0.;
};

/*!
\ingroup PkgBubbleMesh3Ref
What `relax_bubbles()` did: one entry per region that had interior bubbles,
and the totals.
*/
struct Relaxation_report
{
  /// one entry per region with interior bubbles
  std::vector<Region_relaxation_report> regions;
  std::size_t steps = 0;          ///< sum over regions
  double bubble_steps = 0.;       ///< sum over regions
  std::size_t list_rebuilds = 0;  ///< sum over regions
  /// sums over regions of the fields of `Region_relaxation_report` with these names
  ///@{
  std::size_t population = 0, added = 0, removed = 0, rejected = 0;
  ///@}
  /// sums over regions: bubbles whose overlap ratio is below, inside, above the bounds
  ///@{
  std::size_t below = 0, inside = 0, above = 0;
  ///@}
  /// sum over regions of the overlap-ratio histograms
  std::vector<std::size_t> overlap_histogram;
  double seconds = 0.;            ///< wall-clock time of the whole call

  /// every region's last relaxation met the tolerance
  bool converged() const
  {
    for(const Region_relaxation_report& r : regions)
      if(!r.converged) return false;
    return true;
  }

  /// share of the interior bubbles whose overlap ratio lies inside the bounds
  double share_inside_bounds() const
  {
    const std::size_t n = below + inside + above;
    return n == 0 ? 1. : double(inside) / double(n);
  }
};

namespace internal {

struct Default_relaxation_visitor
{
  bool operator()(const Relaxation_progress&) const { return true; }
};

// visitors may return void or bool (false: stop)
template <class Visitor>
bool call_visitor(Visitor& visitor, const Relaxation_progress& p)
{
  if constexpr(std::is_void<decltype(visitor(p))>::value)
  {
    visitor(p);
    return true;
  }
  else
    return bool(visitor(p));
}

constexpr std::size_t overlap_histogram_bins = 31;

/*
Damped dynamics of one region's free bubbles:  m x'' + c x' = F(x),
Heun's predictor-corrector (explicit Euler predictor, trapezoidal corrector):
  a0 = (F(x) - c v)/m,  x* = x + dt v,  v* = v + dt a0,
  a1 = (F(x*) - c v*)/m,  x' = x + dt (v + v*)/2,  v' = v + dt (a0 + a1)/2.
F is summed over Verlet neighbour lists (pairs closer than (cutoff + skin)
times the sum of radii at the last rebuild). A bubble that has moved, or
grown, by more than the skin can absorb is a stray: its list no longer holds
every neighbour, nor do the others' lists hold it. A few bubbles pressed on a
wall or a protected ball stray while the rest has nearly settled, so rather
than rebuilding every list for them, the strays' pairs are found in the grid
of the last rebuild and added after the lists' sums, in stray order; the
lists are rebuilt once the strays are more than a small share of the bubbles.
Each bubble sums its own list in a fixed order, then the strays' pairs in
increasing index order, so forces do not depend on the thread count.
*/
template <class ConcurrencyTag, class K, class ForceLaw, class SizingField>
class Relaxer
{
public:
  struct Figures
  {
    double kinetic_energy = 0.;
    double max_displacement = 0.;
  };

  Relaxer(Bubble_system<K>& s, const ForceLaw& law, const SizingField& sizing, const Dynamics_settings& st)
    : s_(s), law_(law), sizing_(sizing), st_(st)
  {}

  std::size_t list_rebuilds() const { return rebuilds_; }

  /// the free bubbles that moved more than `d` times their radius in the last step
  std::size_t moving_more_than(double d) const
  {
    return std::size_t(std::count_if(disp_.begin(), disp_.begin() + s_.n_free, [d](double v) { return v > d; }));
  }

  /*
  Resting bubbles. After a population pass most of a large region is soon at
  rest while a few parts still move (next to the changes, against walls), and
  every step used to move everyone. A free bubble whose steps stay under
  `threshold` (times its radius) for `rest_after_steps` steps in a row rests:
  it is not moved and its forces are not summed, until a bubble of its list
  moves more than `threshold` in one step, or until every `full_step_period`-th
  step moves all bubbles (drift slower than the threshold adds up, and
  neighbours that left the list are seen again). The threshold is a share of
  the relaxation's tolerance, so a resting bubble is one that would not hold
  up convergence anyway. Every flag is decided from the last step's
  displacements alone: the result does not depend on the number of threads.
  */
  void set_rest_threshold(double threshold) { rest_threshold_ = threshold; }
  /// the free bubbles moved in the last step
  std::size_t moving_bubbles() const { return moving_; }

  /// to call after the population changed
  void reset()
  {
    const std::size_t n = s_.n_free, total = s_.size();
    if(!st_.inertial) // Heun's predicted state; FIRE has none
    {
      px_.assign(s_.x.begin(), s_.x.end());
      py_.assign(s_.y.begin(), s_.y.end());
      pz_.assign(s_.z.begin(), s_.z.end());
      pvx_.assign(n, 0.); pvy_.assign(n, 0.); pvz_.assign(n, 0.);
      f1x_.assign(n, 0.); f1y_.assign(n, 0.); f1z_.assign(n, 0.);
    }
    f0x_.assign(n, 0.); f0y_.assign(n, 0.); f0z_.assign(n, 0.);
    ke_.assign(n, 0.); disp_.assign(n, 0.);
    resting_.assign(n, 0); quiet_steps_.assign(n, 0);
    steps_since_full_ = 0;
    dt_ = st_.time_step; mixing_ = fire_mixing; downhill_steps_ = 0; inertial_steps_ = 0;
    moving_ = n;
    follow_sizing_ = true;
    steps_ = 0;
    CGAL_USE(total);
    rebuild_lists();
    forces(s_.x.data(), s_.y.data(), s_.z.data(), f0x_.data(), f0y_.data(), f0z_.data());
  }

  /// one step of the free bubbles: FIRE by default, else METHOD.md's damped dynamics
  Figures step() { return st_.inertial ? inertial_step() : damped_step(); }

private:
  // m x'' + c x' = F by Heun's scheme (see the class comment)
  Figures damped_step()
  {
    const std::size_t n = s_.n_free;
    const double dt = st_.time_step;
    // predictor
    for_each_block<ConcurrencyTag>(n, 512, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        if(resting_[i])
        {
          px_[i] = s_.x[i]; py_[i] = s_.y[i]; pz_[i] = s_.z[i];
          pvx_[i] = pvy_[i] = pvz_[i] = 0.;
          continue;
        }
        const double inv_m = inv_mass_[i], c = damping_[i];
        double dx = dt * s_.vx[i], dy = dt * s_.vy[i], dz = dt * s_.vz[i];
        const double len = std::sqrt(dx * dx + dy * dy + dz * dz), lim = st_.max_step * s_.r[i];
        if(len > lim) { const double k = lim / len; dx *= k; dy *= k; dz *= k; }
        px_[i] = s_.x[i] + dx; py_[i] = s_.y[i] + dy; pz_[i] = s_.z[i] + dz;
        pvx_[i] = s_.vx[i] + dt * (f0x_[i] - c * s_.vx[i]) * inv_m;
        pvy_[i] = s_.vy[i] + dt * (f0y_[i] - c * s_.vy[i]) * inv_m;
        pvz_[i] = s_.vz[i] + dt * (f0z_[i] - c * s_.vz[i]) * inv_m;
      }
    });
    update_lists(px_.data(), py_.data(), pz_.data());
    forces(px_.data(), py_.data(), pz_.data(), f1x_.data(), f1y_.data(), f1z_.data());
    // corrector, confinement, radii
    for_each_block<ConcurrencyTag>(n, 512, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        if(resting_[i]) { disp_[i] = 0.; ke_[i] = 0.; continue; }
        const double ri = s_.r[i], inv_m = inv_mass_[i], c = damping_[i];
        double dx = 0.5 * dt * (s_.vx[i] + pvx_[i]);
        double dy = 0.5 * dt * (s_.vy[i] + pvy_[i]);
        double dz = 0.5 * dt * (s_.vz[i] + pvz_[i]);
        double vx = s_.vx[i] + 0.5 * dt * inv_m * (f0x_[i] - c * s_.vx[i] + f1x_[i] - c * pvx_[i]);
        double vy = s_.vy[i] + 0.5 * dt * inv_m * (f0y_[i] - c * s_.vy[i] + f1y_[i] - c * pvy_[i]);
        double vz = s_.vz[i] + 0.5 * dt * inv_m * (f0z_[i] - c * s_.vz[i] + f1z_[i] - c * pvz_[i]);
        const double len = std::sqrt(dx * dx + dy * dy + dz * dz), lim = st_.max_step * ri;
        if(len > lim)
        {
          // a safety limit for crowded starts; inactive near rest
          const double k = lim / len;
          dx *= k; dy *= k; dz *= k; vx *= k; vy *= k; vz *= k;
        }
        move_to(i, dx, dy, dz, len, lim, vx, vy, vz, 0.);
      }
    });
    return end_step();
  }

  // what follows a step of either scheme: the figures, the bubbles at rest, the lists and
  // the forces at the new positions
  Figures end_step()
  {
    const std::size_t n = s_.n_free;
    // the kinetic energy summed, the largest displacement
    const std::array<double, 2> sm = deterministic_reduce<ConcurrencyTag, 2>(
      n, [&](std::size_t i) { return std::array<double, 2>{ke_[i], disp_[i]}; }, {false, true});
    // (before the forces below: a bubble woken now needs its force for the next step)
    if(rest_threshold_ > 0.) update_resting();
    update_lists(s_.x.data(), s_.y.data(), s_.z.data());
    forces(s_.x.data(), s_.y.data(), s_.z.data(), f0x_.data(), f0y_.data(), f0z_.data());
    // Radii are held once the motion is small: where the sizing field jumps (a
    // surface bubble entering or leaving the weight-point range) a bubble moving
    // across the jump would otherwise swing between two radii for ever.
    // They are also held after the first steps of a relaxation: where the field
    // varies fast (a huge input triangle next to small ones) bubbles drifting
    // into larger sizes grow, push their neighbours on and never come to rest.
    if(sm[1] < 10. * st_.tolerance || ++steps_ >= st_.radius_update_steps) follow_sizing_ = false;
    Figures f;
    f.kinetic_energy = 0.5 * st_.mass * sm[0];
    f.max_displacement = sm[1];
    return f;
  }

  /*
  FIRE, the fast inertial relaxation engine (Bitzek, Koskinen, Gaehler, Moseler
  and Gumbsch, Phys. Rev. Lett. 97, 170201, 2006), with a semi-implicit Euler
  step: one force evaluation a step where Heun's scheme takes two. The damped
  dynamics slows the long waves of a large region to a crawl (a damping
  critical for one bubble is far above critical for them), and population
  control's insertions start such waves at every round. FIRE moves without
  damping, turns the velocities a little towards the forces at every step and
  lengthens the step while the motion goes downhill (the power F.v, summed
  over the region, positive); when it goes uphill it stops every bubble and
  shortens the step. It comes to the same kind of rest, the forces balanced.
  The sums are taken in fixed blocks: the same for any number of threads.
  */
  Figures inertial_step()
  {
    const std::size_t n = s_.n_free;
    const double dt0 = st_.time_step;
    // F.v, |v|^2 and |F|^2 over the region
    const std::array<double, 3> sums = deterministic_reduce<ConcurrencyTag, 3>(n, [&](std::size_t i) {
      const double vx = s_.vx[i], vy = s_.vy[i], vz = s_.vz[i], fx = f0x_[i], fy = f0y_[i], fz = f0z_[i];
      return std::array<double, 3>{fx * vx + fy * vy + fz * vz, vx * vx + vy * vy + vz * vz, fx * fx + fy * fy + fz * fz};
    }, {false, false, false});
    const bool uphill = sums[0] < 0.;
    ++inertial_steps_;
    if(!uphill)
    {
      if(++downhill_steps_ > fire_delay)
      {
        dt_ = (std::min)(dt_ * fire_grow, fire_max_step * dt0);
        mixing_ *= fire_mixing_decay;
      }
    }
    else
    {
      downhill_steps_ = 0;
      if(inertial_steps_ > fire_delay) dt_ = (std::max)(dt_ * fire_shrink, fire_min_step * dt0);
      mixing_ = fire_mixing;
    }
    const double dt = dt_, a = uphill ? 0. : mixing_, mix = sums[2] > 0. ? a * std::sqrt(sums[1] / sums[2]) : 0.;
    for_each_block<ConcurrencyTag>(n, 512, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        if(resting_[i]) { disp_[i] = 0.; ke_[i] = 0.; continue; }
        const double ri = s_.r[i], inv_m = inv_mass_[i], fx = f0x_[i], fy = f0y_[i], fz = f0z_[i];
        double vx = 0., vy = 0., vz = 0.;
        // A bubble under no force, or one lost in rounding (a millionth of a millionth
        // of a spring's force over its radius), is at rest where it is: without
        // damping it would coast on (two bubbles parted by the repulsive law) or
        // gather speed from rounding errors.
        const double f2 = fx * fx + fy * fy + fz * fz, negligible = 1e-12 * law_.stiffness() * ri;
        if(f2 > negligible * negligible)
        {
          if(!uphill)
          {
            vx = (1. - a) * s_.vx[i] + mix * fx;
            vy = (1. - a) * s_.vy[i] + mix * fy;
            vz = (1. - a) * s_.vz[i] + mix * fz;
          }
          vx += dt * fx * inv_m; vy += dt * fy * inv_m; vz += dt * fz * inv_m;
        }
        double dx = dt * vx, dy = dt * vy, dz = dt * vz;
        const double len = std::sqrt(dx * dx + dy * dy + dz * dz), lim = st_.max_step * ri;
        if(len > lim)
        {
          const double k = lim / len;
          dx *= k; dy *= k; dz *= k; vx *= k; vy *= k; vz *= k;
        }
        // A bubble stopped by an uphill step moves little in the next one, however
        // strong its force: it counts as moving the step the damped dynamics would
        // take under that force at its terminal speed, so that a stop is not taken
        // for rest.
        const double least = uphill ? dt0 * std::sqrt(f2) / (damping_[i] * ri) : 0.;
        move_to(i, dx, dy, dz, len, lim, vx, vy, vz, least);
      }
    });
    return end_step();
  }

  // FIRE's settings, those of Bitzek et al. but for the longest step: twice the
  // damped dynamics' step (whose mass scaling keeps dt omega under 0.8; the
  // semi-implicit step is stable under 2)
  static constexpr std::size_t fire_delay = 5;
  static constexpr double fire_grow = 1.1, fire_shrink = 0.5, fire_max_step = 2., fire_min_step = 0.02;
  static constexpr double fire_mixing = 0.1, fire_mixing_decay = 0.99;
  double dt_ = 0., mixing_ = fire_mixing;
  std::size_t downhill_steps_ = 0, inertial_steps_ = 0;
  // the end of a step of free bubble i: the move (dx, dy, dz), of length `len` before the
  // step limit `lim` was applied, kept inside the region, and the new velocity; `least`
  // is a floor for the displacement recorded
  void move_to(std::size_t i, double dx, double dy, double dz, double len, double lim, double vx, double vy,
               double vz, double least)
  {
    const Region_confinement<K>& conf = *s_.confinement;
    const double ri = s_.r[i];
    const double from[3] = {s_.x[i], s_.y[i], s_.z[i]};
    bool confined = false;
    double p[3] = {from[0] + dx, from[1] + dy, from[2] + dz};
    const double qx = p[0] - s_.cx[i], qy = p[1] - s_.cy[i], qz = p[2] - s_.cz[i];
    if(qx * qx + qy * qy + qz * qz >= s_.clearance[i] * s_.clearance[i] || s_.clearance[i] <= 0.)
    {
      double nrm[3] = {0., 0., 0.}, clear = 0.;
      const Confinement_result res = conf.confine(from, p, ri, nrm, clear);
      confined = res != Confinement_result::UNCHANGED;
      if(res == Confinement_result::REJECTED)
      {
        p[0] = from[0]; p[1] = from[1]; p[2] = from[2];
        vx = vy = vz = 0.;
      }
      else
      {
        if(res == Confinement_result::MOVED)
        {
          // an inelastic contact: drop the velocity into the constraint, keep the
          // rest so that a bubble pressed on a wall still slides along it, and
          // only as much of it as the bubble really moved (a bubble stopped
          // at once must not gather speed it does not use)
          const double vn = vx * nrm[0] + vy * nrm[1] + vz * nrm[2];
          if(vn < 0.) { vx -= vn * nrm[0]; vy -= vn * nrm[1]; vz -= vn * nrm[2]; }
          const double went = std::sqrt((p[0] - from[0]) * (p[0] - from[0]) + (p[1] - from[1]) * (p[1] - from[1]) +
                                        (p[2] - from[2]) * (p[2] - from[2]));
          const double frac = len > 0. ? (std::min)(1., went / (std::min)(len, lim)) : 0.;
          vx *= frac; vy *= frac; vz *= frac;
        }
        s_.cx[i] = p[0]; s_.cy[i] = p[1]; s_.cz[i] = p[2];
        s_.clearance[i] = clear;
      }
    }
    const double mx = p[0] - from[0], my = p[1] - from[1], mz = p[2] - from[2];
    disp_[i] = (std::max)(confined ? 0. : least, std::sqrt(mx * mx + my * my + mz * mz) / ri);
    s_.x[i] = p[0]; s_.y[i] = p[1]; s_.z[i] = p[2];
    s_.vx[i] = vx; s_.vy[i] = vy; s_.vz[i] = vz;
    ke_[i] = vx * vx + vy * vy + vz * vz;
    // radii follow the sizing field; it varies on the scale of the mesh size, so
    // reading it again after a small share of the radius is enough
    const double ux = p[0] - s_.sx[i], uy = p[1] - s_.sy[i], uz = p[2] - s_.sz[i];
    const double ru = st_.radius_update * ri;
    if(follow_sizing_ && ux * ux + uy * uy + uz * uz > ru * ru)
    {
      const double rn = sizing_at<K>(sizing_, p[0], p[1], p[2], s_.region);
      if(rn > 0.) s_.r[i] = rn;
      s_.sx[i] = p[0]; s_.sy[i] = p[1]; s_.sz[i] = p[2];
    }
  }

  // see set_rest_threshold()
  static constexpr unsigned char rest_after_steps = 5;
  static constexpr std::size_t full_step_period = 50;
  void update_resting()
  {
    const std::size_t n = s_.n_free;
    const bool full = ++steps_since_full_ >= full_step_period;
    if(full) steps_since_full_ = 0;
    const double threshold = rest_threshold_;
    const std::uint32_t* nb = nbr_.data();
    const std::size_t* off = offset_.data();
    for_each_block<ConcurrencyTag>(n, 512, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        if(!resting_[i])
        {
          if(disp_[i] >= threshold) { quiet_steps_[i] = 0; continue; }
          if(quiet_steps_[i] < rest_after_steps) ++quiet_steps_[i];
          // (a bubble woken by the full step rests again after one more quiet step)
          if(quiet_steps_[i] >= rest_after_steps && !full)
          {
            resting_[i] = 1;
            s_.vx[i] = s_.vy[i] = s_.vz[i] = 0.;
          }
        }
        else if(full)
          resting_[i] = 0;
        else
          // the lists also hold the fixed bubbles (index n and up), which never move
          for(const std::uint32_t* it = nb + off[i]; it != nb + off[i + 1]; ++it)
            if(*it < n && disp_[*it] > threshold)
            {
              resting_[i] = 0;
              quiet_steps_[i] = 0;
              break;
            }
      }
    });
    moving_ = n - std::size_t(std::count(resting_.begin(), resting_.begin() + n, (unsigned char)(1)));
  }

  // f(w) (r_i + r_j) / l with w = l / (r_i + r_j), the pair force over the distance
  double force_over_distance(double l, double sum) const { return law_(l / sum) * sum / l; }

  // the pair force on a bubble i at (dx, dy, dz) = x_i - x_j from j, over the distance, with
  // s = r_i + r_j, added to f; `sign` parts coincident centres reproducibly (by index); an
  // attraction is scaled by `weight()`, the pair's adjacency (see attraction_weights())
  template <class Weight>
  void add_pair(double dx, double dy, double dz, double sum, double sign, const Weight& weight, double& fx, double& fy,
                double& fz) const
  {
    const double d2 = dx * dx + dy * dy + dz * dz, cut = law_.cutoff() * sum;
    // out of reach: no division, no square root (the lists are short, so this is rare)
    if(d2 >= cut * cut) return;
    if(d2 > 1e-24 * sum * sum)
    {
      double mag = force_over_distance(std::sqrt(d2), sum);
      if(mag < 0.) mag *= double(weight());
      fx += mag * dx; fy += mag * dy; fz += mag * dz;
    }
    else
      fx += sign * law_(0.) * sum;
  }

  /*
  The pair forces of bubble i's list [first, last) (pairs with a stray left out
  when `skip_strays`), added to f in list order: the same sum, bit for bit, as
  add_pair() over the list. Nearly all the time goes to a square root and two
  divisions per pair, which one divider does one after the other; so the pairs
  in reach are first gathered (without a branch: a skin pair is in reach or
  not at random), then their roots and quotients are taken two at a time in
  SSE2 registers (the same correctly rounded operations), and the sum follows
  in list order. A pair out of reach would only add a zero.
  */
  template <bool skip_strays>
  void sum_list(std::size_t i, double xi, double yi, double zi, double ri, const double* P,
                const std::uint32_t* first, const std::uint32_t* last, const float* weight,
                const unsigned char* stray, double& fx_out, double& fy_out, double& fz_out) const
  {
    // (sums in locals: through the references they would go to memory at every pair)
    double fx = fx_out, fy = fy_out, fz = fz_out;
    constexpr std::size_t chunk = 64;
    alignas(16) double DX[chunk], DY[chunk], DZ[chunk], S[chunk], D2[chunk], M[chunk], A[chunk];
    std::uint32_t J[chunk];
    const double cutoff = law_.cutoff();
    while(first != last)
    {
      const std::uint32_t* stop = last - first > std::ptrdiff_t(chunk) ? first + chunk : last;
      std::size_t m = 0;
      for(const std::uint32_t* it = first; it != stop; ++it, ++weight)
      {
        const std::uint32_t j = *it;
        const double* q = P + 4 * std::size_t(j);
        const double dx = xi - q[0], dy = yi - q[1], dz = zi - q[2], sum = ri + q[3];
        const double d2 = dx * dx + dy * dy + dz * dz, cut = cutoff * sum;
        DX[m] = dx; DY[m] = dy; DZ[m] = dz; S[m] = sum; D2[m] = d2; J[m] = j;
        A[m] = double(*weight);
        bool in = d2 < cut * cut;
        if(skip_strays) in = in & (stray[j] == 0); // (not &&: that is a branch again)
        m += in ? 1 : 0;
      }
      first = stop;
      std::size_t t = 0;
#ifdef __SSE2__
      for(; t + 1 < m; t += 2)
      {
        const __m128d l = _mm_sqrt_pd(_mm_load_pd(D2 + t)), sum = _mm_load_pd(S + t);
        alignas(16) double w[2];
        _mm_store_pd(w, _mm_div_pd(l, sum));
        const __m128d f = _mm_set_pd(law_(w[1]), law_(w[0]));
        _mm_store_pd(M + t, _mm_div_pd(_mm_mul_pd(f, sum), l));
      }
#endif
      for(; t < m; ++t) M[t] = force_over_distance(std::sqrt(D2[t]), S[t]);
      // attraction (M < 0) only as far as the pair is adjacent (see attraction_weights())
      for(t = 0; t < m; ++t) M[t] *= M[t] < 0. ? A[t] : 1.;
      for(t = 0; t < m; ++t)
      {
        if(D2[t] > 1e-24 * S[t] * S[t])
        {
          fx += M[t] * DX[t]; fy += M[t] * DY[t]; fz += M[t] * DZ[t];
        }
        else // coincident centres (never at rest): part them along x, by index
          fx += (i < J[t] ? -1. : 1.) * law_(0.) * S[t];
      }
    }
    fx_out = fx; fy_out = fy; fz_out = fz;
  }

  void forces(const double* X, const double* Y, const double* Z, double* FX, double* FY, double* FZ)
  {
    const double* R = s_.r.data();
    // x, y, z, r of each bubble side by side: a neighbour is read from one cache line, not four
    const std::size_t total = s_.size();
    xyzr_.resize(4 * total);
    double* P = xyzr_.data();
    for_each_block<ConcurrencyTag>(total, 4096, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i) { P[4 * i] = X[i]; P[4 * i + 1] = Y[i]; P[4 * i + 2] = Z[i]; P[4 * i + 3] = R[i]; }
    });
    const std::uint32_t* nb = nbr_.data();
    const float* aw = attraction_.data();
    const std::size_t* off = offset_.data();
    const unsigned char* stray = is_stray_.data();
    const bool strays = !strays_.empty();
    for_each_block<ConcurrencyTag>(s_.n_free, 256, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        const double xi = X[i], yi = Y[i], zi = Z[i], ri = R[i];
        double fx = 0., fy = 0., fz = 0.;
        if(resting_[i]) { FX[i] = FY[i] = FZ[i] = 0.; continue; } // not moved: its force is not used
        if(!strays) sum_list<false>(i, xi, yi, zi, ri, P, nb + off[i], nb + off[i + 1], aw + off[i], stray, fx, fy, fz);
        else if(!stray[i])
          sum_list<true>(i, xi, yi, zi, ri, P, nb + off[i], nb + off[i + 1], aw + off[i], stray, fx, fy, fz);
        FX[i] = fx; FY[i] = fy; FZ[i] = fz;
      }
    });
    if(strays) add_stray_forces(X, Y, Z, FX, FY, FZ);
  }

  // the pairs of the strays, in increasing stray order: with the others from the grid
  // of the last rebuild, then among themselves
  void add_stray_forces(const double* X, const double* Y, const double* Z, double* FX, double* FY, double* FZ)
  {
    const double* R = s_.r.data();
    const std::size_t n = s_.n_free;
    // a bubble that is no stray has moved, plus cutoff times its growth, less than
    // skin times its radius at the rebuild: it is filed near enough
    const double cutoff = law_.cutoff(), b = cutoff + st_.skin;
    for(std::uint32_t i : strays_)
    {
      const double xi = X[i], yi = Y[i], zi = Z[i], ri = R[i];
      // (the cells beyond reach skipped: a small stray in a graded region would
      // scan whole cells sized for the median radius; the others come in the same order)
      grid_.for_each_row_in_reach_packed(xi, yi, zi, cutoff * ri, b,
                                         [&](const std::uint32_t* items, const double*, std::size_t count) {
        for(std::size_t k = 0; k < count; ++k)
        {
          const std::size_t j = items[k];
          if(j == i || is_stray_[j]) continue;
          double fx = 0., fy = 0., fz = 0.;
          add_pair(xi - X[j], yi - Y[j], zi - Z[j], ri + R[j], i < j ? -1. : 1.,
                   [&] { return cached_stray_weight(i, j); }, fx, fy, fz);
          FX[i] += fx; FY[i] += fy; FZ[i] += fz;
          if(j < n) { FX[j] -= fx; FY[j] -= fy; FZ[j] -= fz; }
        }
      });
    }
    for(std::size_t a = 0; a < strays_.size(); ++a)
      for(std::size_t c = a + 1; c < strays_.size(); ++c)
      {
        const std::size_t i = strays_[a], j = strays_[c];
        double fx = 0., fy = 0., fz = 0.;
        add_pair(X[i] - X[j], Y[i] - Y[j], Z[i] - Z[j], R[i] + R[j], -1., [&] { return cached_stray_weight(i, j); },
                 fx, fy, fz);
        FX[i] += fx; FY[i] += fy; FZ[i] += fz;
        FX[j] -= fx; FY[j] -= fy; FZ[j] -= fz;
      }
  }

  // stray_weight(i, j) depends on the positions of the last rebuild only, so it is
  // kept until the next one: a stray asks for the same pairs at every force
  // evaluation (a grid query per pair otherwise).
  float cached_stray_weight(std::size_t i, std::size_t j)
  {
    std::vector<std::pair<std::uint32_t, float> >& cache = stray_weights_[i];
    for(const auto& e : cache)
      if(e.first == j) return e.second;
    const float w = stray_weight(i, j);
    cache.emplace_back(std::uint32_t(j), w);
    return w;
  }

  // the strays at positions (X, Y, Z): bubbles that moved, plus cutoff times their
  // radius growth, at least skin times their radius since the last rebuild; the
  // lists are rebuilt when they are too many
  void update_lists(const double* X, const double* Y, const double* Z)
  {
    const double cutoff = law_.cutoff();
    const std::size_t n = s_.n_free;
    for_each_block<ConcurrencyTag>(n, 4096, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        const double dx = X[i] - rx_[i], dy = Y[i] - ry_[i], dz = Z[i] - rz_[i];
        const double grow = (std::max)(0., s_.r[i] - rr_[i]);
        const double slack = std::sqrt(dx * dx + dy * dy + dz * dz) + cutoff * grow;
        is_stray_[i] = !(slack < st_.skin * rr_[i]);
      }
    });
    strays_.clear();
    for(std::size_t i = 0; i < n; ++i)
      if(is_stray_[i]) strays_.push_back(std::uint32_t(i));
    // a stray costs a grid query per force evaluation, a rebuild one per bubble; and the
    // strays' pairs among themselves cost |strays|^2 / 2, hence a fixed cap on large regions
    if(strays_.size() > (std::min)(n / 64 + 8, std::size_t(512))) rebuild_lists();
  }

  void rebuild_lists()
  {
    ++rebuilds_;
    const std::size_t n = s_.n_free;
    // (every cache: a bubble may have strayed and come back since the last rebuild)
    stray_weights_.resize(n);
    for(auto& cache : stray_weights_) cache.clear();
    strays_.clear();
    is_stray_.assign(s_.size(), 0);
    const double reach = law_.cutoff() + st_.skin;
    grid_.build(s_.x.data(), s_.y.data(), s_.z.data(), s_.r.data(), s_.size(), s_.box, reach, true);
    rx_.assign(s_.x.begin(), s_.x.begin() + n);
    ry_.assign(s_.y.begin(), s_.y.begin() + n);
    rz_.assign(s_.z.begin(), s_.z.begin() + n);
    rr_.assign(s_.r.begin(), s_.r.begin() + n);
    const std::size_t block = 1024, nb = (n + block - 1) / block;
    // per block of bubbles, reused from one rebuild to the next (no allocation once warm)
    std::vector<std::vector<std::uint32_t> >& lists = lists_;
    if(lists.size() < nb) { lists.resize(nb); weight_lists_.resize(nb); }
    std::vector<std::size_t>& counts = counts_;
    counts.assign(n, 0);
    inv_mass_.resize(n);
    damping_.resize(n);
    const double cutoff = law_.cutoff();
    list_sizes_.assign(nb, 0);
    for_each_block<ConcurrencyTag>(nb, 1, [&](std::size_t b0, std::size_t b1) {
      // the pairs within the cutoff of the bubble at hand, in list order: d2 and r_i + r_j
      std::vector<double> close_d2, close_sum;
      std::vector<double> near;
      for(std::size_t bk = b0; bk < b1; ++bk)
      {
        // `out` only grows; its first `used` entries are the block's lists
        std::vector<std::uint32_t>& out = lists[bk];
        std::vector<float>& wout = weight_lists_[bk];
        std::size_t used = 0;
        for(std::size_t i = bk * block; i < (std::min)(n, (bk + 1) * block); ++i)
        {
          const double xi = s_.x[i], yi = s_.y[i], zi = s_.z[i], ri = s_.r[i];
          const std::size_t before = used;
          std::size_t close = 0;
          // a row of cells at a time, so that a candidate is kept or dropped without a
          // branch (about half of them are, at random): room for the whole row first
          grid_.for_each_row_in_reach_packed(xi, yi, zi, reach * ri, reach,
                                             [&](const std::uint32_t* items, const double* q, std::size_t count) {
            if(out.size() < used + count) out.resize(2 * (used + count));
            if(close_d2.size() < close + count) { close_d2.resize(2 * (close + count)); close_sum.resize(2 * (close + count)); }
            std::uint32_t* o = out.data() + used;
            double* cd2 = close_d2.data() + close;
            double* cs = close_sum.data() + close;
            std::size_t u = 0, c = 0; // (locals: the stores above cannot move them to memory)
            for(std::size_t k = 0; k < count; ++k, q += 4)
            {
              const std::uint32_t j = items[k];
              const double dx = q[0] - xi, dy = q[1] - yi, dz = q[2] - zi;
              const double d2 = dx * dx + dy * dy + dz * dz, sum = ri + q[3], lim = reach * sum, cut = cutoff * sum;
              const bool in = (d2 < lim * lim) & (j != i);
              o[u] = j;
              u += in ? 1 : 0;
              cd2[c] = d2; cs[c] = sum;
              c += (in & (d2 < cut * cut)) ? 1 : 0;
            }
            used += u;
            close += c;
          });
          scale_mass(i, stiffness_sum(close_d2.data(), close_sum.data(), close));
          if(wout.size() < out.size()) wout.resize(out.size());
          used = before + attraction_weights(i, out.data() + before, wout.data() + before, used - before, near);
          counts[i] = used - before;
        }
        list_sizes_[bk] = used;
      }
    });
    offset_.assign(n + 1, 0);
    for(std::size_t i = 0; i < n; ++i) offset_[i + 1] = offset_[i] + counts[i];
    nbr_.resize(offset_[n]);
    attraction_.resize(offset_[n]);
    for_each_block<ConcurrencyTag>(nb, 1, [&](std::size_t b0, std::size_t b1) {
      for(std::size_t bk = b0; bk < b1; ++bk)
        if(list_sizes_[bk] > 0)
        {
          std::copy(lists[bk].begin(), lists[bk].begin() + list_sizes_[bk], nbr_.begin() + offset_[bk * block]);
          std::copy(weight_lists_[bk].begin(), weight_lists_[bk].begin() + list_sizes_[bk],
                    attraction_.begin() + offset_[bk * block]);
        }
    });
  }

  // the sum, in order, of pair_stiffness(sqrt(d2[t]) / sum[t]) over t < n; the square
  // roots and the divisions are taken two at a time (the same operations, see sum_list())
  double stiffness_sum(const double* d2, const double* sum, std::size_t n) const
  {
    double stiff = 0.;
    std::size_t t = 0;
#ifdef __SSE2__
    for(; t + 1 < n; t += 2)
    {
      const __m128d w = _mm_div_pd(_mm_sqrt_pd(_mm_loadu_pd(d2 + t)), _mm_loadu_pd(sum + t));
      alignas(16) double wv[2], num[2], den[2], fw[2], slope[2], ratio[2];
      _mm_store_pd(wv, w);
      for(int c = 0; c < 2; ++c) stiffness_terms(wv[c], num[c], den[c], fw[c]);
      _mm_store_pd(slope, _mm_div_pd(_mm_load_pd(num), _mm_load_pd(den)));
      _mm_store_pd(ratio, _mm_div_pd(_mm_load_pd(fw), w));
      for(int c = 0; c < 2; ++c) stiff += stiffness(wv[c], slope[c], ratio[c]);
    }
#endif
    for(; t < n; ++t) stiff += pair_stiffness(std::sqrt(d2[t]) / sum[t]);
    return stiff;
  }

  /*
  Mass scaling, as in dynamic relaxation: the explicit step is stable while
  dt * omega stays under about 1, omega^2 <= 2 S_i / m_i by Gershgorin's bound,
  S_i being the sum over the neighbours of the pair stiffness (the larger of
  |dF/dl| = |f'(w)| along the pair and F/l = f(w)/w across it). A bubble so
  crowded that dt * omega would pass `stability` gets a heavier mass, and a
  damping grown with sqrt(m_i) (same damping ratio). Rest states are the
  same; only crowded transients are slowed. In a packing at rest S_i is about
  17k, and with the default step no bubble is scaled. S_i is summed while the
  lists are built (pairs closer than the cutoff, in list order).
  */
  // the pair stiffness: the larger of |f'(w)| (central differences: any law) and f(w)/w
  double pair_stiffness(double w) const
  {
    double num, den, fw;
    stiffness_terms(w, num, den, fw);
    return stiffness(w, num / den, w > stiffness_step ? fw / w : 0.);
  }

  // pair_stiffness() in parts, for stiffness_sum() to take the divisions two at a time:
  // the slope |f(w + h) - f(w - h)| / 2h is num / den, the secant |f(w)| / w is fw / w
  static constexpr double stiffness_step = 1e-4;
  void stiffness_terms(double w, double& num, double& den, double& fw) const
  {
    const double h = stiffness_step, lo = (std::max)(0., w - h);
    num = std::abs(law_(w + h) - law_(lo));
    den = w + h - lo;
    fw = std::abs(law_(w));
  }
  // the larger of slope and secant; near 0 the secant at h
  double stiffness(double w, double slope, double secant) const
  {
    const double h = stiffness_step;
    return (std::max)(slope, w > h ? secant : std::abs(law_(h)) / h);
  }

  void scale_mass(std::size_t i, double stiffness)
  {
    const double stability = 0.8, dt2 = st_.time_step * st_.time_step;
    const double m = (std::max)(st_.mass, 2. * stiffness * dt2 / (stability * stability));
    inv_mass_[i] = 1. / m;
    damping_[i] = st_.damping * std::sqrt(m / st_.mass);
  }

  /*
  Only adjacent bubbles attract (the paper: the force "only works when two
  bubbles are within a specified distance and adjacent to each other"). Two
  bubbles are adjacent unless a third bubble's centre lies inside the ball
  whose diameter joins theirs (the Gabriel test; a pair so shadowed is no
  Gabriel edge). A shadowed pair keeps the repulsive part of the law and
  loses the attractive one. Why: with every pair in reach attracting, a dense
  clump costs less energy than the packing at rest (12 neighbours at w = 0.7
  cost nearly nothing, and the many second neighbours then within w < 1.5 all
  attract), so large regions condensed into over-full clumps beside gaps, and
  population control traded bubbles between them without end.
  The weight fades from 1 to 0 while the nearest third centre goes from the
  ball's sphere to `shadow_ramp` of its radius (squared), so that a bubble
  crossing the sphere changes the force by little: the weights are taken at
  each list rebuild, and a switch there would keep bubbles near rest moving.
  Entry e of the list gets weight[e]. Entries of weight 0 farther than
  1 + skin times the sum of radii are dropped (the new count is returned):
  before the next rebuild they cannot come close enough to repel.
  */
  std::size_t attraction_weights(std::size_t i, std::uint32_t* entries, float* weight, std::size_t count,
                                 std::vector<double>& near) const
  {
    const double xi = s_.x[i], yi = s_.y[i], zi = s_.z[i], ri = s_.r[i];
    // x, y, z and squared length of each x_k - x_i, by coordinate, padded to an even count
    // with a far point (it is in no ball)
    const std::size_t m = count + (count & 1);
    near.resize(4 * m);
    double *KX = near.data(), *KY = KX + m, *KZ = KY + m, *KD = KZ + m;
    for(std::size_t e = 0; e < count; ++e)
    {
      const std::size_t j = entries[e];
      const double ax = s_.x[j] - xi, ay = s_.y[j] - yi, az = s_.z[j] - zi;
      KX[e] = ax; KY[e] = ay; KZ[e] = az; KD[e] = ax * ax + ay * ay + az * az;
    }
    if(m > count) { KX[count] = KY[count] = KZ[count] = 0.; KD[count] = (std::numeric_limits<double>::max)(); }
    // A pair this close cannot attract before the next rebuild, one this far cannot
    // repel: until then each of i and j moves, plus its radius growth, less than
    // skin times its radius (else it is a stray, whose pairs come from the grid), so
    // the gap between the two spheres changes by less than skin times the sum of radii.
    // (A little margin against rounding.)
    const double close = (std::max)(0., 1. - 1.001 * st_.skin), far = 1. + 1.001 * st_.skin;
    for(std::size_t e = 0; e < count; ++e)
    {
      const double sum = ri + s_.r[entries[e]], ajx = KX[e], ajy = KY[e], ajz = KZ[e], aj2 = KD[e];
      if(aj2 < close * close * sum * sum) { weight[e] = 1.f; continue; }
      // the smallest (x_k - x_i).(x_k - x_j) over the list: negative inside the ball on
      // [i, j] only, where |x_k - x_i| < |x_j - x_i| (k = j gives 0)
      double inside = 0.;
      std::size_t k = 0;
#ifdef __SSE2__
      __m128d lo = _mm_setzero_pd();
      const __m128d bx = _mm_set1_pd(ajx), by = _mm_set1_pd(ajy), bz = _mm_set1_pd(ajz);
      // most pairs in reach are deeply shadowed: stop at the first eight third centres
      // that settle the weight at 0 (a margin under the ramp's foot, so that the weight
      // is the one the whole list gives, bit for bit)
      const __m128d deep = _mm_set1_pd(-0.07 * aj2);
      for(std::size_t stop = (std::min)(m, std::size_t(8)); k < m; stop = (std::min)(m, stop + 8))
      {
        for(; k < stop; k += 2)
        {
          const __m128d dot =
            _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_loadu_pd(KX + k), bx), _mm_mul_pd(_mm_loadu_pd(KY + k), by)),
                       _mm_mul_pd(_mm_loadu_pd(KZ + k), bz));
          lo = _mm_min_pd(lo, _mm_sub_pd(_mm_loadu_pd(KD + k), dot));
        }
        if(_mm_movemask_pd(_mm_cmple_pd(lo, deep)) != 0) break;
      }
      alignas(16) double two[2];
      _mm_store_pd(two, lo);
      inside = (std::min)(two[0], two[1]);
      if(k < m) { weight[e] = 0.f; continue; }
#endif
      for(; k < m; ++k) inside = (std::min)(inside, shadow_depth(KX[k], KY[k], KZ[k], KD[k], ajx, ajy, ajz));
      weight[e] = weight_of(1. + 4. * inside / aj2);
    }
    // drop what cannot act before the next rebuild: too far to repel, shadowed from attracting
    std::size_t kept = 0;
    for(std::size_t e = 0; e < count; ++e)
    {
      const double sum = far * (ri + s_.r[entries[e]]);
      if(weight[e] == 0.f && KD[e] > sum * sum) continue;
      entries[kept] = entries[e];
      weight[kept] = weight[e];
      ++kept;
    }
    return kept;
  }

  static constexpr double shadow_ramp = 0.75;
  static float weight_of(double rho2) { return float((std::max)(0., rho2 - shadow_ramp) / (1. - shadow_ramp)); }

  // (x_k - x_i).(x_k - x_j) from k = x_k - x_i, its squared length kd and a = x_j - x_i:
  // negative exactly when x_k is inside the ball on [x_i, x_j] (the SSE2 loop above
  // does the same operations in the same order)
  static double shadow_depth(double kx, double ky, double kz, double kd, double ax, double ay, double az)
  {
    return kd - ((kx * ax + ky * ay) + kz * az);
  }

  /*
  The weight of the pair of a stray i with j, as its list would have had it
  with a skin wide enough: the same test on the positions of the last list
  rebuild (the grid's), over the bubbles filed near the pair's midpoint.
  */
  float stray_weight(std::size_t i, std::size_t j) const
  {
    const std::size_t n = s_.n_free;
    const double xi = i < n ? rx_[i] : s_.x[i], yi = i < n ? ry_[i] : s_.y[i], zi = i < n ? rz_[i] : s_.z[i];
    const double ax = (j < n ? rx_[j] : s_.x[j]) - xi, ay = (j < n ? ry_[j] : s_.y[j]) - yi,
                 az = (j < n ? rz_[j] : s_.z[j]) - zi;
    const double aj2 = ax * ax + ay * ay + az * az;
    double inside = 0.;
    // (only bubbles inside the ball can lower `inside`: the cells beyond it are skipped)
    grid_.for_each_row_in_reach_packed(xi + 0.5 * ax, yi + 0.5 * ay, zi + 0.5 * az, 0.5 * std::sqrt(aj2), 0.,
                                       [&](const std::uint32_t* items, const double* q, std::size_t count) {
      for(std::size_t e = 0; e < count; ++e, q += 4)
      {
        const std::size_t k = items[e];
        if(k == i || k == j) continue;
        const double kx = q[0] - xi, ky = q[1] - yi, kz = q[2] - zi;
        inside = (std::min)(inside, shadow_depth(kx, ky, kz, kx * kx + ky * ky + kz * kz, ax, ay, az));
      }
    });
    return weight_of(1. + 4. * inside / aj2);
  }

  Bubble_system<K>& s_;
  ForceLaw law_;
  const SizingField& sizing_;
  Dynamics_settings st_;
  Bubble_grid grid_;
  std::vector<double> px_, py_, pz_, pvx_, pvy_, pvz_;   // Heun's predicted state (px_ also holds the fixed bubbles)
  std::vector<double> f0x_, f0y_, f0z_, f1x_, f1y_, f1z_;
  std::vector<double> ke_, disp_;
  std::vector<unsigned char> resting_, quiet_steps_;     // per free bubble, see set_rest_threshold()
  double rest_threshold_ = 0.;
  std::size_t steps_since_full_ = 0, moving_ = 0;
  std::vector<double> rx_, ry_, rz_, rr_;                 // positions and radii at the last list rebuild
  std::vector<double> inv_mass_, damping_;                // per bubble, after mass scaling
  std::vector<double> xyzr_;                              // forces()'s work space
  std::vector<std::size_t> offset_;
  std::vector<std::uint32_t> nbr_;
  std::vector<std::uint32_t> strays_;                    // free bubbles beyond their lists' skin, increasing
  std::vector<unsigned char> is_stray_;                  // per bubble (fixed ones never stray)
  std::vector<float> attraction_;                        // per list entry, see attraction_weights()
  std::vector<std::vector<std::pair<std::uint32_t, float> > > stray_weights_; // per bubble, see cached_stray_weight()
  std::vector<std::vector<std::uint32_t> > lists_;       // rebuild_lists()'s work space
  std::vector<std::vector<float> > weight_lists_;        // rebuild_lists()'s work space
  std::vector<std::size_t> counts_;
  std::vector<std::size_t> list_sizes_;                  // entries of lists_[b] in use
  std::size_t rebuilds_ = 0;
  bool follow_sizing_ = true;
  std::size_t steps_ = 0;  // since the last reset()
};

// serialises visitor calls coming from regions relaxing at the same time
template <class Visitor>
struct Shared_visitor
{
  Visitor& visitor;
  std::mutex mutex;
  std::atomic<bool> stop{false};
  explicit Shared_visitor(Visitor& v) : visitor(v) {}
  bool operator()(const Relaxation_progress& p)
  {
    if(stop.load()) return false;
    std::lock_guard<std::mutex> lock(mutex);
    if(!call_visitor(visitor, p)) stop.store(true);
    return !stop.load();
  }
};

template <class ConcurrencyTag, class K>
void tally_overlaps(const Bubble_system<K>& s, const Dynamics_settings& st, Region_relaxation_report& rep)
{
  rep.overlap_histogram.assign(overlap_histogram_bins, 0);
  rep.below = rep.inside = rep.above = 0;
  if(s.n_free == 0) return;
  const std::vector<double> alpha = overlap_ratios<ConcurrencyTag>(s, st.solid_angle_overlap, st.wall_overlap);
  for(double a : alpha)
  {
    if(a < st.min_overlap) ++rep.below;
    else if(a > st.max_overlap) ++rep.above;
    else ++rep.inside;
    const std::size_t bin = a <= 0. ? 0 : (std::min)(std::size_t(a), overlap_histogram_bins - 1);
    ++rep.overlap_histogram[bin];
  }
}

// relaxation and population control of one region
template <class ConcurrencyTag, class K, class ForceLaw, class SizingField, class Visitor>
Region_relaxation_report relax_region(Bubble_system<K>& s, const ForceLaw& law, const SizingField& sizing,
                                      const Dynamics_settings& st, Shared_visitor<Visitor>& visitor)
{
  CGAL::Real_timer timer;
  timer.start();
  Region_relaxation_report rep;
  rep.region = s.region;
  rep.input_population = s.input_population;
  rep.rejected = s.rejected;
  rep.surface_bubbles = s.size() - s.n_free;
  const double sort_cell = 2. * s.max_radius();
  s.sort_free_spatially(sort_cell);
  Relaxer<ConcurrencyTag, K, ForceLaw, SizingField> relaxer(s, law, sizing, st);

  auto relax = [&](std::size_t round, const Population_change& change, double tolerance) {
    relaxer.reset();
    relaxer.set_rest_threshold(st.rest_ratio * tolerance);
    Relaxation_progress p;
    p.region = s.region;
    p.round = round;
    p.added = change.added;
    p.removed = change.removed;
    p.population = s.n_free;
    rep.converged = false;
    // relaxations between population passes only spread the bubbles out
    const std::size_t budget = tolerance > st.tolerance ? st.round_step_budget : st.step_budget;
    for(std::size_t k = 1; k <= budget && s.n_free > 0; ++k)
    {
      const auto f = relaxer.step();
      ++rep.steps;
      rep.bubble_steps += double(relaxer.moving_bubbles());
      p.step = k;
      p.total_steps = rep.steps;
      p.kinetic_energy = rep.kinetic_energy = f.kinetic_energy;
      p.max_displacement = rep.max_displacement = f.max_displacement;
      p.moving = relaxer.moving_bubbles();
      if(!visitor(p)) { rep.interrupted = true; break; }
      if(f.max_displacement < tolerance) { rep.converged = true; break; }
      // In a large region a few bubbles (near a surface, under a steady force but
      // moving 0.5-2 % of their radius a step; the confinement is not what moves
      // them, their steps stay inside their free balls) do not come to rest
      // within the step budget, and they held all the others for the whole of
      // it. One in ten thousand may go on moving, by less than 20 tolerances.
      if(f.max_displacement < 20. * tolerance && relaxer.moving_more_than(tolerance) <= s.n_free / 10000)
      {
        rep.converged = true;
        break;
      }
    }
    if(s.n_free == 0) rep.converged = true;
    rep.list_rebuilds = relaxer.list_rebuilds();
    p.end_of_round = true;
    if(!rep.interrupted && !visitor(p)) rep.interrupted = true;
  };

  if(st.population_rounds == 0)
  {
    relax(0, Population_change(), st.tolerance);
    rep.population = s.n_free;
    tally_overlaps<ConcurrencyTag>(s, st, rep);
    rep.seconds = timer.time();
    return rep;
  }

  // The start is often far too crowded (a lattice of edge r): thin it before
  // moving anything. While the population still changes much the bubbles only
  // need to be spread out roughly, so those relaxations stop at a looser
  // tolerance; once it settles, relaxation goes to the full tolerance and
  // population control checks the result once more.
  double tolerance = (std::max)(st.tolerance, st.round_tolerance);
  const Population_change first = population_pass<ConcurrencyTag>(s, sizing, st);
  rep.added += first.added;
  rep.removed += first.removed;
  if(first.added + first.removed > 0) s.sort_free_spatially(sort_cell);
  relax(0, first, tolerance);
  std::vector<std::size_t> history;
  bool cycled = false;
  for(std::size_t round = 1; round <= st.population_rounds && !rep.interrupted; ++round)
  {
    const Population_change change = population_pass<ConcurrencyTag>(s, sizing, st);
    rep.rounds = round;
    rep.added += change.added;
    rep.removed += change.removed;
    const std::size_t changes = change.added + change.removed;
    // one change alone is noise, not a population still moving
    const bool settled = double(changes) <= (std::max)(1., st.population_tolerance * double(s.n_free));
    // add/delete cycles: the changes of the last two rounds are at least 90 % of
    // those of the two before (over pairs of rounds: a big region may alternate
    // between mostly insertions and mostly deletions)
    history.push_back(changes);
    const std::size_t h = history.size();
    const bool cycling = !settled && h >= 4 &&
                         double(history[h - 1] + history[h - 2]) >= 0.9 * double(history[h - 3] + history[h - 4]);
    const bool strict = tolerance <= st.tolerance;
    // A population that cycled gets one pass after a relaxation to the full
    // tolerance, not a new series: more rounds would only trade bubbles, and
    // each strict relaxation of a big region costs its whole step budget.
    if((settled || cycling || cycled) && strict)
    {
      rep.population_settled = settled;
      rep.stopped_cycling = !settled;
      if(changes > 0) relax(round, change, tolerance);
      break;
    }
    if(settled || cycling)
    {
      tolerance = st.tolerance;
      history.clear();
      cycled = cycling;
    }
    if(changes > 0) s.sort_free_spatially(sort_cell);
    if(changes > 0 || settled || cycling) relax(round, change, tolerance);
  }
  if(!rep.interrupted && tolerance > st.tolerance) relax(rep.rounds + 1, Population_change(), st.tolerance);
  rep.population = s.n_free;
  tally_overlaps<ConcurrencyTag>(s, st, rep);
  rep.seconds = timer.time();
  return rep;
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Relaxes the interior bubbles of every region (METHOD.md, stages 3 and 4):
damped bubble dynamics under a pair force law, confinement to the region, and
adaptive population control, alternated until the population and the
positions settle.

<b>Dynamics.</b> Each interior bubble obeys \f$ m\,\ddot x + c\,\dot x = F \f$,
\f$ F \f$ being the sum over its neighbours \f$ j \f$ (other interior bubbles of
its region and the surface bubbles on the region's surfaces) of
\f$ f(w_{ij})\,(r_i + r_j)\,(x_i - x_j)/l_{ij} \f$, with \f$ f \f$ the force
law (default `Cubic_bubble_force`, the paper's cubic) and
\f$ w_{ij} = l_{ij}/(r_i + r_j) \f$. The factor \f$ r_i + r_j \f$ makes a pair
at rest a spring of stiffness \f$ k = -f'(1) \f$ at any model scale, so the
motion measured in radii, and the tolerances below, do not depend on the
units of length. Surface bubbles never move.

<b>Integration.</b> By default the bubbles come to rest by FIRE, the fast
inertial relaxation engine (Bitzek et al., Phys. Rev. Lett. 97, 170201,
2006): semi-implicit Euler steps without damping, one force evaluation each,
the velocities turned a little towards the forces at every step, the step
lengthened up to twice `time_step` while the motion goes downhill (the power
\f$ \sum_i F_i \cdot v_i \f$ over the region positive) and every bubble stopped
and the step halved when it goes uphill. The rest it reaches is the same kind
of rest, the forces balanced, and `displacement_tolerance` means the same;
a step that stops the bubbles counts each as moving the step the damped
dynamics would take under its force, so that a stop is not taken for rest.
Why: a damping critical for one bubble over-damps the slow drift of a large
region, which population control's insertions start again at every round. On
modelA1 with re-meshed surfaces the relaxation took 2,989 steps instead of
7,413 and half the time; the meshes are as good or better (bench/README.md,
Session 51). With `inertial_relaxation(false)` the relaxation integrates the
dynamics above, METHOD.md's, by Heun's predictor-corrector (an explicit Euler
predictor, a trapezoidal corrector) from zero velocity, as the paper does. Radii follow the sizing field: a bubble's radius is read again each
time it has moved `radius_update_ratio` of it, during the first
`number_of_radius_update_steps` steps of a relaxation and until its motion
falls under ten times its tolerance; then radii are held, since where the
field jumps (a surface bubble entering or leaving the weight-point range) a
bubble moving across the jump would otherwise swing between two radii for
ever, and where it grows fast (a huge input triangle beside small ones)
bubbles drifting into larger sizes grow, push their neighbours on and never
come to rest (CloudSpin's relaxation took 247 s so, 53 s with the radii held
and the round budget).
Every population round reads them afresh.

<b>Only adjacent bubbles attract.</b> The paper's force "only works when two
bubbles are within a specified distance and adjacent to each other". Two
bubbles count as adjacent unless the centre of a third one (interior or
surface) lies inside the ball whose diameter joins their centres (the
Gabriel test, decided at each rebuild of the neighbour lists); a pair that
is not keeps the repulsive part of the law (\f$ w < 1 \f$) and loses the
attractive one, gradually: the attraction fades from full to none while the
third centre goes from the ball's sphere to \f$ \sqrt{0.75} \f$ of its
radius, so that bubbles crossing a sphere near rest do not jolt their
neighbours. With every pair in reach attracting, the cubic law
makes dense clumps cheaper than the packing at rest (twelve neighbours at
\f$ w = 0.7 \f$ cost nearly nothing, and the many second neighbours then
within \f$ w < 1.5 \f$ all attract): large regions condensed into over-full
clumps beside gaps, and population control traded bubbles between them
without end. On a 400 m cube with 25 m squares on its faces (test_dynamics)
the share of overlap ratios in [10, 14] went from 45 % to 99.9 %
(bench/README.md).

<b>Defaults.</b> \f$ m = k = 1 \f$ fix the units of time and force, so only
the ratios matter. The damping \f$ c = 2\sqrt{mk} \f$ is critical for one
bubble on one spring, the original bubble method's choice. In a packing a
bubble is held by about twelve neighbours, so its own rattling is damped at
about half the critical rate and dies within a few periods, while the slow
drift of whole groups, which a damping critical for the rattling would
over-damp, keeps a useful pace; on crowded test clouds \f$ c = 2 \f$ needed
fewer steps than 0.5, 1 or 4. The time step \f$ 0.2\sqrt{m/k} \f$ is a
thirtieth of the period of one spring. Explicit steps are stable only while
\f$ \Delta t\,\omega \f$ stays under about 1 for the stiffest motion of a
bubble, and crowded starts (the initial lattice of edge \f$ r \f$) are far
stiffer than a packing at rest, so a bubble whose neighbourhood would break
that bound (by Gershgorin's bound on its stiffness, the sum over its
neighbours of the larger of \f$ |f'(w)| \f$ and \f$ f(w)/w \f$) gets a heavier
mass and a damping grown with it (same damping ratio), as in dynamic
relaxation: rest states do not change, only the path to them, and the
default step stays safe for any start. A move is also capped at
`max_step_ratio` of the radius.

<b>Convergence.</b> A relaxation stops when the largest move of a bubble in
one step, over its radius, is under its tolerance, or after
`number_of_relaxation_steps` steps. While population control still changes the
population much, relaxations stop at `round_displacement_tolerance` or after
`number_of_round_relaxation_steps`: the bubbles only need to spread out before
the next pass. Once it settles (or after the last round), they go to
`displacement_tolerance` within `number_of_relaxation_steps` and the
population is checked once more.

<b>Confinement.</b> A bubble whose move crosses a surface of its region (its
boundary, or a surface inside it such as a fault that ends in the body), or
ends nearer to one than half `surface_offset_ratio` of its radius, is put
back: at the closest surface point (CGAL's AABB tree), moved inward by
`surface_offset_ratio` of its radius after a crossing, or just to that
nearest distance when it only came too close (a bubble pressed on a wall by
its neighbours then rests against it instead of bouncing off it at every
step, which would keep its relaxation from converging). Bubble centres also stay outside the
diametral balls of the surface triangles (the ball through the corners
centred in the triangle's plane) and surface edges, enlarged by
`1 + diametral_ball_margin`: then every input triangle whose own corners do
not crowd it is a Delaunay facet and the tetrahedralization keeps it whole. A
bubble that enters one such ball goes to the closest point outside it; where
balls overlap it stops where its path meets the first one and slides along
it (pushing out of one ball into the next can go on for ever). It keeps its
velocity along the wall, loses the part into it, and keeps only the share of
its speed that it could use. Balls wider than `max_protected_ball_ratio`
times the local surface-bubble radius (needle and cap triangles) are not
protected, since emptying them would leave holes larger than the mesh size.
A start position that cannot be made valid drops the bubble; a move that
cannot is undone. Each bubble carries a clearance (a ball free of surfaces
and protected balls around its last checked position) and moves inside it
skip the checks; the others read the few triangles and balls a sparse grid
lists near the bubble, and only bubbles far from every surface query CGAL's
AABB tree.

<b>Population control.</b> Before the first relaxation, and after each one,
a pass of `control_bubble_population()` deletes interior bubbles with an
overlap ratio above `max_overlap_ratio` and inserts new ones in the largest
gap next to those below `min_overlap_ratio`. Rounds go on until a pass
changes at most `population_tolerance` of the population (or one bubble),
`number_of_population_rounds` have run, or the changes of two rounds are at
least 90 % of those of the two rounds before (the guard against endless
add/delete cycles); in that last case a relaxation to
`displacement_tolerance`, one more pass and, if the pass changed anything, a
last relaxation end the region's run. A new bubble that has less than half
the lower bound (the edge of an empty part of the region) is itself a parent
later in the same pass, so that empty parts fill in one pass. A relaxation
stops when the largest displacement of a step is under its tolerance, or
when at most one bubble in ten thousand moves more than the tolerance and
none more than 20 times it (a few bubbles of a large region do not come to
rest within the step budget). A bubble whose steps stay under
`resting_displacement_ratio` of the tolerance for 5 steps rests (is neither
moved nor given forces) until a bubble of its neighbour list moves more than
that, or the next full step (every 50th); after a population pass most of a
large region is at rest within tens of steps while the parts next to the
changes still move, and those are all that the following steps pay for.

<b>Parallelism and determinism.</b> Regions relax independently (their
surface bubbles are fixed) and, with `CGAL::Parallel_tag` and TBB, at the
same time; inside a region the force evaluation, the integration and the
confinement run in parallel. Every bubble sums its forces over its own
neighbour list in a fixed order, and sums and maxima over bubbles are taken
over fixed blocks combined in order, so the result is bit-identical whatever
the number of threads. Neighbours are found with Verlet lists (pairs within
`(cutoff + neighbor_skin)(r_i + r_j)`) filled from uniform grids. A bubble
that has moved, or grown, more than the skin allows finds its pairs in the
grid instead, after the lists' sums and in index order, until such bubbles
are more than 1/64 of the region's (or 512); then the lists are rebuilt. A few
bubbles pressed on a wall keep moving after the rest has settled, and would
otherwise force a rebuild at almost every step.

The output is grouped by region (increasing index); in a region, the
surviving input bubbles keep their order and new bubbles follow. Interior
bubbles whose region is not a region of the model are returned unchanged at
the end.

\tparam ConcurrencyTag `CGAL::Parallel_tag` (default when TBB is linked) or `CGAL::Sequential_tag`.
\tparam K the kernel of the model.
\tparam SizingField a model of `BubbleSizingField`: `double operator()(const Point_3& p, std::size_t region) const`,
        callable from several threads at once.

\param model the geological model.
\param surface_bubbles the fixed bubbles, one per model point (`surface_point` set).
\param interior_bubbles the bubbles to relax, each with its `region`; replaced by the result.
\param sizing the radius wanted at a point of a region.
\param np an optional sequence of named parameters among the ones listed below.

\cgalNamedParamsBegin
  \cgalParamNBegin{force_law}
    \cgalParamDescription{the pair force}
    \cgalParamType{a model of `BubbleForceLaw`}
    \cgalParamDefault{`Cubic_bubble_force(stiffness)`}
  \cgalParamNEnd
  \cgalParamNBegin{stiffness}
    \cgalParamDescription{k of the default force law}
    \cgalParamType{`double`} \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{mass}
    \cgalParamDescription{m, the mass of an interior bubble (before mass scaling of crowded bubbles)}
    \cgalParamType{`double`} \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{damping}
    \cgalParamDescription{c, the viscous damping}
    \cgalParamType{`double`} \cgalParamDefault{\f$ 2\sqrt{mk} \f$, k being the force law's `stiffness()`}
  \cgalParamNEnd
  \cgalParamNBegin{inertial_relaxation}
    \cgalParamDescription{`true`: relax by FIRE (see Integration above); `false`: by METHOD.md's damped
      dynamics, integrated by Heun's scheme, which `damping` sets; `mass` and `time_step` serve both}
    \cgalParamType{`bool`} \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{time_step}
    \cgalParamDescription{the integration step (FIRE's first step, and half its longest)}
    \cgalParamType{`double`} \cgalParamDefault{\f$ 0.2\sqrt{m/k} \f$}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_relaxation_steps}
    \cgalParamDescription{step budget of a relaxation to `displacement_tolerance`; a region that has not
      settled in 500 steps (bubbles against needle triangles) did not settle in 2000 either, and its
      overlap ratios were the same}
    \cgalParamType{`std::size_t`} \cgalParamDefault{500}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_round_relaxation_steps}
    \cgalParamDescription{step budget of a relaxation to `round_displacement_tolerance` (between population
      passes while the population still changes); more did not change the mesh quality of the models tried}
    \cgalParamType{`std::size_t`} \cgalParamDefault{300}
  \cgalParamNEnd
  \cgalParamNBegin{displacement_tolerance}
    \cgalParamDescription{the last relaxation has converged when no bubble moves more than this share of its radius in a step}
    \cgalParamType{`double`} \cgalParamDefault{0.001}
  \cgalParamNEnd
  \cgalParamNBegin{round_displacement_tolerance}
    \cgalParamDescription{the same for the relaxations while the population still changes}
    \cgalParamType{`double`} \cgalParamDefault{0.01}
  \cgalParamNEnd
  \cgalParamNBegin{min_overlap_ratio, max_overlap_ratio}
    \cgalParamDescription{bounds of the overlap ratio of interior bubbles (see `overlap_ratios()`)}
    \cgalParamType{`double`} \cgalParamDefault{10 and 14 (the paper's)}
  \cgalParamNEnd
  \cgalParamNBegin{solid_angle_overlap_ratio}
    \cgalParamDescription{weight each interior neighbour's term of the overlap ratio by the solid angle it takes,
      against an equal neighbour's, so that the bounds mean the same in a graded field (surface bubbles count
      unweighted); `false` gives METHOD.md's formula, which counts neighbours whatever their size (see
      `overlap_ratios()`)}
    \cgalParamType{`bool`} \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{wall_overlap_ratio}
    \cgalParamDescription{a bubble within 3 radii of a surface triangle at least 6 radii long (a bare wall)
      counts that surface as the plane of bubbles of its own radius it could hold, less what the surface
      bubbles near it add; `false` counts the surface bubbles alone, as METHOD.md's formula does (see
      `overlap_ratios()`)}
    \cgalParamType{`bool`} \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_population_rounds}
    \cgalParamDescription{most rounds of population control; 0 relaxes only}
    \cgalParamType{`std::size_t`} \cgalParamDefault{12}
  \cgalParamNEnd
  \cgalParamNBegin{population_tolerance}
    \cgalParamDescription{the population has settled when a round adds and removes at most this share of it (or one bubble)}
    \cgalParamType{`double`} \cgalParamDefault{`default_population_tolerance` (0.005)}
  \cgalParamNEnd
  \cgalParamNBegin{insertion_clearance}
    \cgalParamDescription{least distance, over the sum of radii, from an inserted bubble to all others; the cubic
      law costs almost nothing down to 0.7 (its energy at w = 0.7 is that of two bubbles out of reach)}
    \cgalParamType{`double`} \cgalParamDefault{0.7}
  \cgalParamNEnd
  \cgalParamNBegin{diametral_ball_margin}
    \cgalParamDescription{relative enlargement of the protected diametral balls}
    \cgalParamType{`double`} \cgalParamDefault{0.02}
  \cgalParamNEnd
  \cgalParamNBegin{max_protected_ball_ratio}
    \cgalParamDescription{diametral balls wider than this times the local surface-bubble radius are not protected}
    \cgalParamType{`double`} \cgalParamDefault{3}
  \cgalParamNEnd
  \cgalParamNBegin{surface_offset_ratio}
    \cgalParamDescription{how far off the surface, over its radius, a bubble put back after crossing a surface
      lands; half of it is the nearest a bubble may come to a surface}
    \cgalParamType{`double`} \cgalParamDefault{0.5}
  \cgalParamNEnd
  \cgalParamNBegin{neighbor_skin}
    \cgalParamDescription{reach of the neighbour lists beyond the force's, over the sum of radii:
      larger rebuilds them less often but makes them longer (from a crowded start, 0.35 rebuilds
      about every 7 steps and 0.25 every 4.6; 0.35 was the fastest of 0.25-0.4, see bench/README.md)}
    \cgalParamType{`double`} \cgalParamDefault{0.35}
  \cgalParamNEnd
  \cgalParamNBegin{max_step_ratio}
    \cgalParamDescription{longest move in one step over the radius (capped at 0.9 `neighbor_skin`)}
    \cgalParamType{`double`} \cgalParamDefault{0.125}
  \cgalParamNEnd
  \cgalParamNBegin{radius_update_ratio}
    \cgalParamDescription{a radius is read again from the sizing field after its bubble moved this share of it}
    \cgalParamType{`double`} \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{resting_displacement_ratio}
    \cgalParamDescription{a free bubble whose steps stay under this share of the relaxation's tolerance
      (times its radius) for 5 steps in a row rests: it is not moved and its forces are not summed until
      a bubble of its neighbour list moves more than that in one step, or the next full step (every 50th
      step moves all bubbles); 0 moves every bubble at every step. Must be under 1, so that a resting
      bubble never holds up convergence.}
    \cgalParamType{`double`} \cgalParamDefault{0.25}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_radius_update_steps}
    \cgalParamDescription{radii follow the sizing field during this many steps of each relaxation, then are held}
    \cgalParamType{`std::size_t`} \cgalParamDefault{300}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{threads used (a TBB task arena); 0 uses all cores. The result does not depend on it.}
    \cgalParamType{`std::size_t`} \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{visitor}
    \cgalParamDescription{called with a `Relaxation_progress` after every step and at the end of every
      relaxation of every region; calls are serialised (never two at once) but come from the
      threads of the regions; returning `false` stops the relaxation (it may also return `void`)}
    \cgalParamType{a callable}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Relaxation_report`: per region, steps, population changes,
convergence, and the final distribution of the overlap ratios.
*/
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class K, class SizingField,
          class NP = CGAL::parameters::Default_named_parameters>
Relaxation_report relax_bubbles(const Geological_model_3<K>& model, const std::vector<Bubble<K> >& surface_bubbles,
                                std::vector<Bubble<K> >& interior_bubbles, const SizingField& sizing,
                                const NP& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::force_law_t, NP, Cubic_bubble_force>::type
    Force_law;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::visitor_t, NP,
                                                             internal::Default_relaxation_visitor>::type Visitor;

  CGAL::Real_timer timer;
  timer.start();
  const double k = choose_parameter(get_parameter(np, internal_np::stiffness), 1.);
  const Force_law law = choose_parameter(get_parameter(np, internal_np::force_law), Cubic_bubble_force(k));
  const internal::Dynamics_settings st = internal::dynamics_settings(np, law.stiffness());
  Visitor visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), internal::Default_relaxation_visitor());
  internal::Shared_visitor<Visitor> shared(visitor);

  Relaxation_report report;
  internal::run_with_threads<ConcurrencyTag>(st.threads, [&] {
    std::vector<std::size_t> skipped;
    std::vector<internal::Bubble_system<K> > systems =
      internal::make_bubble_systems<ConcurrencyTag>(model, surface_bubbles, interior_bubbles, sizing, st, skipped);
    report.regions.resize(systems.size());
    internal::for_each_block<ConcurrencyTag>(systems.size(), 1, [&](std::size_t a, std::size_t b) {
      for(std::size_t i = a; i < b; ++i)
        report.regions[i] = internal::relax_region<ConcurrencyTag>(systems[i], law, sizing, st, shared);
    });
    internal::write_back(systems, interior_bubbles, skipped, interior_bubbles);
  });

  report.overlap_histogram.assign(internal::overlap_histogram_bins, 0);
  for(const Region_relaxation_report& r : report.regions)
  {
    report.steps += r.steps;
    report.bubble_steps += r.bubble_steps;
    report.list_rebuilds += r.list_rebuilds;
    report.population += r.population;
    report.added += r.added;
    report.removed += r.removed;
    report.rejected += r.rejected;
    report.below += r.below;
    report.inside += r.inside;
    report.above += r.above;
    for(std::size_t b = 0; b < r.overlap_histogram.size(); ++b) report.overlap_histogram[b] += r.overlap_histogram[b];
  }
  report.seconds = timer.time();
  return report;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_RELAX_BUBBLES_H
