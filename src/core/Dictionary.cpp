#include "core/Dictionary.hpp"

#include "core/Error.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

namespace poro {

namespace {

// Shortest text that reads back as the same double: "0.1", not "0.10000000000000001"; "100", not "1e+02";
// whole numbers in plain digits ("1000000", not "1e+06"), as a user writes an iteration limit.
std::string formatNumber(double v) {
  char buf[32];
  const bool whole = v == std::floor(v) && std::fabs(v) < 1e10; // 1e+13 rather than 14 digits
  const auto end = whole ? std::to_chars(buf, buf + sizeof buf, static_cast<long long>(v)).ptr
                         : std::to_chars(buf, buf + sizeof buf, v).ptr;
  return std::string(buf, end);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string joined(const std::vector<std::string>& words, const char* separator) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : separator) + w;
  return out;
}

// YAML spells them .nan/.inf; strtod would also take nan/inf/infinity. All are rejected by name so the
// user reads "expected a finite number" instead of "expected a number".
bool isNonFiniteWord(const std::string& text) {
  std::string s = lower(text);
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.erase(0, 1);
  if (!s.empty() && s[0] == '.') s.erase(0, 1);
  return s == "nan" || s == "inf" || s == "infinity";
}

// Plain decimal grammar [+-]? (d+ (. d*)? | . d+) ([eE] [+-]? d+)?: strtod alone would accept hex,
// leading blanks and "nan", which are not numbers in a case file.
bool isDecimal(const std::string& s, bool& integral) {
  std::size_t i = 0, n = s.size();
  auto digits = [&] {
    const std::size_t start = i;
    while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i - start;
  };
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa = digits();
  integral = true;
  if (i < n && s[i] == '.') {
    ++i;
    mantissa += digits();
    integral = false;
  }
  if (mantissa == 0) return false;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return false;
    integral = false;
  }
  return i == n;
}

// YAML text is UTF-8 without control characters other than tab and line breaks (YAML 1.2 §5.1). A binary file
// (a .vtp or a core dump saved under a dictionary's name) would otherwise reach the user as yaml-cpp's
// "unknown escape character" or as a key made of raw bytes. Returns the message for the first offending
// byte ("line 3, column 7: byte 0x00"), or "".
std::string firstNonTextByte(const std::string& text) {
  int line = 1;
  std::size_t lineStart = 0;
  auto at = [&](std::size_t i, const std::string& what) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(text[i]));
    return std::to_string(line) + ": byte " + hex + " at column " + std::to_string(i - lineStart + 1) + " " + what;
  };
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++line;
      lineStart = ++i;
      continue;
    }
    if (c < 0x80) {
      if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7F) return at(i, "is a control character");
      ++i;
      continue;
    }
    // Length of a UTF-8 sequence from its lead byte; continuation bytes are 10xxxxxx.
    const std::size_t length = (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    bool valid = length > 0 && i + length <= text.size();
    for (std::size_t k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if (!valid) return at(i, "is not valid UTF-8");
    i += length;
  }
  return {};
}

std::string quoted(const std::string& s) {
  // A pasted paragraph would drown the message; 60 characters identify the value.
  return "'" + (s.size() > 60 ? s.substr(0, 57) + "..." : s) + "'";
}

// "got ..." part of a message: the scalar text, or what kind of node stood there.
std::string describeValue(const YAML::Node& v) {
  switch (v.Type()) {
  case YAML::NodeType::Scalar: return quoted(v.Scalar());
  case YAML::NodeType::Sequence:
    return "a sequence of " + std::to_string(v.size()) + (v.size() == 1 ? " element" : " elements");
  case YAML::NodeType::Map: return "a mapping";
  default: return "an empty value";
  }
}

// A value in canonical YAML flow form (Dictionary::canonical): numbers as formatNumber writes them, words plain,
// other scalars double-quoted with YAML escapes, sequences in order, mappings sorted by key. Reading the text back and
// canonicalising it again gives the same text.
std::string canonicalScalar(const std::string& s) {
  bool integral = false;
  if (isDecimal(s, integral)) {
    const double x = std::strtod(s.c_str(), nullptr);
    if (std::isfinite(x)) return formatNumber(x);
  }
  // Words stay plain (column, yMax, true, stone.stl): YAML reads them back as the same text. Anything else is
  // quoted, including the words YAML reads as null.
  const bool word = !s.empty() && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_') &&
                    std::all_of(s.begin(), s.end(), [](char c) {
                      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-';
                    });
  if (word && lower(s) != "null") return s;
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned char>(c));
      out += hex;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string canonicalNode(const YAML::Node& node) {
  switch (node.Type()) {
  case YAML::NodeType::Scalar: return canonicalScalar(node.Scalar());
  case YAML::NodeType::Sequence: {
    std::string out = "[";
    for (std::size_t i = 0; i < node.size(); ++i) out += (i ? ", " : "") + canonicalNode(node[i]);
    return out + "]";
  }
  case YAML::NodeType::Map: {
    std::vector<std::pair<std::string, std::string>> entries;
    for (const auto& kv : node) entries.emplace_back(canonicalNode(kv.first), canonicalNode(kv.second));
    std::sort(entries.begin(), entries.end());
    std::string out = "{";
    for (std::size_t i = 0; i < entries.size(); ++i)
      out += (i ? ", " : "") + entries[i].first + ": " + entries[i].second;
    return out + "}";
  }
  default: return "~";
  }
}

// (path prefix, key): a pair rather than the joined string, so a key that itself contains '.' cannot
// pose as a sub-dictionary entry.
using KnownKeys = std::set<std::pair<std::string, std::string>>;

} // namespace

// ---------------------------------------------------------------------------------------------------
// Range

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (min && (minOpen ? v <= *min : v < *min)) return false;
  if (max && (maxOpen ? v >= *max : v > *max)) return false;
  return true;
}

std::string Range::describe() const {
  if (min && max)
    return std::string("in ") + (minOpen ? "(" : "[") + formatNumber(*min) + ", " + formatNumber(*max) +
           (maxOpen ? ")" : "]");
  if (min) return (minOpen ? "> " : ">= ") + formatNumber(*min);
  if (max) return (maxOpen ? "< " : "<= ") + formatNumber(*max);
  return "finite";
}

// ---------------------------------------------------------------------------------------------------
// Impl: the mapping node, where it came from, and the known-key set shared by a whole file.

struct Dictionary::Impl {
  YAML::Node node; ///< always a mapping
  std::string file;
  std::string prefix;               ///< "" at top level, "pressure." or "regions[2]." below
  int line = 1;                     ///< 1-based
  std::shared_ptr<KnownKeys> known; ///< shared with every sub-dictionary of the same file

  struct Entry {
    YAML::Node key, value;
  };

  Impl(YAML::Node n, std::string f, std::string p, int l, std::shared_ptr<KnownKeys> k)
      : node(std::move(n)), file(std::move(f)), prefix(std::move(p)), line(l), known(std::move(k)) {
    checkKeys();
  }

  static int lineOf(const YAML::Node& n) { return std::max(n.Mark().line, 0) + 1; }
  std::string at(int l) const { return file + ":" + std::to_string(l) + ": "; }
  std::string path(const std::string& key) const { return prefix + key; }

  // Keys must be names and unique: yaml-cpp keeps both copies of a repeated key, and only the first
  // would be read — a silently ignored entry.
  void checkKeys() const {
    std::vector<std::pair<std::string, int>> seen;
    for (const auto& kv : node) {
      const int l = lineOf(kv.first);
      if (!kv.first.IsScalar())
        throw InputError(at(l) + "expected a key name, got " + describeValue(kv.first) + " as a key");
      const std::string& key = kv.first.Scalar();
      for (const auto& [name, first] : seen)
        if (name == key)
          throw InputError(at(l) + "duplicate key '" + path(key) + "' (first given at line " +
                           std::to_string(first) + ")");
      seen.emplace_back(key, l);
    }
  }

  // Linear search: dictionaries hold tens of keys, and iterating gives us the key node (its line).
  std::optional<Entry> find(const std::string& key) const {
    for (const auto& kv : node)
      if (kv.first.Scalar() == key) return Entry{kv.first, kv.second};
    return std::nullopt;
  }

  void markKnown(const std::string& key) const { known->emplace(prefix, key); }

  Entry require(const std::string& key) const {
    markKnown(key);
    if (auto e = find(key)) return *e;
    // A misspelt key is the likely cause: name it at its own line rather than report the key missing.
    for (const auto& kv : node) {
      const std::string& present = kv.first.Scalar();
      if (!known->count({prefix, present}) && closest(present, {key}) == key)
        throw InputError(at(lineOf(kv.first)) + "unknown key '" + path(present) + "'; did you mean '" + key + "'?");
    }
    throw InputError(at(line) + "missing required key '" + path(key) + "'");
  }

  std::optional<Entry> optional(const std::string& key) const {
    markKnown(key);
    return find(key);
  }

  [[noreturn]] void failValue(const Entry& e, const YAML::Node& value, const std::string& expected,
                              const std::string& hint = "") const {
    // A null value's mark points at the next token, often on a later line; the key is where it is.
    const int l = value.IsNull() ? lineOf(e.key) : lineOf(value);
    throw InputError(at(l) + "key '" + path(e.key.Scalar()) + "': expected " + expected + ", got " +
                     describeValue(value) + hint);
  }

  static std::string expectedNumber(const char* kind, const Range& r) {
    const bool any = !r.min && !r.max;
    return std::string(kind) + (any ? "" : " " + r.describe());
  }

  double toReal(const Entry& e, const YAML::Node& v, const Range& r, const std::string& what = "") const {
    bool integral = false;
    if (v.IsScalar() && isNonFiniteWord(v.Scalar()))
      failValue(e, v, expectedNumber("a finite number", r) + what);
    if (!v.IsScalar() || !isDecimal(v.Scalar(), integral))
      failValue(e, v, expectedNumber(r.min || r.max ? "a number" : "a finite number", r) + what);
    const double x = std::strtod(v.Scalar().c_str(), nullptr);
    if (!std::isfinite(x)) failValue(e, v, expectedNumber("a finite number", r) + what); // e.g. 1e400
    if (!r.contains(x)) failValue(e, v, expectedNumber("a number", r) + what);
    return x;
  }

  long long toInt(const Entry& e, const YAML::Node& v, const Range& r) const {
    const std::string expected = expectedNumber("an integer", r);
    bool integral = false;
    if (!v.IsScalar() || !isDecimal(v.Scalar(), integral)) failValue(e, v, expected);
    long long n = 0;
    if (integral) {
      errno = 0;
      n = std::strtoll(v.Scalar().c_str(), nullptr, 10);
      if (errno == ERANGE) failValue(e, v, expected + " that fits in 64 bits");
    } else {
      // "1e6" particles is a natural spelling; accept a real only if it is an exact integer.
      const double x = std::strtod(v.Scalar().c_str(), nullptr);
      if (!std::isfinite(x) || x != std::floor(x)) failValue(e, v, expected);
      if (std::fabs(x) > 9007199254740992.0) // beyond 2^53 a double no longer holds every integer
        failValue(e, v, expected + " (write it in plain digits above 2^53)");
      n = static_cast<long long>(x);
    }
    if (!r.contains(static_cast<double>(n))) failValue(e, v, expected);
    return n;
  }

  bool toBool(const Entry& e, const YAML::Node& v) const {
    const std::string s = v.IsScalar() ? lower(v.Scalar()) : "";
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
    failValue(e, v, "true or false");
  }

  std::string toString(const Entry& e, const YAML::Node& v) const {
    if (!v.IsScalar()) failValue(e, v, "a string");
    return v.Scalar();
  }

  std::string toWord(const Entry& e, const YAML::Node& v, const std::vector<std::string>& choices) const {
    const std::string expected = "one of " + joined(choices, ", ");
    if (!v.IsScalar()) failValue(e, v, expected);
    const std::string& s = v.Scalar();
    if (std::find(choices.begin(), choices.end(), s) != choices.end()) return s;
    const std::string best = closest(s, choices);
    failValue(e, v, expected, best.empty() ? "" : "; did you mean '" + best + "'?");
  }

  Vec3 toVec3(const Entry& e, const YAML::Node& v) const {
    if (!v.IsSequence() || v.size() != 3) failValue(e, v, "a sequence [x, y, z] of 3 finite numbers");
    Vec3 out;
    for (int i = 0; i < 3; ++i)
      out[i] = toReal(e, v[i], Range::any(), " as component " + std::to_string(i + 1) + " of [x, y, z]");
    return out;
  }

  Dictionary toDict(const YAML::Node& v, const std::string& name, int l) const {
    // A key whose sub-keys are all commented out ("pressure:" alone) holds no value: every sub-key at its default.
    if (v.IsNull())
      return Dictionary(std::make_unique<Impl>(YAML::Node(YAML::NodeType::Map), file, prefix + name + ".", l, known));
    if (!v.IsMap()) {
      throw InputError(at(lineOf(v)) + "key '" + prefix + name + "': expected a mapping of keys, got " +
                       describeValue(v));
    }
    return Dictionary(std::make_unique<Impl>(v, file, prefix + name + ".", l, known));
  }

  /// The candidate nearest to `word` if it is a plausible typo, else "". Letter case does not count, and a word
  /// that a single candidate holds in order with letters left out ("lattice" of "latticeCorrected") matches it.
  static std::string closest(const std::string& word, const std::vector<std::string>& candidates) {
    const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
    const std::string w = lower(word);
    std::string best;
    std::size_t bestDistance = limit + 1;
    for (const auto& c : candidates) {
      const std::size_t d = editDistance(w, lower(c));
      if (d < bestDistance) bestDistance = d, best = c;
    }
    if (!best.empty() || w.size() < 4) return best;
    std::vector<std::string> holding;
    for (const auto& c : candidates)
      if (isSubsequence(w, lower(c))) holding.push_back(c);
    return holding.size() == 1 ? holding.front() : "";
  }

  static bool isSubsequence(const std::string& part, const std::string& whole) {
    std::size_t i = 0;
    for (char c : whole)
      if (i < part.size() && part[i] == c) ++i;
    return i == part.size();
  }

  /// "the top level" or "'pressure'": the mapping a prefix names.
  static std::string levelOf(const std::string& p) {
    return p.empty() ? "the top level" : "'" + p.substr(0, p.size() - 1) + "'";
  }

  /// A key of this name (letter case aside) known at another level of the file, as "'pressure.wallContact', a key
  /// of 'pressure'", or "". Levels are known once read, so a level read later than this one is not found.
  std::string elsewhere(const std::string& key) const {
    for (const auto& [p, k] : *known)
      if (p != prefix && lower(k) == lower(key)) return "'" + p + k + "', a key of " + levelOf(p);
    return "";
  }

  /// Known keys directly in this mapping (not in its sub-dictionaries), sorted.
  std::vector<std::string> knownHere() const {
    std::vector<std::string> out;
    for (auto it = known->lower_bound({prefix, ""}); it != known->end() && it->first == prefix; ++it)
      out.push_back(it->second);
    return out;
  }
};

// ---------------------------------------------------------------------------------------------------
// Dictionary

Dictionary::Dictionary(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Dictionary::Dictionary(Dictionary&&) noexcept = default;
Dictionary& Dictionary::operator=(Dictionary&&) noexcept = default;
Dictionary::~Dictionary() = default;
Dictionary::Dictionary(const Dictionary& other)
    : impl_(other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr) {}

Dictionary& Dictionary::operator=(const Dictionary& other) {
  // Never `*impl_ = *other.impl_`: YAML::Node::operator= rebinds the shared node data, which would
  // change every other Dictionary viewing the same mapping. Copy-constructing a new Impl is safe.
  if (this != &other) impl_ = other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr;
  return *this;
}

namespace {
std::string readText(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": cannot open file (it is a directory)");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int error = errno; // before the filesystem calls below can change it
    // A missing system/ or constant/ is the likely cause: name the directory rather than only the file.
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
      throw InputError(path + ": cannot open file: there is no directory " + parent.string());
    throw InputError(path + ": cannot open file (" + std::strerror(error) + ")");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read file");
  return text.str();
}
} // namespace

Dictionary Dictionary::read(const std::string& path) { return parse(readText(path), path); }

Dictionary Dictionary::readOptional(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return parse("{}", path);
  return parse(readText(path), path, true);
}

Dictionary Dictionary::parse(const std::string& text, const std::string& path, bool emptyIsMapping) {
  if (const std::string bad = firstNonTextByte(text); !bad.empty())
    throw InputError(path + ":" + bad + "; expected a YAML text file (is this a binary file?)");
  std::vector<YAML::Node> docs;
  try {
    docs = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    // An unclosed bracket or quote is found at the end of the input, which yaml-cpp marks as the line after
    // the last one; name the last line and say why.
    const int lines =
        static_cast<int>(std::count(text.begin(), text.end(), '\n')) + (!text.empty() && text.back() != '\n' ? 1 : 0);
    const int line = std::max(e.mark.line, 0) + 1;
    const bool atEnd = line > lines || (e.mark.pos >= 0 && static_cast<std::size_t>(e.mark.pos) >= text.size());
    throw InputError(path + ":" + std::to_string(std::max(1, std::min(line, lines))) + ": malformed YAML" +
                     (atEnd ? " (at the end of the file)" : "") + ": " + e.msg);
  }
  // Only the first document would be read; a second one is almost surely a stray "---".
  for (std::size_t i = 1; i < docs.size(); ++i)
    if (!docs[i].IsNull())
      throw InputError(path + ":" + std::to_string(Impl::lineOf(docs[i])) +
                       ": expected a single YAML document, found a second one");
  if ((docs.empty() || docs[0].IsNull()) && emptyIsMapping) return parse("{}", path);
  if (docs.empty() || docs[0].IsNull())
    throw InputError(path + ":1: expected a YAML mapping of keys, but the file is empty");
  if (!docs[0].IsMap())
    throw InputError(path + ":" + std::to_string(Impl::lineOf(docs[0])) +
                     ": expected a YAML mapping of keys, got " + describeValue(docs[0]));
  return Dictionary(
      std::make_unique<Impl>(docs[0], path, "", Impl::lineOf(docs[0]), std::make_shared<KnownKeys>()));
}

const std::string& Dictionary::file() const { return impl_->file; }
int Dictionary::line() const { return impl_->line; }

std::string Dictionary::where(const std::string& key) const {
  const auto e = impl_->find(key);
  return impl_->file + ":" + std::to_string(e ? Impl::lineOf(e->key) : impl_->line);
}

bool Dictionary::has(const std::string& key) const { return impl_->find(key).has_value(); }

std::vector<std::string> Dictionary::keys() const {
  std::vector<std::string> out;
  for (const auto& kv : impl_->node) out.push_back(kv.first.Scalar());
  return out;
}

std::string Dictionary::canonical(const std::string& key) const {
  const auto e = impl_->find(key);
  return e ? canonicalNode(e->value) : std::string();
}

double Dictionary::getReal(const std::string& key, const Range& range) const {
  const auto e = impl_->require(key);
  return impl_->toReal(e, e.value, range);
}

double Dictionary::getReal(const std::string& key, double fallback, const Range& range) const {
  const auto e = impl_->optional(key);
  return e ? impl_->toReal(*e, e->value, range) : fallback;
}

long long Dictionary::getInt(const std::string& key, const Range& range) const {
  const auto e = impl_->require(key);
  return impl_->toInt(e, e.value, range);
}

long long Dictionary::getInt(const std::string& key, long long fallback, const Range& range) const {
  const auto e = impl_->optional(key);
  return e ? impl_->toInt(*e, e->value, range) : fallback;
}

bool Dictionary::getBool(const std::string& key) const {
  const auto e = impl_->require(key);
  return impl_->toBool(e, e.value);
}

bool Dictionary::getBool(const std::string& key, bool fallback) const {
  const auto e = impl_->optional(key);
  return e ? impl_->toBool(*e, e->value) : fallback;
}

std::string Dictionary::getString(const std::string& key) const {
  const auto e = impl_->require(key);
  return impl_->toString(e, e.value);
}

std::string Dictionary::getString(const std::string& key, const std::string& fallback) const {
  const auto e = impl_->optional(key);
  return e ? impl_->toString(*e, e->value) : fallback;
}

std::string Dictionary::getWord(const std::string& key, const std::vector<std::string>& choices) const {
  const auto e = impl_->require(key);
  return impl_->toWord(e, e.value, choices);
}

std::string Dictionary::getWord(const std::string& key, const std::vector<std::string>& choices,
                                const std::string& fallback) const {
  const auto e = impl_->optional(key);
  return e ? impl_->toWord(*e, e->value, choices) : fallback;
}

Vec3 Dictionary::getVec3(const std::string& key) const {
  const auto e = impl_->require(key);
  return impl_->toVec3(e, e.value);
}

Vec3 Dictionary::getVec3(const std::string& key, const Vec3& fallback) const {
  const auto e = impl_->optional(key);
  return e ? impl_->toVec3(*e, e->value) : fallback;
}

std::vector<double> Dictionary::getReals(const std::string& key, std::size_t count,
                                         const std::vector<double>& fallback, const Range& range) const {
  const auto e = impl_->optional(key);
  if (!e) return fallback;
  const std::string expected = "a sequence of " + std::to_string(count) + " numbers";
  if (!e->value.IsSequence() || e->value.size() != count) impl_->failValue(*e, e->value, expected);
  std::vector<double> out;
  for (std::size_t i = 0; i < count; ++i)
    out.push_back(impl_->toReal(*e, e->value[i], range, " as item " + std::to_string(i + 1) + " of " + expected));
  return out;
}

std::vector<std::string> Dictionary::getWordList(const std::string& key, const std::vector<std::string>& choices) const {
  const auto e = impl_->optional(key);
  std::vector<std::string> out;
  if (!e) return out;
  if (!e->value.IsSequence()) impl_->failValue(*e, e->value, "a sequence [a, b, ...]");
  for (std::size_t i = 0; i < e->value.size(); ++i) out.push_back(impl_->toWord(*e, e->value[i], choices));
  return out;
}

Dictionary Dictionary::subDict(const std::string& key) const {
  const auto e = impl_->require(key);
  return impl_->toDict(e.value, key, Impl::lineOf(e.key));
}

std::optional<Dictionary> Dictionary::optionalSubDict(const std::string& key) const {
  const auto e = impl_->optional(key);
  if (!e) return std::nullopt;
  return impl_->toDict(e->value, key, Impl::lineOf(e->key));
}

Dictionary Dictionary::subDictOrEmpty(const std::string& key) const {
  if (auto d = optionalSubDict(key)) return std::move(*d);
  return Dictionary(std::make_unique<Impl>(YAML::Node(YAML::NodeType::Map), impl_->file, impl_->prefix + key + ".",
                                           impl_->line, impl_->known));
}

std::vector<Dictionary> Dictionary::getDictList(const std::string& key) const {
  const auto e = impl_->require(key);
  if (!e.value.IsSequence()) impl_->failValue(e, e.value, "a sequence of mappings");
  std::vector<Dictionary> out;
  for (std::size_t i = 0; i < e.value.size(); ++i) {
    const YAML::Node item = e.value[i];
    out.push_back(impl_->toDict(item, key + "[" + std::to_string(i) + "]", Impl::lineOf(item)));
  }
  return out;
}

void Dictionary::markKnown(const std::string& key) const { impl_->markKnown(key); }

void Dictionary::checkUnknownKeys() const {
  for (const auto& kv : impl_->node) {
    const std::string& key = kv.first.Scalar();
    if (impl_->known->count({impl_->prefix, key})) continue;
    const auto candidates = impl_->knownHere();
    const std::string best = Impl::closest(key, candidates);
    const std::string other = impl_->elsewhere(key);
    std::string message = "unknown key '" + impl_->path(key) + "'";
    if (!best.empty())
      message += "; did you mean '" + best + "'?";
    else if (!other.empty())
      message += "; did you mean " + other + "?";
    else if (!candidates.empty())
      message += "; expected one of: " + joined(candidates, ", ");
    else
      message += "; no keys are expected here";
    throw InputError(impl_->at(Impl::lineOf(kv.first)) + message);
  }
}

void Dictionary::fail(const std::string& key, const std::string& message) const {
  throw InputError(where(key) + ": key '" + impl_->path(key) + "': " + message);
}

std::size_t Dictionary::editDistance(const std::string& a, const std::string& b) {
  // Levenshtein with two rows: row[j] = distance between a[0, i) and b[0, j).
  std::vector<std::size_t> prev(b.size() + 1), row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      row[j] = std::min({prev[j] + 1, row[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, row);
  }
  return prev[b.size()];
}

} // namespace poro
