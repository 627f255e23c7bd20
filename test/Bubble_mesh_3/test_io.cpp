// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the geological model readers and writers: real models, round
// trips, and located error messages on bad input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/merge_coincident_points.h>
#include <CGAL/Bubble_mesh_3/IO/read_multibody_obj.h>
#include <CGAL/Bubble_mesh_3/IO/write_multibody_obj.h>
#include <CGAL/Bubble_mesh_3/IO/read_gocad_model3d.h>
#include <CGAL/Bubble_mesh_3/IO/read_gocad_tsurf.h>
#include <CGAL/Bubble_mesh_3/orient_patch_sides.h>
#include <CGAL/Bubble_mesh_3/validate_geological_model.h>
#include <CGAL/Bubble_mesh_3/IO/read_geological_model.h>
#include <CGAL/Bubble_mesh_3/IO/read_face_graphs.h>
#include <CGAL/Bubble_mesh_3/IO/write_face_graphs.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#ifdef BUBBLE_MESH_3_HAS_OPENMESH
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
// double coordinates: real models sit at 1e6 m, where floats lose the volumes
struct OpenMesh_double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<OpenMesh_double_traits> OpenMesh_mesh;
// CGAL 5.5.1's OpenMesh point map writes floats: this one keeps the doubles
struct OpenMesh_double_point_map
{
  typedef boost::graph_traits<OpenMesh_mesh>::vertex_descriptor key_type;
  typedef CGAL::Epick::Point_3 value_type;
  typedef CGAL::Epick::Point_3 reference;
  typedef boost::writable_property_map_tag category;
  OpenMesh_mesh* mesh;
  friend void put(const OpenMesh_double_point_map& m, key_type v, const value_type& p)
  {
    m.mesh->set_point(v, OpenMesh::Vec3d(p.x(), p.y(), p.z()));
  }
};
#endif

#include <cassert>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Bubble_mesh_3::Geological_model_3<K> Model;
using CGAL::Bubble_mesh_3::Geological_model_error;
namespace BIO = CGAL::Bubble_mesh_3::IO;
namespace BP = CGAL::Bubble_mesh_3::parameters;

static const std::string test_data = std::string(BUBBLE_MESH_3_TEST_DATA_DIR) + "/io/";
static const std::string binary_dir = BUBBLE_MESH_3_BINARY_DIR;

// runs `f`, which must throw Geological_model_error whose message contains every piece of `needles`
static void expect_error(const std::string& what, const std::function<void()>& f,
                         const std::vector<std::string>& needles)
{
  try
  {
    f();
  }
  catch(const Geological_model_error& e)
  {
    const std::string msg = e.what();
    std::cout << "  " << what << ": " << msg << "\n";
    for(const std::string& n : needles)
      if(msg.find(n) == std::string::npos)
      {
        std::cerr << "FAIL: message for '" << what << "' lacks '" << n << "'\n";
        assert(false);
      }
    return;
  }
  std::cerr << "FAIL: no Geological_model_error for '" << what << "'\n";
  assert(false);
}

static double relative_error(double a, double b) { return std::abs(a - b) / (std::max)(std::abs(a), std::abs(b)); }

// volumes positive and adding up to the outer volume; returns the worst relative error
static double check_volumes(const Model& m, const std::string& name)
{
  const std::vector<double> vol = CGAL::Bubble_mesh_3::region_volumes(m);
  double sum = 0;
  for(std::size_t r = 1; r < vol.size(); ++r)
  {
    if(!(vol[r] > 0)) std::cerr << name << ": " << m.region_label(r) << " has volume " << vol[r] << "\n";
    assert(vol[r] > 0);
    sum += vol[r];
  }
  const double err = relative_error(sum, vol[0]);
  std::cout << "  " << name << ": " << m.number_of_regions() << " regions, " << m.number_of_patches() << " patches, "
            << m.number_of_triangles() << " triangles, " << m.number_of_points() << " points; outer volume "
            << vol[0] << ", sum of regions " << sum << ", relative difference " << err << "\n";
  assert(vol[0] > 0);
  assert(err < 1e-9);
  return err;
}

// ---------------------------------------------------------------------------
// two stacked unit boxes A (z in [0,1]) and B (z in [1,2]), each with its own
// copy of the points; B listed inward (the reader flips it); a fault inside B

static const char* two_boxes_obj = R"(# two boxes
o A
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f 4 1 5
f 4 5 8
o B
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
v 0 0 2
v 1 0 2
v 1 1 2
v 0 1 2
# B inward: every face reversed, the quads given as polygons
f -8 -7 -6 -5
f -1 -2 -3 -4
f 9 14 10
f 9 13 14
f 10 15 11
f 10 14 15
f 11 16 12
f 11 15 16
f 12 13 9
f 12 16 13
o Fault in B
#@inside B
v 0.2 0.2 1.5
v 0.8 0.2 1.5
v 0.5/0 0.8 1.5
)";

static void test_obj_two_boxes()
{
  std::cout << "multi-body OBJ: two boxes and a fault\n";
  // the third fault vertex above is deliberately broken: fix it for the good case
  std::string text = two_boxes_obj;
  const std::string bad_fault = "v 0.5/0 0.8 1.5\n";
  const std::string good_fault = "v 0.5 0.8 1.5\nf -3 -2 -1\n";
  {
    Model m;
    expect_error("slash in a coordinate", [&] {
      std::istringstream is(text);
      BIO::read_multibody_obj(is, "boxes.obj", m);
    }, {"boxes.obj:47:", "coordinate of vertex 19", "'0.5/0'"});
    assert(m.number_of_triangles() == 0);  // untouched on error
  }
  text.replace(text.find(bad_fault), bad_fault.size(), good_fault);
  Model m;
  std::istringstream is(text);
  BIO::read_multibody_obj(is, "boxes.obj", m);
  assert(m.number_of_regions() == 2);
  assert(m.region(1).name == "A" && m.region(2).name == "B");
  // A: 12, B: 10 own + 2 shared (listed twice, kept once) + 1 fault = 23
  assert(m.number_of_triangles() == 23);
  assert(m.number_of_points() == 15);  // 12 box corners + 3 fault points
  assert(m.number_of_patches() == 4);  // A/outside, A/B, B/outside, fault
  std::size_t inside = 0;
  for(const auto& p : m.patches())
    if(p.is_inside_region()) { ++inside; assert(p.positive_region == 2 && p.name == "Fault in B"); }
  assert(inside == 1);
  const std::vector<double> vol = CGAL::Bubble_mesh_3::region_volumes(m);
  std::cout << "  volumes A " << vol[1] << ", B " << vol[2] << ", outer " << vol[0] << "\n";
  assert(std::abs(vol[1] - 1) < 1e-12 && std::abs(vol[2] - 1) < 1e-12 && std::abs(vol[0] - 2) < 1e-12);

  // round trip through the writer: same everything, exactly
  std::stringstream ss;
  BIO::write_multibody_obj(ss, m);
  Model m2;
  BIO::read_multibody_obj(ss, "roundtrip.obj", m2);
  assert(m2.number_of_regions() == 2 && m2.number_of_triangles() == 23 && m2.number_of_patches() == 4);
  const std::vector<double> vol2 = CGAL::Bubble_mesh_3::region_volumes(m2);
  for(std::size_t r = 0; r < vol.size(); ++r) assert(vol2[r] == vol[r]);
  for(std::size_t p = 0; p < m.number_of_patches(); ++p) assert(m2.patch(p).name == m.patch(p).name);
  std::cout << "  round trip: " << m2.number_of_regions() << " regions, " << m2.number_of_patches() << " patches, "
            << m2.number_of_triangles() << " triangles, volumes identical\n";

  // through a file (written to .tmp, then renamed)
  const std::string file = binary_dir + "/test_io_two_boxes.obj";
  BIO::write_multibody_obj(file, m);
  assert(!std::ifstream(file + ".tmp"));
  Model m3;
  BIO::read_multibody_obj(file, m3, BP::merge_tolerance(1e-9));
  assert(m3.number_of_triangles() == 23 && m3.file_name() == file);

  // errors located in the text
  auto read_text = [](const std::string& t, const std::string& name) {
    Model mm;
    std::istringstream s(t);
    BIO::read_multibody_obj(s, name, mm);
    return mm;
  };
  expect_error("face with a missing vertex", [&] { read_text("o X\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "m.obj"); },
               {"m.obj:5:", "vertex 7", "'X'", "3 vertices"});
  expect_error("relative index before the first vertex", [&] { read_text("v 0 0 0\nf -1 -2 -3\n", "m.obj"); },
               {"m.obj:2:", "vertex -2"});
  expect_error("NaN coordinate", [&] { read_text("o X\nv 0 0 0\nv 1 nan 0\n", "m.obj"); },
               {"m.obj:3:", "vertex 2", "'nan'"});
  expect_error("inf coordinate", [&] { read_text("o X\nv 0 0 -inf\n", "m.obj"); }, {"m.obj:2:", "vertex 1", "'-inf'"});
  expect_error("huge index", [&] { read_text("v 0 0 0\nf 1 2 99999999999999999999999\n", "m.obj"); },
               {"m.obj:2:", "out of range"});
  expect_error("unknown statement", [&] { read_text("v 0 0 0\nhello world\n", "m.obj"); }, {"m.obj:2:", "'hello'"});
  expect_error("empty", [&] { read_text("", "m.obj"); }, {"m.obj", "empty"});
  expect_error("no faces", [&] { read_text("v 1 2 3\n", "m.obj"); }, {"m.obj", "no faces"});
  expect_error("binary", [&] { read_text(std::string("v 1 2 3\n\x7f\x45LF\x02\x01\0\0", 16), "m.obj"); }, {"m.obj:2:"});
  expect_error("degenerate face", [&] { read_text("v 0 0 0\nv 1 0 0\nv 0 0 0\nf 1 2 3\n", "m.obj"); },
               {"m.obj:4:", "degenerate", "vertices 3 and 1", "(0 0 0)"});
  expect_error("inside an unknown body", [&] { read_text("o F\n#@inside Nobody\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "m.obj"); },
               {"m.obj:1:", "'F'", "'Nobody'"});
  expect_error("unknown directive", [&] { read_text("o F\n#@insde X\n", "m.obj"); }, {"m.obj:2:", "#@insde"});
  {
    // the fault given again in a second piece, saying again where it lies: one patch
    Model two = read_text(text + "g Fault in B\n#@inside B\nv 0.5 0.05 1.5\nf -3 -4 -1\n", "m.obj");
    assert(two.number_of_triangles() == 24 && two.number_of_patches() == 4);
    // ... or saying something else: an error naming where it was said to lie
    expect_error("a group given again inside another body",
                 [&] { read_text(text + "g Fault in B\n#@inside A\n", "m.obj"); },
                 {"must come before the faces of group 'Fault in B'", "which lies inside 'B'"});
  }
  {
    // the shared face listed with the same orientation in both bodies
    std::string t = text;
    const std::string bface = "f -8 -7 -6 -5\n";
    t.replace(t.find(bface), bface.size(), "f -8 -5 -6 -7\n");
    expect_error("interface with the same orientation twice", [&] { read_text(t, "b.obj"); },
                 {"b.obj:", "same orientation", "'A'", "'B'"});
  }
}

template <class FaceGraph>
static void boundary_to_face_graph(const Model& m, std::size_t r, FaceGraph& g)
{
  CGAL::Bubble_mesh_3::region_boundary_to_face_graph(m, r, g);
}
#ifdef BUBBLE_MESH_3_HAS_OPENMESH
static void boundary_to_face_graph(const Model& m, std::size_t r, OpenMesh_mesh& g)
{
  CGAL::Bubble_mesh_3::region_boundary_to_face_graph(m, r, g, CGAL::parameters::vertex_point_map(OpenMesh_double_point_map{&g}));
}
#endif

// ---------------------------------------------------------------------------
// region boundaries -> face graphs -> model: same regions and volumes; the
// face graphs' own volumes (PMP) agree with region_volumes()

template <class FaceGraph>
static void face_graph_round_trip(const Model& m, const std::string& what)
{
  std::vector<FaceGraph> bodies(m.number_of_regions());
  std::vector<std::string> names;
  const std::vector<double> vol = CGAL::Bubble_mesh_3::region_volumes(m);
  double worst_pmp = 0;
  for(std::size_t r = 1; r <= m.number_of_regions(); ++r)
  {
    boundary_to_face_graph(m, r, bodies[r - 1]);
    names.push_back(m.region(r).name);
    assert(CGAL::is_closed(bodies[r - 1]));
    worst_pmp = (std::max)(worst_pmp, relative_error(CGAL::to_double(CGAL::Polygon_mesh_processing::volume(bodies[r - 1])), vol[r]));
  }
  Model back;
  CGAL::Bubble_mesh_3::geological_model_from_face_graphs(bodies, back, names);
  std::size_t boundary_triangles = 0;
  for(std::size_t t = 0; t < m.number_of_triangles(); ++t) boundary_triangles += !m.patch(m.patch_of_triangle(t)).is_inside_region();
  assert(back.number_of_regions() == m.number_of_regions());
  assert(back.number_of_triangles() == boundary_triangles);
  const std::vector<double> vol2 = CGAL::Bubble_mesh_3::region_volumes(back);
  double worst = 0;
  for(std::size_t r = 0; r < vol.size(); ++r)
  {
    assert(back.region(r).name == m.region(r).name);
    worst = (std::max)(worst, relative_error(vol[r], vol2[r]));
  }
  std::cout << "    " << what << " round trip: " << back.number_of_regions() << " closed bodies, "
            << back.number_of_triangles() << " boundary triangles, worst relative volume difference " << worst
            << " (PMP::volume of the bodies vs region_volumes: " << worst_pmp << ")\n";
  std::cout << std::flush;
  assert(worst < 1e-12 && worst_pmp < 1e-9);
}

static void test_merge_coincident_points()
{
  std::cout << "merge_coincident_points\n";
  // a strip of triangles whose second row is stored twice, once shifted by 1e-9
  Model m;
  const std::size_t r = m.add_region("r");
  const std::size_t p = m.add_patch("p", 0, r);
  const int n = 2000;
  for(int i = 0; i < n; ++i) m.add_point(K::Point_3(i, 0, 0));
  for(int i = 0; i < n; ++i) m.add_point(K::Point_3(i, 1, 0));
  for(int i = 0; i < n; ++i) m.add_point(K::Point_3(i + 1e-9, 1, 0));
  for(int i = 0; i + 1 < n; ++i)
  {
    m.add_triangle(i, i + 1, n + i, p);           // on row 1
    m.add_triangle(i + 1, 2 * n + i + 1, 2 * n + i, p);  // on the shifted copy
  }
  m.add_triangle(0, n - 1, 2 * n - 1, p);  // uses the last point of row 1
  m.add_point(K::Point_3(5, 5, 5));  // unused
  Model exact = m;
  const std::size_t removed_exact = CGAL::Bubble_mesh_3::merge_coincident_points(exact);
  assert(removed_exact == 1 && exact.number_of_points() == std::size_t(3 * n));
  CGAL::Real_timer timer;
  timer.start();
  const std::size_t removed = CGAL::Bubble_mesh_3::merge_coincident_points(m, 1e-10);
  timer.stop();
  std::cout << "  " << 3 * n + 1 << " points: exact merge removes " << removed_exact << ", tolerance 1e-10 of the diagonal removes "
            << removed << " in " << timer.time() << " s\n";
  assert(removed == std::size_t(n) + 1 && m.number_of_points() == std::size_t(2 * n));
  // the kept points are the first ones, with their own coordinates
  for(std::size_t t = 0; t < m.number_of_triangles(); ++t)
    for(std::size_t v : m.triangle(t)) assert(m.point(v).y() == 0 || m.point(v).x() == std::floor(m.point(v).x()));
  // a tolerance as large as the model merges everything, at once
  Model all = exact;
  CGAL::Bubble_mesh_3::merge_coincident_points(all, 2.);
  assert(all.number_of_points() == 1);
  expect_error("negative tolerance", [&] { CGAL::Bubble_mesh_3::merge_coincident_points(all, -1.); }, {"tolerance", "-1"});
}

static void test_small_files()
{
  std::cout << "hand-written files in " << test_data << "\n";
  for(const char* f : {"two_boxes.ml", "two_boxes_depth.ml", "two_boxes.ts"})
  {
    Model m;
    BIO::read_geological_model(test_data + f, m);
    check_volumes(m, f);
    assert(m.number_of_regions() == 2);
    assert(m.region(1).name == "lower" && m.region(2).name == "upper");
    assert(m.number_of_triangles() == 22 && m.number_of_points() == 12);
    const std::vector<double> vol = CGAL::Bubble_mesh_3::region_volumes(m);
    assert(std::abs(vol[1] - 1) < 1e-12 && std::abs(vol[2] - 1) < 1e-12);
    face_graph_round_trip<CGAL::Surface_mesh<K::Point_3> >(m, "Surface_mesh");
  }
  {
    // parts are named after their surface, with a suffix where a surface has several
    Model m;
    BIO::read_gocad_model3d(test_data + "two_boxes.ml", m);
    assert(m.number_of_patches() == 3);
    assert(m.patch(0).name == "boundary_1" && m.patch(1).name == "boundary_2" && m.patch(2).name == "horizon");
    // horizon: lower below, upper above, whatever the file's ZPOSITIVE
    Model d;
    BIO::read_gocad_model3d(test_data + "two_boxes_depth.ml", d);
    for(const Model* x : {&m, &d})
    {
      const auto& tri = x->triangle(x->number_of_triangles() - 1);
      const K::Vector_3 n = CGAL::cross_product(x->point(tri[1]) - x->point(tri[0]), x->point(tri[2]) - x->point(tri[0]));
      const auto& h = x->patch(2);
      assert((n.z() > 0) == (h.positive_region == 2) && (n.z() > 0) == (h.negative_region == 1));
    }
    std::cout << "  Model3d Elevation and Depth: horizon between 'lower' and 'upper' on the right sides\n";
  }
  {
    // other writers' spellings: `GOCAD Tsurf` (Seismic Unix), `HEADER{`, Windows line ends
    std::ifstream f(test_data + "two_boxes.ts");
    std::stringstream ss;
    ss << f.rdbuf();
    std::string text = ss.str(), variant;
    for(std::size_t i = 0; i < text.size(); ++i)
    {
      if(text.compare(i, 11, "GOCAD TSurf") == 0) { variant += "GOCAD Tsurf"; i += 10; continue; }
      if(text.compare(i, 8, "HEADER {") == 0) { variant += "HEADER{"; i += 7; continue; }
      if(text[i] == '\n') variant += '\r';
      variant += text[i];
    }
    variant = "\xEF\xBB\xBF" + variant; // and a UTF-8 byte order mark
    assert(variant.find("Tsurf") != std::string::npos && variant.find("HEADER{") != std::string::npos);
    std::istringstream is(variant);
    Model m, ref;
    BIO::read_gocad_tsurf(is, "variant.ts", m);
    BIO::read_gocad_tsurf(test_data + "two_boxes.ts", ref);
    assert(m.number_of_triangles() == ref.number_of_triangles() && m.number_of_points() == ref.number_of_points());
    assert(CGAL::Bubble_mesh_3::region_volumes(m) == CGAL::Bubble_mesh_3::region_volumes(ref));
    std::cout << "  TSurf spelt 'Tsurf', 'HEADER{', CRLF, byte order mark: read the same\n";
  }
  {
    // a single body as OFF (a quad per face, inward: turned outward), ASCII STL (points
    // repeated per facet: merged) and ASCII PLY
    const std::string off = binary_dir + "/test_io_Slab.off", stl = binary_dir + "/test_io_Slab.STL",
                      ply = binary_dir + "/test_io_Slab.ply";
    const double P[8][3] = {{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {0, 2, 0}, {0, 0, 1}, {4, 0, 1}, {4, 2, 1}, {0, 2, 1}};
    const int Q[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}}; // inward
    {
      std::ofstream o(off);
      o << "OFF\n8 6 0\n";
      for(const auto& p : P) o << p[0] << " " << p[1] << " " << p[2] << "\n";
      for(const auto& q : Q) o << "4 " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n";
    }
    {
      std::ofstream o(stl);
      o << "solid slab\n";
      for(const auto& q : Q)
        for(int k = 1; k < 3; ++k)
        {
          o << " facet normal 0 0 0\n  outer loop\n";
          for(int c : {q[0], q[k + 1], q[k]}) o << "   vertex " << P[c][0] << " " << P[c][1] << " " << P[c][2] << "\n";
          o << "  endloop\n endfacet\n";
        }
      o << "endsolid slab\n";
    }
    {
      std::ofstream o(ply);
      o << "ply\nformat ascii 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\n"
           "element face 6\nproperty list uchar int vertex_indices\nend_header\n";
      for(const auto& p : P) o << p[0] << " " << p[1] << " " << p[2] << "\n";
      for(const auto& q : Q) o << "4 " << q[3] << " " << q[2] << " " << q[1] << " " << q[0] << "\n";
    }
    for(const std::string& f : {off, stl, ply})
    {
      Model m;
      BIO::read_geological_model(f, m);
      assert(m.number_of_regions() == 1 && m.region(1).name == "test_io_Slab");
      assert(m.number_of_points() == 8 && m.number_of_triangles() == 12);
      const std::vector<double> vol = CGAL::Bubble_mesh_3::region_volumes(m);
      assert(std::abs(vol[1] - 8.) < 1e-12);
      CGAL::Bubble_mesh_3::validate_geological_model(m);
    }
    std::cout << "  one body as OFF, STL and PLY: 8 points, 12 triangles, volume 8\n";
    {
      std::ofstream o(binary_dir + "/test_io_bad.off");
      o << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
    }
    Model m;
    expect_error("OFF face with a vertex out of range",
                 [&] { BIO::read_geological_model(binary_dir + "/test_io_bad.off", m); },
                 {"test_io_bad.off"});
  }
  {
    // region assignment: a box and a fault inside it
    Model m;
    BIO::read_gocad_tsurf(test_data + "box_and_fault.ts", m,
                          BP::region_assignment_file(test_data + "box_and_fault_regions.txt"));
    assert(m.number_of_regions() == 1 && m.region(1).name == "rock");
    assert(m.number_of_patches() == 2 && m.patch(1).name == "fault" && m.patch(1).is_inside_region());
    const std::vector<double> vol = CGAL::Bubble_mesh_3::region_volumes(m);
    assert(std::abs(vol[1] - 1) < 1e-12);
    CGAL::Bubble_mesh_3::Region_assignment a;
    a["box"] = std::make_pair(std::string("outside"), std::string("rock"));
    a["fault"] = std::make_pair(std::string("rock"), std::string("rock"));
    Model m2;
    BIO::read_gocad_tsurf(test_data + "box_and_fault.ts", m2, BP::region_assignment(a));
    assert(m2.number_of_triangles() == m.number_of_triangles() && m2.number_of_patches() == 2);
    std::cout << "  TSurf with a region assignment: 1 region of volume " << vol[1] << ", fault inside it\n";
    a.erase("fault");
    expect_error("object missing from the assignment", [&] { BIO::read_gocad_tsurf(test_data + "box_and_fault.ts", m2, BP::region_assignment(a)); },
                 {"box_and_fault.ts:", "'fault'", "not in the region assignment"});
    // without the assignment the fault would be a body of its own: an open one, which validation reports
  }
  {
    // the same bodies as OBJ: read_geological_model dispatches on the extension
    Model m;
    BIO::read_geological_model(test_data + "two_boxes.ts", m);
    const std::string obj = binary_dir + "/test_io_two_boxes_from_ts.OBJ";
    BIO::write_multibody_obj(obj, m);
    Model back;
    BIO::read_geological_model(obj, back, BP::merge_tolerance(0.));
    assert(back.number_of_triangles() == 22 && back.number_of_regions() == 2);
  }

  {
    // found by fuzzing: open, overlapping bodies must not be flipped by one read and
    // not by the next (an open surface has no inside), so the round trip reads back
    Model m;
    BIO::read_multibody_obj(test_data + "fuzz_open_bodies.obj", m);
    std::stringstream ss;
    BIO::write_multibody_obj(ss, m);
    Model back;
    BIO::read_multibody_obj(ss, "again.obj", back);
    assert(back.number_of_triangles() == m.number_of_triangles() && back.number_of_regions() == m.number_of_regions());
    for(std::size_t t = 0; t < m.number_of_triangles(); ++t) assert(back.triangle(t) == m.triangle(t));
    std::cout << "  open bodies (fuzz finding): " << m.number_of_triangles() << " triangles read back unchanged\n";
  }

  // bad input: every message names the file, the line and the element at fault
  Model m;
  auto read = [&](const std::string& f) { return [&m, f] { BIO::read_geological_model(test_data + f, m); }; };
  expect_error("empty file", read("empty.ml"), {"empty.ml", "empty file"});
  expect_error("truncated file", read("truncated.ml"), {"truncated.ml:67:", "vertex 10"});
  expect_error("garbage text", read("garbage.ml"), {"garbage.ml:1:", "not a GOCAD Model3d file"});
  expect_error("binary bytes", read("binary.ml"), {"binary.ml:"});
  {
    // key points written with about seven digits: found when a single triangle is that close
    std::ifstream f(test_data + "two_boxes.ml");
    std::stringstream ss;
    ss << f.rdbuf();
    const std::string text = ss.str();
    const std::size_t key = text.find("\n", text.find("TFACE 3")) + 1; // "  0.0 0.0 1.0"
    assert(text.compare(key, 14, "  0.0 0.0 1.0\n") == 0);
    for(const char* z : {"1.000001", "1.001"})
    {
      std::string t = text;
      t.replace(key, 14, std::string("  0.0 0.0 ") + z + "\n");
      std::istringstream is(t);
      Model k;
      if(std::string(z) == "1.000001")
      {
        BIO::read_gocad_model3d(is, "rounded_key.ml", k);
        assert(k.number_of_patches() == 3 && k.patch(2).name == "horizon");
      }
      else
        expect_error("key triangle 1e-3 off", [&] { BIO::read_gocad_model3d(is, "far_key.ml", k); },
                     {"far_key.ml:", "key triangle of TFACE 3", "is in none of the"});
    }
    std::cout << "  key triangle rounded to 7 digits: found; 1e-3 off: an error\n";
  }

  {
    // a part with the Universe on both sides (a fault running on beyond the box) is left out
    std::ifstream f(test_data + "two_boxes.ml");
    std::stringstream ss;
    ss << f.rdbuf();
    std::string text = ss.str();
    const std::size_t end = text.find("\nEND\n");
    const std::size_t universe = text.find("REGION", text.find("TFACE"));
    assert(end != std::string::npos && universe < end);
    text.insert(universe, "TFACE 90 fault outer\n 5 0 0\n 6 0 0\n 6 1 1\n");
    const std::size_t list_end = text.find(" 0", text.find("\n", text.find("Universe")));
    text.insert(list_end, " +90 -90");
    text += "GOCAD TSurf 1\nHEADER {\nname: outer\n}\nTFACE\nVRTX 1 5 0 0\nVRTX 2 6 0 0\nVRTX 3 6 1 1\n"
            "VRTX 4 5 1 1\nTRGL 1 2 3\nTRGL 1 3 4\nEND\n";
    text.insert(text.find("TSURF"), "TSURF outer\n");
    std::istringstream is(text);
    Model with, without;
    BIO::read_gocad_model3d(is, "outer_part.ml", with);
    BIO::read_gocad_model3d(test_data + "two_boxes.ml", without);
    assert(with.notes().size() == 1 && with.notes()[0].find("TFACE 90") != std::string::npos &&
           with.notes()[0].find("left out") != std::string::npos);
    assert(with.number_of_patches() == without.number_of_patches() &&
           with.number_of_triangles() == without.number_of_triangles() &&
           with.number_of_points() == without.number_of_points());
    std::cout << "  " << with.notes()[0] << "\n";
  }

  expect_error("only the Universe", [&m] {
    // two squares that close nothing, both sides the outside
    std::istringstream is("GOCAD Model3d 1\nTSURF a\nTFACE 1 none a\n 0 0 0\n 1 0 0\n 1 1 0\n"
                          "REGION 2 Universe\n +1 -1 0\nEND\nGOCAD TSurf 1\nHEADER {\nname: a\n}\nTFACE\n"
                          "VRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 1 1 0\nVRTX 4 0 1 0\nTRGL 1 2 3\nTRGL 1 3 4\nEND\n");
    BIO::read_gocad_model3d(is, "universe_only.ml", m);
  }, {"universe_only.ml", "no REGION but the Universe", "no body to mesh"});

  expect_error("TRGL with a missing vertex", read("missing_vertex.ts"), {"missing_vertex.ts:22:", "vertex 99", "'lower'"});
  expect_error("NaN coordinate", read("nan_vertex.ts"), {"nan_vertex.ts:16:", "vertex 3", "'nan'"});
  expect_error("inf coordinate", read("inf_vertex.ml"), {"inf_vertex.ml:67:", "vertex 10", "'inf'"});
  expect_error("REGION with an unknown TFACE", read("bad_region_tface.ml"),
               {"bad_region_tface.ml:28:", "REGION 'upper'", "TFACE 7"});
  expect_error("unknown extension", read("two_boxes.step"), {"two_boxes.step", "'.step'", ".ml", ".ts", ".obj", ".stl"});
  expect_error("missing file", read("no_such_file.ml"), {"no_such_file.ml", "cannot open"});
  expect_error("truncated in the header", [&] {
    std::ifstream f(test_data + "two_boxes.ml");
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    std::istringstream is(text.substr(0, text.find("REGION 6")));
    BIO::read_gocad_model3d(is, "cut.ml", m);
  }, {"cut.ml:", "no END", "header"});
  expect_error("key triangle in no part", [&] {
    std::ifstream f(test_data + "two_boxes.ml");
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const std::string key = "  0.0 0.0 2.0\n";
    text.replace(text.find(key), key.size(), "  0.0 0.5 2.0\n");
    std::istringstream is(text);
    BIO::read_gocad_model3d(is, "key.ml", m);
  }, {"key.ml:15:", "TFACE 2", "(0 0.5 2)", "'boundary'"});
  assert(m.number_of_triangles() == 0);  // nothing half-built

  // REGION lists: how a TFACE is placed
  auto read_edited = [&](const std::string& from, const std::string& to, Model& out) {
    std::ifstream f(test_data + "two_boxes.ml");
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    assert(text.find(from) != std::string::npos);
    text.replace(text.find(from), from.size(), to);
    std::istringstream is(text);
    BIO::read_gocad_model3d(is, "edited.ml", out);
  };
  {
    // the same sign in both regions: read with a note, the sides left to the geometry
    Model same;
    read_edited("  -2  +3\n", "  -2  -3\n", same);
    assert(same.notes().size() == 1);
    const std::string& note = same.notes()[0];
    for(const char* part : {"edited.ml:19:", "TFACE 3", "'horizon'", "REGION 'lower' as -3", "REGION 'upper' as -3",
                            "same sign"})
      assert(note.find(part) != std::string::npos);
    CGAL::Bubble_mesh_3::orient_patch_sides(same);
    CGAL::Bubble_mesh_3::validate_geological_model(same);
    const std::vector<double> vol = CGAL::Bubble_mesh_3::region_volumes(same);
    assert(std::abs(vol[1] - 1) < 1e-12 && std::abs(vol[2] - 1) < 1e-12);
    std::cout << "  " << note << "; volumes 1 and 1 after orient_patch_sides()\n";
  }
  expect_error("TFACE in no REGION", [&] { read_edited("  -1  -3  0\nREGION 6  upper \n  -2  +3\n", "  -1  0\nREGION 6  upper \n  -2\n", m); },
               {"edited.ml:19:", "TFACE 3", "in no REGION"});
  {
    // with both signs in one region (CloudSpin's faults), or in one region only
    // beside a Universe, a TFACE is a surface inside that region
    Model both, once;
    read_edited("  -1  -3  0\nREGION 6  upper \n  -2  +3\n", "  -1  -3  +3  0\nREGION 6  upper \n  -2\n", both);
    read_edited("  -2  +3\n", "  -2\n", once);
    for(const Model* x : {&both, &once})
      assert(x->patch(2).name == "horizon" && x->patch(2).is_inside_region() && x->patch(2).positive_region == 1);
    std::cout << "  TFACE listed +3 and -3 in 'lower', or only in 'lower': a surface inside 'lower'\n";
  }
}

static const char* real_models[] = {"modelA1.ml", "modelA2.ml", "modelA5.ml", "CloudSpin_fixed.ml"};
static const std::string shared_dir = std::string(BUBBLE_MESH_3_SHARED_DATA_DIR) + "/";

static bool have_shared_data()
{
  std::ifstream probe(shared_dir + real_models[0]);
  if(!probe) std::cout << "SKIP: real models not found in " << shared_dir << " (the folder is optional)\n";
  return bool(probe);
}

static void test_real_models()
{
  std::cout << "GOCAD Model3d: real models\n";
  if(!have_shared_data()) return;
  for(const char* f : real_models)
  {
    Model m;
    CGAL::Real_timer timer;
    timer.start();
    BIO::read_gocad_model3d(shared_dir + f, m);
    timer.stop();
    std::cout << "  read " << f << " in " << timer.time() << " s\n";
    check_volumes(m, f);
    std::size_t inside = 0;
    for(const auto& p : m.patches()) inside += p.is_inside_region();
    std::cout << "    " << inside << " patches inside a region\n";

    // .ml -> multi-body OBJ -> model: same regions, triangles, patches, volumes
    std::stringstream obj;
    BIO::write_multibody_obj(obj, m);
    Model back;
    timer.reset();
    timer.start();
    BIO::read_multibody_obj(obj, std::string(f) + ".obj", back);
    timer.stop();
    assert(back.number_of_regions() == m.number_of_regions());
    assert(back.number_of_triangles() == m.number_of_triangles());
    assert(back.number_of_patches() == m.number_of_patches());
    assert(back.number_of_points() == m.number_of_points());
    const std::vector<double> v1 = CGAL::Bubble_mesh_3::region_volumes(m), v2 = CGAL::Bubble_mesh_3::region_volumes(back);
    double worst = 0;
    for(std::size_t r = 0; r < v1.size(); ++r)
    {
      assert(back.region(r).name == m.region(r).name);
      worst = (std::max)(worst, relative_error(v1[r], v2[r]));
    }
    std::cout << "    multi-body OBJ round trip (" << obj.str().size() << " bytes, read in " << timer.time()
              << " s): same counts, worst relative volume difference " << worst << "\n";
    assert(worst < 1e-12);

    face_graph_round_trip<CGAL::Surface_mesh<K::Point_3> >(m, "Surface_mesh");
#ifdef BUBBLE_MESH_3_HAS_OPENMESH
    face_graph_round_trip<OpenMesh_mesh>(m, "OpenMesh TriMesh");
#endif
  }
}

int main()
{
  test_obj_two_boxes();
  test_merge_coincident_points();
  test_small_files();
  test_real_models();
  std::cout << "test_io: all checks passed\n";
  return EXIT_SUCCESS;
}
