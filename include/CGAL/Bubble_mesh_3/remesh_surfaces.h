// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_REMESH_SURFACES_H
#define CGAL_BUBBLE_MESH_3_REMESH_SURFACES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Remeshing_sizing_field.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/model_features.h>
#include <CGAL/Bubble_mesh_3/snap_points_to_axis_planes.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_chart_triangulation.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_charts.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_mesh_improvement.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_patch_isotropic.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_triangle_tree.h>
#include <CGAL/Bubble_mesh_3/internal/remesh_volume_balance.h>
#include <CGAL/Bubble_mesh_3/internal/parallel_loops.h>
#include <CGAL/Bubble_mesh_3/internal/Point_index_tree.h>
#include <CGAL/Bubble_mesh_3/internal/remeshing_parameters.h>
#include <CGAL/Bubble_mesh_3/internal/resample_curves.h>
#include <CGAL/Bubble_mesh_3/internal/vertex_angle.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

What `remesh_surfaces()` did and how good the result is. Angles are in
degrees; distances are relative as stated; times are in seconds.
*/
struct Surface_remeshing_report
{
  Surface_remeshing_method method = Surface_remeshing_method::BUBBLES; ///< the patch method used
  std::size_t number_of_corners = 0;          ///< corners of the input (`detect_model_features()`)
  std::size_t number_of_curves = 0;           ///< curves of the input
  std::size_t number_of_charts = 0;           ///< planar pieces the patches were triangulated in
  std::size_t number_of_chart_cuts = 0;       ///< charts cut again because their boundary overlapped in the plane
  std::size_t number_of_kept_curve_points = 0; ///< input points kept on curves (corners and turns)
  std::size_t number_of_curve_points = 0;     ///< points on the re-meshed curves
  /// curve pieces whose points were moved half-way between those of another
  /// curve across a narrow strip (a thin layer's side where it meets a wall)
  std::size_t number_of_staggered_curve_pieces = 0;
  /// free points collapsed into a neighbour to lift a triangle over the
  /// angle bound (a point left crowded against a curve)
  std::size_t number_of_collapsed_points = 0;
  /// curve samples slid along their curve to lift a triangle between curve
  /// points over the angle bound (where two curves' samples meet at a corner)
  std::size_t number_of_slid_curve_points = 0;
  /// free points added across an edge of a triangle under the angle bound
  /// whose three points are curve samples, where that lifts the four
  /// triangles around them over the bound
  std::size_t number_of_split_curve_triangles = 0;
  std::size_t number_of_points = 0;           ///< points of the output
  std::size_t number_of_triangles = 0;        ///< triangles of the output

  double target_size = 0.;                    ///< the size asked for: `edge_length` (or its default, the median input edge)
  /// the thinnest layer, or smallest gap between a fault tip and a surface,
  /// that the thickness rule found (infinite when none binds)
  double smallest_thickness = std::numeric_limits<double>::infinity();
  /// the size the thickness rule set there (`Remeshing_sizing_field::smallest_thickness_size()`; 0 when none binds)
  double smallest_thickness_size = 0.;
  double angle_bound = 25.;                   ///< the `minimum_triangle_angle` aimed at
  double input_min_angle = 0.;                ///< smallest triangle angle of the input
  double min_angle = 0.;                      ///< smallest triangle angle of the output
  double input_share_of_small_angle_triangles = 0.; ///< input triangles with an angle under the bound, share
  std::size_t number_of_small_angle_triangles = 0;  ///< output triangles with an angle under the bound
  /// of those, the triangles whose smallest angle sits at a curve point where
  /// the patch's own angle (between its two curve edges) is under the bound
  std::size_t number_of_forced_small_angle_triangles = 0;
  /// of those, the triangles whose three points lie on curves (or on the
  /// seams between a patch's charts): the curve sampling sets them (a strip
  /// between two curves narrower than the size, as a fault strip between two
  /// horizon cut lines), and no flip, move or collapse of the patch's points
  /// can change them
  std::size_t number_of_small_angle_triangles_between_curve_points = 0;
  /// of the triangles under the bound, those in the wedge of an input corner
  /// whose own angle is under the bound: the forced ones, and those whose three
  /// points lie on the corner's two curves, followed from the corner to where
  /// another curve meets them or they turn back (a fault lens between its
  /// tips, a layer pinching out on a wall). Such a wedge is narrower than any
  /// triangle of 25 degrees at the sizing field's floor over a length that
  /// grows as the corner's angle shrinks
  std::size_t number_of_small_angle_triangles_in_sharp_wedges = 0;
  /// the other triangles under the bound (output triangle indices): the ones
  /// the input does not explain
  std::vector<std::size_t> small_angle_triangles_outside_sharp_wedges;
  /// A triangle under the bound that an input corner forces (see
  /// `number_of_small_angle_triangles_in_sharp_wedges`): its output index and
  /// the corner's own angle, the patch's angle between its two curves there.
  struct Corner_forced_triangle
  {
    std::size_t triangle;  ///< output triangle index
    double corner_angle;   ///< degrees
    std::array<std::array<double, 3>, 3> points; ///< its corners (the output's coordinates, in its order)
  };
  /// the triangles counted by `number_of_small_angle_triangles_in_sharp_wedges`,
  /// by increasing index: a tetrahedron against one is thin because of the
  /// input's corner, which the quality report can tell (`Corner_forced_facet_angle`
  /// gives each boundary facet the smaller of its own angle and its corner's)
  std::vector<Corner_forced_triangle> corner_forced_triangles;
  double share_of_small_angle_triangles = 0.; ///< output triangles with an angle under the bound, share
  double share_of_edges_within_size = 0.;     ///< output edges with length in [0.5, 1.5] of the target there
  double input_share_of_edges_within_size = 0.; ///< the same for the input edges and the same targets
  /// shortest and longest output edge
  ///@{
  double min_edge_length = 0., max_edge_length = 0.; ///< output edge lengths
  ///@}

  double max_point_distance = 0.;     ///< largest distance of an output point to its input patch, over the diagonal
  double max_curve_distance = 0.;     ///< largest Hausdorff distance between an output curve and its input polyline, over the diagonal
  double max_triangle_distance = 0.;  ///< largest sampled distance of an output triangle to its input patch, over the local target
  double surface_distance = 1e-3;     ///< the `surface_distance` bound on it
  double share_of_triangles_beyond_distance = 0.; ///< output triangles farther than `surface_distance`, share

  std::vector<double> input_volumes;  ///< `region_volumes()` of the input (entry 0: whole model)
  std::vector<double> output_volumes; ///< `region_volumes()` of the output
  /// signed change of region `r`'s volume over its input volume (0 for a
  /// region of no volume, or beyond the volumes)
  double relative_volume_change(std::size_t r) const
  {
    if(r >= input_volumes.size() || r >= output_volumes.size() || input_volumes[r] == 0.) return 0.;
    return (output_volumes[r] - input_volumes[r]) / std::abs(input_volumes[r]);
  }
  double max_relative_volume_error = 0.; ///< largest |output - input| / input over the regions 1..n
  /// `max_relative_volume_error` before the free points slid along the input
  /// surface to give every region its volume back (`keep_region_volumes`)
  double volume_error_before_balancing = 0.;
  std::size_t number_of_volume_balancing_steps = 0;  ///< Newton steps of that balancing
  std::size_t number_of_volume_balancing_points = 0; ///< free points it moved
  /// the farthest one of them went (summed over the steps), over its local target size
  double largest_volume_balancing_move = 0.;
  /// regions left out of the balancing because slides could not give their
  /// volume back (a convex body faceted coarsely, whose chords all cut into
  /// it, or a region none of whose points may move)
  std::vector<std::size_t> regions_not_balanced; ///< those regions, in increasing order
  /// patches re-meshed again with every crease kept as a curve, so that the
  /// regions they bound keep their volume (those regions could not be
  /// balanced: 0 unless `keep_region_volumes`)
  std::size_t number_of_faceted_patches = 0;
  double time_volume_balance = 0.; ///< seconds spent on it (part of `time_patches`)

  /// seconds spent on the features, the sizing field, the curves, the patches and the measures
  ///@{
  double time_features = 0., time_sizing = 0., time_curves = 0., time_patches = 0., time_measures = 0.;
  ///@}
  double time = 0.; ///< total
};

namespace internal {

// Patches of regions the volume balance left out are re-meshed again with
// their creases kept (remesh_surfaces()): only patches with no input angle
// under the first bound (their creases would bring the needles back), and
// every crease over the second one, in degrees (the fault-and-tunnel model:
// the tunnel's volume change 1.9e-2, 1.5e-5 with the creases over 1 degree
// kept, 2.4e-8 over 0.01)
constexpr double faceted_patch_min_angle = 5.;
constexpr double faceted_patch_crease_angle = 0.01;
// The result is kept if it has no more triangles than the first under the
// angle bound less this (a salt dome of 21 k input triangles came out with one
// of 24.6 degrees, and its volume change 8.3e-3 -> 4.7e-9)
constexpr double faceted_patch_angle_slack = 5.;

// the smallest angle of triangle t of `model`, in degrees
template <class GeomTraits>
double triangle_min_angle(const Geological_model_3<GeomTraits>& model, std::size_t t)
{
  const auto& tri = model.triangle(t);
  return min_angle_degrees(model.point(tri[0]), model.point(tri[1]), model.point(tri[2]));
}

// the smallest angle of each patch's input triangles, in degrees
template <class GeomTraits>
std::vector<double> patch_smallest_angles(const Geological_model_3<GeomTraits>& model)
{
  std::vector<double> smallest(model.number_of_patches(), 180.);
  for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
  {
    double& s = smallest[model.patch_of_triangle(t)];
    s = (std::min)(s, triangle_min_angle(model, t));
  }
  return smallest;
}

// A polyline to resample: a feature curve or a seam between two charts.
struct Remesh_line
{
  std::vector<std::size_t> points; // input point indices
  bool is_curve = true;
  std::size_t patch = 0;          // seams: their patch
  std::vector<std::size_t> patches; // the patches whose sizes apply
  std::vector<char> essential;
  std::vector<std::size_t> out_points; // output point indices along the line
  std::vector<std::size_t> out_span;   // span (between two kept points) of each output segment
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > span_charts; // (chart, triangles on it)
};

template <class GeomTraits>
class Surface_remesher
{
public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename GeomTraits::Segment_3 Segment_3;
  typedef Geological_model_3<GeomTraits> Model;
  typedef std::array<std::size_t, 3> Triangle;

  struct Settings
  {
    Surface_remeshing_method method = Surface_remeshing_method::BUBBLES;
    double curve_distance = 5e-7;
    double surface_distance = 1e-3;
    double chart_angle = 50.;
    double angle_bound = 25.;
    std::size_t relaxation_steps = 40;
    std::size_t population_rounds = 3;
    bool keep_region_volumes = true;
    // patches whose free points the volume balance leaves where they are:
    // re-meshed with their creases kept, they lie flat between them, where a
    // slide changes no volume and the balance's steps would only wander
    std::vector<char> unbalanced_patches;
    bool verbose = false;
    bool parallel = false; // charts triangulated on several threads
  };

  Surface_remesher(const Model& input, const Model_features& features, Remeshing_sizing_field<GeomTraits>& sizing,
                   const Settings& settings, Surface_remeshing_report& report)
    : in_(input), features_(features), sizing_(sizing), set_(settings), report_(report)
  {}

  void run(Model& output)
  {
    Real_timer timer;
    timer.start();
    et_ = edge_triangles(in_);
    for(const Model_features::Curve& c : features_.curves)
      for(std::size_t i = 0; i + 1 < c.points.size(); ++i) feature_edges_[edge_key(c.points[i], c.points[i + 1])] = 1;
    point_on_feature_.assign(in_.number_of_points(), 0);
    for(const Model_features::Curve& c : features_.curves)
      for(std::size_t v : c.points) point_on_feature_[v] = 1;
    for(std::size_t p = 0; p < in_.number_of_patches(); ++p)
      patch_trees_.emplace_back(in_, features_.patch_triangles[p]);

    make_charts();
    // cut charts whose resampled boundary overlaps in the plane, and start again
    for(int attempt = 0;; ++attempt)
    {
      make_lines();
      resample_lines();
      if(attempt == 0) report_.time_curves = timer.time();
      std::vector<std::size_t> failed;
      triangulate_charts(failed);
      if(failed.empty() || attempt >= 8) break;
      for(std::size_t c : failed) cut_chart(c);
    }
    improve_patches();
    slide_curve_samples();
    if(set_.keep_region_volumes) balance_volumes();
    snap_to_axis_planes();
    build_output(output);
    report_.time_patches = timer.time() - report_.time_curves;
  }

  // output point index of each output point's curve: curve points of feature lines
  const std::vector<Remesh_line>& lines() const { return lines_; }
  const std::vector<Point_3>& output_points() const { return out_points_; }
  const std::vector<char>& fixed_output_points() const { return out_fixed_; }
  const Edge_set& output_curve_edges() const { return out_curve_edges_; }
  const Remesh_triangle_tree<GeomTraits>& patch_tree(std::size_t p) const { return patch_trees_[p]; }
  // the regions the volume balance left out (convex bodies faceted coarsely)
  const std::vector<std::size_t>& regions_not_balanced() const { return not_balanced_; }

private:
  double line_size(const Remesh_line& line, const Point_3& x) const
  {
    double h = std::numeric_limits<double>::infinity();
    for(std::size_t p : line.patches) h = (std::min)(h, sizing_(x, p));
    return h;
  }

  void add_chart(std::size_t patch, const std::vector<std::size_t>& triangles)
  {
    Remesh_chart<GeomTraits> chart;
    chart.patch = patch;
    chart.triangles = triangles;
    set_chart_frame(in_, chart);
    charts_.push_back(chart);
  }

  void make_charts()
  {
    for(std::size_t p = 0; p < in_.number_of_patches(); ++p)
    {
      if(features_.patch_triangles[p].empty()) continue;
      std::vector<std::vector<std::size_t> > groups = grow_charts(in_, features_.patch_triangles[p], et_, set_.chart_angle);
      std::vector<std::vector<std::size_t> > todo(groups.rbegin(), groups.rend());
      std::size_t guard = 0;
      while(!todo.empty())
      {
        std::vector<std::size_t> g = todo.back();
        todo.pop_back();
        Remesh_chart<GeomTraits> chart;
        chart.patch = p;
        chart.triangles = g;
        set_chart_frame(in_, chart);
        if(g.size() > 1 && ++guard < 10000 && !is_valid_chart(in_, chart, et_, feature_edges_))
        {
          ++report_.number_of_chart_cuts;
          std::vector<std::vector<std::size_t> > parts = bisect_chart(in_, chart, et_);
          if(parts.size() > 1)
          {
            for(auto it = parts.rbegin(); it != parts.rend(); ++it) todo.push_back(*it);
            continue;
          }
        }
        charts_.push_back(chart);
      }
    }
    index_charts();
  }

  void index_charts()
  {
    chart_of_triangle_.assign(in_.number_of_triangles(), std::size_t(-1));
    for(std::size_t c = 0; c < charts_.size(); ++c)
      for(std::size_t t : charts_[c].triangles) chart_of_triangle_[t] = c;
    chart_trees_.clear();
    for(std::size_t c = 0; c < charts_.size(); ++c) chart_trees_.emplace_back(in_, charts_[c].triangles);
  }

  void cut_chart(std::size_t c)
  {
    ++report_.number_of_chart_cuts;
    std::vector<std::vector<std::size_t> > parts = bisect_chart(in_, charts_[c], et_);
    const std::size_t patch = charts_[c].patch;
    if(parts.size() < 2) return;
    charts_[c].triangles = parts[0];
    set_chart_frame(in_, charts_[c]);
    for(std::size_t i = 1; i < parts.size(); ++i) add_chart(patch, parts[i]);
    index_charts();
  }

  // (chart, number of its triangles) on an input edge
  std::vector<std::pair<std::size_t, std::size_t> > edge_charts(std::size_t a, std::size_t b) const
  {
    std::map<std::size_t, std::size_t> count;
    for(std::size_t t : et_.at(edge_key(a, b))) ++count[chart_of_triangle_[t]];
    return std::vector<std::pair<std::size_t, std::size_t> >(count.begin(), count.end());
  }

  void make_lines()
  {
    lines_.clear();
    for(const Model_features::Curve& c : features_.curves)
    {
      Remesh_line line;
      line.points = c.points;
      line.is_curve = true;
      line.patches = c.patches;
      lines_.push_back(line);
    }
    // seams: edges between two triangles of one patch in different charts
    std::vector<std::pair<std::size_t, std::size_t> > seam_edges;
    for(const auto& e : et_)
    {
      const std::vector<std::size_t>& ts = e.second;
      if(ts.size() != 2 || feature_edges_.count(e.first)) continue;
      if(in_.patch_of_triangle(ts[0]) != in_.patch_of_triangle(ts[1])) continue;
      if(chart_of_triangle_[ts[0]] == chart_of_triangle_[ts[1]]) continue;
      seam_edges.push_back(e.first);
    }
    std::sort(seam_edges.begin(), seam_edges.end());
    on_seam_.assign(in_.number_of_points(), 0);
    std::map<std::size_t, std::vector<std::size_t> > adjacent;
    for(const auto& e : seam_edges)
    {
      adjacent[e.first].push_back(e.second);
      adjacent[e.second].push_back(e.first);
      on_seam_[e.first] = on_seam_[e.second] = 1;
    }
    auto chart_pair = [&](std::size_t a, std::size_t b) {
      std::vector<std::pair<std::size_t, std::size_t> > ec = edge_charts(a, b);
      return ec;
    };
    auto is_end = [&](std::size_t v) {
      const std::vector<std::size_t>& nb = adjacent[v];
      if(nb.size() != 2 || point_on_feature_[v]) return true;
      return chart_pair(v, nb[0]) != chart_pair(v, nb[1]);
    };
    Edge_set used;
    auto walk = [&](std::size_t start, std::size_t next) {
      Remesh_line line;
      line.is_curve = false;
      line.points.push_back(start);
      std::size_t prev = start, cur = next;
      used[edge_key(prev, cur)] = 1;
      for(;;)
      {
        line.points.push_back(cur);
        if(cur == start || is_end(cur)) break;
        const std::vector<std::size_t>& nb = adjacent[cur];
        const std::size_t nx = (nb[0] == prev) ? nb[1] : nb[0];
        prev = cur;
        cur = nx;
        used[edge_key(prev, cur)] = 1;
      }
      line.patch = in_.patch_of_triangle(et_.at(edge_key(line.points[0], line.points[1]))[0]);
      line.patches.push_back(line.patch);
      lines_.push_back(line);
    };
    for(auto& a : adjacent)
    {
      if(!is_end(a.first)) continue;
      std::vector<std::size_t> nb = a.second;
      std::sort(nb.begin(), nb.end());
      for(std::size_t w : nb)
        if(!used.count(edge_key(a.first, w))) walk(a.first, w);
    }
    for(auto& a : adjacent)
    {
      std::vector<std::size_t> nb = a.second;
      std::sort(nb.begin(), nb.end());
      for(std::size_t w : nb)
        if(!used.count(edge_key(a.first, w))) walk(a.first, w);
    }
  }

  // A piece of a line between two kept points (indices into the line's
  // points), and the positions sampled on it.
  struct Line_piece
  {
    std::size_t first = 0, last = 0;
    std::vector<Polyline_position> samples;
  };

  /*
  Two curves of one patch closer than their spacing - the sides of a thin
  layer where it meets the model's walls, a fault strip - are sampled alike,
  so their points face each other across the strip (or drift in and out of
  facing when their counts differ). Across a width w under t s, with s the
  spacing and t the tangent of the angle bound, facing points make
  triangles under the bound (atan(w / s)); from t s / 2 up, points of one
  side half-way between those of the other make triangles that reach it
  (atan(2 w / s)). Nearer (a ribbon pinching out) that would not help, and
  such strips are left as they are (the sizing field's strip rule makes
  the spacing of a thin layer's sides 3.5 times their width, so that they
  are not). Line by line, in each curve piece, the other curve of a common
  patch with points nearest to most samples is the piece's partner; where
  the partner's points at such a width from the piece follow each other at
  most two spacings apart (three or more, or all along the piece), the
  piece's samples there go half-way between them
  (interleave_polyline_samples()). A strip narrows and widens along its
  sides, and the strip rule grades their spacing with it: s is the
  partner's own gap about each of its points, not a mean over the piece
  (which left many points of a layer widening from 0.05 to 0.25 facing
  each other). The partner's points must stay where
  they are: kept points, or samples of a line before this one that was not
  moved, so that of two sides of a strip one moves.
  */
  std::size_t stagger_strip_sides(const std::vector<std::vector<Point_3> >& line_points,
                                  std::vector<std::vector<Line_piece> >& pieces) const
  {
    const double t = std::tan(set_.angle_bound * CGAL_PI / 180.);
    const std::size_t kept_point = std::size_t(-1);
    std::vector<Point_3> points;
    std::vector<std::size_t> owner_line, owner_piece; // owner_piece: kept_point for a piece's end
    std::vector<std::vector<std::vector<Point_3> > > positions(lines_.size());
    for(std::size_t l = 0; l < lines_.size(); ++l)
    {
      if(!lines_[l].is_curve) continue;
      const std::vector<Point_3>& pts = line_points[l];
      for(std::size_t k = 0; k < pieces[l].size(); ++k)
      {
        const Line_piece& piece = pieces[l][k];
        std::vector<Point_3> x(1, pts[piece.first]);
        for(const Polyline_position& p : piece.samples) x.push_back(point_on_polyline(pts, p));
        x.push_back(pts[piece.last]);
        for(std::size_t j = 0; j < x.size(); ++j)
        {
          points.push_back(x[j]);
          owner_line.push_back(l);
          owner_piece.push_back((j == 0 || j + 1 == x.size()) ? kept_point : k);
        }
        positions[l].push_back(x);
      }
    }
    const Point_index_tree<GeomTraits> tree(points);
    auto share_patch = [&](std::size_t a, std::size_t b) {
      for(std::size_t p : lines_[a].patches)
        if(std::find(lines_[b].patches.begin(), lines_[b].patches.end(), p) != lines_[b].patches.end()) return true;
      return false;
    };
    std::size_t staggered = 0;
    std::vector<std::vector<char> > moved(lines_.size());
    std::vector<std::size_t> found;
    for(std::size_t l = 0; l < lines_.size(); ++l)
    {
      moved[l].assign(pieces[l].size(), 0);
      if(!lines_[l].is_curve) continue;
      const std::vector<Point_3>& pts = line_points[l];
      for(std::size_t k = 0; k < pieces[l].size(); ++k)
      {
        const Line_piece& piece = pieces[l][k];
        const std::vector<Point_3>& x = positions[l][k];
        const std::size_t m = x.size() - 2;
        if(m == 0) continue;
        const Polyline_arc_length<Point_3> arc(pts, piece.first, piece.last);
        const double length = arc.total();
        // the samples' arc lengths, and the spacing about an arc length: the
        // gap between the samples around it (a strip's sides are graded along
        // it, as the strip narrows and widens)
        std::vector<double> at(1, 0.);
        for(const Polyline_position& p : piece.samples) at.push_back(arc.arc_length_at(p));
        at.push_back(length);
        auto spacing_at = [&](double a) {
          const std::size_t g = std::size_t((std::min)(
            std::ptrdiff_t(at.size()) - 2,
            (std::max)(std::ptrdiff_t(0), std::ptrdiff_t(std::upper_bound(at.begin(), at.end(), a) - at.begin()) - 1)));
          return at[g + 1] - at[g];
        };
        // the points of other curves of a common patch near the samples, that stay where they are
        std::vector<std::size_t> near;
        std::map<std::size_t, std::size_t> samples_near; // other line -> samples with a point of it near
        for(std::size_t j = 1; j <= m; ++j)
        {
          tree.points_in_ball(x[j], (std::max)(at[j] - at[j - 1], at[j + 1] - at[j]), found);
          std::set<std::size_t> lines_here;
          for(std::size_t q : found)
          {
            const std::size_t other = owner_line[q];
            if(other == l || points[q] == x.front() || points[q] == x.back()) continue;
            if(owner_piece[q] != kept_point && (other > l || moved[other][owner_piece[q]])) continue;
            if(!share_patch(l, other)) continue;
            near.push_back(q);
            lines_here.insert(other);
          }
          for(std::size_t other : lines_here) ++samples_near[other];
        }
        std::size_t partner = 0, votes = 0;
        for(const auto& v : samples_near)
          if(v.second > votes) { partner = v.first; votes = v.second; }
        if(votes == 0) continue;
        std::sort(near.begin(), near.end());
        near.erase(std::unique(near.begin(), near.end()), near.end());
        std::vector<Point_3> facing;
        for(std::size_t q : near)
          if(owner_line[q] == partner) facing.push_back(points[q]);
        // across the strip, away from the piece's ends (a point near an end is
        // the other side's corner, or would leave a tiny edge there); the
        // spacing about a facing point is the partner's own, the mean gap to
        // its neighbours (the partner's sides are graded along a strip that
        // narrows and widens)
        std::vector<std::pair<double, double> > across = project_on_polyline(pts, piece.first, piece.last, facing);
        std::sort(across.begin(), across.end());
        std::vector<double> arcs, spacings;
        for(std::size_t i = 0; i < across.size(); ++i)
        {
          double s = 0., gaps = 0.;
          if(i > 0) { s += across[i].first - across[i - 1].first; ++gaps; }
          if(i + 1 < across.size()) { s += across[i + 1].first - across[i].first; ++gaps; }
          s = gaps > 0. ? s / gaps : spacing_at(across[i].first);
          const double a = across[i].first, w = across[i].second;
          if(w >= 0.5 * t * s && w < t * s && a > 0.6 * s && a < length - 0.6 * s)
          {
            arcs.push_back(a);
            spacings.push_back(s);
          }
        }
        // runs of points at most two spacings apart: where the strip runs along the piece
        for(std::size_t i = 0; i < arcs.size();)
        {
          std::size_t j = i + 1;
          while(j < arcs.size() && arcs[j] - arcs[j - 1] <= 2. * spacings[j - 1]) ++j;
          const std::vector<double> run(arcs.begin() + std::ptrdiff_t(i), arcs.begin() + std::ptrdiff_t(j));
          const double s_front = spacings[i], s_back = spacings[j - 1];
          const bool whole = run.front() <= 2. * s_front && length - run.back() <= 2. * s_back;
          if(run.size() >= 3 || whole)
          {
            // (the samples kept around the run at the smaller of the two sides' spacings there)
            pieces[l][k].samples = interleave_polyline_samples(
              pts, piece.first, piece.last, pieces[l][k].samples, run,
              0.75 * (std::min)(s_front, spacing_at(run.front())), 0.75 * (std::min)(s_back, spacing_at(run.back())));
            moved[l][k] = 1;
          }
          i = j;
        }
        staggered += moved[l][k];
      }
    }
    return staggered;
  }

  void resample_lines()
  {
    const double curve_tolerance = set_.curve_distance * sizing_.diagonal();
    out_points_.clear();
    out_fixed_.clear();
    out_curve_edges_.clear();
    curve_samples_.clear();
    std::map<std::size_t, std::size_t> kept; // input point -> output point
    auto keep = [&](std::size_t v) {
      auto it = kept.find(v);
      if(it != kept.end()) return it->second;
      out_points_.push_back(in_.point(v));
      out_fixed_.push_back(1);
      kept[v] = out_points_.size() - 1;
      return out_points_.size() - 1;
    };
    // kept points: ends, turns beyond the tolerance, and (on curves) where a seam ends
    for(Remesh_line& line : lines_)
    {
      const std::size_t n = line.points.size();
      line.essential.assign(n, 0);
      line.essential[0] = line.essential[n - 1] = 1;
      std::vector<Point_3> pts;
      for(std::size_t v : line.points) pts.push_back(in_.point(v));
      if(line.is_curve)
      {
        for(std::size_t i = 1; i + 1 < n; ++i)
          if(on_seam_[line.points[i]]) line.essential[i] = 1;
        std::size_t last = 0;
        for(std::size_t i = 1; i < n; ++i)
          if(line.essential[i])
          {
            mark_essential_vertices(pts, last, i, curve_tolerance, line.essential);
            last = i;
          }
      }
      else
      {
        // seams are not features: straighten them to a fifth of the size
        const double tol = 0.2 * sizing_.patch_size(line.patch);
        mark_essential_vertices(pts, 0, n - 1, tol, line.essential);
      }
      if(line.is_curve)
      {
        // a short span between kept points fixes the local size
        std::size_t last = 0;
        for(std::size_t i = 1; i < n; ++i)
          if(line.essential[i])
          {
            const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(pts[last], pts[i])));
            const double h = (std::min)(line_size(line, pts[last]), line_size(line, pts[i]));
            if(l < 0.7 * h)
            {
              sizing_.add_size_constraint(pts[last], l);
              sizing_.add_size_constraint(pts[i], l);
            }
            last = i;
          }
      }
    }
    // the pieces between kept points, sampled
    std::vector<std::vector<Point_3> > line_points(lines_.size());
    std::vector<std::vector<Line_piece> > pieces(lines_.size());
    for(std::size_t l = 0; l < lines_.size(); ++l)
    {
      const Remesh_line& line = lines_[l];
      std::vector<Point_3>& pts = line_points[l];
      for(std::size_t v : line.points) pts.push_back(in_.point(v));
      std::size_t last = 0;
      for(std::size_t i = 1; i < line.points.size(); ++i)
      {
        if(!line.essential[i]) continue;
        Line_piece piece;
        piece.first = last;
        piece.last = i;
        piece.samples = sample_polyline_piece(pts, last, i, [&](const Point_3& x) { return line_size(line, x); });
        pieces[l].push_back(piece);
        last = i;
      }
    }
    report_.number_of_staggered_curve_pieces = stagger_strip_sides(line_points, pieces);
    for(std::size_t l = 0; l < lines_.size(); ++l)
    {
      Remesh_line& line = lines_[l];
      const std::vector<Point_3>& pts = line_points[l];
      line.out_points.clear();
      line.out_span.clear();
      line.span_charts.clear();
      line.out_points.push_back(keep(line.points[0]));
      for(const Line_piece& piece : pieces[l])
      {
        const std::size_t last = piece.first, i = piece.last;
        const std::size_t span = line.span_charts.size();
        line.span_charts.push_back(edge_charts(line.points[last], line.points[last + 1]));
        for(const Polyline_position& s : piece.samples)
        {
          out_points_.push_back(point_on_polyline(pts, s));
          out_fixed_.push_back(1);
          if(line.is_curve) curve_samples_.insert(out_points_.size() - 1);
          line.out_points.push_back(out_points_.size() - 1);
          line.out_span.push_back(span);
        }
        line.out_points.push_back(keep(line.points[i]));
        line.out_span.push_back(span);
      }
      if(line.is_curve)
        for(std::size_t k = 0; k + 1 < line.out_points.size(); ++k)
          out_curve_edges_[edge_key(line.out_points[k], line.out_points[k + 1])] = 1;
    }
    report_.number_of_kept_curve_points = kept.size();
    number_of_line_points_ = out_points_.size();
    // points on seams are free in the 3D clean-up: only curve points stay
    out_fixed_.assign(out_points_.size(), 0);
    for(const Remesh_line& line : lines_)
      if(line.is_curve)
        for(std::size_t v : line.out_points) out_fixed_[v] = 1;
    std::size_t on_curves = 0;
    for(char f : out_fixed_) on_curves += f;
    report_.number_of_curve_points = on_curves;
  }

  void triangulate_charts(std::vector<std::size_t>& failed)
  {
    out_points_.resize(number_of_line_points_);
    out_fixed_.resize(number_of_line_points_);
    patch_out_.assign(in_.number_of_patches(), std::vector<Triangle>());
    // the segments of each chart: (output a, output b, chart triangles on it)
    std::vector<std::vector<std::array<std::size_t, 3> > > chart_segments(charts_.size());
    for(const Remesh_line& line : lines_)
      for(std::size_t k = 0; k + 1 < line.out_points.size(); ++k)
        for(const auto& cc : line.span_charts[line.out_span[k]])
          chart_segments[cc.first].push_back(
            std::array<std::size_t, 3>{{line.out_points[k], line.out_points[k + 1], cc.second}});

    typename Chart_triangulator<GeomTraits, Patch_size>::Parameters param;
    param.angle_bound = set_.angle_bound;
    param.relaxation_steps = set_.relaxation_steps;
    param.population_rounds = set_.population_rounds;
    param.bubbles = (set_.method == Surface_remeshing_method::BUBBLES);
    // The charts are triangulated independently (their boundaries, the
    // resampled lines, are fixed), in parallel if asked; the results are
    // appended in chart order, so the output does not depend on the threads.
    struct Chart_result
    {
      bool failed = false;
      std::vector<std::size_t> ids;  // output indices of the chart's line points
      std::vector<Point_3> points;   // those points, then the new ones
      std::vector<std::array<std::size_t, 3> > triangles; // local indices
    };
    std::vector<Chart_result> results(charts_.size());
    auto triangulate = [&](std::size_t c) {
      Chart_result& result = results[c];
      // local numbering: the chart's line points in increasing output order
      std::vector<std::size_t>& ids = result.ids;
      for(const auto& s : chart_segments[c])
      {
        ids.push_back(s[0]);
        ids.push_back(s[1]);
      }
      std::sort(ids.begin(), ids.end());
      ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
      std::map<std::size_t, std::size_t> local;
      std::vector<Point_3> pts;
      for(std::size_t i = 0; i < ids.size(); ++i)
      {
        local[ids[i]] = i;
        pts.push_back(out_points_[ids[i]]);
      }
      std::vector<std::array<std::size_t, 3> > segs;
      for(const auto& s : chart_segments[c]) segs.push_back(std::array<std::size_t, 3>{{local[s[0]], local[s[1]], s[2]}});
      const Patch_size size(sizing_, charts_[c].patch);
      Chart_triangulator<GeomTraits, Patch_size> tri(in_, charts_[c], chart_trees_[c], patch_trees_[charts_[c].patch], size,
                                                     param);
      if(pts.size() < 3 || !tri.set_boundary(pts, segs))
      {
        result.failed = true;
        return;
      }
      tri.run();
      result.points = tri.points();
      result.triangles.assign(tri.triangles().begin(), tri.triangles().end());
    };
    auto each = [&](std::size_t first, std::size_t last) {
      for(std::size_t c = first; c < last; ++c) triangulate(c);
    };
    if(set_.parallel) for_each_block<CGAL::Parallel_tag>(charts_.size(), 1, each);
    else each(0, charts_.size());
    for(std::size_t c = 0; c < charts_.size(); ++c)
    {
      Chart_result& result = results[c];
      if(result.failed)
      {
        failed.push_back(c);
        continue;
      }
      const std::vector<std::size_t>& ids = result.ids;
      std::vector<std::size_t> global(result.points.size());
      for(std::size_t i = 0; i < ids.size(); ++i) global[i] = ids[i];
      for(std::size_t i = ids.size(); i < result.points.size(); ++i)
      {
        out_points_.push_back(result.points[i]);
        out_fixed_.push_back(0);
        global[i] = out_points_.size() - 1;
      }
      for(const auto& t : result.triangles)
        patch_out_[charts_[c].patch].push_back(Triangle{{global[t[0]], global[t[1]], global[t[2]]}});
      result = Chart_result();
    }
    report_.number_of_charts = charts_.size();
  }

  void improve_patches()
  {
    for(std::size_t p = 0; p < patch_out_.size(); ++p)
    {
      if(patch_out_[p].empty()) continue;
      if(set_.method == Surface_remeshing_method::ISOTROPIC)
      {
        const Patch_size size(sizing_, p);
        double target = 0.;
        isotropic_remesh_patch<GeomTraits>(out_points_, patch_out_[p], out_fixed_, out_curve_edges_, patch_trees_[p],
                                           size, 5, target);
        out_fixed_.resize(out_points_.size(), 0);
        continue;
      }
      for(int round = 0; round < 3; ++round)
      {
        for(int pass = 0; pass < 4; ++pass)
        {
          const std::size_t flips = flip_to_improve_angles(out_points_, patch_out_[p], out_curve_edges_, 30.);
          const std::size_t moves = smooth_free_vertices<GeomTraits>(out_points_, patch_out_[p], out_fixed_,
                                                                     patch_trees_[p], set_.angle_bound + 5.);
          if(flips == 0 && moves == 0) break;
        }
        const std::size_t collapses =
          collapse_crowded_vertices(out_points_, patch_out_[p], out_fixed_, Patch_size(sizing_, p),
                                    [&](const Point_3& q) { return patch_trees_[p].closest_point(q); }, set_.angle_bound);
        report_.number_of_collapsed_points += collapses;
        if(collapses == 0) break;
      }
      report_.number_of_split_curve_triangles += split_fixed_triangles<GeomTraits>(
        out_points_, patch_out_[p], out_fixed_, out_curve_edges_, patch_trees_[p], set_.angle_bound);
      flip_to_improve_angles(out_points_, patch_out_[p], out_curve_edges_, 30.);
    }
  }

  // A triangle under the angle bound with its three points on curves (where
  // two curves' samples meet at a corner out of step, a strip's end) is beyond
  // the flips and moves of the free points. A curve sample of such a triangle
  // slides along its input curve, between its neighbours there, to where the
  // smallest angle of its triangles (in every patch along the curve) is the
  // largest, no triangle turning over: it stays on the curve, so the curves
  // are kept as they were.
  void slide_curve_samples()
  {
    const double bound = set_.angle_bound;
    std::map<std::size_t, std::vector<std::pair<std::size_t, std::size_t> > > incident; // sample -> (patch, triangle)
    for(std::size_t p = 0; p < patch_out_.size(); ++p)
      for(std::size_t i = 0; i < patch_out_[p].size(); ++i)
        for(std::size_t v : patch_out_[p][i])
          if(curve_samples_.count(v)) incident[v].push_back(std::make_pair(p, i));
    // the unit normals of v's triangles where v is now, and the side each
    // patch along the curve faces around v (their sum there): what
    // keeps_facing_star() compares a move with, taken once per sample
    std::vector<Vector_3> before;
    std::map<std::size_t, Vector_3> star; // patch -> the side it faces around v
    auto take_star = [&](std::size_t v) {
      before.clear();
      star.clear();
      for(const auto& pi : incident[v])
      {
        const Triangle& t = patch_out_[pi.first][pi.second];
        before.push_back(remesh_unit_normal(out_points_[t[0]], out_points_[t[1]], out_points_[t[2]]));
        auto at = star.emplace(pi.first, NULL_VECTOR).first;
        at->second = at->second + before.back();
      }
    };
    // the smallest angle of v's triangles with v at q, or -1 if one turns over
    // (after take_star(v)); `under`: how many of them are under the bound
    auto worst_at = [&](std::size_t v, const Point_3& q, std::size_t& under) {
      double worst = 180.;
      under = 0;
      const auto& around = incident[v];
      for(std::size_t i = 0; i < around.size(); ++i)
      {
        const Triangle& t = patch_out_[around[i].first][around[i].second];
        std::array<Point_3, 3> moved;
        for(int k = 0; k < 3; ++k) moved[k] = t[k] == v ? q : out_points_[t[k]];
        if(!keeps_facing_star(remesh_unit_normal(moved[0], moved[1], moved[2]), before[i], star[around[i].first]))
          return -1.;
        const double a = min_angle_degrees(moved[0], moved[1], moved[2]);
        worst = (std::min)(worst, a);
        if(a < bound) ++under;
      }
      return worst;
    };
    for(int pass = 0; pass < 3; ++pass)
    {
      std::size_t slid = 0;
      for(const Remesh_line& line : lines_)
      {
        if(!line.is_curve || line.out_points.size() < 3) continue;
        std::vector<Point_3> pts;
        for(std::size_t v : line.points) pts.push_back(in_.point(v));
        const Polyline_arc_length<Point_3> arc(pts, 0, pts.size() - 1);
        for(std::size_t k = 1; k + 1 < line.out_points.size(); ++k)
        {
          const std::size_t v = line.out_points[k];
          if(!curve_samples_.count(v)) continue;
          std::size_t under_now = 0, under = 0;
          take_star(v);
          const double now = worst_at(v, out_points_[v], under_now);
          if(!(now < bound)) continue;
          // arc lengths of the neighbours (the line's ends at 0 and its length: a closed line starts where it ends)
          const std::vector<std::pair<double, double> > at = project_on_polyline(
            pts, 0, pts.size() - 1, std::vector<Point_3>{out_points_[line.out_points[k - 1]], out_points_[line.out_points[k + 1]]});
          const double a0 = k == 1 ? 0. : at[0].first, a1 = k + 2 == line.out_points.size() ? arc.total() : at[1].first;
          if(!(a1 > a0)) continue;
          double best = now;
          Point_3 best_q = out_points_[v];
          for(int j = 1; j < 16; ++j)
          {
            const Point_3 q = point_on_polyline(pts, arc.position_at(a0 + (a1 - a0) * double(j) / 16.));
            const double w = worst_at(v, q, under);
            // (no more triangles under the bound: raising the worst one must not pull others under)
            if(w > best && under <= under_now)
            {
              best = w;
              best_q = q;
            }
          }
          if(best > now + 1e-6)
          {
            out_points_[v] = best_q;
            ++slid;
          }
        }
      }
      report_.number_of_slid_curve_points += slid;
      if(slid == 0) break;
    }
  }

  // Free points slide along the input patches until every region has its
  // input volume again (internal/remesh_volume_balance.h). Before the snap to
  // axis planes: on a flat wall the points have nothing to trade and stay.
  void balance_volumes()
  {
    Real_timer timer;
    timer.start();
    std::vector<std::pair<std::size_t, std::size_t> > sides;
    for(std::size_t p = 0; p < in_.number_of_patches(); ++p)
      sides.emplace_back(in_.patch(p).negative_region, in_.patch(p).positive_region);
    auto project = [&](const Point_3& q, std::size_t p) {
      const auto on = patch_trees_[p].closest_point_and_triangle(q);
      const auto& tri = in_.triangle(on.second);
      return std::make_pair(on.first, remesh_unit_normal(in_.point(tri[0]), in_.point(tri[1]), in_.point(tri[2])));
    };
    auto size = [&](const Point_3& q, std::size_t p) { return sizing_(q, p); };
    const std::vector<double> target = region_volumes(in_);
    std::vector<char> balanced(target.size(), 1);
    balanced[0] = 0;
    // A region whose chords all cut into it (a convex body faceted coarsely: a
    // tunnel, a dome) cannot get its volume back by slides, only lose less of
    // it by points crowding onto its creases, at the cost of the mesh there.
    // Such regions are left out and the others balanced again from the
    // chords; after three failures no point moves. A region none of whose
    // points may move is left out at once, without a new attempt: the
    // balance already left it as it is.
    const double converged = 1e-7;
    const std::vector<Point_3> chords = out_points_;
    std::vector<char> fixed = out_fixed_;
    for(std::size_t p = 0; p < set_.unbalanced_patches.size() && p < patch_out_.size(); ++p)
      if(set_.unbalanced_patches[p])
        for(const Triangle& t : patch_out_[p])
          for(std::size_t v : t) fixed[v] = 1;
    Volume_balance_result balance;
    for(int attempt = 0;; ++attempt)
    {
      balance = balance_region_volumes(out_points_, patch_out_, fixed, sides, target, balanced, box_centre(in_),
                                       project, size, set_.angle_bound);
      if(attempt == 0) report_.volume_error_before_balancing = balance.error_before;
      // a region none of whose points may move is left out as it is (unless its volume is right)
      for(std::size_t r = 1; r < balanced.size(); ++r)
        if(balance.immovable[r] && balance.relative_errors[r] > converged) balanced[r] = 0;
      if(balance.residual_after <= converged) break;
      out_points_ = chords;
      for(std::size_t r = 1; r < balanced.size(); ++r)
        if(attempt == 2 || balance.residual_errors[r] > converged) balanced[r] = 0;
      balance = Volume_balance_result();
      if(attempt == 2) break;
    }
    report_.number_of_volume_balancing_steps = balance.iterations;
    report_.number_of_volume_balancing_points = balance.moved_points;
    report_.largest_volume_balancing_move = balance.largest_move;
    not_balanced_.clear();
    for(std::size_t r = 1; r < balanced.size(); ++r)
      if(!balanced[r]) not_balanced_.push_back(r);
    report_.regions_not_balanced = not_balanced_;
    report_.time_volume_balance = timer.time();
  }

  // A point projected onto an input triangle that lies in an axis plane (x,
  // y or z constant: most box walls) lands on it only up to rounding. A wall
  // whose points are an ulp off is no longer flat, and on the outer boundary
  // no point beyond it makes its facets Delaunay from outside: CloudSpin
  // re-meshed failed on one after 200 Steiner points on a triangle. Points of
  // a patch within a few ulps of one of its axis planes get the plane's
  // coordinate back.
  void snap_to_axis_planes()
  {
    typedef typename GeomTraits::FT FT;
    const std::vector<std::array<std::set<FT>, 3> > levels = internal::patch_axis_planes(in_);
    const double diagonal = bbox_diagonal(in_);
    for(std::size_t p = 0; p < patch_out_.size() && p < levels.size(); ++p)
      for(int k = 0; k < 3; ++k)
      {
        if(levels[p][k].empty()) continue;
        for(const Triangle& t : patch_out_[p])
          for(std::size_t v : t)
          {
            const Point_3& q = out_points_[v];
            std::array<FT, 3> c{{q.x(), q.y(), q.z()}};
            const auto it = internal::nearest_axis_plane(levels[p][k], c[k]);
            const double level = CGAL::to_double(*it);
            const double tolerance = 16. * std::numeric_limits<double>::epsilon() * (std::abs(level) + diagonal);
            if(c[k] == *it || !(std::abs(CGAL::to_double(c[k]) - level) <= tolerance)) continue;
            c[k] = *it;
            out_points_[v] = Point_3(c[0], c[1], c[2]);
          }
      }
  }

  void build_output(Model& output)
  {
    output = Model();
    for(std::size_t r = 1; r < in_.regions().size(); ++r) output.add_region(in_.region(r).name);
    for(std::size_t p = 0; p < in_.number_of_patches(); ++p)
      output.add_patch(in_.patch(p).name, in_.patch(p).positive_region, in_.patch(p).negative_region);
    // its triangles are new: an error about one must not read as if it were the input file's
    output.set_file_name(in_.file_name().empty() ? std::string() : in_.file_name() + " (re-meshed)");
    for(const Point_3& q : out_points_) output.add_point(q);
    for(std::size_t p = 0; p < patch_out_.size(); ++p)
      for(const Triangle& t : patch_out_[p]) output.add_triangle(t[0], t[1], t[2], p);
    // renumbering would break the caller's view of curve points: keep unused points out instead
    std::vector<char> used(out_points_.size(), 0);
    for(const auto& tris : patch_out_)
      for(const Triangle& t : tris)
        for(std::size_t v : t) used[v] = 1;
    bool all_used = true;
    for(char u : used) all_used = all_used && u;
    if(!all_used)
    {
      std::vector<std::size_t> renumber(out_points_.size(), std::size_t(-1));
      std::size_t n = 0;
      for(std::size_t i = 0; i < used.size(); ++i)
        if(used[i]) renumber[i] = n++;
      for(Remesh_line& line : lines_)
        for(std::size_t& v : line.out_points) v = renumber[v];
      std::vector<Point_3> pts;
      std::vector<char> fixed;
      for(std::size_t i = 0; i < used.size(); ++i)
        if(used[i])
        {
          pts.push_back(out_points_[i]);
          fixed.push_back(out_fixed_[i]);
        }
      Edge_set edges;
      for(const auto& e : out_curve_edges_)
        if(used[e.first.first] && used[e.first.second])
          edges[edge_key(renumber[e.first.first], renumber[e.first.second])] = 1;
      out_curve_edges_.swap(edges);
      for(auto& tris : patch_out_)
        for(Triangle& t : tris)
          for(std::size_t& v : t) v = renumber[v];
      out_points_.swap(pts);
      out_fixed_.swap(fixed);
      output.remove_unused_points();
    }
  }

  struct Patch_size
  {
    Patch_size(const Remeshing_sizing_field<GeomTraits>& s, std::size_t p) : sizing(&s), patch(p) {}
    double operator()(const Point_3& x) const { return (*sizing)(x, patch); }
    const Remeshing_sizing_field<GeomTraits>* sizing;
    std::size_t patch;
  };

  const Model& in_;
  const Model_features& features_;
  Remeshing_sizing_field<GeomTraits>& sizing_;
  std::vector<std::size_t> not_balanced_;
  Settings set_;
  Surface_remeshing_report& report_;
  Edge_triangles_map et_;
  Edge_set feature_edges_;
  std::vector<char> point_on_feature_, on_seam_;
  std::vector<Remesh_triangle_tree<GeomTraits> > patch_trees_, chart_trees_;
  std::vector<Remesh_chart<GeomTraits> > charts_;
  std::vector<std::size_t> chart_of_triangle_;
  std::vector<Remesh_line> lines_;
  std::vector<Point_3> out_points_;
  std::vector<char> out_fixed_;
  Edge_set out_curve_edges_;
  std::set<std::size_t> curve_samples_; // output points sampled on curves (not kept input points)
  std::size_t number_of_line_points_ = 0;
  std::vector<std::vector<Triangle> > patch_out_;
};

// an output curve point where a patch's sector between two curve edges is
// under the angle bound, with the other ends of those edges
struct Sharp_sector
{
  std::size_t tip, patch, side0, side1;
  double angle; // the patch's angle at the tip, degrees
};

// The triangles (sorted, each with the smallest angle of the sectors whose
// wedge holds it) of a sharp sector's patch whose three points lie on
// the sector's wedge: its tip and its two sides, each followed along the
// curve from the tip until a point where other curves meet it, or where it
// turns back (the other tip of a lens), with a point on each side.
template <class GeomTraits>
std::vector<std::pair<std::size_t, double> > triangles_in_sharp_wedges(const Geological_model_3<GeomTraits>& output,
                                                                      const Edge_set& curve_edges,
                                                                      const std::vector<Sharp_sector>& sectors)
{
  if(sectors.empty()) return std::vector<std::pair<std::size_t, double> >();
  std::map<std::size_t, std::vector<std::size_t> > next; // curve point -> its curve neighbours
  for(const auto& e : curve_edges)
  {
    next[e.first.first].push_back(e.first.second);
    next[e.first.second].push_back(e.first.first);
  }
  // (point, wedge) -> 0 at the tip, 1 or 2 on a side
  std::map<std::size_t, std::vector<std::pair<std::size_t, int> > > on_wedge;
  for(std::size_t s = 0; s < sectors.size(); ++s)
  {
    const Sharp_sector& w = sectors[s];
    on_wedge[w.tip].push_back(std::make_pair(s, 0));
    for(int side = 1; side <= 2; ++side)
    {
      std::size_t prev = w.tip, cur = side == 1 ? w.side0 : w.side1;
      std::set<std::size_t> seen{w.tip};
      while(seen.insert(cur).second)
      {
        on_wedge[cur].push_back(std::make_pair(s, side));
        const std::vector<std::size_t>& n = next[cur];
        if(n.size() != 2) break;
        const std::size_t after = n[0] == prev ? n[1] : n[0];
        const auto in = output.point(cur) - output.point(prev), out = output.point(after) - output.point(cur);
        if(in * out < 0.) break; // turns back
        prev = cur;
        cur = after;
      }
    }
  }
  std::vector<std::pair<std::size_t, double> > result;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
  {
    const auto& tri = output.triangle(t);
    const auto i0 = on_wedge.find(tri[0]);
    if(i0 == on_wedge.end()) continue;
    double angle = std::numeric_limits<double>::infinity(); // the sharpest wedge it lies in
    for(const auto& m0 : i0->second)
    {
      if(sectors[m0.first].patch != output.patch_of_triangle(t)) continue;
      // (a lens's far tip lies on both sides)
      int sides = 0, found = 0;
      for(std::size_t v : tri)
      {
        const auto iv = on_wedge.find(v);
        if(iv == on_wedge.end()) break;
        bool on = false;
        for(const auto& m : iv->second)
          if(m.first == m0.first)
          {
            on = true;
            sides |= m.second == 0 ? 3 : m.second;
          }
        found += on ? 1 : 0;
      }
      if(found == 3 && sides == 3) angle = (std::min)(angle, sectors[m0.first].angle);
    }
    if(angle < std::numeric_limits<double>::infinity()) result.push_back(std::make_pair(t, angle));
  }
  return result;
}

// the measures of the report that compare the output with the input
template <class GeomTraits>
void measure_remeshing(const Geological_model_3<GeomTraits>& input, const Geological_model_3<GeomTraits>& output,
                       const Model_features& features, const Remeshing_sizing_field<GeomTraits>& sizing,
                       const Surface_remesher<GeomTraits>& remesher, Surface_remeshing_report& report)
{
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Segment_3 Segment_3;
  const double diag = sizing.diagonal();
  const double bound = report.angle_bound;
  report.number_of_points = output.number_of_points();
  report.number_of_triangles = output.number_of_triangles();

  // angles, and which small angles the input forces (a narrow sector at a curve point)
  report.input_min_angle = 180.;
  std::size_t input_small = 0;
  for(std::size_t t = 0; t < input.number_of_triangles(); ++t)
  {
    const double a = triangle_min_angle(input, t);
    report.input_min_angle = (std::min)(report.input_min_angle, a);
    if(a < bound) ++input_small;
  }
  report.input_share_of_small_angle_triangles =
    input.number_of_triangles() ? double(input_small) / double(input.number_of_triangles()) : 0.;

  const std::vector<char>& fixed = remesher.fixed_output_points();
  const Edge_set& curve_edges = remesher.output_curve_edges();
  // angle of each output triangle at each corner
  auto corner_angle = [&](std::size_t t, int k) {
    const auto& tri = output.triangle(t);
    return internal::angle_degrees(output.point(tri[k]), output.point(tri[(k + 1) % 3]), output.point(tri[(k + 2) % 3]));
  };
  // the fan of triangles of one patch around a curve point, cut at curve edges
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t> > around; // (point, patch) -> triangles
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
    for(std::size_t v : output.triangle(t))
      if(v < fixed.size() && fixed[v]) around[std::make_pair(v, output.patch_of_triangle(t))].push_back(t);
  std::map<std::pair<std::size_t, std::size_t>, double> sector; // (triangle, point) -> sector angle
  std::vector<Sharp_sector> sharp_sectors;
  for(const auto& a : around)
  {
    const std::size_t v = a.first.first;
    const std::vector<std::size_t>& ts = a.second;
    std::vector<std::size_t> group(ts.size());
    for(std::size_t i = 0; i < ts.size(); ++i) group[i] = i;
    auto find = [&](std::size_t i) {
      while(group[i] != i) i = group[i] = group[group[i]];
      return i;
    };
    for(std::size_t i = 0; i < ts.size(); ++i)
      for(std::size_t j = i + 1; j < ts.size(); ++j)
      {
        // triangles sharing an edge at v that is not a curve edge are in one sector
        for(std::size_t w : output.triangle(ts[i]))
        {
          if(w == v) continue;
          const auto& tj = output.triangle(ts[j]);
          if(std::find(tj.begin(), tj.end(), w) != tj.end() && !curve_edges.count(edge_key(v, w)))
            group[find(i)] = find(j);
        }
      }
    std::map<std::size_t, double> sum;
    for(std::size_t i = 0; i < ts.size(); ++i)
    {
      const auto& tri = output.triangle(ts[i]);
      const int k = int(std::find(tri.begin(), tri.end(), v) - tri.begin());
      sum[find(i)] += corner_angle(ts[i], k);
    }
    for(std::size_t i = 0; i < ts.size(); ++i) sector[std::make_pair(ts[i], v)] = sum[find(i)];
    // a sharp sector's two curve edges at v start the sides of its wedge
    for(const auto& g : sum)
    {
      if(!(g.second < bound)) continue;
      std::vector<std::size_t> starts;
      for(std::size_t i = 0; i < ts.size(); ++i)
        if(find(i) == g.first)
          for(std::size_t w : output.triangle(ts[i]))
            if(w != v && curve_edges.count(edge_key(v, w)) &&
               std::find(starts.begin(), starts.end(), w) == starts.end())
              starts.push_back(w);
      if(starts.size() == 2) sharp_sectors.push_back(Sharp_sector{v, a.first.second, starts[0], starts[1], g.second});
    }
  }
  const std::vector<std::pair<std::size_t, double> > in_sharp_wedge =
    triangles_in_sharp_wedges(output, curve_edges, sharp_sectors);
  report.min_angle = 180.;
  report.number_of_small_angle_triangles = 0;
  report.number_of_forced_small_angle_triangles = 0;
  report.number_of_small_angle_triangles_between_curve_points = 0;
  report.number_of_small_angle_triangles_in_sharp_wedges = 0;
  report.small_angle_triangles_outside_sharp_wedges.clear();
  report.corner_forced_triangles.clear();
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
  {
    const double a = triangle_min_angle(output, t);
    report.min_angle = (std::min)(report.min_angle, a);
    if(a >= bound) continue;
    ++report.number_of_small_angle_triangles;
    bool all_fixed = true;
    for(std::size_t v : output.triangle(t)) all_fixed = all_fixed && v < fixed.size() && fixed[v];
    if(all_fixed) ++report.number_of_small_angle_triangles_between_curve_points;
    int k_min = 0;
    for(int k = 1; k < 3; ++k)
      if(corner_angle(t, k) < corner_angle(t, k_min)) k_min = k;
    const auto it = sector.find(std::make_pair(t, output.triangle(t)[k_min]));
    const bool forced = it != sector.end() && it->second < bound;
    if(forced) ++report.number_of_forced_small_angle_triangles;
    const auto w = std::lower_bound(in_sharp_wedge.begin(), in_sharp_wedge.end(),
                                    std::make_pair(t, -std::numeric_limits<double>::infinity()));
    const bool in_wedge = w != in_sharp_wedge.end() && w->first == t;
    if(forced || in_wedge)
    {
      ++report.number_of_small_angle_triangles_in_sharp_wedges;
      const double corner = (std::min)(forced ? it->second : 180., in_wedge ? w->second : 180.);
      Surface_remeshing_report::Corner_forced_triangle cf{t, corner, {}};
      for(int k = 0; k < 3; ++k)
      {
        const auto& q = output.point(output.triangle(t)[std::size_t(k)]);
        cf.points[std::size_t(k)] = {{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
      }
      report.corner_forced_triangles.push_back(cf);
    }
    else
      report.small_angle_triangles_outside_sharp_wedges.push_back(t);
  }
  report.share_of_small_angle_triangles =
    output.number_of_triangles() ? double(report.number_of_small_angle_triangles) / double(output.number_of_triangles())
                                 : 0.;

  // edge lengths against the field (the smaller target of the patches on the edge)
  auto edge_share = [&](const Geological_model_3<GeomTraits>& m, double* lo, double* hi) {
    std::map<std::pair<std::size_t, std::size_t>, double> target;
    for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
    {
      const auto& tri = m.triangle(t);
      for(int k = 0; k < 3; ++k)
      {
        const auto e = edge_key(tri[k], tri[(k + 1) % 3]);
        const double h = sizing(CGAL::midpoint(m.point(e.first), m.point(e.second)), m.patch_of_triangle(t));
        auto it = target.find(e);
        if(it == target.end()) target[e] = h;
        else it->second = (std::min)(it->second, h);
      }
    }
    std::size_t within = 0;
    double mn = std::numeric_limits<double>::infinity(), mx = 0.;
    for(const auto& e : target)
    {
      const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(m.point(e.first.first), m.point(e.first.second))));
      mn = (std::min)(mn, l);
      mx = (std::max)(mx, l);
      if(l >= 0.5 * e.second && l <= 1.5 * e.second) ++within;
    }
    if(lo) *lo = mn;
    if(hi) *hi = mx;
    return target.empty() ? 0. : double(within) / double(target.size());
  };
  report.share_of_edges_within_size = edge_share(output, &report.min_edge_length, &report.max_edge_length);
  report.input_share_of_edges_within_size = edge_share(input, nullptr, nullptr);

  // points and triangles against the input patch
  report.max_point_distance = 0.;
  report.max_triangle_distance = 0.;
  std::size_t beyond = 0;
  std::vector<char> seen(output.number_of_points(), 0);
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
  {
    const std::size_t p = output.patch_of_triangle(t);
    const Remesh_triangle_tree<GeomTraits>& tree = remesher.patch_tree(p);
    const auto& tri = output.triangle(t);
    for(std::size_t v : tri)
    {
      if(seen[v]) continue;
      seen[v] = 1;
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(output.point(v), tree.closest_point(output.point(v)))));
      report.max_point_distance = (std::max)(report.max_point_distance, d / diag);
    }
    const Point_3 &a = output.point(tri[0]), &b = output.point(tri[1]), &c = output.point(tri[2]);
    const Point_3 g = CGAL::centroid(a, b, c);
    const double h = sizing(g, p);
    double worst = 0.;
    const Point_3 samples[7] = {g, CGAL::midpoint(a, b), CGAL::midpoint(b, c), CGAL::midpoint(c, a),
                                CGAL::midpoint(g, a), CGAL::midpoint(g, b), CGAL::midpoint(g, c)};
    for(const Point_3& s : samples)
      worst = (std::max)(worst, std::sqrt(CGAL::to_double(CGAL::squared_distance(s, tree.closest_point(s)))));
    report.max_triangle_distance = (std::max)(report.max_triangle_distance, worst / h);
    if(worst > report.surface_distance * h) ++beyond;
  }
  report.share_of_triangles_beyond_distance =
    output.number_of_triangles() ? double(beyond) / double(output.number_of_triangles()) : 0.;

  // curves: symmetric distance between each output polyline and its input one, sampled
  typedef typename std::vector<Segment_3>::const_iterator Segment_iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GeomTraits, CGAL::AABB_segment_primitive<GeomTraits, Segment_iterator> > >
    Segment_tree;
  report.max_curve_distance = 0.;
  const std::vector<Remesh_line>& lines = remesher.lines();
  for(std::size_t c = 0; c < features.curves.size() && c < lines.size(); ++c)
  {
    std::vector<Segment_3> in_segs, out_segs;
    for(std::size_t i = 0; i + 1 < lines[c].points.size(); ++i)
      in_segs.push_back(Segment_3(input.point(lines[c].points[i]), input.point(lines[c].points[i + 1])));
    for(std::size_t i = 0; i + 1 < lines[c].out_points.size(); ++i)
      out_segs.push_back(Segment_3(output.point(lines[c].out_points[i]), output.point(lines[c].out_points[i + 1])));
    if(in_segs.empty() || out_segs.empty()) continue;
    Segment_tree in_tree(in_segs.begin(), in_segs.end()), out_tree(out_segs.begin(), out_segs.end());
    in_tree.accelerate_distance_queries();
    out_tree.accelerate_distance_queries();
    auto one_way = [&](const std::vector<Segment_3>& from, const Segment_tree& to) {
      double worst = 0.;
      for(const Segment_3& s : from)
        for(int k = 0; k <= 4; ++k)
        {
          const Point_3 x = s.source() + (s.target() - s.source()) * (double(k) / 4.);
          worst = (std::max)(worst, CGAL::to_double(to.squared_distance(x)));
        }
      return std::sqrt(worst);
    };
    const double d = (std::max)(one_way(in_segs, out_tree), one_way(out_segs, in_tree));
    report.max_curve_distance = (std::max)(report.max_curve_distance, d / diag);
  }

  report.input_volumes = region_volumes(input);
  report.output_volumes = region_volumes(output);
  report.max_relative_volume_error = 0.;
  for(std::size_t r = 1; r < report.input_volumes.size(); ++r)
    report.max_relative_volume_error =
      (std::max)(report.max_relative_volume_error, std::abs(report.relative_volume_change(r)));
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Re-meshes the surfaces of a geological model with bubbles, keeping its
geometry and its interfaces: `output` is a geological model like any input,
with the same regions and patches (names and sides) and new points and
triangles, so that placement, dynamics and tetrahedralization run on it
unchanged. Use it when the input triangles are poor (angles far below one
degree, lengths spread over orders of magnitude): tetrahedra next to such
triangles are poor whatever happens inside.

The method follows the original bubble meshing, level by level:
- <b>corners</b> (`detect_model_features()`) stay where they are;
- <b>curves</b> keep the input points they cannot drop without moving
  farther than `curve_distance` from the input polyline; between those,
  bubbles relax along the curve (1-D, cubic force law, radii from the
  `Remeshing_sizing_field`), so every curve point lies on an input segment;
  each curve is resampled once and its points are shared by all the patches
  that meet there, so interfaces stay conforming; where two curves of one
  patch run closer than a fraction of their spacing (a thin layer's side on
  the model's walls: a strip narrower than the re-meshing's floor), one
  curve's points move half-way between the other's, so that the strip is
  cut into isosceles triangles, not right ones with a tiny angle
  (`Surface_remeshing_report::number_of_staggered_curve_pieces`);
- <b>patches</b> are triangulated once each (a patch is shared by its two
  regions) with the curve points fixed on their boundary: every patch is
  flattened onto one plane, or cut into a few charts when it bends more than
  `chart_angle`; interior points come from a size refinement of the 2D
  constrained Delaunay triangulation, then move as surface bubbles (3D
  distances, cubic force law, each move lifted back onto the input patch
  and kept inside it), with population control by the overlap ratio, and
  circumcentres are added where an angle is still under
  `minimum_triangle_angle`; in 3D, edge flips and vertex moves projected
  onto the patch finish the job, and a point left crowded into a triangle
  under that angle is collapsed into a neighbour where that helps
  (`Surface_remeshing_report::number_of_collapsed_points`), a triangle
  under it between three curve samples gets a new point across an edge
  where that lifts the triangles around it over the angle
  (`Surface_remeshing_report::number_of_split_curve_triangles`), and a curve
  sample of a triangle under it slides along its curve where that helps
  (`Surface_remeshing_report::number_of_slid_curve_points`).

Every new point lies on the input patch (it is a point of an input
triangle of the same patch, up to rounding). On a curved input patch a new
triangle is a chord across the input's creases, which changes the volumes
of the regions on either side (by 1e-4 to 6e-4 on the models of the test
data). With `keep_region_volumes(true)`, the default, the free points then slide
along their input triangles until every region has its input volume again
(Newton steps on the region volumes, each the smallest move of the free
points that corrects all regions at once, a move kept only when no triangle
around the point turns over or falls under `minimum_triangle_angle`): where
a surface bends both ways, as horizons do, what one chord cuts off another
gives back. Points within two edges of a curve point, or of a triangle under
that angle, stay: there the patches come closest and the surface recovery is
most fragile. A region whose chords all cut into it (a convex body faceted
coarsely: a tunnel, a dome) cannot be given its volume back that way. The
surfaces of such regions (and of those whose only curved surfaces they
share) are then re-meshed again with every crease over 0.01 degrees kept as
a curve, unless they have input angles under 5 degrees, whose creases would
keep the needles; the result is kept if every region's volume comes closer
and no more triangles fall under the angle bound less 5 degrees
(`Surface_remeshing_report::number_of_faceted_patches`): the
fault-and-tunnel model's tunnel goes from 1.9e-2 to 2.4e-8, a salt dome from
2.0e-2 to 3e-14, each with twice the tetrahedra. Regions neither way
reaches are left as the chords make them
(`Surface_remeshing_report::regions_not_balanced`), and so is a
region none of whose points may move; where the outer walls are flat, what
it lost went to the others, which share it in proportion to their volumes.
The balance is off by default: the tetrahedra keep every median with it, but
the single smallest dihedral angle, on a needle facet in a fault strip, moves
either way (CloudSpin 0.0103 -> 0.0012, modelA5 0.40 -> 0.83).
Curve points and corners do not move. The report measures all of it.

<b>Why bubbles are the default.</b> On the four GOCAD models of the test
data (modelA1, modelA2, modelA5, CloudSpin_fixed), the bubble method gives
triangles whose smallest angle is under 25 degrees only at input corners
that force it, and nearly all edges within [0.5, 1.5] of the local target;
`Surface_remeshing_method::ISOTROPIC` (CGAL's isotropic remeshing with the
curve edges protected, started from the same triangulation) cannot follow a
graded size in CGAL 5.5 (one target per patch), so the fine curve spacing
near short input curve segments leaves more small angles and off-size
edges (see the manual for the table).

The charts are triangulated on several threads with `CGAL::Parallel_tag`;
the output is the same whatever the number of threads.

\tparam ConcurrencyTag `CGAL::Parallel_tag` (default when TBB is linked) or `CGAL::Sequential_tag`.
\tparam GeomTraits a model of `Kernel`.

\param input a geological model that `validate_geological_model()` accepts
\param output receives the re-meshed model (cleared first)
\param np an optional sequence of named parameters among the ones listed
below and those of `Remeshing_sizing_field` and `detect_model_features()`

\cgalNamedParamsBegin
  \cgalParamNBegin{curve_distance}
    \cgalParamDescription{largest distance of a re-meshed curve from the input polyline, as a fraction of the bounding-box diagonal}
    \cgalParamType{`double`}
    \cgalParamDefault{5e-7}
  \cgalParamNEnd
  \cgalParamNBegin{surface_distance}
    \cgalParamDescription{distance of a triangle to the input patch, as a fraction of the local target, that the report counts as too far}
    \cgalParamType{`double`}
    \cgalParamDefault{1e-3}
  \cgalParamNEnd
  \cgalParamNBegin{chart_angle}
    \cgalParamDescription{largest angle between the normals of a chart and its plane}
    \cgalParamType{`double` (degrees)}
    \cgalParamDefault{50}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_triangle_angle}
    \cgalParamDescription{the smallest triangle angle aimed at}
    \cgalParamType{`double` (degrees)}
    \cgalParamDefault{25}
  \cgalParamNEnd
  \cgalParamNBegin{surface_remeshing_method}
    \cgalParamDescription{how the patches are triangulated}
    \cgalParamType{`Surface_remeshing_method`}
    \cgalParamDefault{`Surface_remeshing_method::BUBBLES`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{bubble relaxation steps per round}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{40}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_population_steps}
    \cgalParamDescription{rounds of relaxation and population control}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{3}
  \cgalParamNEnd
  \cgalParamNBegin{keep_region_volumes}
    \cgalParamDescription{slide the free points along the input surface until every region has its input volume (see above)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{sizing_field_output}
    \cgalParamDescription{receives the sizing field used in the end: the one built from `np`, plus the spacing of the curve points that had to be kept}
    \cgalParamType{`Remeshing_sizing_field<GeomTraits>*`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{progress on `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what was done and measured: counts, angles, edge lengths against
the target, distances of points, triangles and curves to the input, region
volumes before and after, times.
*/
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class GeomTraits, class CGAL_NP_TEMPLATE_PARAMETERS>
Surface_remeshing_report remesh_surfaces(const Geological_model_3<GeomTraits>& input,
                                         Geological_model_3<GeomTraits>& output,
                                         const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Surface_remeshing_report report;
  Real_timer timer;
  timer.start();

  typename internal::Surface_remesher<GeomTraits>::Settings settings;
  settings.method = choose_parameter(get_parameter(np, internal_np::surface_remeshing_method),
                                     Surface_remeshing_method::BUBBLES);
  settings.curve_distance = choose_parameter(get_parameter(np, internal_np::curve_distance), 5e-7);
  settings.surface_distance = choose_parameter(get_parameter(np, internal_np::surface_distance), 1e-3);
  settings.chart_angle = choose_parameter(get_parameter(np, internal_np::chart_angle), 50.);
  settings.angle_bound = choose_parameter(get_parameter(np, internal_np::minimum_triangle_angle), 25.);
  settings.relaxation_steps =
    choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(40));
  settings.population_rounds =
    choose_parameter(get_parameter(np, internal_np::number_of_population_steps), std::size_t(3));
  settings.keep_region_volumes = choose_parameter(get_parameter(np, internal_np::keep_region_volumes), true);
  settings.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  settings.parallel = internal::Runs_in_parallel<ConcurrencyTag>::value;
  report.method = settings.method;
  report.angle_bound = settings.angle_bound;
  report.surface_distance = settings.surface_distance;

  // One re-meshing from `features`: its output, report (the settings' part
  // already in it), sizing field and the regions its volume balance left out.
  typedef Remeshing_sizing_field<GeomTraits> Sizing;
  auto remesh = [&](const Model_features& features, Geological_model_3<GeomTraits>& out,
                    Surface_remeshing_report& rep, std::unique_ptr<Sizing>& sizing,
                    std::vector<std::size_t>& not_balanced) {
    Real_timer t;
    t.start();
    rep.number_of_corners = features.corners.size();
    rep.number_of_curves = features.curves.size();
    sizing.reset(new Sizing(input, features, np));
    rep.time_sizing = t.time();
    rep.target_size = sizing->user_size();
    rep.smallest_thickness = sizing->smallest_thickness();
    rep.smallest_thickness_size = sizing->smallest_thickness_size();
    if(settings.verbose)
      std::cerr << "remesh_surfaces: " << features.corners.size() << " corners, " << features.curves.size()
                << " curves, size " << sizing->user_size() << ", " << sizing->number_of_point_sizes()
                << " point sizes (" << rep.time_sizing << " s)\n";
    internal::Surface_remesher<GeomTraits> remesher(input, features, *sizing, settings, rep);
    remesher.run(out);
    const double t_measure = t.time();
    internal::measure_remeshing(input, out, features, *sizing, remesher, rep);
    rep.time_measures = t.time() - t_measure;
    not_balanced = remesher.regions_not_balanced();
  };

  Real_timer feature_timer;
  feature_timer.start();
  const Model_features features = detect_model_features(input, np);
  report.time_features = feature_timer.time();
  std::unique_ptr<Sizing> sizing;
  std::vector<std::size_t> not_balanced;
  remesh(features, output, report, sizing, not_balanced);

  // A convex body faceted coarsely (a tunnel, a salt dome) loses volume to
  // chords that all cut into it, which no slide along its surface gives
  // back: only its own creases do. Its patches are re-meshed again with every
  // crease kept as a curve, and the result kept if every region then keeps
  // its volume better and no more triangles fall well under the angle bound.
  // Patches with needles are left out (keeping their creases would keep the
  // needles: a GOCAD horizon).
  if(settings.keep_region_volumes && !not_balanced.empty())
  {
    const std::vector<double> smallest = internal::patch_smallest_angles(input);
    std::vector<double> crease_angles(input.number_of_patches(), 0.);
    std::size_t faceted = 0;
    for(std::size_t p = 0; p < input.number_of_patches(); ++p)
    {
      const bool bounds_one = std::binary_search(not_balanced.begin(), not_balanced.end(), input.patch(p).negative_region) ||
                              std::binary_search(not_balanced.begin(), not_balanced.end(), input.patch(p).positive_region);
      if(bounds_one && smallest[p] >= internal::faceted_patch_min_angle)
        crease_angles[p] = internal::faceted_patch_crease_angle;
    }
    feature_timer.reset();
    const Model_features faceted_features =
      internal::detect_model_features(input, features.feature_angle, crease_angles);
    // the patches with creases to keep (a flat wall has none)
    auto creases = [](const Model_features& f, std::size_t p) {
      std::size_t n = 0;
      for(std::size_t c : f.patch_curves[p]) n += (f.curves[c].kind == Model_features::Curve_kind::SHARP);
      return n;
    };
    for(std::size_t p = 0; p < input.number_of_patches(); ++p)
      faceted += (crease_angles[p] > 0. && creases(faceted_features, p) > creases(features, p));
    if(faceted > 0)
    {
      Surface_remeshing_report again = report;
      again.time_features = feature_timer.time();
      Geological_model_3<GeomTraits> faceted_output;
      std::unique_ptr<Sizing> faceted_sizing;
      std::vector<std::size_t> still;
      settings.unbalanced_patches.assign(crease_angles.size(), 0);
      for(std::size_t p = 0; p < crease_angles.size(); ++p) settings.unbalanced_patches[p] = (crease_angles[p] > 0.);
      remesh(faceted_features, faceted_output, again, faceted_sizing, still);
      // the triangles well under the bound (needles brought back), whether the input forces them or not
      auto poor = [&](const Geological_model_3<GeomTraits>& m) {
        std::size_t n = 0;
        for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
          n += (internal::triangle_min_angle(m, t) < settings.angle_bound - internal::faceted_patch_angle_slack);
        return n;
      };
      if(again.max_relative_volume_error < report.max_relative_volume_error && poor(faceted_output) <= poor(output))
      {
        again.number_of_faceted_patches = faceted;
        report = again;
        output = faceted_output;
        sizing.swap(faceted_sizing);
      }
    }
  }
  Remeshing_sizing_field<GeomTraits>* used =
    choose_parameter(get_parameter(np, internal_np::sizing_field_output), (Remeshing_sizing_field<GeomTraits>*)nullptr);
  if(used != nullptr) *used = *sizing;
  report.time = timer.time();
  return report;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_REMESH_SURFACES_H
