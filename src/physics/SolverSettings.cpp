#include "physics/SolverSettings.hpp"

#include "core/Dictionary.hpp"

namespace poro {

SolverSettings SolverSettings::read(const Dictionary& dict) {
  SolverSettings s;
  if (auto p = dict.optionalSubDict("pressure")) {
    auto& ps = s.pressure;
    ps.maxDensityError = p->getReal("maxDensityError", ps.maxDensityError, Range::positive());
    ps.minIterations = static_cast<int>(p->getInt("minIterations", ps.minIterations, Range::closed(1, 1e6)));
    ps.maxIterations = static_cast<int>(p->getInt("maxIterations", ps.maxIterations, Range::closed(1, 1e6)));
    if (ps.minIterations > ps.maxIterations)
      p->fail("minIterations", "expected minIterations <= maxIterations (" + std::to_string(ps.maxIterations) +
                                   "), got " + std::to_string(ps.minIterations));
    ps.relaxation = p->getReal("relaxation", ps.relaxation, Range{0.0, 1.0, true, false});
    ps.warmStart = p->getReal("warmStart", ps.warmStart, Range::closed(0.0, 1.0));
    p->checkUnknownKeys();
  }
  if (auto i = dict.optionalSubDict("implicit")) {
    auto& is = s.implicit;
    is.tolerance = i->getReal("tolerance", is.tolerance, Range::open(0.0, 1.0));
    is.maxIterations = static_cast<int>(i->getInt("maxIterations", is.maxIterations, Range::closed(1, 1e6)));
    is.preconditioner = i->getWord("preconditioner", {"blockJacobi", "none"}, "blockJacobi") == "blockJacobi";
    i->checkUnknownKeys();
  }
  if (auto n = dict.optionalSubDict("neighbourSearch")) {
    s.sortInterval = static_cast<int>(n->getInt("sortInterval", s.sortInterval, Range::closed(0, 1e9)));
    n->checkUnknownKeys();
  }
  s.threads = static_cast<int>(dict.getInt("threads", s.threads, Range::closed(0, 4096)));
  dict.checkUnknownKeys();
  return s;
}

} // namespace poro
