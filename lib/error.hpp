// Errors inside the library: thrown as mc::Error, caught at the C API boundary (capi.cpp),
// turned into a status code and a per-model message. Nothing here is global.
#pragma once
#include "mortarcontact.h"
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

}  // namespace mc
