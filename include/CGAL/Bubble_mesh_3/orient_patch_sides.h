// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_ORIENT_PATCH_SIDES_H
#define CGAL_BUBBLE_MESH_3_ORIENT_PATCH_SIDES_H

#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/internal/centred_coordinates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {

namespace internal {

// Solid angle of the triangle (a, b, c) seen from the origin, signed by its
// orientation (Van Oosterom and Strackee's formula); summed over a closed
// surface it is +-4 pi inside and 0 outside.
inline double solid_angle(const Centred_point& a, const Centred_point& b, const Centred_point& c)
{
  auto dot = [](const Centred_point& u, const Centred_point& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const double la = std::sqrt(dot(a, a)), lb = std::sqrt(dot(b, b)), lc = std::sqrt(dot(c, c));
  const double det = triple_product(a, b, c);
  const double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2. * std::atan2(det, den);
}

} // namespace internal

/*!
\ingroup PkgBubbleMesh3Ref
What `orient_patch_sides()` changed in a model.
*/
struct Patch_side_repair
{
  std::vector<std::size_t> swapped_patches;   ///< patches whose two regions were exchanged, in increasing order
  std::vector<std::size_t> flipped_triangles; ///< triangles turned over to face like their patch, in increasing order
  /// true when nothing was changed
  bool empty() const { return swapped_patches.empty() && flipped_triangles.empty(); }
};

/*!
\ingroup PkgBubbleMesh3Ref

Decides from the geometry which region lies on which side of each patch and
which way each of its triangles faces, and mends the model where the
recorded sides or orientations contradict it: a patch whose regions are the
wrong way round gets them exchanged, a triangle facing against the rest of
its patch is turned over. Returns what was changed; nothing when the model
was right or when the geometry does not decide (then the model is left as it
was, for `validate_geological_model()` to report what is wrong).

A GOCAD Model3d file gives, for each region, the surface parts around it
with a sign telling the side. Hand-written or converted files sometimes give
a sign that contradicts the part's triangles, or a part whose triangles face
both ways (a box whose top and bottom both face up), so that a region's
boundary is not consistently oriented and validation rejects it.

Each region's boundary (the triangles of the patches that have it on exactly
one side) is oriented here from its triangles alone: its connected shells
are oriented consistently across their edges; a shell enclosed by an odd
number of the region's other shells is a cavity (its normals point into it),
any other shell encloses the region (normals outward). A triangle between two
regions must get the same verdict from both; the majority of a patch's
triangles decides the patch's sides (a tie keeps them). The geometry does not
decide, and nothing is changed, when the two verdicts of a triangle differ,
when a boundary edge does not have exactly two triangles of the region, or
when a shell cannot be oriented or encloses no volume. Patches inside a
region (the same region on both sides) keep their sides.

On a model that passes `validate_geological_model()` with every shell
oriented as documented, nothing is changed.
*/
template <class GeomTraits>
Patch_side_repair orient_patch_sides(Geological_model_3<GeomTraits>& model)
{
  typedef internal::Centred_point P3;
  const std::size_t nt = model.number_of_triangles();
  if(nt == 0) return Patch_side_repair();

  const P3 centre = internal::box_centre(model);
  std::vector<P3> pts(model.number_of_points());
  for(std::size_t i = 0; i < pts.size(); ++i) pts[i] = internal::centred(model.point(i), centre);

  // a side: a triangle as part of the boundary of one region
  struct Side
  {
    std::size_t region, triangle;
  };
  std::vector<Side> sides;
  for(std::size_t t = 0; t < nt; ++t)
  {
    const auto& patch = model.patch(model.patch_of_triangle(t));
    if(patch.is_inside_region()) continue;
    for(std::size_t r : {patch.negative_region, patch.positive_region})
      if(r != 0) sides.push_back(Side{r, t});
  }
  if(sides.empty()) return Patch_side_repair();

  // edge uses, grouped by (region, edge); `forward` is the stored triangle running from the
  // smaller to the larger vertex index
  struct Use
  {
    std::size_t region, a, b, side;
    bool forward;
  };
  std::vector<Use> uses;
  uses.reserve(3 * sides.size());
  for(std::size_t s = 0; s < sides.size(); ++s)
  {
    const auto& tri = model.triangle(sides[s].triangle);
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t u = tri[k], v = tri[(k + 1) % 3];
      uses.push_back(Use{sides[s].region, (std::min)(u, v), (std::max)(u, v), s, u < v});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    if(x.region != y.region) return x.region < y.region;
    if(x.a != y.a) return x.a < y.a;
    if(x.b != y.b) return x.b < y.b;
    return x.side < y.side;
  });

  // neighbours across edges; `flip` = the two sides need opposite flips of their stored
  // orientation (they run the edge the same way)
  std::vector<std::vector<std::pair<std::size_t, bool> > > next(sides.size());
  for(std::size_t i = 0; i < uses.size(); i += 2)
  {
    if(i + 1 >= uses.size() || uses[i + 1].region != uses[i].region || uses[i + 1].a != uses[i].a ||
       uses[i + 1].b != uses[i].b)
      return Patch_side_repair(); // an open edge
    if(i + 2 < uses.size() && uses[i + 2].region == uses[i].region && uses[i + 2].a == uses[i].a &&
       uses[i + 2].b == uses[i].b)
      return Patch_side_repair(); // more than two triangles of the region at an edge
    const bool same = uses[i].forward == uses[i + 1].forward;
    next[uses[i].side].emplace_back(uses[i + 1].side, same);
    next[uses[i + 1].side].emplace_back(uses[i].side, same);
  }

  // shells: connected sides with their flips relative to the first side
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> shell_of(sides.size(), none);
  std::vector<char> flipped(sides.size(), 0);
  std::vector<std::size_t> shell_region, shell_first;
  std::vector<double> shell_volume; // with the flips applied
  for(std::size_t s0 = 0; s0 < sides.size(); ++s0)
  {
    if(shell_of[s0] != none) continue;
    const std::size_t id = shell_region.size();
    shell_region.push_back(sides[s0].region);
    shell_first.push_back(s0);
    double volume = 0.;
    std::vector<std::size_t> stack(1, s0);
    shell_of[s0] = id;
    while(!stack.empty())
    {
      const std::size_t s = stack.back();
      stack.pop_back();
      const auto& tri = model.triangle(sides[s].triangle);
      const double v = internal::signed_volume(pts[tri[0]], pts[tri[1]], pts[tri[2]]);
      volume += flipped[s] ? -v : v;
      for(const auto& n : next[s])
      {
        const char f = static_cast<char>(flipped[s] ^ static_cast<char>(n.second));
        if(shell_of[n.first] == none)
        {
          shell_of[n.first] = id;
          flipped[n.first] = f;
          stack.push_back(n.first);
        }
        else if(flipped[n.first] != f)
          return Patch_side_repair(); // not orientable
      }
    }
    if(volume == 0.) return Patch_side_repair(); // flat: no inside
    shell_volume.push_back(volume);
  }

  // a shell is a cavity when an odd number of its region's other shells enclose it (the
  // winding number of a closed shell is +-1 inside, 0 outside); a point of the shell is
  // tested, which lies on no other shell of a valid region
  std::vector<std::size_t> shells_in_region(model.number_of_regions() + 1, 0);
  for(std::size_t r : shell_region) ++shells_in_region[r];
  std::vector<char> reverse_shell(shell_region.size(), 0);
  for(std::size_t c = 0; c < shell_region.size(); ++c)
  {
    int depth = 0;
    if(shells_in_region[shell_region[c]] > 1)
    {
      const auto& tri = model.triangle(sides[shell_first[c]].triangle);
      P3 x;
      for(int d = 0; d < 3; ++d) x[d] = (pts[tri[0]][d] + pts[tri[1]][d] + pts[tri[2]][d]) / 3.;
      std::vector<double> winding(shell_region.size(), 0.);
      for(std::size_t s = 0; s < sides.size(); ++s)
      {
        if(sides[s].region != shell_region[c] || shell_of[s] == c) continue;
        const auto& t = model.triangle(sides[s].triangle);
        P3 q[3];
        for(int k = 0; k < 3; ++k)
          for(int d = 0; d < 3; ++d) q[k][d] = pts[t[k]][d] - x[d];
        const double omega = internal::solid_angle(q[0], q[1], q[2]);
        winding[shell_of[s]] += flipped[s] ? -omega : omega; // the shell's own consistent orientation
      }
      for(double w : winding)
        if(std::abs(w) > 2. * 3.14159265358979323846) ++depth;
    }
    const bool cavity = depth % 2 == 1;
    // outward normals give an enclosing shell a positive volume and a cavity a negative one
    reverse_shell[c] = static_cast<char>((shell_volume[c] > 0.) == cavity);
  }

  // does each triangle, as stored, face the way its patch's regions say? Its sides in the
  // two regions must agree
  const std::size_t none_yet = 2;
  std::vector<char> agrees(nt, static_cast<char>(none_yet));
  for(std::size_t s = 0; s < sides.size(); ++s)
  {
    const std::size_t t = sides[s].triangle;
    const bool out = flipped[s] == reverse_shell[shell_of[s]]; // stored normal points out of the region
    const bool is_negative = sides[s].region == model.patch(model.patch_of_triangle(t)).negative_region;
    const char a = static_cast<char>(out == is_negative);
    if(agrees[t] == static_cast<char>(none_yet)) agrees[t] = a;
    else if(agrees[t] != a) return Patch_side_repair(); // the two regions disagree
  }

  // the majority of a patch's triangles decides its sides; the others are turned over
  const std::size_t np = model.number_of_patches();
  std::vector<std::size_t> yes(np, 0), no(np, 0);
  for(std::size_t t = 0; t < nt; ++t)
    if(agrees[t] == 1) ++yes[model.patch_of_triangle(t)];
    else if(agrees[t] == 0) ++no[model.patch_of_triangle(t)];
  Patch_side_repair repair;
  for(std::size_t p = 0; p < np; ++p)
    if(no[p] > yes[p]) repair.swapped_patches.push_back(p);
  for(std::size_t t = 0; t < nt; ++t)
  {
    if(agrees[t] == static_cast<char>(none_yet)) continue;
    const std::size_t p = model.patch_of_triangle(t);
    if((agrees[t] == 1) == (no[p] > yes[p])) repair.flipped_triangles.push_back(t);
  }
  for(std::size_t p : repair.swapped_patches)
  {
    const auto& patch = model.patch(p);
    model.set_patch_regions(p, patch.negative_region, patch.positive_region);
  }
  for(std::size_t t : repair.flipped_triangles)
  {
    auto tri = model.triangle(t);
    std::swap(tri[1], tri[2]);
    model.set_triangle(t, tri);
  }
  return repair;
}

} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_ORIENT_PATCH_SIDES_H
