# Axisymmetric models (MC_AXISYMMETRIC): patch tests, shrink fit, sphere on a flat, bad input.
mc_add_check_test(test_axisymmetric test_axisymmetric.c)
target_link_libraries(test_axisymmetric PRIVATE sphere_on_flat)
