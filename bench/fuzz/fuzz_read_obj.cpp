// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: multi-body OBJ reader, with exact merging or, for inputs
// of odd size, merging within 1e-3 of the diagonal (bench/run_fuzzers.sh).

#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const double tolerance = (size % 2) ? 1e-3 : 0.;
  return fuzz_reader(data, size, [tolerance](std::istream& is, Fuzz_model& m) {
    CGAL::Bubble_mesh_3::IO::read_multibody_obj(is, "fuzz.obj", m,
                                                CGAL::Bubble_mesh_3::parameters::merge_tolerance(tolerance));
  }, true);
}
