#include "analysis/Axis.hpp"

#include "core/Error.hpp"

namespace poro {

std::string Axis::name() const { return std::string(sign < 0.0 ? "-" : "") + "xyz"[component]; }

Axis Axis::parse(const std::string& text, const std::string& option) {
  std::string word = text;
  Axis axis;
  if (!word.empty() && (word[0] == '-' || word[0] == '+')) {
    axis.sign = word[0] == '-' ? -1.0 : 1.0;
    word.erase(0, 1);
  }
  if (word != "x" && word != "y" && word != "z")
    throw InputError("option " + option + " expects x, y, z, -x, -y or -z, got '" + text + "'");
  axis.component = word[0] - 'x';
  return axis;
}

Axis Axis::up(const Vec3& gravity) {
  Axis axis;
  if (gravity.isZero(0.0)) return axis;
  gravity.cwiseAbs().maxCoeff(&axis.component);
  axis.sign = gravity[axis.component] > 0.0 ? -1.0 : 1.0;
  return axis;
}

} // namespace poro
