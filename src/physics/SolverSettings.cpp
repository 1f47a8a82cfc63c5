#include "physics/SolverSettings.hpp"

#include "core/Dictionary.hpp"

#include <string>
#include <vector>

namespace poro {

namespace {

HealthAction readAction(const Dictionary& dict, const std::string& key, const std::vector<std::string>& choices,
                        HealthAction fallback) {
  const char* names[] = {"warn", "remove", "stop"};
  const std::string word = dict.getWord(key, choices, names[static_cast<int>(fallback)]);
  return word == "warn" ? HealthAction::Warn : word == "remove" ? HealthAction::Remove : HealthAction::Stop;
}

/// Reads one switch: `offWord` (false) or `onWord` (true); `fallback` when the key is absent.
bool readSwitch(const Dictionary& dict, const std::string& key, const std::string& offWord, const std::string& onWord,
                bool fallback) {
  return dict.getWord(key, {offWord, onWord}, fallback ? onWord : offWord) == onWord;
}

CompatibilitySettings readCompatibility(const Dictionary& c) {
  const bool reference = c.getWord("preset", {"paper", "reference"}, "paper") == "reference";
  CompatibilitySettings s = reference ? CompatibilitySettings::reference() : CompatibilitySettings{};
  s.unitLambdaVolumetricStress =
      readSwitch(c, "volumetricStress", "lambda", "unitLambda", s.unitLambdaVolumetricStress);
  s.lambdaScaledBloating = readSwitch(c, "bloatingStress", "absolute", "lambdaScaled", s.lambdaScaledBloating);
  s.deltaTScaledInitialGuess =
      readSwitch(c, "implicitInitialGuess", "deltaV", "deltaTDeltaV", s.deltaTScaledInitialGuess);
  s.restCouplingSolidDensity = readSwitch(c, "couplingSolidDensity", "current", "rest", s.restCouplingSolidDensity);
  s.setSequentialPressure = readSwitch(c, "pressureSweep", "jacobi", "setSequential", s.setSequentialPressure);
  s.cappedPressureWarmStart = readSwitch(c, "pressureWarmStartCap", "none", "reference", s.cappedPressureWarmStart);
  c.checkUnknownKeys();
  return s;
}

} // namespace

CompatibilitySettings CompatibilitySettings::reference() {
  CompatibilitySettings s;
  s.unitLambdaVolumetricStress = s.lambdaScaledBloating = s.deltaTScaledInitialGuess = true;
  s.restCouplingSolidDensity = s.setSequentialPressure = true;
  return s;
}

SolverSettings SolverSettings::read(const Dictionary& dict) {
  SolverSettings s;
  // Compatibility first: naming a preset, paper or reference, asks for Eq. 4 and 13 and the stopping rule as
  // published, so it turns the defaults of pressure.poreFluidDensity and implicit.adhesionInFullPores back to paper
  // (METHOD.md §3.3, §6.5.6), the skeleton's single-particle bound off (§6.7) and the wall contact back to the
  // compressible skeletons it was made for; the keys themselves still win.
  if (auto c = dict.optionalSubDict("compatibility")) {
    s.compatibility = readCompatibility(*c);
    if (c->has("preset")) {
      s.pressure.latticeCorrectedPoreFluid = s.implicit.adhesionFadesInFullPores = false;
      s.pressure.maxSkeletonParticleDensityError = 0.0;
      s.pressure.wallContactAllSkeletons = false;
      // The reference preset is the authors' iteration sweep for sweep (METHOD.md §10).
      if (c->getWord("preset", {"paper", "reference"}, "paper") == "reference") s.pressure.chebyshev = false;
    }
  }
  if (auto p = dict.optionalSubDict("pressure")) {
    auto& ps = s.pressure;
    ps.maxDensityError = p->getReal("maxDensityError", ps.maxDensityError, Range::positive());
    ps.maxParticleDensityError =
        p->getReal("maxParticleDensityError", ps.maxParticleDensityError, Range::nonNegative());
    ps.maxSkeletonParticleDensityError =
        p->getReal("maxSkeletonParticleDensityError", ps.maxSkeletonParticleDensityError, Range::nonNegative());
    ps.minIterations = static_cast<int>(p->getInt("minIterations", ps.minIterations, Range::closed(1, 1e6)));
    ps.maxIterations = static_cast<int>(p->getInt("maxIterations", ps.maxIterations, Range::closed(1, 1e6)));
    if (ps.minIterations > ps.maxIterations)
      p->fail("minIterations", "expected minIterations <= maxIterations (" + std::to_string(ps.maxIterations) +
                                   "), got " + std::to_string(ps.minIterations));
    ps.relaxation = p->getReal("relaxation", ps.relaxation, Range{0.0, 1.0, true, false});
    ps.warmStart = p->getReal("warmStart", ps.warmStart, Range::closed(0.0, 1.0));
    ps.chebyshev = readSwitch(*p, "acceleration", "none", "chebyshev", ps.chebyshev);
    ps.spectralRadius = p->getReal("spectralRadius", ps.spectralRadius, Range::open(0.0, 1.0));
    ps.latticeCorrectedPoreFluid =
        readSwitch(*p, "poreFluidDensity", "paper", "latticeCorrected", ps.latticeCorrectedPoreFluid);
    ps.wallContactAllSkeletons =
        readSwitch(*p, "wallContact", "compressibleSkeletons", "allSkeletons", ps.wallContactAllSkeletons);
    p->checkUnknownKeys();
  }
  if (auto i = dict.optionalSubDict("implicit")) {
    auto& is = s.implicit;
    is.tolerance = i->getReal("tolerance", is.tolerance, Range::open(0.0, 1.0));
    is.maxIterations = static_cast<int>(i->getInt("maxIterations", is.maxIterations, Range::closed(1, 1e6)));
    is.preconditioner = i->getWord("preconditioner", {"blockJacobi", "none"}, "blockJacobi") == "blockJacobi";
    is.adhesionFadesInFullPores = readSwitch(*i, "adhesionInFullPores", "paper", "fades", is.adhesionFadesInFullPores);
    i->checkUnknownKeys();
  }
  s.xsph = dict.getReal("xsph", s.xsph, Range::closed(0.0, 1.0));
  if (auto n = dict.optionalSubDict("neighbourSearch")) {
    s.sortInterval = static_cast<int>(n->getInt("sortInterval", s.sortInterval, Range::closed(0, 1e9)));
    s.searchSkin = n->getReal("skin", s.searchSkin, Range::closed(0.0, 1.0));
    n->checkUnknownKeys();
  }
  if (auto h = dict.optionalSubDict("health")) {
    auto& hs = s.health;
    hs.nonFinite = readAction(*h, "nonFinite", {"stop", "remove"}, hs.nonFinite);
    hs.leavingDomain = readAction(*h, "leavingDomain", {"warn", "remove", "stop"}, hs.leavingDomain);
    hs.pressureIterations = readAction(*h, "pressureIterations", {"warn", "stop"}, hs.pressureIterations);
    hs.implicitIterations = readAction(*h, "implicitIterations", {"warn", "stop"}, hs.implicitIterations);
    hs.startDensity = h->getReal("startDensity", hs.startDensity, Range::atLeast(1.0));
    if (auto d = h->optionalSubDict("domain")) {
      Domain domain{d->getVec3("min"), d->getVec3("max")};
      if (!(domain.max.array() > domain.min.array()).all()) d->fail("max", "expected max > min in every component");
      hs.domain = domain;
      d->checkUnknownKeys();
    }
    h->checkUnknownKeys();
  }
  s.threads = static_cast<int>(dict.getInt("threads", s.threads, Range::closed(0, 4096)));
  dict.checkUnknownKeys();
  return s;
}

} // namespace poro
