#include "physics/SolverSettings.hpp"

#include "core/Dictionary.hpp"
#include "core/Log.hpp"

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
  {
    const Dictionary c = dict.subDictOrEmpty("compatibility");
    s.compatibility = readCompatibility(c);
    if (c.has("preset")) {
      s.pressure.latticeCorrectedPoreFluid = s.implicit.adhesionFadesInFullPores = false;
      s.pressure.maxSkeletonParticleDensityError = 0.0;
      s.pressure.wallContactAllSkeletons = false;
      // The reference preset is the authors' iteration sweep for sweep (METHOD.md §10).
      if (c.getWord("preset", {"paper", "reference"}, "paper") == "reference") s.pressure.chebyshev = false;
    }
  }
  // Every section is read, present or not, and checked once all are read: a key in the wrong one is sent to its own.
  const Dictionary pressure = dict.subDictOrEmpty("pressure");
  {
    auto& ps = s.pressure;
    ps.maxDensityError = pressure.getReal("maxDensityError", ps.maxDensityError, Range::positive());
    ps.maxParticleDensityError =
        pressure.getReal("maxParticleDensityError", ps.maxParticleDensityError, Range::nonNegative());
    ps.maxSkeletonParticleDensityError =
        pressure.getReal("maxSkeletonParticleDensityError", ps.maxSkeletonParticleDensityError, Range::nonNegative());
    ps.minIterations = static_cast<int>(pressure.getInt("minIterations", ps.minIterations, Range::closed(1, 1e6)));
    ps.maxIterations = static_cast<int>(pressure.getInt("maxIterations", ps.maxIterations, Range::closed(1, 1e6)));
    if (ps.minIterations > ps.maxIterations)
      pressure.fail("minIterations", "expected minIterations <= maxIterations (" + std::to_string(ps.maxIterations) +
                                         "), got " + std::to_string(ps.minIterations));
    ps.relaxation = pressure.getReal("relaxation", ps.relaxation, Range{0.0, 1.0, true, false});
    ps.warmStart = pressure.getReal("warmStart", ps.warmStart, Range::closed(0.0, 1.0));
    ps.chebyshev = readSwitch(pressure, "acceleration", "none", "chebyshev", ps.chebyshev);
    ps.spectralRadius = pressure.getReal("spectralRadius", ps.spectralRadius, Range::open(0.0, 1.0));
    if (!ps.chebyshev && pressure.has("spectralRadius"))
      log::warning(pressure.where("spectralRadius") +
                   ": key 'pressure.spectralRadius' has no effect: it sets the Chebyshev acceleration, and the sweeps "
                   "here are Jacobi's alone (pressure.acceleration none, or compatibility.preset reference)");
    ps.latticeCorrectedPoreFluid =
        readSwitch(pressure, "poreFluidDensity", "paper", "latticeCorrected", ps.latticeCorrectedPoreFluid);
    ps.wallContactAllSkeletons =
        readSwitch(pressure, "wallContact", "compressibleSkeletons", "allSkeletons", ps.wallContactAllSkeletons);
  }
  const Dictionary implicit = dict.subDictOrEmpty("implicit");
  {
    auto& is = s.implicit;
    is.tolerance = implicit.getReal("tolerance", is.tolerance, Range::open(0.0, 1.0));
    is.maxIterations = static_cast<int>(implicit.getInt("maxIterations", is.maxIterations, Range::closed(1, 1e6)));
    is.preconditioner = implicit.getWord("preconditioner", {"blockJacobi", "none"}, "blockJacobi") == "blockJacobi";
    is.adhesionFadesInFullPores =
        readSwitch(implicit, "adhesionInFullPores", "paper", "fades", is.adhesionFadesInFullPores);
  }
  s.xsph = dict.getReal("xsph", s.xsph, Range::closed(0.0, 1.0));
  const Dictionary search = dict.subDictOrEmpty("neighbourSearch");
  s.sortInterval = static_cast<int>(search.getInt("sortInterval", s.sortInterval, Range::closed(0, 1e9)));
  s.searchSkin = search.getReal("skin", s.searchSkin, Range::closed(0.0, 1.0));
  const Dictionary health = dict.subDictOrEmpty("health");
  {
    auto& hs = s.health;
    hs.nonFinite = readAction(health, "nonFinite", {"stop", "remove"}, hs.nonFinite);
    hs.leavingDomain = readAction(health, "leavingDomain", {"warn", "remove", "stop"}, hs.leavingDomain);
    hs.pressureIterations = readAction(health, "pressureIterations", {"warn", "stop"}, hs.pressureIterations);
    hs.implicitIterations = readAction(health, "implicitIterations", {"warn", "stop"}, hs.implicitIterations);
    hs.startDensity = health.getReal("startDensity", hs.startDensity, Range::atLeast(1.0));
    if (auto d = health.optionalSubDict("domain")) {
      Domain domain{d->getVec3("min"), d->getVec3("max")};
      if (!(domain.max.array() > domain.min.array()).all()) d->fail("max", "expected max > min in every component");
      hs.domain = domain;
      d->checkUnknownKeys();
    }
  }
  s.threads = static_cast<int>(dict.getInt("threads", s.threads, Range::closed(0, 4096)));
  for (const Dictionary* section : {&pressure, &implicit, &search, &health}) section->checkUnknownKeys();
  dict.checkUnknownKeys();
  return s;
}

} // namespace poro
