// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The plane of the programs' --section option (bubble_mesh_3 and
// bubble_mesh_3_quality draw the same sections): "x=V", "y=V" or "z=V", or by
// default a vertical plane through the middle of the model along its longer
// horizontal side, the view a geologist draws a cross-section in.

#ifndef BUBBLE_MESH_3_TOOLS_SECTION_PLANE_H
#define BUBBLE_MESH_3_TOOLS_SECTION_PLANE_H

#include <CGAL/Bbox_3.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <string>

struct Section_choice
{
  int axis = -1;     // 0, 1, 2: x, y or z = level; -1: the default vertical plane
  double level = 0.;
};

// "x=V", "y=V" or "z=V"; false when `spec` is none of these
inline bool parse_section_choice(const std::string& spec, Section_choice& out)
{
  const std::size_t eq = spec.find('=');
  if(eq != 1 || (spec[0] != 'x' && spec[0] != 'y' && spec[0] != 'z')) return false;
  const std::string value = spec.substr(2);
  char* end = nullptr;
  const double level = std::strtod(value.c_str(), &end);
  if(value.empty() || *end != '\0' || !std::isfinite(level)) return false;
  out.axis = spec[0] - 'x';
  out.level = level;
  return true;
}

inline const char* section_choice_syntax() { return "x=V, y=V or z=V (a plane of constant x, y or z)"; }

// The plane for `choice` in a model whose box is `box`, and a description for a
// title; false, with `error` set, when the plane misses the box.
template <class Plane_3>
bool section_plane(const CGAL::Bbox_3& box, Section_choice choice, Plane_3& plane, std::string& description,
                   std::string& error)
{
  typedef typename Plane_3::R K;
  if(choice.axis < 0)
  {
    choice.axis = box.xmax() - box.xmin() >= box.ymax() - box.ymin() ? 1 : 0;
    choice.level = 0.5 * (box.min(choice.axis) + box.max(choice.axis));
  }
  const int a = choice.axis;
  const char name = char('x' + a);
  if(!(choice.level > box.min(a) && choice.level < box.max(a)))
  {
    std::ostringstream msg;
    msg << std::setprecision(10) << "--section " << name << "=" << choice.level << " misses the model: its " << name
        << " runs from " << box.min(a) << " to " << box.max(a);
    error = msg.str();
    return false;
  }
  // seen from -x (y to the right), from +y (x to the right), from above (x to the right)
  const typename K::Vector_3 normal =
    a == 0 ? typename K::Vector_3(-1, 0, 0) : a == 1 ? typename K::Vector_3(0, 1, 0) : typename K::Vector_3(0, 0, 1);
  plane = Plane_3(typename K::Point_3(a == 0 ? choice.level : 0., a == 1 ? choice.level : 0., a == 2 ? choice.level : 0.),
                  normal);
  std::ostringstream text;
  text << std::setprecision(10) << "section " << name << " = " << choice.level
       << (a == 0 ? " (y to the right, z up)" : a == 1 ? " (x to the right, z up)" : " (seen from above, x to the right)");
  description = text.str();
  return true;
}

#endif // BUBBLE_MESH_3_TOOLS_SECTION_PLANE_H
