// rupture/input/names.cpp
#include "input/names.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"

namespace rupture {

bool valid_name(const std::string& name) {
  if (name.empty() || name.size() > kMaxNameLength) return false;
  for (const char ch : name) {
    const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                    ch == '_' || ch == '-';
    if (!ok) return false;
  }
  return true;
}

void check_name(const std::string& key, const std::string& name) {
  if (valid_name(name)) return;
  std::string why;
  if (name.empty()) {
    why = "is empty";
  } else if (name.size() > kMaxNameLength) {
    why = fmt::format("is {} characters long", name.size());
  } else {
    for (const char ch : name)
      if (!valid_name(std::string(1, ch))) {
        why = fmt::format("holds '{}'", printable(std::string(1, ch)));
        break;
      }
  }
  throw InputError(fmt::format("input key '{}' = \"{}\": the name {}; {}", key,
                               printable(name), why, kNameRule));
}

std::string printable(const std::string& text) {
  constexpr std::size_t kMost = 200;
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (out.size() >= kMost) {
      out += "...";
      break;
    }
    const auto ch = static_cast<unsigned char>(text[i]);
    if (ch < 0x20 || ch >= 0x7f || ch == '"' || ch == '\\')
      out += fmt::format("\\x{:02x}", unsigned(ch));
    else
      out += char(ch);
  }
  return out;
}

}  // namespace rupture
