// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared body of the reader fuzzers: feed the bytes to a reader's istream
// overload. A Geological_model_error is the expected answer to bad input;
// any other exception, a crash, a hang or a sanitizer report is a finding.
// With `strict_round_trip`, a model that reads must also survive the
// multi-body OBJ round trip (for the OBJ reader itself; other formats may
// hold what validation, not the OBJ reader, is there to refuse).

#ifndef BUBBLE_MESH_3_BENCH_FUZZ_READER_H
#define BUBBLE_MESH_3_BENCH_FUZZ_READER_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <CGAL/Bubble_mesh_3/geological_model_measures.h>
#include <CGAL/Bubble_mesh_3/IO/read_multibody_obj.h>
#include <CGAL/Bubble_mesh_3/IO/write_multibody_obj.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

typedef CGAL::Bubble_mesh_3::Geological_model_3<CGAL::Epick> Fuzz_model;

template <class Read>
int fuzz_reader(const std::uint8_t* data, std::size_t size, Read read, bool strict_round_trip = false)
{
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  Fuzz_model m;
  try
  {
    read(is, m);
  }
  catch(const CGAL::Bubble_mesh_3::Geological_model_error&)
  {
    return 0;
  }
  CGAL::Bubble_mesh_3::region_volumes(m);
  std::stringstream obj;
  try
  {
    CGAL::Bubble_mesh_3::IO::write_multibody_obj(obj, m);
  }
  catch(const CGAL::Bubble_mesh_3::Geological_model_error&)
  {
    return 0;  // e.g. two regions of the same name: documented refusal
  }
  Fuzz_model back;
  try
  {
    CGAL::Bubble_mesh_3::IO::read_multibody_obj(obj, "round trip", back);
  }
  catch(const CGAL::Bubble_mesh_3::Geological_model_error& e)
  {
    if(!strict_round_trip) return 0;
    // what the reader accepted, the writer must write readably
    std::fprintf(stderr, "round trip failed: %s\n", e.what());
    std::abort();
  }
  if(back.number_of_regions() > m.number_of_regions())
  {
    std::fprintf(stderr, "round trip: %zu regions became %zu\n", m.number_of_regions(), back.number_of_regions());
    std::abort();
  }
  return 0;
}

#endif // BUBBLE_MESH_3_BENCH_FUZZ_READER_H
