// Copyright (c) 2026 Bubble_mesh_3 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Bubble_mesh_3 team

#ifndef CGAL_BUBBLE_MESH_3_IO_INTERNAL_LINE_READER_H
#define CGAL_BUBBLE_MESH_3_IO_INTERNAL_LINE_READER_H

#include <CGAL/Bubble_mesh_3/Geological_model_error.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <istream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Bubble_mesh_3 {
namespace IO {
namespace internal {

// a token as it may appear in a message: short, printable
inline std::string quoted(std::string_view s, std::size_t max_length = 40)
{
  std::string r = "'";
  for(std::size_t i = 0; i < s.size() && i < max_length; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if(c >= 32 && c < 127) r += char(c);
    else
    {
      static const char* hex = "0123456789abcdef";
      r += "\\x";
      r += hex[c >> 4];
      r += hex[c & 15];
    }
  }
  if(s.size() > max_length) r += "...";
  return r + "'";
}

inline std::string point_text(double x, double y, double z)
{
  std::ostringstream s;
  s << std::setprecision(17) << "(" << x << " " << y << " " << z << ")";
  return s.str();
}

// `a` and `b` equal but for case: object types are spelled `TSurf` or `Tsurf` by different writers
inline bool equal_ignoring_case(std::string_view a, std::string_view b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

inline std::string trim(std::string_view s)
{
  const char* ws = " \t\r\n\v\f";
  const std::size_t b = s.find_first_not_of(ws);
  if(b == std::string_view::npos) return std::string();
  const std::size_t e = s.find_last_not_of(ws);
  return std::string(s.substr(b, e - b + 1));
}

// Reads a text file line by line, splits lines into whitespace-separated
// tokens, and turns every parse failure into a Geological_model_error that
// names the file and line.
class Line_reader
{
public:
  Line_reader(std::istream& is, const std::string& name) : is_(is), name_(name) {}

  // next line (comments are the caller's business); false at the end of input
  bool next()
  {
    if(!std::getline(is_, line_))
    {
      if(is_.bad()) error_here("read error");
      return false;
    }
    ++line_number_;
    if(!line_.empty() && line_.back() == '\r') line_.pop_back();
    // the byte order mark Windows editors put at the start of UTF-8 files
    if(line_number_ == 1 && line_.compare(0, 3, "\xEF\xBB\xBF") == 0) line_.erase(0, 3);
    if(line_.find('\0') != std::string::npos)
      error_here("binary data (a NUL byte) in a text file");
    tokens_.clear();
    const char* ws = " \t\r\v\f";
    std::size_t i = 0;
    while(true)
    {
      i = line_.find_first_not_of(ws, i);
      if(i == std::string::npos) break;
      std::size_t j = line_.find_first_of(ws, i);
      if(j == std::string::npos) j = line_.size();
      tokens_.emplace_back(line_.data() + i, j - i);
      i = j;
    }
    return true;
  }

  const std::string& line() const { return line_; }
  std::size_t line_number() const { return line_number_; }
  const std::string& name() const { return name_; }
  const std::vector<std::string_view>& tokens() const { return tokens_; }
  std::size_t size() const { return tokens_.size(); }
  std::string_view operator[](std::size_t i) const { return tokens_[i]; }
  bool empty() const { return tokens_.empty(); }

  // the text after the first `n` tokens, trimmed (names may contain spaces)
  std::string rest_after(std::size_t n) const
  {
    if(n >= tokens_.size()) return std::string();
    const std::size_t start = static_cast<std::size_t>(tokens_[n].data() - line_.data());
    return trim(std::string_view(line_).substr(start));
  }

  std::string where() const { return where(line_number_); }
  std::string where(std::size_t line) const
  {
    return name_ + ":" + std::to_string(line) + ": ";
  }

  [[noreturn]] void error_here(const std::string& what) const
  {
    throw Geological_model_error(where() + what);
  }

  // token i as a finite double; `what` names the value in messages
  double to_double(std::size_t i, const std::string& what) const
  {
    if(i >= tokens_.size()) error_here("missing " + what);
    std::string_view t = tokens_[i];
    if(!t.empty() && t[0] == '+') t.remove_prefix(1);
    double v = 0;
    const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if(res.ec == std::errc::result_out_of_range)
      error_here(what + " " + quoted(tokens_[i]) + " is out of the range of double");
    if(res.ec != std::errc() || res.ptr != t.data() + t.size())
      error_here(what + " " + quoted(tokens_[i]) + " is not a number");
    if(!std::isfinite(v))
      error_here(what + " is " + quoted(tokens_[i]) + ", not a finite number");
    return v;
  }

  // token i (or a given piece of text) as an integer; `what` names the value in messages
  long long to_integer(std::size_t i, const std::string& what) const
  {
    if(i >= tokens_.size()) error_here("missing " + what);
    return to_integer(tokens_[i], what);
  }
  long long to_integer(std::string_view t0, const std::string& what) const
  {
    std::string_view t = t0;
    if(!t.empty() && t[0] == '+') t.remove_prefix(1);
    long long v = 0;
    const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if(res.ec == std::errc::result_out_of_range)
      error_here(what + " " + quoted(t0) + " is out of range");
    if(res.ec != std::errc() || res.ptr != t.data() + t.size())
      error_here(what + " " + quoted(t0) + " is not an integer");
    return v;
  }

private:
  std::istream& is_;
  std::string name_;
  std::string line_;
  std::size_t line_number_ = 0;
  std::vector<std::string_view> tokens_;
};

// the last part of a path: the file name without its folders
inline std::string file_name_part(const std::string& path)
{
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// the extension of a file name, lower case and without the dot ("" when its last part has none)
inline std::string file_extension(const std::string& filename)
{
  const std::string base = file_name_part(filename);
  const std::size_t dot = base.find_last_of('.');
  std::string ext = dot == std::string::npos ? std::string() : base.substr(dot + 1);
  for(char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// opens `filename` for reading or throws a message that names it and says why
inline void open_for_reading(std::ifstream& is, const std::string& filename)
{
  is.open(filename, std::ios::in | std::ios::binary);
  if(!is)
    throw Geological_model_error("cannot open '" + filename + "' for reading: " +
                                 std::string(std::strerror(errno)));
}

} // namespace internal
} // namespace IO
} // namespace Bubble_mesh_3
} // namespace CGAL

#endif // CGAL_BUBBLE_MESH_3_IO_INTERNAL_LINE_READER_H
