#include "io/SamplingRecord.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <utility>

namespace poro {

namespace fs = std::filesystem;

namespace {

const char* const kMotion = "motion";         ///< the one key of a region poroSph reads at run time
const char* const kFileDigest = "fileDigest"; ///< the record's own key: the digest of a surface region's file
const char* const kFix = "run sampleParticles again (it rewrites 0/) and start from 0";

/// "fnv1a64-<16 hex digits>" (a word, which Dictionary::canonical gives back as it is) of the file's bytes (FNV-1a, 64
/// bits: a change detector, not a cryptographic hash), or nothing when the file cannot be read.
std::optional<std::string> fileDigest(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::uint64_t hash = 14695981039346656037ULL;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash ^= static_cast<unsigned char>(buffer[i]);
      hash *= 1099511628211ULL;
    }
    if (!in) break;
  }
  char text[32];
  std::snprintf(text, sizeof text, "fnv1a64-%016llx", static_cast<unsigned long long>(hash));
  return std::string(text);
}

/// A region as the record holds it: (key, canonical value) in the region's key order, `motion` left out, and the
/// digest of a surface region's file (when it can be read).
using Entries = std::vector<std::pair<std::string, std::string>>;

Entries entriesOf(const Dictionary& region, const fs::path& surfaceDirectory) {
  Entries entries;
  for (const std::string& key : region.keys())
    if (key != kMotion) entries.emplace_back(key, region.canonical(key));
  if (region.has("file"))
    if (const auto digest = fileDigest(surfaceDirectory / region.getString("file")))
      entries.emplace_back(kFileDigest, *digest); // a word: as Dictionary::canonical gives it back
  return entries;
}

/// The recorded entries of a region of the record (every key it has).
Entries recordedEntries(const Dictionary& region) {
  Entries entries;
  for (const std::string& key : region.keys()) entries.emplace_back(key, region.canonical(key));
  return entries;
}

const std::string* find(const Entries& entries, const std::string& key) {
  for (const auto& [k, value] : entries)
    if (k == key) return &value;
  return nullptr;
}

std::string nameOf(const Dictionary& region) { return region.has("name") ? region.getString("name") : ""; }

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

/// A name as a YAML double-quoted scalar.
std::string yamlString(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

/// A region present in both, compared key by key.
void compareRegion(const Dictionary& current, const Dictionary& recorded, const fs::path& surfaceDirectory,
                   const std::string& sampled) {
  const Entries now = entriesOf(current, surfaceDirectory), then = recordedEntries(recorded);
  for (const auto& [key, value] : now) {
    const std::string* before = find(then, key);
    if (key == kFileDigest) {
      if (before && *before != value)
        current.fail("file", (surfaceDirectory / current.getString("file")).string() + " has changed since " + sampled +
                                 " from it (" + recorded.where(kFileDigest) + " holds its digest then); " +
                                 "restore the file, or " + kFix);
    } else if (!before) {
      current.fail(key, "added after " + sampled + " (" + recorded.where("name") +
                            " records the region without it); remove it, or " + kFix);
    } else if (*before != value) {
      current.fail(key, value + " differs from " + *before + ", the value " + sampled + " with (" +
                            recorded.where(key) + "); set it back, or " + kFix);
    }
  }
  for (const auto& [key, value] : then)
    if (key != kFileDigest && !find(now, key)) // a surface file that is gone cannot be compared: passed over
      current.fail(key, "removed after " + sampled + " with " + key + ": " + value + " (" + recorded.where(key) +
                            "); restore it, or " + kFix);
}

} // namespace

std::string samplingRecord(const Dictionary& particleDict, const fs::path& surfaceDirectory,
                           const ParticleSystem& particles, const std::vector<PorousMaterial>& materials) {
  std::ostringstream out;
  out << "# What the particles of this time directory were sampled from (sampleParticles; every later time directory\n"
         "# carries it along). poroSph refuses to run from here when system/particleDict's regions (but a wall's\n"
         "# motion) or the order of constant/porosityProperties's materials no longer match it.\n"
         "regions:\n";
  for (const Dictionary& region : particleDict.getDictList("regions")) {
    out << "  - {";
    const Entries entries = entriesOf(region, surfaceDirectory);
    for (std::size_t k = 0; k < entries.size(); ++k)
      out << (k ? ", " : "") << entries[k].first << ": " << entries[k].second;
    out << "}\n";
  }
  std::ostringstream sampledAs;
  for (std::size_t s = 0; s < particles.size(); ++s) {
    if (particles[s].kind() != SetKind::Porous) continue;
    const auto material = std::find_if(materials.begin(), materials.end(),
                                       [&](const PorousMaterial& m) { return m.name == particles[s].name(); });
    if (material == materials.end()) continue;
    sampledAs << "\n  - {materialId: " << material - materials.begin() << ", name: " << yamlString(material->name)
              << "}";
  }
  // An empty list is written before the comment: after it, YAML would read no value at all.
  out << "porousMaterials:" << (sampledAs.str().empty() ? " []" : "")
      << "  # materialId in porous.vtp: the material of constant/porosityProperties it was sampled as"
      << sampledAs.str() << "\n";
  return out.str();
}

void checkSampledRegions(const fs::path& caseDir, const fs::path& timeDir) {
  const fs::path recordPath = timeDir / "uniform" / kSamplingRecordName;
  const fs::path dictPath = caseDir / "system" / "particleDict";
  if (!fs::exists(recordPath) || !fs::exists(dictPath)) return; // written before the record existed
  const Dictionary record = Dictionary::read(recordPath.string());
  const std::vector<Dictionary> recorded = record.getDictList("regions");
  const Dictionary dict = Dictionary::read(dictPath.string());
  if (!dict.has("regions")) return; // readWallMotions and sampleParticles report it
  const std::vector<Dictionary> current = dict.getDictList("regions");
  const std::string sampled = "the particles of " + timeDir.string() + " were sampled";

  std::vector<std::string> recordedNames, currentNames;
  for (const Dictionary& r : recorded) recordedNames.push_back(nameOf(r));
  for (const Dictionary& r : current) currentNames.push_back(nameOf(r));
  const auto index = [](const std::vector<std::string>& names, const std::string& name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  for (std::size_t k = 0; k < current.size(); ++k)
    if (index(recordedNames, currentNames[k]) == recordedNames.size())
      current[k].fail("name", "region '" + currentNames[k] + "' was added after " + sampled + " from the regions " +
                                  joined(recordedNames) + " (" + record.where("regions") + "); remove it, or " + kFix);
  for (std::size_t k = 0; k < recorded.size(); ++k)
    if (index(currentNames, recordedNames[k]) == currentNames.size())
      dict.fail("regions", "region '" + recordedNames[k] + "' was removed after " + sampled + " from it (" +
                               recorded[k].where("name") + "), so its particles would run without their region; " +
                               "restore it, or " + kFix);
  for (std::size_t k = 0; k < current.size(); ++k)
    compareRegion(current[k], recorded[index(recordedNames, currentNames[k])], caseDir / "constant" / "triSurface",
                  sampled);
  if (currentNames != recordedNames)
    dict.fail("regions", "the regions are listed as " + joined(currentNames) + ", but " + sampled + " from them as " +
                             joined(recordedNames) + " (" + record.where("regions") + "); a particle's objectId is " +
                             "its region's place in the list, which wall motions and saturationAnalysis go by; " +
                             "restore the order, or " + kFix);
}

void checkSampledMaterials(const fs::path& caseDir, const fs::path& timeDir,
                           const std::vector<PorousMaterial>& materials) {
  const fs::path recordPath = timeDir / "uniform" / kSamplingRecordName;
  // Without materials, reading porous.vtp says that constant/porosityProperties is missing.
  if (materials.empty() || !fs::exists(recordPath)) return;
  const Dictionary record = Dictionary::read(recordPath.string());
  for (const Dictionary& entry : record.getDictList("porousMaterials")) {
    const auto id = static_cast<std::size_t>(entry.getInt("materialId", Range::nonNegative()));
    const std::string name = entry.getString("name");
    if (id < materials.size() && materials[id].name == name) continue;
    const auto now =
        std::find_if(materials.begin(), materials.end(), [&](const PorousMaterial& m) { return m.name == name; });
    std::ostringstream msg;
    msg << "the porous particles of " << timeDir.string() << " with materialId " << id << " were sampled as material '"
        << name << "' (" << entry.where("name") << "), but materialId " << id << " (the materials' place in this "
        << "file, counted from 0) now names "
        << (id < materials.size() ? "'" + materials[id].name + "'" : std::string("no material")) << "; ";
    if (now != materials.end())
      msg << "'" << name << "' is now materialId " << now - materials.begin()
          << ": put the materials back in their order, or " << kFix;
    else
      msg << "'" << name << "' is no longer defined: restore it, or " << kFix;
    const Dictionary properties = Dictionary::read((caseDir / "constant" / "porosityProperties").string());
    properties.fail(now != materials.end() ? name : id < materials.size() ? materials[id].name : name, msg.str());
  }
}

} // namespace poro
