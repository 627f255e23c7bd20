// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_INTERNAL_PARALLEL_LOOPS_H
#define CGAL_BUBBLE_MESH_3_INTERNAL_PARALLEL_LOOPS_H

// Loops that run on TBB when the concurrency tag asks for it and TBB is
// linked, sequentially otherwise. Callers write per index, so how the range is
// split never changes a result.

#include <CGAL/config.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace internal {

template <class ConcurrencyTag>
struct Runs_in_parallel
{
#ifdef CGAL_LINKED_WITH_TBB
  static constexpr bool value = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
#else
  static constexpr bool value = false;
#endif
};

// f(begin, end) over [0, n); the split does not matter to callers that write per index
template <class ConcurrencyTag, class F>
void for_each_block(std::size_t n, std::size_t grain, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(Runs_in_parallel<ConcurrencyTag>::value && n > grain)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
    return;
  }
#endif
  CGAL_USE(grain);
  if(n > 0) f(std::size_t(0), n);
}

} // namespace internal
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_INTERNAL_PARALLEL_LOOPS_H
