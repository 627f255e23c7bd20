// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_INTERNAL_WRITE_ATOMICALLY_H
#define CGAL_BUBBLE_MESH_3_IO_INTERNAL_WRITE_ATOMICALLY_H

#include <CGAL/Bubble_mesh_3/Geological_model_error.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// Calls `write(os)` on `filename.tmp`, then renames it to `filename`: readers
// never see a half-written file under the final name. On any failure the
// temporary file is removed and a Geological_model_error says what failed.
template <class Write>
void write_atomically(const std::string& filename, Write write)
{
  const std::string tmp = filename + ".tmp";
  {
    std::ofstream os(tmp, std::ios::out | std::ios::binary | std::ios::trunc);
    if(!os)
      throw Geological_model_error("cannot open '" + tmp + "' for writing: " + std::string(std::strerror(errno)));
    try
    {
      write(os);
      os.flush();
      if(!os) throw Geological_model_error("writing '" + tmp + "' failed: " + std::string(std::strerror(errno)));
      os.close();
      if(os.fail()) throw Geological_model_error("closing '" + tmp + "' failed: " + std::string(std::strerror(errno)));
    }
    catch(...)
    {
      os.close();
      std::remove(tmp.c_str());
      throw;
    }
  }
  if(std::rename(tmp.c_str(), filename.c_str()) != 0)
  {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw Geological_model_error("cannot rename '" + tmp + "' to '" + filename + "': " + why);
  }
}

} // namespace internal
} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_INTERNAL_WRITE_ATOMICALLY_H
