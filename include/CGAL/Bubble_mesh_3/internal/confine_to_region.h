// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_CONFINE_TO_REGION_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_CONFINE_TO_REGION_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/Point_index_tree.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

/// what `Region_confinement` does to a proposed position
enum class Confinement_result
{
  UNCHANGED, ///< the position is valid as it is
  MOVED,     ///< the position was put back inside or out of a diametral ball
  REJECTED   ///< no valid position was found near it
};

/// margins of `Region_confinement` (see `relax_bubbles()` for their meaning)
struct Confinement_settings
{
  double ball_margin = 0.02;   // centres stay beyond (1 + margin) times a ball's radius
  double max_ball_ratio = 3.;  // wider balls (over the local surface radius) are not protected
  double offset_ratio = 0.5;   // a bubble put back lands this share of its radius off the surface
};

/*
Keeps the bubbles of one region inside it and away from its surfaces.

The constraint surfaces of region `r` are the triangles of the patches that
have `r` on one side (its boundary) or on both sides (surfaces inside it, such
as fault tips): a bubble may cross none of them. On top of that a bubble
centre must stay outside the diametral ball of every constraint triangle (the
ball through its corners centred in its plane) and of every constraint edge
(the ball on the edge as diameter), enlarged by `1 + ball_margin`: an input
triangle whose diametral ball holds no other point is a Delaunay facet, so the
tetrahedralization keeps it whole. Balls wider than `max_ball_ratio` times the
local surface-bubble radius (those of needle and cap triangles) are not
protected: keeping bubbles out of them would leave holes much larger than the
mesh size; the surface recovery splits such triangles instead. Nor is a ball
that holds a model point in its interior: that element is split (or kept, on
the convex hull) whatever the bubbles do.

The checks are the expensive part of a step, so a bubble carries a clearance:
the radius of a ball around a checked position that meets no surface and no
protected ball. Moves that stay inside it need no check. The others are
answered from a sparse grid that lists, per cell, the balls and triangles
near it (a bubble resting against a surface is checked at every step, and
a walk down the AABB tree for each check made the relaxation of models with
many such bubbles take hours); the tree serves the positions far from the
surfaces and the inside test of start positions. All queries are
`const` and may run from several threads once the object is built.
*/
template <class GeomTraits>
class Region_confinement
{
public:
  typedef GeomTraits                                  K;
  typedef typename K::Point_3                         Point_3;
  typedef typename K::Vector_3                        Vector_3;
  typedef typename K::Segment_3                       Segment_3;
  typedef typename K::Ray_3                           Ray_3;
  typedef typename K::Triangle_3                      Triangle_3;
  typedef std::vector<Triangle_3>                     Triangles;
  typedef typename Triangles::const_iterator          Triangle_iterator;
  typedef CGAL::AABB_triangle_primitive<K, Triangle_iterator> Primitive;
  typedef CGAL::AABB_traits<K, Primitive>             Traits;
  typedef CGAL::AABB_tree<Traits>                     Tree;

  typedef Confinement_settings Settings;

  /// `point_radius[v]`: radius of the surface bubble at model point `v` (0 if none)
  Region_confinement(const Geological_model_3<K>& model, std::size_t region,
                     const std::vector<double>& point_radius, const Settings& settings)
    : region_(region), settings_(settings)
  {
    collect_triangles(model);
    if(triangles_.empty()) return;
    tree_.reset(new Tree(triangles_.begin(), triangles_.end()));
    // build now: a lazy build would race when threads query the tree
    tree_->build();
    tree_->accelerate_distance_queries();
    collect_balls(model, point_radius);
    build_ball_grid();
  }

  bool has_surfaces() const { return !triangles_.empty(); }
  std::size_t number_of_triangles() const { return triangles_.size(); }
  std::size_t number_of_protected_balls() const { return balls_.size(); }
  const std::array<double, 6>& bbox() const { return bbox_; }

  /// a typical surface-bubble radius on the region's surfaces (the median)
  double typical_surface_radius() const { return typical_radius_; }

  /// inside the region by ray parity over its boundary, three rays voting
  /// (a ray through an edge or vertex may miscount; two rays rarely both do)
  bool is_inside(double x, double y, double z) const
  {
    if(!tree_) return false;
    if(x < bbox_[0] || y < bbox_[1] || z < bbox_[2] || x > bbox_[3] || y > bbox_[4] || z > bbox_[5])
      return false;
    static const double dirs[3][3] = {{0.5773502691896257, 0.5773502691896258, 0.5773502691896259},
                                      {-0.3141592653589793, 0.8164965809277261, -0.4841229182759271},
                                      {0.7071067811865476, -0.1732050807568877, -0.6855654600401044}};
    int votes = 0;
    const Point_3 p(x, y, z);
    for(int d = 0; d < 3; ++d)
    {
      std::vector<typename Primitive::Id> hits;
      tree_->all_intersected_primitives(Ray_3(p, Vector_3(dirs[d][0], dirs[d][1], dirs[d][2])),
                                        std::back_inserter(hits));
      std::size_t crossings = 0;
      for(const auto& id : hits)
        if(is_boundary_[std::size_t(id - triangles_.begin())]) ++crossings;
      if(crossings % 2 == 1) ++votes;
      if(votes == 2 || (d == 1 && votes == 0)) break;
    }
    return votes >= 2;
  }

  /// does the segment `[a,b]` meet a constraint surface?
  bool crosses(const double a[3], const double b[3]) const
  {
    if(!tree_) return false;
    if(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) return false; // a valid position stays valid
    const Segment_3 seg(Point_3(a[0], a[1], a[2]), Point_3(b[0], b[1], b[2]));
    const double l2 = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
    // a triangle that meets a segment shorter than the pad lies within the pad of its end
    // b, so b's cell lists it; the same exact predicate as the tree's, on fewer triangles
    if(!(l2 < face_pad_ * face_pad_)) return tree_->do_intersect(seg);
    double lo[3], hi[3];
    for(int d = 0; d < 3; ++d) { lo[d] = (std::min)(a[d], b[d]); hi[d] = (std::max)(a[d], b[d]); }
    bool hit = false;
    for_each_face_near(cell_at(b), [&](std::uint32_t t) {
      const Face& f = faces_[t];
      for(int d = 0; d < 3; ++d)
        if(f.hi[d] < lo[d] || f.lo[d] > hi[d]) return true;
      hit = CGAL::do_intersect(seg, triangles_[t]);
      return !hit;
    });
    return hit;
  }

  /// true when the segment `[a,b]` lies in the ball around `b` of squared
  /// radius `d2b`, `b`'s squared distance to the surfaces: then it crosses
  /// none. A move is shorter than the surface gap, so this spares most
  /// segment queries; the margin keeps rounding in `d2b` harmless.
  static bool surely_not_crossing(const double a[3], const double b[3], double d2b)
  {
    const double l2 = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
    return l2 * (1. + 1e-6) < d2b;
  }

  /// the protected ball that holds `p` deepest, or `none`
  std::size_t deepest_ball(const double p[3]) const { return deepest_ball(p, cell_at(p)); }

  /// distance from `p` to the constraint surfaces, exact below `wanted` (beyond, some value >=
  /// `wanted`), and below it the longest edge of the nearest triangle in `longest_edge`
  double distance_to_surfaces(const double p[3], double wanted, double& longest_edge) const
  {
    longest_edge = 0.;
    if(!tree_) return (std::numeric_limits<double>::max)();
    std::size_t t = none;
    const double d2 = squared_distance_to_surfaces(p, wanted, &t);
    if(!(d2 < wanted * wanted) || t == none) return std::sqrt(d2);
    const Triangle_3& tr = triangles_[t];
    for(int k = 0; k < 3; ++k)
      longest_edge = (std::max)(longest_edge, std::sqrt(CGAL::to_double(CGAL::squared_distance(tr[k], tr[(k + 1) % 3]))));
    return std::sqrt(d2);
  }

  /// nearest a bubble of radius `radius` may come to a surface
  double gap(double radius) const { return 0.5 * settings_.offset_ratio * radius; }

  /// how far the distance to the surfaces must be known for the checks of a bubble of
  /// radius `radius`: the gap, plus half the radius so that its clearance spares a few steps
  double wanted_distance(double radius) const { return gap(radius) + 0.5 * radius; }

  /// radius of a ball around `p` in which a bubble of radius `radius` meets no
  /// surface closer than `gap(radius)` and no protected ball; negative if it does at `p`
  double clearance(const double p[3], double radius) const
  {
    if(!tree_) return (std::numeric_limits<double>::max)();
    return clearance(p, radius, squared_distance_to_surfaces(p, wanted_distance(radius)));
  }

  /// the same, knowing the squared distance `d2` from `p` to the surfaces
  double clearance(const double p[3], double radius, double d2) const
  {
    const double dist = std::sqrt(d2) - gap(radius);
    // a protected ball lies within twice its radius of the surfaces (its centre is
    // at most one radius off its triangle): far from them no ball needs looking at
    return clearance(p, radius, d2, cell_at(p));
  }

  /*
  Checks the move of a bubble of radius `radius` from the valid position
  `from` to `p`. If `p` lies across a surface, or nearer to one than
  `gap(radius)`, it is put back: at the closest surface point, moved inward
  (off the surface by `offset_ratio * radius` after a crossing, by just over
  `gap(radius)` otherwise).
  A position inside protected balls is pushed out of them along their radii.
  REJECTED when that fails: the caller then keeps `from`. When MOVED,
  `normal` is the unit normal of the last constraint met, towards the side
  the bubble may be on (the caller removes the velocity against it).
  */
  Confinement_result confine(const double from[3], double p[3], double radius, double normal[3],
                             double& clear) const
  {
    clear = (std::numeric_limits<double>::max)();
    if(!tree_) return Confinement_result::UNCHANGED;
    double q[3] = {p[0], p[1], p[2]};
    // one look-up of q's cell serves the distance, ball and clearance queries
    const Cell* cell = cell_at(q);
    const double d2 = squared_distance_to_surfaces(q, wanted_distance(radius), cell);
    const bool crossing = !surely_not_crossing(from, q, d2) && crosses(from, q);
    if(crossing || d2 < gap(radius) * gap(radius))
    {
      // A bubble that only came too close lands just outside the gap, not at the
      // full offset: pressed on a wall by its neighbours it would otherwise be
      // pushed in and thrown back out by a quarter of its radius at every step,
      // and its relaxation would never meet the tolerance.
      const double off = crossing ? settings_.offset_ratio * radius : gap(radius) * (1. + 1e-6);
      if(!put_back(from, p, radius, off, q, normal)) return Confinement_result::REJECTED;
      bool pushed = false;
      if(!push_out_of_balls(from, q, pushed, normal)) return Confinement_result::REJECTED;
      if(pushed && crosses(from, q)) return Confinement_result::REJECTED;
    }
    else if(deepest_ball(q, cell) != none)
    {
      // out of one ball: the closest point outside it (radially), the projection
      // that lets a bubble settle against the ball; where balls overlap, that
      // can bounce a bubble from one to the other for ever, so there it stops
      // where its path enters the first ball
      bool pushed = false;
      double r[3] = {q[0], q[1], q[2]};
      if(!push_out_of_balls(from, r, pushed, normal, 1) || crosses(from, r))
      {
        if(!stop_at_balls(from, q, normal)) return Confinement_result::REJECTED;
      }
      else
        for(int d = 0; d < 3; ++d) q[d] = r[d];
    }
    else
    {
      clear = clearance(q, radius, d2, cell);
      return Confinement_result::UNCHANGED;
    }
    p[0] = q[0]; p[1] = q[1]; p[2] = q[2];
    clear = clearance(q, radius);
    return Confinement_result::MOVED;
  }

  /*
  Makes a start position valid: a bubble outside the region goes to the
  closest boundary point and inward; then out of the protected balls.
  REJECTED when it cannot be made valid (the caller removes the bubble).
  */
  Confinement_result place(double p[3], double radius) const
  {
    if(!tree_) return Confinement_result::REJECTED;
    bool moved = false;
    double inside[3] = {p[0], p[1], p[2]};
    const bool in = is_inside(p[0], p[1], p[2]);
    if(!in || too_close(p, radius))
    {
      const auto cp = tree_->closest_point_and_primitive(Point_3(p[0], p[1], p[2]));
      const std::size_t t = std::size_t(cp.second - triangles_.begin());
      double s = inward_sign_[t];
      if(in || !is_boundary_[t])
      {
        // inside already (too close), or near a surface inside the region: stay on p's side
        const double side = (p[0] - CGAL::to_double(cp.first.x())) * normal_[t][0] +
                            (p[1] - CGAL::to_double(cp.first.y())) * normal_[t][1] +
                            (p[2] - CGAL::to_double(cp.first.z())) * normal_[t][2];
        s = side >= 0. ? 1. : -1.;
      }
      const double off = settings_.offset_ratio * radius;
      for(int d = 0; d < 3; ++d)
        inside[d] = CGAL::to_double(cp.first[d]) + s * normal_[t][d] * off;
      if(!is_inside(inside[0], inside[1], inside[2]) || too_close(inside, radius)) return Confinement_result::REJECTED;
      if(in && crosses(p, inside)) return Confinement_result::REJECTED;
      moved = true;
    }
    double q[3] = {inside[0], inside[1], inside[2]};
    bool pushed = false;
    double normal[3];
    if(!push_out_of_balls(inside, q, pushed, normal)) return Confinement_result::REJECTED;
    if(pushed && crosses(inside, q)) return Confinement_result::REJECTED;
    if(!moved && !pushed) return Confinement_result::UNCHANGED;
    p[0] = q[0]; p[1] = q[1]; p[2] = q[2];
    return Confinement_result::MOVED;
  }

  /// may a new bubble of radius `radius` sit at `p`, reached from the valid position `from` without crossing a surface?
  bool accepts(const double from[3], const double p[3], double radius) const
  {
    if(!tree_) return false;
    return deepest_ball(p) == none && !crosses(from, p) && !too_close(p, radius);
  }

private:
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
  typedef std::pair<std::uint32_t, std::uint32_t> Cell_range;

  // what a cell of the sparse grid lists: ranges of `ball_index_` and `face_index_`
  struct Cell
  {
    Cell_range balls = Cell_range(0, 0);
    Cell_range faces = Cell_range(0, 0);
  };

  // a constraint triangle in doubles, for the distance scans
  struct Face
  {
    double p[3][3];
    double lo[3], hi[3]; // bounding box
    bool flat;           // no area: distances to its edges
  };

  struct Ball
  {
    double c[3];
    double radius;  // enlarged by the margin
    double radius2;
    std::size_t id; // index in `balls_`
  };

  void collect_triangles(const Geological_model_3<K>& model)
  {
    bbox_ = {{(std::numeric_limits<double>::max)(), (std::numeric_limits<double>::max)(),
              (std::numeric_limits<double>::max)(), -(std::numeric_limits<double>::max)(),
              -(std::numeric_limits<double>::max)(), -(std::numeric_limits<double>::max)()}};
    for(std::size_t t = 0; t < model.number_of_triangles(); ++t)
    {
      const auto& patch = model.patch(model.patch_of_triangle(t));
      const bool pos = patch.positive_region == region_, neg = patch.negative_region == region_;
      if(!pos && !neg) continue;
      const auto& tri = model.triangle(t);
      const Point_3& a = model.point(tri[0]);
      const Point_3& b = model.point(tri[1]);
      const Point_3& c = model.point(tri[2]);
      triangles_.push_back(Triangle_3(a, b, c));
      model_triangle_.push_back(t);
      is_boundary_.push_back(pos != neg);
      // the region lies on the normal's side when it is the positive region
      inward_sign_.push_back(pos && !neg ? 1. : -1.);
      const Vector_3 n = CGAL::cross_product(b - a, c - a);
      const double len = std::sqrt(CGAL::to_double(n.squared_length()));
      std::array<double, 3> un = {{0., 0., 0.}};
      if(len > 0.)
        un = {{CGAL::to_double(n.x()) / len, CGAL::to_double(n.y()) / len, CGAL::to_double(n.z()) / len}};
      normal_.push_back(un);
      if(pos != neg)
        for(const Point_3* q : {&a, &b, &c})
          for(int d = 0; d < 3; ++d)
          {
            bbox_[d] = (std::min)(bbox_[d], CGAL::to_double((*q)[d]));
            bbox_[d + 3] = (std::max)(bbox_[d + 3], CGAL::to_double((*q)[d]));
          }
    }
  }

  // A ball that holds a model point in its interior is not protected: the
  // recovery splits its element whatever the bubbles do (or, on the convex
  // hull, keeps it whatever they do), and keeping bubbles out would only empty
  // its surroundings - the two triangles of a box's top or bottom face have
  // balls that span whole layers (modelA1: 361 bubbles in 7.8e11 m3).
  void collect_balls(const Geological_model_3<K>& model, const std::vector<double>& point_radius)
  {
    const Point_index_tree<K> point_tree(model.points());
    std::vector<std::size_t> found;
    auto holds_model_point = [&](const Point_3& center, double radius, auto&& strictly_inside) {
      point_tree.points_in_ball(center, radius, found);
      for(std::size_t i : found)
        if(strictly_inside(model.point(i))) return true;
      return false;
    };
    const auto side = K().side_of_bounded_sphere_3_object();
    const double grow = 1. + settings_.ball_margin;
    auto local_radius = [&](std::size_t v, double fallback) {
      return (v < point_radius.size() && point_radius[v] > 0.) ? point_radius[v] : fallback;
    };
    std::vector<double> radii;
    std::vector<std::pair<std::size_t, std::size_t> > edges;
    for(std::size_t i = 0; i < triangles_.size(); ++i)
    {
      const auto& tri = model.triangle(model_triangle_[i]);
      const Triangle_3& t = triangles_[i];
      double longest = 0.;
      for(int e = 0; e < 3; ++e)
        longest = (std::max)(longest, std::sqrt(CGAL::to_double(CGAL::squared_distance(t[e], t[(e + 1) % 3]))));
      double rl = 0.;
      for(int e = 0; e < 3; ++e)
      {
        rl += local_radius(tri[e], 0.5 * longest) / 3.;
        radii.push_back(local_radius(tri[e], 0.5 * longest));
        edges.push_back(std::make_pair((std::min)(tri[e], tri[(e + 1) % 3]),
                                       (std::max)(tri[e], tri[(e + 1) % 3])));
      }
      if(CGAL::collinear(t[0], t[1], t[2])) continue;
      const Point_3 cc = CGAL::circumcenter(t[0], t[1], t[2]);
      const double R = std::sqrt(CGAL::to_double(CGAL::squared_distance(cc, t[0])));
      if(R > settings_.max_ball_ratio * rl) continue;
      if(holds_model_point(cc, R, [&](const Point_3& p) {
           return side(t[0], t[1], t[2], p) == CGAL::ON_BOUNDED_SIDE;
         }))
        continue;
      add_ball(cc, grow * R, i);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for(const auto& e : edges)
    {
      const Point_3& a = model.point(e.first);
      const Point_3& b = model.point(e.second);
      const double half = 0.5 * std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
      const double rl = 0.5 * (local_radius(e.first, half) + local_radius(e.second, half));
      if(half > settings_.max_ball_ratio * rl || half == 0.) continue;
      if(holds_model_point(CGAL::midpoint(a, b), half,
                           [&](const Point_3& p) { return side(a, b, p) == CGAL::ON_BOUNDED_SIDE; }))
        continue;
      add_ball(CGAL::midpoint(a, b), grow * half, none);
    }
    if(!radii.empty())
    {
      std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
      typical_radius_ = radii[radii.size() / 2];
    }
  }

  void add_ball(const Point_3& c, double radius, std::size_t /* triangle */)
  {
    Ball b;
    for(int d = 0; d < 3; ++d) b.c[d] = CGAL::to_double(c[d]);
    b.radius = radius;
    b.radius2 = radius * radius;
    b.id = balls_.size();
    balls_.push_back(b);
  }

  // sparse grid of balls: only the cells near the surfaces exist
  std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    const std::int64_t lim = (std::int64_t(1) << 21) - 1;
    auto clamp = [lim](std::int64_t v) { return std::uint64_t((std::min)((std::max)(v, std::int64_t(0)), lim)); };
    return (clamp(k) << 42) | (clamp(j) << 21) | clamp(i);
  }

  std::int64_t coordinate(double v, int d) const
  {
    const double t = (v - ball_origin_[d]) / ball_cell_size_;
    if(!(t > -1e18 && t < 1e18)) return 0;
    // floor(t) without the libm call (every check of a bubble looks up its cell)
    const std::int64_t i = std::int64_t(t);
    return double(i) > t ? i - 1 : i;
  }

  void build_ball_grid()
  {
    double largest = 0.;
    std::vector<double> rs;
    for(const Ball& b : balls_) { rs.push_back(b.radius); largest = (std::max)(largest, b.radius); }
    // cells of the median ball radius: a ball is listed in a few dozen cells and a cell
    // lists a dozen balls; with cells twice as wide a query would scan about five times as many
    double h = typical_radius_ > 0. ? typical_radius_ : 1.;
    if(!rs.empty())
    {
      std::nth_element(rs.begin(), rs.begin() + rs.size() / 2, rs.end());
      h = rs[rs.size() / 2];
    }
    const double ext = (std::max)({bbox_[3] - bbox_[0], bbox_[4] - bbox_[1], bbox_[5] - bbox_[2], 0.});
    // 2^21 cells per axis at most
    h = (std::max)(h, ext / 1.e6);
    if(!(h > 0.)) h = 1.;
    // A ball is filed in every cell it reaches: a few balls much wider than the
    // median (a wide spread of triangle sizes) would fill millions of cells and
    // make the set-up cost more than the relaxation. Coarser cells until the
    // lists hold a few dozen entries per ball; the queries stay exact.
    for(int k = 0; k < 40; ++k)
    {
      double cells = 0.;
      for(const Ball& b : balls_)
      {
        const double c = (2. * b.radius + h) / h + 1.;
        cells += c * c * c;
      }
      if(cells <= 128. * double(balls_.size()) + 1024.) break;
      h *= 1.25;
    }
    ball_cell_size_ = h;
    largest_ball_radius_ = largest;
    for(int d = 0; d < 3; ++d) ball_origin_[d] = bbox_[d] - largest - h;
    const double pad = 0.5 * h; // so that a clearance of half a cell is exact
    // f(key) for the cells that come within the pad of ball i (the corners of its box do not)
    auto cells_of_ball = [&](std::size_t i, auto&& f) {
      const Ball& b = balls_[i];
      std::int64_t lo[3], hi[3];
      for(int d = 0; d < 3; ++d)
      {
        lo[d] = coordinate(b.c[d] - b.radius - pad, d);
        hi[d] = coordinate(b.c[d] + b.radius + pad, d);
      }
      const double reach = (b.radius + pad) * (1. + 1e-9) + 1e-9 * h;
      for(std::int64_t k = lo[2]; k <= hi[2]; ++k)
        for(std::int64_t j = lo[1]; j <= hi[1]; ++j)
          for(std::int64_t l = lo[0]; l <= hi[0]; ++l)
          {
            const std::int64_t cc[3] = {l, j, k};
            double d2 = 0.;
            for(int d = 0; d < 3; ++d)
            {
              const double c0 = ball_origin_[d] + double(cc[d]) * h, c1 = c0 + h;
              const double o = (std::max)({c0 - b.c[d], 0., b.c[d] - c1});
              d2 += o * o;
            }
            if(d2 <= reach * reach) f(key(l, j, k));
          }
    };
    std::unordered_map<std::uint64_t, Cell> cells;
    fill_cell_lists(balls_.size(), cells_of_ball, ball_index_, cells, &Cell::balls);
    // the triangles' pad is a whole cell: distances are exact as far as with the coarser cells
    build_face_lists(h, cells);
    // an open-addressing table: a look-up is a multiplication and a probe or two
    std::size_t bits = 4;
    while((std::size_t(1) << bits) < 2 * cells.size()) ++bits;
    slot_shift_ = 64 - int(bits);
    slot_key_.assign(std::size_t(1) << bits, empty_key);
    slot_cell_.assign(std::size_t(1) << bits, Cell());
    // (filled in key order, so that the table does not depend on the map's iteration order)
    std::vector<std::uint64_t> keys;
    keys.reserve(cells.size());
    for(const auto& kc : cells) keys.push_back(kc.first);
    std::sort(keys.begin(), keys.end());
    for(std::uint64_t k : keys)
    {
      std::size_t s = slot_of(k);
      while(slot_key_[s] != empty_key) s = (s + 1) & (slot_key_.size() - 1);
      slot_key_[s] = k;
      slot_cell_[s] = cells[k];
    }
  }

  static constexpr std::uint64_t empty_key = ~std::uint64_t(0); // never a key: coordinates have 21 bits
  std::size_t slot_of(std::uint64_t k) const { return std::size_t((k * 0x9E3779B97F4A7C15ull) >> slot_shift_); }

  /*
  The triangles in the same sparse grid: each is listed in the cells that
  come within `pad` of it (its box grown by the pad, less the cells too far
  from its plane), so a cell lists every triangle within the pad of its
  points, and the distance, crossing and projection queries of bubbles near
  the surfaces scan a few triangles instead of walking the tree. A triangle
  that would fill too many cells is scanned by every query instead.
  */
  void build_face_lists(double pad, std::unordered_map<std::uint64_t, Cell>& cells)
  {
    const double h = ball_cell_size_;
    face_pad_ = pad;
    faces_.resize(triangles_.size());
    const double reach = pad + 0.5 * std::sqrt(3.) * h; // pad plus half a cell diagonal
    // per face: its cell box and whether cells far from its plane can be left out
    struct Listing { std::uint32_t face; std::int64_t lo[3], hi[3]; double margin; bool planar; };
    std::vector<Listing> listed;
    for(std::size_t i = 0; i < triangles_.size(); ++i)
    {
      Face& f = faces_[i];
      for(int v = 0; v < 3; ++v)
        for(int d = 0; d < 3; ++d) f.p[v][d] = CGAL::to_double(triangles_[i][v][d]);
      for(int d = 0; d < 3; ++d)
      {
        f.lo[d] = (std::min)({f.p[0][d], f.p[1][d], f.p[2][d]});
        f.hi[d] = (std::max)({f.p[0][d], f.p[1][d], f.p[2][d]});
      }
      double l2 = 0.;
      for(int e = 0; e < 3; ++e)
      {
        double s = 0.;
        for(int d = 0; d < 3; ++d) s += (f.p[(e + 1) % 3][d] - f.p[e][d]) * (f.p[(e + 1) % 3][d] - f.p[e][d]);
        l2 = (std::max)(l2, s);
      }
      const double ab[3] = {f.p[1][0] - f.p[0][0], f.p[1][1] - f.p[0][1], f.p[1][2] - f.p[0][2]};
      const double ac[3] = {f.p[2][0] - f.p[0][0], f.p[2][1] - f.p[0][1], f.p[2][2] - f.p[0][2]};
      const double cr[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
      const double n2 = dot(cr, cr);
      // a sliver of a triangle: its plane and corner regions are ill-conditioned, use its edges
      f.flat = !(n2 > 1e-20 * l2 * l2) ||
               (normal_[i][0] == 0. && normal_[i][1] == 0. && normal_[i][2] == 0.);
      Listing li;
      li.face = std::uint32_t(i);
      double cells_in_box = 1.;
      for(int d = 0; d < 3; ++d)
      {
        li.lo[d] = coordinate(f.lo[d] - pad, d);
        li.hi[d] = coordinate(f.hi[d] + pad, d);
        cells_in_box *= double(li.hi[d] - li.lo[d] + 1);
      }
      if(cells_in_box > 4096.) { wide_faces_.push_back(std::uint32_t(i)); continue; }
      // cells far from the plane are left out only when the unit normal is accurate: its
      // error, about 1e-16 l^2 / |ab x ac|, stays under 1e-10 here, and the margin below covers it
      li.planar = n2 > 1e-12 * l2 * l2;
      li.margin = 1e-8 * (std::sqrt(l2) + reach + h);
      listed.push_back(li);
    }
    // f(key) for the cells of the i-th listed face
    auto cells_of_face = [&](std::size_t i, auto&& f) {
      const Listing& li = listed[i];
      const Face& face = faces_[li.face];
      const double* n = normal_[li.face].data();
      for(std::int64_t k = li.lo[2]; k <= li.hi[2]; ++k)
        for(std::int64_t j = li.lo[1]; j <= li.hi[1]; ++j)
          for(std::int64_t l = li.lo[0]; l <= li.hi[0]; ++l)
          {
            if(li.planar)
            {
              const double c[3] = {ball_origin_[0] + (double(l) + 0.5) * h, ball_origin_[1] + (double(j) + 0.5) * h,
                                   ball_origin_[2] + (double(k) + 0.5) * h};
              const double off = (c[0] - face.p[0][0]) * n[0] + (c[1] - face.p[0][1]) * n[1] + (c[2] - face.p[0][2]) * n[2];
              if(std::abs(off) > reach + li.margin) continue;
            }
            f(key(l, j, k));
          }
    };
    fill_cell_lists(listed.size(), cells_of_face, face_index_, cells, &Cell::faces);
    for(std::uint32_t& t : face_index_) t = listed[t].face;
  }

  // The items 0..n-1 filed by cell: `cells_of(i, f)` calls f(key) for each cell of item i.
  // `index` gets the items sorted by cell, increasing in each cell, and each cell the range
  // of its items there (the member `list` of Cell). Counted by a first pass, filed by a
  // second into arrays of that size, and sorted by a stable radix sort on the keys alone:
  // a large region files some ten million entries, which a growing vector of pairs and a
  // comparison sort made a good part of the set-up.
  template <class CellsOf>
  void fill_cell_lists(std::size_t n, const CellsOf& cells_of, std::vector<std::uint32_t>& index,
                       std::unordered_map<std::uint64_t, Cell>& cells, Cell_range Cell::*list) const
  {
    // Each pass files what fits and counts all: the first (room for none) counts, the
    // second files them all. Both run the same code, so they agree.
    // Two halves each, for the sort's passes; left uninitialised (no pass of zeros).
    std::size_t count = 0;
    std::unique_ptr<std::uint64_t[]> keys;
    std::unique_ptr<std::uint32_t[]> items;
    for(;;)
    {
      keys.reset(new std::uint64_t[2 * count + 1]);
      items.reset(new std::uint32_t[2 * count + 1]);
      std::size_t filed = 0;
      for(std::size_t i = 0; i < n; ++i)
        cells_of(i, [&](std::uint64_t k) {
          if(filed < count) { keys[filed] = k; items[filed] = std::uint32_t(i); }
          ++filed;
        });
      if(filed == count) break;
      count = filed;
    }
    CGAL_assertion(count < (std::numeric_limits<std::uint32_t>::max)());
    // items were filed in increasing order: still so in each cell
    const std::size_t half = sort_by_key(keys.get(), items.get(), count);
    const std::uint64_t* sorted = keys.get() + half;
    Cell_range* range = nullptr;
    for(std::size_t e = 0; e < count; ++e)
    {
      if(e == 0 || sorted[e] != sorted[e - 1])
      {
        range = &(cells[sorted[e]].*list);
        *range = Cell_range(std::uint32_t(e), std::uint32_t(e));
      }
      ++range->second;
    }
    keys.reset(); // before the copy below: the peak stays at the sort's
    index.assign(items.get() + half, items.get() + half + count);
  }

  // Stable LSD radix sort of keys[0, n) (16 bits a pass, passes where every key has the
  // same digit skipped), items alongside; each array holds 2n, its second half the
  // passes' other buffer. Returns where the sorted keys start: 0 or n.
  static std::size_t sort_by_key(std::uint64_t* keys, std::uint32_t* items, std::size_t n)
  {
    if(n < 2) return 0;
    std::uint64_t varying = 0;
    for(std::size_t e = 1; e < n; ++e) varying |= keys[e] ^ keys[0];
    std::vector<std::size_t> start(std::size_t(1) << 16);
    std::size_t from = 0, to = n;
    for(int shift = 0; shift < 64; shift += 16)
    {
      if(((varying >> shift) & 0xFFFFu) == 0) continue;
      std::fill(start.begin(), start.end(), std::size_t(0));
      for(std::size_t e = from; e < from + n; ++e) ++start[(keys[e] >> shift) & 0xFFFFu];
      std::size_t sum = to;
      for(std::size_t& s : start) { const std::size_t c = s; s = sum; sum += c; }
      for(std::size_t e = from; e < from + n; ++e)
      {
        const std::size_t at = start[(keys[e] >> shift) & 0xFFFFu]++;
        keys[at] = keys[e];
        items[at] = items[e];
      }
      std::swap(from, to);
    }
    return from;
  }

  const Cell* cell_at(const double p[3]) const
  {
    if(slot_key_.empty()) return nullptr;
    const std::uint64_t k = key(coordinate(p[0], 0), coordinate(p[1], 1), coordinate(p[2], 2));
    for(std::size_t s = slot_of(k);; s = (s + 1) & (slot_key_.size() - 1))
    {
      if(slot_key_[s] == k) return &slot_cell_[s];
      if(slot_key_[s] == empty_key) return nullptr;
    }
  }

  Cell_range balls_near(const double p[3]) const
  {
    const Cell* c = cell_at(p);
    return c ? c->balls : Cell_range(0, 0);
  }

  // f(t) for the triangles listed in cell `c` (p's cell), then the wide ones; stops when f
  // returns false. Together they hold every triangle within `face_pad_` of p.
  template <class F>
  void for_each_face_near(const Cell* c, const F& f) const
  {
    if(c)
      for(std::uint32_t k = c->faces.first; k < c->faces.second; ++k)
        if(!f(face_index_[k])) return;
    for(std::uint32_t t : wide_faces_)
      if(!f(t)) return;
  }

  /// the protected ball that holds `p` deepest, or `none`; `cell` is p's
  std::size_t deepest_ball(const double p[3], const Cell* cell) const
  {
    if(!cell) return none;
    std::size_t best = none;
    double best_depth = 0.;
    for(std::uint32_t k = cell->balls.first; k < cell->balls.second; ++k)
    {
      const Ball& b = balls_[ball_index_[k]];
      const double dx = p[0] - b.c[0], dy = p[1] - b.c[1], dz = p[2] - b.c[2];
      const double d2 = dx * dx + dy * dy + dz * dz;
      if(d2 < b.radius2)
      {
        const double depth = b.radius - std::sqrt(d2);
        if(best == none || depth > best_depth) { best = b.id; best_depth = depth; }
      }
    }
    return best;
  }

  // clearance() knowing the squared distance to the surfaces and p's cell
  double clearance(const double p[3], double radius, double d2, const Cell* cell) const
  {
    const double dist = std::sqrt(d2) - gap(radius);
    // a protected ball lies within twice its radius of the surfaces (its centre is
    // at most one radius off its triangle): far from them no ball needs looking at
    const double far = dist - 2. * largest_ball_radius_;
    // the cell lists hold every ball within half a cell of the cell: beyond that we know nothing
    double c = (std::min)(dist, 0.5 * ball_cell_size_);
    if(cell)
      for(std::uint32_t k = cell->balls.first; k < cell->balls.second; ++k)
      {
        const Ball& b = balls_[ball_index_[k]];
        const double dx = p[0] - b.c[0], dy = p[1] - b.c[1], dz = p[2] - b.c[2];
        const double l2 = dx * dx + dy * dy + dz * dz, reach = c + b.radius;
        // a root only for the balls that come nearer than c
        if(reach > 0. && l2 < reach * reach) c = (std::min)(c, std::sqrt(l2) - b.radius);
      }
    return (std::max)(c, far);
  }

  static double dot(const double u[3], const double v[3]) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

  // squared distance from p to the segment [a,b], and its closest point q
  static double point_segment_d2(const double p[3], const double a[3], const double b[3], double q[3])
  {
    const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ap[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double l2 = dot(ab, ab);
    const double t = l2 > 0. ? (std::min)(1., (std::max)(0., dot(ap, ab) / l2)) : 0.;
    double d2 = 0.;
    for(int d = 0; d < 3; ++d)
    {
      q[d] = a[d] + t * ab[d];
      d2 += (p[d] - q[d]) * (p[d] - q[d]);
    }
    return d2;
  }

  // squared distance from p to a triangle, and its closest point q: the region of the
  // triangle's plane (corner, edge or inside) p projects to decides which feature is nearest
  static double point_face_d2(const double p[3], const Face& f, double q[3])
  {
    const double* a = f.p[0];
    const double* b = f.p[1];
    const double* c = f.p[2];
    if(f.flat)
    {
      double best = point_segment_d2(p, a, b, q), r[3];
      for(int e = 1; e < 3; ++e)
      {
        const double d2 = point_segment_d2(p, f.p[e], f.p[(e + 1) % 3], r);
        if(d2 < best) { best = d2; q[0] = r[0]; q[1] = r[1]; q[2] = r[2]; }
      }
      return best;
    }
    const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double ap[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double bp[3] = {p[0] - b[0], p[1] - b[1], p[2] - b[2]}, cp[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
    const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    double u = 0., v = 0.; // q = a + u ab + v ac
    if(d1 <= 0. && d2 <= 0.) {}                                        // corner a
    else if(d3 >= 0. && d4 <= d3) u = 1.;                              // corner b
    else if(d6 >= 0. && d5 <= d6) v = 1.;                              // corner c
    else if(vc <= 0. && d1 >= 0. && d3 <= 0.) u = d1 / (d1 - d3);      // edge ab
    else if(vb <= 0. && d2 >= 0. && d6 <= 0.) v = d2 / (d2 - d6);      // edge ac
    else if(va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.)                // edge bc
    {
      v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
      u = 1. - v;
    }
    else
    {
      const double inv = 1. / (va + vb + vc);
      u = vb * inv;
      v = vc * inv;
    }
    double d2q = 0.;
    for(int d = 0; d < 3; ++d)
    {
      q[d] = a[d] + u * ab[d] + v * ac[d];
      d2q += (p[d] - q[d]) * (p[d] - q[d]);
    }
    return d2q;
  }

  /*
  Squared distance from p to the constraint surfaces, and optionally the
  nearest triangle and point. The cell lists hold every triangle within the
  pad of p, so when one of them is nearer than the pad it is the nearest one.
  Otherwise the pad is a lower bound, returned (with `none` as the triangle)
  when the caller needs the distance only up to `wanted` <= pad and not the
  nearest point (a bubble deep inside its region then costs a cell look-up,
  not a walk down the tree); else the tree answers.
  */
  double squared_distance_to_surfaces(const double p[3], double wanted, std::size_t* tri = nullptr,
                                      double q[3] = nullptr) const
  {
    return squared_distance_to_surfaces(p, wanted, cell_at(p), tri, q);
  }

  double squared_distance_to_surfaces(const double p[3], double wanted, const Cell* cell, std::size_t* tri = nullptr,
                                      double q[3] = nullptr) const
  {
    const double pad2 = face_pad_ * face_pad_;
    double best = pad2, r[3], bq[3] = {0., 0., 0.};
    std::size_t bt = none;
    for_each_face_near(cell, [&](std::uint32_t t) {
      const Face& f = faces_[t];
      // the box's distance bounds the triangle's: most candidates stop here
      double lb = 0.;
      for(int d = 0; d < 3; ++d)
      {
        const double o = (std::max)({f.lo[d] - p[d], 0., p[d] - f.hi[d]});
        lb += o * o;
      }
      if(lb >= best) return true;
      const double d2 = point_face_d2(p, f, r);
      if(d2 < best) { best = d2; bt = t; bq[0] = r[0]; bq[1] = r[1]; bq[2] = r[2]; }
      return true;
    });
    if(bt == none && wanted <= face_pad_ && !q)
    {
      if(tri) *tri = none;
      return pad2;
    }
    if(bt == none)
    {
      const auto cp = tree_->closest_point_and_primitive(Point_3(p[0], p[1], p[2]));
      bt = std::size_t(cp.second - triangles_.begin());
      for(int d = 0; d < 3; ++d) bq[d] = CGAL::to_double(cp.first[d]);
      best = (p[0] - bq[0]) * (p[0] - bq[0]) + (p[1] - bq[1]) * (p[1] - bq[1]) + (p[2] - bq[2]) * (p[2] - bq[2]);
    }
    if(tri) *tri = bt;
    if(q) { q[0] = bq[0]; q[1] = bq[1]; q[2] = bq[2]; }
    return best;
  }

  // p lies across a surface seen from `from`: closest surface point to p, then inward
  bool too_close(const double p[3], double radius) const
  {
    const double g = gap(radius);
    return squared_distance_to_surfaces(p, g) < g * g;
  }

  bool put_back(const double from[3], const double p[3], double radius, double off, double q[3],
                double normal[3]) const
  {
    double c[3];
    std::size_t t = 0;
    squared_distance_to_surfaces(p, (std::numeric_limits<double>::max)(), &t, c);
    double s = inward_sign_[t];
    if(!is_boundary_[t])
    {
      // a surface inside the region: go back to the side the bubble came from
      const double side = (from[0] - c[0]) * normal_[t][0] + (from[1] - c[1]) * normal_[t][1] +
                          (from[2] - c[2]) * normal_[t][2];
      s = side >= 0. ? 1. : -1.;
    }
    for(int d = 0; d < 3; ++d)
    {
      normal[d] = s * normal_[t][d];
      q[d] = c[d] + normal[d] * off;
    }
    if(!crosses(from, q)) return true;
    if(!crosses(from, p)) return false;
    // near folds the closest point may lie on another sheet: stop short along the path instead
    double lo = 0., hi = 1.;
    for(int it = 0; it < 30; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      double m[3];
      for(int d = 0; d < 3; ++d) m[d] = from[d] + mid * (p[d] - from[d]);
      if(crosses(from, m)) hi = mid; else lo = mid;
    }
    const double len = std::sqrt((p[0] - from[0]) * (p[0] - from[0]) + (p[1] - from[1]) * (p[1] - from[1]) +
                                 (p[2] - from[2]) * (p[2] - from[2]));
    const double tt = len > 0. ? (std::max)(0., lo - off / len) : 0.;
    for(int d = 0; d < 3; ++d)
    {
      q[d] = from[d] + tt * (p[d] - from[d]);
      normal[d] = len > 0. ? (from[d] - p[d]) / len : 0.;
    }
    return !too_close(q, radius);
  }

  // moves q back along the path from `from` (outside every ball) to where it
  // first meets a protected ball; false if it cannot leave `from`
  bool stop_at_balls(const double from[3], double q[3], double normal[3]) const
  {
    const double d[3] = {q[0] - from[0], q[1] - from[1], q[2] - from[2]};
    const double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if(!(a > 0.)) return false;
    double t_min = 1.;
    std::size_t hit = none;
    // the path is short against a cell, so the balls near its end hold all it meets
    const Cell_range range = balls_near(q);
    for(std::uint32_t k = range.first; k < range.second; ++k)
    {
      const Ball& ball = balls_[ball_index_[k]];
      const double f[3] = {from[0] - ball.c[0], from[1] - ball.c[1], from[2] - ball.c[2]};
      const double c = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - ball.radius2;
      if(c <= 0.) continue; // `from` on or in this ball: only rounding, it was checked
      const double b = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
      const double disc = b * b - a * c;
      if(b >= 0. || disc < 0.) continue; // moving away, or missing it
      const double t = (-b - std::sqrt(disc)) / a;
      if(t < t_min) { t_min = t; hit = ball.id; }
    }
    if(hit == none) return false;
    // a hair short of the ball, so that rounding cannot put q inside it
    const double t = (std::max)(0., t_min * (1. - 1e-9) - 1e-12);
    for(int dd = 0; dd < 3; ++dd) q[dd] = from[dd] + t * d[dd];
    const Ball& ball = balls_[hit];
    const double n[3] = {q[0] - ball.c[0], q[1] - ball.c[1], q[2] - ball.c[2]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for(int dd = 0; dd < 3; ++dd) normal[dd] = len > 0. ? n[dd] / len : 0.;
    if(deepest_ball(q) != none)
    {
      for(int dd = 0; dd < 3; ++dd) q[dd] = from[dd];
      return true;
    }
    // slide: the rest of the move, less its part into the ball, along the tangent
    // plane (outside the ball, which is convex); kept if it meets nothing else
    double rest[3];
    double into = 0.;
    for(int dd = 0; dd < 3; ++dd)
    {
      rest[dd] = (1. - t) * d[dd];
      into += rest[dd] * normal[dd];
    }
    if(into < 0.)
    {
      double slid[3];
      for(int dd = 0; dd < 3; ++dd) slid[dd] = q[dd] + rest[dd] - into * normal[dd];
      if(deepest_ball(slid) == none && !crosses(from, slid))
        for(int dd = 0; dd < 3; ++dd) q[dd] = slid[dd];
    }
    return true;
  }

  // pushes q radially out of the protected balls that hold it; false if it stays in one
  bool push_out_of_balls(const double from[3], double q[3], bool& pushed, double normal[3], int pushes = 8) const
  {
    pushed = false;
    for(int it = 0; it < pushes; ++it)
    {
      const std::size_t b = deepest_ball(q);
      if(b == none) return true;
      const Ball& ball = balls_[b];
      double dir[3] = {q[0] - ball.c[0], q[1] - ball.c[1], q[2] - ball.c[2]};
      double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
      if(len < 1e-9 * ball.radius)
      {
        // at the centre: leave towards where the bubble came from
        for(int d = 0; d < 3; ++d) dir[d] = from[d] - ball.c[d];
        len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        if(len < 1e-9 * ball.radius) return false;
      }
      const double target = ball.radius * (1. + 1e-6);
      for(int d = 0; d < 3; ++d)
      {
        normal[d] = dir[d] / len;
        q[d] = ball.c[d] + dir[d] * (target / len);
      }
      pushed = true;
    }
    return deepest_ball(q) == none;
  }

  std::size_t region_;
  Settings settings_;
  Triangles triangles_;
  std::vector<std::size_t> model_triangle_;
  std::vector<bool> is_boundary_;
  std::vector<double> inward_sign_;
  std::vector<std::array<double, 3> > normal_;
  std::array<double, 6> bbox_;
  std::unique_ptr<Tree> tree_;
  std::vector<Ball> balls_;
  double typical_radius_ = 0.;
  double ball_cell_size_ = 1.;
  double largest_ball_radius_ = 0.;
  double ball_origin_[3] = {0., 0., 0.};
  std::vector<std::uint32_t> ball_index_; // the cells' ball lists
  std::vector<std::uint64_t> slot_key_;   // the cells that list something, by hash
  std::vector<Cell> slot_cell_;
  int slot_shift_ = 60;
  std::vector<Face> faces_;                // one per triangle
  std::vector<std::uint32_t> face_index_;  // the cells' triangle lists
  std::vector<std::uint32_t> wide_faces_;  // triangles too wide to list: scanned by every query
  double face_pad_ = 0.;                   // a cell lists every triangle within this of its points
};

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_CONFINE_TO_REGION_H
