// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team
//
// The quality report on tetrahedra whose measures are derived by hand (in the
// comments), on a small labelled mesh, and on a C3T3 filled by hand.

#include <CGAL/Bubble_mesh_3/mesh_quality.h>
#include <CGAL/Bubble_mesh_3/IO/read_tet_mesh.h>
#include <CGAL/Bubble_mesh_3/IO/write_quality_report.h>
#include <CGAL/Bubble_mesh_3/IO/write_svg_histograms.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/File_medit.h>
#include <CGAL/IO/output_to_vtu.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace BM = CGAL::Bubble_mesh_3;
typedef std::array<double, 3> P;

static const double pi = 3.14159265358979323846;
static double deg(double radians) { return radians * 180. / pi; }

static bool near(double a, double b, double tol = 1e-9) { return std::abs(a - b) <= tol * (1. + std::abs(b)); }

static void check(const std::string& what, bool ok, double got, double expected)
{
  std::cout << "  " << what << ": " << got << " (expected " << expected << ")" << (ok ? "" : "  FAILED") << std::endl;
  assert(ok);
}
static void check_near(const std::string& what, double got, double expected, double tol = 1e-9)
{
  check(what, near(got, expected, tol), got, expected);
}

static double histogram_sum(const BM::Quality_histogram& h)
{
  double s = 0.;
  for(double f : h.frequencies) s += f;
  return s;
}

// 1. regular tetrahedron (alternate corners of the cube [-1,1]^3, edge 2 sqrt(2))
static void test_regular()
{
  std::cout << "regular tetrahedron\n";
  const BM::Tetrahedron_quality q =
    BM::tetrahedron_quality(P{{1, 1, 1}}, P{{1, -1, -1}}, P{{-1, 1, -1}}, P{{-1, -1, 1}});
  // dihedral acos(1/3) = 70.528779 degrees everywhere
  for(double a : q.dihedral_angles) check_near("dihedral", a, deg(std::acos(1. / 3.)), 1e-12);
  assert(near(deg(std::acos(1. / 3.)), 70.5287793655, 1e-10));
  for(double a : q.face_angles) assert(near(a, 60., 1e-12));
  std::cout << "  12 face angles: 60\n";
  // longest edge 2 sqrt(2); face area (sqrt(3)/4) 8 = 2 sqrt(3); volume a^3/(6 sqrt(2)) = 8/3;
  // altitude 3 V / A = 8 / (2 sqrt(3)) = 4/sqrt(3); ratio 2 sqrt(2) sqrt(3) / 4 = sqrt(3/2)
  check_near("aspect ratio", q.aspect_ratio, std::sqrt(1.5), 1e-12);
  // (1,1,1) sees the other three clockwise: CGAL::NEGATIVE orientation
  check_near("volume (negative orientation)", q.volume, -8. / 3., 1e-12);
}

// 2. sliver: the unit square with one corner lifted by e,
//    A=(0,0,0) B=(1,0,0) C=(0,1,0) D=(1,1,e)
//  at AB: half-plane to C along (0,1,0), to D along (0,1,e): atan(e); same at AC
//  at BD: from B, to A (-1,0,0), to C (-1,1,0) minus its part along BD = (0,1,e):
//         (-1, e^2/(1+e^2), -e/(1+e^2)), so tan = e / sqrt(1+e^2); same at CD -> the smallest
//  at BC: to A (-1/2,-1/2,0), to D (1/2,1/2,e): cos = -1/sqrt(1+2e^2): 180 - atan(sqrt(2) e) -> the largest
//  at AD: cos = -1/(1+e^2): 180 - atan(e sqrt(2+e^2))
//  aspect ratio: longest edge AD = sqrt(2+e^2), volume e/6, largest face BCD of area
//  sqrt(1+2e^2)/2, so AR = sqrt(2+e^2) sqrt(1+2e^2) / e
static void test_sliver()
{
  for(double e : {1e-2, 1e-5})
  {
    std::cout << "sliver, e = " << e << "\n";
    const BM::Tetrahedron_quality q =
      BM::tetrahedron_quality(P{{0, 0, 0}}, P{{1, 0, 0}}, P{{0, 1, 0}}, P{{1, 1, e}});
    const double at_ab = deg(std::atan(e));
    const double at_bd = deg(std::atan(e / std::sqrt(1 + e * e)));
    // edges (0,1)=AB (0,2)=AC (0,3)=AD (1,2)=BC (1,3)=BD (2,3)=CD
    check_near("dihedral AB", q.dihedral_angles[0], at_ab, 1e-9);
    check_near("dihedral AC", q.dihedral_angles[1], at_ab, 1e-9);
    check_near("dihedral AD", q.dihedral_angles[2], 180. - deg(std::atan(e * std::sqrt(2 + e * e))), 1e-12);
    check_near("dihedral BC", q.dihedral_angles[3], 180. - deg(std::atan(std::sqrt(2.) * e)), 1e-12);
    check_near("dihedral BD", q.dihedral_angles[4], at_bd, 1e-9);
    check_near("dihedral CD", q.dihedral_angles[5], at_bd, 1e-9);
    check_near("smallest dihedral", q.min_dihedral_angle, at_bd, 1e-9);
    assert(q.min_dihedral_angle < 60. * e); // -> 0 with e (57.3 e degrees)
    check_near("aspect ratio", q.aspect_ratio, std::sqrt(2 + e * e) * std::sqrt(1 + 2 * e * e) / e, 1e-6);
    check_near("volume", q.volume, e / 6., 1e-9);
  }
  // flat: volume 0, aspect ratio infinite, smallest dihedral 0
  const BM::Tetrahedron_quality f =
    BM::tetrahedron_quality(P{{0, 0, 0}}, P{{1, 0, 0}}, P{{0, 1, 0}}, P{{1, 1, 0}});
  std::cout << "flat: volume " << f.volume << ", aspect ratio " << f.aspect_ratio << ", min dihedral "
            << f.min_dihedral_angle << "\n";
  assert(f.volume == 0. && std::isinf(f.aspect_ratio) && f.min_dihedral_angle == 0.);
}

// 3. right corner O=(0,0,0) X=(1,0,0) Y=(0,1,0) Z=(0,0,1):
//  dihedrals 90 at OX, OY, OZ; at XY, XZ, YZ between a coordinate plane and
//  x+y+z=1: acos(1/sqrt(3)) = 54.7356; faces: three (90,45,45) and one equilateral;
//  longest edge sqrt(2), volume 1/6, largest face sqrt(3)/2, altitude (1/2)/(sqrt(3)/2) = 1/sqrt(3),
//  aspect ratio sqrt(2) sqrt(3) = sqrt(6) = 2.4495
static void test_right_corner()
{
  std::cout << "right-corner tetrahedron\n";
  const BM::Tetrahedron_quality q =
    BM::tetrahedron_quality(P{{0, 0, 0}}, P{{1, 0, 0}}, P{{0, 1, 0}}, P{{0, 0, 1}});
  const double a = deg(std::acos(1. / std::sqrt(3.)));
  const double expected[6] = {90, 90, 90, a, a, a};
  for(int e = 0; e < 6; ++e) check_near("dihedral " + std::to_string(e), q.dihedral_angles[e], expected[e], 1e-12);
  std::multiset<long> faces;
  for(double f : q.face_angles) faces.insert(std::lround(f * 1e6));
  assert(faces.count(90000000) == 3 && faces.count(45000000) == 6 && faces.count(60000000) == 3);
  std::cout << "  face angles: 3 x 90, 6 x 45, 3 x 60\n";
  check_near("aspect ratio", q.aspect_ratio, std::sqrt(6.), 1e-12);
  check_near("volume", q.volume, 1. / 6., 1e-12);
  // the other orientation gives the same shape, a negative volume
  const BM::Tetrahedron_quality r =
    BM::tetrahedron_quality(P{{0, 0, 0}}, P{{0, 1, 0}}, P{{1, 0, 0}}, P{{0, 0, 1}});
  check_near("volume, swapped", r.volume, -1. / 6., 1e-12);
  check_near("aspect ratio, swapped", r.aspect_ratio, std::sqrt(6.), 1e-12);
}

// three separate tets: regular (region 1), sliver e = 0.01 (region 2), right corner (region 5)
static BM::Labeled_tetrahedral_mesh_3 three_tets(double e)
{
  BM::Labeled_tetrahedral_mesh_3 m;
  m.points = {{{1, 1, 1}}, {{1, -1, -1}}, {{-1, 1, -1}}, {{-1, -1, 1}},
              {{10, 0, 0}}, {{11, 0, 0}}, {{10, 1, 0}}, {{11, 1, e}},
              {{20, 0, 0}}, {{21, 0, 0}}, {{20, 1, 0}}, {{20, 0, 1}}};
  m.tetrahedra = {{{0, 1, 2, 3}}, {{4, 5, 6, 7}}, {{8, 9, 10, 11}}};
  m.regions = {1, 2, 5};
  m.region_names[5] = "corner";
  return m;
}

static void test_report()
{
  std::cout << "report on three tets\n";
  const double e = 0.01;
  BM::Labeled_tetrahedral_mesh_3 m = three_tets(e);
  const double sliver_min = deg(std::atan(e / std::sqrt(1 + e * e)));
  const double corner_min = deg(std::acos(1. / std::sqrt(3.)));
  const double regular = deg(std::acos(1. / 3.));

  BM::Mesh_quality_report r =
    BM::compute_mesh_quality(m, BM::parameters::number_of_steiner_points(7, BM::parameters::number_of_worst_tetrahedra(2)));
  assert(r.regions.size() == 3);
  assert(r.regions[0].region == 1 && r.regions[1].region == 2 && r.regions[2].region == 5);
  assert(r.regions[2].name == "corner");
  check("tets all", r.all.number_of_tetrahedra == 3, double(r.all.number_of_tetrahedra), 3);
  check("vertices all", r.all.number_of_vertices == 12, double(r.all.number_of_vertices), 12);
  for(const BM::Region_quality& q : r.regions)
    assert(q.number_of_tetrahedra == 1 && q.number_of_vertices == 4);
  check_near("volume all = 8/3 + e/6 + 1/6", r.all.volume, 8. / 3. + e / 6. + 1. / 6.);
  check_near("min dihedral all", r.all.min_dihedral_angle, sliver_min, 1e-9);
  check_near("max dihedral all", r.all.max_dihedral_angle, 180. - deg(std::atan(std::sqrt(2.) * e)), 1e-9);
  // mean of the 18 dihedrals: regular 6 x 70.53, right corner 3 x 90 + 3 x 54.74,
  // sliver 2 atan(e) + 2 (bd) + two near 180
  const double sliver_sum = 2 * deg(std::atan(e)) + 2 * sliver_min + 360. -
                            deg(std::atan(e * std::sqrt(2 + e * e))) - deg(std::atan(std::sqrt(2.) * e));
  check_near("mean dihedral all", r.all.mean_dihedral_angle,
             (6 * regular + 270. + 3 * corner_min + sliver_sum) / 18., 1e-9);
  check_near("mean smallest dihedral", r.all.mean_smallest_dihedral_angle,
             (regular + sliver_min + corner_min) / 3., 1e-9);
  for(std::size_t k = 0; k < 4; ++k)
    check_near("share under " + std::to_string(int(BM::Region_quality::dihedral_thresholds[k])),
               r.all.share_smallest_dihedral_under[k], 1. / 3.);
  check_near("region 2 share under 5", r.regions[1].share_smallest_dihedral_under[0], 1.);
  check_near("region 5 share under 20", r.regions[2].share_smallest_dihedral_under[3], 0.);
  // aspect ratios sqrt(3/2), sqrt(6), ~141.4: median sqrt(6); one above 10 and above 40
  check_near("aspect ratio median", r.all.median_aspect_ratio, std::sqrt(6.), 1e-12);
  check_near("aspect ratio min", r.all.min_aspect_ratio, std::sqrt(1.5), 1e-12);
  check_near("share AR > 10", r.all.share_aspect_ratio_above_10, 1. / 3.);
  check_near("share AR > 40", r.all.share_aspect_ratio_above_40, 1. / 3.);
  assert(std::isnan(r.all.share_under_10_not_at_small_surface_angle)); // no surfaces given
  assert(r.number_of_steiner_points && *r.number_of_steiner_points == 7);
  assert(!r.number_of_input_triangles_kept_whole);

  // histograms: frequencies sum to 1, and the bins the hand values fall in
  for(const BM::Region_quality* q : {&r.all, &r.regions[0], &r.regions[1], &r.regions[2]})
  {
    assert(near(histogram_sum(q->aspect_ratio_histogram), 1., 1e-12));
    assert(near(histogram_sum(q->face_angle_histogram), 1., 1e-12));
    assert(near(histogram_sum(q->dihedral_angle_histogram), 1., 1e-12));
  }
  std::cout << "  every histogram sums to 1\n";
  assert(r.all.aspect_ratio_histogram.counts.size() == 19 && r.all.face_angle_histogram.counts.size() == 18);
  const BM::Region_quality& reg = r.regions[0];
  assert(reg.dihedral_angle_histogram.frequencies[7] == 1.); // 70.53 in [70,80)
  assert(reg.face_angle_histogram.frequencies[6] == 1.);     // 60 in [60,70)
  assert(reg.aspect_ratio_histogram.frequencies[0] == 1.);   // 1.22 in [1,1.5)
  const BM::Region_quality& corner = r.regions[2];
  // dihedrals 3 x 90 in [90,100), 3 x 54.7 in [50,60); faces 6 x 45, 3 x 60, 3 x 90
  check_near("corner dihedral [50,60)", corner.dihedral_angle_histogram.frequencies[5], 0.5);
  check_near("corner dihedral [90,100)", corner.dihedral_angle_histogram.frequencies[9], 0.5);
  check_near("corner face [40,50)", corner.face_angle_histogram.frequencies[4], 0.5);
  check_near("corner face [60,70)", corner.face_angle_histogram.frequencies[6], 0.25);
  check_near("corner face [90,100)", corner.face_angle_histogram.frequencies[9], 0.25);
  check_near("corner AR [2,2.5)", corner.aspect_ratio_histogram.frequencies[2], 1.);
  check_near("sliver AR in [10,inf)", r.regions[1].aspect_ratio_histogram.frequencies[18], 1.);
  // all: 18 dihedrals; [70,80) holds the regular six
  check_near("all dihedral [70,80)", r.all.dihedral_angle_histogram.frequencies[7], 6. / 18.);

  // worst: the sliver, then the right corner
  assert(r.worst_tetrahedra.size() == 2);
  const BM::Worst_tetrahedron& w = r.worst_tetrahedra[0];
  assert(w.index == 1 && w.region == 2 && r.worst_tetrahedra[1].index == 2);
  check_near("worst centroid x", w.centroid[0], 10.5);
  check_near("worst centroid z", w.centroid[2], e / 4.);
  assert(std::isnan(w.touching_surface_min_angle) && w.boundary_faces == 0);

  // surfaces: the sliver's face (4,5,6) and the corner's face (8,9,10) as boundary triangles
  m.boundary_triangles = {{{4, 5, 6}}, {{8, 9, 10}}};
  m.boundary_patches = {3, 4};
  r = BM::compute_mesh_quality(m);
  assert(r.surface_angle_source == "boundary facets");
  // the triangle's own smallest angle is 45: the sliver is not explained by the surface
  check_near("worst touching surface angle (own)", r.worst_tetrahedra[0].touching_surface_min_angle, 45.);
  assert(r.worst_tetrahedra[0].boundary_faces == 1);
  assert(r.worst_tetrahedra[0].touching_patches == std::vector<int>{3});
  check_near("share under 10 unexplained", r.all.share_under_10_not_at_small_surface_angle, 1. / 3.);
  check_near("share under 10 touching nothing", r.all.share_under_10_not_touching_small_surface_angle, 1. / 3.);
  {
    // a needle triangle (angle 0.06 degrees) through the sliver's vertex 4 only:
    // the sliver shares no edge with it, so it stays unexplained, but it
    // touches a small surface angle at a point
    BM::Labeled_tetrahedral_mesh_3 mn = m;
    const std::array<double, 3> p4 = mn.points[4];
    mn.points.push_back({{p4[0] + 100., p4[1], p4[2]}});
    mn.points.push_back({{p4[0] + 100., p4[1] + 0.1, p4[2]}});
    mn.boundary_triangles.push_back({{4, mn.points.size() - 2, mn.points.size() - 1}});
    mn.boundary_patches.push_back(6);
    const BM::Mesh_quality_report rn = BM::compute_mesh_quality(mn);
    check_near("needle at a vertex: share under 10 unexplained", rn.all.share_under_10_not_at_small_surface_angle,
               1. / 3.);
    check_near("needle at a vertex: share under 10 touching nothing",
               rn.all.share_under_10_not_touching_small_surface_angle, 0.);
    std::ostringstream json;
    BM::IO::write_quality_report_json(json, rn);
    assert(json.str().find("\"share_under_10_not_touching_small_surface_angle\": 0") != std::string::npos);
  }
  // given input angles: the sliver's triangle came from an input triangle with a 5-degree angle
  m.input_min_angles = {5., 50.};
  r = BM::compute_mesh_quality(m);
  assert(r.surface_angle_source == "input triangles");
  check_near("worst touching surface angle (input)", r.worst_tetrahedra[0].touching_surface_min_angle, 5.);
  check_near("share under 10 unexplained, forced by input", r.all.share_under_10_not_at_small_surface_angle, 0.);
  check_near("corner touching surface angle", r.worst_tetrahedra[1].touching_surface_min_angle, 50.);
  // angles other than the input triangles' are named by the caller, and the counts do not change
  {
    const BM::Mesh_quality_report named =
      BM::compute_mesh_quality(m, BM::parameters::surface_angle_source("angles of my own"));
    assert(named.surface_angle_source == "angles of my own");
    assert(named.all.share_under_10_not_at_small_surface_angle == r.all.share_under_10_not_at_small_surface_angle);
    std::ostringstream named_text;
    BM::IO::write_quality_report_text(named_text, named);
    assert(named_text.str().find("(angles of my own)") != std::string::npos);
  }

  std::ostringstream json, text;
  BM::IO::write_quality_report_json(json, r);
  BM::IO::write_quality_report_text(text, r);
  std::cout << text.str();
  assert(json.str().find("\"share_under_10\": 0.333333333333") != std::string::npos);
  assert(json.str().find("\"name\": \"corner\"") != std::string::npos);
  assert(text.str().find("5 corner") != std::string::npos);

  // empty mesh: nothing to measure, no crash, NaN minima written as null
  r = BM::compute_mesh_quality(BM::Labeled_tetrahedral_mesh_3());
  assert(r.all.number_of_tetrahedra == 0 && r.regions.empty() && std::isnan(r.all.min_dihedral_angle));
  std::ostringstream empty;
  BM::IO::write_quality_report_json(empty, r);
  assert(empty.str().find("\"min\": null") != std::string::npos);
  std::cout << "  empty mesh: min dihedral null\n";
}

// a C3T3 filled by hand: the unit cube's corners and its centre. The Delaunay
// tetrahedralization is 12 congruent tets (centre + half a cube face), region 1
// when the centroid has x < 1/2, else 2: 6 and 6 (each face other than x=0 and
// x=1 has one half of each). Each tet, e.g. C=(.5,.5,.5) O X=(1,0,0) Y'=(1,1,0):
//  dihedrals 45 (at OX and XY'), 90 (at OY'), 120 (at CX), 60 (at CO and CY'): min 45, max 120, mean 70
//  faces (90,45,45), 2 x (54.74,54.74,70.53), (35.26,35.26,109.47)
//  longest edge sqrt(2), volume 1/12, largest face 1/2: aspect ratio 2 sqrt(2)
struct Fake_domain
{
  typedef int Subdomain_index;
  typedef int Surface_patch_index;
  typedef int Index;
};

static void test_c3t3()
{
  std::cout << "C3T3 filled by hand\n";
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Mesh_triangulation_3<Fake_domain, K>::type Tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;
  typedef Tr::Bare_point Bare_point;
  typedef Tr::Weighted_point Weighted_point;

  C3T3 c3t3;
  Tr& tr = c3t3.triangulation();
  for(int i = 0; i < 8; ++i)
    tr.insert(Weighted_point(Bare_point(i & 1, (i >> 1) & 1, (i >> 2) & 1)));
  tr.insert(Weighted_point(Bare_point(0.5, 0.5, 0.5)));
  assert(tr.number_of_finite_cells() == 12);
  // CGAL's writers skip vertices whose dimension is not set
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    c3t3.set_dimension(v, v->point().x() == 0.5 ? 3 : 2);

  std::set<Tr::Vertex_handle> in_region[3];
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
  {
    double x = 0;
    for(int k = 0; k < 4; ++k) x += c->vertex(k)->point().x() / 4;
    const int region = x < 0.5 ? 1 : 2;
    c3t3.add_to_complex(c, region);
    for(int k = 0; k < 4; ++k) in_region[region].insert(c->vertex(k));
  }
  // facets: hull (patch 10) and the interface between the regions (patch 20)
  std::size_t hull = 0, interface = 0;
  for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f)
  {
    const Tr::Cell_handle c = f->first, d = c->neighbor(f->second);
    // a finite facet may be given by its infinite cell
    if(tr.is_infinite(c) || tr.is_infinite(d)) { c3t3.add_to_complex(*f, 10); ++hull; }
    else if(c3t3.subdomain_index(c) != c3t3.subdomain_index(d)) { c3t3.add_to_complex(*f, 20); ++interface; }
  }
  std::cout << "  hull facets " << hull << ", interface facets " << interface << std::endl;
  // 4 interface facets inside the faces y=0, y=1, z=0, z=1 (their two halves differ),
  // more along the cube's x-parallel edges, depending on which diagonals the triangulation took
  assert(hull == 12 && interface >= 4);

  // own parameters chain with the two-argument form
  const auto angle = [&](const C3T3::Facet& f) { return c3t3.surface_patch_index(f) == 20 ? 7.5 : 45.; };
  const BM::Mesh_quality_report r = BM::compute_c3t3_quality(
    c3t3, BM::parameters::number_of_input_triangles_kept_whole(12, BM::parameters::facet_input_min_angle(angle)));
  check("tets", r.all.number_of_tetrahedra == 12, double(r.all.number_of_tetrahedra), 12);
  check("vertices", r.all.number_of_vertices == 9, double(r.all.number_of_vertices), 9);
  check("boundary triangles", r.number_of_boundary_triangles == hull + interface,
        double(r.number_of_boundary_triangles), double(hull + interface));
  assert(r.regions.size() == 2);
  for(int i = 0; i < 2; ++i)
  {
    const BM::Region_quality& q = r.regions[i];
    check("region " + std::to_string(q.region) + " tets", q.number_of_tetrahedra == 6,
          double(q.number_of_tetrahedra), 6);
    check("region " + std::to_string(q.region) + " vertices", q.number_of_vertices == in_region[q.region].size(),
          double(q.number_of_vertices), double(in_region[q.region].size()));
    check_near("region " + std::to_string(q.region) + " volume", q.volume, 0.5, 1e-12);
  }
  check_near("min dihedral", r.all.min_dihedral_angle, 45., 1e-9);
  check_near("max dihedral", r.all.max_dihedral_angle, 120., 1e-9);
  check_near("mean dihedral", r.all.mean_dihedral_angle, 70., 1e-9);
  check_near("min face angle", r.all.min_face_angle, deg(std::atan(1. / std::sqrt(2.))), 1e-9);
  check_near("max face angle", r.all.max_face_angle, 180. - 2. * deg(std::atan(1. / std::sqrt(2.))), 1e-9);
  check_near("aspect ratio median", r.all.median_aspect_ratio, 2. * std::sqrt(2.), 1e-9);
  assert(r.all.number_of_negatively_oriented_tetrahedra == 0); // CGAL cells are positive
  assert(r.surface_angle_source == "input triangles");
  assert(r.number_of_input_triangles_kept_whole && *r.number_of_input_triangles_kept_whole == 12);
  // every tet has its base on the hull, and the tets next to the interface touch it: 7.5
  std::size_t at_interface = 0;
  for(const BM::Worst_tetrahedron& w : r.worst_tetrahedra)
  {
    assert(w.boundary_faces >= 1);
    if(w.touching_surface_min_angle == 7.5) ++at_interface;
    else assert(w.touching_surface_min_angle == 45.);
  }
  std::cout << "  worst tets listed " << r.worst_tetrahedra.size() << ", touching the interface " << at_interface
            << "\n";
  // the 8 tets on the faces y=0, y=1, z=0, z=1 contain the interface facets themselves
  assert(r.worst_tetrahedra.size() == 12 && at_interface >= 8);

  // CGAL's own writers, read back: the same tets, the same numbers
  const std::string dir = BUBBLE_MESH_3_BINARY_DIR;
  {
    std::ofstream os(dir + "/test_quality_c3t3.mesh");
    CGAL::IO::output_to_medit(os, c3t3);
  }
  {
    std::ofstream os(dir + "/test_quality_c3t3.vtu", std::ios::binary);
    CGAL::IO::output_to_vtu(os, c3t3); // binary, raw appended data
  }
  {
    std::ofstream os(dir + "/test_quality_c3t3_ascii.vtu");
    CGAL::IO::output_to_vtu(os, c3t3, CGAL::IO::ASCII);
  }
  for(const char* f : {"/test_quality_c3t3.mesh", "/test_quality_c3t3.vtu", "/test_quality_c3t3_ascii.vtu"})
  {
    const BM::Labeled_tetrahedral_mesh_3 m = BM::IO::read_tet_mesh(dir + f);
    const BM::Mesh_quality_report back = BM::compute_mesh_quality(m);
    std::cout << "  read back " << f << ": " << m.tetrahedra.size() << " tets, " << m.boundary_triangles.size()
              << " triangles" << std::endl;
    assert(back.regions.size() == 2);
    for(int i = 0; i < 2; ++i)
    {
      assert(back.regions[i].region == r.regions[i].region);
      assert(back.regions[i].number_of_tetrahedra == r.regions[i].number_of_tetrahedra);
      assert(back.regions[i].number_of_vertices == r.regions[i].number_of_vertices);
      assert(near(back.regions[i].volume, r.regions[i].volume, 1e-12));
    }
    assert(near(back.all.min_dihedral_angle, r.all.min_dihedral_angle, 1e-12));
    assert(near(back.all.median_aspect_ratio, r.all.median_aspect_ratio, 1e-12));
  }
}

// the SVG pictures: well formed enough to hold one curve per region and the legend
static void test_svg()
{
  std::cout << "SVG histograms\n";
  const BM::Mesh_quality_report r = BM::compute_mesh_quality(three_tets(0.01));
  std::ostringstream one, two;
  BM::IO::write_svg_histograms(one, r);
  BM::IO::write_svg_histogram_comparison(two, {r, r}, {"ours", "peer"});
  auto count = [](const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for(std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
  };
  // 3 regions + the whole model, in 3 panels
  std::cout << "  one mesh: " << count(one.str(), "<path") << " curves; two meshes: " << count(two.str(), "<path")
            << " curves" << std::endl;
  assert(count(one.str(), "<path") == 12 && count(two.str(), "<path") == 6);
  assert(one.str().find("region 5 corner (1 tets)") != std::string::npos);
  assert(two.str().find("peer (3 tets)") != std::string::npos);
  assert(one.str().rfind("</svg>") != std::string::npos);
}


// The tet faces met once become the boundary triangles, their input said to be
// good (angle 60), so that no surface angle explains anything.
static void add_faces_met_once(BM::Labeled_tetrahedral_mesh_3& m)
{
  std::map<std::array<std::size_t, 3>, int> faces;
  for(const auto& tet : m.tetrahedra)
    for(int f = 0; f < 4; ++f)
    {
      std::array<std::size_t, 3> s = {{tet[(f + 1) % 4], tet[(f + 2) % 4], tet[(f + 3) % 4]}};
      std::sort(s.begin(), s.end());
      ++faces[s];
    }
  for(const auto& f : faces)
    if(f.second == 1)
    {
      m.boundary_triangles.push_back(f.first);
      m.input_min_angles.push_back(60.);
    }
}

// Region 1 of a wedge between z = 0 and z = t x, x and y in [0, 1]: a prism with
// ends (A, C, E) = points 0, 1, 2 at y = 0 and (B, D, F) = 3, 4, 5 at y = 1, in
// three tets.
static BM::Labeled_tetrahedral_mesh_3 wedge_prism(double t)
{
  BM::Labeled_tetrahedral_mesh_3 m;
  m.points = {{{0., 0., 0.}}, {{1., 0., 0.}}, {{1., 0., t}}, {{0., 1., 0.}}, {{1., 1., 0.}}, {{1., 1., t}}};
  const std::size_t A = 0, C = 1, E = 2, B = 3, D = 4, F = 5;
  m.tetrahedra = {{{A, C, E, F}}, {{A, C, F, D}}, {{A, D, F, B}}};
  m.regions = {1, 1, 1};
  return m;
}

// A sharp contact: region 1 is a wedge between z = 0 and z = t x (5 degrees),
// x and y in [0, 1], whose edge x = z = 0 no mesher can meet with good tets;
// region 2 is a box [2, 3] x [0, 1] x [0, t], as thin as the wedge's end, whose
// edges are right angles: its thin tets are the mesher's. The input triangles
// are said to be good (angle 60), so that no surface angle explains anything.
static void test_sharp_contact()
{
  const double t = std::tan(5. * pi / 180.);
  BM::Labeled_tetrahedral_mesh_3 m = wedge_prism(t);
  // the box: corner k at (2 + (k & 1), (k >> 1) & 1, t ((k >> 2) & 1)), six tets around its diagonal
  for(int k = 0; k < 8; ++k) m.points.push_back({{2. + (k & 1), double((k >> 1) & 1), t * ((k >> 2) & 1)}});
  const std::size_t o = 6;
  for(int a : {1, 2, 4})
    for(int b : {1, 2, 4})
      if(a != b)
      {
        m.tetrahedra.push_back({{o, o + a, o + a + b, o + 7}});
        m.regions.push_back(2);
      }
  add_faces_met_once(m);
  assert(m.boundary_triangles.size() == 8 + 12);

  const BM::Mesh_quality_report r = BM::compute_mesh_quality(m);
  const BM::Region_quality &wedge = r.regions[0], &box = r.regions[1];
  check_near("wedge: share under 10", wedge.share_smallest_dihedral_under[1], 1.);
  check_near("wedge: share under 10 not at a small surface angle", wedge.share_under_10_not_at_small_surface_angle, 1.);
  check_near("wedge: share under 10 at a sharp contact", wedge.share_under_10_at_sharp_contact, 1.);
  assert(box.share_smallest_dihedral_under[1] > 0.);
  check_near("box: share under 10 not at a small surface angle", box.share_under_10_not_at_small_surface_angle,
             box.share_smallest_dihedral_under[1]);
  check_near("box: share under 10 at a sharp contact", box.share_under_10_at_sharp_contact, 0.);
  check_near("all: share under 10 at a sharp contact", r.all.share_under_10_at_sharp_contact, 3. / 9.);
  // each worst tet's contact angle: the wedge's 5 degrees (the sum of its tets'
  // dihedrals at A B), the box's right angle
  bool seen_wedge = false, seen_box = false;
  for(const BM::Worst_tetrahedron& w : r.worst_tetrahedra)
  {
    if(w.region == 1) { check_near("wedge tet's contact angle", w.contact_min_angle, 5., 1e-9); seen_wedge = true; }
    if(w.region == 2) { check_near("box tet's contact angle", w.contact_min_angle, 90., 1e-9); seen_box = true; }
  }
  assert(seen_wedge && seen_box);
  std::ostringstream text;
  BM::IO::write_quality_report_text(text, r);
  assert(text.str().find("next to a sharp contact") != std::string::npos);
}

// Inside a sharp contact's wedge: region 1 is the 5-degree wedge between z = 0
// and z = t x for x in [0, 2], y in [0, 1]: a prism at its edge (three tets
// through A or B) and a slab x in [1, 2] (six tets touching neither). The
// slab's tets span the wedge, at most 2 t = 0.17 thick, with edges of about 1:
// thin there whatever the mesher does, so counted at the contact. A sliver 0.05
// across inside the slab, where the wedge is thicker than it, is the mesh's own
// (it touches no surface). Region 2, a box [3, 4] x [0, 1] x [0, t], is as
// thin but its edges are right angles: nothing there is the contact's.
static void test_thin_wedge()
{
  const double t = std::tan(5. * pi / 180.);
  BM::Labeled_tetrahedral_mesh_3 m = wedge_prism(t);
  const std::size_t C = 1, E = 2, D = 4, F = 5;
  // a hexahedron with corner k at (x0 + (k & 1), (k >> 1) & 1, top(x) if k & 4), in
  // six tets around its diagonal (0, 7); `corner` gives the indices of its corners
  auto hexahedron = [&](std::array<std::size_t, 8> corner, int region) {
    for(int a : {1, 2, 4})
      for(int b : {1, 2, 4})
        if(a != b)
        {
          m.tetrahedra.push_back({{corner[0], corner[a], corner[a + b], corner[7]}});
          m.regions.push_back(region);
        }
  };
  auto add_point = [&](double x, double y, double z) {
    m.points.push_back({{x, y, z}});
    return m.points.size() - 1;
  };
  // the slab shares the prism's face x = 1 (split along C F, as the six tets split it)
  hexahedron({{C, add_point(2., 0., 0.), D, add_point(2., 1., 0.), E, add_point(2., 0., 2. * t), F,
               add_point(2., 1., 2. * t)}},
             1);
  std::array<std::size_t, 8> box;
  for(int k = 0; k < 8; ++k) box[k] = add_point(3. + (k & 1), double((k >> 1) & 1), t * ((k >> 2) & 1));
  hexahedron(box, 2);
  add_faces_met_once(m);
  // the sliver: a square's corners lifted alternately, 0.05 across, at (1.8, 0.5, 0.07)
  {
    const double h = 0.025, lift = 0.002;
    const std::size_t s0 = add_point(1.8 - h, 0.5 - h, 0.07), s1 = add_point(1.8 + h, 0.5 + h, 0.07),
                      s2 = add_point(1.8 + h, 0.5 - h, 0.07 + lift), s3 = add_point(1.8 - h, 0.5 + h, 0.07 + lift);
    m.tetrahedra.push_back({{s0, s1, s2, s3}});
    m.regions.push_back(1);
  }

  const BM::Mesh_quality_report r = BM::compute_mesh_quality(m);
  const BM::Region_quality &wedge = r.regions[0], &thin_box = r.regions[1];
  const double n1 = double(wedge.number_of_tetrahedra);
  assert(wedge.number_of_tetrahedra == 3 + 6 + 1);
  std::size_t slab_under_10 = 0, slab_tets = 0;
  for(std::size_t i = 3; i < 9; ++i)
  {
    const auto& tet = m.tetrahedra[i];
    ++slab_tets;
    if(BM::tetrahedron_quality(m.points[tet[0]], m.points[tet[1]], m.points[tet[2]], m.points[tet[3]])
         .min_dihedral_angle < 10.)
      ++slab_under_10;
  }
  std::cout << "  thin wedge: " << slab_under_10 << " of the slab's " << slab_tets << " tets under 10 degrees"
            << std::endl;
  assert(slab_under_10 > 0);
  // the prism's 3, the slab's thin ones and the sliver are under 10 and no surface angle explains them
  check_near("wedge: share under 10 not at a small surface angle", wedge.share_under_10_not_at_small_surface_angle,
             double(3 + slab_under_10 + 1) / n1);
  // the contact takes all but the sliver
  check_near("wedge: share under 10 at a sharp contact", wedge.share_under_10_at_sharp_contact,
             double(3 + slab_under_10) / n1);
  assert(thin_box.share_smallest_dihedral_under[1] > 0.);
  check_near("thin box: share under 10 at a sharp contact", thin_box.share_under_10_at_sharp_contact, 0.);
}

int main()
{
  std::cout.precision(10);
  test_regular();
  test_sliver();
  test_right_corner();
  test_report();
  test_sharp_contact();
  test_thin_wedge();
  test_c3t3();
  test_svg();
  std::cout << "test_quality: all checks passed\n";
  return EXIT_SUCCESS;
}
