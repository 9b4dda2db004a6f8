# Hard contact scenes (docs/robustness.md, "Hard scenes"), included from tests/CMakeLists.txt.
mc_add_check_test(test_contact_hard test_contact_hard.c)
target_link_libraries(test_contact_hard PRIVATE hertz_scene)

# Part 2: non-mortar choice, units, grazing, partial coverage, interference, reversal, wavy.
mc_add_check_test(test_contact_scenes test_contact_scenes.c)
target_link_libraries(test_contact_scenes PRIVATE hertz_scene)
