// Errors inside the library: thrown as mc::Error, caught at the C API boundary (capi.cpp),
// turned into a status code and a per-model message. Nothing here is global.
#pragma once
#include "mortarcontact.h"
#include <cstddef>
#include <exception>
#include <string>

namespace mc {

class Error : public std::exception {
public:
  Error(mc_status status, std::string message) : status_(status), message_(std::move(message)) {}
  mc_status status() const { return status_; }
  const char *what() const noexcept override { return message_.c_str(); }

private:
  mc_status status_;
  std::string message_;
};

// printf-style formatting of an error message, then throw.
[[noreturn]] void fail(mc_status status, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

// An array position in a message, in the model's index base, written as the caller's own
// language writes it (docs/api.md, "Errors"): base 0 "name[i]" (C, C++, Python), base 1
// "name(i + 1)" (Fortran, Julia, MATLAB). index is 0-based. A 1-based position in brackets
// would read as a C subscript one too far; parentheses say which convention is meant.
std::string array_position(const char *name, size_t index, int base);
// Positions first..last (0-based, inclusive): "name[6..7]" in base 0, "name(7:8)" in base 1.
std::string array_range(const char *name, size_t first, size_t last, int base);

}  // namespace mc
