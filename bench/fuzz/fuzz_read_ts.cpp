// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: GOCAD TSurf reader, one body per object (bench/run_fuzzers.sh builds and runs it).

#include "fuzz_reader.h"
#include <CGAL/Bubble_mesh_3/IO/read_gocad_tsurf.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return fuzz_reader(data, size, [](std::istream& is, Fuzz_model& m) {
    CGAL::Bubble_mesh_3::IO::read_gocad_tsurf(is, "fuzz.ts", m);
  });
}
