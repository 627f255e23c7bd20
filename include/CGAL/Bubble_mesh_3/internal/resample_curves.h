// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_RESAMPLE_CURVES_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_RESAMPLE_CURVES_H

// Curve bubbles: the points of a re-meshed curve. A polyline keeps the input
// vertices it cannot drop without moving farther than a tolerance from the
// input (Douglas-Peucker), and between two kept vertices bubbles relax in 1-D,
// by arc length, under the cubic force law with radii from the sizing field.
// Every point lies on a segment of the input polyline.

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

// Marks in `keep` the vertices of `pts[first..last]` that the polyline needs
// to stay within `tolerance` of the input (the ends are kept by the caller).
template <class Point_3>
void mark_essential_vertices(const std::vector<Point_3>& pts, std::size_t first, std::size_t last,
                             double tolerance, std::vector<char>& keep)
{
  typedef typename Kernel_traits<Point_3>::Kernel K;
  // explicit stack: curves can have thousands of vertices
  std::vector<std::pair<std::size_t, std::size_t> > stack(1, std::make_pair(first, last));
  const double tol2 = tolerance * tolerance;
  while(!stack.empty())
  {
    const std::size_t i = stack.back().first, j = stack.back().second;
    stack.pop_back();
    if(j <= i + 1) continue;
    const typename K::Segment_3 s(pts[i], pts[j]);
    double best = -1.;
    std::size_t bi = i;
    for(std::size_t k = i + 1; k < j; ++k)
    {
      const double d = CGAL::to_double(CGAL::squared_distance(pts[k], s));
      if(d > best) { best = d; bi = k; }
    }
    if(best > tol2)
    {
      keep[bi] = 1;
      stack.push_back(std::make_pair(i, bi));
      stack.push_back(std::make_pair(bi, j));
    }
  }
}

// A position on a polyline: segment index and parameter in [0,1].
struct Polyline_position
{
  std::size_t segment = 0;
  double t = 0.;
};

// The point at `pos` on the polyline `pts`.
template <class Point_3>
Point_3 point_on_polyline(const std::vector<Point_3>& pts, const Polyline_position& pos)
{
  return pts[pos.segment] + (pts[pos.segment + 1] - pts[pos.segment]) * pos.t;
}

// Arc length along `pts[first..last]`, and back: positions on a piece of a
// polyline from their distance to its start.
template <class Point_3>
class Polyline_arc_length
{
public:
  Polyline_arc_length(const std::vector<Point_3>& pts, std::size_t first, std::size_t last)
    : first_(first), cumulative_(1, 0.)
  {
    for(std::size_t i = first; i < last; ++i)
      cumulative_.push_back(cumulative_.back() +
                            std::sqrt(CGAL::to_double(CGAL::squared_distance(pts[i], pts[i + 1]))));
  }

  double total() const { return cumulative_.back(); }

  Polyline_position position_at(double s) const
  {
    s = (std::max)(0., (std::min)(total(), s));
    std::size_t k = std::size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), s) - cumulative_.begin());
    k = (k == 0) ? 0 : k - 1;
    if(k + 1 >= cumulative_.size()) k = cumulative_.size() - 2;
    const double len = cumulative_[k + 1] - cumulative_[k];
    Polyline_position pos;
    pos.segment = first_ + k;
    pos.t = len > 0. ? (std::min)(1., (std::max)(0., (s - cumulative_[k]) / len)) : 0.;
    return pos;
  }

  double arc_length_at(const Polyline_position& pos) const
  {
    const std::size_t k = pos.segment - first_;
    return cumulative_[k] + pos.t * (cumulative_[k + 1] - cumulative_[k]);
  }

private:
  std::size_t first_;
  std::vector<double> cumulative_;
};

// Where the points of `facing` (on another curve across a narrow strip) fall
// on `pts[first..last]`, as arc lengths from its start, with their distances
// to it. Each point goes to its nearest segment of the piece.
template <class Point_3>
std::vector<std::pair<double, double> > project_on_polyline(const std::vector<Point_3>& pts, std::size_t first,
                                                           std::size_t last, const std::vector<Point_3>& facing)
{
  const Polyline_arc_length<Point_3> arc(pts, first, last);
  std::vector<std::pair<double, double> > result;
  for(const Point_3& q : facing)
  {
    double best = std::numeric_limits<double>::infinity();
    Polyline_position at;
    for(std::size_t i = first; i < last; ++i)
    {
      const auto ab = pts[i + 1] - pts[i];
      const double l2 = CGAL::to_double(ab.squared_length());
      double t = l2 > 0. ? CGAL::to_double((q - pts[i]) * ab) / l2 : 0.;
      t = (std::max)(0., (std::min)(1., t));
      const double d2 = CGAL::to_double(CGAL::squared_distance(q, pts[i] + ab * t));
      if(d2 < best) { best = d2; at.segment = i; at.t = t; }
    }
    if(std::isfinite(best)) result.push_back(std::make_pair(arc.arc_length_at(at), std::sqrt(best)));
  }
  return result;
}

// `samples` of `pts[first..last]`, with those along a strip replaced by
// points half-way between the other side's points. `facing` are the arc
// lengths of those points projected onto the piece (sorted, at most two
// spacings apart). The samples within a spacing of the run's ends go
// (`spacing_front` and `spacing_back`: a strip's sides are graded along it);
// the new points are half-way between consecutive ones of: the last sample
// kept before the run (or the piece's start), the run, and the first one
// kept after it (or the piece's end, unless that is nearer than a spacing).
// Two curves across a strip narrower than
// their spacing are sampled alike, so their points face each other and the
// strip is cut into right triangles with an angle of atan(width / spacing),
// 16 degrees for a 2 m layer at a spacing of 7; with one side's points
// half-way between the other's, the triangles are isosceles with base angles
// of atan(2 width / spacing), 30 degrees there.
template <class Point_3>
std::vector<Polyline_position> interleave_polyline_samples(const std::vector<Point_3>& pts, std::size_t first,
                                                           std::size_t last,
                                                           const std::vector<Polyline_position>& samples,
                                                           const std::vector<double>& facing, double spacing_front,
                                                           double spacing_back)
{
  const Polyline_arc_length<Point_3> arc(pts, first, last);
  std::vector<double> before, after;
  for(const Polyline_position& p : samples)
  {
    const double s = arc.arc_length_at(p);
    if(s < facing.front() - spacing_front) before.push_back(s);
    else if(s > facing.back() + spacing_back) after.push_back(s);
  }
  std::vector<double> run(1, before.empty() ? 0. : before.back());
  run.insert(run.end(), facing.begin(), facing.end());
  run.push_back(after.empty() ? arc.total() : after.front());
  std::vector<Polyline_position> result;
  for(double s : before) result.push_back(arc.position_at(s));
  for(std::size_t k = 0; k + 1 < run.size(); ++k)
  {
    // no point half-way to the piece's end (a corner) nearer than a spacing:
    // it would leave an edge of under half a spacing there, against the
    // spacing of the other curves at the corner
    if(k == 0 && before.empty() && run[1] - run[0] < spacing_front) continue;
    if(k + 2 == run.size() && after.empty() && run[k + 1] - run[k] < spacing_back) continue;
    result.push_back(arc.position_at(0.5 * (run[k] + run[k + 1])));
  }
  for(double s : after) result.push_back(arc.position_at(s));
  return result;
}

// The cubic law of the bubble method (METHOD.md eq. 6), normalised distance w.
inline double remesh_cubic_force(double w)
{
  return w < 1.5 ? (1.25 * w - 2.375) * w * w + 1.125 : 0.;
}

// Arc-length sampling of `pts[first..last]` (a piece between two kept
// vertices): the interior points, each as a position on the polyline.
// `size(point)` is the target edge length. The count comes from the integral
// of 1/size (the 1-D bubble equilibrium), then the bubbles relax under the
// cubic law with radii size/2, their ends fixed, and gaps or crowds left are
// fixed by adding or removing a bubble (population control, ideal overlap 2).
template <class Point_3, class SizeFunction>
std::vector<Polyline_position> sample_polyline_piece(const std::vector<Point_3>& pts, std::size_t first,
                                                     std::size_t last, const SizeFunction& size,
                                                     std::size_t relaxation_steps = 30)
{
  const Polyline_arc_length<Point_3> arc(pts, first, last);
  const double total = arc.total();
  std::vector<Polyline_position> result;
  if(!(total > 0.)) return result;

  auto point_at = [&](double s) { return arc.position_at(s); };
  auto size_at = [&](double s) { return size(point_on_polyline(pts, point_at(s))); };

  // integral of ds / h, by steps of a quarter of the local size
  std::vector<double> ss(1, 0.), ii(1, 0.);
  {
    double s = 0., h = size_at(0.);
    while(s < total)
    {
      const double step = (std::min)(total - s, 0.25 * h);
      const double h1 = size_at(s + step);
      ii.push_back(ii.back() + step * 0.5 * (1. / h + 1. / h1));
      s += step;
      ss.push_back(s);
      h = h1;
    }
  }
  const double integral = ii.back();
  // rounded up from 0.3: a span a bit longer than the size gets two edges, so
  // that sizes along the curve do not jump more than the grading allows
  const std::size_t n = (std::max)(std::size_t(1), std::size_t(std::ceil(integral - 0.3)));
  std::vector<double> s_of(n + 1, 0.);
  s_of[n] = total;
  for(std::size_t k = 1; k < n; ++k)
  {
    const double target = integral * double(k) / double(n);
    std::size_t j = std::size_t(std::lower_bound(ii.begin(), ii.end(), target) - ii.begin());
    j = (std::max)(std::size_t(1), (std::min)(j, ii.size() - 1));
    const double f = (ii[j] > ii[j - 1]) ? (target - ii[j - 1]) / (ii[j] - ii[j - 1]) : 0.;
    s_of[k] = ss[j - 1] + f * (ss[j] - ss[j - 1]);
  }

  // 1-D bubbles: fixed ends, overdamped steps under the cubic law
  for(int round = 0; round < 3; ++round)
  {
    const std::size_t m = s_of.size();
    std::vector<double> r(m);
    for(std::size_t step = 0; step < relaxation_steps && m > 2; ++step)
    {
      for(std::size_t k = 0; k < m; ++k) r[k] = 0.5 * size_at(s_of[k]);
      std::vector<double> next = s_of;
      for(std::size_t k = 1; k + 1 < m; ++k)
      {
        const double dl = s_of[k] - s_of[k - 1], dr = s_of[k + 1] - s_of[k];
        // the left neighbour pushes forward, the right one backward
        const double fl = remesh_cubic_force(dl / (r[k] + r[k - 1])) * (r[k] + r[k - 1]);
        const double fr = remesh_cubic_force(dr / (r[k] + r[k + 1])) * (r[k] + r[k + 1]);
        double move = 0.25 * (fl - fr);
        const double limit = 0.25 * (std::min)(dl, dr);
        move = (std::max)(-limit, (std::min)(limit, move));
        next[k] = s_of[k] + move;
      }
      s_of.swap(next);
    }
    // population control: split gaps that hold a missing bubble, merge crowds
    bool changed = false;
    std::vector<double> controlled(1, s_of[0]);
    for(std::size_t k = 1; k < s_of.size(); ++k)
    {
      const double gap = s_of[k] - controlled.back();
      const double h = size_at(0.5 * (s_of[k] + controlled.back()));
      if(gap > 1.6 * h)
      {
        controlled.push_back(0.5 * (s_of[k] + controlled.back()));
        changed = true;
      }
      else if(gap < 0.55 * h && k + 1 < s_of.size() && controlled.size() > 1)
      {
        // drop the bubble before, keep this one half-way
        controlled.back() = 0.5 * (controlled.back() + s_of[k]);
        changed = true;
        continue;
      }
      controlled.push_back(s_of[k]);
    }
    s_of.swap(controlled);
    if(!changed) break;
  }

  for(std::size_t k = 1; k + 1 < s_of.size(); ++k)
  {
    if(!(s_of[k] > s_of[k - 1]) || !(s_of[k] < total)) continue; // keep the order strict
    result.push_back(point_at(s_of[k]));
  }
  return result;
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_RESAMPLE_CURVES_H
