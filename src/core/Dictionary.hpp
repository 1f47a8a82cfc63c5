#pragma once
/// Typed access to a YAML case dictionary (system/controlDict, constant/fluidProperties, ...).
/// Every error is an InputError whose message starts with `file:line:` and names the key, the value and
/// what was expected. Keys a reader asked for are remembered; checkUnknownKeys() reports any other key
/// with a "did you mean" hint. yaml-cpp stays behind this class (ARCHITECTURE.md).

#include "core/Types.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace poro {

/// Closed interval check for numbers; either end may be open or absent.
struct Range {
  std::optional<double> min, max;
  bool minOpen = false, maxOpen = false;

  static Range positive() { return {0.0, std::nullopt, true, false}; }           ///< (0, inf)
  static Range nonNegative() { return {0.0, std::nullopt, false, false}; }       ///< [0, inf)
  static Range closed(double a, double b) { return {a, b, false, false}; }       ///< [a, b]
  static Range open(double a, double b) { return {a, b, true, true}; }           ///< (a, b)
  static Range halfOpen(double a, double b) { return {a, b, false, true}; }      ///< [a, b)
  static Range atLeast(double a) { return {a, std::nullopt, false, false}; }     ///< [a, inf)
  static Range any() { return {}; }                                              ///< finite
  bool contains(double v) const;
  std::string describe() const;                                                   ///< "in (0, 1]", "> 0"
};

/// One YAML mapping (a whole file or a sub-dictionary) and the file it came from.
class Dictionary {
public:
  /// Reads and parses a YAML file whose top level must be a mapping. Missing or unreadable file (with the
  /// OS's reason, or the missing directory), bytes that are not UTF-8 text (binary files, with line and column),
  /// malformed YAML (with its line) and a non-mapping top level are InputErrors.
  static Dictionary read(const std::string& path);
  /// A dictionary every key of which has a default (system/solverDict): a missing file, an empty one and one of
  /// comments only are an empty mapping; otherwise as read().
  static Dictionary readOptional(const std::string& path);
  /// Parses YAML text as if it were the file `path` (tests, embedded defaults); with `emptyIsMapping`, text without
  /// a document (empty, or comments only) is an empty mapping rather than an InputError.
  static Dictionary parse(const std::string& text, const std::string& path, bool emptyIsMapping = false);

  Dictionary(Dictionary&&) noexcept;
  Dictionary& operator=(Dictionary&&) noexcept;
  Dictionary(const Dictionary&);
  Dictionary& operator=(const Dictionary&);
  ~Dictionary();

  const std::string& file() const;
  /// 1-based line of this mapping (of the key that opened it for sub-dictionaries).
  int line() const;
  /// "file:line" of a key if present, else of this mapping.
  std::string where(const std::string& key) const;

  bool has(const std::string& key) const;
  /// Keys present, in file order.
  std::vector<std::string> keys() const;

  /// The value of `key` in a canonical YAML flow form, to tell whether two files say the same: numbers in their
  /// shortest decimal form ("0.20" and "2e-1" are "0.2"), words plain, other scalars double-quoted, mappings with
  /// their keys sorted, so comments, layout, quoting and key order make no difference. "" when the key is absent. Does
  /// not count as reading the key (checkUnknownKeys).
  std::string canonical(const std::string& key) const;

  /// Required scalars. Wrong type, NaN/inf, out of range: InputError naming file, line, key and value.
  double getReal(const std::string& key, const Range& range = Range::any()) const;
  double getReal(const std::string& key, double fallback, const Range& range = Range::any()) const;
  long long getInt(const std::string& key, const Range& range = Range::any()) const;
  long long getInt(const std::string& key, long long fallback, const Range& range = Range::any()) const;
  bool getBool(const std::string& key) const;
  bool getBool(const std::string& key, bool fallback) const;
  std::string getString(const std::string& key) const;
  std::string getString(const std::string& key, const std::string& fallback) const;
  /// A string that must be one of `choices`.
  std::string getWord(const std::string& key, const std::vector<std::string>& choices) const;
  std::string getWord(const std::string& key, const std::vector<std::string>& choices,
                      const std::string& fallback) const;
  /// An optional sequence of words, each one of `choices` (empty when the key is absent).
  std::vector<std::string> getWordList(const std::string& key, const std::vector<std::string>& choices) const;
  /// A 3-vector written as a YAML sequence [x, y, z].
  Vec3 getVec3(const std::string& key) const;
  Vec3 getVec3(const std::string& key, const Vec3& fallback) const;
  /// An optional sequence of exactly `count` numbers in `range`, e.g. `range: [0, 1]` (`fallback` when absent).
  std::vector<double> getReals(const std::string& key, std::size_t count, const std::vector<double>& fallback,
                               const Range& range = Range::any()) const;

  /// Required / optional sub-mapping. Sub-dictionaries share the set of known keys with their parent
  /// path prefix ("pressure.maxIterations").
  Dictionary subDict(const std::string& key) const;
  std::optional<Dictionary> optionalSubDict(const std::string& key) const;
  /// An optional sub-mapping whose keys all have defaults: absent, it is empty. Reading it still makes its keys
  /// known, so that one given at the wrong level is pointed to its own ("did you mean 'pressure.wallContact'").
  Dictionary subDictOrEmpty(const std::string& key) const;
  /// A required sequence of mappings (e.g. particleDict regions).
  std::vector<Dictionary> getDictList(const std::string& key) const;

  /// Marks a key as known without reading it (keys read by other code paths).
  void markKnown(const std::string& key) const;
  /// Throws InputError for the first key present in this mapping that no getter asked for, with the
  /// closest known key as a hint ("did you mean 'endTime'?"). Does not recurse; call it on sub-dictionaries too.
  void checkUnknownKeys() const;

  /// An InputError for `key` with the standard prefix "file:line: key 'k': " + message.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  /// Edit distance used for the "did you mean" hint (exposed for tests).
  static std::size_t editDistance(const std::string& a, const std::string& b);

private:
  struct Impl;
  explicit Dictionary(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace poro
