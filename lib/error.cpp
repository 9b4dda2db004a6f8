#include "error.hpp"
#include <cstdarg>
#include <cstdio>

namespace mc {

void fail(mc_status status, const char *format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  throw Error(status, buffer);
}

}  // namespace mc
