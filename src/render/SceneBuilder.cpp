#include "render/SceneBuilder.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "physics/FieldNames.hpp"
#include "render/ClipCap.hpp"
#include "sph/ParticleSystem.hpp"
#include "surface/ShepardInterpolation.hpp"
#include "surface/SurfaceReconstruction.hpp"

#include <algorithm>

namespace poro {

namespace fs = std::filesystem;

namespace {

SetKind kindOf(const std::string& set) {
  return set == "fluid" ? SetKind::Fluid : set == "porous" ? SetKind::Porous : SetKind::Boundary;
}

/// Fields the solver writes from its first step on: absent at time 0 (sampleParticles), drawn as 0 there.
bool isSolverOutput(const std::string& name) {
  return name == field::saturation || name == field::density || name == field::pressure ||
         name == field::localPorosity;
}

double magnitude(const ParticleSet& set, const std::string& name, std::size_t i) {
  switch (set.info(name)->type) {
  case FieldType::Real: return set.real(name)[i];
  case FieldType::Vec3: return set.vec3(name)[i].norm();
  case FieldType::Mat3: return set.mat3(name)[i].norm();
  case FieldType::Int: return static_cast<double>(set.integer(name)[i]);
  }
  return 0.0;
}

/// |f| per point of values[point components + c].
std::vector<double> magnitudes(const std::vector<double>& values, int components) {
  const auto k = static_cast<std::size_t>(components);
  std::vector<double> out(values.size() / k);
  for (std::size_t p = 0; p < out.size(); ++p) {
    double sum = 0.0;
    for (std::size_t c = 0; c < k; ++c) sum += values[p * k + c] * values[p * k + c];
    out[p] = std::sqrt(sum);
  }
  return out;
}

/// |f| at the surface's points for the field `name` (empty if the surface has none).
std::vector<double> surfaceValues(const TriangleSurface& surface, const std::string& name) {
  const TriangleSurface::Field* f = surface.field(name);
  return f ? magnitudes(f->values, f->components) : std::vector<double>();
}

std::size_t finiteCount(const ParticleSet& set) {
  return static_cast<std::size_t>(
      std::count_if(set.x().begin(), set.x().end(), [](const Vec3& x) { return x.allFinite(); }));
}

bool clips(const RenderSettings& render, const std::string& set) {
  return render.clip && std::find(render.clip->sets.begin(), render.clip->sets.end(), set) != render.clip->sets.end();
}

} // namespace

SceneBuilder::SceneBuilder(fs::path caseDir, const RenderSettings& render, const SurfaceSettings& surface,
                           const Vec3& gravity)
    : caseDir_(std::move(caseDir)), render_(render), surface_(surface),
      up_(gravity.norm() > 0.0 ? Vec3(-gravity.normalized()) : Vec3(Vec3::UnitY())) {
  // Containers are boxes of system/particleDict; sampleParticles has validated it, so anything unexpected here
  // only means no outline.
  const fs::path path = caseDir_ / "system" / "particleDict";
  if (!fs::exists(path)) return;
  try {
    const Dictionary dict = Dictionary::read(path.string());
    const std::vector<Dictionary> regions = dict.getDictList("regions");
    for (std::size_t k = 0; k < regions.size(); ++k) {
      const Dictionary& region = regions[k];
      if (region.getString("phase", "") != "boundary" || region.getString("shape", "") != "container") continue;
      containers_.push_back({region.getVec3("min"), region.getVec3("max")});
      containerIds_.push_back(static_cast<std::int64_t>(k));
    }
  } catch (const InputError&) {
    containers_.clear();
    containerIds_.clear();
  }
}

std::vector<double> SceneBuilder::particleValues(const ParticleSystem& particles, const SetStyle& style) {
  std::vector<double> values;
  if (style.colourBy.empty()) return values;
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const ParticleSet& set = particles[s];
    if (set.kind() != kindOf(style.set)) continue;
    if (!set.has(style.colourBy)) {
      if (isSolverOutput(style.colourBy)) {
        values.insert(values.end(), finiteCount(set), 0.0);
        continue;
      }
      std::string names;
      for (const auto& f : set.fields()) names += (names.empty() ? "" : ", ") + f.name;
      throw InputError(style.where + ": key '" + style.set + ".colourBy': expected a field of the " + style.set +
                       " particles (" + names + "), got '" + style.colourBy + "'");
    }
    for (std::size_t i = 0; i < set.size(); ++i)
      if (set.x()[i].allFinite()) values.push_back(magnitude(set, style.colourBy, i));
  }
  return values;
}

Scene SceneBuilder::build(const ParticleSystem& particles, const std::string& timeName, double time) {
  Scene scene;
  scene.timeName = timeName;
  scene.time = time;
  scene.up = up_;
  contact_.clear();
  const double r = particles.particleRadius();
  for (const SetStyle* style : render_.styles()) {
    if (style->show == SetStyle::Show::None) continue;
    if (style->set == "boundary" && style->show == SetStyle::Show::Surface) {
      scene.layers.push_back(wallLayer(particles, timeName));
      scene.layers.back().style = style;
      scene.layers.back().particleRadius = r;
      continue;
    }
    SceneLayer layer;
    layer.style = style;
    if (style->show == SetStyle::Show::Particles) {
      // Particles of a diverged run (NaN or infinite positions) are left out, here and in particleValues alike, so
      // the values stay aligned and neither VTK's bounds nor the camera clipping range become NaN.
      for (std::size_t s = 0; s < particles.size(); ++s)
        if (particles[s].kind() == kindOf(style->set))
          for (const Vec3& x : particles[s].x())
            if (x.allFinite()) layer.particles.push_back(x);
      layer.particleRadius = r;
      layer.values = particleValues(particles, *style);
      scene.layers.push_back(std::move(layer));
      continue;
    }
    const bool fluid = style->set == "fluid";
    const ParticleCloud cloud = fluid ? fluidCloud(particles, surface_) : porousCloud(particles);
    if (cloud.positions.empty()) continue;
    const ReconstructionSettings& settings = fluid ? surface_.fluid : surface_.porous;
    Reconstruction made = reconstruct(cloud, settings, r);
    layer.surface = std::move(made.surface);
    layer.values = surfaceValues(layer.surface, style->colourBy);
    if (fluid) trimContact(layer.surface);
    else contact_.push_back(made.grid);
    if (clips(render_, style->set)) {
      layer.cap = clipCap(made.grid, made.iso, *render_.clip);
      const ShepardInterpolation interpolation(cloud, settings.kernelRadius * r, settings.where);
      for (const ParticleField& f : cloud.fields)
        if (f.name == style->colourBy) layer.capValues = magnitudes(interpolation.at(layer.cap.points, f), f.components);
    }
    scene.layers.push_back(std::move(layer));
  }
  return scene;
}

SceneLayer SceneBuilder::wallLayer(const ParticleSystem& particles, const std::string& timeName) {
  SceneLayer layer;
  layer.containers = containers_;
  const bool moving = fs::exists(caseDir_ / timeName / "boundary.vtp");
  if (moving || !staticWalls_) {
    ParticleCloud bodies;
    for (std::size_t s = 0; s < particles.size(); ++s) {
      const ParticleSet& set = particles[s];
      if (set.kind() != SetKind::Boundary) continue;
      const auto& ids = set.integer(field::objectId);
      for (std::size_t i = 0; i < set.size(); ++i) {
        if (std::find(containerIds_.begin(), containerIds_.end(), ids[i]) != containerIds_.end()) continue;
        bodies.positions.push_back(set.x()[i]);
        bodies.volumes.push_back(particles.particleVolume());
      }
    }
    staticWalls_ = reconstruct(bodies, ReconstructionSettings{}, particles.particleRadius());
  }
  layer.surface = staticWalls_->surface;
  if (staticWalls_->grid.points() > 0) contact_.push_back(staticWalls_->grid);
  return layer;
}

void SceneBuilder::trimContact(TriangleSurface& water) const {
  if (contact_.empty()) return;
  std::vector<char> touching(water.points.size(), 0);
  for (std::size_t p = 0; p < water.points.size(); ++p)
    for (const ScalarGrid& grid : contact_)
      if (grid.sample(water.points[p]) >= 0.2) touching[p] = 1;
  const auto on = [&](Index p) { return touching[static_cast<std::size_t>(p)] != 0; };
  water.triangles.erase(std::remove_if(water.triangles.begin(), water.triangles.end(),
                                       [&](const auto& t) { return on(t[0]) && on(t[1]) && on(t[2]); }),
                        water.triangles.end());
}

} // namespace poro
