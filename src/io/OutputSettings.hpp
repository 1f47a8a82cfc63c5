#pragma once
/// The output keys of system/controlDict: writeFormat (binary | ascii) and purgeWrite (keep only the
/// newest N time directories besides 0/; 0 keeps all).

namespace poro {
class Dictionary;

struct OutputSettings {
  bool binary = true;
  int purgeWrite = 0;

  static OutputSettings read(const Dictionary& controlDict);
};

} // namespace poro
