// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_MAKE_LAYERED_MODEL_H
#define CGAL_BUBBLE_MESH_3_MAKE_LAYERED_MODEL_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/Geological_model_error.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Random.h>
#include <CGAL/Unique_hash_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

/*!
\ingroup PkgBubbleMesh3Ref

Parameters of `make_layered_model()`. Lengths are in model units (metres);
the defaults give the package's bundled model
(`examples/Bubble_mesh_3/data/layered_model.obj`).

Ratios are relative to the model's size, so that `size_*` alone scales the
whole model.
*/
struct Layered_model_parameters
{
  /// extent of the box `[0,size_x] x [0,size_y] x [0,size_z]`, z up
  ///@{
  double size_x = 1000., size_y = 600., size_z = 400.;
  ///@}
  /// number of ordinary layers (at least 2); the thin layer comes in addition,
  /// above the `number_of_layers / 2` lowest ones
  std::size_t number_of_layers = 4;
  /// thickness of the thin layer over `size_z`
  double thin_layer_ratio = 0.05;
  /// largest height of the horizons' undulation over `size_z`
  double undulation_ratio = 0.05;
  /// dip of the through-going fault, in degrees (60 to 90; lower dips make
  /// angles between the fault and the horizons on the box faces that the
  /// surface meshing cannot resolve); it dips towards +x
  double fault_dip = 65.;
  /// x where the fault crosses mid-height, over `size_x`
  double fault_position_ratio = 0.55;
  /// vertical offset of the hanging wall (the +x side, moved down) over the
  /// thickness of an ordinary layer
  double fault_throw_ratio = 0.5;
  /// target edge length of the surface triangles: a bound on the longest edge
  /// (the mean edge comes out at about 0.6 of it); 0 means `0.2 * size_z`
  double edge_length = 0.;
  /// lower bound on the triangle angles, in degrees, for the 2D Delaunay
  /// refinement of each surface (at most 33); horizons, meshed in their (x,y)
  /// projection, can end a little below it in 3D
  double min_angle = 30.;
  /// seed of the phases of the undulations
  unsigned int seed = 0;
  /// adds the small fault that ends inside the thickest layer
  bool small_fault = true;
};

namespace internal {

typedef std::array<double, 3> LM_vec3;
typedef std::array<double, 2> LM_vec2;

// index of a surface vertex in the model; new vertices of the 2D mesher have none
struct LM_index
{
  std::size_t value = std::size_t(-1);
};

// a curve where surfaces meet: sampled once, and every surface through it
// uses these very points (conforming by construction)
struct LM_curve
{
  std::function<LM_vec3(double)> eval; // point at parameter t
  std::vector<double> t;               // parameters of the samples, increasing
  std::vector<std::size_t> v;          // point indices of the samples
};

// (positive region, negative region); (-1,-1) where the surface is absent
typedef std::pair<int, int> LM_label;

// a planar or height-field piece meshed in its own 2D coordinates
struct LM_surface
{
  std::string name;
  std::vector<std::size_t> curves;
  std::function<LM_vec2(const LM_vec3&)> to_2d;
  std::function<LM_vec3(const LM_vec2&)> to_3d;
  std::function<LM_label(const LM_vec3&)> label;
  LM_vec3 positive_direction; // the positive region lies on this side
  std::function<std::string(const LM_label&)> patch_name;
};

class Layered_model_builder
{
public:
  typedef CGAL::Exact_predicates_inexact_constructions_kernel       EK;
  typedef CGAL::Triangulation_vertex_base_with_info_2<LM_index, EK> Vb0;
  typedef CGAL::Delaunay_mesh_vertex_base_2<EK, Vb0>                Vb;
  typedef CGAL::Delaunay_mesh_face_base_2<EK>                       Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb>              Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<EK, Tds, CGAL::Exact_predicates_tag> CDT;
  typedef CGAL::Delaunay_mesh_size_criteria_2<CDT>                  Criteria;
  typedef CDT::Vertex_handle Vertex_handle;
  typedef CDT::Face_handle   Face_handle;
  typedef EK::Point_2        Point_2;

  // one output triangle before the patches are numbered
  struct Out_triangle
  {
    std::size_t surface;
    LM_label label;
    std::array<std::size_t, 3> v;
  };

  std::vector<LM_vec3> points;
  std::vector<std::string> region_names; // index 0 = outside
  std::vector<LM_surface> surfaces;
  std::vector<Out_triangle> triangles;
  std::size_t rounds = 0;

  explicit Layered_model_builder(const Layered_model_parameters& p) : p_(p)
  {
    check_parameters();
    set_up_geometry();
    check_gaps();
    build_curves_and_surfaces();
    mesh_all();
  }

private:
  Layered_model_parameters p_;
  double X_ = 0, Y_ = 0, Z_ = 0, h_ = 0;
  std::size_t N_ = 0;         // ordinary layers
  std::size_t bodies_ = 0;    // N_ + 1 (with the thin layer), per side
  std::size_t thin_body_ = 0; // index of the thin layer among the bodies, from the bottom
  double thin_ = 0, ordinary_ = 0, amplitude_ = 0, throw_ = 0;
  double cos_dip_ = 0, sin_dip_ = 0, fault_xc_ = 0, fault_zc_ = 0;
  std::vector<double> base_;          // base height of horizon i (1..N_), [0] unused
  std::vector<std::size_t> variation_; // which variation term horizon i uses
  std::array<double, 5> phase_{};     // phases of the common undulation
  std::vector<std::array<double, 2>> variation_phase_;
  std::vector<LM_curve> curves_;
  std::vector<std::unique_ptr<CDT>> cdts_;

  // ---- geometry ---------------------------------------------------------------

  void check_parameters()
  {
    const Layered_model_parameters& p = p_;
    auto fail = [](const std::string& m) { throw std::invalid_argument("make_layered_model: " + m); };
    if(!(p.size_x > 0 && p.size_y > 0 && p.size_z > 0) || !std::isfinite(p.size_x + p.size_y + p.size_z))
      fail("the box sizes must be positive");
    if(p.number_of_layers < 2) fail("number_of_layers must be at least 2");
    if(!(p.thin_layer_ratio > 0 && p.thin_layer_ratio < 0.5)) fail("thin_layer_ratio must be in (0, 0.5)");
    if(!(p.undulation_ratio >= 0 && p.undulation_ratio < 0.5)) fail("undulation_ratio must be in [0, 0.5)");
    if(!(p.fault_dip >= 60 && p.fault_dip <= 90)) fail("fault_dip must be in [60, 90] degrees");
    if(!(p.fault_position_ratio > 0.1 && p.fault_position_ratio < 0.9))
      fail("fault_position_ratio must be in (0.1, 0.9)");
    if(!(p.fault_throw_ratio > 0)) fail("fault_throw_ratio must be positive");
    if(!(p.edge_length >= 0) || !std::isfinite(p.edge_length)) fail("edge_length must be positive (or 0 for automatic)");
    if(!(p.min_angle > 0 && p.min_angle <= 33)) fail("min_angle must be in (0, 33] degrees");
  }

  void set_up_geometry()
  {
    X_ = p_.size_x; Y_ = p_.size_y; Z_ = p_.size_z;
    h_ = p_.edge_length > 0 ? p_.edge_length : 0.2 * Z_;
    if(h_ > 0.5 * std::min({X_, Y_, Z_}))
      throw std::invalid_argument("make_layered_model: edge_length is larger than half the smallest box side");
    N_ = p_.number_of_layers;
    bodies_ = N_ + 1;
    thin_body_ = N_ / 2;
    thin_ = p_.thin_layer_ratio * Z_;
    ordinary_ = (Z_ - thin_) / double(N_);
    amplitude_ = p_.undulation_ratio * Z_;
    throw_ = p_.fault_throw_ratio * ordinary_;
    const double dip = p_.fault_dip * CGAL_PI / 180.;
    cos_dip_ = std::cos(dip);
    sin_dip_ = std::sin(dip);
    fault_xc_ = p_.fault_position_ratio * X_;
    fault_zc_ = 0.5 * Z_;

    base_.assign(N_ + 1, 0.);
    double z = 0;
    for(std::size_t b = 0; b < N_; ++b)
    {
      z += (b == thin_body_) ? thin_ : ordinary_;
      base_[b + 1] = z;
    }
    // the two horizons of the thin layer share their variation: the thin layer
    // keeps a constant vertical thickness and never pinches out
    variation_.assign(N_ + 1, 0);
    for(std::size_t i = 1; i <= N_; ++i) variation_[i] = (i == thin_body_ + 1) ? i - 1 : i;

    CGAL::Random rnd(p_.seed);
    const double two_pi = 2 * CGAL_PI;
    for(double& ph : phase_) ph = rnd.get_double(0, two_pi);
    variation_phase_.resize(N_ + 1);
    for(std::size_t i = 1; i <= N_; ++i)
      variation_phase_[i] = {{rnd.get_double(0, two_pi), rnd.get_double(0, two_pi)}};

    region_names.assign(1, "outside");
    for(int side = 0; side < 2; ++side)
      for(std::size_t b = 0; b < bodies_; ++b)
        region_names.push_back(body_name(b) + (side == 0 ? "_footwall" : "_hangingwall"));
  }

  std::string body_name(std::size_t b) const
  {
    if(b == thin_body_) return "Thin_layer";
    return "Layer_" + std::to_string(b < thin_body_ ? b + 1 : b);
  }

  // common undulation in [-1,1]: two smooth waves, one oblique
  double undulation(double x, double y) const
  {
    const double two_pi = 2 * CGAL_PI;
    const double a = phase_[4] * 0.5; // oblique direction in [0, pi)
    return 0.55 * std::sin(two_pi * x / (0.9 * X_) + phase_[0]) * std::cos(two_pi * y / (1.3 * Y_) + phase_[1]) +
           0.45 * std::sin(two_pi * (x * std::cos(a) + y * std::sin(a)) / (0.5 * X_) + phase_[2]);
  }

  // z of horizon i (1..N_) on side 0 (footwall) or 1 (hanging wall, moved down by the throw)
  double horizon_z(std::size_t i, int side, double x, double y) const
  {
    const double two_pi = 2 * CGAL_PI;
    const std::array<double, 2>& ph = variation_phase_[variation_[i]];
    const double var = std::sin(two_pi * x / (0.6 * X_) + ph[0]) * std::sin(two_pi * y / (0.7 * Y_) + ph[1]);
    return base_[i] + amplitude_ * (undulation(x, y) + 0.15 * var) - (side == 1 ? throw_ : 0.);
  }

  double fault_x(double z) const { return fault_xc_ + (fault_zc_ - z) * cos_dip_ / sin_dip_; }
  int side_of(double x, double z) const { return x > fault_x(z) ? 1 : 0; }

  std::size_t body_of(int side, double x, double y, double z) const
  {
    std::size_t b = 0;
    for(std::size_t i = 1; i <= N_; ++i)
      if(z > horizon_z(i, side, x, y)) b = i;
    return b;
  }

  int region(int side, std::size_t body) const { return int(1 + side * bodies_ + body); }
  int region_at(const LM_vec3& q) const
  {
    const int s = side_of(q[0], q[2]);
    return region(s, body_of(s, q[0], q[1], q[2]));
  }

  // the point where horizon i of `side` meets the fault at y: z - H(x_f(z), y) is
  // increasing in z for the allowed dips and slopes, so bisection finds the root
  LM_vec3 fault_trace(std::size_t i, int side, double y) const
  {
    auto g = [&](double z) { return z - horizon_z(i, side, fault_x(z), y); };
    double lo = 0, hi = Z_;
    if(!(g(lo) < 0 && g(hi) > 0))
      throw std::invalid_argument("make_layered_model: horizon " + std::to_string(i) +
                                  " leaves the box at the fault; reduce the throw or the undulation");
    for(int it = 0; it < 200 && hi - lo > 1e-13 * Z_; ++it)
    {
      const double m = 0.5 * (lo + hi);
      (g(m) < 0 ? lo : hi) = m;
    }
    const double z = 0.5 * (lo + hi);
    return {{fault_x(z), y, z}};
  }

  // horizons must stay apart (and inside the box) on each side and across the
  // fault, else the layers would touch or line up
  void check_gaps() const
  {
    const double min_gap = 0.5 * thin_;
    const int n = 60;
    for(int side = 0; side < 2; ++side)
      for(int a = 0; a <= n; ++a)
        for(int b = 0; b <= n; ++b)
        {
          const double x = X_ * a / n, y = Y_ * b / n;
          double below = 0;
          for(std::size_t i = 1; i <= N_ + 1; ++i)
          {
            const double z = (i <= N_) ? horizon_z(i, side, x, y) : Z_;
            if(z - below < min_gap)
              throw std::invalid_argument("make_layered_model: layers closer than half the thin layer's "
                                          "thickness; change the throw, the undulation or the number of layers");
            below = z;
          }
        }
    for(int b = 0; b <= n; ++b)
    {
      const double y = Y_ * b / n;
      std::vector<double> zs{0., Z_};
      for(int side = 0; side < 2; ++side)
        for(std::size_t i = 1; i <= N_; ++i) zs.push_back(fault_trace(i, side, y)[2]);
      std::sort(zs.begin(), zs.end());
      for(std::size_t k = 1; k < zs.size(); ++k)
        if(zs[k] - zs[k - 1] < min_gap)
          throw std::invalid_argument("make_layered_model: on the fault, horizons of the two sides come "
                                      "closer than half the thin layer's thickness; change the throw");
    }
  }

  // ---- curves -----------------------------------------------------------------

  std::size_t add_point(const LM_vec3& q)
  {
    points.push_back(q);
    return points.size() - 1;
  }

  static double distance(const LM_vec3& a, const LM_vec3& b)
  {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  }

  // a curve from point a (parameter t0) to point b (t1), sampled uniformly in t
  // with chords of about 0.8 h (the mesher splits what it needs)
  std::size_t add_curve(std::function<LM_vec3(double)> eval, double t0, double t1, std::size_t a, std::size_t b)
  {
    LM_curve c;
    c.eval = std::move(eval);
    double length = 0;
    LM_vec3 prev = points[a];
    for(int k = 1; k <= 32; ++k)
    {
      const LM_vec3 q = (k == 32) ? points[b] : c.eval(t0 + (t1 - t0) * k / 32.);
      length += distance(prev, q);
      prev = q;
    }
    const std::size_t n = std::max<std::size_t>(a == b ? 6 : 1, std::size_t(std::ceil(length / (0.8 * h_))));
    c.t.push_back(t0);
    c.v.push_back(a);
    for(std::size_t k = 1; k < n; ++k)
    {
      const double t = t0 + (t1 - t0) * double(k) / double(n);
      c.t.push_back(t);
      c.v.push_back(add_point(c.eval(t)));
    }
    c.t.push_back(t1);
    c.v.push_back(b);
    curves_.push_back(std::move(c));
    return curves_.size() - 1;
  }

  std::size_t add_line(std::size_t a, std::size_t b)
  {
    const LM_vec3 pa = points[a], pb = points[b];
    return add_curve([pa, pb](double t) {
                       return LM_vec3{{pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]), pa[2] + t * (pb[2] - pa[2])}};
                     }, 0., 1., a, b);
  }

  // straight curves through the points `chain`, sorted by coordinate `axis`
  std::vector<std::size_t> add_lines(std::vector<std::size_t> chain, int axis)
  {
    std::sort(chain.begin(), chain.end(),
              [&](std::size_t u, std::size_t w) { return points[u][axis] < points[w][axis]; });
    std::vector<std::size_t> res;
    for(std::size_t k = 0; k + 1 < chain.size(); ++k) res.push_back(add_line(chain[k], chain[k + 1]));
    return res;
  }

  static void append(std::vector<std::size_t>& to, const std::vector<std::size_t>& from)
  {
    to.insert(to.end(), from.begin(), from.end());
  }

  // ---- the model's curves and surfaces -----------------------------------------

  void build_curves_and_surfaces()
  {
    const double X = X_, Y = Y_, Z = Z_;
    const double ys[2] = {0., Y}, zs[2] = {0., Z}, xs[2] = {0., X};

    // corners, each computed once
    std::size_t box[2][2][2];
    for(int a = 0; a < 2; ++a)
      for(int b = 0; b < 2; ++b)
        for(int c = 0; c < 2; ++c) box[a][b][c] = add_point({{xs[a], ys[b], zs[c]}});
    std::size_t fault_corner[2][2]; // [y][z]
    for(int b = 0; b < 2; ++b)
      for(int c = 0; c < 2; ++c) fault_corner[b][c] = add_point({{fault_x(zs[c]), ys[b], zs[c]}});
    // horizon i of side s meets the vertical box edge of that side at y
    std::vector<std::array<std::array<std::size_t, 2>, 2>> edge_corner(N_ + 1), trace_corner(N_ + 1);
    for(std::size_t i = 1; i <= N_; ++i)
      for(int s = 0; s < 2; ++s)
        for(int b = 0; b < 2; ++b)
        {
          const double x = xs[s];
          edge_corner[i][s][b] = add_point({{x, ys[b], horizon_z(i, s, x, ys[b])}});
          trace_corner[i][s][b] = add_point(fault_trace(i, s, ys[b]));
        }

    // box edges, split where horizons and the fault reach them
    std::vector<std::size_t> vertical_edge[2][2]; // [x][y]
    for(int a = 0; a < 2; ++a)
      for(int b = 0; b < 2; ++b)
      {
        std::vector<std::size_t> chain{box[a][b][0], box[a][b][1]};
        for(std::size_t i = 1; i <= N_; ++i) chain.push_back(edge_corner[i][a][b]);
        vertical_edge[a][b] = add_lines(chain, 2);
      }
    std::vector<std::size_t> x_edge[2][2]; // [y][z], through the fault
    for(int b = 0; b < 2; ++b)
      for(int c = 0; c < 2; ++c) x_edge[b][c] = add_lines({box[0][b][c], fault_corner[b][c], box[1][b][c]}, 0);
    std::size_t y_edge[2][2]; // [x][z]
    for(int a = 0; a < 2; ++a)
      for(int c = 0; c < 2; ++c) y_edge[a][c] = add_line(box[a][0][c], box[a][1][c]);

    // the fault's boundary: lines on the top and bottom, and on the y faces
    // through the points where the horizons of both sides reach it
    std::size_t fault_edge_z[2];
    for(int c = 0; c < 2; ++c) fault_edge_z[c] = add_line(fault_corner[0][c], fault_corner[1][c]);
    std::vector<std::size_t> fault_edge_y[2];
    for(int b = 0; b < 2; ++b)
    {
      std::vector<std::size_t> chain{fault_corner[b][0], fault_corner[b][1]};
      for(std::size_t i = 1; i <= N_; ++i)
        for(int s = 0; s < 2; ++s) chain.push_back(trace_corner[i][s][b]);
      fault_edge_y[b] = add_lines(chain, 2);
    }

    // horizon curves: on the y faces, on the x face of their side, on the fault
    std::vector<std::array<std::array<std::size_t, 2>, 2>> horizon_y_curve(N_ + 1);
    std::vector<std::array<std::size_t, 2>> horizon_x_curve(N_ + 1), horizon_fault_curve(N_ + 1);
    for(std::size_t i = 1; i <= N_; ++i)
      for(int s = 0; s < 2; ++s)
      {
        for(int b = 0; b < 2; ++b)
        {
          const double y = ys[b];
          auto eval = [this, i, s, y](double x) { return LM_vec3{{x, y, horizon_z(i, s, x, y)}}; };
          const std::size_t e = edge_corner[i][s][b], f = trace_corner[i][s][b];
          horizon_y_curve[i][s][b] = (s == 0) ? add_curve(eval, 0., points[f][0], e, f)
                                              : add_curve(eval, points[f][0], X, f, e);
        }
        const double x = xs[s];
        horizon_x_curve[i][s] = add_curve([this, i, s, x](double y) { return LM_vec3{{x, y, horizon_z(i, s, x, y)}}; },
                                          0., Y, edge_corner[i][s][0], edge_corner[i][s][1]);
        horizon_fault_curve[i][s] = add_curve([this, i, s](double y) { return fault_trace(i, s, y); },
                                              0., Y, trace_corner[i][s][0], trace_corner[i][s][1]);
      }

    // faces y = 0 (South) and y = Y (North); x = 0 (West, footwall only) and
    // x = X (East, hanging wall only); z = 0 (Bottom) and z = Z (Top)
    const char* y_names[2] = {"South", "North"};
    for(int b = 0; b < 2; ++b)
    {
      std::vector<std::size_t> cs = vertical_edge[0][b];
      append(cs, vertical_edge[1][b]);
      append(cs, x_edge[b][0]);
      append(cs, x_edge[b][1]);
      append(cs, fault_edge_y[b]);
      for(std::size_t i = 1; i <= N_; ++i)
        for(int side = 0; side < 2; ++side) cs.push_back(horizon_y_curve[i][side][b]);
      add_box_face(y_names[b], 1, b, cs);
    }
    const char* x_names[2] = {"West", "East"};
    for(int a = 0; a < 2; ++a)
    {
      std::vector<std::size_t> cs = vertical_edge[a][0];
      append(cs, vertical_edge[a][1]);
      cs.push_back(y_edge[a][0]);
      cs.push_back(y_edge[a][1]);
      for(std::size_t i = 1; i <= N_; ++i) cs.push_back(horizon_x_curve[i][a]);
      add_box_face(x_names[a], 0, a, cs);
    }
    const char* z_names[2] = {"Bottom", "Top"};
    for(int c = 0; c < 2; ++c)
    {
      std::vector<std::size_t> cs = x_edge[0][c];
      append(cs, x_edge[1][c]);
      cs.push_back(y_edge[0][c]);
      cs.push_back(y_edge[1][c]);
      cs.push_back(fault_edge_z[c]);
      add_box_face(z_names[c], 2, c, cs);
    }
    // the fault, in (y, distance along the dip from mid-height): an isometry
    {
      LM_surface s;
      s.name = "Fault";
      append(s.curves, fault_edge_y[0]);
      append(s.curves, fault_edge_y[1]);
      s.curves.push_back(fault_edge_z[0]);
      s.curves.push_back(fault_edge_z[1]);
      for(std::size_t i = 1; i <= N_; ++i)
        for(int side = 0; side < 2; ++side) s.curves.push_back(horizon_fault_curve[i][side]);
      const double xc = fault_xc_, zc = fault_zc_, c = cos_dip_, sn = sin_dip_;
      s.to_2d = [zc, sn](const LM_vec3& q) { return LM_vec2{{q[1], (q[2] - zc) / sn}}; };
      s.to_3d = [xc, zc, c, sn](const LM_vec2& q) { return LM_vec3{{xc - q[1] * c, q[0], zc + q[1] * sn}}; };
      s.label = [this](const LM_vec3& q) {
        return LM_label(region(1, body_of(1, q[0], q[1], q[2])), region(0, body_of(0, q[0], q[1], q[2])));
      };
      s.positive_direction = {{sn, 0., c}}; // towards x > x_f(z): the hanging wall
      s.patch_name = [this](const LM_label& l) { return "Fault_" + region_names[l.second] + "_" + region_names[l.first]; };
      surfaces.push_back(s);
    }
    // horizons, one height field per side, in (x,y)
    for(std::size_t i = 1; i <= N_; ++i)
      for(int side = 0; side < 2; ++side)
      {
        LM_surface s;
        s.name = "Horizon_" + std::to_string(i) + (side == 0 ? "_footwall" : "_hangingwall");
        s.curves = {horizon_y_curve[i][side][0], horizon_y_curve[i][side][1], horizon_x_curve[i][side],
                    horizon_fault_curve[i][side]};
        s.to_2d = [](const LM_vec3& q) { return LM_vec2{{q[0], q[1]}}; };
        s.to_3d = [this, i, side](const LM_vec2& q) { return LM_vec3{{q[0], q[1], horizon_z(i, side, q[0], q[1])}}; };
        const int above = region(side, i), below = region(side, i - 1);
        s.label = [this, side, above, below](const LM_vec3& q) {
          return side_of(q[0], q[2]) == side ? LM_label(above, below) : LM_label(-1, -1);
        };
        s.positive_direction = {{0., 0., 1.}};
        const std::string name = s.name;
        s.patch_name = [name](const LM_label&) { return name; };
        surfaces.push_back(s);
      }
    if(p_.small_fault) add_small_fault();
  }

  // the box face where coordinate `axis` is at its minimum (`at_max` 0) or
  // maximum (1), meshed in the two other coordinates; one patch per region
  void add_box_face(const std::string& name, int axis, int at_max, const std::vector<std::size_t>& curves)
  {
    const int i = (axis == 0) ? 1 : 0, j = (axis == 2) ? 1 : 2;
    const double value = at_max ? (axis == 0 ? X_ : axis == 1 ? Y_ : Z_) : 0.;
    LM_surface s;
    s.name = name;
    s.curves = curves;
    s.to_2d = [i, j](const LM_vec3& q) { return LM_vec2{{q[i], q[j]}}; };
    s.to_3d = [axis, value, i, j](const LM_vec2& q) {
      LM_vec3 r;
      r[axis] = value;
      r[i] = q[0];
      r[j] = q[1];
      return r;
    };
    s.label = [this](const LM_vec3& q) { return LM_label(0, region_at(q)); }; // the outside is positive
    s.positive_direction = {{0., 0., 0.}};
    s.positive_direction[axis] = at_max ? 1. : -1.;
    s.patch_name = [this, name](const LM_label& l) { return name + "_" + region_names[l.second]; };
    surfaces.push_back(s);
  }

  // A small elliptic fault inside the thickest layer (the top one of the hanging
  // wall), its whole boundary clear of every other surface.
  void add_small_fault()
  {
    const int side = 1;
    const std::size_t body = N_;
    const double yc = 0.5 * Y_;
    double xc = 0.5 * (fault_x(0.5 * Z_) + X_), zc = 0;
    for(int it = 0; it < 3; ++it) // centre it between the fault and the East face, at mid-layer
    {
      zc = 0.5 * (horizon_z(N_, side, xc, yc) + Z_);
      xc = 0.5 * (fault_x(zc) + X_);
    }
    const double thickness = Z_ - horizon_z(N_, side, xc, yc);
    const double strike = 20. * CGAL_PI / 180., dip = 40. * CGAL_PI / 180.;
    const LM_vec3 u{{std::sin(strike), std::cos(strike), 0.}};                     // along strike
    const LM_vec3 w{{std::cos(strike), -std::sin(strike), 0.}};                    // horizontal, across
    const LM_vec3 v{{w[0] * std::cos(dip), w[1] * std::cos(dip), -std::sin(dip)}}; // down the dip
    const double ra = std::min(0.25 * Y_, 0.3 * (X_ - fault_x(zc)));
    const double rb = 0.25 * thickness / std::sin(dip);
    const LM_vec3 c{{xc, yc, zc}};
    auto to_3d = [c, u, v](const LM_vec2& q) {
      return LM_vec3{{c[0] + q[0] * u[0] + q[1] * v[0], c[1] + q[0] * u[1] + q[1] * v[1], c[2] + q[0] * u[2] + q[1] * v[2]}};
    };
    // clearance: every point of the disc at least a tenth of the layer's thickness
    // from the horizon below, the top, and the fault and box faces
    for(int r = 0; r <= 8; ++r)
      for(int k = 0; k < 64; ++k)
      {
        const double a = 2 * CGAL_PI * k / 64.;
        const LM_vec3 q = to_3d({{ra * r / 8. * std::cos(a), rb * r / 8. * std::sin(a)}});
        const double m = 0.1 * thickness;
        if(q[2] - horizon_z(N_, side, q[0], q[1]) < m || Z_ - q[2] < m || q[0] - fault_x(q[2]) < m ||
           X_ - q[0] < m || q[1] < m || Y_ - q[1] < m || side_of(q[0], q[2]) != side)
          throw std::invalid_argument("make_layered_model: the small fault does not fit inside the top layer "
                                      "of the hanging wall; disable it or change the geometry");
      }
    const std::size_t start = add_point(to_3d({{ra, 0.}}));
    const std::size_t curve = add_curve([to_3d, ra, rb](double t) { return to_3d({{ra * std::cos(t), rb * std::sin(t)}}); },
                                        0., 2 * CGAL_PI, start, start);
    LM_surface s;
    s.name = "Small_fault";
    s.curves = {curve};
    s.to_2d = [c, u, v](const LM_vec3& q) {
      const LM_vec3 d{{q[0] - c[0], q[1] - c[1], q[2] - c[2]}};
      return LM_vec2{{d[0] * u[0] + d[1] * u[1] + d[2] * u[2], d[0] * v[0] + d[1] * v[1] + d[2] * v[2]}};
    };
    s.to_3d = to_3d;
    const int r = region(side, body);
    s.label = [r](const LM_vec3&) { return LM_label(r, r); };
    s.positive_direction = {{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
    s.patch_name = [](const LM_label&) { return std::string("Small_fault"); };
    surfaces.push_back(s);
  }

  // ---- meshing ----------------------------------------------------------------

  // connected components of the finite faces across unconstrained edges, each
  // labelled by the label covering most of its area (robust to the small gap
  // between a curve and its chords)
  std::vector<LM_label> label_components(const LM_surface& s, const CDT& cdt,
                                         CGAL::Unique_hash_map<Face_handle, int>& comp) const
  {
    std::vector<std::map<LM_label, double>> votes;
    for(Face_handle f : cdt.finite_face_handles())
    {
      if(comp[f] >= 0) continue;
      const int id = int(votes.size());
      votes.emplace_back();
      std::vector<Face_handle> stack{f};
      comp[f] = id;
      while(!stack.empty())
      {
        const Face_handle g = stack.back();
        stack.pop_back();
        const Point_2 &a = g->vertex(0)->point(), &b = g->vertex(1)->point(), &c = g->vertex(2)->point();
        const LM_vec3 q = s.to_3d({{(a.x() + b.x() + c.x()) / 3., (a.y() + b.y() + c.y()) / 3.}});
        votes[id][s.label(q)] += std::abs(CGAL::area(a, b, c));
        for(int e = 0; e < 3; ++e)
        {
          const Face_handle n = g->neighbor(e);
          if(cdt.is_infinite(n) || cdt.is_constrained(std::make_pair(g, e)) || comp[n] >= 0) continue;
          comp[n] = id;
          stack.push_back(n);
        }
      }
    }
    std::vector<LM_label> labels;
    for(const auto& vote : votes)
      labels.push_back(std::max_element(vote.begin(), vote.end(), [](const auto& x, const auto& y) {
                         return x.second < y.second;
                       })->first);
    return labels;
  }

  // Builds the constrained Delaunay triangulation of surface `si` from the
  // current curve samples and refines it (angle and size bounds); records the
  // curve edges the refinement had to split.
  void mesh_surface(std::size_t si, std::vector<std::vector<std::size_t>>& splits)
  {
    const LM_surface& s = surfaces[si];
    CDT& cdt = *cdts_[si];
    cdt.clear();
    std::map<std::size_t, Vertex_handle> vh;
    for(std::size_t c : s.curves)
      for(std::size_t idx : curves_[c].v)
      {
        if(vh.count(idx)) continue;
        const LM_vec2 q = s.to_2d(points[idx]);
        const Vertex_handle h = cdt.insert(Point_2(q[0], q[1]));
        h->info().value = idx;
        vh[idx] = h;
      }
    if(cdt.number_of_vertices() != vh.size())
      throw Geological_model_error("make_layered_model: two points of surface " + s.name + " coincide");
    for(std::size_t c : s.curves)
      for(std::size_t k = 0; k + 1 < curves_[c].v.size(); ++k)
        cdt.insert_constraint(vh[curves_[c].v[k]], vh[curves_[c].v[k + 1]]);
    if(cdt.number_of_vertices() != vh.size())
      throw Geological_model_error("make_layered_model: curves of surface " + s.name + " cross");

    // the parts of the convex hull the surface does not cover are not refined
    CGAL::Unique_hash_map<Face_handle, int> comp(-1);
    const std::vector<LM_label> labels = label_components(s, cdt, comp);
    std::vector<Point_2> seeds;
    std::vector<bool> seeded(labels.size(), false);
    for(Face_handle f : cdt.finite_face_handles())
    {
      const int id = comp[f];
      if(labels[id].first >= 0 || seeded[id]) continue;
      seeded[id] = true;
      seeds.push_back(CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
    }
    const double sine = std::sin(p_.min_angle * CGAL_PI / 180.);
    CGAL::Delaunay_mesher_2<CDT, Criteria> mesher(cdt, Criteria(sine * sine, h_));
    mesher.set_seeds(seeds.begin(), seeds.end(), false);
    mesher.refine_mesh();

    for(std::size_t c : s.curves)
      for(std::size_t k = 0; k + 1 < curves_[c].v.size(); ++k)
        if(!cdt.is_edge(vh[curves_[c].v[k]], vh[curves_[c].v[k + 1]])) splits[c].push_back(k);
  }

  // Meshes every surface until no refinement splits a curve edge any more: a
  // split edge is split on the curve itself (at its middle parameter) for all
  // the surfaces through it, which are then meshed again. (Taking the mesher's
  // own split points instead does not work: surfaces that see a curve in
  // different projections put them at different places, and the curve ends up
  // with points very close together.)
  void mesh_all()
  {
    std::vector<std::vector<std::size_t>> surfaces_of_curve(curves_.size());
    for(std::size_t si = 0; si < surfaces.size(); ++si)
      for(std::size_t c : surfaces[si].curves) surfaces_of_curve[c].push_back(si);
    for(std::size_t si = 0; si < surfaces.size(); ++si) cdts_.emplace_back(new CDT());

    std::vector<bool> dirty(surfaces.size(), true);
    for(rounds = 1;; ++rounds)
    {
      if(rounds > 100)
        throw Geological_model_error("make_layered_model: the surface meshes do not agree on their curves "
                                     "after 100 rounds");
      std::vector<std::vector<std::size_t>> splits(curves_.size());
      for(std::size_t si = 0; si < surfaces.size(); ++si)
        if(dirty[si]) mesh_surface(si, splits);
      std::fill(dirty.begin(), dirty.end(), false);
      bool any = false;
      for(std::size_t c = 0; c < curves_.size(); ++c)
      {
        std::vector<std::size_t>& ks = splits[c];
        if(ks.empty()) continue;
        any = true;
        std::sort(ks.begin(), ks.end());
        ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
        LM_curve& cv = curves_[c];
        for(auto k = ks.rbegin(); k != ks.rend(); ++k) // from the end: indices stay valid
        {
          const double t = 0.5 * (cv.t[*k] + cv.t[*k + 1]);
          // midpoint splits cascade at small angles between curves; stop cleanly
          if(distance(points[cv.v[*k]], points[cv.v[*k + 1]]) < h_ / 256)
            throw Geological_model_error("make_layered_model: the surface meshes keep splitting a curve (edge "
                                         "shorter than edge_length / 256); the angles between surfaces are too small");
          cv.t.insert(cv.t.begin() + std::ptrdiff_t(*k + 1), t);
          cv.v.insert(cv.v.begin() + std::ptrdiff_t(*k + 1), add_point(cv.eval(t)));
        }
        for(std::size_t si : surfaces_of_curve[c]) dirty[si] = true;
      }
      if(!any) break;
    }
    collect_triangles();
  }

  void collect_triangles()
  {
    for(std::size_t si = 0; si < surfaces.size(); ++si)
    {
      const LM_surface& s = surfaces[si];
      CDT& cdt = *cdts_[si];
      CGAL::Unique_hash_map<Face_handle, int> comp(-1);
      const std::vector<LM_label> labels = label_components(s, cdt, comp);
      for(Face_handle f : cdt.finite_face_handles())
      {
        const LM_label& l = labels[comp[f]];
        if(l.first < 0 || !f->is_in_domain()) continue;
        std::array<std::size_t, 3> t;
        for(int k = 0; k < 3; ++k)
        {
          LM_index& idx = f->vertex(k)->info();
          if(idx.value == std::size_t(-1)) // a vertex the refinement added inside
          {
            const Point_2& q = f->vertex(k)->point();
            idx.value = add_point(s.to_3d({{q.x(), q.y()}}));
          }
          t[k] = idx.value;
        }
        // orient so that the positive region lies on the side of the normal
        const LM_vec3 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
        const LM_vec3 e1{{b[0] - a[0], b[1] - a[1], b[2] - a[2]}}, e2{{c[0] - a[0], c[1] - a[1], c[2] - a[2]}};
        const LM_vec3 n{{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]}};
        const LM_vec3& d = s.positive_direction;
        if(n[0] * d[0] + n[1] * d[1] + n[2] * d[2] < 0) std::swap(t[1], t[2]);
        triangles.push_back(Out_triangle{si, l, t});
      }
      cdt.clear(); // done with it
    }
  }
};

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref

Builds the package's synthetic geological model into `model` (its content is
replaced): a box `[0,size_x] x [0,size_y] x [0,size_z]` (z up) of ordinary
layers and one thin layer bounded by smooth undulating horizons, cut from top
to bottom by a planar fault that dips towards +x and moves the hanging wall
(the +x side) down by a throw that lines no horizon up with another, and a
small elliptic fault that ends inside the top layer of the hanging wall (a
patch with that region on both sides).

Regions are named after the layer and the side of the fault, from the bottom:
`Layer_1_footwall`, ..., `Thin_layer_footwall`, ..., then the same with
`_hangingwall`. Patches are named after their surface: `Horizon_2_footwall`,
`Small_fault`; the box faces (`South` y=0, `North`, `West` x=0, `East`,
`Bottom`, `Top`) and the fault get one patch per region they bound, e.g.
`Top_Layer_4_hangingwall`, `Fault_Layer_2_footwall_Layer_1_hangingwall`
(footwall region, then hanging-wall region).

Construction, conforming by design: every curve where surfaces meet is
sampled once and all the surfaces through it use the same points; each planar
surface (box faces, fault, small fault) and each horizon (in its (x,y)
projection) is meshed by a 2D constrained Delaunay refinement with the bounds
`edge_length` and `min_angle`; when a refinement splits a curve edge, the curve
is split for all the surfaces through it and they are meshed again, until they
agree. The same parameters give the same model, bit for bit.

\throws std::invalid_argument if the parameters are out of range or give
layers that touch, horizons that line up across the fault, or no room for the
small fault.
*/
template <class GeomTraits>
void make_layered_model(Geological_model_3<GeomTraits>& model,
                        const Layered_model_parameters& parameters = Layered_model_parameters())
{
  internal::Layered_model_builder b(parameters);

  Geological_model_3<GeomTraits> m;
  for(std::size_t r = 1; r < b.region_names.size(); ++r) m.add_region(b.region_names[r]);
  for(const internal::LM_vec3& q : b.points) m.add_point(typename GeomTraits::Point_3(q[0], q[1], q[2]));

  // patches in surface order, and within a surface by (negative, positive) region
  std::map<std::pair<std::size_t, internal::LM_label>, std::size_t> patch_of;
  for(std::size_t si = 0; si < b.surfaces.size(); ++si)
  {
    std::vector<internal::LM_label> labels;
    for(const auto& t : b.triangles)
      if(t.surface == si) labels.push_back(t.label);
    std::sort(labels.begin(), labels.end(), [](const internal::LM_label& x, const internal::LM_label& y) {
      return std::make_pair(x.second, x.first) < std::make_pair(y.second, y.first);
    });
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    for(const internal::LM_label& l : labels)
      patch_of[std::make_pair(si, l)] =
        m.add_patch(b.surfaces[si].patch_name(l), std::size_t(l.first), std::size_t(l.second));
  }
  // triangles grouped by patch, in the order the meshes gave them
  std::vector<std::vector<std::size_t>> by_patch(m.number_of_patches());
  for(std::size_t k = 0; k < b.triangles.size(); ++k)
    by_patch[patch_of.at(std::make_pair(b.triangles[k].surface, b.triangles[k].label))].push_back(k);
  for(std::size_t pa = 0; pa < by_patch.size(); ++pa)
    for(std::size_t k : by_patch[pa])
    {
      const auto& t = b.triangles[k].v;
      m.add_triangle(t[0], t[1], t[2], pa);
    }
  m.remove_unused_points();
  model = std::move(m);
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_MAKE_LAYERED_MODEL_H
