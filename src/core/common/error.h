// Error types of the AutoBlock core.
//
// InputError: the user's input is wrong (a bad file, an unsupported face, a bad option). Front ends
// report it as a one-line message and exit 2 (CLI) or raise ValueError (Python).
// Any other std::exception is an internal failure.
#pragma once

#include <stdexcept>
#include <string>

namespace autoblock {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace autoblock
