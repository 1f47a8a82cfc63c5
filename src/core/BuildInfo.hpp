#pragma once

#include <string>

namespace poro {

/// The compiler and the arithmetic this binary was built with, for the logs: results of two builds may differ in
/// their last bits (another compiler, instruction set or fused multiply-adds), while one binary reproduces itself
/// (METHOD.md §1). Read from the compiler's predefined macros, so it cannot disagree with the flags used.
std::string buildDescription();

} // namespace poro
