#pragma once
/// Error classes. Libraries throw; applications catch, print one message and exit non-zero (STYLE.md §6).

#include <stdexcept>
#include <string>

namespace poro {

/// Base of every error PoroSPH reports to a user.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
  /// Short class name for the message prefix ("input error", "numerical error", ...).
  virtual const char* kind() const noexcept { return "error"; }
};

/// Something the user can fix in the case: the message starts with `file:line:` and names the key,
/// the value and what was expected.
class InputError : public Error {
public:
  using Error::Error;
  const char* kind() const noexcept override { return "input error"; }
};

/// Divergence, NaN, a non-positive-definite system or a solver that cannot go on.
class NumericalError : public Error {
public:
  using Error::Error;
  const char* kind() const noexcept override { return "numerical error"; }
};

/// An output file or directory could not be written (full disk, permissions).
class OutputError : public Error {
public:
  using Error::Error;
  const char* kind() const noexcept override { return "output error"; }
};

} // namespace poro
