// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_SURFACE_BUBBLE_SIZING_FIELD_H
#define CGAL_BUBBLE_MESH_3_SURFACE_BUBBLE_SIZING_FIELD_H

#include <CGAL/Bubble_mesh_3/Bubble.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/Neighbor_grid.h>
#include <CGAL/Bubble_mesh_3/internal/placement_parameters.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Orthogonal_incremental_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The default model of `BubbleSizingField`: the radius wanted at a point of a
region, interpolated from the surface bubbles of that region by the
weight-point rule of METHOD.md (stage 2), times a per-region scale factor.

For region `r`, let `q_5`, `q_95` be the 5 % and 95 % quantiles of the
radii of the surface bubbles on `r`'s boundary or on surfaces inside `r`,
and `R0 = (q_95 + q_5) / 2` (the paper takes the smallest and largest
radius; a box face given as two triangles would make them meaningless).
With `area_weighted_radius_floor`, R0 is at least half of what the same
quantiles give when each bubble is weighted by the area it covers (`r^2`):
counted, the faces of a thin layer re-meshed at a tenth of the size hold over
95 % of a neighbouring body's bubbles on a third of its surface, and R0, the size far from every
surface, was that fine throughout a body hundreds of times thicker (a 2 m
layer in a 1 km box: 9.6 M tetrahedra instead of 1.7 M). By area alone R0
would also grow where the count is right (modelA1 re-meshed: 1.84 instead of
1.80 for the aspect-ratio median), hence the floor at half; it is off by
default because a few huge input triangles would weigh in. A
surface bubble `j` of `r` is a weight point of `p` when
`l_j = |p - c_j| < f (R0 + r_j)` (`f` = `interaction_range_factor`, 1.5).
With weight points `j = 1..n`:

    R(p) = s_r * min( (sum_j w_j r_j + w_0 R0) / (sum_j w_j + w_0),  min_i (r_i + g l_i) ),
    w_j = v_j (1 - (l_j / L_j)^2)^2,   L_j = f (R0 + r_j),

with `v_j = 1 / l_j` (`Radius_weighting::INVERSE_DISTANCE`, default: the
closer, the heavier) or `v_j = 1 / r_j` (`Radius_weighting::INVERSE_RADIUS`,
the paper's printed formula), and `w_0` the weight of a bubble of radius R0
at the edge of its untapered range: `1 / (2 f R0)`, or `1 / R0`. At a
surface bubble's centre (`l_j = 0`) the inverse-distance rule gives that
bubble's radius. Without weight point, `R(p) = s_r * R0`. The taper and the
weight point R0 are deviations from the paper's plain
`lambda_j = v_j / sum_k v_k`: they make the field continuous (see `taper()`
below). `s_r` is entry `r` of `region_scale_factors` (1 when absent): below
1 asks for a denser mesh in region `r`, above 1 a coarser one, without
touching its surface. The second term, over all surface bubbles `i` of `r`,
bounds the growth of the radius away from the surface by `g` per unit of
distance (`g` = `size_gradation`, 0.5; 0 drops it, as in the paper): the few
huge bubbles at the corners of coarse triangles (a box's faces) would
otherwise be interpolated over the whole fine mesh beside them. Two touching
bubbles the bound holds have radii within a ratio `(1 + g) / (1 - g)`: 3 at
0.5. A gentler bound grades a body beside a finer one more slowly, with more
bubbles: `make_bubble_mesh_3()` passes `g = 1/9` (a ratio of 1.25) on re-meshed
surfaces, which with 1.63 edges across thin layers takes the bundled model's
aspect-ratio median from 1.85 to 1.78 with 22 % fewer tetrahedra, but
CloudSpin's from 1.64 to 1.66 with 21 % more: where the inside cannot grow as
fast as the surfaces do, the jump moves to the coarse surfaces (bench/README.md,
sessions 52 and 56). It and the quantiles are deviations from the paper, measured on
modelA1 (bench/README.md).

Only surface bubbles whose `surface_point` is a model point are used. Weight
points are found in a uniform grid per region (cells of half the search
radius); the graded bound's farther bubbles, when needed, in the same grid,
cells nearest first, each skipped when its smallest bubble could not lower
the bound (a `CGAL::Kd_tree` per region serves the regions too large for a
grid; both are built in the constructor). Concurrent queries are safe.
Copies share the grids and trees.

\cgalModels `BubbleSizingField`
*/
template <class GeomTraits>
class Surface_bubble_sizing_field
{
public:
  /// the traits class
  typedef GeomTraits Geom_traits;
  /// point type
  typedef typename GeomTraits::Point_3 Point_3;

  /// `size_gradation` unless given: touching bubbles' radii within a ratio of 3
  static constexpr double default_size_gradation = 0.5;
  /// `size_gradation` that `make_bubble_mesh_3()` gives re-meshed surfaces unless
  /// told otherwise: a ratio of 1.25 (bench/README.md, session 56)
  static constexpr double default_remeshed_size_gradation = 1. / 9.;
  /// the `size_gradation` a run takes unless given: the one for surfaces
  /// `remesh_surfaces()` made, or the one for the input's own
  static constexpr double default_size_gradation_for(bool surfaces_remeshed)
  {
    return surfaces_remeshed ? default_remeshed_size_gradation : default_size_gradation;
  }

private:
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<GeomTraits> > Traits;
  typedef CGAL::Distance_adapter<std::size_t, Point_map, CGAL::Euclidean_distance<CGAL::Search_traits_3<GeomTraits> > >
    Distance;
  typedef CGAL::Orthogonal_incremental_neighbor_search<Traits, Distance> Incremental_search;
  typedef typename Incremental_search::Tree Tree;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

  struct Region_data
  {
    std::vector<Point_3> centres;
    std::vector<double> radii;
    double r_min = 0., r_max = 0., r0 = 0.;
    std::unique_ptr<Tree> tree;
    // the centres in a grid of cells of half the search radius: the weight-point
    // candidates of a query are a few rows of cells (the tree's walk cost more)
    internal::Neighbor_grid grid;
    bool has_grid = false;
    // the smallest radius in each cell of the grid: the graded bound skips the
    // cells whose bubbles are all too far for their size to lower it
    internal::Cell_minima cell_min_radius;
  };

public:
  /*!
  \cgalNamedParamsBegin
    \cgalParamNBegin{radius_weighting}
      \cgalParamDescription{weights of the weight points}
      \cgalParamType{`Radius_weighting`}
      \cgalParamDefault{`Radius_weighting::INVERSE_DISTANCE`}
    \cgalParamNEnd
    \cgalParamNBegin{interaction_range_factor}
      \cgalParamDescription{`f` in the weight-point test `l_j < f (R0 + r_j)`}
      \cgalParamType{double}
      \cgalParamDefault{1.5 (the force law's range)}
    \cgalParamNEnd
    \cgalParamNBegin{size_gradation}
      \cgalParamDescription{`g`: the radius grows at most `g` per unit of distance from a surface bubble; 0: no bound}
      \cgalParamType{double}
      \cgalParamDefault{`default_size_gradation` (0.5); `make_bubble_mesh_3()` passes
        `default_remeshed_size_gradation` (1/9) when it re-meshed the surfaces}
    \cgalParamNEnd
    \cgalParamNBegin{area_weighted_radius_floor}
      \cgalParamDescription{R0 at least half of the quantiles' value weighted by area (see above); for surfaces
        whose triangles all have about the size wanted, as `remesh_surfaces()` makes them}
      \cgalParamType{bool}
      \cgalParamDefault{false (`make_bubble_mesh_3()` sets it when it re-meshed the surfaces)}
    \cgalParamNEnd
    \cgalParamNBegin{region_scale_factors}
      \cgalParamDescription{entry `r` multiplies the radius wanted in region `r`}
      \cgalParamType{std::vector<double>}
      \cgalParamDefault{empty: 1 everywhere}
    \cgalParamNEnd
  \cgalNamedParamsEnd
  */
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  Surface_bubble_sizing_field(const Geological_model_3<GeomTraits>& model,
                              const std::vector<Bubble<GeomTraits> >& surface_bubbles,
                              const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    weighting_ = choose_parameter(get_parameter(np, internal_np::radius_weighting),
                                  Radius_weighting::INVERSE_DISTANCE);
    range_factor_ = choose_parameter(get_parameter(np, internal_np::interaction_range_factor), 1.5);
    gradation_ = choose_parameter(get_parameter(np, internal_np::size_gradation), default_size_gradation);
    scale_ = choose_parameter(get_parameter(np, internal_np::region_scale_factors), std::vector<double>());
    const bool area_floor = choose_parameter(get_parameter(np, internal_np::area_weighted_radius_floor), false);

    // (region, point) incidences, so that each region gets its own bubbles
    std::vector<std::pair<std::size_t, std::size_t> > incidences;
    for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    {
      const auto& patch = model.patch(model.patch_of_triangle(t));
      for(std::size_t v : model.triangle(t))
      {
        incidences.emplace_back(patch.positive_region, v);
        if(patch.negative_region != patch.positive_region) incidences.emplace_back(patch.negative_region, v);
      }
    }
    std::sort(incidences.begin(), incidences.end());
    incidences.erase(std::unique(incidences.begin(), incidences.end()), incidences.end());

    std::vector<std::size_t> bubble_of_point(model.number_of_points(), no_index);
    for(std::size_t b = 0; b < surface_bubbles.size(); ++b)
      if(surface_bubbles[b].surface_point < model.number_of_points())
        bubble_of_point[surface_bubbles[b].surface_point] = b;

    auto regions = std::make_shared<std::vector<Region_data> >(model.number_of_regions() + 1);
    for(const auto& rp : incidences)
    {
      const std::size_t b = bubble_of_point[rp.second];
      if(b == no_index) continue;
      (*regions)[rp.first].centres.push_back(surface_bubbles[b].center);
      (*regions)[rp.first].radii.push_back(surface_bubbles[b].radius);
    }
    (*regions)[0] = Region_data(); // the outside wants no bubble
    for(Region_data& rd : *regions)
    {
      if(rd.radii.empty()) continue;
      rd.r_min = *std::min_element(rd.radii.begin(), rd.radii.end());
      rd.r_max = *std::max_element(rd.radii.begin(), rd.radii.end());
      // R0 from the 5 % and 95 % quantiles
      std::vector<double> sorted = rd.radii;
      const std::pair<double, double> q = internal::quantiles_5_95(sorted);
      rd.r0 = 0.5 * (q.first + q.second);
      if(area_floor)
      {
        const std::pair<double, double> a = internal::area_weighted_quantiles_5_95(sorted);
        rd.r0 = (std::max)(rd.r0, 0.25 * (a.first + a.second));
      }
      std::vector<std::size_t> keys(rd.centres.size());
      for(std::size_t i = 0; i < keys.size(); ++i) keys[i] = i;
      rd.tree.reset(new Tree(keys.begin(), keys.end(), typename Tree::Splitter(),
                             Traits(Point_map(rd.centres.data()))));
      rd.tree->build(); // built now: later const queries may run concurrently
      const double range = range_factor_ * (rd.r0 + rd.r_max);
      if(range > 0. && rd.centres.size() < std::size_t(internal::Neighbor_grid::none))
      {
        const std::size_t n = rd.centres.size();
        std::vector<double> x(n), y(n), z(n);
        for(std::size_t i = 0; i < n; ++i)
        {
          x[i] = CGAL::to_double(rd.centres[i].x());
          y[i] = CGAL::to_double(rd.centres[i].y());
          z[i] = CGAL::to_double(rd.centres[i].z());
        }
        rd.grid.set_domain(*std::min_element(x.begin(), x.end()), *std::min_element(y.begin(), y.end()),
                           *std::min_element(z.begin(), z.end()), *std::max_element(x.begin(), x.end()),
                           *std::max_element(y.begin(), y.end()), *std::max_element(z.begin(), z.end()),
                           0.5 * range, 4 * n + 64);
        rd.grid.build(x.data(), y.data(), z.data(), n, nullptr, rd.radii.data());
        rd.cell_min_radius.build(rd.grid, x.data(), y.data(), z.data(), rd.radii.data(), n);
        rd.has_grid = true;
      }
    }
    regions_ = regions;
  }

  /// the radius wanted at `p` in region `region`; 0 for the outside (region 0), an unknown region or a region without surface bubbles
  double operator()(const Point_3& p, std::size_t region) const
  {
    if(region >= regions_->size()) return 0.;
    const Region_data& rd = (*regions_)[region];
    if(!rd.tree) return 0.;
    return scale_factor(region) * unscaled_radius(rd, p);
  }

  /// `R0 = (q_95 + q_5) / 2` of the surface-bubble radii of `region` (5 % and 95 % quantiles, see
  /// `area_weighted_radius_floor`), unscaled
  double default_radius(std::size_t region) const
  {
    return region < regions_->size() ? (*regions_)[region].r0 : 0.;
  }
  /// smallest radius of the surface bubbles of `region`
  double smallest_surface_radius(std::size_t region) const
  {
    return region < regions_->size() ? (*regions_)[region].r_min : 0.;
  }
  /// largest radius of the surface bubbles of `region`
  double largest_surface_radius(std::size_t region) const
  {
    return region < regions_->size() ? (*regions_)[region].r_max : 0.;
  }
  /// the scale factor of `region` (1 unless `region_scale_factors` says otherwise)
  double scale_factor(std::size_t region) const
  {
    return region < scale_.size() ? scale_[region] : 1.;
  }

private:
  double unscaled_radius(const Region_data& rd, const Point_3& p) const
  {
    const double range = range_factor_ * (rd.r0 + rd.r_max);
    double weight_sum = 0., weighted = 0.;
    double coincident_sum = 0.;
    std::size_t coincident = 0;
    // min_j (r_j + g l_j) over the bubbles visited, the candidates of the graded bound
    double graded = std::numeric_limits<double>::infinity();
    // one weight point j of radius `radius` at distance `l`
    auto visit = [&](double l, double radius) {
      graded = (std::min)(graded, radius + gradation_ * l);
      const double reach = range_factor_ * (rd.r0 + radius);
      if(!(l < reach)) return;
      double w = 1. / radius;
      if(weighting_ == Radius_weighting::INVERSE_DISTANCE)
      {
        // a bubble at p has an infinite weight: its radius wins
        if(l == 0.) { coincident_sum += radius; ++coincident; return; }
        w = 1. / l;
      }
      w *= taper(l / reach);
      weight_sum += w;
      weighted += w * radius;
    };
    if(rd.has_grid)
    {
      // The bubbles within `range`, and maybe a few just beyond it (the margin covers
      // rounding): those add no weight (they are farther than f (R0 + r_j)) and cannot
      // lower the graded bound below the interpolated radius where it is read from
      // the visited ones (see below). The grid's cells and their items come in a fixed
      // order, so the sums do too (same input, same bits), with no list to gather and
      // sort: this query runs for every bubble at every step, and sorting its list was
      // 13 % of the CPU samples of a whole modelA5 run.
      const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
      const double r2 = range * range * (1. + 1e-9);
      rd.grid.for_each_row_in_ball_packed(x, y, z, range, [&](const std::uint32_t*, const double* q,
                                                               std::size_t count) {
        for(std::size_t k = 0; k < count; ++k, q += 4)
        {
          const double dx = q[0] - x, dy = q[1] - y, dz = q[2] - z, d2 = dx * dx + dy * dy + dz * dz;
          if(d2 <= r2) visit(std::sqrt(d2), q[3]);
        }
      });
    }
    else
    {
      std::vector<std::size_t> near;
      rd.tree->search(std::back_inserter(near), Sphere(p, range, 0., rd.tree->traits()));
      std::sort(near.begin(), near.end()); // sums in a fixed order: same input, same bits
      for(std::size_t j : near)
        visit(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, rd.centres[j]))), rd.radii[j]);
    }
    if(coincident > 0) return coincident_sum / double(coincident);
    const double w0 = background_weight(rd);
    const double interpolated = weight_sum + w0 > 0. ? (weighted + w0 * rd.r0) / (weight_sum + w0) : rd.r0;
    if(!(gradation_ > 0.)) return interpolated;
    // Only bubbles closer than (interpolated - r_min) / g can lower the bound. When
    // that distance is well inside the search radius, they were all visited, and a
    // minimum does not depend on the order: the same bits as the nearest-first walk
    // of graded_bound(), without its allocations. (Margins cover rounding.)
    const double needed = (interpolated - rd.r_min + 1e-9 * interpolated) / gradation_;
    if(needed < 0.999 * range) return (std::min)(interpolated, graded);
    // (the walk starts from what the bubbles visited above already give)
    return (std::min)(interpolated, graded_bound(rd, p, (std::min)(interpolated, graded)));
  }

  // A weight point's weight fades to 0 at the edge of its range, and R0 is one
  // more weight point everywhere, with the weight of a bubble of radius R0 at
  // the edge of its untapered range: the field is then continuous. With cut-off
  // weights and R0 only where no weight point is left, it jumped where the last
  // one left the range, from the surface radius to R0 (twice it on modelA1
  // re-meshed), and the bubbles either side of the jump could not pack: a
  // small one among big ones has too few neighbours, a big one too many.
  static double taper(double t)
  {
    const double u = 1. - t * t;
    return u * u;
  }
  double background_weight(const Region_data& rd) const
  {
    const double edge = weighting_ == Radius_weighting::INVERSE_DISTANCE ? 2. * range_factor_ * rd.r0 : rd.r0;
    return edge > 0. ? 1. / edge : 0.;
  }

  // min_j (r_j + g l_j) over the region's surface bubbles, or `bound` if that
  // is smaller: the radius grows at most g per unit of distance from a surface
  // bubble, so that the coarse triangles of a box's faces do not ask for huge
  // bubbles a few fine-mesh sizes away from a fine surface
  double graded_bound(const Region_data& rd, const Point_3& p, double bound) const
  {
    if(!(gradation_ > 0.)) return bound;
    if(rd.has_grid)
    {
      // Nearest cells first, each skipped when its smallest bubble at its nearest
      // point could not lower the bound; the walk ends where the smallest bubble
      // of the region could not. A gentle gradation reaches far (the bound is
      // sought up to (bound - r_min) / g away), and where the bubbles near p are
      // large the region's r_min says little: the tree's walk, bounded by r_min
      // alone, visited thousands of bubbles a query (a third of modelA1's run
      // at g = 0.12).
      return rd.cell_min_radius.cone_minimum(rd.grid, CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                             CGAL::to_double(p.z()), gradation_, bound);
    }
    Incremental_search search(*rd.tree, p, 0., true, Distance(Point_map(rd.centres.data())));
    for(auto it = search.begin(); it != search.end(); ++it)
    {
      const double l = std::sqrt(CGAL::to_double(it->second));
      if(!(rd.r_min + gradation_ * l < bound)) break; // no farther bubble can lower it
      bound = (std::min)(bound, rd.radii[it->first] + gradation_ * l);
    }
    return bound;
  }

  std::shared_ptr<const std::vector<Region_data> > regions_;
  std::vector<double> scale_;
  double gradation_ = 0.5;
  double range_factor_ = 1.5;
  Radius_weighting weighting_ = Radius_weighting::INVERSE_DISTANCE;
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_SURFACE_BUBBLE_SIZING_FIELD_H
