/*
 * check_helpers.h - assertion macros shared by the Check test programs (C99, needs check.h).
 * They refer to a variable `mc_model *m` in scope, whose mc_errmsg they print.
 *
 *   OK(call)                      the call returns MC_OK
 *   SUCCEEDS(call)                the call returns MC_OK and mc_errmsg(m) is then ""
 *   FAILS(call, status, needle)   the call returns status, mc_errmsg(m) is non-empty and
 *                                 contains needle (a string; NULL: any message)
 *   AT(name, i, base)             an array position as the library's messages write it in
 *                                 the index base: "name[i]" (base 0), "name(i + 1)" (base 1);
 *                                 i is 0-based
 *   AT_RANGE(name, i, j, base)    positions i..j: "name[i..j]" (base 0), "name(i+1:j+1)" (base 1)
 */
#ifndef MC_TESTS_CHECK_HELPERS_H
#define MC_TESTS_CHECK_HELPERS_H

#include <check.h>
#include <stdio.h>
#include <string.h>

#include "mortarcontact.h"

#define OK(call) ck_assert_msg((call) == MC_OK, "%s failed: %s", #call, mc_errmsg(m))

#define SUCCEEDS(call)                                                                                  \
  do {                                                                                                  \
    OK(call);                                                                                           \
    ck_assert_msg(mc_errmsg(m)[0] == '\0', "%s: message \"%s\" after success", #call, mc_errmsg(m));    \
  } while (0)

#define FAILS(call, status, needle)                                                                           \
  do {                                                                                                        \
    const char *needle_ = (needle);                                                                           \
    mc_status st_ = (call);                                                                                   \
    const char *msg_;                                                                                         \
    ck_assert_msg(st_ == (status), "%s returned %s, expected %s (message: %s)", #call, mc_status_string(st_), \
                  mc_status_string(status), mc_errmsg(m));                                                    \
    msg_ = mc_errmsg(m);                                                                                      \
    ck_assert_ptr_nonnull(msg_);                                                                              \
    ck_assert_msg(msg_[0] != '\0', "%s: empty message", #call);                                               \
    if (needle_ != NULL)                                                                                      \
      ck_assert_msg(strstr(msg_, needle_) != NULL, "%s: message \"%s\" lacks \"%s\"", #call, msg_, needle_);  \
  } while (0)

static inline const char *mc_test_position(char *text, size_t size, const char *name, long i, long j, int base) {
  if (j < 0) snprintf(text, size, base == 1 ? "%s(%ld)" : "%s[%ld]", name, i + base);
  else if (base == 1) snprintf(text, size, "%s(%ld:%ld)", name, i + 1, j + 1);
  else snprintf(text, size, "%s[%ld..%ld]", name, i, j);
  return text;
}
/* (a compound literal: the text lives until the end of the enclosing block) */
#define AT(name, i, base) mc_test_position((char[64]){0}, 64, (name), (long)(i), -1, (base))
#define AT_RANGE(name, i, j, base) mc_test_position((char[64]){0}, 64, (name), (long)(i), (long)(j), (base))

#endif /* MC_TESTS_CHECK_HELPERS_H */
