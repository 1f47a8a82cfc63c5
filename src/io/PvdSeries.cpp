#include "io/PvdSeries.hpp"

#include "core/Error.hpp"
#include "io/AtomicFile.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

namespace poro {

namespace fs = std::filesystem;

namespace {

/// %.17g without the locale: enough digits that reading the value back gives the same double.
std::string formatTime(double time) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, time, std::chars_format::general, 17);
  return std::string(buffer, result.ptr);
}

std::string escapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&apos;"; break;
    default: out += c;
    }
  }
  return out;
}

std::string unescapeXml(const std::string& text) {
  static const std::pair<const char*, char> entities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    bool replaced = false;
    if (text[i] == '&') {
      for (const auto& [entity, c] : entities) {
        if (text.compare(i, std::strlen(entity), entity) == 0) {
          out += c;
          i += std::strlen(entity);
          replaced = true;
          break;
        }
      }
    }
    if (!replaced) out += text[i++];
  }
  return out;
}

/// The first path component of a relative file path: its time directory.
std::string timeDirectory(const std::string& file) {
  const fs::path path(file);
  return path.begin() == path.end() ? std::string() : path.begin()->string();
}

/// Attributes of one element tag `<Name a="1" b='2'/>`; throws a plain message on malformed syntax.
std::map<std::string, std::string> parseAttributes(const std::string& tag) {
  std::map<std::string, std::string> attributes;
  std::size_t i = tag.find_first_of(" \t\r\n");
  while (i < tag.size()) {
    i = tag.find_first_not_of(" \t\r\n", i);
    if (i == std::string::npos || tag[i] == '/' || tag[i] == '>') break;
    const std::size_t equals = tag.find('=', i);
    if (equals == std::string::npos) throw std::runtime_error("attribute without value");
    std::string key = tag.substr(i, equals - i);
    key.erase(key.find_last_not_of(" \t\r\n") + 1);
    const std::size_t open = tag.find_first_not_of(" \t\r\n", equals + 1);
    if (open == std::string::npos || (tag[open] != '"' && tag[open] != '\''))
      throw std::runtime_error("attribute '" + key + "' is not quoted");
    const std::size_t close = tag.find(tag[open], open + 1);
    if (close == std::string::npos) throw std::runtime_error("attribute '" + key + "' is not closed");
    attributes[key] = unescapeXml(tag.substr(open + 1, close - open - 1));
    i = close + 1;
  }
  return attributes;
}

} // namespace

void PvdSeries::add(double time, const std::string& part, const std::string& file) {
  for (auto& entry : entries_) {
    if (entry.time == time && entry.part == part) {
      entry.file = file;
      return;
    }
  }
  entries_.push_back({time, part, file});
}

void PvdSeries::removeTimesAfter(double time) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.time > time; }),
                 entries_.end());
}

void PvdSeries::removeTime(double time) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.time == time; }),
                 entries_.end());
}

void PvdSeries::removeTime(const std::string& timeName) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const Entry& e) { return timeDirectory(e.file) == timeName; }),
                 entries_.end());
}

void PvdSeries::removeMissingFiles(double time, const fs::path& baseDir) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const Entry& e) {
                                  std::error_code ec;
                                  return e.time == time && !fs::exists(baseDir / e.file, ec);
                                }),
                 entries_.end());
}

void PvdSeries::write(const fs::path& path) const {
  // Parts in order of first appearance (their pvd part index) and, per part, its entries by time: a static
  // part shows its one file at every later time.
  std::vector<std::string> parts;
  std::vector<double> times; // in order of first appearance
  std::map<std::string, std::map<double, std::string>> filesOf;
  for (const auto& entry : entries_) {
    if (std::find(parts.begin(), parts.end(), entry.part) == parts.end()) parts.push_back(entry.part);
    if (std::find(times.begin(), times.end(), entry.time) == times.end()) times.push_back(entry.time);
    filesOf[entry.part][entry.time] = entry.file;
  }
  // Walls are written where they change: static ones once, moving ones at every time. A time without a walls file
  // shows the latest one before it: the static walls of 0/ also at the times before a later time that holds them
  // (a case reconstructed from subdomains decomposed at that time). Any other part, such as a surface fluidSurface
  // made at one time, belongs to its own times alone.
  const auto carriedForward = [&](const std::string& part) {
    return part == kStaticPart || part.rfind(std::string(kStaticPart) + ".", 0) == 0; // or a subdomain's
  };
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\">\n"
      << "  <Collection>\n";
  for (const double time : times)
    for (std::size_t index = 0; index < parts.size(); ++index) {
      const auto& files = filesOf[parts[index]];
      auto latest = files.upper_bound(time);
      if (latest == files.begin()) continue; // the part does not exist yet
      --latest;
      if (latest->first != time && !carriedForward(parts[index])) continue; // no file of this time
      out << "    <DataSet timestep=\"" << formatTime(time) << "\" group=\"\" part=\"" << index << "\" name=\""
          << escapeXml(parts[index]) << "\" file=\"" << escapeXml(latest->second) << "\"/>\n";
    }
  out << "  </Collection>\n"
      << "</VTKFile>\n";
  writeFileAtomically(path, out.str());
}

PvdSeries PvdSeries::read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open (" + std::strerror(errno) + ")");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();

  const auto lineOf = [&](std::size_t offset) {
    return 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n');
  };
  const auto fail = [&](std::size_t offset, const std::string& what) {
    throw InputError(path.string() + ":" + std::to_string(lineOf(offset)) + ": " + what);
  };

  const std::size_t root = text.find("<VTKFile");
  if (root == std::string::npos) fail(0, "not a ParaView collection (.pvd) file: no <VTKFile> element");
  const std::size_t rootEnd = text.find('>', root);
  if (rootEnd == std::string::npos) fail(root, "unterminated <VTKFile> element");
  std::map<std::string, std::string> rootAttributes;
  try {
    rootAttributes = parseAttributes(text.substr(root, rootEnd - root + 1));
  } catch (const std::runtime_error& e) {
    fail(root, std::string("malformed <VTKFile> element: ") + e.what());
  }
  if (const auto type = rootAttributes.find("type"); type == rootAttributes.end() || type->second != "Collection")
    fail(root, "not a ParaView collection (.pvd) file: VTKFile type is not \"Collection\"");

  PvdSeries series;
  for (std::size_t at = text.find("<DataSet", rootEnd); at != std::string::npos; at = text.find("<DataSet", at + 1)) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) fail(at, "unterminated <DataSet> element");
    std::map<std::string, std::string> attributes;
    try {
      attributes = parseAttributes(text.substr(at, end - at + 1));
    } catch (const std::runtime_error& e) {
      fail(at, std::string("malformed <DataSet> element: ") + e.what());
    }
    const auto timestep = attributes.find("timestep");
    const auto file = attributes.find("file");
    if (timestep == attributes.end()) fail(at, "<DataSet> without a timestep attribute");
    if (file == attributes.end() || file->second.empty()) fail(at, "<DataSet> without a file attribute");
    double time = 0.0;
    const std::string& value = timestep->second;
    const auto parsed = std::from_chars(value.data(), value.data() + value.size(), time);
    if (parsed.ec != std::errc() || parsed.ptr != value.data() + value.size())
      fail(at, "timestep \"" + value + "\" is not a number");
    const std::string part = fs::path(file->second).stem().string();
    // A file already listed for this part is write()'s repetition of a static set at a later time.
    const bool repeated = std::any_of(series.entries_.begin(), series.entries_.end(),
                                      [&](const Entry& e) { return e.part == part && e.file == file->second; });
    if (!repeated) series.entries_.push_back({time, part, file->second});
  }
  return series;
}

} // namespace poro
