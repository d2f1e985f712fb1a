// rupture/input/text_limits.cpp
#include "input/text_limits.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "input/names.hpp"

namespace rupture {

void check_toml_limits(const std::string& text, const std::string& origin) {
  if (text.size() > kMaxCaseBytes)
    throw InputError(fmt::format("{}: {} bytes of TOML; at most {} MiB are read", printable(origin),
                                 text.size(), kMaxCaseBytes >> 20));
  int depth = 0, dots = 0;
  bool in_key = true;  // after a line start, '{' , ',' or '[', before the next '='
  long line = 1;
  const std::size_t n = text.size();
  auto at = [&](std::size_t i) { return i < n ? text[i] : '\0'; };
  for (std::size_t i = 0; i < n; ++i) {
    const char ch = text[i];
    if (ch == '\n') {
      ++line;
      in_key = true, dots = 0;
    } else if (ch == '#') {  // a comment runs to the end of the line
      while (i + 1 < n && text[i + 1] != '\n') ++i;
    } else if (ch == '"' || ch == '\'') {
      const bool multi = at(i + 1) == ch && at(i + 2) == ch;
      const bool escapes = ch == '"';
      i += multi ? 3 : 1;
      for (; i < n; ++i) {
        if (text[i] == '\n') ++line;
        if (escapes && text[i] == '\\') {
          ++i;
          if (at(i) == '\n') ++line;
          continue;
        }
        if (text[i] != ch) continue;
        if (!multi) break;
        if (at(i + 1) == ch && at(i + 2) == ch) {
          i += 2;
          while (at(i + 1) == ch) ++i;  // up to two quotes may end the string's content
          break;
        }
      }
    } else if (ch == '[' || ch == '{') {
      if (++depth > kMaxTomlNesting)
        throw InputError(fmt::format("{}:{}: arrays and tables nested more than {} deep", printable(origin),
                                     line, kMaxTomlNesting));
      in_key = true, dots = 0;
    } else if (ch == ']' || ch == '}') {
      --depth;
    } else if (ch == ',') {
      in_key = true, dots = 0;
    } else if (ch == '=') {
      in_key = false;
    } else if (ch == '.' && in_key && ++dots >= kMaxKeyParts) {
      throw InputError(fmt::format("{}:{}: a key of more than {} dotted parts", printable(origin), line,
                                   kMaxKeyParts));
    }
  }
}

std::string read_bounded_file(const std::string& path, std::size_t max_bytes, const std::string& what) {
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(fmt::format("cannot read {} '{}': {}", what, printable(path), std::strerror(errno)));
  if (!S_ISREG(st.st_mode))
    throw InputError(fmt::format("{} '{}' is not a regular file (a directory, FIFO, socket or device); "
                                 "give the path of a file",
                                 what, printable(path)));
  if (std::size_t(st.st_size) > max_bytes)
    throw InputError(fmt::format("{} '{}' holds {} bytes; at most {} MiB are read", what, printable(path),
                                 std::size_t(st.st_size), max_bytes >> 20));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("cannot read {} '{}'", what, printable(path)));
  std::string out(std::size_t(st.st_size), '\0');
  in.read(out.data(), std::streamsize(out.size()));
  out.resize(std::size_t(in.gcount()));
  return out;
}

}  // namespace rupture
