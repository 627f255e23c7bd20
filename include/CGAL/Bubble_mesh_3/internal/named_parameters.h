// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_NAMED_PARAMETERS_H

// The one way this package declares a named parameter. Each stage lists its
// tags in `CGAL::Bubble_mesh_3::internal_np` and then, inside
// `CGAL::Bubble_mesh_3::parameters`, writes one line per tag:
//
//   CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(double, cell_edge_factor)
//
// which makes the pair of functions CGAL users know: the one-argument form
// starts a chain (`parameters::cell_edge_factor(1.2).random_seed(7)`), the
// two-argument form appends to an existing chain, CGAL's or ours
// (`parameters::cell_edge_factor(1.2, CGAL::parameters::random_seed(7))`).
// The value is taken as `TYPE const&`: with `const TYPE&` a pointer TYPE would
// become a pointer to const.
// The tag is looked up as `internal_np::TAG_t` from the namespace of the use.

#include <CGAL/Named_function_parameters.h>

#define CGAL_BUBBLE_MESH_3_NAMED_PARAMETER_WITH_TAG(TYPE, NAME, TAG)                             \
  inline CGAL::Named_function_parameters<TYPE, internal_np::TAG##_t> NAME(TYPE const& value)     \
  {                                                                                              \
    return CGAL::Named_function_parameters<TYPE, internal_np::TAG##_t>(value);                   \
  }                                                                                              \
  template <class T, class Tag, class Base>                                                      \
  CGAL::Named_function_parameters<TYPE, internal_np::TAG##_t,                                    \
                                  CGAL::Named_function_parameters<T, Tag, Base> >                \
  NAME(TYPE const& value, const CGAL::Named_function_parameters<T, Tag, Base>& np)               \
  {                                                                                              \
    return CGAL::Named_function_parameters<TYPE, internal_np::TAG##_t,                           \
                                           CGAL::Named_function_parameters<T, Tag, Base> >(      \
      value, np);                                                                                \
  }

#define CGAL_BUBBLE_MESH_3_NAMED_PARAMETER(TYPE, NAME) \
  CGAL_BUBBLE_MESH_3_NAMED_PARAMETER_WITH_TAG(TYPE, NAME, NAME)

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_NAMED_PARAMETERS_H
