// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of stages 1 and 2 (issue 4): surface bubbles, k-means and its
// validity indices, the choice of k, the sizing field's weight-point rule and
// the initial interior bubbles.

#include <CGAL/Bubble_mesh_3/IO/read_gocad_model3d.h>
#include <CGAL/Bubble_mesh_3/K_means_clustering.h>
#include <CGAL/Bubble_mesh_3/Surface_bubble_sizing_field.h>
#include <CGAL/Bubble_mesh_3/cluster_validity.h>
#include <CGAL/Bubble_mesh_3/make_layered_model.h>
#include <CGAL/Bubble_mesh_3/place_initial_bubbles.h>
#include <CGAL/Bubble_mesh_3/place_surface_bubbles.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;
typedef CGAL::Bubble_mesh_3::Bubble<K> Bubble;
typedef std::array<double, 3> P3;
namespace BM = CGAL::Bubble_mesh_3;
namespace BMP = CGAL::Bubble_mesh_3::parameters;

static bool close(double a, double b, double tol) { return std::abs(a - b) <= tol; }

// ---------------------------------------------------------------- models in memory

// Adds a grid of (nu x nv) quads, two triangles each, on the rectangle
// o + [0,1]u + [0,1]v; normals point along u x v. Points are shared through `ids`.
static void add_grid(Model& m, std::map<std::array<long, 3>, std::size_t>& ids, const P3& o, const P3& u,
                     const P3& v, int nu, int nv, std::size_t patch)
{
  auto id = [&](int i, int j) {
    P3 p;
    for(int d = 0; d < 3; ++d) p[d] = o[d] + u[d] * i / nu + v[d] * j / nv;
    const std::array<long, 3> key{{std::lround(p[0] * 1e6), std::lround(p[1] * 1e6), std::lround(p[2] * 1e6)}};
    auto it = ids.find(key);
    if(it != ids.end()) return it->second;
    const std::size_t n = m.add_point(Point_3(p[0], p[1], p[2]));
    ids[key] = n;
    return n;
  };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      m.add_triangle(id(i, j), id(i + 1, j), id(i + 1, j + 1), patch);
      m.add_triangle(id(i, j), id(i + 1, j + 1), id(i, j + 1), patch);
    }
}

// The box [0,10]x[0,6]x[0,4] in two layers split at z = 2 (region 1 below,
// region 2 above), with a small vertical fault x = 5, y in [2,4], z in
// [2.5,3.5] inside region 2. Grid step 0.5, 0.25 on the top face.
static Model make_two_layer_box()
{
  Model m;
  const std::size_t lower = m.add_region("lower"), upper = m.add_region("upper");
  const std::size_t p_bottom = m.add_patch("bottom", 0, lower), p_low_sides = m.add_patch("lower sides", 0, lower);
  const std::size_t p_interface = m.add_patch("interface", upper, lower);
  const std::size_t p_top = m.add_patch("top", 0, upper), p_up_sides = m.add_patch("upper sides", 0, upper);
  const std::size_t p_fault = m.add_patch("fault", upper, upper);
  std::map<std::array<long, 3>, std::size_t> ids;
  const double L = 10, W = 6;
  const P3 X{{L, 0, 0}}, Y{{0, W, 0}};
  add_grid(m, ids, {{0, 0, 0}}, Y, X, 12, 20, p_bottom);          // -z
  add_grid(m, ids, {{0, 0, 2}}, X, Y, 20, 12, p_interface);       // +z: upper is positive
  add_grid(m, ids, {{0, 0, 4}}, X, Y, 40, 24, p_top);             // +z, finer
  for(int layer = 0; layer < 2; ++layer)
  {
    const double z0 = 2. * layer;
    const std::size_t p = layer == 0 ? p_low_sides : p_up_sides;
    const P3 Z{{0, 0, 2}};
    add_grid(m, ids, {{0, 0, z0}}, Z, Y, 4, 12, p);  // x = 0, -x
    add_grid(m, ids, {{L, 0, z0}}, Y, Z, 12, 4, p);  // x = L, +x
    add_grid(m, ids, {{0, 0, z0}}, X, Z, 20, 4, p);  // y = 0, -y
    add_grid(m, ids, {{0, W, z0}}, Z, X, 4, 20, p);  // y = W, +y
  }
  add_grid(m, ids, {{5, 2, 2.5}}, {{0, 2, 0}}, {{0, 0, 1}}, 4, 2, p_fault);
  return m;
}

// The tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) as region 1, normals outward.
static Model make_tetrahedron()
{
  Model m;
  const std::size_t r = m.add_region("tet");
  const std::size_t p = m.add_patch("hull", 0, r);
  m.add_point(Point_3(0, 0, 0));
  m.add_point(Point_3(1, 0, 0));
  m.add_point(Point_3(0, 1, 0));
  m.add_point(Point_3(0, 0, 1));
  m.add_triangle(0, 2, 1, p);
  m.add_triangle(0, 1, 3, p);
  m.add_triangle(0, 3, 2, p);
  m.add_triangle(1, 2, 3, p);
  return m;
}

// well-separated blobs: `per_blob` points uniform in a cube of half-edge 1 around each centre
static std::vector<P3> make_blobs(const std::vector<P3>& centres, std::size_t per_blob, unsigned seed,
                                  std::vector<std::size_t>& truth)
{
  CGAL::Random rng(seed);
  std::vector<P3> pts;
  truth.clear();
  for(std::size_t c = 0; c < centres.size(); ++c)
    for(std::size_t i = 0; i < per_blob; ++i)
    {
      pts.push_back({{centres[c][0] + rng.get_double(-1, 1), centres[c][1] + rng.get_double(-1, 1),
                      centres[c][2] + rng.get_double(-1, 1)}});
      truth.push_back(c);
    }
  return pts;
}

// ---------------------------------------------------------------- checks

static void test_surface_bubbles()
{
  const Model tet = make_tetrahedron();
  const std::vector<Bubble> sb = BM::place_surface_bubbles(tet);
  assert(sb.size() == 4);
  // vertex 0: three edges of length 1 -> r = 0.5 * 1
  // vertex 1: edges 1, sqrt2, sqrt2   -> r = 0.5 * median = 0.5 sqrt2 (the mean would give 0.638)
  const double r1 = 0.5 * std::sqrt(2.);
  std::cout << "surface bubbles of the unit tetrahedron: r0 = " << sb[0].radius << " (expected 0.5), r1 = "
            << sb[1].radius << " (expected " << r1 << ")\n";
  assert(close(sb[0].radius, 0.5, 1e-12) && close(sb[1].radius, r1, 1e-12));
  assert(close(sb[2].radius, r1, 1e-12) && close(sb[3].radius, r1, 1e-12));
  for(std::size_t i = 0; i < 4; ++i)
    assert(sb[i].is_fixed && sb[i].surface_point == i && sb[i].region == BM::no_index);
  const std::vector<Bubble> sb2 = BM::place_surface_bubbles(tet, BMP::surface_radius_factor(1.));
  assert(close(sb2[1].radius, 2. * r1, 1e-12));

  // shared edges count once: on the box, an inner vertex of a face grid of
  // step 0.5 has 6 edges: 4 of length 0.5 and 2 diagonals 0.5 sqrt2, median 0.5
  const Model box = make_two_layer_box();
  const std::vector<Bubble> bb = BM::place_surface_bubbles(box);
  assert(bb.size() == box.number_of_points());
  std::size_t checked = 0;
  const double inner = 0.5 * 0.5;
  for(const Bubble& b : bb)
    if(b.center.z() == 0 && b.center.x() > 0.1 && b.center.x() < 9.9 && b.center.y() > 0.1 && b.center.y() < 5.9)
    {
      assert(close(b.radius, inner, 1e-12));
      ++checked;
    }
  std::cout << "box bottom: " << checked << " inner vertices with r = " << inner << "\n";
  assert(checked == 11 * 19);

  // region_surface_points: region 1 has z <= 2, region 2 z >= 2 and the fault
  const std::vector<std::size_t> r1p = BM::region_surface_points(box, 1), r2p = BM::region_surface_points(box, 2);
  std::size_t fault_in_2 = 0;
  for(std::size_t v : r1p) assert(box.point(v).z() <= 2);
  for(std::size_t v : r2p)
  {
    assert(box.point(v).z() >= 2);
    if(box.point(v).x() == 5 && box.point(v).y() > 1.9 && box.point(v).y() < 4.1 && box.point(v).z() > 2.4 && box.point(v).z() < 3.6) ++fault_in_2;
  }
  std::cout << "region surface points: " << r1p.size() << " in region 1, " << r2p.size() << " in region 2 ("
            << fault_in_2 << " on the fault)\n";
  assert(fault_in_2 == 15);
}

static void test_validity_by_hand()
{
  // 6 points on the x axis, clusters {0,1,2} and {10,11,12}; means 1 and 11, overall mean 6.
  // SSE = (1 + 0 + 1) * 2 = 4
  // CH  = [B/(k-1)] / [W/(n-k)], B = 3*25 + 3*25 = 150, W = 4 -> (150/1) / (4/4) = 150
  // silhouette: x=0: a = (1+2)/2 = 1.5, b = (10+11+12)/3 = 11, s = 9.5/11 = 19/22
  //             x=1: a = 1, b = 10, s = 9/10;  x=2: a = 1.5, b = 9, s = 7.5/9 = 5/6
  //             by symmetry the mean is (19/22 + 9/10 + 5/6) / 3 = (857/330) / 3 = 857/990
  const std::vector<P3> pts{{{0, 0, 0}}, {{1, 0, 0}}, {{2, 0, 0}}, {{10, 0, 0}}, {{11, 0, 0}}, {{12, 0, 0}}};
  const std::vector<std::size_t> labels{0, 0, 0, 1, 1, 1};
  const double sse = BM::sum_of_squared_errors(pts, labels);
  const double ch = BM::calinski_harabasz_index(pts, labels);
  const double s = BM::silhouette_coefficient(pts, labels);
  std::cout << "hand-computed set: SSE " << sse << " (4), CH " << ch << " (150), silhouette " << s << " ("
            << 857. / 990. << ")\n";
  assert(close(sse, 4., 1e-12) && close(ch, 150., 1e-9) && close(s, 857. / 990., 1e-12));

  // the same far from the origin (real coordinates): same values
  std::vector<P3> far = pts;
  for(P3& p : far) { p[0] += 4.5e6; p[1] += 6.2e6; p[2] -= 3000.; }
  assert(close(BM::sum_of_squared_errors(far, labels), 4., 1e-6));
  assert(close(BM::calinski_harabasz_index(far, labels), 150., 1e-4));

  // k-means finds that clustering itself
  std::vector<std::size_t> l;
  std::vector<P3> c;
  BM::K_means_clustering()(far, 2, l, c);
  assert(l[0] == l[1] && l[1] == l[2] && l[3] == l[4] && l[4] == l[5] && l[0] != l[3]);
}

static void test_k_means_blobs()
{
  const std::vector<P3> truth_centres{{{0, 0, 0}}, {{20, 0, 0}}, {{0, 20, 0}}, {{0, 0, 20}}, {{20, 20, 20}}};
  std::vector<std::size_t> truth;
  const std::vector<P3> pts = make_blobs(truth_centres, 300, 11, truth);
  const BM::K_means_clustering km(CGAL::parameters::random_seed(5));
  std::vector<std::size_t> labels;
  std::vector<P3> centres;
  km(pts, 5, labels, centres);
  // purity: every blob is one cluster, different blobs different clusters
  std::map<std::size_t, std::size_t> blob_to_label;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    auto it = blob_to_label.emplace(truth[i], labels[i]).first;
    assert(it->second == labels[i]);
  }
  std::set<std::size_t> used;
  for(const auto& bl : blob_to_label) used.insert(bl.second);
  assert(used.size() == 5);
  double worst = 0.;
  for(const auto& bl : blob_to_label)
    worst = (std::max)(worst, std::sqrt(BM::internal::squared_distance_3(centres[bl.second], truth_centres[bl.first])));
  std::cout << "k-means on 5 blobs of 300 points: all pure, worst centre error " << worst << "\n";
  assert(worst < 0.2);

  // same seed -> same labels; the result does not depend on the restart count when blobs are clear
  std::vector<std::size_t> labels2;
  std::vector<P3> centres2;
  km(pts, 5, labels2, centres2);
  assert(labels2 == labels && centres2 == centres);

  // the SSE elbow on a hand-made curve: k = 2..6, SSE 100, 40, 20, 15, 12.
  // Normalised: x = 0, .25, .5, .75, 1; y = 1, .318, .091, .034, 0; the gap
  // below the chord y = 1 - x is .432 at k = 3, .409 at k = 4, .216 at k = 5.
  std::vector<BM::Cluster_validity> curve(5);
  const double sse_curve[5] = {100, 40, 20, 15, 12};
  for(std::size_t i = 0; i < 5; ++i)
  {
    curve[i].number_of_clusters = i + 2;
    curve[i].sum_of_squared_errors = sse_curve[i];
  }
  std::cout << "elbow of 100, 40, 20, 15, 12 (k = 2..6): " << BM::internal::sse_elbow(curve) << " (3)\n";
  assert(BM::internal::sse_elbow(curve) == 3);
  curve.resize(2);
  assert(BM::internal::sse_elbow(curve) == 0); // undefined with two values

  // the choice of k on clear data, for two different true k
  for(std::size_t true_k : {3u, 5u})
  {
    const std::vector<P3> tc(truth_centres.begin(), truth_centres.begin() + true_k);
    const std::vector<P3> p = make_blobs(tc, 200, 17 + unsigned(true_k), truth);
    const BM::Number_of_clusters_selection sel = BM::select_number_of_clusters(p, 2, 8, km);
    std::cout << "selection on " << true_k << " blobs:\n   k        SSE          CH   silhouette\n";
    for(const auto& row : sel.table)
      std::cout << "  " << row.number_of_clusters << "  " << row.sum_of_squared_errors << "  "
                << row.calinski_harabasz << "  " << row.silhouette << "\n";
    std::cout << "  CH -> " << sel.calinski_harabasz_choice << ", silhouette -> " << sel.silhouette_choice
              << ", elbow -> " << sel.elbow_choice << ", chosen " << sel.number_of_clusters << "\n";
    assert(sel.number_of_clusters == true_k);
    assert(sel.table.size() == 7 && sel.labels.size() == p.size() && sel.centres.size() == true_k);
  }
}

static void test_silhouette_subsample()
{
  const std::vector<P3> tc{{{0, 0, 0}}, {{6, 0, 0}}, {{0, 6, 0}}};
  std::vector<std::size_t> truth;
  const std::vector<P3> pts = make_blobs(tc, 2000, 3, truth);
  CGAL::Real_timer t;
  t.start();
  const double exact = BM::silhouette_coefficient(pts, truth, BMP::silhouette_sample_size(pts.size()));
  const double exact_s = t.time();
  const double sub = BM::silhouette_coefficient(pts, truth, BMP::silhouette_sample_size(500).random_seed(9));
  const double sub2 = BM::silhouette_coefficient(pts, truth, BMP::silhouette_sample_size(500).random_seed(9));
  std::cout << "silhouette of 6000 points: exact " << exact << " (" << exact_s << " s), subsample of 500 " << sub
            << "\n";
  assert(sub == sub2);
  assert(close(exact, sub, 0.03));
}

static void test_radius_rule()
{
  // Hand-made: the unit tetrahedron with surface radii 0.1, 0.2, 0.3, 0.4.
  // R0 = (0.4 + 0.1) / 2 = 0.25; weight point when l_j < L_j = 1.5 (0.25 + r_j),
  // i.e. l < 0.525, 0.675, 0.825, 0.975; a weight point's weight is tapered by
  // (1 - (l_j / L_j)^2)^2, and R0 is one more weight point, of weight
  // 1 / (2 * 1.5 * R0) (inverse distance) or 1 / R0 (inverse radius).
  // p = (0.2,0.2,0.2): l_0 = sqrt(0.12) = 0.3464, l_1 = l_2 = l_3 = sqrt(0.72) = 0.8485
  // -> weight points 0 and 3 only.
  // Far away (5,5,5): no weight point -> R0 = 0.25; at vertex 1: its own radius 0.2.
  const Model tet = make_tetrahedron();
  std::vector<Bubble> sb = BM::place_surface_bubbles(tet);
  for(std::size_t i = 0; i < 4; ++i) sb[i].radius = 0.1 * double(i + 1);
  const BM::Surface_bubble_sizing_field<K> idw(tet, sb);
  const BM::Surface_bubble_sizing_field<K> inv_r(tet, sb, BMP::radius_weighting(BM::Radius_weighting::INVERSE_RADIUS));
  const BM::Surface_bubble_sizing_field<K> scaled(tet, sb, BMP::region_scale_factors({1., 2.}));
  const Point_3 p(0.2, 0.2, 0.2);
  const double l0 = std::sqrt(0.12), l1 = std::sqrt(0.72);
  auto taper = [](double l, double reach) { const double u = 1. - (l / reach) * (l / reach); return u * u; };
  const double t0 = taper(l0, 0.525), t3 = taper(l1, 0.975);
  const double expected = (t0 / l0 * 0.1 + t3 / l1 * 0.4 + 0.25 / 0.75) / (t0 / l0 + t3 / l1 + 1. / 0.75);
  const double expected_inv_r = (t0 / 0.1 * 0.1 + t3 / 0.4 * 0.4 + 0.25 / 0.25) / (t0 / 0.1 + t3 / 0.4 + 1. / 0.25);
  std::cout << "weight-point rule: inverse distance " << idw(p, 1) << " (" << expected << "), inverse radius "
            << inv_r(p, 1) << " (" << expected_inv_r << "), no weight point " << idw(Point_3(5, 5, 5), 1)
            << " (0.25), at a vertex " << idw(Point_3(1, 0, 0), 1) << " (0.2), scaled x2 " << scaled(p, 1) << "\n";
  assert(close(idw(p, 1), expected, 1e-12));
  assert(close(inv_r(p, 1), expected_inv_r, 1e-12));
  assert(close(idw(Point_3(5, 5, 5), 1), 0.25, 1e-12));
  assert(close(idw(Point_3(1, 0, 0), 1), 0.2, 1e-12));
  assert(close(scaled(p, 1), 2. * expected, 1e-12));
  assert(idw.default_radius(1) == 0.25 && idw.smallest_surface_radius(1) == 0.1);
  assert(idw(p, 0) == 0. && idw(p, 7) == 0.); // no surface bubbles / no such region

  // The field is continuous, also where weight points leave their range: along
  // a line from inside the tetrahedron to far outside, sampled every 1e-4, no
  // step changes the radius by more than a slope of 2 allows (cut-off weights
  // jumped by 0.109 on this line where a weight point left).
  {
    const BM::Surface_bubble_sizing_field<K> ungraded_field(tet, sb, BMP::size_gradation(0.));
    double previous = ungraded_field(Point_3(0.2, 0.2, 0.14), 1), largest_step = 0.;
    for(int k = 1; k <= 30000; ++k)
    {
      const double c = 0.2 + 1e-4 * double(k);
      const double now = ungraded_field(Point_3(c, c, 0.7 * c), 1);
      largest_step = (std::max)(largest_step, std::abs(now - previous));
      previous = now;
    }
    std::cout << "largest change of the radius over 1e-4 along a line: " << largest_step << "\n";
    assert(largest_step < 2. * 1e-4 * std::sqrt(2.49));
    assert(close(previous, 0.25, 1e-12)); // far away: R0
  }

  // Gradation. Radii 0.01, 10, 10, 10: R0 = 5.005,
  // all four are weight points of p; the tapered inverse distance gives 5.51,
  // but the radius may grow only 0.5 per unit of distance from bubble 0:
  // 0.01 + 0.5 l_0 = 0.1832.
  sb[0].radius = 0.01;
  for(std::size_t i = 1; i < 4; ++i) sb[i].radius = 10.;
  const double r0 = 0.5 * (0.01 + 10.), ta = taper(l0, 1.5 * (r0 + 0.01)), tb = taper(l1, 1.5 * (r0 + 10.));
  const double wb = 1. / (3. * r0);
  const double interpolated = (ta / l0 * 0.01 + 3. * tb / l1 * 10. + wb * r0) / (ta / l0 + 3. * tb / l1 + wb);
  const BM::Surface_bubble_sizing_field<K> graded(tet, sb);
  const BM::Surface_bubble_sizing_field<K> ungraded(tet, sb, BMP::size_gradation(0.));
  const BM::Surface_bubble_sizing_field<K> steep(tet, sb, BMP::size_gradation(2.));
  std::cout << "gradation: " << ungraded(p, 1) << " (" << interpolated << ") ungraded, " << graded(p, 1) << " ("
            << 0.01 + 0.5 * l0 << ") at 0.5, " << steep(p, 1) << " at 2\n";
  assert(close(ungraded(p, 1), interpolated, 1e-12));
  assert(close(graded(p, 1), 0.01 + 0.5 * l0, 1e-12));
  assert(close(steep(p, 1), 0.01 + 2. * l0, 1e-12));
  assert(close(graded(Point_3(1, 0, 0), 1), 10., 1e-12)); // a surface bubble's own radius stays
}

// R0 with area_weighted_radius_floor: a region whose surface has many small
// bubbles and a few large ones. One point in 40 gets radius 1, the others 0.1:
// by count the large ones are under 5 % (R0 = 0.1), by area they cover 1 / (1 +
// 39 * 0.01) = 72 % of the surface, so the floor is (0.1 + 1) / 4 = 0.275.
static void test_area_weighted_radius_floor()
{
  const Model box = make_two_layer_box();
  std::vector<Bubble> sb = BM::place_surface_bubbles(box);
  for(Bubble& b : sb) b.radius = b.surface_point % 40 == 0 ? 1. : 0.1;
  // region 1's radii, from its patches' triangles
  std::set<std::size_t> points;
  for(std::size_t t = 0; t < box.number_of_triangles(); ++t)
  {
    const auto& patch = box.patch(box.patch_of_triangle(t));
    if(patch.positive_region == 1 || patch.negative_region == 1)
      for(std::size_t v : box.triangle(t)) points.insert(v);
  }
  std::vector<double> r;
  for(const Bubble& b : sb)
    if(points.count(b.surface_point)) r.push_back(b.radius);
  std::sort(r.begin(), r.end());
  const std::size_t q = (r.size() - 1) / 20;
  const double by_count = 0.5 * (r[q] + r[r.size() - 1 - q]);
  double total = 0., covered = 0., low = -1., high = -1.;
  for(double x : r) total += x * x;
  for(double x : r)
  {
    covered += x * x;
    if(low < 0. && covered >= 0.05 * total) low = x;
    if(high < 0. && covered >= 0.95 * total) high = x;
  }
  const double floor = 0.25 * (low + high);
  const BM::Surface_bubble_sizing_field<K> counted(box, sb);
  const BM::Surface_bubble_sizing_field<K> floored(box, sb, BMP::area_weighted_radius_floor(true));
  std::cout << "R0 of region 1 (" << r.size() << " surface bubbles): by count " << counted.default_radius(1)
            << " (" << by_count << "), with the area floor " << floored.default_radius(1) << " (" << floor << ")\n";
  assert(by_count == 0.1 && close(floor, 0.275, 1e-12)); // the case the floor is for
  assert(counted.default_radius(1) == by_count);
  assert(close(floored.default_radius(1), floor, 1e-12));
  // far from every surface bubble the field is R0
  const Point_3 far(100., 100., 100.);
  assert(close(counted(far, 1), by_count, 1e-12) && close(floored(far, 1), floor, 1e-12));
  // where the count is right (equal radii) the floor changes nothing
  for(Bubble& b : sb) b.radius = 0.3;
  const BM::Surface_bubble_sizing_field<K> even(box, sb, BMP::area_weighted_radius_floor(true));
  assert(even.default_radius(1) == 0.3 && even.default_radius(2) == 0.3);
}

// The graded bound min_j (r_j + g l_j) of a gentle gradation reaches far from
// the query; the field walks its grid's cells nearest first and skips those whose
// smallest bubble could not lower it. Against brute force over every surface
// bubble of the region, on the two-layer box with radii spread over 0.05..0.5
// (a cell of small bubbles beside cells of large ones, in two radius classes),
// at points inside, on and outside the box: the same value; and the same
// interpolated radius as the weight-point formula over every bubble.
static void test_graded_bound_against_brute_force()
{
  const Model box = make_two_layer_box();
  std::vector<Bubble> sb = BM::place_surface_bubbles(box);
  CGAL::Random rng(7);
  for(Bubble& b : sb) b.radius = rng.get_double() < 0.1 ? rng.get_double(0.05, 0.1) : rng.get_double(0.2, 0.5);
  for(std::size_t region = 1; region <= 2; ++region)
  {
    std::set<std::size_t> points;
    for(std::size_t t = 0; t < box.number_of_triangles(); ++t)
    {
      const auto& patch = box.patch(box.patch_of_triangle(t));
      if(patch.positive_region == region || patch.negative_region == region)
        for(std::size_t v : box.triangle(t)) points.insert(v);
    }
    std::size_t checked = 0, bound_wins = 0;
    for(double g : {0.5, 0.1, 0.02})
    {
      const BM::Surface_bubble_sizing_field<K> field(box, sb, BMP::size_gradation(g));
      const BM::Surface_bubble_sizing_field<K> interpolated(box, sb, BMP::size_gradation(0.));
      for(int k = 0; k < 300; ++k)
      {
        const Point_3 p(rng.get_double(-3., 13.), rng.get_double(-3., 9.), rng.get_double(-1., 5.));
        const double x = p.x(), y = p.y(), z = p.z();
        // the weight points by the formula, over every surface bubble of the region
        const double r0 = interpolated.default_radius(region);
        double weights = 1. / (2. * 1.5 * r0), sum = r0 * weights;
        for(const Bubble& b : sb)
          if(points.count(b.surface_point))
          {
            const double dx = b.center.x() - x, dy = b.center.y() - y, dz = b.center.z() - z;
            const double l = std::sqrt(dx * dx + dy * dy + dz * dz), reach = 1.5 * (r0 + b.radius);
            if(!(l < reach)) continue;
            const double u = 1. - (l / reach) * (l / reach), w = u * u / l;
            weights += w;
            sum += w * b.radius;
          }
        assert(close(interpolated(p, region), sum / weights, 1e-12));
        double brute = interpolated(p, region);
        for(const Bubble& b : sb)
          if(points.count(b.surface_point))
          {
            const double dx = b.center.x() - x, dy = b.center.y() - y, dz = b.center.z() - z;
            brute = (std::min)(brute, b.radius + g * std::sqrt(dx * dx + dy * dy + dz * dz));
          }
        const double got = field(p, region);
        if(!close(got, brute, 1e-12))
          std::cout << "region " << region << ", g " << g << ", at " << p << ": " << got << " against " << brute << "\n";
        assert(close(got, brute, 1e-12));
        ++checked;
        if(brute < interpolated(p, region)) ++bound_wins;
      }
    }
    std::cout << "graded bound, region " << region << ": " << checked << " points as brute force, the bound below the interpolation at "
              << bound_wins << "\n";
    assert(bound_wins > checked / 4); // the bound is what is tested
  }
}

// Smallest (distance to the nearest model triangle) / radius over the bubbles:
// by brute force over all triangles, or with one AABB tree of all triangles
// (independent of the per-region trees of the placement).
static double min_clearance_ratio(const Model& m, const std::vector<Bubble>& bubbles, bool brute_force)
{
  std::vector<K::Triangle_3> tris;
  for(const auto& t : m.triangles()) tris.emplace_back(m.point(t[0]), m.point(t[1]), m.point(t[2]));
  typedef CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator> Primitive;
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > tree(tris.begin(), tris.end());
  double worst = std::numeric_limits<double>::max();
  for(const Bubble& b : bubbles)
  {
    double d2 = std::numeric_limits<double>::max();
    if(brute_force)
      for(const K::Triangle_3& t : tris) d2 = (std::min)(d2, CGAL::to_double(CGAL::squared_distance(b.center, t)));
    else
      d2 = CGAL::to_double(tree.squared_distance(b.center));
    worst = (std::min)(worst, std::sqrt(d2) / b.radius);
  }
  return worst;
}

static void test_initial_bubbles_on_box()
{
  const Model box = make_two_layer_box();
  const std::vector<Bubble> sb = BM::place_surface_bubbles(box);
  std::vector<BM::Region_placement_statistics> stats;
  CGAL::Real_timer t;
  t.start();
  // the paper's lattice (graded cells: test_graded_cells_on_box())
  const std::vector<Bubble> ib =
    BM::place_initial_bubbles(box, sb, BMP::graded_cell_factor(0., BMP::placement_statistics(&stats).random_seed(1)));
  std::cout << "two-layer box: " << ib.size() << " initial bubbles in " << t.time() << " s\n";
  assert(stats.size() == 3);
  std::size_t count[3] = {0, 0, 0};
  for(const Bubble& b : ib)
  {
    assert(!b.is_fixed && b.surface_point == BM::no_index && (b.region == 1 || b.region == 2));
    ++count[b.region];
    const double x = b.center.x(), y = b.center.y(), z = b.center.z();
    const double zlo = b.region == 1 ? 0. : 2.;
    assert(x > 0 && x < 10 && y > 0 && y < 6 && z > zlo && z < zlo + 2);
    assert(b.radius > 0);
  }
  for(std::size_t r = 1; r <= 2; ++r)
  {
    const auto& s = stats[r];
    std::cout << "  region " << r << ": " << s.number_of_surface_points << " surface points, k = "
              << s.number_of_clusters << " (CH " << s.calinski_harabasz_choice << ", silhouette "
              << s.silhouette_choice << ", elbow " << s.elbow_choice << "), cell edge " << s.cell_edge << ", "
              << s.number_of_cells << " cells, " << s.rejected_outside << " outside, " << s.rejected_near_surface
              << " near a surface, " << s.number_of_bubbles << " bubbles\n";
    assert(s.number_of_bubbles == count[r] && count[r] > 0);
    assert(s.number_of_cells == s.rejected_outside + s.rejected_near_surface + s.number_of_bubbles);
    assert(s.cluster_validity.size() == 9);
  }
  // cell edge = (r_max + r_min) / 2 of the region's surface bubbles (no scale)
  const BM::Surface_bubble_sizing_field<K> field(box, sb);
  for(std::size_t r = 1; r <= 2; ++r)
    assert(close(stats[r].cell_edge, field.default_radius(r), 1e-12));

  // no duplicates where cluster boxes overlap
  std::set<std::array<double, 3> > centres;
  for(const Bubble& b : ib) centres.insert({{b.center.x(), b.center.y(), b.center.z()}});
  assert(centres.size() == ib.size());

  // clearance, brute force over all triangles (the fault included)
  const double ratio = min_clearance_ratio(box, ib, true);
  std::cout << "  smallest distance to a surface / radius: " << ratio << "\n";
  assert(ratio >= 1. - 1e-12);
  // nobody sits closer than its radius to the fault (rectangle x = 5, y in [2,4], z in [2.5,3.5])
  std::size_t near_fault = 0;
  for(const Bubble& b : ib)
  {
    const double dx = b.center.x() - 5.;
    const double dy = (std::max)({0., 2. - b.center.y(), b.center.y() - 4.});
    const double dz = (std::max)({0., 2.5 - b.center.z(), b.center.z() - 3.5});
    const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    assert(d >= b.radius * (1. - 1e-12));
    if(d < 2. * b.radius) ++near_fault;
  }
  std::cout << "  " << near_fault << " bubbles within two radii of the fault, none within one\n";
  assert(near_fault > 0);

  // same seed, same result; and with or without parallelism
  const std::vector<Bubble> again = BM::place_initial_bubbles(box, sb, BMP::graded_cell_factor(0., BMP::parallel_regions(false).random_seed(1)));
  assert(again.size() == ib.size());
  for(std::size_t i = 0; i < ib.size(); ++i)
    assert(again[i].center == ib[i].center && again[i].radius == ib[i].radius && again[i].region == ib[i].region);

  // a fixed k, a per-region scale (denser region 2) and a larger clearance
  std::vector<BM::Region_placement_statistics> st2;
  t.reset();
  const std::vector<Bubble> dense = BM::place_initial_bubbles(
    box, sb, BMP::graded_cell_factor(0., BMP::number_of_clusters(3, BMP::region_scale_factors({1., 1., 0.7},
                                                                  BMP::placement_statistics(&st2)))));
  std::cout << "  k = 3, region 2 at scale 0.7: " << st2[1].number_of_bubbles << " + " << st2[2].number_of_bubbles
            << " bubbles, cell edges " << st2[1].cell_edge << ", " << st2[2].cell_edge << ", " << t.time() << " s\n";
  assert(st2[1].number_of_clusters == 3 && st2[2].number_of_clusters == 3 && st2[1].cluster_validity.empty());
  assert(close(st2[2].cell_edge, 0.7 * stats[2].cell_edge, 1e-12));
  assert(st2[2].number_of_bubbles > 2 * stats[2].number_of_bubbles);
  assert(min_clearance_ratio(box, dense, false) >= 1. - 1e-12);

  const std::vector<Bubble> wide = BM::place_initial_bubbles(box, sb, BMP::graded_cell_factor(0., BMP::surface_clearance_factor(2.)));
  const double wide_ratio = min_clearance_ratio(box, wide, false);
  std::cout << "  clearance factor 2: " << wide.size() << " bubbles, smallest distance / radius " << wide_ratio << "\n";
  assert(wide.size() < ib.size() && wide_ratio >= 2. - 1e-12);
}

// A radius of 0.1 where x < 5 and 0.2 beyond: a field with two sizes.
struct Two_sizes
{
  double operator()(const Point_3& p, std::size_t) const { return p.x() < 5. ? 0.1 : 0.2; }
};

// graded_cell_factor: cells that follow the sizing field
static void test_graded_cells_on_box()
{
  const Model box = make_two_layer_box();
  const std::vector<Bubble> sb = BM::place_surface_bubbles(box);
  const Two_sizes sizing;
  const double g = 1.8;
  std::vector<BM::Region_placement_statistics> stats;
  const std::vector<Bubble> ib =
    BM::place_initial_bubbles(box, sb, sizing, BMP::graded_cell_factor(g, BMP::placement_statistics(&stats)));
  std::size_t fine = 0, coarse = 0;
  for(const Bubble& b : ib)
  {
    assert(!b.is_fixed && (b.region == 1 || b.region == 2));
    const double x = b.center.x(), y = b.center.y(), z = b.center.z();
    const double zlo = b.region == 1 ? 0. : 2.;
    assert(x > 0 && x < 10 && y > 0 && y < 6 && z > zlo && z < zlo + 2);
    assert(b.radius == sizing(b.center, b.region));
    (x < 5. ? fine : coarse) += 1;
  }
  for(std::size_t r = 1; r <= 2; ++r)
    assert(stats[r].number_of_cells == stats[r].rejected_outside + stats[r].rejected_near_surface +
                                         stats[r].number_of_bubbles);
  // a cell's edge is within a factor sqrt(2) of g R: each half holds between
  // (V / (sqrt 2 g R)^3) and (V / (g R / sqrt 2)^3) cells, less those near the walls
  const double half = 5. * 6. * 4.;
  const auto bounds = [&](double R) {
    return std::make_pair(half / std::pow(std::sqrt(2.) * g * R, 3), half / std::pow(g * R / std::sqrt(2.), 3));
  };
  std::cout << "graded cells (g = " << g << "): " << fine << " bubbles where R = 0.1, " << coarse
            << " where R = 0.2; at most " << bounds(0.1).second << " and " << bounds(0.2).second << "\n";
  assert(double(fine) <= bounds(0.1).second && double(coarse) <= bounds(0.2).second);
  // the walls take a layer of about R, less than half the volume here
  assert(double(fine) >= 0.5 * bounds(0.1).first && double(coarse) >= 0.5 * bounds(0.2).first);
  // eight times the volume per bubble on the coarse side, within the cells' rounding
  const double ratio = double(fine) / double(coarse);
  assert(ratio > 4. && ratio < 16.);
  // the uniform lattice of the same field has one cell edge for both halves
  const std::vector<Bubble> uniform = BM::place_initial_bubbles(box, sb, sizing, BMP::graded_cell_factor(0.));
  std::size_t ufine = 0, ucoarse = 0;
  for(const Bubble& b : uniform) (b.center.x() < 5. ? ufine : ucoarse) += 1;
  std::cout << "  uniform lattice: " << ufine << " and " << ucoarse << "\n";
  assert(double(ufine) < 2. * double(ucoarse) && double(ucoarse) < 2. * double(ufine));
  assert(min_clearance_ratio(box, ib, true) >= 1. - 1e-12);
  // with or without parallelism, the same bubbles in the same order
  const std::vector<Bubble> again =
    BM::place_initial_bubbles(box, sb, sizing, BMP::graded_cell_factor(g, BMP::parallel_regions(false)));
  assert(again.size() == ib.size());
  for(std::size_t i = 0; i < ib.size(); ++i)
    assert(again[i].center == ib[i].center && again[i].radius == ib[i].radius && again[i].region == ib[i].region);
}

// Region of a point by ray parity against each region's boundary, with an
// AABB tree of that boundary and a fixed skew direction (independent of
// Side_of_triangle_mesh, which the placement uses). 0 if in none.
struct Region_locator
{
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator> > > Tree;
  std::vector<std::vector<K::Triangle_3> > boundary;
  std::vector<std::unique_ptr<Tree> > trees;

  explicit Region_locator(const Model& m) : boundary(m.number_of_regions() + 1), trees(m.number_of_regions() + 1)
  {
    for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
    {
      const auto& patch = m.patch(m.patch_of_triangle(t));
      if(patch.is_inside_region()) continue;
      const auto& tri = m.triangle(t);
      const K::Triangle_3 T(m.point(tri[0]), m.point(tri[1]), m.point(tri[2]));
      boundary[patch.positive_region].push_back(T);
      boundary[patch.negative_region].push_back(T);
    }
    for(std::size_t r = 1; r < boundary.size(); ++r)
      trees[r].reset(new Tree(boundary[r].begin(), boundary[r].end()));
  }
  bool is_inside(const Point_3& p, std::size_t r) const
  {
    const K::Ray_3 ray(p, K::Vector_3(0.3183098861837907, 0.5772156649015329, 0.7390851332151607));
    return trees[r]->number_of_intersected_primitives(ray) % 2 == 1;
  }
};

// Places the bubbles of `m` with the defaults and checks, independently of
// the placement's own tests, that every bubble is inside its region and at
// least its radius away from every triangle. Returns the bubble count.
static std::size_t check_model_placement(const std::string& name, const Model& m)
{
  CGAL::Real_timer t;
  t.start();
  const std::vector<Bubble> sb = BM::place_surface_bubbles(m);
  const double t_surface = t.time();
  std::vector<BM::Region_placement_statistics> stats;
  const std::vector<Bubble> ib = BM::place_initial_bubbles(m, sb, BMP::placement_statistics(&stats));
  const double t_total = t.time();
  std::cout << name << ": " << m.number_of_regions() << " regions, " << m.number_of_triangles() << " triangles, "
            << sb.size() << " surface bubbles (" << t_surface << " s), " << ib.size() << " initial bubbles ("
            << t_total - t_surface << " s)\n";
  for(std::size_t r = 1; r < stats.size(); ++r)
    std::cout << "  region " << r << ": " << stats[r].number_of_surface_points << " points, k = "
              << stats[r].number_of_clusters << " (CH " << stats[r].calinski_harabasz_choice << ", S "
              << stats[r].silhouette_choice << ", elbow " << stats[r].elbow_choice << "), h = " << stats[r].cell_edge
              << ", " << stats[r].number_of_bubbles << " bubbles (" << stats[r].clustering_seconds << " + "
              << stats[r].placement_seconds << " s)\n";
  for(const Bubble& b : sb) assert(b.is_fixed && b.radius > 0 && b.surface_point < m.number_of_points());
  const Region_locator locate(m);
  std::size_t regions_with_bubbles = 0;
  for(std::size_t r = 1; r < stats.size(); ++r)
    if(stats[r].number_of_bubbles > 0) ++regions_with_bubbles;
  for(const Bubble& b : ib)
  {
    assert(b.region >= 1 && b.region <= m.number_of_regions() && !b.is_fixed && b.radius > 0);
    assert(locate.is_inside(b.center, b.region));
  }
  const double ratio = min_clearance_ratio(m, ib, false);
  std::cout << "  all inside their region (ray parity); smallest distance to a surface / radius " << ratio
            << "; regions with bubbles " << regions_with_bubbles << "/" << m.number_of_regions() << "\n";
  assert(ratio >= 1. - 1e-9);
  return ib.size();
}

static void test_default_model()
{
  Model m;
  BM::make_layered_model(m);
  const std::size_t n = check_model_placement("default layered model", m);
  assert(n > 0);
}

static void test_real_models()
{
  const std::string dir = BUBBLE_MESH_3_SHARED_DATA_DIR;
  if(!std::filesystem::is_directory(dir))
  {
    std::cout << "SKIP: no real models (" << dir << " is absent)\n";
    return;
  }
  std::vector<std::string> files;
  for(const auto& e : std::filesystem::directory_iterator(dir))
    if(e.path().extension() == ".ml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  if(files.empty()) std::cout << "SKIP: no .ml model in " << dir << "\n";
  for(const std::string& f : files)
  {
    Model m;
    BM::IO::read_gocad_model3d(f, m);
    check_model_placement(std::filesystem::path(f).filename().string(), m);
  }
}

int main()
{
  std::cout.setf(std::ios::unitbuf); // lines appear before an assertion aborts
  test_surface_bubbles();
  test_validity_by_hand();
  test_k_means_blobs();
  test_silhouette_subsample();
  test_radius_rule();
  test_area_weighted_radius_floor();
  test_graded_bound_against_brute_force();
  test_initial_bubbles_on_box();
  test_graded_cells_on_box();
  test_default_model();
  test_real_models();
  std::cout << "test_placement: OK\n";
  return EXIT_SUCCESS;
}
