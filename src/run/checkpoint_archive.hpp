// rupture/run/checkpoint_archive.hpp
// Internal to run/checkpoint.cpp: the archive a checkpoint is written and read with. Named,
// typed entries (name, kind, element type and size, count, bytes) in native byte order after
// a magic, the format version and a byte-order mark, and an FNV-1a checksum of everything
// before it. Writer and Reader walk the same `fields` lists (run/checkpoint.cpp: found by
// argument-dependent lookup in this namespace); the Reader checks the encoding of every entry
// (run/checkpoint_checks.hpp checks what it decodes to).
#pragma once
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "core/errors.hpp"
#include "run/checkpoint.hpp"

namespace rupture::checkpoint_detail {

constexpr char kMagic[8] = {'R', 'U', 'P', 'T', 'C', 'K', 'P', 'T'};
constexpr std::uint32_t kByteOrderMark = 0x01020304u;

// ---- The archive: named, typed entries ----

template <class T>
struct is_vector : std::false_type {};
template <class T>
struct is_vector<std::vector<T>> : std::true_type {};

template <class T>
constexpr char type_code() {
  if constexpr (std::is_enum_v<T>)
    return type_code<std::underlying_type_t<T>>();
  else if constexpr (std::is_same_v<T, bool>)
    return 'b';
  else if constexpr (std::is_floating_point_v<T>)
    return 'f';
  else if constexpr (std::is_signed_v<T>)
    return 'i';
  else
    return 'u';
}
template <class T>
constexpr bool is_plain = std::is_arithmetic_v<T> || std::is_enum_v<T>;

// Entry kinds: scalar, vector of scalars, text, list (of texts or groups), group (a struct).
enum Kind : char { kScalar = 's', kVector = 'v', kText = 't', kList = 'l', kGroup = 'g' };

std::uint64_t fnv1a(const char* p, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t k = 0; k < n; ++k) h = (h ^ std::uint8_t(p[k])) * 1099511628211ull;
  return h;
}

class Writer {
 public:
  static constexpr bool reading = false;
  std::string out;

  Writer() {
    out.append(kMagic, sizeof kMagic);
    pod(std::uint32_t(kCheckpointVersion));
    pod(kByteOrderMark);
  }
  std::string finish() {
    pod(fnv1a(out.data(), out.size()));
    return std::move(out);
  }
  // A value that is not restored but must agree (sizes derived from the case).
  template <class T>
  void same(const char* name, T value) {
    (*this)(name, value);
  }

  template <class T>
  void operator()(const char* name, const T& v) {
    if constexpr (is_plain<T>) {
      header(name, kScalar, type_code<T>(), sizeof(T), 1);
      raw(&v, sizeof v);
    } else if constexpr (std::is_same_v<T, std::string>) {
      header(name, kText, 'u', 1, v.size());
      raw(v.data(), v.size());
    } else if constexpr (is_vector<T>::value) {
      using E = typename T::value_type;
      static_assert(!std::is_same_v<E, bool>, "std::vector<bool> has no data(): use uint8_t");
      if constexpr (is_plain<E>) {
        header(name, kVector, type_code<E>(), sizeof(E), v.size());
        raw(v.data(), v.size() * sizeof(E));
      } else {
        header(name, kList, std::is_same_v<E, std::string> ? 't' : 'g', 0, v.size());
        for (const E& e : v) (*this)("item", e);
      }
    } else {
      header(name, kGroup, 'g', 0, 0);
      fields(*this, const_cast<T&>(v));  // the list is shared with Reader; nothing is changed
    }
  }

 private:
  void raw(const void* p, std::size_t n) {
    if (n > 0) out.append(static_cast<const char*>(p), n);  // an empty vector's data() may be null
  }
  template <class T>
  void pod(const T& v) {
    raw(&v, sizeof v);
  }
  void header(const char* name, char kind, char type, std::size_t size, std::uint64_t count) {
    const auto len = std::uint32_t(std::strlen(name));
    pod(len);
    raw(name, len);
    pod(kind);
    pod(type);
    pod(std::uint8_t(size));
    pod(count);
  }
};

// Enums stored as their underlying integer: every one read must be one of its values.
constexpr bool valid_enum(Scheme v) { return v == Scheme::USF || v == Scheme::USL || v == Scheme::MUSL; }

// The entries that may hold +infinity (a step limit without interfaces); every other floating
// point number a checkpoint holds is finite.
bool may_be_infinite(const char* name) {
  return std::strcmp(name, "cohesive_dt") == 0 || std::strcmp(name, "min_cohesive_dt") == 0;
}

// The bytes an entry's header takes with the name "item" (a list's items): length, name, kind,
// type, size, count.
constexpr std::size_t kItemHeaderBytes = sizeof(std::uint32_t) + 4 + 3 + sizeof(std::uint64_t);

// Items whose entries are all unconditional: each takes at least what a default one takes.
template <class E>
constexpr bool fixed_entries = std::is_same_v<E, EnergySample> || std::is_same_v<E, CrackSample> ||
                               std::is_same_v<E, MachReading> || std::is_same_v<E, StationSeries> ||
                               std::is_same_v<E, NodeBC>;

// The fewest bytes one item of a list of E takes, so that a list's count can be bounded by the
// bytes left before anything is allocated.
template <class E>
std::size_t min_item_bytes() {
  if constexpr (fixed_entries<E>) {
    static const std::size_t n = [] {
      Writer w;
      const std::size_t before = w.out.size();
      w("item", E{});
      return w.out.size() - before;
    }();
    return n;
  } else {
    return kItemHeaderBytes;
  }
}

class Reader {
 public:
  static constexpr bool reading = true;

  Reader(const std::string& bytes, std::string origin) : origin_(std::move(origin)) {
    const std::size_t head = sizeof kMagic + 2 * sizeof(std::uint32_t);
    if (bytes.size() < head + sizeof(std::uint64_t) ||
        std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
      throw InputError(fmt::format("'{}' is not a rupture checkpoint", origin_));
    std::uint32_t version = 0, mark = 0;
    std::memcpy(&version, bytes.data() + sizeof kMagic, sizeof version);
    std::memcpy(&mark, bytes.data() + sizeof kMagic + sizeof version, sizeof mark);
    if (mark != kByteOrderMark)
      throw InputError(
          fmt::format("checkpoint '{}' was written on a machine of another byte order", origin_));
    if (version != std::uint32_t(kCheckpointVersion))
      throw InputError(
          fmt::format("checkpoint '{}' has format version {}; this rupture reads "
                      "version {}",
                      origin_, version, kCheckpointVersion));
    const std::size_t body = bytes.size() - sizeof(std::uint64_t);
    std::uint64_t sum = 0;
    std::memcpy(&sum, bytes.data() + body, sizeof sum);
    if (sum != fnv1a(bytes.data(), body))
      throw InputError(
          fmt::format("checkpoint '{}' is truncated or corrupt (checksum mismatch, "
                      "{} bytes)",
                      origin_, bytes.size()));
    p_ = bytes.data() + head;
    left_ = body - head;
  }
  bool at_end() const { return left_ == 0; }
  const std::string& origin() const { return origin_; }

  template <class T>
  void same(const char* name, T expected) {
    T stored{};
    (*this)(name, stored);
    if (stored != expected)
      throw InputError(
          fmt::format("checkpoint '{}' does not belong to this case: {} = {} there, "
                      "{} here",
                      origin_, where(name), stored, expected));
  }

  template <class T>
  void operator()(const char* name, T& v) {
    path_.push_back({name, -1});
    value(name, v);
    path_.pop_back();
  }

 private:
  // The entry being read, for messages: its names from the top, list items by index.
  struct Frame {
    const char* name;
    std::int64_t index;  // -1: not a list item
  };
  std::string where(const char* last = nullptr) const {
    std::string w;
    for (const Frame& f : path_) {
      if (!w.empty()) w += '.';
      w += f.name;
      if (f.index >= 0) w += fmt::format("[{}]", f.index);
    }
    if (last) w += (w.empty() ? "" : ".") + std::string(last);
    return w;
  }
  [[noreturn]] void refuse(const std::string& value, const std::string& allowed, std::int64_t index = -1) const {
    throw InputError(fmt::format("checkpoint '{}': {}{} = {}: {}", origin_, where(),
                                 index >= 0 ? fmt::format("[{}]", index) : std::string(), value, allowed));
  }
  template <class E>
  void check_finite(const char* name, const E* v, std::size_t n, bool indexed) const {
    if constexpr (std::is_floating_point_v<E>) {
      const bool inf_ok = may_be_infinite(name);
      for (std::size_t k = 0; k < n; ++k)
        if (!std::isfinite(v[k]) && !(inf_ok && v[k] > 0))
          refuse(fmt::format("{}", v[k]), inf_ok ? "must be finite or +inf" : "must be finite",
                 indexed ? std::int64_t(k) : -1);
    }
  }

  template <class T>
  void value(const char* name, T& v) {
    if constexpr (std::is_same_v<T, bool>) {  // stored as one byte: 0 or 1, anything else is UB
      expect(name, kScalar, 'b', sizeof(bool));
      const auto b = pod<std::uint8_t>();
      if (b > 1) refuse(std::to_string(int(b)), "must be 0 or 1 (a bool)");
      v = b == 1;
    } else if constexpr (std::is_enum_v<T>) {
      using U = std::underlying_type_t<T>;
      expect(name, kScalar, type_code<T>(), sizeof(T));
      const U u = pod<U>();
      if (!valid_enum(T(u))) refuse(std::to_string(u), "is not one of the enum's values");
      v = T(u);
    } else if constexpr (is_plain<T>) {
      expect(name, kScalar, type_code<T>(), sizeof(T));
      raw(&v, sizeof v);
      check_finite(name, &v, 1, false);
    } else if constexpr (std::is_same_v<T, std::string>) {
      const std::uint64_t n = expect(name, kText, 'u', 1);
      need(n);
      v.assign(p_, std::size_t(n));
      p_ += n, left_ -= std::size_t(n);
    } else if constexpr (is_vector<T>::value) {
      using E = typename T::value_type;
      if constexpr (is_plain<E>) {
        static_assert(!std::is_enum_v<E> && !std::is_same_v<E, bool>, "vectors of enums or bools: check each value");
        const std::uint64_t n = expect(name, kVector, type_code<E>(), sizeof(E));
        if (n > left_ / sizeof(E))  // n * sizeof(E) could wrap
          throw InputError(fmt::format("checkpoint '{}' is truncated: {} holds {} values of {} bytes, {} bytes left",
                                       origin_, where(), n, sizeof(E), left_));
        v.resize(std::size_t(n));
        raw(v.data(), std::size_t(n) * sizeof(E));
        check_finite(name, v.data(), v.size(), true);
      } else {
        const std::uint64_t n = expect(name, kList, std::is_same_v<E, std::string> ? 't' : 'g', 0);
        const std::size_t least = min_item_bytes<E>();
        if (n > left_ / least)
          throw InputError(fmt::format("checkpoint '{}' is truncated: {} holds {} items of at least {} bytes, {} bytes left",
                                       origin_, where(), n, least, left_));
        // Existing items keep what is not stored (CohesiveInterface::spec); new ones are added
        // as they are read, so memory grows with the bytes actually there.
        for (std::size_t k = 0; k < std::size_t(n); ++k) {
          if (k == v.size()) v.emplace_back();
          path_.back().index = std::int64_t(k);
          value("item", v[k]);
        }
        path_.back().index = -1;
        v.resize(std::size_t(n));
      }
    } else {
      expect(name, kGroup, 'g', 0);
      fields(*this, v);
    }
  }

  void need(std::uint64_t n) const {
    if (n > left_)
      throw InputError(fmt::format("checkpoint '{}' is truncated ({}: an entry of {} bytes, {} left)",
                                   origin_, where(), n, left_));
  }
  void raw(void* dst, std::size_t n) {
    need(n);
    if (n > 0) std::memcpy(dst, p_, n);  // an empty vector's data() may be null
    p_ += n, left_ -= n;
  }
  template <class T>
  T pod() {
    T v{};
    raw(&v, sizeof v);
    return v;
  }
  std::uint64_t expect(const char* name, char kind, char type, std::size_t size) {
    const auto len = pod<std::uint32_t>();
    need(len);
    const std::string found(p_, len);
    p_ += len, left_ -= len;
    const char k = pod<char>(), t = pod<char>();
    const auto s = pod<std::uint8_t>();
    const auto count = pod<std::uint64_t>();
    if (found != name || k != kind || t != type || s != size)
      throw InputError(
          fmt::format("checkpoint '{}' does not match this version of rupture: expected entry '{}' "
                      "({}{}{}), found '{}' ({}{}{})",
                      origin_, where(), kind, type, size, found.substr(0, 64), k, t, int(s)));
    return count;
  }
  std::string origin_;
  const char* p_ = nullptr;
  std::size_t left_ = 0;
  std::vector<Frame> path_;
};

}  // namespace rupture::checkpoint_detail
