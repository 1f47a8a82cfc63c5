#include "core/BuildInfo.hpp"

namespace poro {

std::string buildDescription() {
  std::string text;
#if defined(__clang__)
  text += "Clang " __clang_version__;
#elif defined(__GNUC__)
  text += "GCC " __VERSION__;
#else
  text += "an unknown compiler";
#endif
#if !defined(__OPTIMIZE__)
  text += ", unoptimised";
#endif
#if defined(__SANITIZE_ADDRESS__)
  text += ", AddressSanitizer";
#endif
#if defined(__AVX512F__)
  text += ", AVX-512";
#elif defined(__AVX2__)
  text += ", AVX2";
#elif defined(__x86_64__)
  text += ", generic x86-64";
#endif
  // GCC and Clang form fused multiply-adds wherever the instruction set has them, unless told otherwise (CMake's
  // POROSPH_FMA=OFF passes -mno-fma).
#if defined(__FMA__)
  text += ", fused multiply-adds";
#else
  text += ", no fused multiply-adds";
#endif
  return text;
}

} // namespace poro
