#pragma once
/// Logging: plain lines to stdout (progress, info) and stderr (warnings, fatal errors).

#include <string>

namespace poro {
class Error;
namespace log {

void info(const std::string& message);
void warning(const std::string& message);
/// Prints "--> FOAM-style FATAL" block for an error the application cannot recover from.
void fatal(const Error& error);
void fatal(const std::string& message);
/// Suppresses info output (tests).
void setQuiet(bool quiet);

} // namespace log
} // namespace poro
