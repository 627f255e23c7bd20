// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_REMESHING_SIZING_FIELD_H
#define CGAL_BUBBLE_MESH_3_REMESHING_SIZING_FIELD_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/model_features.h>
#include <CGAL/Bubble_mesh_3/internal/Neighbor_grid.h>
#include <CGAL/Bubble_mesh_3/internal/asked_edge_length.h>
#include <CGAL/Bubble_mesh_3/internal/remeshing_parameters.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

The target edge length of the surface re-meshing (`remesh_surfaces()`) at a
point of a patch. It is the smallest of

- the patch size \f$ b_p = s \cdot f_p \cdot \min(g_{r^+}, g_{r^-}) \f$: the
  user size \f$ s \f$ (absolute `edge_length`, or `relative_edge_length`
  times the bounding-box diagonal, or by default the median input edge
  length) times the patch factor \f$ f_p \f$ (`patch_size_factors`) and the
  smaller factor of the patch's two regions (`region_size_factors`; region 0,
  the outside, has none);
- the local feature size rule \f$ \max(h_{min}, d / N) \f$, with \f$ d \f$ the
  thickness at the point - the distance, along the surface normal, to the
  nearest surface that is not adjacent (sharing no point with the patch), or
  that is adjacent but nearly parallel (within 30 degrees: a pinch-out) - so
  that a thin layer gets at least \f$ N \f$ = `elements_across_thickness`
  edges across; on curves, \f$ d \f$ is the distance to the nearest patch or
  curve that does not touch the curve (a fault tip near a horizon);
  \f$ h_{min} \f$ = `minimum_edge_length` keeps pinch-outs from demanding an
  endless refinement;
- the curvature rule \f$ \max(h_{min}, \theta\, l / \varphi) \f$ at every
  input edge inside a patch whose two triangles turn by an angle
  \f$ \varphi \f$ under the feature angle (a larger turn is a curve): an
  edge of length \f$ l \f$ turning by \f$ \varphi \f$ lies on a radius of
  curvature of about \f$ l / \varphi \f$, and a new edge there turns by at
  most \f$ \theta \f$ = `curvature_angle` (22.5 degrees: 16 edges around a
  circle); without it a tunnel of radius 25 re-meshed at size 30 is a
  hexagonal tube and loses several percent of its volume;
- the strip rule: on a curve, where another curve of one of its patches
  runs parallel to it (within 10 degrees) without touching it, at a distance
  \f$ w \f$ under \f$ h_{min} / 3.5 \f$ (a thin layer's side on the model's
  walls), \f$ \max(h_{min} / 4, 3.5\, w) \f$: the re-meshing puts one side's
  points half-way between the other's, and at that spacing the triangles
  across reach 25 degrees;
- with `refine_ribbons`, the ribbon rule: on the two curves of a patch that
  meet at a corner under 10 degrees, the distance across to the other one
  where it is at least a twentieth of \f$ h_{min} \f$ (one edge across a
  strip makes good triangles; narrower, the tip is left as it is);
- constraints added with `add_size_constraint()` (the re-meshing adds the
  spacing of the curve points it must keep);

graded: every value \f$ h_i \f$ given at a point \f$ x_i \f$ (all the rules
above are sampled at points) bounds the field by
\f$ h_i + (g - 1)\,|x - x_i| \f$, with \f$ g \f$ = `size_grading`, so that
neighbouring edges differ by a ratio of at most about \f$ g \f$. Patch sizes
are graded across the curves between patches the same way.

Queries may run concurrently (the point search is built on the first one,
under a lock); adding a constraint may not run concurrently with anything.

\tparam GeomTraits a model of `Kernel`
*/
template <class GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel>
class Remeshing_sizing_field
{
public:
  typedef GeomTraits Geom_traits;                   ///< the geometric traits
  typedef typename GeomTraits::Point_3 Point_3;     ///< point type
  typedef typename GeomTraits::Vector_3 Vector_3;   ///< vector type

  /// default of the named parameter `elements_across_thickness`: about two
  /// tetrahedra across a thin layer (one layer of bubbles between its faces),
  /// as with 2 (until session 55), but fewer of them: the bundled model's thin
  /// layer gets 30,945 tetrahedra instead of 49,956 (bench/README.md, session 56)
  static constexpr double default_elements_across_thickness = 1.63;
  /// default of the named parameter `size_grading`
  static constexpr double default_size_grading = 1.5;
  /// default of the named parameter `curvature_angle`: 16 edges around a circle
  static constexpr double default_curvature_angle = 22.5;

private:
  typedef typename GeomTraits::Triangle_3 Triangle_3;
  typedef typename GeomTraits::Segment_3 Segment_3;

public:
  /*!
  builds the field of `model`, whose features are `features`
  (`detect_model_features()`).

  \cgalNamedParamsBegin
    \cgalParamNBegin{edge_length}
      \cgalParamDescription{the user size \f$ s \f$ in model units}
      \cgalParamType{`double`}
      \cgalParamDefault{the median input edge length}
    \cgalParamNEnd
    \cgalParamNBegin{relative_edge_length}
      \cgalParamDescription{the user size as a fraction of the bounding-box diagonal (if `edge_length` is not given)}
      \cgalParamType{`double`}
    \cgalParamNEnd
    \cgalParamNBegin{region_size_factors}
      \cgalParamDescription{a factor per region (entry 0 ignored; missing entries are 1)}
      \cgalParamType{`std::vector<double>`}
      \cgalParamDefault{all 1}
    \cgalParamNEnd
    \cgalParamNBegin{patch_size_factors}
      \cgalParamDescription{a factor per patch (missing entries are 1)}
      \cgalParamType{`std::vector<double>`}
      \cgalParamDefault{all 1}
    \cgalParamNEnd
    \cgalParamNBegin{elements_across_thickness}
      \cgalParamDescription{edges wanted across the local thickness; 0 turns the rule off}
      \cgalParamType{`double`}
      \cgalParamDefault{`default_elements_across_thickness` (1.63)}
    \cgalParamNEnd
    \cgalParamNBegin{minimum_edge_length}
      \cgalParamDescription{floor of the thickness rule, in model units (positive)}
      \cgalParamType{`double`}
      \cgalParamDefault{a tenth of the smallest patch size}
    \cgalParamNEnd
    \cgalParamNBegin{size_grading}
      \cgalParamDescription{largest size ratio between neighbouring edges (> 1)}
      \cgalParamType{`double`}
      \cgalParamDefault{1.5}
    \cgalParamNEnd
    \cgalParamNBegin{curvature_angle}
      \cgalParamDescription{the largest turn, in degrees, of the input surface along one new edge (the
        curvature rule); 0 turns the rule off}
      \cgalParamType{`double`}
      \cgalParamDefault{`default_curvature_angle` (22.5)}
    \cgalParamNEnd
    \cgalParamNBegin{refine_ribbons}
      \cgalParamDescription{applies the ribbon rule (needs `elements_across_thickness` > 0). modelA5's
        fault strip f3_1, 3 to 13 wide over 3 km with a floor of 37: re-meshed triangles under 25 degrees
        199 -> 68, tetrahedra under 10 degrees 395 -> 221, but 1.96 -> 2.43 million tetrahedra and
        241 -> 564 s}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd
  */
  template <class CGAL_NP_TEMPLATE_PARAMETERS>
  Remeshing_sizing_field(const Geological_model_3<GeomTraits>& model, const Model_features& features,
                         const CGAL_NP_CLASS& np = parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;

    diagonal_ = Bubble_mesh_3::bbox_diagonal(model);
    const std::optional<double> asked = internal::asked_edge_length(model, np);
    const double size = asked ? *asked : median_edge_length(model);
    CGAL_precondition_msg(size > 0., "the target edge length must be positive");
    user_size_ = size;

    const std::vector<double> region_factors =
      choose_parameter(get_parameter(np, internal_np::region_size_factors), std::vector<double>());
    const std::vector<double> patch_factors =
      choose_parameter(get_parameter(np, internal_np::patch_size_factors), std::vector<double>());
    patch_size_.assign(model.number_of_patches(), size);
    for(std::size_t p = 0; p < model.number_of_patches(); ++p)
    {
      double f = (p < patch_factors.size()) ? patch_factors[p] : 1.;
      double g = std::numeric_limits<double>::infinity();
      for(std::size_t r : {model.patch(p).positive_region, model.patch(p).negative_region})
        if(r != 0) g = (std::min)(g, (r < region_factors.size()) ? region_factors[r] : 1.);
      if(!std::isfinite(g)) g = 1.;
      CGAL_precondition_msg(f > 0. && g > 0., "size factors must be positive");
      patch_size_[p] = size * f * g;
    }
    max_patch_size_ = patch_size_.empty() ? size : *std::max_element(patch_size_.begin(), patch_size_.end());
    const double min_patch_size =
      patch_size_.empty() ? size : *std::min_element(patch_size_.begin(), patch_size_.end());

    elements_across_ = choose_parameter(get_parameter(np, internal_np::elements_across_thickness),
                                        default_elements_across_thickness);
    minimum_size_ = choose_parameter(get_parameter(np, internal_np::minimum_edge_length), 0.1 * min_patch_size);
    grading_ = choose_parameter(get_parameter(np, internal_np::size_grading), default_size_grading);
    refine_ribbons_ = choose_parameter(get_parameter(np, internal_np::refine_ribbons), false);
    const double curvature_angle =
      choose_parameter(get_parameter(np, internal_np::curvature_angle), default_curvature_angle);
    CGAL_precondition_msg(curvature_angle >= 0., "curvature_angle must not be negative");
    CGAL_precondition_msg(grading_ > 1., "size_grading must be above 1");
    // (0 would let a pinch-out or a ribbon's tip ask for edges down to nothing)
    CGAL_precondition_msg(minimum_size_ > 0., "minimum_edge_length must be positive");
    slope_ = grading_ - 1.;

    add_curve_grading_sources(model, features);
    if(curvature_angle > 0.) add_curvature_sources(model, features, curvature_angle);
    if(elements_across_ > 0.)
    {
      add_thickness_sources(model, features);
      add_curve_proximity_sources(model, features);
    }
  }

  /// copies the values (the point search is rebuilt on demand)
  Remeshing_sizing_field(const Remeshing_sizing_field& other) { copy_values(other); }
  /// copies the values (the point search is rebuilt on demand)
  Remeshing_sizing_field& operator=(const Remeshing_sizing_field& other)
  {
    if(this != &other) copy_values(other);
    return *this;
  }

  /// the target edge length at `p`, a point of patch `patch`
  double operator()(const Point_3& p, std::size_t patch) const { return cone(p, patch_size_[patch]); }

  /// the target edge length at `p` whatever its patch (the largest patch size is the cap)
  double operator()(const Point_3& p) const { return cone(p, max_patch_size_); }

  /// the size \f$ b_p \f$ of patch `p` before the local rules
  double patch_size(std::size_t p) const { return patch_size_[p]; }
  /// the user size \f$ s \f$
  double user_size() const { return user_size_; }
  /// the floor of the thickness rule
  double minimum_size() const { return minimum_size_; }
  /// the size grading ratio
  double size_grading() const { return grading_; }
  /// the bounding-box diagonal of the model
  double diagonal() const { return diagonal_; }
  /// number of point values (thickness samples, grading samples, constraints) held
  std::size_t number_of_point_sizes() const { return source_points_.size(); }
  /// smallest thickness found (infinite if none is under the patch sizes times N)
  double smallest_thickness() const { return smallest_thickness_; }
  /// the size the thickness rule sets at the smallest thickness: that
  /// thickness over `elements_across_thickness`, at least `minimum_edge_length`
  /// (0 if no thickness binds)
  double smallest_thickness_size() const
  {
    return std::isfinite(smallest_thickness_) && elements_across_ > 0.
             ? (std::max)(minimum_size_, smallest_thickness_ / elements_across_) : 0.;
  }

  /// bounds the field by `h` at `p` (and by the graded value around it)
  void add_size_constraint(const Point_3& p, double h)
  {
    if(!(h < max_patch_size_)) return;
    source_points_.push_back(p);
    source_sizes_.push_back(h);
    min_source_ = (std::min)(min_source_, h);
    // constraints come one by one between queries (the curves' short spans):
    // the searches are rebuilt only once many wait, the others are read one by one
    if(source_points_.size() - searched_ > max_unsearched) grid_ready_.store(false);
  }

private:
  template <class Model>
  static double median_edge_length(const Model& model)
  {
    std::vector<double> lengths;
    lengths.reserve(3 * model.number_of_triangles());
    for(const auto& tri : model.triangles())
      for(int k = 0; k < 3; ++k)
        if(tri[k] < tri[(k + 1) % 3]) // each interior edge once per side is fine for a median
          lengths.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(model.point(tri[k]),
                                                                              model.point(tri[(k + 1) % 3])))));
    if(lengths.empty()) return 1.;
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    return lengths[lengths.size() / 2];
  }

  void add_source(const Point_3& p, double h)
  {
    if(!(h < max_patch_size_)) return;
    source_points_.push_back(p);
    source_sizes_.push_back(h);
    min_source_ = (std::min)(min_source_, h);
  }

  // Points along every curve carrying the smallest size of the patches on it,
  // so that a coarse patch grades down towards a finer neighbour.
  void add_curve_grading_sources(const Geological_model_3<GeomTraits>& model, const Model_features& features)
  {
    for(const Model_features::Curve& c : features.curves)
    {
      double lo = std::numeric_limits<double>::infinity(), hi = 0.;
      for(std::size_t p : c.patches)
      {
        lo = (std::min)(lo, patch_size_[p]);
        hi = (std::max)(hi, patch_size_[p]);
      }
      if(!(lo < max_patch_size_)) continue; // no patch anywhere is coarser
      for(std::size_t i = 0; i + 1 < c.points.size(); ++i)
      {
        const Point_3& a = model.point(c.points[i]);
        const Point_3& b = model.point(c.points[i + 1]);
        const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
        const std::size_t n = (std::max)(std::size_t(1), std::size_t(std::ceil(len / lo)));
        for(std::size_t k = 0; k < n; ++k) add_source(a + (b - a) * (double(k) / double(n)), lo);
      }
      add_source(model.point(c.points.back()), lo);
      (void)hi;
    }
  }

  // plain doubles for the thickness and proximity rays: a size heuristic on needle triangles
  typedef CGAL::Simple_cartesian<double> SK;
  typedef typename SK::Point_3 SPoint;
  typedef typename SK::Vector_3 SVector;
  typedef typename SK::Segment_3 SSegment;
  typedef typename SK::Triangle_3 STriangle;
  static SPoint sp(const Point_3& p)
  {
    return SPoint(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  // The curvature rule at the midpoint of every input edge inside a patch
  // (two triangles of the patch, turning by less than the feature angle).
  void add_curvature_sources(const Geological_model_3<GeomTraits>& model, const Model_features& features,
                             double curvature_angle)
  {
    const double pi = 3.14159265358979323846;
    const double turn = curvature_angle * pi / 180., feature = features.feature_angle * pi / 180.;
    const internal::Edge_triangles_map et = internal::edge_triangles(model);
    auto normal = [&](std::size_t t) {
      const auto& tri = model.triangle(t);
      const SPoint p = sp(model.point(tri[0]));
      return CGAL::cross_product(sp(model.point(tri[1])) - p, sp(model.point(tri[2])) - p);
    };
    // each edge once, from its first triangle, in triangle order
    for(std::size_t t1 = 0; t1 < model.number_of_triangles(); ++t1)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t a = model.triangle(t1)[k], b = model.triangle(t1)[(k + 1) % 3];
        const std::vector<std::size_t>& ts = et.at(internal::edge_key(a, b));
        if(ts.size() != 2) continue; // a border or a non-manifold edge
        const std::size_t t2 = ts[0] == t1 ? ts[1] : ts[0];
        if(t2 < t1 || model.patch_of_triangle(t1) != model.patch_of_triangle(t2)) continue;
        // a patch's triangles are oriented alike: the normals' angle is the turn
        // (atan2 rather than acos: exact for the small turns of smooth surfaces)
        const auto n1 = normal(t1), n2 = normal(t2);
        const double phi = std::atan2(std::sqrt(CGAL::cross_product(n1, n2).squared_length()), n1 * n2);
        if(!(phi > 0.) || !(phi < feature)) continue;
        const Point_3& p = model.point(a);
        const Point_3& q = model.point(b);
        add_source(CGAL::midpoint(p, q),
                   (std::max)(minimum_size_, turn * std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q))) / phi));
      }
  }

  // Sample points of each patch, about half a patch size apart; thickness
  // rays are cast from them along the triangle normal, both ways.
  void add_thickness_sources(const Geological_model_3<GeomTraits>& model, const Model_features& features)
  {
    typedef typename std::vector<STriangle>::const_iterator Iterator;
    typedef CGAL::AABB_triangle_primitive<SK, Iterator> Primitive;
    typedef CGAL::AABB_traits<SK, Primitive> Traits;
    typedef CGAL::AABB_tree<Traits> Tree;

    std::vector<STriangle> triangles;
    triangles.reserve(model.number_of_triangles());
    for(const auto& tri : model.triangles())
      triangles.push_back(STriangle(sp(model.point(tri[0])), sp(model.point(tri[1])), sp(model.point(tri[2]))));
    if(triangles.empty()) return;
    // the tree holds pieces of the triangles no longer than twice the
    // smallest patch size: long needles would otherwise have boxes that
    // every ray crosses
    std::vector<STriangle> pieces;
    std::vector<std::size_t> owner;
    {
      const double limit2 = CGAL::square(2. * *std::min_element(patch_size_.begin(), patch_size_.end()));
      std::vector<std::pair<STriangle, std::size_t> > stack;
      for(std::size_t t = 0; t < triangles.size(); ++t)
      {
        stack.push_back(std::make_pair(triangles[t], t));
        while(!stack.empty())
        {
          const STriangle tr = stack.back().first;
          stack.pop_back();
          int k = 0;
          double longest = 0.;
          for(int i = 0; i < 3; ++i)
          {
            const double l = CGAL::squared_distance(tr.vertex(i), tr.vertex((i + 1) % 3));
            if(l > longest) { longest = l; k = i; }
          }
          if(longest <= limit2 || pieces.size() > 50 * triangles.size())
          {
            pieces.push_back(tr);
            owner.push_back(t);
            continue;
          }
          const SPoint m = CGAL::midpoint(tr.vertex(k), tr.vertex((k + 1) % 3));
          stack.push_back(std::make_pair(STriangle(tr.vertex(k), m, tr.vertex((k + 2) % 3)), t));
          stack.push_back(std::make_pair(STriangle(m, tr.vertex((k + 1) % 3), tr.vertex((k + 2) % 3)), t));
        }
      }
    }
    Tree tree(pieces.begin(), pieces.end());

    // patch adjacency: sharing a point
    const std::size_t np = model.number_of_patches();
    std::vector<std::vector<std::size_t> > point_patches(model.number_of_points());
    for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
      for(std::size_t v : model.triangle(t))
      {
        std::vector<std::size_t>& pp = point_patches[v];
        if(std::find(pp.begin(), pp.end(), model.patch_of_triangle(t)) == pp.end())
          pp.push_back(model.patch_of_triangle(t));
      }
    std::vector<std::vector<char> > adjacent(np, std::vector<char>(np, 0));
    for(const std::vector<std::size_t>& pp : point_patches)
      for(std::size_t a : pp)
        for(std::size_t b : pp) adjacent[a][b] = 1;

    std::vector<SVector> unit_normal(triangles.size());
    for(std::size_t t = 0; t < triangles.size(); ++t)
    {
      SVector n = triangles[t].supporting_plane().orthogonal_vector();
      const double l = std::sqrt(CGAL::to_double(n.squared_length()));
      unit_normal[t] = (l > 0.) ? n / l : SVector(0, 0, 0);
    }
    const double parallel_cos = std::cos(30. * 3.14159265358979323846 / 180.);

    typedef typename Tree::template Intersection_and_primitive_id<SSegment>::Type Hit;
    std::vector<Hit> hits;
    // thickness at `x` of patch `p` along the unit normal `n`
    auto thickness = [&](const SPoint& x, const SVector& n, std::size_t p, double reach) {
      double best = std::numeric_limits<double>::infinity();
      // start a hair off the surface: a segment starting on a triangle is a degenerate case for the predicates
      const double lift = 1e-7 * diagonal_;
      for(int side = -1; side <= 1; side += 2)
      {
        const SVector dir = n * double(side);
        const SSegment ray(x + dir * lift, x + dir * reach);
        hits.clear();
        tree.all_intersections(ray, std::back_inserter(hits));
        for(const Hit& h : hits)
        {
          const std::size_t s = owner[std::size_t(h.second - pieces.begin())];
          const std::size_t q = model.patch_of_triangle(s);
          if(q == p) continue;
          if(adjacent[p][q] && std::abs(CGAL::to_double(unit_normal[s] * n)) < parallel_cos) continue;
          const SPoint* hp = boost::get<SPoint>(&h.first);
          double d = 0.;
          if(hp != nullptr) d = std::sqrt(CGAL::to_double(CGAL::squared_distance(x, *hp)));
          else
          {
            const SSegment* hs = boost::get<SSegment>(&h.first);
            if(hs == nullptr) continue;
            d = std::sqrt(CGAL::to_double((std::min)(CGAL::squared_distance(x, hs->source()),
                                                     CGAL::squared_distance(x, hs->target()))));
          }
          // a neighbour touched where the sample sits on the shared border: no thickness
          if(d <= 2. * lift) continue;
          best = (std::min)(best, d);
        }
      }
      return best;
    };
    auto record = [&](const SPoint& x, double d) {
      smallest_thickness_ = (std::min)(smallest_thickness_, d);
      add_source(Point_3(x.x(), x.y(), x.z()), (std::max)(minimum_size_, d / elements_across_));
    };

    for(std::size_t p = 0; p < np; ++p)
    {
      const double b = patch_size_[p];
      const double reach = elements_across_ * b; // thicker than this: the rule does not bind
      // samples: the patch's points (with the area-weighted normal around them) ...
      std::map<std::size_t, SVector> point_normal;
      for(std::size_t t : features.patch_triangles[p])
        for(std::size_t v : model.triangle(t))
        {
          const SVector an = triangles[t].supporting_plane().orthogonal_vector() * 0.5;
          auto it = point_normal.find(v);
          if(it == point_normal.end()) point_normal[v] = an;
          else it->second = it->second + an;
        }
      std::map<std::size_t, double> point_thickness;
      for(const auto& pn : point_normal)
      {
        const double l = std::sqrt(CGAL::to_double(pn.second.squared_length()));
        if(!(l > 0.)) continue;
        const double d = thickness(sp(model.point(pn.first)), pn.second / l, p, reach);
        if(d < reach)
        {
          record(sp(model.point(pn.first)), d);
          point_thickness[pn.first] = d;
        }
      }
      // ... and a grid inside large triangles: two sizes apart first, then,
      // where that finds a thin spot, one local size apart (the field grows
      // by half the distance to a sample, so sparse samples would let it
      // reach 1.5 times the wanted size between them)
      for(std::size_t t : features.patch_triangles[p])
      {
        const STriangle& tri = triangles[t];
        const SVector& n = unit_normal[t];
        if(n == CGAL::NULL_VECTOR) continue;
        double longest = 0.;
        for(int k = 0; k < 3; ++k)
          longest = (std::max)(longest, std::sqrt(CGAL::to_double(
                                          CGAL::squared_distance(tri.vertex(k), tri.vertex((k + 1) % 3)))));
        double thinnest = reach;
        for(std::size_t v : model.triangle(t))
        {
          auto it = point_thickness.find(v);
          if(it != point_thickness.end()) thinnest = (std::min)(thinnest, it->second);
        }
        auto sample_grid = [&](double spacing, std::size_t cap) {
          const std::size_t m = (std::min)(cap, std::size_t(std::ceil(longest / spacing)));
          for(std::size_t i = 0; i <= m; ++i)
            for(std::size_t j = 0; i + j <= m; ++j)
            {
              if((i == 0 && j == 0) || i == m || j == m) continue; // the corners are sampled above
              const double u = double(i) / double(m), v = double(j) / double(m);
              const SPoint x = tri.vertex(0) + (tri.vertex(1) - tri.vertex(0)) * u + (tri.vertex(2) - tri.vertex(0)) * v;
              const double d = thickness(x, n, p, reach);
              if(d < reach)
              {
                record(x, d);
                thinnest = (std::min)(thinnest, d);
              }
            }
        };
        if(longest > 2. * b) sample_grid(2. * b, 32);
        const double local = (std::max)(minimum_size_, thinnest / elements_across_);
        if(thinnest < reach && longest > local) sample_grid(local, 256);
      }
    }
  }

  // Distance from curve points to the patches and curves that do not touch
  // the curve: a fault tip close under a horizon needs small elements there.
  void add_curve_proximity_sources(const Geological_model_3<GeomTraits>& model, const Model_features& features)
  {
    typedef typename std::vector<STriangle>::const_iterator Triangle_iterator;
    typedef CGAL::AABB_triangle_primitive<SK, Triangle_iterator> Triangle_primitive;
    typedef CGAL::AABB_tree<CGAL::AABB_traits<SK, Triangle_primitive> > Triangle_tree;
    typedef typename std::vector<SSegment>::const_iterator Segment_iterator;
    typedef CGAL::AABB_segment_primitive<SK, Segment_iterator> Segment_primitive;
    typedef CGAL::AABB_tree<CGAL::AABB_traits<SK, Segment_primitive> > Segment_tree;
    

    if(features.curves.empty()) return;
    std::vector<STriangle> triangles;
    for(const auto& tri : model.triangles())
      triangles.push_back(STriangle(sp(model.point(tri[0])), sp(model.point(tri[1])), sp(model.point(tri[2]))));
    std::vector<SSegment> segments;
    std::vector<std::size_t> segment_curve;
    for(std::size_t c = 0; c < features.curves.size(); ++c)
      for(std::size_t i = 0; i + 1 < features.curves[c].points.size(); ++i)
      {
        segments.push_back(SSegment(sp(model.point(features.curves[c].points[i])),
                                     sp(model.point(features.curves[c].points[i + 1]))));
        segment_curve.push_back(c);
      }
    Triangle_tree ttree(triangles.begin(), triangles.end());
    Segment_tree stree(segments.begin(), segments.end());

    // which curves and patches touch each curve (share a point with it)
    std::vector<std::vector<std::size_t> > point_curves(model.number_of_points());
    for(std::size_t c = 0; c < features.curves.size(); ++c)
      for(std::size_t v : features.curves[c].points)
        if(point_curves[v].empty() || point_curves[v].back() != c) point_curves[v].push_back(c);
    std::vector<std::vector<std::size_t> > point_patches(model.number_of_points());
    for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
      for(std::size_t v : model.triangle(t))
      {
        std::vector<std::size_t>& pp = point_patches[v];
        if(std::find(pp.begin(), pp.end(), model.patch_of_triangle(t)) == pp.end())
          pp.push_back(model.patch_of_triangle(t));
      }

    const std::vector<std::vector<std::size_t> > partners =
      refine_ribbons_ ? ribbon_partners(model, features) : std::vector<std::vector<std::size_t> >(features.curves.size());

    std::vector<Triangle_iterator> near_triangles;
    std::vector<Segment_iterator> near_segments;
    // squared distance from x to the nearest curve segment within `radius` (in
    // its box) that `accept`s (segment, its curve), or radius squared
    auto nearest_segment2 = [&](const SPoint& x, double radius, const auto& accept) {
      const Bbox_3 box(x.x() - radius, x.y() - radius, x.z() - radius, x.x() + radius, x.y() + radius, x.z() + radius);
      double best2 = radius * radius;
      near_segments.clear();
      stree.all_intersected_primitives(box, std::back_inserter(near_segments));
      for(Segment_iterator it : near_segments)
        if(accept(*it, segment_curve[std::size_t(it - segments.begin())]))
          best2 = (std::min)(best2, CGAL::to_double(CGAL::squared_distance(x, *it)));
      return best2;
    };
    for(std::size_t c = 0; c < features.curves.size(); ++c)
    {
      const Model_features::Curve& curve = features.curves[c];
      std::vector<std::size_t> touching_curves, touching_patches;
      for(std::size_t v : curve.points)
      {
        touching_curves.insert(touching_curves.end(), point_curves[v].begin(), point_curves[v].end());
        touching_patches.insert(touching_patches.end(), point_patches[v].begin(), point_patches[v].end());
      }
      std::sort(touching_curves.begin(), touching_curves.end());
      std::sort(touching_patches.begin(), touching_patches.end());
      const std::vector<std::size_t>& ribbon = partners[c];
      double b = 0.;
      for(std::size_t p : curve.patches) b = (std::max)(b, patch_size_[p]);
      const double reach = elements_across_ * b;
      for(std::size_t i = 0; i + 1 < curve.points.size(); ++i)
      {
        const SPoint a = sp(model.point(curve.points[i]));
        const SPoint e = sp(model.point(curve.points[i + 1]));
        const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, e)));
        const std::size_t n = (std::min)(std::size_t(200), (std::max)(std::size_t(1),
                                                                      std::size_t(std::ceil(len / (0.5 * b)))));
        for(std::size_t k = 0; k <= n; ++k)
        {
          const SPoint x = a + (e - a) * (double(k) / double(n));
          // the search ball's box, not a Sphere_3: CGAL's Sphere_3 intersection
          // tests are with the sphere's surface and miss what lies wholly inside it
          const Bbox_3 box(x.x() - reach, x.y() - reach, x.z() - reach, x.x() + reach, x.y() + reach, x.z() + reach);
          double best2 = reach * reach;
          near_triangles.clear();
          ttree.all_intersected_primitives(box, std::back_inserter(near_triangles));
          for(Triangle_iterator it : near_triangles)
          {
            const std::size_t q = model.patch_of_triangle(std::size_t(it - triangles.begin()));
            if(std::binary_search(touching_patches.begin(), touching_patches.end(), q)) continue;
            best2 = (std::min)(best2, CGAL::to_double(CGAL::squared_distance(x, *it)));
          }
          best2 = (std::min)(best2, nearest_segment2(x, reach, [&](const SSegment&, std::size_t d) {
                               return !std::binary_search(touching_curves.begin(), touching_curves.end(), d);
                             }));
          if(best2 < reach * reach)
          {
            const double d = std::sqrt(best2);
            smallest_thickness_ = (std::min)(smallest_thickness_, d);
            add_source(Point_3(x.x(), x.y(), x.z()), (std::max)(minimum_size_, d / elements_across_));
          }
        }
        // A strip: another curve of a patch of this one, parallel to it and not
        // touching it, closer than the floor allows for (a thin layer's side on a
        // wall). Its sides are sampled as densely as the sizes they ask for, as a
        // ribbon's below.
        if(elements_across_ > 0.)
        {
          const double narrow = minimum_size_ / strip_spacing_over_width;
          const SVector u = e - a;
          auto strip_side = [&](const SSegment& s, std::size_t d) {
            if(std::binary_search(touching_curves.begin(), touching_curves.end(), d)) return false;
            const std::vector<std::size_t>& dp = features.curves[d].patches;
            if(std::find_first_of(curve.patches.begin(), curve.patches.end(), dp.begin(), dp.end()) == curve.patches.end())
              return false;
            // along this curve, not converging on it (a pinch-out, which the floor is for)
            const SVector v = s.to_vector();
            return !(CGAL::square(u * v) < strip_parallel_cos2 * u.squared_length() * v.squared_length());
          };
          for(double t = 0.; t < len;)
          {
            const SPoint x = a + (e - a) * (t / len);
            const double across2 = nearest_segment2(x, narrow, strip_side);
            const double h = strip_spacing_over_width * std::sqrt(across2);
            if(h < minimum_size_ && h >= strip_floor * minimum_size_) add_source(Point_3(x.x(), x.y(), x.z()), h);
            t += 0.5 * (h < minimum_size_ ? (std::max)(h, strip_floor * minimum_size_) : minimum_size_);
          }
        }
        if(ribbon.empty()) continue;
        // Across a ribbon one edge makes good triangles. Its sides are sampled as densely
        // as the sizes they ask for (the grading would undo sparser samples), and its
        // floor is lower than the thickness rule's, which left it needles all along.
        const double floor = ribbon_floor * minimum_size_;
        for(double t = 0.; t < len;)
        {
          const SPoint x = a + (e - a) * (t / len);
          const double across2 = nearest_segment2(x, b, [&](const SSegment&, std::size_t d) {
            return std::binary_search(ribbon.begin(), ribbon.end(), d);
          });
          // narrower than the floor, smaller edges would only make more needles
          const double h = std::sqrt(across2);
          if(h >= floor && h < b) add_source(Point_3(x.x(), x.y(), x.z()), h);
          // (a step of a hundredth of the patch size at least: a floor of 0 must not stall)
          t += 0.5 * (std::max)({floor, h, 0.01 * b});
        }
      }
    }
  }

  /*
  Ribbons: a patch whose border curves meet at a corner under
  `ribbon_corner_angle` is a strip between them near that corner, and often
  all along (a fault between two horizon cut lines that nearly coincide:
  modelA5's f3_1 is 3 to 13 units wide over 3 km, CloudSpin's fault lenses
  up to 19 wide over 5 km). The curve proximity rule skips curves that touch,
  so the strip's two sides never saw each other and the triangles spanned it
  as needles. For each curve, the curves it meets at such a corner of a patch
  they both bound (sorted).
  */
  static constexpr double ribbon_corner_angle = 10.;
  // the ribbon rule's floor, over minimum_edge_length: only the tip of a ribbon, where it
  // is narrower than this, is left to needles (a lens pinching out at 0.03 degrees would
  // otherwise ask for edges down to nothing)
  static constexpr double ribbon_floor = 0.05;
  // A strip of width w narrower than the floor: its sides' points, placed
  // half-way between each other's by the re-meshing, make triangles of
  // atan(2 w / s) at a spacing s, at least 25 degrees up to s = 4.3 w. The
  // strip's own floor, over minimum_edge_length, keeps a strip pinching out
  // from asking for edges down to nothing (a hundredth takes CloudSpin's
  // layer squeezed to 0.16-2.4 m along a fault out of its needles, but the
  // volume stage then spends over 19 minutes placing bubbles against its
  // 47,000 small surface bubbles); its sides are parallel within 10 degrees
  // (the squared cosine).
  static constexpr double strip_spacing_over_width = 3.5;
  static constexpr double strip_floor = 0.25;
  static constexpr double strip_parallel_cos2 = 0.9698;
  static std::vector<std::vector<std::size_t> > ribbon_partners(const Geological_model_3<GeomTraits>& model,
                                                                const Model_features& features)
  {
    std::vector<std::vector<std::size_t> > partners(features.curves.size());
    const std::vector<Patch_corner_angles> corners = patch_corner_angles(model, ribbon_corner_angle);
    for(std::size_t p = 0; p < corners.size() && p < features.patch_curves.size(); ++p)
      for(const auto& vc : corners[p].sharp_corners)
      {
        std::vector<std::size_t> ends;
        for(std::size_t c : features.patch_curves[p])
          if(features.curves[c].points.front() == vc.first || features.curves[c].points.back() == vc.first)
            ends.push_back(c);
        for(std::size_t a : ends)
          for(std::size_t b : ends)
            if(a != b) partners[a].push_back(b);
      }
    for(std::vector<std::size_t>& v : partners)
    {
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
    }
    return partners;
  }

  void copy_values(const Remeshing_sizing_field& o)
  {
    diagonal_ = o.diagonal_; user_size_ = o.user_size_; max_patch_size_ = o.max_patch_size_;
    elements_across_ = o.elements_across_; minimum_size_ = o.minimum_size_; grading_ = o.grading_;
    refine_ribbons_ = o.refine_ribbons_;
    slope_ = o.slope_; min_source_ = o.min_source_; smallest_thickness_ = o.smallest_thickness_;
    patch_size_ = o.patch_size_; source_points_ = o.source_points_; source_sizes_ = o.source_sizes_;
    grid_ready_.store(false); // rebuilt on demand
    searched_ = 0;
  }

  // The sources in a grid of cells of half the largest patch size (a query's
  // reach where the sizes are coarse), each cell with its smallest size, for
  // the walk of `internal::Cell_minima::cone_minimum()`.
  void build_grid() const
  {
    if(grid_ready_.load(std::memory_order_acquire)) return;
    std::lock_guard<std::mutex> lock(build_mutex_);
    if(grid_ready_.load(std::memory_order_relaxed)) return;
    const std::size_t n = source_points_.size();
    CGAL_precondition(n < std::size_t(internal::Neighbor_grid::none));
    std::vector<double> x(n), y(n), z(n);
    const double inf = std::numeric_limits<double>::infinity();
    double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
    for(std::size_t i = 0; i < n; ++i)
    {
      const Point_3& q = source_points_[i];
      x[i] = CGAL::to_double(q.x());
      y[i] = CGAL::to_double(q.y());
      z[i] = CGAL::to_double(q.z());
      const double c[3] = {x[i], y[i], z[i]};
      for(int d = 0; d < 3; ++d)
      {
        lo[d] = (std::min)(lo[d], c[d]);
        hi[d] = (std::max)(hi[d], c[d]);
      }
    }
    grid_.set_domain(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2], 0.5 * max_patch_size_,
                     (std::max)(std::size_t(1) << 16, 2 * n));
    grid_.build(x.data(), y.data(), z.data(), n, nullptr, source_sizes_.data());
    cell_min_size_.build(grid_, x.data(), y.data(), z.data(), source_sizes_.data(), n);
    searched_ = n;
    grid_ready_.store(true, std::memory_order_release);
  }

  double cone(const Point_3& p, double cap) const
  {
    if(source_points_.empty() || !(min_source_ < cap)) return cap;
    build_grid();
    double best = cap;
    for(std::size_t i = searched_; i < source_points_.size(); ++i)
      best = (std::min)(best, source_sizes_[i] + slope_ * std::sqrt(CGAL::to_double(
                                                        CGAL::squared_distance(p, source_points_[i]))));
    return cell_min_size_.cone_minimum(grid_, CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                       CGAL::to_double(p.z()), slope_, best);
  }

  double diagonal_ = 0., user_size_ = 0., max_patch_size_ = 0.;
  double elements_across_ = default_elements_across_thickness, minimum_size_ = 0., grading_ = 1.5, slope_ = 0.5;
  bool refine_ribbons_ = false;
  double min_source_ = std::numeric_limits<double>::infinity();
  double smallest_thickness_ = std::numeric_limits<double>::infinity();
  std::vector<double> patch_size_;
  std::vector<Point_3> source_points_;
  std::vector<double> source_sizes_;
  mutable internal::Neighbor_grid grid_;
  mutable internal::Cell_minima cell_min_size_;
  mutable std::atomic<bool> grid_ready_{false};
  // sources [0, searched_) are in `grid_`, the others are read one by one
  mutable std::size_t searched_ = 0;
  static constexpr std::size_t max_unsearched = 256;
  mutable std::mutex build_mutex_;
};

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_REMESHING_SIZING_FIELD_H
