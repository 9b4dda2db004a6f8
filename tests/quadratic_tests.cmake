# Quadratic cells (T6, Q8, Q9) beside P1 and Q1: linear fields, consistent loads, contact patch
# tests for every pair of kinds, the zigzag, curved Q8 shrink fit, bad input (tests/test_quadratic.c).
mc_add_check_test(test_quadratic test_quadratic.c)
target_link_libraries(test_quadratic PRIVATE mc_contact_checks)

# The error estimate (issue 23): round-off on patch tests, effectivity on Lame's shrink fits
# (axisymmetric and plane strain) against the true error by quadrature, the option, host bodies.
mc_add_check_test(test_error_estimate test_error_estimate.c host_assembly.c)
