#include "core/Log.hpp"

#include "core/Error.hpp"

#include <iostream>

namespace poro::log {

namespace {
bool quiet_ = false;
}

void setQuiet(bool quiet) { quiet_ = quiet; }

void info(const std::string& message) {
  if (!quiet_) std::cout << message << std::endl; // flushed: `tail -f log.poroSph` follows the run step by step
}

void warning(const std::string& message) {
  std::cout.flush();
  std::cerr << "Warning: " << message << std::endl;
}

void fatal(const Error& error) {
  std::cout.flush();
  std::cerr << "\n--> PoroSPH FATAL " << error.kind() << ":\n" << error.what() << "\n" << std::endl;
}

void fatal(const std::string& message) {
  std::cout.flush();
  std::cerr << "\n--> PoroSPH FATAL error:\n" << message << "\n" << std::endl;
}

} // namespace poro::log
