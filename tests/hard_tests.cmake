# Hard contact scenes (docs/robustness.md, "Hard scenes"), included from tests/CMakeLists.txt.
mc_add_check_test(test_contact_hard test_contact_hard.c)
target_link_libraries(test_contact_hard PRIVATE hertz_scene)

# Contact results, KKT and balance checks, the Hertz scene in any role (contact_checks.h).
add_library(mc_contact_checks STATIC contact_checks.c)
target_link_libraries(mc_contact_checks PUBLIC mc_test_scenes hertz_scene)
target_compile_options(mc_contact_checks PRIVATE -Wall -Wextra)

# Part 2: non-mortar choice, units, grazing, partial coverage, interference, reversal, wavy.
mc_add_check_test(test_contact_scenes test_contact_scenes.c)
target_link_libraries(test_contact_scenes PRIVATE mc_contact_checks)

# Issue 11: contact geometry on curved, closed, cornered and partly covered surfaces.
mc_add_check_test(test_contact_geometry test_contact_geometry.c)
target_link_libraries(test_contact_geometry PRIVATE mc_contact_checks)
