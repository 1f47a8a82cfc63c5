#include "io/OutputSettings.hpp"

#include "core/Dictionary.hpp"

namespace poro {

OutputSettings OutputSettings::read(const Dictionary& controlDict) {
  OutputSettings s;
  s.binary = controlDict.getWord("writeFormat", {"binary", "ascii"}, "binary") == "binary";
  s.purgeWrite = static_cast<int>(controlDict.getInt("purgeWrite", 0, Range::closed(0, 1e9)));
  return s;
}

} // namespace poro
