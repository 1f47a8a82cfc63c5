#include "physics/HourglassControl.hpp"

#include "core/Parallel.hpp"

namespace poro {

// With eps_st = F_s X_st - x_st and F_s = sum_t V0_t x_st (x) g_st, g_st = L_s gradW(X_s - X_t), eps_st is a
// scalar-weighted sum of positions, so dE/dx_k = own_k + sum_{s in N0(k)} (V0_k H_s g_sk - w_sk eps_sk)
// (N0 is symmetric); the three coordinates never mix.

template <class F> void HourglassControl::forEachStressed(const F& f) const {
  if (stressed_.empty())
    parallel::forEach(size_, f);
  else
    parallel::forEach(stressed_.size(), [&](std::size_t k) { f(static_cast<std::size_t>(stressed_[k])); });
}

void HourglassControl::prepare(const ElasticRestState& rest, const std::vector<Vec3>& restX, double stiffness,
                               std::size_t size, const std::vector<Index>& stressed, bool restRebuilt) {
  const bool changed = restRebuilt || stiffness != stiffness_ || size != diagonal_.size();
  rest_ = &rest;
  restX_ = &restX;
  stiffness_ = stiffness;
  size_ = size;
  stressed_ = stressed;
  if (!enabled()) {
    std::vector<Mat3>().swap(gradient_);
    std::vector<Mat3>().swap(moment_);
    std::vector<Vec3>().swap(own_);
    std::vector<double>().swap(diagonal_);
    std::vector<double>().swap(laplacianWeight_);
    return;
  }
  gradient_.resize(size);
  moment_.resize(size);
  own_.resize(size);
  if (changed) formDiagonal();
}

void HourglassControl::formDiagonal() {
  // d eps_st / d x_k = [k = s] (1 - G_s . X_st) + [k in N0(s)] V0_k g_sk . X_st - [k = t]:
  // K_kk = sum_t w_kt (1 - G_k . X_kt)^2 + sum_{s in N0(k)} (V0_k^2 g_sk.M_s g_sk - 2 w_sk V0_k g_sk . X_sk + w_sk),
  // M_s = sum_t w_st X_st (x) X_st (held in moment_ meanwhile, which addForces refills).
  const ElasticRestState& rest = *rest_;
  const auto& restX = *restX_;
  // k = gradW(X_s - X_t) . X_st / |X_st|^2 = -W'(r)/r from the rounded gradient. Pairs sharing a gradient share their
  // offset up to round-off in the positions; the last pair's value is kept (serially: the same on any thread count).
  laplacianWeight_.assign(rest.storedGradients(), 0.0);
  for (std::size_t s = 0; s < size_; ++s)
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
      const Vec3 offset = restX[static_cast<std::size_t>(rest.neighbour(pair))] - restX[s];
      laplacianWeight_[rest.gradientIndex(pair)] = rest.gradient(pair).dot(offset) / offset.squaredNorm();
    }
  forEachStressed([&](std::size_t s) {
    Mat3 m = Mat3::Zero();
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
      const Vec3 offset = restX[t] - restX[s];
      addOuter(m, weight(s, t, pair) * offset, offset);
    }
    moment_[s] = m;
  });
  diagonal_.assign(size_, 0.0);
  forEachStressed([&](std::size_t k) {
    const Vec3 g = rest.correction(k) * rest.gradientSum(k);
    const double v0 = rest.volume(k);
    double sum = 0.0;
    for (std::size_t pair = rest.begin(k); pair < rest.end(k); ++pair) {
      const std::size_t s = static_cast<std::size_t>(rest.neighbour(pair));
      const Vec3 offset = restX[s] - restX[k]; // X_ks = -X_sk
      const double w = weight(k, s, pair);
      const double own = 1.0 - g.dot(offset);
      const Vec3 gsk = -(rest.correction(s) * rest.gradient(pair));
      sum += w * own * own + v0 * v0 * gsk.dot(moment_[s] * gsk) + 2.0 * w * v0 * gsk.dot(offset) + w;
    }
    diagonal_[k] = sum;
  });
}

void HourglassControl::formGradients(const Vec3* y) const {
  const ElasticRestState& rest = *rest_;
  forEachStressed([&](std::size_t s) {
    Mat3 f = Mat3::Zero();
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
      addOuter(f, y[t] - y[s], rest.weightedGradient(pair));
    }
    gradient_[s] = f * rest.correction(s).transpose(); // sum (y_t - y_s) (x) L gradW0 = [sum ...] L^T
  });
}

void HourglassControl::addForces(const Vec3* y, std::size_t owned, double scale, Vec3* out) const {
  const ElasticRestState& rest = *rest_;
  const auto& restX = *restX_;
  forEachStressed([&](std::size_t s) {
    const Mat3& f = gradient_[s];
    Mat3 h = Mat3::Zero();
    Vec3 e = Vec3::Zero();
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
      const Vec3 offset = restX[t] - restX[s];
      const Vec3 eps = weight(s, t, pair) * (f * offset - (y[t] - y[s]));
      addOuter(h, eps, offset);
      e += eps;
    }
    moment_[s] = h * rest.correction(s);
    own_[s] = e - moment_[s] * rest.gradientSum(s);
  });
  parallel::forEach(owned, [&](std::size_t k) {
    Vec3 derivative = own_[k];
    for (std::size_t pair = rest.begin(k); pair < rest.end(k); ++pair) {
      const std::size_t s = static_cast<std::size_t>(rest.neighbour(pair));
      const Vec3 offset = restX[k] - restX[s]; // X_sk
      const Vec3 eps = gradient_[s] * offset - (y[k] - y[s]);
      // H_s g_sk = H_s L_s gradW(X_s - X_k), and the stored gradient of k's pair is gradW(X_k - X_s).
      derivative -= rest.volume(k) * (moment_[s] * rest.gradient(pair)) + weight(k, s, pair) * eps;
    }
    out[k] -= scale * derivative;
  });
}

} // namespace poro
