#pragma once
/// Why an output directory (postProcessing/<utility>/...) cannot be made: the message a user can act on
/// instead of the system's bare "Not a directory" or "No such file or directory".

#include <filesystem>
#include <string>
#include <system_error>

namespace poro {

/// After create_directories(dir) failed with `ec`: names the deepest part of `dir` that exists and says what is
/// wrong with it -- a file where a directory belongs, or a directory without write permission -- and what to
/// do; otherwise `dir` and the system's reason.
std::string whyDirectoryFails(const std::filesystem::path& dir, const std::error_code& ec);

} // namespace poro
