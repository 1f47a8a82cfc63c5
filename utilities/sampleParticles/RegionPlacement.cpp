#include "RegionPlacement.hpp"

#include "ClosePairs.hpp"
#include "core/Error.hpp"

#include <limits>
#include <sstream>

namespace poro {

namespace {

using Phase = ParticleRegion::Phase;

const char* const kFaces[] = {"xMin", "xMax", "yMin", "yMax", "zMin", "zMax"};

std::string format(const Vec3& v) {
  std::ostringstream out;
  out << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']';
  return out.str();
}

const char* phaseName(Phase phase) {
  return phase == Phase::Fluid ? "fluid" : phase == Phase::Porous ? "porous" : phase == Phase::Rigid ? "rigid" : "wall";
}

/// "region 'water' (fluid, system/particleDict:5)".
/// Walls and rigid bodies: regions whose particles are wall particles.
bool isSolid(Phase phase) { return phase == Phase::Boundary || phase == Phase::Rigid; }

std::string describe(const ParticleRegion& r) {
  return "region '" + r.name + "' (" + phaseName(r.phase) + ", " + r.where + ")";
}

/// A box some walls enclose; infinite bounds beyond a container's open faces.
struct Enclosure {
  Vec3 min, max;
  std::string what; ///< for the message: "container 'tank' (inner box from ... to ..., open at yMax)"

  bool contains(const Vec3& p) const { return (p.array() >= min.array()).all() && (p.array() <= max.array()).all(); }
};

std::vector<Enclosure> enclosures(const ParticleDict& dict) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<Enclosure> result;
  for (const ParticleRegion& r : dict.regions) {
    if (r.phase != Phase::Boundary) continue;
    if (r.shape == ParticleRegion::Shape::Container) {
      Enclosure e{r.min, r.max, ""};
      std::string open;
      for (int f = 0; f < 6; ++f) {
        if (!r.open[static_cast<std::size_t>(f)]) continue;
        (f % 2 == 0 ? e.min : e.max)[f / 2] = f % 2 == 0 ? -inf : inf;
        open += (open.empty() ? "" : ", ") + std::string(kFaces[f]);
      }
      e.what = "container '" + r.name + "' (its inner box from " + format(r.min) + " to " + format(r.max) +
               (open.empty() ? "" : ", and beyond its open " + open) + ")";
      result.push_back(e);
    } else if (r.body && r.side == WallSide::Outside) {
      result.push_back({r.body->boxMin(), r.body->boxMax(),
                        "wall '" + r.name + "' (the bounding box of its surface, from " + format(r.body->boxMin()) +
                            " to " + format(r.body->boxMax()) + ")"});
    }
  }
  return result;
}

/// Per region: its particle count, bounding box and whether a particle of it lies in `inside`.
struct RegionExtent {
  std::size_t count = 0;
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 max = Vec3::Constant(std::numeric_limits<double>::lowest());
  bool enclosed = false;
};

void checkEnclosed(const ParticleDict& dict, const ParticleSystem& particles) {
  const std::vector<Enclosure> walls = enclosures(dict);
  if (walls.empty()) return;
  std::vector<RegionExtent> extents(dict.regions.size());
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const ParticleSet& set = particles[s];
    if (set.kind() == SetKind::Boundary) continue;
    const auto& object = set.integer(field::objectId);
    for (std::size_t i = 0; i < set.size(); ++i) {
      RegionExtent& e = extents[static_cast<std::size_t>(object[i])];
      const Vec3& p = set.x()[i];
      ++e.count;
      e.min = e.min.cwiseMin(p);
      e.max = e.max.cwiseMax(p);
      if (!e.enclosed)
        for (const Enclosure& wall : walls) e.enclosed = e.enclosed || wall.contains(p);
    }
  }
  for (std::size_t k = 0; k < dict.regions.size(); ++k) {
    const RegionExtent& e = extents[k];
    if (e.count == 0 || e.enclosed) continue;
    const ParticleRegion& r = dict.regions[k];
    std::ostringstream msg;
    msg << r.where << ": region '" << r.name << "' (" << phaseName(r.phase) << ") lies outside every wall: none of its "
        << e.count << " particles (from " << format(e.min) << " to " << format(e.max) << ") is inside ";
    for (std::size_t w = 0; w < walls.size(); ++w)
      msg << (w == 0 ? "" : w + 1 < walls.size() ? ", " : " or ") << walls[w].what;
    msg << ", so it would fall or drift away from them and leave the domain; move it inside (check the signs and "
           "units of its coordinates)";
    throw InputError(msg.str());
  }
}

void checkOverlaps(const ParticleDict& dict, const ParticleSystem& particles) {
  const std::size_t n = dict.regions.size();
  std::vector<std::vector<bool>> apart(n, std::vector<bool>(n, false));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      const Phase pa = dict.regions[a].phase, pb = dict.regions[b].phase;
      // Walls may overlap walls; nothing else may reach into a wall or a rigid body (whose particles are walls too),
      // nor a body into another; fluid may fill a porous region's pores.
      const bool walls = pa == Phase::Boundary && pb == Phase::Boundary;
      apart[a][b] = a != b && !walls && (isSolid(pa) || isSolid(pb) || pa == pb);
    }
  std::vector<LabelledPoints> points;
  for (std::size_t s = 0; s < particles.size(); ++s)
    points.push_back({&particles[s].x(), &particles[s].integer(field::objectId)});
  const double distance = kOverlapFraction * particles.spacing();
  const std::vector<ClosePairs> overlaps = findClosePairs(points, distance, apart);
  if (overlaps.empty()) return;

  // Named first: the later region, or the fluid or porous one of a wall pair (walls are rarely what moved).
  const ClosePairs& o = overlaps.front();
  const bool wall = isSolid(dict.regions[o.a].phase) || isSolid(dict.regions[o.b].phase);
  const bool swap = !wall || !isSolid(dict.regions[o.b].phase);
  const ParticleRegion &named = dict.regions[swap ? o.b : o.a], &other = dict.regions[swap ? o.a : o.b];
  const Vec3 &namedPoint = swap ? o.pointB : o.pointA, &otherPoint = swap ? o.pointA : o.pointB;
  std::ostringstream msg;
  msg << named.where << ": region '" << named.name << "' (" << phaseName(named.phase) << ") overlaps "
      << describe(other) << ": " << o.count << (o.count == 1 ? " pair" : " pairs")
      << " of their particles are closer than sqrt(3) particleRadius = " << distance << " m, the closest " << o.closest
      << " m apart, at " << format(namedPoint) << " ('" << named.name << "') and " << format(otherPoint) << " ('"
      << other.name << "'); ";
  if (wall)
    msg << "a region must not reach into a wall or a rigid body (wall particles lie particleRadius behind a wall's "
           "surface, so a region may reach up to the surface)";
  else
    msg << "two regions must not share space (it would hold twice the particles: twice the rest density, which the "
           "first pressure solve blows apart)";
  msg << "; move or shrink one of them";
  if (overlaps.size() > 1) {
    msg << " (" << overlaps.size() - 1 << " more pair" << (overlaps.size() > 2 ? "s" : "") << " of regions overlap:";
    for (std::size_t k = 1; k < overlaps.size() && k < 4; ++k)
      msg << (k == 1 ? " " : ", ") << "'" << dict.regions[overlaps[k].a].name << "' and '"
          << dict.regions[overlaps[k].b].name << "'";
    msg << (overlaps.size() > 4 ? ", ...)" : ")");
  }
  throw InputError(msg.str());
}

} // namespace

void checkRegionPlacement(const ParticleDict& dict, const ParticleSystem& particles) {
  checkEnclosed(dict, particles);
  checkOverlaps(dict, particles);
}

} // namespace poro
