// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Surface re-meshing: features of a model, the sizing field, and
// remesh_surfaces() on an in-memory model with a badly triangulated patch
// (needles), a thin layer and a fault ending inside a body, then on real
// GOCAD models when ../shared is there. The done-when list of issue 9 is
// checked here: volumes, curves, conformity (the output validates), angles,
// edge lengths against the target, points on the input.

#include <CGAL/Bubble_mesh_3/Corner_forced_facet_angle.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/Remeshing_sizing_field.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/model_features.h>
#include <CGAL/Bubble_mesh_3/remesh_surfaces.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef K::Segment_3 Segment;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;
namespace BM = CGAL::Bubble_mesh_3;

namespace {

// Builds models from planar rectangles whose edges carry given points, so
// that neighbouring rectangles share them; each rectangle is a fan around
// its centre (needles where an edge carries many points).
struct Builder
{
  Model model;
  std::map<std::array<double, 3>, std::size_t> index;
  // points along an edge, by the edge's endpoints in lexicographic order
  std::map<std::pair<std::array<double, 3>, std::array<double, 3> >, std::vector<double> > edge_params;

  typedef std::array<double, 3> Key;
  static Key key(const Point& p) { return Key{{p.x(), p.y(), p.z()}}; }
  // by value: std::minmax of temporaries would return dangling references
  static std::pair<Key, Key> ordered(const Point& p, const Point& q)
  {
    const Key a = key(p), b = key(q);
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  }

  std::size_t point(const Point& p)
  {
    auto it = index.find(key(p));
    if(it != index.end()) return it->second;
    const std::size_t i = model.add_point(p);
    index[key(p)] = i;
    return i;
  }

  // parameters in (0,1) of the inner points of edge pq (default: none)
  void set_edge(const Point& p, const Point& q, const std::vector<double>& params)
  {
    edge_params[ordered(p, q)] = params;
  }

  // the points from p to q, ends included, computed from the smaller end so both sides agree
  std::vector<std::size_t> edge(const Point& p, const Point& q)
  {
    const std::pair<Key, Key> k = ordered(p, q);
    const Point a(k.first[0], k.first[1], k.first[2]), b(k.second[0], k.second[1], k.second[2]);
    std::vector<std::size_t> pts{point(a)};
    auto it = edge_params.find(k);
    if(it != edge_params.end())
      for(double t : it->second) pts.push_back(point(a + (b - a) * t));
    pts.push_back(point(b));
    if(key(p) != k.first) std::reverse(pts.begin(), pts.end());
    return pts;
  }

  // polygon with corners in order around, a fan around `centre` (from which
  // every corner must be seen), normal along `normal` side
  void polygon(std::size_t patch, const std::vector<Point>& corners, const Point& centre, const Vector& normal)
  {
    std::vector<std::size_t> ring;
    for(std::size_t i = 0; i < corners.size(); ++i)
    {
      std::vector<std::size_t> pts = edge(corners[i], corners[(i + 1) % corners.size()]);
      ring.insert(ring.end(), pts.begin(), pts.end() - 1);
    }
    const std::size_t c = point(centre);
    const bool flip = CGAL::cross_product(corners[0] - centre, corners[1] - centre) * normal < 0;
    for(std::size_t i = 0; i < ring.size(); ++i)
    {
      const std::size_t u = ring[i], v = ring[(i + 1) % ring.size()];
      if(flip) model.add_triangle(c, v, u, patch);
      else model.add_triangle(c, u, v, patch);
    }
  }

  // rectangle a b c d (in order around), normal along `normal` side
  void rectangle(std::size_t patch, const Point& a, const Point& b, const Point& c, const Point& d,
                 const Vector& normal)
  {
    polygon(patch, std::vector<Point>{a, b, c, d}, CGAL::centroid(a, b, c, d), normal);
  }
};

// Box [0,10] x [0,8] x [0,4] in three layers: bottom (z < 1.5), a thin
// layer (1.5 < z < 1.8) and top; the top face is a fan of needles (its
// edge x = 10 carries 30 points packed towards one end); a fault, a
// rectangle inside the top layer, ends there on all four sides.
Model test_model()
{
  Builder b;
  const std::size_t bottom = b.model.add_region("bottom"), thin = b.model.add_region("thin"),
                    top = b.model.add_region("top");
  const double z[4] = {0., 1.5, 1.8, 4.};
  const std::size_t base = b.model.add_patch("base", 0, bottom);
  const std::size_t h1 = b.model.add_patch("h1", thin, bottom);
  const std::size_t h2 = b.model.add_patch("h2", top, thin);
  const std::size_t roof = b.model.add_patch("roof", 0, top);
  const std::size_t fault = b.model.add_patch("fault", top, top);
  // needles: 30 points on the roof edge x = 10, geometric towards y = 0
  std::vector<double> packed;
  double t = 1.;
  for(int i = 0; i < 30; ++i) packed.push_back(t *= 0.8);
  std::reverse(packed.begin(), packed.end());
  b.set_edge(Point(10, 0, 4), Point(10, 8, 4), packed);
  b.rectangle(base, Point(0, 0, 0), Point(10, 0, 0), Point(10, 8, 0), Point(0, 8, 0), Vector(0, 0, -1));
  b.rectangle(h1, Point(0, 0, z[1]), Point(10, 0, z[1]), Point(10, 8, z[1]), Point(0, 8, z[1]), Vector(0, 0, 1));
  b.rectangle(h2, Point(0, 0, z[2]), Point(10, 0, z[2]), Point(10, 8, z[2]), Point(0, 8, z[2]), Vector(0, 0, 1));
  b.rectangle(roof, Point(0, 0, 4), Point(10, 0, 4), Point(10, 8, 4), Point(0, 8, 4), Vector(0, 0, 1));
  const std::size_t regions[3] = {bottom, thin, top};
  const char* names[3] = {"bottom", "thin", "top"};
  for(int r = 0; r < 3; ++r)
  {
    const std::size_t side = b.model.add_patch(std::string("sides_") + names[r], 0, regions[r]);
    const double lo = z[r], hi = z[r + 1];
    b.rectangle(side, Point(0, 0, lo), Point(10, 0, lo), Point(10, 0, hi), Point(0, 0, hi), Vector(0, -1, 0));
    b.rectangle(side, Point(10, 0, lo), Point(10, 8, lo), Point(10, 8, hi), Point(10, 0, hi), Vector(1, 0, 0));
    b.rectangle(side, Point(10, 8, lo), Point(0, 8, lo), Point(0, 8, hi), Point(10, 8, hi), Vector(0, 1, 0));
    b.rectangle(side, Point(0, 8, lo), Point(0, 0, lo), Point(0, 0, hi), Point(0, 8, hi), Vector(-1, 0, 0));
  }
  b.rectangle(fault, Point(5, 2, 2.3), Point(5, 6, 2.3), Point(5, 6, 3.5), Point(5, 2, 3.5), Vector(1, 0, 0));
  return b.model;
}

// Two layers of the box [0,10] x [0,4] x [0,10] on both sides of the
// horizon h (z = 5), which a small reverse fault offsets: the fault strip f
// (another patch) is the quadrilateral P1 Pa P3 Pb, with the fault tips P1
// = (5,1,5) and P3 = (5,3,5) and the most offset points Pa = (5.15,2,4.85) on
// the footwall side and Pb = (4.85,2,5.15) on the hangingwall side. Seen
// from above, h is one piece whose triangles all face up and whose borders
// (the box rim and the two fault cut lines P1 Pa P3 and P1 Pb P3) do not
// cross, yet it covers the lens between the cut lines twice: CloudSpin's
// horizon KOBE_1 along its fault strips.
Model overhang_model()
{
  Builder b;
  const std::size_t lower = b.model.add_region("lower"), upper = b.model.add_region("upper");
  const std::size_t base = b.model.add_patch("base", 0, lower), roof = b.model.add_patch("roof", 0, upper);
  const std::size_t h = b.model.add_patch("h", upper, lower), f = b.model.add_patch("f", upper, lower);
  const std::size_t sides_lower = b.model.add_patch("sides_lower", 0, lower),
                    sides_upper = b.model.add_patch("sides_upper", 0, upper);
  // the horizon meets the sides y = 0 and y = 4 at x = 5 too
  b.set_edge(Point(0, 0, 5), Point(10, 0, 5), {0.5});
  b.set_edge(Point(0, 4, 5), Point(10, 4, 5), {0.5});
  b.rectangle(base, Point(0, 0, 0), Point(10, 0, 0), Point(10, 4, 0), Point(0, 4, 0), Vector(0, 0, -1));
  b.rectangle(roof, Point(0, 0, 10), Point(10, 0, 10), Point(10, 4, 10), Point(0, 4, 10), Vector(0, 0, 1));
  for(double x : {0., 10.})
  {
    const Vector out(x == 0. ? -1 : 1, 0, 0);
    b.rectangle(sides_lower, Point(x, 0, 0), Point(x, 4, 0), Point(x, 4, 5), Point(x, 0, 5), out);
    b.rectangle(sides_upper, Point(x, 0, 5), Point(x, 4, 5), Point(x, 4, 10), Point(x, 0, 10), out);
  }
  for(double y : {0., 4.})
  {
    const Vector out(0, y == 0. ? -1 : 1, 0);
    b.rectangle(sides_lower, Point(0, y, 0), Point(10, y, 0), Point(10, y, 5), Point(0, y, 5), out);
    b.rectangle(sides_upper, Point(0, y, 5), Point(10, y, 5), Point(10, y, 10), Point(0, y, 10), out);
  }
  const Point p1(5, 1, 5), pa(5.15, 2, 4.85), p3(5, 3, 5), pb(4.85, 2, 5.15);
  // the upper layer lies under the strip: its normal points down
  b.polygon(f, {p1, pa, p3, pb}, Point(5, 2, 5), Vector(0, 0, -1));
  // h: footwall triangles on the cut line P1 Pa P3 (from x < 5.15),
  // hangingwall ones on P1 Pb P3 (from x > 4.85), and a ring to the box
  const Point l(3, 1.8, 5), r(7, 2, 5), c00(0, 0, 5), c10(10, 0, 5), c11(10, 4, 5), c01(0, 4, 5), m0(5, 0, 5),
    m4(5, 4, 5);
  const std::array<Point, 3> up[] = {{l, p1, pa}, {l, pa, p3},  {r, p3, pb},    {r, pb, p1},   {c00, m0, p1},
                                     {c00, p1, l}, {c00, l, c01}, {c01, l, p3}, {c01, p3, m4}, {m0, c10, r},
                                     {m0, r, p1},  {c10, c11, r}, {r, c11, m4}, {r, m4, p3}};
  for(const auto& t : up) b.model.add_triangle(b.point(t[0]), b.point(t[1]), b.point(t[2]), h);
  return b.model;
}

double diagonal(const Model& m)
{
  const CGAL::Bbox_3 box = BM::bbox(m);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

double min_angle(const Model& m, std::size_t t)
{
  const auto& tri = m.triangle(t);
  return BM::internal::min_angle_degrees(m.point(tri[0]), m.point(tri[1]), m.point(tri[2]));
}

// share of distinct output edges within [0.5, 1.5] of the field (the smaller target of its patches)
double share_within_size(const Model& m, const BM::Remeshing_sizing_field<K>& field)
{
  std::map<std::pair<std::size_t, std::size_t>, double> target;
  for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
    for(int k = 0; k < 3; ++k)
    {
      const auto& tri = m.triangle(t);
      const auto e = std::minmax(tri[k], tri[(k + 1) % 3]);
      const double h = field(CGAL::midpoint(m.point(e.first), m.point(e.second)), m.patch_of_triangle(t));
      auto it = target.find(e);
      if(it == target.end()) target[e] = h;
      else it->second = std::min(it->second, h);
    }
  std::size_t within = 0;
  for(const auto& e : target)
  {
    const double l = std::sqrt(CGAL::squared_distance(m.point(e.first.first), m.point(e.first.second)));
    if(l >= 0.5 * e.second && l <= 1.5 * e.second) ++within;
  }
  return double(within) / double(target.size());
}

void print(const std::string& name, const BM::Surface_remeshing_report& r)
{
  std::cout << "  " << name << ": " << r.number_of_triangles << " triangles, " << r.number_of_charts << " charts, "
            << "min angle " << r.input_min_angle << " -> " << r.min_angle << " deg, under " << r.angle_bound
            << " deg " << r.number_of_small_angle_triangles << " (forced " << r.number_of_forced_small_angle_triangles
            << "), edges in [0.5,1.5] of target " << 100. * r.share_of_edges_within_size << " %, volume error "
            << r.max_relative_volume_error << ", curve distance " << r.max_curve_distance << " of diagonal, point distance "
            << r.max_point_distance << ", triangle distance " << r.max_triangle_distance << " of size, " << r.time
            << " s\n";
}

void test_features()
{
  std::cout << "features of the in-memory model\n";
  const Model m = test_model();
  BM::validate_geological_model(m);
  const BM::Model_features f = BM::detect_model_features(m);
  std::size_t free_curves = 0, contact = 0, sharp = 0;
  double free_length = 0.;
  for(const auto& c : f.curves)
  {
    if(c.kind == BM::Model_features::Curve_kind::FREE)
    {
      ++free_curves;
      for(std::size_t i = 0; i + 1 < c.points.size(); ++i)
        free_length += std::sqrt(CGAL::squared_distance(m.point(c.points[i]), m.point(c.points[i + 1])));
    }
    if(c.kind == BM::Model_features::Curve_kind::CONTACT) ++contact;
    if(c.kind == BM::Model_features::Curve_kind::SHARP) ++sharp;
  }
  std::cout << "  " << f.corners.size() << " corners, " << f.curves.size() << " curves (" << contact << " contact, "
            << free_curves << " fault tips of total length " << free_length << ", " << sharp << " sharp)\n";
  // the fault tip: four sides (its corners turn by 90 degrees), perimeter 2 * (4 + 1.2)
  assert(free_curves == 4);
  assert(std::abs(free_length - 10.4) < 1e-12);
  // box: 8 corners of the box, 4 per horizon on the sides, 4 fault corners
  assert(f.corners.size() == 8 + 8 + 4);
  // the rims of the base, the two horizons and the roof, 4 sides each
  assert(contact == 4 * 4);
  // the vertical box edges are creases inside each region's side patch, cut at the horizons
  assert(sharp == 4 * 3);
  // the side patches have 90-degree creases between their faces: with a feature angle of 95 they are not curves
  const BM::Model_features g = BM::detect_model_features(m, BM::parameters::feature_angle(95.));
  std::cout << "  feature angle 95: " << g.curves.size() << " curves, " << g.corners.size() << " corners\n";
  assert(g.curves.size() < f.curves.size());
}

void test_sizing()
{
  std::cout << "sizing field\n";
  const Model m = test_model();
  const BM::Model_features f = BM::detect_model_features(m);
  // (two edges across given: the figures below follow from it, not from the default)
  const BM::Remeshing_sizing_field<K> field(
    m, f, BM::parameters::elements_across_thickness(2., BM::parameters::edge_length(1.)));
  // the thin layer (0.3 thick) wants 0.15 with two elements across; far from it the user size
  const double on_h1 = field(Point(5, 4, 1.5), 1);
  const double on_roof = field(Point(1, 1, 4), 3);
  const double above_fault = field(Point(5, 4, 4), 3);
  const double on_base = field(Point(2, 2, 0), 0);
  std::cout << "  size on the thin layer's horizon " << on_h1 << ", on the roof " << on_roof << ", on the roof above the fault tip "
            << above_fault << ", on the base " << on_base << ", thinnest " << field.smallest_thickness() << "\n";
  assert(std::abs(on_h1 - 0.15) < 1e-9);
  assert(std::abs(field.smallest_thickness() - 0.3) < 1e-9);
  assert(on_roof == 1.);
  // the fault ends 0.5 under the roof: two elements across that gap
  assert(std::abs(above_fault - 0.25) < 1e-9);
  // the bottom layer is 1.5 thick (0.75 with two elements across), and the
  // thin layer's 0.15 is 1.5 away, so grows to 0.9 here
  assert(on_base >= 0.75 - 1e-9 && on_base < 0.9);
  // graded: neighbouring points differ by at most the slope times their distance
  for(int i = 0; i < 50; ++i)
  {
    const Point p(0.2 * i, 4, 2.5), q(0.2 * i + 0.1, 4, 2.5);
    assert(std::abs(field(p, 2) - field(q, 2)) <= 0.5 * 0.1 + 1e-9);
  }
  // factors: region 3 (top) twice as fine
  const BM::Remeshing_sizing_field<K> finer(
    m, f, BM::parameters::region_size_factors(std::vector<double>{1., 1., 1., 0.5},
                                              BM::parameters::elements_across_thickness(2., BM::parameters::edge_length(1.))));
  // (away from the fault tip, where the thickness rule does not apply)
  std::cout << "  top region factor 0.5: size on the roof " << finer(Point(1, 1, 4), 3) << "\n";
  assert(std::abs(finer(Point(1, 1, 4), 3) - 0.5) < 1e-12);
  // the thickness rule still wins above the fault tip
  assert(std::abs(finer(Point(5, 4, 4), 3) - 0.25) < 1e-9);
}

// A fault tip 0.5 under a small body (a 0.4 x 0.4 x 0.4 lens) that lies
// wholly within the curve rule's search radius (twice the size): the rule
// must see the lens (CGAL's Sphere_3 intersection tests, with the sphere's
// surface, missed it); no thickness ray from either surface meets the other
void test_proximity_inside_search_ball()
{
  std::cout << "curve proximity to a body inside the search radius\n";
  Builder b;
  const std::size_t rock = b.model.add_region("rock"), lens = b.model.add_region("lens");
  const std::size_t outer = b.model.add_patch("outer", 0, rock), lens_faces = b.model.add_patch("lens", rock, lens);
  const std::size_t fault = b.model.add_patch("fault", rock, rock);
  auto box = [&](std::size_t patch, const Point& lo, const Point& hi) {
    const double x[2] = {lo.x(), hi.x()}, y[2] = {lo.y(), hi.y()}, z[2] = {lo.z(), hi.z()};
    for(int k = 0; k < 2; ++k)
    {
      const double sign = k == 0 ? -1. : 1.;
      b.rectangle(patch, Point(x[k], y[0], z[0]), Point(x[k], y[1], z[0]), Point(x[k], y[1], z[1]),
                  Point(x[k], y[0], z[1]), Vector(sign, 0, 0));
      b.rectangle(patch, Point(x[0], y[k], z[0]), Point(x[1], y[k], z[0]), Point(x[1], y[k], z[1]),
                  Point(x[0], y[k], z[1]), Vector(0, sign, 0));
      b.rectangle(patch, Point(x[0], y[0], z[k]), Point(x[1], y[0], z[k]), Point(x[1], y[1], z[k]),
                  Point(x[0], y[1], z[k]), Vector(0, 0, sign));
    }
  };
  box(outer, Point(0, 0, 0), Point(10, 8, 4));
  box(lens_faces, Point(4.8, 3.8, 2.5), Point(5.2, 4.2, 2.9));
  b.rectangle(fault, Point(5, 2, 1), Point(5, 6, 1), Point(5, 6, 2), Point(5, 2, 2), Vector(1, 0, 0));
  const Model& m = b.model;
  const BM::Model_features f = BM::detect_model_features(m);
  const BM::Remeshing_sizing_field<K> field(
    m, f, BM::parameters::elements_across_thickness(2., BM::parameters::edge_length(1.)));
  const double at_tip = field(Point(5, 4, 2), fault);
  std::cout << "  size on the fault tip under the lens " << at_tip << " (0.5 away: 0.25 wanted)\n";
  assert(std::abs(at_tip - 0.25) < 1e-9);
}

// an output point of a patch near one of the patch's axis planes (an input
// triangle with x, y or z constant, as box walls are) lies exactly on it;
// returns how many points were so near
std::size_t check_axis_planes_kept(const Model& input, const Model& output)
{
  std::vector<std::array<std::set<double>, 3> > levels(input.number_of_patches());
  for(std::size_t t = 0; t < input.number_of_triangles(); ++t)
  {
    const auto& tri = input.triangle(t);
    for(int k = 0; k < 3; ++k)
      if(input.point(tri[0])[k] == input.point(tri[1])[k] && input.point(tri[0])[k] == input.point(tri[2])[k])
        levels[input.patch_of_triangle(t)][k].insert(input.point(tri[0])[k]);
  }
  const double near = 1e-9 * diagonal(input);
  std::size_t on_planes = 0;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
    for(std::size_t v : output.triangle(t))
      for(int k = 0; k < 3; ++k)
        for(double level : levels[output.patch_of_triangle(t)][k])
        {
          const double x = output.point(v)[k];
          if(std::abs(x - level) > near) continue;
          ++on_planes;
          if(x != level)
            std::cout << "    point " << v << " is " << x - level << " off the plane " << "xyz"[k] << " = " << level
                      << std::endl;
          assert(x == level);
        }
  return on_planes;
}

// The in-memory model moved to real coordinates (CloudSpin's corner, some
// 1.6e6 m east): points projected onto its walls must still lie exactly on
// them (CloudSpin re-meshed had wall points an ulp off, and its surface
// recovery failed on such a wall)
void test_far_from_origin()
{
  std::cout << "remesh_surfaces far from the origin\n";
  const Model near = test_model();
  Model input = near;
  const Vector shift(1610685.000281947, -181489.13117834617, -7471.2849178777487);
  for(std::size_t v = 0; v < input.number_of_points(); ++v) input.set_point(v, near.point(v) + shift);
  Model output;
  const auto np = BM::parameters::edge_length(0.5);
  BM::remesh_surfaces(input, output, np);
  BM::validate_geological_model(output);
  const std::size_t on_planes = check_axis_planes_kept(input, output);
  std::cout << "    " << on_planes << " point coordinates on the walls' planes, all exact" << std::endl;
  assert(on_planes > 1000);
}

// A pipe of radius 1 through a box: a prism of 24 sides, each side 24 faces
// of 0.25 along the axis (about its width: the rule reads the curvature from
// an edge's length and its turn, which holds on even triangles). Each edge
// along the axis turns by 15 degrees, under the feature angle. The rule
// sizes the pipe's sides by the angle a new edge may turn, the walls not at all.
// A pipe of radius 1 (24 sides: creases of 15 degrees, under the feature
// angle, so one curved patch with its end caps) along x through a 10-box
Model pipe_model()
{
  const double pi = 3.14159265358979323846;
  const int n = 24;
  Builder b;
  const std::size_t rock = b.model.add_region("rock"), pipe = b.model.add_region("pipe");
  const std::size_t outer = b.model.add_patch("outer", 0, rock), sides = b.model.add_patch("pipe", rock, pipe);
  for(int k = 0; k < 2; ++k)
  {
    const double x = 10. * k, sign = k == 0 ? -1. : 1.;
    b.rectangle(outer, Point(x, 0, 0), Point(x, 10, 0), Point(x, 10, 10), Point(x, 0, 10), Vector(sign, 0, 0));
    b.rectangle(outer, Point(0, x, 0), Point(10, x, 0), Point(10, x, 10), Point(0, x, 10), Vector(0, sign, 0));
    b.rectangle(outer, Point(0, 0, x), Point(10, 0, x), Point(10, 10, x), Point(0, 10, x), Vector(0, 0, sign));
  }
  auto ring = [&](double x, int i) { return Point(x, 5 + std::cos(2 * pi * i / n), 5 + std::sin(2 * pi * i / n)); };
  std::vector<Point> left, right;
  for(int i = 0; i < n; ++i)
  {
    left.push_back(ring(2, i));
    right.push_back(ring(8, i));
    for(int k = 0; k < 24; ++k)
    {
      const double x0 = 2 + 0.25 * k, x1 = x0 + 0.25;
      const Point mid = CGAL::midpoint(ring(x0, i), ring(x0, i + 1));
      b.rectangle(sides, ring(x0, i), ring(x1, i), ring(x1, i + 1), ring(x0, i + 1), mid - Point(x0, 5, 5));
    }
  }
  b.polygon(sides, left, Point(2, 5, 5), Vector(-1, 0, 0));
  b.polygon(sides, right, Point(8, 5, 5), Vector(1, 0, 0));
  return b.model;
}

void test_curvature_rule()
{
  std::cout << "curvature rule on a pipe\n";
  const double pi = 3.14159265358979323846;
  const int n = 24;
  auto ring = [&](double x, int i) { return Point(x, 5 + std::cos(2 * pi * i / n), 5 + std::sin(2 * pi * i / n)); };
  const std::size_t outer = 0, sides = 1;
  const Model m = pipe_model();
  assert(m.patch(sides).name == "pipe" && m.patch(outer).name == "outer");
  BM::validate_geological_model(m);
  const BM::Model_features f = BM::detect_model_features(m);
  auto field = [&](double angle) {
    return BM::Remeshing_sizing_field<K>(
      m, f, BM::parameters::curvature_angle(angle, BM::parameters::minimum_edge_length(0.05,
            BM::parameters::elements_across_thickness(0., BM::parameters::edge_length(2.)))));
  };
  // at the midpoint of an edge along the axis: the angle over the turn (15 degrees) times the edge (0.25)
  const Point on_edge = CGAL::midpoint(ring(5, 3), ring(5.25, 3));
  const double by_default = field(22.5)(on_edge, sides), finer = field(11.25)(on_edge, sides), off = field(0.)(on_edge, sides);
  const double on_wall = field(22.5)(Point(0, 9, 9), outer);
  std::cout << "  pipe side: " << by_default << " (22.5 degrees), " << finer << " (11.25), " << off
            << " (off); wall far from it " << on_wall << std::endl;
  assert(std::abs(by_default - 22.5 / 15. * 0.25) < 1e-9);
  assert(std::abs(finer - 11.25 / 15. * 0.25) < 1e-9);
  assert(off == 2.);
  assert(on_wall == 2.);
}

// `field` is the one remesh_surfaces() used (`given` plus the spacing of the curve points it had to keep)
void check_remeshed(const Model& input, const Model& output, const BM::Surface_remeshing_report& r,
                    const BM::Remeshing_sizing_field<K>& field, const BM::Remeshing_sizing_field<K>& given,
                    bool strict_angles, bool strict_volumes)
{
  // conforming interfaces, closed oriented region boundaries, no crossing: the model validates
  BM::validate_geological_model(output);
  assert(output.number_of_patches() == input.number_of_patches());
  assert(output.number_of_regions() == input.number_of_regions());
  for(std::size_t p = 0; p < input.number_of_patches(); ++p)
  {
    assert(output.patch(p).name == input.patch(p).name);
    assert(output.patch(p).positive_region == input.patch(p).positive_region);
    assert(output.patch(p).negative_region == input.patch(p).negative_region);
  }
  const double diag = diagonal(input);
  // volumes
  const std::vector<double> vin = BM::region_volumes(input), vout = BM::region_volumes(output);
  double worst = 0.;
  for(std::size_t i = 1; i < vin.size(); ++i) worst = std::max(worst, std::abs(vout[i] - vin[i]) / vin[i]);
  std::cout << "    largest relative volume error " << worst << "\n";
  assert(std::abs(worst - r.max_relative_volume_error) <= 1e-12 + 1e-9 * worst);
  if(strict_volumes) assert(worst < 1e-6);
  check_axis_planes_kept(input, output);
  // points on the input surface
  std::cout << "    largest point distance to the input " << r.max_point_distance << " of the diagonal\n";
  assert(r.max_point_distance < 1e-12);
  // curves
  std::cout << "    largest curve distance " << r.max_curve_distance << " of the diagonal\n";
  assert(r.max_curve_distance < 1e-6);
  // angles: count independently
  std::size_t small = 0;
  double smallest = 180.;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
  {
    const double a = min_angle(output, t);
    smallest = std::min(smallest, a);
    if(a < 25.) ++small;
  }
  std::cout << "    min angle " << smallest << ", " << small << " triangles under 25 deg (" << r.number_of_forced_small_angle_triangles
            << " forced by input corners)\n";
  assert(small == r.number_of_small_angle_triangles);
  // the forced ones lie in the wedges of their corners; the rest are listed (the first ten printed)
  std::cout << "    " << r.number_of_small_angle_triangles_in_sharp_wedges << " in the wedges of sharp input corners\n";
  assert(r.number_of_small_angle_triangles_in_sharp_wedges >= r.number_of_forced_small_angle_triangles);
  assert(r.number_of_small_angle_triangles_in_sharp_wedges + r.small_angle_triangles_outside_sharp_wedges.size() == small);
  for(std::size_t i = 0; i < r.small_angle_triangles_outside_sharp_wedges.size(); ++i)
  {
    const std::size_t t = r.small_angle_triangles_outside_sharp_wedges[i];
    const auto& tri = output.triangle(t);
    if(i < 10)
      std::cout << "      outside them: " << min_angle(output, t) << " on " << output.patch(output.patch_of_triangle(t)).name
                << " at " << output.point(tri[0]) << ", " << output.point(tri[1]) << ", " << output.point(tri[2]) << "\n";
    assert(min_angle(output, t) < 25.);
  }
  if(strict_angles) assert(small == r.number_of_forced_small_angle_triangles);
  // of those, the ones between three points of the output's curves
  const BM::Model_features out_features = BM::detect_model_features(output);
  std::vector<char> on_curve(output.number_of_points(), 0);
  for(const BM::Model_features::Curve& c : out_features.curves)
    for(std::size_t v : c.points) on_curve[v] = 1;
  std::size_t between = 0;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
  {
    const auto& tri = output.triangle(t);
    if(min_angle(output, t) < 25. && on_curve[tri[0]] && on_curve[tri[1]] && on_curve[tri[2]]) ++between;
  }
  std::cout << "    " << between << " of them between three curve points\n";
  assert(between == r.number_of_small_angle_triangles_between_curve_points);
  // edge lengths against the field
  const double share = share_within_size(output, field);
  std::cout << "    edges within [0.5, 1.5] of the target: " << 100. * share << " % (of the field given: "
            << 100. * share_within_size(output, given) << " %)\n";
  assert(share >= 0.95);
  assert(std::abs(share - r.share_of_edges_within_size) < 1e-12);
  // the constraints only make the field finer
  for(std::size_t v = 0; v < output.number_of_points(); v += 7)
    for(std::size_t p = 0; p < output.number_of_patches(); ++p)
      assert(field(output.point(v), p) <= given(output.point(v), p));
  (void)diag;
}

void test_in_memory(BM::Surface_remeshing_method method)
{
  const bool bubbles = (method == BM::Surface_remeshing_method::BUBBLES);
  std::cout << "remesh_surfaces on the in-memory model, " << (bubbles ? "bubbles" : "isotropic") << "\n";
  const Model input = test_model();
  Model output;
  // (two edges across thin layers given, as the thin layer's edge lengths are checked against it)
  const auto np = BM::parameters::surface_remeshing_method(
    method, BM::parameters::elements_across_thickness(2., BM::parameters::edge_length(1.)));
  const BM::Model_features f = BM::detect_model_features(input);
  BM::Remeshing_sizing_field<K> field(input, f, np);
  const BM::Remeshing_sizing_field<K> given = field;
  const BM::Surface_remeshing_report r = BM::remesh_surfaces(input, output, BM::parameters::sizing_field_output(&field, np));
  print("in-memory", r);
  assert(r.input_min_angle < 1.); // the roof's needles
  check_remeshed(input, output, r, field, given, bubbles, true);
  // no needles left on the roof
  double roof_min = 180.;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
    if(output.patch_of_triangle(t) == 3) roof_min = std::min(roof_min, min_angle(output, t));
  std::cout << "    roof min angle " << roof_min << "\n";
  assert(roof_min > (bubbles ? 25. : 15.));
  // the thin layer gets two edges across its thickness on its horizons
  std::vector<double> lengths;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
    if(output.patch_of_triangle(t) == 1)
      for(int k = 0; k < 3; ++k)
        lengths.push_back(std::sqrt(CGAL::squared_distance(output.point(output.triangle(t)[k]),
                                                           output.point(output.triangle(t)[(k + 1) % 3]))));
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  std::cout << "    median edge on the thin layer's floor " << lengths[lengths.size() / 2] << " (thickness 0.3)\n";
  if(bubbles) assert(lengths[lengths.size() / 2] < 0.15 * 1.25 && lengths[lengths.size() / 2] > 0.15 * 0.75);
  // the fault tip is kept: same free border length, its corners are output points
  const BM::Model_features g = BM::detect_model_features(output);
  double free_length = 0.;
  for(const auto& c : g.curves)
    if(c.kind == BM::Model_features::Curve_kind::FREE)
      for(std::size_t i = 0; i + 1 < c.points.size(); ++i)
        free_length += std::sqrt(CGAL::squared_distance(output.point(c.points[i]), output.point(c.points[i + 1])));
  std::cout << "    fault tip length " << free_length << " (input 10.4)\n";
  assert(std::abs(free_length - 10.4) < 1e-9);
  for(const Point& corner : {Point(5, 2, 2.3), Point(5, 6, 2.3), Point(5, 6, 3.5), Point(5, 2, 3.5)})
    assert(std::find(output.points().begin(), output.points().end(), corner) != output.points().end());
  // deterministic, and the same on one thread as on several
  Model again, sequential;
  BM::remesh_surfaces(input, again, np);
  assert(again.points() == output.points());
  assert(again.triangles() == output.triangles());
  BM::remesh_surfaces<CGAL::Sequential_tag>(input, sequential, np);
  assert(sequential.points() == output.points());
  assert(sequential.triangles() == output.triangles());
  std::cout << "    same output with CGAL::Sequential_tag (" << r.number_of_charts << " charts)\n";
}

// A patch that covers part of its plane twice (the horizon of
// overhang_model()) is not one chart: flattened as one, the band covered
// twice fell out of the chart's domain and the new triangles along both
// fault cut lines lay on the wrong side of them (inconsistently oriented
// region boundaries).
void test_overhang()
{
  std::cout << "remesh_surfaces on a horizon offset by a reverse fault\n";
  const Model input = overhang_model();
  BM::validate_geological_model(input);
  const BM::Model_features f = BM::detect_model_features(input);
  const BM::internal::Edge_triangles_map et = BM::internal::edge_triangles(input);
  BM::internal::Edge_set feature_edges;
  for(const auto& c : f.curves)
    for(std::size_t i = 0; i + 1 < c.points.size(); ++i)
      feature_edges[BM::internal::edge_key(c.points[i], c.points[i + 1])] = 1;
  const std::size_t h = 2;
  assert(input.patch(h).name == "h");
  BM::internal::Remesh_chart<K> whole;
  whole.patch = h;
  whole.triangles = f.patch_triangles[h];
  BM::internal::set_chart_frame(input, whole);
  // every triangle faces up and no border crosses another, yet it is no chart
  assert(!BM::internal::is_valid_chart(input, whole, et, feature_edges));
  // the footwall side alone is one
  BM::internal::Remesh_chart<K> sheet = whole;
  sheet.triangles.clear();
  for(std::size_t t : whole.triangles)
    if(CGAL::centroid(input.point(input.triangle(t)[0]), input.point(input.triangle(t)[1]),
                      input.point(input.triangle(t)[2])).x() < 4.5)
      sheet.triangles.push_back(t);
  BM::internal::set_chart_frame(input, sheet);
  assert(BM::internal::is_valid_chart(input, sheet, et, feature_edges));

  Model output;
  const auto np = BM::parameters::edge_length(0.5);
  BM::Remeshing_sizing_field<K> field(input, f, np);
  const BM::Remeshing_sizing_field<K> given = field;
  const BM::Surface_remeshing_report r = BM::remesh_surfaces(
    input, output, BM::parameters::sizing_field_output(&field, BM::parameters::keep_region_volumes(true, np)));
  print("overhang", r);
  assert(r.number_of_chart_cuts > 0);
  // The strip f is a lens narrower than the size, with 24-degree tips:
  // triangles across it next to the tips are under 25 degrees without being
  // at a tip. h bends by a few degrees at the fault: chords across those folds
  // move the volumes a little (the surface is planar elsewhere), and the free
  // points slide along h until every region has its volume back
  check_remeshed(input, output, r, field, given, false, true);
  assert(r.number_of_volume_balancing_steps > 0 && r.number_of_volume_balancing_points > 0);

  // without the balance: the chords' error, which the balance started from
  Model unbalanced;
  const BM::Surface_remeshing_report u =
    BM::remesh_surfaces(input, unbalanced, BM::parameters::keep_region_volumes(false, np));
  std::cout << "  without the balance: largest relative volume error " << u.max_relative_volume_error << "\n";
  assert(u.max_relative_volume_error > 1e-6 && u.max_relative_volume_error < 1e-3);
  assert(u.number_of_volume_balancing_steps == 0 && u.volume_error_before_balancing == 0.);
  // (the balance sums the volumes of its own point list, around the box's centre, the
  // report those of the output model, after the snap to axis planes: the same chords
  // give the same error up to rounding)
  assert(std::abs(r.volume_error_before_balancing - u.max_relative_volume_error) <= 1e-9 * u.max_relative_volume_error);
  // the same triangles, the same curve points; the free points moved, and no
  // angle they touch fell under the bound
  assert(unbalanced.number_of_triangles() == output.number_of_triangles());
  assert(unbalanced.number_of_points() == output.number_of_points());
  std::size_t moved = 0;
  for(std::size_t v = 0; v < output.number_of_points(); ++v) moved += (output.point(v) != unbalanced.point(v));
  assert(moved == r.number_of_volume_balancing_points);
  assert(r.number_of_small_angle_triangles <= u.number_of_small_angle_triangles);
  assert(r.min_angle >= (std::min)(u.min_angle, 25.) - 1e-9);
}

// A region no free point can change (a coarse lens whose points all lie near
// curves or needles: the graben of bench/make_graben_model.py) must not hold
// back the balance of the others. Here a cone under a spherical cap (its
// points on the sphere, the inner ones free) gets its volume back while a
// tetrahedron with fixed points keeps its larger error. Before, the balance
// undid its first step, which left the largest error as it was, and moved
// nothing. `enclosed`: the cap is shared with a second region above it, closed
// by a fixed lid, and the tetrahedron is a hole in that region. No slide then
// changes the two regions' total volume, and their targets miss it by what
// the tetrahedron lost: each gets its target less its share of that volume,
// in proportion to its volume (before, the solve was singular there and its
// steps went astray).
void test_balance_beside_an_immovable_region(bool enclosed)
{
  std::cout << "volume balance beside a region no point can change" << (enclosed ? ", inside a closed group" : "")
            << "\n";
  typedef std::array<std::size_t, 3> Tri;
  const int n = 11; // points per side of the cap's grid over [0, 2]^2
  const Point centre(1., 1., -2.);
  const double radius = 3.;
  std::vector<Point> points;
  std::vector<char> fixed;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const double x = 2. * i / (n - 1), y = 2. * j / (n - 1);
      points.push_back(Point(x, y, centre.z() + std::sqrt(radius * radius - (x - 1.) * (x - 1.) - (y - 1.) * (y - 1.))));
      fixed.push_back(i == 0 || j == 0 || i == n - 1 || j == n - 1);
    }
  auto add_fixed = [&](const Point& q) {
    points.push_back(q);
    fixed.push_back(1);
    return points.size() - 1;
  };
  const std::size_t bottom = add_fixed(Point(1., 1., -1.)), top = add_fixed(Point(1., 1., 3.));
  // patches: the cap, the cone under it, the tetrahedron, the lid
  std::vector<std::vector<Tri> > patches(4);
  auto at = [&](int i, int j) { return std::size_t(j * n + i); };
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i)
    {
      patches[0].push_back(Tri{{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
      patches[0].push_back(Tri{{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
    }
  // the cones from the cap's border to the bottom and top points, the border walked counterclockwise
  std::vector<std::size_t> border;
  for(int i = 0; i + 1 < n; ++i) border.push_back(at(i, 0));
  for(int j = 0; j + 1 < n; ++j) border.push_back(at(n - 1, j));
  for(int i = n - 1; i > 0; --i) border.push_back(at(i, n - 1));
  for(int j = n - 1; j > 0; --j) border.push_back(at(0, j));
  for(std::size_t k = 0; k < border.size(); ++k)
  {
    patches[1].push_back(Tri{{border[(k + 1) % border.size()], border[k], bottom}});
    patches[3].push_back(Tri{{border[k], border[(k + 1) % border.size()], top}});
  }
  // the tetrahedron, all its points fixed: apart, or a hole in the region above the cap
  const Vector shift = enclosed ? Vector(0.9, 0.9, 1.6) : Vector(5., 0., 0.);
  const double e = enclosed ? 0.2 : 1.;
  const std::size_t t0 = add_fixed(Point(0, 0, 0) + shift);
  add_fixed(Point(e, 0, 0) + shift);
  add_fixed(Point(0, e, 0) + shift);
  add_fixed(Point(0, 0, e) + shift);
  patches[2] = {Tri{{t0, t0 + 2, t0 + 1}}, Tri{{t0, t0 + 1, t0 + 3}}, Tri{{t0, t0 + 3, t0 + 2}},
                Tri{{t0 + 1, t0 + 2, t0 + 3}}};
  if(!enclosed) patches[3].clear();
  const std::size_t above = enclosed ? 3 : 0;
  const std::vector<std::pair<std::size_t, std::size_t> > sides = {{2, above}, {2, 0}, {1, above}, {3, 0}};
  const BM::internal::Centred_point origin{{0., 0., 0.}};
  std::vector<double> volume(4, 0.);
  auto volumes = [&](const std::vector<Point>& q) {
    std::fill(volume.begin(), volume.end(), 0.);
    for(std::size_t p = 0; p < patches.size(); ++p)
      for(const Tri& t : patches[p])
      {
        const double v = BM::internal::signed_volume(BM::internal::centred(q[t[0]], origin),
                                                     BM::internal::centred(q[t[1]], origin),
                                                     BM::internal::centred(q[t[2]], origin));
        volume[sides[p].first] += v;
        volume[sides[p].second] -= v;
      }
    return volume;
  };
  auto project = [&](const Point& q, std::size_t p) {
    if(p != 0) return std::make_pair(q, Vector(0., 0., 1.));
    Vector u = q - centre;
    u = u / std::sqrt(u.squared_length());
    return std::make_pair(centre + radius * u, u);
  };
  // the cone's target: its volume with one inner point slid a little along the sphere
  std::vector<Point> slid = points;
  slid[at(4, 6)] = project(slid[at(4, 6)] + Vector(0.05, 0.03, 0.), 0).first;
  const std::vector<double> start = volumes(points), moved = volumes(slid);
  assert(std::abs(start[1] - e * e * e / 6.) < 1e-12);
  assert(std::abs(moved[2] - start[2]) > 1e-9 * start[2] && std::abs(moved[2] - start[2]) < 1e-3 * start[2]);
  // the tetrahedron's input was 1 % larger; enclosed, the region around it was
  // smaller by as much, and what the cone gains it loses
  std::vector<double> target = {0., 1.01 * start[1], moved[2], 0.};
  std::vector<char> balanced = {0, 1, 1, 0};
  if(enclosed)
  {
    target[3] = moved[3] - 0.01 * start[1];
    balanced[3] = 1;
  }
  auto size = [](const Point&, std::size_t) { return 0.2; };
  const std::vector<Point> before = points;
  const BM::internal::Volume_balance_result r =
    BM::internal::balance_region_volumes(points, patches, fixed, sides, target, balanced, origin, project, size, 25.);
  std::cout << "  " << r.iterations << " steps, " << r.moved_points << " points moved; cone " << r.relative_errors[2]
            << " (from " << std::abs(start[2] - target[2]) / target[2] << "), tetrahedron " << r.relative_errors[1];
  if(enclosed) std::cout << ", above the cap " << r.relative_errors[3];
  std::cout << "\n";
  assert(r.iterations > 0 && r.moved_points > 0);
  assert(r.immovable[1] && !r.immovable[2] && r.residual_errors[1] == 0.);
  assert(std::abs(r.relative_errors[1] - 0.01 / 1.01) < 1e-12);
  if(!enclosed) assert(r.relative_errors[2] < 1e-9);
  else
  {
    // both off by the same share, 0.01 of the tetrahedron over their volumes
    // (2.5e-6), up to the balance's tolerance (1e-9)
    const double share = 0.01 * start[1] / (target[2] + target[3]);
    assert(std::abs(r.relative_errors[2] - share) < 1.01e-9);
    assert(std::abs(r.relative_errors[3] - share) < 1.01e-9);
    assert(r.residual_errors[2] < 1e-9 && r.residual_errors[3] < 1e-9);
  }
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    if(fixed[v]) assert(points[v] == before[v]);
    else assert(std::abs(std::sqrt((points[v] - centre).squared_length()) - radius) < 1e-12);
  }
}

// The pipe is convex and faceted coarsely: every chord across its creases
// cuts into it, so no slide along its surface gives its volume back, and the
// rock around it gains what it loses. With keep_region_volumes, its patch is
// re-meshed again with every crease kept as a curve.
void test_faceted_body()
{
  std::cout << "remesh_surfaces keeping the volume of a faceted pipe\n";
  const Model input = pipe_model();
  const auto np = BM::parameters::edge_length(1.);
  Model chords;
  const BM::Surface_remeshing_report u = BM::remesh_surfaces(input, chords, BM::parameters::keep_region_volumes(false, np));
  std::cout << "  without the balance: largest relative volume error " << u.max_relative_volume_error << "\n";
  assert(u.max_relative_volume_error > 1e-4);
  assert(u.number_of_faceted_patches == 0);

  Model output;
  BM::Remeshing_sizing_field<K> field(input, BM::detect_model_features(input), np);
  const BM::Surface_remeshing_report r = BM::remesh_surfaces(
    input, output, BM::parameters::sizing_field_output(&field, BM::parameters::keep_region_volumes(true, np)));
  print("faceted pipe", r);
  // the pipe's patch only: the outer walls bound the rock, which was left out
  // too, but they are flat and have no crease to keep
  assert(r.number_of_faceted_patches == 1);
  assert(r.regions_not_balanced.empty());
  // the field with the creases as curves: its own measure of the sizes
  check_remeshed(input, output, r, field, field, true, true);
  // every crease of the pipe lies along output edges (the chords cut across them)
  std::vector<Segment> edges;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
    for(int k = 0; k < 3; ++k)
      edges.push_back(Segment(output.point(output.triangle(t)[k]), output.point(output.triangle(t)[(k + 1) % 3])));
  const BM::internal::Edge_triangles_map et = BM::internal::edge_triangles(input);
  std::size_t creases = 0;
  for(const auto& e : et)
  {
    if(e.second.size() != 2 || input.patch_of_triangle(e.second[0]) != 1 || input.patch_of_triangle(e.second[1]) != 1)
      continue;
    const auto normal = [&](std::size_t t) {
      const auto& tri = input.triangle(t);
      return CGAL::unit_normal(input.point(tri[0]), input.point(tri[1]), input.point(tri[2]));
    };
    if(normal(e.second[0]) * normal(e.second[1]) > 0.9999) continue; // within one flat facet or cap
    ++creases;
    const Point m = CGAL::midpoint(input.point(e.first.first), input.point(e.first.second));
    double nearest = 1.;
    for(const Segment& s : edges) nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(m, s)));
    assert(nearest < 1e-9);
  }
  std::cout << "  " << creases << " input crease edges, each along output edges\n";
  assert(creases >= 24 * 24);
}

// A ribbon: the top face of a box holds a strip between two curves that meet at
// a corner at atan(1/20) = 2.86 degrees and end 0.5 apart, 10 away (a fault strip
// between two horizon cut lines). The curves touch, so the curve proximity rule
// skips them, and the strip used to be spanned by needles of the patch size; the
// ribbon rule (refine_ribbons) sizes it by its width, so that its triangles away from the corner
// are as good as elsewhere.
void test_ribbon()
{
  std::cout << "a ribbon between two curves meeting at 2.86 degrees\n";
  Builder b;
  const std::size_t rock = b.model.add_region("rock");
  const std::size_t skin = b.model.add_patch("skin", 0, rock), strip = b.model.add_patch("strip", 0, rock),
                    top = b.model.add_patch("top", 0, rock);
  b.set_edge(Point(10, 0, 4), Point(10, 8, 4), {0.0625});
  b.rectangle(skin, Point(0, 0, 0), Point(10, 0, 0), Point(10, 8, 0), Point(0, 8, 0), Vector(0, 0, -1));
  b.rectangle(skin, Point(0, 0, 0), Point(10, 0, 0), Point(10, 0, 4), Point(0, 0, 4), Vector(0, -1, 0));
  b.rectangle(skin, Point(0, 8, 0), Point(10, 8, 0), Point(10, 8, 4), Point(0, 8, 4), Vector(0, 1, 0));
  b.rectangle(skin, Point(0, 0, 0), Point(0, 8, 0), Point(0, 8, 4), Point(0, 0, 4), Vector(-1, 0, 0));
  b.rectangle(skin, Point(10, 0, 0), Point(10, 8, 0), Point(10, 8, 4), Point(10, 0, 4), Vector(1, 0, 0));
  const Point o(0, 0, 4), e(10, 0, 4), s(10, 0.5, 4);
  b.polygon(strip, {o, e, s}, CGAL::centroid(o, e, s), Vector(0, 0, 1));
  b.rectangle(top, o, s, Point(10, 8, 4), Point(0, 8, 4), Vector(0, 0, 1));
  const Model& input = b.model;
  BM::validate_geological_model(input);
  const BM::Model_features f = BM::detect_model_features(input);
  // by default the rule is off: the strip is spanned at the floor of the thickness rule or more
  const BM::Remeshing_sizing_field<K> plain(input, f, BM::parameters::edge_length(1.));
  assert(plain(Point(5, 0, 4), strip) >= plain.minimum_size());
  const auto np = BM::parameters::edge_length(1., BM::parameters::refine_ribbons(true));
  BM::Remeshing_sizing_field<K> field(input, f, np);
  // on the strip's straight side, the width across at x is x sin(atan(1/20)), and
  // the samples are half a size apart (the grading adds at most a quarter of it)
  for(double x : {2., 5., 8.})
  {
    const double width = x * std::sin(std::atan(0.05)), h = field(Point(x, 0, 4), strip);
    std::cout << "  size at x = " << x << ": " << h << " (width " << width << ")\n";
    assert(h <= 1.25 * width && h >= 0.5 * width);
  }
  const BM::Remeshing_sizing_field<K> given = field;
  Model output;
  const BM::Surface_remeshing_report r = BM::remesh_surfaces(input, output, BM::parameters::sizing_field_output(&field, np));
  print("ribbon", r);
  check_remeshed(input, output, r, field, given, false, false);
  // the strip's triangles where it is wider than the floor of the thickness rule
  // (x > 2) are not needles
  double worst = 180.;
  std::size_t in_strip = 0;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
  {
    if(output.patch_of_triangle(t) != strip) continue;
    ++in_strip;
    const auto& tri = output.triangle(t);
    if(CGAL::centroid(output.point(tri[0]), output.point(tri[1]), output.point(tri[2])).x() > 2.)
      worst = (std::min)(worst, min_angle(output, t));
  }
  std::cout << "  strip: " << in_strip << " triangles, smallest angle where x > 2: " << worst << "\n";
  assert(worst >= 20.);
  // the triangles under 25 degrees are those of the strip with their three
  // points on its two sides (o e and o s), in the wedge of the corner o
  auto on_sides = [&](const Point& q) {
    return CGAL::squared_distance(q, K::Segment_3(o, e)) < 1e-20 || CGAL::squared_distance(q, K::Segment_3(o, s)) < 1e-20;
  };
  std::size_t small = 0, spanning = 0;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
  {
    if(!(min_angle(output, t) < 25.)) continue;
    ++small;
    const auto& tri = output.triangle(t);
    if(output.patch_of_triangle(t) == strip && on_sides(output.point(tri[0])) && on_sides(output.point(tri[1])) &&
       on_sides(output.point(tri[2])))
      ++spanning;
  }
  std::cout << "  " << small << " triangles under 25 degrees, " << spanning << " spanning the wedge, "
            << r.number_of_small_angle_triangles_in_sharp_wedges << " in it by the report\n";
  assert(spanning > 0 && spanning == small);
  assert(r.number_of_small_angle_triangles_in_sharp_wedges == spanning);

  // each of them is listed with the corner's own angle, atan(1/20) = 2.86 degrees
  const double corner = std::atan(0.05) * 180. / CGAL_PI;
  assert(r.corner_forced_triangles.size() == spanning);
  for(const auto& cf : r.corner_forced_triangles)
  {
    assert(output.patch_of_triangle(cf.triangle) == strip && std::abs(cf.corner_angle - corner) < 1e-6);
    for(int k = 0; k < 3; ++k)
      assert(output.point(output.triangle(cf.triangle)[std::size_t(k)]) ==
             Point(cf.points[std::size_t(k)][0], cf.points[std::size_t(k)][1], cf.points[std::size_t(k)][2]));
  }
  // and a tetrahedral mesh's facet on one of them (its corners in another order)
  // counts with that angle, any other facet with its own
  struct Vertex { Point p; const Point& point() const { return p; } };
  struct Cell { std::array<const Vertex*, 4> v; const Vertex* vertex(int k) const { return v[std::size_t(k)]; } };
  struct Complex { typedef std::pair<const Cell*, int> Facet; };
  const BM::Corner_forced_facet_angle<Complex> facet_angle(r);
  // (the widest of them: the ones at the tip are as sharp as the corner)
  const auto& cf = *std::max_element(r.corner_forced_triangles.begin(), r.corner_forced_triangles.end(),
                                     [&](const auto& x, const auto& y) {
                                       return min_angle(output, x.triangle) < min_angle(output, y.triangle);
                                     });
  auto at = [&](int k) { return Vertex{Point(cf.points[std::size_t(k)][0], cf.points[std::size_t(k)][1], cf.points[std::size_t(k)][2])}; };
  const Vertex a = at(0), b2 = at(1), c = at(2);
  // the apex makes an equilateral triangle with a and b2, which is in no wedge
  const K::Vector_3 ab = b2.p - a.p, up = CGAL::cross_product(ab, K::Vector_3(0, 0, 1));
  const Vertex apex{CGAL::midpoint(a.p, b2.p) + up * (0.866 * std::sqrt(ab.squared_length() / up.squared_length()))};
  const Cell cell{{{&apex, &c, &a, &b2}}};
  const double own = min_angle(output, cf.triangle);
  std::cout << "  a facet on a wedge triangle of " << own << " degrees counts " << facet_angle(Complex::Facet(&cell, 0))
            << " (the corner " << corner << ")\n";
  assert(own > corner + 1. && std::abs(facet_angle(Complex::Facet(&cell, 0)) - corner) < 1e-6);
  const double side = facet_angle(Complex::Facet(&cell, 1)); // apex, a, b2
  assert(side > 59. && side < 61.);
}

// A free vertex crowded against a curve edge: a hexagon of fixed points
// around a free centre c, with a second free vertex d at 0.1 from the edge
// H0 H1 (triangle d H0 H1 of 11.3 degrees). Collapsing d away leaves the six
// equilateral triangles; with sizes too small for the edges that would make,
// nothing changes. Then two free points crowded together.
void test_collapse_crowded_vertex()
{
  std::cout << "a free vertex crowded against a curve edge\n";
  std::vector<Point> pts;
  for(int k = 0; k < 6; ++k) pts.push_back(Point(std::cos(k * CGAL_PI / 3.), std::sin(k * CGAL_PI / 3.), 0.));
  const std::size_t c = pts.size();
  pts.push_back(Point(0, 0, 0));
  const std::size_t d = pts.size();
  const double r = std::sqrt(0.75) - 0.1; // 0.1 inside the edge H0 H1
  pts.push_back(Point(r * std::cos(CGAL_PI / 6.), r * std::sin(CGAL_PI / 6.), 0.));
  std::vector<char> fixed(pts.size(), 1);
  fixed[c] = fixed[d] = 0;
  std::vector<std::array<std::size_t, 3> > tris{{{c, 0, d}}, {{c, d, 1}}, {{d, 0, 1}}};
  for(std::size_t k = 1; k < 6; ++k) tris.push_back({{c, k, (k + 1) % 6}});
  auto smallest = [&](const std::vector<std::array<std::size_t, 3> >& ts) {
    double m = 180.;
    for(const auto& t : ts) m = (std::min)(m, BM::internal::min_angle_degrees(pts[t[0]], pts[t[1]], pts[t[2]]));
    return m;
  };
  assert(smallest(tris) < 12.);
  auto in_plane = [](const Point& q) { return Point(q.x(), q.y(), 0.); };
  // sizes of 0.5: the collapse would make edges of 1, twice the size
  std::vector<std::array<std::size_t, 3> > small_sizes = tris;
  assert(BM::internal::collapse_crowded_vertices(pts, small_sizes, fixed, [](const Point&) { return 0.5; }, in_plane, 25.) == 0);
  assert(small_sizes == tris);
  assert(BM::internal::collapse_crowded_vertices(pts, tris, fixed, [](const Point&) { return 1.; }, in_plane, 25.) == 1);
  std::cout << "  " << tris.size() << " triangles, smallest angle " << smallest(tris) << "\n";
  assert(tris.size() == 6 && smallest(tris) > 59.99);
  std::set<std::size_t> used;
  for(const auto& t : tris) used.insert(t.begin(), t.end());
  assert(used.count(d) == 0 && used.count(c) == 1 && used.size() == 7);

  // two free points 0.2 apart about the centre: either one kept in place
  // leaves the fan off-centre; both moved to their middle make it regular
  pts.resize(6);
  const std::size_t c1 = pts.size(), c2 = c1 + 1;
  pts.push_back(Point(-0.1, 0, 0));
  pts.push_back(Point(0.1, 0, 0));
  fixed.assign(pts.size(), 1);
  fixed[c1] = fixed[c2] = 0;
  tris = {{{c2, 5, 0}}, {{c2, 0, 1}}, {{c2, 1, c1}}, {{c1, 1, 2}}, {{c1, 2, 3}}, {{c1, 3, 4}}, {{c2, c1, 4}}, {{c2, 4, 5}}};
  assert(smallest(tris) < 15.);
  assert(BM::internal::collapse_crowded_vertices(pts, tris, fixed, [](const Point&) { return 1.; }, in_plane, 25.) == 1);
  std::cout << "  two free points: " << tris.size() << " triangles, smallest angle " << smallest(tris) << "\n";
  assert(tris.size() == 6 && smallest(tris) > 59.99);
  used.clear();
  for(const auto& t : tris) used.insert(t.begin(), t.end());
  const std::size_t kept = used.count(c1) ? c1 : c2;
  assert(used.size() == 7 && CGAL::squared_distance(pts[kept], Point(0, 0, 0)) < 1e-24);
}

// The square [-h, h]^2 of the plane z = 0 as one patch (two triangles): the
// surface that the moves of the tests below are projected onto.
Model square_patch(double h)
{
  Model plane;
  const std::size_t region = plane.add_region("below");
  const std::size_t patch = plane.add_patch("plane", 0, region);
  for(const Point& q : {Point(-h, -h, 0), Point(h, -h, 0), Point(h, h, 0), Point(-h, h, 0)}) plane.add_point(q);
  plane.add_triangle(0, 1, 2, patch);
  plane.add_triangle(0, 2, 3, patch);
  return plane;
}

// A free vertex whose best place is not at the centre of its neighbours, nor
// at the apex that would make one of its triangles equilateral: an uneven
// ring of seven fixed points (from a random draw) around it, where the centre
// gives a smallest angle of 4 degrees and the best place about 14.7 (a grid of
// 161 x 161 points over the ring). The smoothing's compass search must get
// within half a degree of the grid's best.
void test_smooth_to_best_place()
{
  std::cout << "a free vertex in an uneven ring\n";
  const Model plane = square_patch(5.);
  const BM::internal::Remesh_triangle_tree<K> tree(plane, std::vector<std::size_t>{0, 1});
  std::vector<Point> pts{Point(1.286, 0.864, 0),  Point(0.265, 0.416, 0), Point(0.08, 0.962, 0),
                         Point(-1.076, 0.481, 0), Point(-1.023, 0.135, 0), Point(-1.128, -0.64, 0),
                         Point(0.492, -1.474, 0)};
  const std::size_t n = pts.size();
  double x = 0., y = 0.;
  for(const Point& q : pts) { x += q.x() / double(n); y += q.y() / double(n); }
  pts.push_back(Point(x, y, 0));
  std::vector<std::array<std::size_t, 3> > tris;
  for(std::size_t k = 0; k < n; ++k) tris.push_back({{n, k, (k + 1) % n}});
  std::vector<char> fixed(pts.size(), 1);
  fixed[n] = 0;
  // the smallest angle of the fan with the free vertex at q, or -1 if a triangle turns over
  auto fan = [&](const Point& q) {
    double m = 180.;
    for(const auto& t : tris)
    {
      const Point& a = pts[t[1]];
      const Point& b = pts[t[2]];
      if(CGAL::orientation(K::Point_2(q.x(), q.y()), K::Point_2(a.x(), a.y()), K::Point_2(b.x(), b.y())) != CGAL::LEFT_TURN)
        return -1.;
      m = (std::min)(m, BM::internal::min_angle_degrees(q, a, b));
    }
    return m;
  };
  const double at_centre = fan(pts[n]);
  double grid_best = -1.;
  for(int i = 0; i <= 160; ++i)
    for(int j = 0; j <= 160; ++j)
      grid_best = (std::max)(grid_best, fan(Point(-2. + 0.025 * i, -2. + 0.025 * j, 0)));
  BM::internal::smooth_free_vertices<K>(pts, tris, fixed, tree, 30.);
  const double got = fan(pts[n]);
  std::cout << "  smallest angle at the centre " << at_centre << ", smoothed " << got << ", grid's best " << grid_best << "\n";
  assert(at_centre < 5. && grid_best > 14.);
  assert(got >= grid_best - 0.5);
}

// A free vertex pushed past its ring, so that two of its six triangles face
// the other way (slivers of a chart mapped back onto a wrinkled input patch:
// modelA5's h1_2 with the thickness rule's floor at 7 or 8). Moves that keep
// them turned over slid them over their neighbours, and the re-meshed patch
// crossed itself; the smoothing must bring the vertex back inside its ring,
// every triangle facing the side most of them face.
void test_smooth_turns_triangles_back()
{
  std::cout << "a free vertex outside its ring\n";
  const Model plane = square_patch(5.);
  const BM::internal::Remesh_triangle_tree<K> tree(plane, std::vector<std::size_t>{0, 1});
  std::vector<Point> pts;
  for(int k = 0; k < 6; ++k) pts.push_back(Point(std::cos(k * CGAL_PI / 3.), std::sin(k * CGAL_PI / 3.), 0));
  pts.push_back(Point(1.3, 0.1, 0));
  std::vector<std::array<std::size_t, 3> > tris;
  for(std::size_t k = 0; k < 6; ++k) tris.push_back({{6, k, (k + 1) % 6}});
  std::vector<char> fixed(pts.size(), 1);
  fixed[6] = 0;
  auto turned_over = [&]() {
    int n = 0;
    for(const auto& t : tris)
      n += CGAL::orientation(K::Point_2(pts[t[0]].x(), pts[t[0]].y()), K::Point_2(pts[t[1]].x(), pts[t[1]].y()),
                             K::Point_2(pts[t[2]].x(), pts[t[2]].y())) != CGAL::LEFT_TURN;
    return n;
  };
  const int before = turned_over();
  BM::internal::smooth_free_vertices<K>(pts, tris, fixed, tree, 30.);
  std::cout << "  triangles turned over " << before << " -> " << turned_over() << ", vertex at " << pts[6] << "\n";
  assert(before == 2);
  assert(turned_over() == 0);
  assert(pts[6].z() == 0.);
}

// The rule both the smoothing and the slide of curve samples apply to a
// triangle around a moving point: face the star's side, turn by at most 60
// degrees, and a triangle facing away may only turn back.
void test_keeps_facing_star()
{
  std::cout << "a moved triangle against the side its star faces\n";
  typedef K::Vector_3 V;
  const V up(0, 0, 1), star(0, 0, 3);
  const double c50 = std::cos(50. * CGAL_PI / 180.), s50 = std::sin(50. * CGAL_PI / 180.);
  const double c70 = std::cos(70. * CGAL_PI / 180.), s70 = std::sin(70. * CGAL_PI / 180.);
  assert(BM::internal::keeps_facing_star(V(s50, 0, c50), up, star));   // turned 50 degrees
  assert(!BM::internal::keeps_facing_star(V(s70, 0, c70), up, star));  // turned 70 degrees
  assert(!BM::internal::keeps_facing_star(V(0, 0, -1), up, star));     // turned over
  const V over(0, 0.6, -0.8);                                           // facing away before the move
  assert(!BM::internal::keeps_facing_star(V(0, 0.8, -0.6), over, star)); // staying over is refused,
  assert(BM::internal::keeps_facing_star(V(0, 0.6, 0.8), over, star));   // turning back is not, by any angle
}

// A triangle under 25 degrees between three curve samples (fixed points) -
// a strip's sides sampled closer than its width, modelA2's last one - is
// split across its longest free edge when the new point can lift the four
// triangles around it over the bound, and left as it is when it cannot (the
// triangle across that edge a needle itself).
void test_split_fixed_triangle()
{
  std::cout << "a triangle between three curve samples\n";
  const Model plane = square_patch(20.);
  const BM::internal::Remesh_triangle_tree<K> tree(plane, std::vector<std::size_t>{0, 1});
  for(const Point& far : {Point(6, 8, 0), Point(2.0, 4.5, 0)})
  {
    // A, B on one curve, C on the other, D beyond the free edge B C
    std::vector<Point> pts{Point(0, 0, 0), Point(3.66, 0, 0), Point(0, 8.8, 0), far};
    std::vector<std::array<std::size_t, 3> > tris{{{0, 1, 2}}, {{2, 1, 3}}};
    std::vector<char> fixed(pts.size(), 1);
    BM::internal::Edge_set curves;
    for(const auto& e : {std::make_pair(0, 1), std::make_pair(0, 2), std::make_pair(1, 3), std::make_pair(2, 3)})
      curves[BM::internal::edge_key(std::size_t(e.first), std::size_t(e.second))] = 1;
    auto smallest = [&]() {
      double m = 180.;
      for(const auto& t : tris) m = (std::min)(m, BM::internal::min_angle_degrees(pts[t[0]], pts[t[1]], pts[t[2]]));
      return m;
    };
    const double before = smallest();
    const std::vector<std::array<std::size_t, 3> > old = tris;
    const std::size_t splits = BM::internal::split_fixed_triangles<K>(pts, tris, fixed, curves, tree, 25.);
    std::cout << "  D at " << far << ": smallest angle " << before << " -> " << smallest() << ", " << splits << " split\n";
    assert(before < 23.);
    if(far == Point(6, 8, 0))
    {
      assert(splits == 1 && tris.size() == 4 && pts.size() == 5 && fixed.size() == 5 && !fixed[4]);
      assert(smallest() >= 25.);
      assert(pts[4].z() == 0.);
    }
    else
      assert(splits == 0 && tris == old && pts.size() == 4 && fixed.size() == 4);
  }
}

// A layer `thickness` thick in the box [0,10] x [0,8] x [0,6], with a floor
// of the thickness rule (0.6) well over its thickness: its sides on the
// box's walls are strips whose two long curves are sampled alike.
// - 0.2 thick, at the floor (about 0.65 apart): points facing each other cut
//   the strip into right triangles of atan(0.2 / 0.65) = 17 degrees; one
//   side's points half-way between the other's make isosceles ones of
//   atan(0.4 / 0.65) = 32 degrees.
// - 0.1 thick: at the floor even those would be 17 degrees; the strip's
//   sides are sampled at 3.5 times its width instead (the sizing field's
//   strip rule), and the half-way points make triangles of 30 degrees.
//
// With `widening`, the layer's top rises by that much per unit of x: a
// strip whose width, and so the strip rule's size, grows along its sides.
// 0.05 thick, widening 0.02: the strip rule's sizes go from 0.175 (the
// rule's floor is 0.15) to the floor at x = 6.1; each side is one curve
// piece, and its points go half-way between the other's at the local
// spacing (at the piece's mean spacing, many faced each other).
void test_thin_layer_sides(double thickness, double widening = 0.)
{
  std::cout << "a layer " << thickness << " thick";
  if(widening > 0.) std::cout << ", widening by " << widening << " per unit";
  std::cout << ", meeting the walls, with a floor of 0.6\n";
  Builder b;
  const double z[4] = {0., 3., 3. + thickness, 6.};
  // the z of boundary r (0 to 3) at x
  auto z_at = [&](int r, double x) { return r == 2 ? z[2] + widening * x : z[r]; };
  const std::size_t regions[3] = {b.model.add_region("lower"), b.model.add_region("layer"), b.model.add_region("upper")};
  const std::size_t base = b.model.add_patch("base", 0, regions[0]), roof = b.model.add_patch("roof", 0, regions[2]);
  b.rectangle(base, Point(0, 0, 0), Point(10, 0, 0), Point(10, 8, 0), Point(0, 8, 0), Vector(0, 0, -1));
  b.rectangle(roof, Point(0, 0, 6), Point(10, 0, 6), Point(10, 8, 6), Point(0, 8, 6), Vector(0, 0, 1));
  std::size_t layer_sides = 0;
  for(int r = 0; r < 3; ++r)
  {
    if(r > 0)
    {
      const std::size_t h = b.model.add_patch("h" + std::to_string(r), regions[r], regions[r - 1]);
      b.rectangle(h, Point(0, 0, z_at(r, 0)), Point(10, 0, z_at(r, 10)), Point(10, 8, z_at(r, 10)), Point(0, 8, z_at(r, 0)),
                  Vector(0, 0, 1));
    }
    const std::size_t side = b.model.add_patch("sides" + std::to_string(r), 0, regions[r]);
    if(r == 1) layer_sides = side;
    const double lo0 = z_at(r, 0), lo10 = z_at(r, 10), hi0 = z_at(r + 1, 0), hi10 = z_at(r + 1, 10);
    b.rectangle(side, Point(0, 0, lo0), Point(10, 0, lo10), Point(10, 0, hi10), Point(0, 0, hi0), Vector(0, -1, 0));
    b.rectangle(side, Point(10, 0, lo10), Point(10, 8, lo10), Point(10, 8, hi10), Point(10, 0, hi10), Vector(1, 0, 0));
    b.rectangle(side, Point(10, 8, lo10), Point(0, 8, lo0), Point(0, 8, hi0), Point(10, 8, hi10), Vector(0, 1, 0));
    b.rectangle(side, Point(0, 8, lo0), Point(0, 0, lo0), Point(0, 0, hi0), Point(0, 8, hi0), Vector(-1, 0, 0));
  }
  const Model& input = b.model;
  BM::validate_geological_model(input);
  const auto np = BM::parameters::edge_length(1., BM::parameters::minimum_edge_length(0.6));
  BM::Remeshing_sizing_field<K> field(input, BM::detect_model_features(input), np);
  const BM::Remeshing_sizing_field<K> given = field;
  Model output;
  const BM::Surface_remeshing_report r = BM::remesh_surfaces(input, output, BM::parameters::sizing_field_output(&field, np));
  print("thin layer's sides", r);
  double worst = 180.;
  std::size_t on_sides = 0;
  for(std::size_t t = 0; t < output.number_of_triangles(); ++t)
    if(output.patch_of_triangle(t) == layer_sides)
    {
      ++on_sides;
      worst = (std::min)(worst, min_angle(output, t));
      if(min_angle(output, t) < 25.)
      {
        const auto& tri = output.triangle(t);
        std::cout << "      under 25 degrees: " << min_angle(output, t) << " at " << output.point(tri[0]) << ", "
                  << output.point(tri[1]) << ", " << output.point(tri[2]) << "\n";
      }
    }
  std::cout << "    layer's sides: " << on_sides << " triangles, smallest angle " << worst << "\n";
  assert(on_sides > 100 && worst >= 25.);
  // one of the two long curves of each of the four sides
  std::cout << "    " << r.number_of_staggered_curve_pieces << " curve pieces staggered\n";
  assert(r.number_of_staggered_curve_pieces == 4);
  check_remeshed(input, output, r, field, given, true, true);
}

// GOCAD models named on the command line, looked up in ../shared when not a path
// (a real model takes tens of seconds: too long for every CI run)
void test_real_models(const std::vector<std::string>& names)
{
  const std::string dir = BUBBLE_MESH_3_SHARED_DATA_DIR;
  if(names.empty()) std::cout << "SKIP: real models (pass e.g. modelA1.ml as an argument)\n";
  for(const std::string& name : names)
  {
    const std::string file = std::filesystem::exists(name) ? name : dir + "/" + name;
    if(!std::filesystem::exists(file))
    {
      std::cout << "SKIP: " << file << " not found (the real models live in ../shared/data/geomodels)\n";
      continue;
    }
    std::cout << "remesh_surfaces on " << name << "\n";
    Model input;
    BM::IO::read_geological_model(file, input);
    Model output;
    const auto np = CGAL::parameters::default_values();
    const BM::Model_features f = BM::detect_model_features(input);
    BM::Remeshing_sizing_field<K> field(input, f, np);
    const BM::Remeshing_sizing_field<K> given = field;
    const BM::Surface_remeshing_report r = BM::remesh_surfaces(
      input, output, BM::parameters::sizing_field_output(&field, BM::parameters::keep_region_volumes(true, np)));
    print(name, r);
    // the chords across curved horizons change the volumes by about 1e-4; with
    // keep_region_volumes the free points' slide along the input gives them back
    std::cout << "    before the balance " << r.volume_error_before_balancing << " (" << r.number_of_volume_balancing_points
              << " points moved)\n";
    check_remeshed(input, output, r, field, given, true, true);
    // an error about a re-meshed triangle names the re-meshed surfaces, not the file's triangle of that index
    assert(output.file_name() == file + " (re-meshed)");
  }
}

} // namespace

int main(int argc, char** argv)
{
  test_features();
  test_sizing();
  test_proximity_inside_search_ball();
  test_curvature_rule();
  test_far_from_origin();
  test_in_memory(BM::Surface_remeshing_method::BUBBLES);
  test_in_memory(BM::Surface_remeshing_method::ISOTROPIC);
  test_overhang();
  test_faceted_body();
  test_balance_beside_an_immovable_region(false);
  test_balance_beside_an_immovable_region(true);
  test_ribbon();
  test_collapse_crowded_vertex();
  test_smooth_to_best_place();
  test_smooth_turns_triangles_back();
  test_keeps_facing_star();
  test_split_fixed_triangle();
  test_thin_layer_sides(0.2);
  test_thin_layer_sides(0.1);
  test_thin_layer_sides(0.05, 0.02);
  test_real_models(std::vector<std::string>(argv + 1, argv + argc));
  std::cout << "all remesh_surfaces checks passed\n";
  return EXIT_SUCCESS;
}
