#pragma once
// Typed errors: misuse and bad input throw these with a message a user can act on.

#include <stdexcept>
#include <string>

namespace roomscout {

/// A caller passed a value the contract forbids (negative resolution, empty scan, ...).
class InvalidArgument : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// An option has an unknown name or a value out of its documented range.
class OptionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file or other external input is missing or malformed. The message names the source.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& source, const std::string& problem)
      : std::runtime_error(source + ": " + problem), source_(source), problem_(problem) {}
  const std::string& source() const { return source_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string source_;
  std::string problem_;
};

}  // namespace roomscout
