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
#if defined(__x86_64__)
#if defined(__AVX512F__)
  text += ", AVX-512";
#elif defined(__AVX2__)
  text += ", AVX2";
#else
  text += ", generic x86-64";
#endif
  // GCC and Clang form fused multiply-adds wherever the instruction set has them; CMake's POROSPH_FMA=OFF passes
  // -mno-fma, which removes them from the set. (Elsewhere the macros do not tell whether contraction is on.)
#if defined(__FMA__)
  text += ", fused multiply-adds";
#else
  text += ", no fused multiply-adds";
#endif
#endif
  return text;
}

} // namespace poro
