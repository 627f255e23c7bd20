// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Validation of geological models: every class of bad input gives a located
// message, good inputs pass, and the summary's numbers are right.

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/IO/read_gocad_model3d.h>
#include <CGAL/Bubble_mesh_3/IO/read_multibody_obj.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/geological_model_summary.h>
#include <CGAL/Bubble_mesh_3/orient_patch_sides.h>
#include <CGAL/Bubble_mesh_3/snap_points_to_axis_planes.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Timer.h>

#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;
namespace BM = CGAL::Bubble_mesh_3;

namespace {

const std::string bad_dir = std::string(BUBBLE_MESH_3_TEST_DATA_DIR) + "/bad/";

// Builds models from grids of squares; coincident points are shared.
struct Builder
{
  Model model;
  std::map<std::array<double, 3>, std::size_t> index;

  std::size_t point(const Point& p)
  {
    const std::array<double, 3> key{{p.x(), p.y(), p.z()}};
    auto it = index.find(key);
    if(it != index.end()) return it->second;
    const std::size_t i = model.add_point(p);
    index[key] = i;
    return i;
  }

  // the rectangle o + [0,1] u + [0,1] v as nu x nv squares of two triangles, normals along u x v
  void grid(std::size_t patch, const Point& o, const Vector& u, const Vector& v, int nu, int nv)
  {
    for(int i = 0; i < nu; ++i)
      for(int j = 0; j < nv; ++j)
      {
        // a*u/nu rather than (a/nu)*u: exact for the sizes used here, so that grids share points
        auto P = [&](int a, int b) { return point(o + (u * double(a)) / double(nu) + (v * double(b)) / double(nv)); };
        const std::size_t p00 = P(i, j), p10 = P(i + 1, j), p11 = P(i + 1, j + 1), p01 = P(i, j + 1);
        model.add_triangle(p00, p10, p11, patch);
        model.add_triangle(p00, p11, p01, patch);
      }
  }

  // the six faces of the box [a,b], n squares per unit length, normals outward
  void box(std::size_t patch, const Point& a, const Point& b, int n, bool inward = false)
  {
    const double dx = b.x() - a.x(), dy = b.y() - a.y(), dz = b.z() - a.z();
    const Vector X(dx, 0, 0), Y(0, dy, 0), Z(0, 0, dz);
    const int nx = std::max(1, int(n * dx)), ny = std::max(1, int(n * dy)), nz = std::max(1, int(n * dz));
    auto face = [&](const Point& o, const Vector& u, const Vector& v, int nu, int nv) {
      if(inward) grid(patch, o, v, u, nv, nu);
      else grid(patch, o, u, v, nu, nv);
    };
    face(a, Y, X, ny, nx);          // z = a.z, normal -z
    face(a + Z, X, Y, nx, ny);      // z = b.z, normal +z
    face(a, X, Z, nx, nz);          // y = a.y, normal -y
    face(a + Y, Z, X, nz, nx);      // y = b.y, normal +y
    face(a, Z, Y, nz, ny);          // x = a.x, normal -x
    face(a + X, Y, Z, ny, nz);      // x = b.x, normal +x
  }
};

// Two layers in the box [0,3]x[0,3]x[0,2] (n squares per unit length, n a power of two so that
// coordinates are exact and the fault's top meets the horizon's points) and a fault in the
// lower layer: a vertical rectangle on x = 1 that hangs from the horizon down to z = 0.5 and
// ends there, inside the layer.
Model two_layers_with_fault(int n = 1)
{
  Builder b;
  Model& m = b.model;
  const std::size_t lower = m.add_region("Lower"), upper = m.add_region("Upper");
  const std::size_t base = m.add_patch("Base", 0, lower);
  const std::size_t horizon = m.add_patch("Horizon", upper, lower);
  const std::size_t top = m.add_patch("Top", 0, upper);
  const std::size_t lower_sides = m.add_patch("Lower sides", 0, lower);
  const std::size_t upper_sides = m.add_patch("Upper sides", 0, upper);
  const std::size_t fault = m.add_patch("Fault", lower, lower);
  const Vector X(3, 0, 0), Y(0, 3, 0);
  b.grid(base, Point(0, 0, 0), Y, X, 3 * n, 3 * n);
  b.grid(horizon, Point(0, 0, 1), X, Y, 3 * n, 3 * n);
  b.grid(top, Point(0, 0, 2), X, Y, 3 * n, 3 * n);
  for(int layer = 0; layer < 2; ++layer)
  {
    const std::size_t p = layer == 0 ? lower_sides : upper_sides;
    const Point o(0, 0, layer);
    const Vector Z(0, 0, 1);
    b.grid(p, o, Z, Y, n, 3 * n);          // x = 0
    b.grid(p, o + X, Y, Z, 3 * n, n);      // x = 3
    b.grid(p, o, X, Z, 3 * n, n);          // y = 0
    b.grid(p, o + Y, Z, X, n, 3 * n);      // y = 3
  }
  b.grid(fault, Point(1, 1, 0.5), Vector(0, 1, 0), Vector(0, 0, 0.5), n, std::max(1, n / 2));
  return m;
}

Model unit_cube(const std::string& name = "Cube")
{
  Builder b;
  const std::size_t r = b.model.add_region(name);
  b.box(b.model.add_patch("Skin", 0, r), Point(0, 0, 0), Point(1, 1, 1), 1);
  return b.model;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string validation_message(const Model& m)
{
  try
  {
    BM::validate_geological_model(m);
  }
  catch(const BM::Geological_model_error& e)
  {
    return e.what();
  }
  return std::string();
}

// `m` must be rejected with a message holding every one of `parts`
void expect_error(const std::string& what, const Model& m, std::initializer_list<std::string> parts)
{
  const std::string msg = validation_message(m);
  std::cout << "-- " << what << ":\n" << msg << "\n";
  assert(!msg.empty());
  for(const std::string& p : parts)
  {
    if(!contains(msg, p)) std::cerr << "missing in the message: \"" << p << "\"\n";
    assert(contains(msg, p));
  }
  // the list of problems starts with the same one
  const std::vector<std::string> problems = BM::geological_model_problems(m);
  assert(!problems.empty() && problems.front() == msg);
}

Model read_bad(const std::string& file)
{
  Model m;
  if(file.size() > 3 && file.compare(file.size() - 3, 3, ".ml") == 0)
    BM::IO::read_gocad_model3d(bad_dir + file, m);
  else
    BM::IO::read_multibody_obj(bad_dir + file, m);
  return m;
}

void expect_file_error(const std::string& file, std::initializer_list<std::string> parts)
{
  expect_error(file, read_bad(file), parts);
}

void test_good_models()
{
  const Model m = two_layers_with_fault();
  BM::validate_geological_model(m);
  assert(BM::geological_model_problems(m).empty());
  std::cout << "two layers with a fault ending inside the lower one: " << m.number_of_triangles()
            << " triangles, valid\n";

  // the same, finer, and a body with a cavity (the cavity's surface faces into the cavity)
  const Model fine = two_layers_with_fault(4);
  BM::validate_geological_model(fine);
  Builder b;
  const std::size_t shell = b.model.add_region("Shell");
  b.box(b.model.add_patch("Outer", 0, shell), Point(0, 0, 0), Point(3, 3, 3), 1);
  b.box(b.model.add_patch("Cavity", 0, shell), Point(1, 1, 1), Point(2, 2, 2), 1, true);
  BM::validate_geological_model(b.model);
  const BM::Geological_model_summary s = BM::summarize_geological_model(b.model);
  std::cout << "body with a cavity: valid, volume " << s.regions[0].volume << " (27 - 1)\n";
  assert(std::abs(s.regions[0].volume - 26.) < 1e-12);

  // two separate pieces of one region are fine too
  Builder p;
  const std::size_t r = p.model.add_region("Pieces");
  const std::size_t skin = p.model.add_patch("Skin", 0, r);
  p.box(skin, Point(0, 0, 0), Point(1, 1, 1), 1);
  p.box(skin, Point(2, 0, 0), Point(3, 1, 1), 1);
  BM::validate_geological_model(p.model);
  std::cout << "region in two pieces: valid\n";
}

void test_bad_in_memory()
{
  {
    Model m;
    expect_error("empty model", m, {"empty", "no region and no triangle"});
  }
  {
    Model m = unit_cube();
    m.set_point(3, Point(std::numeric_limits<double>::quiet_NaN(), 0., 1.));
    expect_error("NaN coordinate", m, {"not finite", "vertex 3 ", "nan"});
  }
  {
    Model m = unit_cube();
    m.set_patch_regions(0, 7, 0);
    expect_error("unknown region id", m, {"patch 0 'Skin'", "region 7", "does not exist", "1 regions"});
  }
  {
    Model m = unit_cube();
    const std::size_t v = m.add_point(Point(0.5, 0.5, 0.5));
    const std::size_t w = m.add_point(Point(1.5, 1.5, 1.5));
    const std::size_t p = m.add_patch("Needle", 1, 1);
    m.add_triangle(v, w, 0, p); // 0 = (0,0,0): collinear with v and w
    expect_error("collinear triangle", m, {"degenerate", "triangle 12 of patch 1 'Needle'", "zero area", "vertex 9 (1.5, 1.5, 1.5)"});
  }
  {
    Model m = unit_cube();
    m.set_triangle(3, Model::Triangle{{2, 2, 5}});
    expect_error("repeated vertex", m, {"degenerate", "triangle 3 of patch 0 'Skin' uses vertex 2"});
  }
  {
    // a region that no patch bounds
    Model m = unit_cube();
    m.add_region("Ghost");
    expect_error("region without boundary", m, {"region 2 'Ghost' has no boundary"});
  }
  {
    // a surface inside the region that pokes through its top: vertex outside
    Model m = two_layers_with_fault();
    const std::size_t q = m.add_point(Point(2, 2, 1.5));
    const std::size_t r = m.add_point(Point(2, 2, 3)); // above the model
    const std::size_t s = m.add_point(Point(2, 2.5, 1.5));
    const std::size_t p = m.add_patch("Spike", 2, 2);
    m.add_triangle(q, s, r, p);
    expect_error("surface inside a region that leaves it", m,
                 {"1 vertex lies outside", "patch 6 'Spike' lies inside region 2 'Upper'",
                  "vertex " + std::to_string(r) + " (2, 2, 3)"});
  }
}

// The box [0,4]^3 holding two one-triangle surfaces S1 and S2: to test the pair predicate.
Model two_triangles_in_a_box(const std::array<Point, 3>& t1, const std::array<Point, 3>& t2)
{
  Builder b;
  const std::size_t r = b.model.add_region("Box");
  b.box(b.model.add_patch("Skin", 0, r), Point(0, 0, 0), Point(4, 4, 4), 1);
  for(int k = 0; k < 2; ++k)
  {
    const auto& t = k == 0 ? t1 : t2;
    const std::size_t p = b.model.add_patch(k == 0 ? "S1" : "S2", r, r);
    b.model.add_triangle(b.point(t[0]), b.point(t[1]), b.point(t[2]), p);
  }
  return b.model;
}

void test_triangle_pairs()
{
  const Point v(1, 1, 1), a(3, 1, 1), c(1, 3, 1);
  const std::array<Point, 3> t{{v, a, c}};
  struct Case
  {
    const char* what;
    std::array<Point, 3> other;
    const char* expected; // nullptr: valid
  };
  const Case cases[] = {
    {"common vertex, the other triangle pierces", {{v, Point(2.5, 1.2, 0.5), Point(1.2, 2.5, 1.5)}}, " intersect near "},
    {"common vertex only", {{v, Point(0.5, 2, 2), Point(2, 0.5, 2)}}, nullptr},
    {"common vertex, coplanar, overlapping", {{v, Point(2, 1.5, 1), Point(3, 3, 1)}}, " overlap near "},
    {"common vertex, coplanar, apart", {{v, Point(0.5, 0.5, 1), Point(1, 0.5, 1)}}, nullptr},
    {"common edge, bent", {{a, v, Point(2, 1, 3)}}, nullptr},
    {"common edge, coplanar, folded over", {{a, v, Point(2, 2, 1)}}, " overlap near "},
    {"common edge, coplanar, flat", {{a, v, Point(2, 0.5, 1)}}, nullptr},
    {"a vertex on the other's edge", {{Point(2, 1, 1), Point(2, 0.5, 2), Point(2, 0.5, 0.5)}}, " intersect near (2, 1, 1)"},
    {"a vertex inside the other", {{Point(1.5, 1.5, 1), Point(2, 2, 2), Point(2, 1, 2)}}, " intersect near (1.5, 1.5, 1)"},
    {"apart", {{Point(1, 1, 2), Point(3, 1, 2), Point(1, 3, 2)}}, nullptr},
  };
  for(const Case& k : cases)
  {
    const std::string msg = validation_message(two_triangles_in_a_box(t, k.other));
    std::cout << k.what << ": " << (msg.empty() ? std::string("valid") : msg.substr(msg.find('\n') + 3)) << "\n";
    if(k.expected == nullptr)
      assert(msg.empty());
    else
      assert(contains(msg, "surfaces intersect: 1 pair") && contains(msg, "patch 1 'S1'") &&
             contains(msg, "patch 2 'S2'") && contains(msg, k.expected));
  }
}

void test_bad_files()
{
  expect_file_error("self_intersecting.obj", {"surfaces intersect", "8 pairs", "self_intersecting.obj:13: triangle 0",
                                              "and triangle 10 of patch 0 'Dented/outside' (line 23) intersect near"});
  expect_file_error("open_boundary.obj", {"not closed", "3 edges", "open_boundary.obj:15: ", "region 1 'Cube'",
                                          "edge 1-5 (1, 0, 0)-(1, 0, 1)", "triangle 4 of patch 0"});
  expect_file_error("nonmanifold_edge.obj", {"not manifold", "region 1 'TwoTets'", "edge 0-1 (0, 0, 0)-(1, 0, 0)",
                                             "shared by 4 triangles"});
  expect_file_error("nonmanifold_vertex.obj", {"not manifold", "pinched", "region 1 'Hourglass'",
                                               "vertex 0 (0, 0, 0) joins 2 separate fans"});
  expect_file_error("inconsistent_orientation.obj", {"not consistently oriented", "3 edges", "region 1 'Cube'",
                                                     "inconsistent_orientation.obj:13: ", "triangle 2 of patch 0"});
  expect_file_error("inside_surface_outside.obj", {"leave", "patch 1 'Fault' lies inside region 1 'Cube'",
                                                   "vertex 10 (0.5, 0.8, 1.5)", "inside_surface_outside.obj:"});
  expect_file_error("crossing_bodies.obj", {"surfaces intersect", "patch 0 'A/outside'", "patch 1 'B/outside'",
                                            "crossing_bodies.obj:", "near ("});
  expect_file_error("overlapping_coplanar.obj", {"surfaces intersect", "'Lower/outside'", "'Upper/outside'",
                                                 "overlapping_coplanar.obj:14: triangle 2 of patch 0", "(line 33) overlap near"});
  expect_file_error("degenerate_triangle.obj", {"degenerate", "zero area", "degenerate_triangle.obj:25: ",
                                                "triangle 13 of patch 0", "vertex 8 (0.5, 0, 0)"});
  // the OBJ reader flips bodies of negative volume and rejects repeated triangles: GOCAD files
  expect_file_error("wrong_side.ml", {"non-positive volume", "wrong_side.ml: ", "region 1 'Cube' has volume -1",
                                      "patch 0 'skin' has it as positive region"});
  expect_file_error("duplicate_triangle.ml", {"duplicate", "duplicate_triangle.ml:60: triangle 12 of patch 1 'copy'",
                                              "duplicates triangle 2 of patch 0 'skin' (line 41)", "vertices 4, 5, 6"});
  expect_file_error("wrong_cavity.obj", {"wrongly nested", "region 1 'Shell'", "faces outward but lies inside",
                                         "wrong_cavity.obj:"});

  // the list of all problems: the open cube also crosses a second body
  {
    Model m = read_bad("crossing_bodies.obj");
    const std::vector<std::string> problems = BM::geological_model_problems(m, BM::parameters::maximum_number_of_reported_elements(2));
    assert(problems.size() == 1);
    assert(contains(problems[0], "... and "));
    std::cout << "crossing bodies: " << problems.size() << " problem, message limited to 2 lines plus a count\n";
  }
}

void test_summary()
{
  Model cube = unit_cube("Cube \"A\"\\B");
  const BM::Geological_model_summary s = BM::summarize_geological_model(cube);
  const auto& r = s.regions.at(0);
  std::cout << "unit cube: volume " << r.volume << ", edges " << r.min_edge_length << " / " << r.median_edge_length
            << " / " << r.max_edge_length << ", min angle " << r.min_angle << ", " << r.number_of_points
            << " points, " << r.number_of_boundary_triangles << " triangles\n";
  assert(std::abs(r.volume - 1.) < 1e-14 && std::abs(s.volume - 1.) < 1e-14);
  assert(r.min_edge_length == 1. && r.median_edge_length == 1.);
  assert(std::abs(r.max_edge_length - std::sqrt(2.)) < 1e-14);
  assert(std::abs(r.min_angle - 45.) < 1e-9 && std::abs(s.min_angle - 45.) < 1e-9);
  assert(r.number_of_points == 8 && r.number_of_boundary_triangles == 12 && r.number_of_inside_triangles == 0);
  assert(s.number_of_poor_triangles == 0);
  assert(s.bbox.xmin() == 0. && s.bbox.zmax() == 1.);

  std::ostringstream text;
  BM::write_summary_text(text, s);
  std::cout << text.str();
  assert(!contains(text.str(), "warning"));

  std::ostringstream json;
  BM::write_summary_json(json, s);
  const std::string j = json.str();
  int depth = 0, min_depth = 0;
  bool in_string = false;
  for(std::size_t i = 0; i < j.size(); ++i)
  {
    if(in_string)
    {
      if(j[i] == '\\') ++i;
      else if(j[i] == '"') in_string = false;
      continue;
    }
    if(j[i] == '"') in_string = true;
    else if(j[i] == '{' || j[i] == '[') ++depth;
    else if(j[i] == '}' || j[i] == ']') min_depth = std::min(min_depth, --depth);
  }
  assert(depth == 0 && min_depth == 0 && !in_string);
  assert(contains(j, "\"name\": \"Cube \\\"A\\\"\\\\B\""));
  assert(contains(j, "\"volume\": 1"));
  const std::string json_file = std::string(BUBBLE_MESH_3_BINARY_DIR) + "/test_validation_summary.json";
  {
    std::ofstream out(json_file);
    out << j;
  }
  if(std::system("command -v python3 >/dev/null 2>&1") == 0)
  {
    const int rc = std::system(("python3 -c 'import json,sys; json.load(open(sys.argv[1]))' '" + json_file + "'").c_str());
    assert(rc == 0);
    std::cout << "summary JSON parses with python3\n";
  }
  else
    std::cout << "SKIP: python3 not found, JSON checked for balanced brackets only\n";

  // two layers with a fault: per-region numbers, the surface inside, the global min angle
  const Model m = two_layers_with_fault();
  const BM::Geological_model_summary t = BM::summarize_geological_model(m, BM::parameters::poor_angle_bound(30.));
  std::ostringstream text2;
  BM::write_summary_text(text2, t);
  std::cout << text2.str();
  assert(t.regions.size() == 2 && t.surfaces_inside_regions.size() == 1);
  assert(std::abs(t.regions[0].volume - 9.) < 1e-12 && std::abs(t.regions[1].volume - 9.) < 1e-12);
  assert(std::abs(t.volume - 18.) < 1e-12);
  assert(t.regions[0].number_of_inside_triangles == 2 && t.regions[1].number_of_inside_triangles == 0);
  assert(t.surfaces_inside_regions[0].name == "Fault" && t.surfaces_inside_regions[0].region == 1);
  // the fault's 1 x 0.5 rectangle has the smallest angle, atan(1/2)
  const double expected = std::atan(0.5) * 180. / 3.14159265358979323846;
  assert(std::abs(t.min_angle - expected) < 1e-9 && t.min_angle_patch_name == "Fault");
  assert(std::abs(t.regions[0].min_angle - expected) < 1e-9 && std::abs(t.regions[1].min_angle - 45.) < 1e-9);
  assert(std::abs(t.regions[0].min_edge_length - 0.5) < 1e-14);
  assert(t.number_of_poor_triangles == 2);
  assert(contains(text2.str(), "warning: input min angle 26.6 deg at triangle") &&
         contains(text2.str(), "(patch 'Fault')") && contains(text2.str(), "--remesh-surfaces"));
}

// A wedge of `degrees` between two patches meeting along the y axis (a layer pinching
// out), closed by a wall and two ends; with `one_patch` both faces are one surface that
// folds back.
Model pinch_out(double degrees, bool one_patch)
{
  Model m;
  const std::size_t r = m.add_region("Wedge");
  const std::size_t lower = m.add_patch("Lower", 0, r);
  const std::size_t upper = one_patch ? lower : m.add_patch("Upper", 0, r);
  const std::size_t wall = m.add_patch("Wall", 0, r);
  const double a = degrees * 3.14159265358979323846 / 180., c = std::cos(a), sn = std::sin(a);
  const std::size_t A0 = m.add_point(Point(0, 0, 0)), A1 = m.add_point(Point(0, 1, 0));
  const std::size_t B0 = m.add_point(Point(1, 0, 0)), B1 = m.add_point(Point(1, 1, 0));
  const std::size_t C0 = m.add_point(Point(c, 0, sn)), C1 = m.add_point(Point(c, 1, sn));
  // normals outward
  m.add_triangle(A0, A1, B1, lower);
  m.add_triangle(A0, B1, B0, lower);
  m.add_triangle(A0, C0, C1, upper);
  m.add_triangle(A0, C1, A1, upper);
  m.add_triangle(B0, B1, C1, wall);
  m.add_triangle(B0, C1, C0, wall);
  m.add_triangle(A0, B0, C0, wall);
  m.add_triangle(A1, C1, B1, wall);
  return m;
}

// The region's angle between its surfaces at an edge: 90 at a box's edges, the
// wedge's angle at a pinch-out, with a warning that names the place and the patches.
void test_contact_angles()
{
  const BM::Geological_model_summary cube = BM::summarize_geological_model(unit_cube());
  assert(std::abs(cube.regions.at(0).min_contact_angle - 90.) < 1e-9);
  assert(cube.regions.at(0).number_of_sharp_contact_edges == 0);
  // the fault meets the horizon at 90 degrees; its free edges (its tip) have the whole turn
  const BM::Geological_model_summary layers = BM::summarize_geological_model(two_layers_with_fault());
  for(const auto& r : layers.regions)
    assert(std::abs(r.min_contact_angle - 90.) < 1e-9 && r.number_of_sharp_contact_edges == 0);
  assert(cube.sharp_patch_corners.empty() && layers.sharp_patch_corners.empty());
  std::ostringstream quiet;
  BM::write_summary_text(quiet, layers);
  assert(!contains(quiet.str(), "surfaces meet") && !contains(quiet.str(), "border curves"));

  for(bool one_patch : {false, true})
  {
    const Model m = pinch_out(5., one_patch);
    assert(validation_message(m).empty());
    const BM::Geological_model_summary s = BM::summarize_geological_model(m);
    const auto& r = s.regions.at(0);
    assert(r.volume > 0.); // (the normals point out)
    std::ostringstream text;
    BM::write_summary_text(text, s);
    std::cout << text.str();
    assert(std::abs(r.min_contact_angle - 5.) < 1e-9);
    assert(r.number_of_sharp_contact_edges == 1 && std::abs(r.sharp_contact_length - 1.) < 1e-15);
    assert(r.min_contact_point[0] == 0. && r.min_contact_point[1] == 0.5 && r.min_contact_point[2] == 0.);
    const std::size_t lo = (std::min)(r.min_contact_patches.first, r.min_contact_patches.second);
    const std::size_t hi = (std::max)(r.min_contact_patches.first, r.min_contact_patches.second);
    assert(lo == 0 && hi == (one_patch ? 0u : 1u));
    assert(contains(text.str(), "warning: region 1 'Wedge': its surfaces meet at 5 deg at (0, 0.5, 0)"));
    assert(contains(text.str(), one_patch ? "where patch 'Lower' folds back" : "between patches"));
    // the wall meets the faces at the wedge's base angles, 87.5 degrees, the ends at 90
    const BM::Geological_model_summary wide =
      BM::summarize_geological_model(m, BM::parameters::sharp_angle_bound(88.));
    assert(wide.regions.at(0).number_of_sharp_contact_edges == 3);
    std::ostringstream json;
    BM::write_summary_json(json, s);
    assert(contains(json.str(), "\"number_of_sharp_contact_edges\": 1") && contains(json.str(), "\"sharp_angle_bound\": 10"));
    // the wedge's ends are triangles of the patch 'Wall' with the wedge's angle at the pinch-out line
    assert(s.sharp_patch_corners.size() == 1 && s.sharp_patch_corners[0].name == "Wall");
    assert(std::abs(s.sharp_patch_corners[0].angle - 5.) < 1e-9 && s.sharp_patch_corners[0].number_of_sharp_corners == 2);
    assert(s.sharp_patch_corners[0].point[0] == 0. && s.sharp_patch_corners[0].point[2] == 0.);
    const auto& both = s.sharp_patch_corners[0].corners; // A0 and A1, in point order
    assert(both.size() == 2 && both[0][1] == 0. && both[1][1] == 1. && std::abs(both[1][3] - 5.) < 1e-9);
    assert(contains(text.str(), "warning: 1 patch has 2 corners under 10 deg") &&
           contains(text.str(), "sharpest: patch 'Wall' 5 deg at (0, "));
    assert(contains(json.str(), std::string("\"sharp_patch_corners\": [\n    {\"patch\": ") + (one_patch ? "1" : "2") +
                                  ", \"name\": \"Wall\""));
  }
  std::cout << "contact angles: box 90, fault on a horizon 90, pinch-out 5 (warned); patch corners: the wedge's ends 5\n";
}

// A layered box with a fine grid: validation must stay fast.
void test_timing()
{
  const Model m = two_layers_with_fault(16);
  CGAL::Real_timer timer;
  timer.start();
  BM::validate_geological_model(m, CGAL::parameters::verbose(true)); // times of each check on std::cerr
  timer.stop();
  std::cout << "synthetic model, " << m.number_of_triangles() << " triangles: validated in " << timer.time() << " s\n";
  assert(timer.time() < 5.); // generous: shared CI machines; about 0.1 s expected
}

// The real GOCAD models, when ../shared is there: all valid, and read and validated fast.
void test_real_models()
{
  const std::filesystem::path dir(BUBBLE_MESH_3_SHARED_DATA_DIR);
  if(!std::filesystem::is_directory(dir))
  {
    std::cout << "SKIP: real models: " << dir.string() << " not found\n";
    return;
  }
  std::vector<std::string> files;
  for(const auto& entry : std::filesystem::directory_iterator(dir))
    if(entry.path().extension() == ".ml") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  if(files.empty()) std::cout << "SKIP: real models: no .ml file in " << dir.string() << "\n";
  for(const std::string& f : files)
  {
    Model m;
    CGAL::Real_timer timer;
    CGAL::Timer cpu; // the machine may be shared: CPU time too
    timer.start();
    cpu.start();
    BM::IO::read_gocad_model3d(f, m);
    const double read_time = timer.time(), read_cpu = cpu.time();
    timer.reset();
    cpu.reset();
    const std::vector<std::string> problems = BM::geological_model_problems(m);
    const double validate_time = timer.time(), validate_cpu = cpu.time();
    for(const std::string& p : problems) std::cerr << p << "\n";
    assert(problems.empty());
    assert(BM::orient_patch_sides(m).empty()); // the geometry agrees with the file's sides
    const BM::Geological_model_summary s = BM::summarize_geological_model(m);
    std::cout << std::filesystem::path(f).filename().string() << ": " << s.number_of_regions << " regions, "
              << s.number_of_triangles << " triangles, " << s.surfaces_inside_regions.size()
              << " surfaces inside regions, min angle " << s.min_angle << " deg; valid; read " << read_time
              << " s + validate " << validate_time << " s (CPU " << read_cpu << " + " << validate_cpu
              << " s; CGAL's assertions on)\n";
    double sum = 0.;
    for(const auto& r : s.regions)
    {
      assert(r.volume > 0.);
      sum += r.volume;
    }
    assert(std::abs(sum - s.volume) <= 1e-9 * s.volume); // the regions fill the model
    assert(read_cpu + validate_cpu < 10.); // about 0.2 s for the largest at -O2 -DNDEBUG
  }
}

// Patch sides contradicted by the triangles are mended from the geometry; sides that are
// right, and defects that swapping sides cannot mend, are left alone.
void test_orient_patch_sides()
{
  auto volumes_are = [](const Model& m, std::initializer_list<double> expected) {
    const std::vector<double> v = BM::region_volumes(m);
    std::size_t r = 1;
    for(double e : expected)
    {
      if(!(std::abs(v[r] - e) < 1e-12 * e)) std::cerr << "region " << r << ": volume " << v[r] << ", expected " << e << "\n";
      assert(std::abs(v[r++] - e) < 1e-12 * e);
    }
  };
  {
    Model m = two_layers_with_fault();
    assert(BM::orient_patch_sides(m).empty());
    // the horizon (patch 1) with its two layers the wrong way round: each layer's boundary
    // runs the horizon's edges the same way as its sides
    m.set_patch_regions(1, m.patch(1).negative_region, m.patch(1).positive_region);
    assert(!validation_message(m).empty());
    const BM::Patch_side_repair repair = BM::orient_patch_sides(m);
    assert(repair.swapped_patches == std::vector<std::size_t>{1} && repair.flipped_triangles.empty());
    BM::validate_geological_model(m);
    volumes_are(m, {9., 9.});
    assert(m.patch(5).is_inside_region()); // the fault stays inside the lower layer
    std::cout << "orient_patch_sides: horizon's sides swapped back\n";
  }
  {
    // every patch of the two layers wrong but the fault: swapped back together
    Model m = two_layers_with_fault();
    for(std::size_t p = 0; p < 5; ++p)
      m.set_patch_regions(p, m.patch(p).negative_region, m.patch(p).positive_region);
    assert(BM::orient_patch_sides(m).swapped_patches == (std::vector<std::size_t>{0, 1, 2, 3, 4}));
    BM::validate_geological_model(m);
    volumes_are(m, {9., 9.});
  }
  {
    // a cavity listed with the rock on the wrong side: the shell enclosed by the outer one
    // must face into the cavity
    Builder b;
    const std::size_t shell = b.model.add_region("Shell");
    b.box(b.model.add_patch("Outer", 0, shell), Point(0, 0, 0), Point(3, 3, 3), 1);
    b.box(b.model.add_patch("Cavity", 0, shell), Point(1, 1, 1), Point(2, 2, 2), 1, true);
    assert(BM::orient_patch_sides(b.model).empty());
    b.model.set_patch_regions(1, shell, 0);
    assert(!validation_message(b.model).empty());
    assert(BM::orient_patch_sides(b.model).swapped_patches == std::vector<std::size_t>{1});
    BM::validate_geological_model(b.model);
    volumes_are(b.model, {26.});
    // a body inside the cavity and a second piece of the shell around it all, both with their
    // sides wrong: the first piece, enclosed by both shells of the second, is no cavity
    const std::size_t core = b.model.add_region("Core");
    b.box(b.model.add_patch("Core skin", core, 0), Point(1.25, 1.25, 1.25), Point(1.75, 1.75, 1.75), 2);
    b.box(b.model.add_patch("Outer 2", shell, 0), Point(-2, -2, -2), Point(5, 5, 5), 1);
    b.box(b.model.add_patch("Cavity 2", shell, 0), Point(-1, -1, -1), Point(4, 4, 4), 1);
    assert(BM::orient_patch_sides(b.model).swapped_patches == (std::vector<std::size_t>{2, 3}));
    BM::validate_geological_model(b.model);
    volumes_are(b.model, {26. + 343. - 125., 0.125});
    std::cout << "orient_patch_sides: cavity and nested bodies mended\n";
  }
  {
    // a triangle facing against the rest of its patch is turned over, validation then passes
    Model m = read_bad("inconsistent_orientation.obj");
    assert(!validation_message(m).empty());
    const BM::Patch_side_repair r = BM::orient_patch_sides(m);
    assert(r.swapped_patches.empty() && r.flipped_triangles == std::vector<std::size_t>{2});
    BM::validate_geological_model(m);
    volumes_are(m, {1.});
    // the cavity sharing the outer shell's patch, facing out of the cavity: 12 triangles
    // against 12, a tie that keeps the patch's sides and turns the cavity over
    Model c = read_bad("wrong_cavity.obj");
    const BM::Patch_side_repair rc = BM::orient_patch_sides(c);
    assert(rc.swapped_patches.empty() && rc.flipped_triangles.size() == 12);
    BM::validate_geological_model(c);
    volumes_are(c, {26.});
    // open boundaries are not touched
    Model o = read_bad("open_boundary.obj");
    const std::string before = validation_message(o);
    assert(BM::orient_patch_sides(o).empty());
    assert(validation_message(o) == before);
    // the cube whose only region is listed on the side its normals point to
    Model w = read_bad("wrong_side.ml");
    assert(BM::orient_patch_sides(w).swapped_patches == std::vector<std::size_t>{0});
    BM::validate_geological_model(w);
    volumes_are(w, {1.});
  }
}

} // namespace

// Points a hair off a box wall (as where a horizon's cut line meets a wall in
// a Gmsh export) get the wall's coordinate back; a point farther off, or one
// whose move would flatten a triangle, stays.
void test_snap_points_to_axis_planes()
{
  Model m = two_layers_with_fault(2);
  assert(BM::snap_points_to_axis_planes(m).number_of_points == 0); // nothing off: nothing moves
  std::vector<std::size_t> off;
  std::size_t far_off = m.number_of_points();
  for(std::size_t v = 0; v < m.number_of_points(); ++v)
  {
    const Point& p = m.point(v);
    // the horizon's cut line on the wall y = 0, a hair off it, but for its ends (so that
    // the wall keeps triangles on its plane); one point of the top's cut line a millimetre off
    if(p.y() != 0. || p.x() == 0. || p.x() == 3.) continue;
    if(p.z() == 1.)
    {
      m.set_point(v, Point(p.x(), off.size() % 2 ? 3e-14 : -2e-14, p.z()));
      off.push_back(v);
    }
    else if(p.z() == 2. && far_off == m.number_of_points())
    {
      far_off = v;
      m.set_point(v, Point(p.x(), 1e-3, p.z()));
    }
  }
  assert(off.size() > 4 && far_off < m.number_of_points());
  const BM::Axis_plane_snap_report r = BM::snap_points_to_axis_planes(m);
  std::cout << "snap: " << r.number_of_points << " of " << off.size() << " points, by up to " << r.largest_move << std::endl;
  assert(r.number_of_points == off.size());
  assert(r.largest_move == 3e-14);
  for(std::size_t v : off) assert(m.point(v).y() == 0.);
  assert(m.point(far_off).y() == 1e-3);
  BM::validate_geological_model(m);

  // a wall triangle a hair off y = 0 whose point also ends a flat sliver of another patch:
  // on the wall that point would make the sliver a segment, so it stays
  Model f;
  const std::size_t r1 = f.add_region("r");
  const std::size_t wall = f.add_patch("wall", 0, r1), other = f.add_patch("other", r1, 0);
  const std::size_t a = f.add_point(Point(0, 0, 0)), b = f.add_point(Point(1, 0, 0)), c = f.add_point(Point(0, 0, 1));
  const std::size_t d = f.add_point(Point(2, 1e-14, 0)), e = f.add_point(Point(1, 0, 1));
  f.add_triangle(a, b, c, wall);  // exactly on y = 0: the wall's plane
  f.add_triangle(b, d, e, wall);  // d a hair off it
  f.add_triangle(a, b, d, other); // a, b, d: collinear once d is on the wall
  const BM::Axis_plane_snap_report flat = BM::snap_points_to_axis_planes(f);
  assert(flat.number_of_points == 0 && f.point(d).y() == 1e-14);
}

int main()
{
  test_good_models();
  test_bad_in_memory();
  test_triangle_pairs();
  test_bad_files();
  test_orient_patch_sides();
  test_snap_points_to_axis_planes();
  test_summary();
  test_contact_angles();
  test_timing();
  test_real_models();
  std::cout << "test_validation: OK\n";
  return EXIT_SUCCESS;
}
