#include "support/error.hpp"
#include <cstdarg>
#include <cstdio>

namespace mc {

void fail(mc_status status, const char *format, ...) {
  char buffer[1024];  // (the longest messages name two edges and their nodes)
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  throw Error(status, buffer);
}

std::string array_position(const char *name, size_t index, int base) {
  char text[160];
  if (base == 1) std::snprintf(text, sizeof text, "%s(%zu)", name, index + 1);
  else std::snprintf(text, sizeof text, "%s[%zu]", name, index);
  return text;
}

std::string array_range(const char *name, size_t first, size_t last, int base) {
  char text[160];
  if (base == 1) std::snprintf(text, sizeof text, "%s(%zu:%zu)", name, first + 1, last + 1);
  else std::snprintf(text, sizeof text, "%s[%zu..%zu]", name, first, last);
  return text;
}

}  // namespace mc
