#pragma once
// A small well-formedness check for the SVG the analysis writes: one root element, every tag closed in order,
// attributes quoted, and '&' only in entities. Enough to catch what a renderer would refuse. (No std::regex:
// GCC 12 warns inside it at -O1, which the sanitizer build uses.)

#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <vector>

namespace poro::test {

namespace xml {

inline bool nameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '.' || c == '-';
}
inline bool space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

/// Reads a name at `p`; empty if there is none.
inline std::string name(const std::string& text, std::size_t& p) {
  const std::size_t start = p;
  while (p < text.size() && nameChar(text[p])) ++p;
  return text.substr(start, p - start);
}

inline bool entityAt(const std::string& text, std::size_t at) {
  for (const char* e : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"})
    if (text.compare(at, std::char_traits<char>::length(e), e) == 0) return true;
  if (text.compare(at, 2, "&#") != 0) return false;
  std::size_t p = at + 2 + (text.compare(at, 3, "&#x") == 0 ? 1 : 0);
  const std::size_t digits = p;
  while (p < text.size() && std::isxdigit(static_cast<unsigned char>(text[p]))) ++p;
  return p > digits && p < text.size() && text[p] == ';';
}

} // namespace xml

inline ::testing::AssertionResult wellFormedXml(const std::string& text) {
  using ::testing::AssertionFailure;
  std::vector<std::string> open;
  int roots = 0;
  std::size_t p = 0;
  while (p < text.size()) {
    const char c = text[p];
    if (c == '&' && !xml::entityAt(text, p)) return AssertionFailure() << "bare '&' at " << p;
    if (c != '<') {
      if (open.empty() && !xml::space(c)) return AssertionFailure() << "text outside the root at " << p;
      ++p;
      continue;
    }
    if (text.compare(p, 2, "<?") == 0) { // the declaration, before the root
      const auto end = text.find("?>", p);
      if (end == std::string::npos || roots > 0) return AssertionFailure() << "bad declaration";
      p = end + 2;
      continue;
    }
    const std::size_t at = p++;
    const bool closing = p < text.size() && text[p] == '/';
    if (closing) ++p;
    const std::string tag = xml::name(text, p);
    if (tag.empty()) return AssertionFailure() << "tag without a name at " << at;
    bool selfClosing = false;
    for (;;) {
      const bool spaced = p < text.size() && xml::space(text[p]);
      while (p < text.size() && xml::space(text[p])) ++p;
      if (p >= text.size()) return AssertionFailure() << "<" << tag << " never ends";
      if (text[p] == '>') break;
      if (!closing && text.compare(p, 2, "/>") == 0) {
        selfClosing = true;
        ++p;
        break;
      }
      const std::string attribute = xml::name(text, p);
      if (closing || !spaced || attribute.empty() || text.compare(p, 2, "=\"") != 0)
        return AssertionFailure() << "malformed attribute in <" << tag << "> at " << p;
      const auto end = text.find('"', p + 2);
      if (end == std::string::npos || text.find('<', p + 2) < end)
        return AssertionFailure() << "unterminated value of " << attribute;
      for (std::size_t q = p + 2; q < end; ++q)
        if (text[q] == '&' && !xml::entityAt(text, q)) return AssertionFailure() << "bare '&' in " << attribute;
      p = end + 1;
    }
    ++p; // past '>'
    if (closing) {
      if (open.empty() || open.back() != tag)
        return AssertionFailure() << "</" << tag << "> closes " << (open.empty() ? "nothing" : open.back());
      open.pop_back();
    } else {
      if (open.empty() && ++roots > 1) return AssertionFailure() << "second root element <" << tag << ">";
      if (!selfClosing) open.push_back(tag);
    }
  }
  if (!open.empty()) return AssertionFailure() << "<" << open.back() << "> never closed";
  if (roots != 1) return AssertionFailure() << "no root element";
  return ::testing::AssertionSuccess();
}

inline std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
  return n;
}

} // namespace poro::test
