# Contact tests (included from tests/CMakeLists.txt).
mc_add_check_test(test_contact test_contact.c)
target_link_libraries(test_contact PRIVATE hertz_scene)
add_library(mc_contact_study STATIC contact_study.c)
target_link_libraries(mc_contact_study PUBLIC mc_test_scenes)
mc_add_check_test(test_contact_convergence test_contact_convergence.c)
target_link_libraries(test_contact_convergence PRIVATE mc_contact_study)
set_tests_properties(test_contact test_contact_convergence PROPERTIES TIMEOUT 600)

# The BLAS actually loaded (CHOLMOD's libblas.so.3 goes through Debian's alternatives) must be
# OpenBLAS, not the reference BLAS.
add_test(NAME blas_is_openblas COMMAND sh -c
  "ldd '$<TARGET_FILE:mortarcontact>' | awk '/libblas|liblapack|libopenblas/ {print $3}' | xargs -n1 readlink -f | tee /dev/stderr | grep -v openblas && exit 1 || exit 0")

# Threads: MC_OPTION_THREADS, two models in two host threads at once. Run a second time with
# OpenBLAS at one thread, where the threaded results must be the serial ones bit for bit.
find_package(Threads REQUIRED)
mc_add_check_test(test_model_threads test_model_threads.c)
target_link_libraries(test_model_threads PRIVATE hertz_scene Threads::Threads PkgConfig::OPENBLAS)
add_test(NAME test_model_threads_blas1 COMMAND test_model_threads)
set_tests_properties(test_model_threads_blas1 PROPERTIES TIMEOUT 120 ENVIRONMENT OPENBLAS_NUM_THREADS=1)

# Westergaard's wavy contact, many separate patches on one interface (the scene of
# bench/westergaard.c at N = 4 wavelengths), against the closed form.
mc_add_check_test(test_westergaard test_westergaard.c westergaard_scene.c)

# The two interface solvers (MC_OPTION_INTERFACE_SOLVER) forced on every contact scene of the
# suite: the same answer to round-off (tests/test_interface_solvers.c).
mc_add_check_test(test_interface_solvers test_interface_solvers.c westergaard_scene.c)
target_link_libraries(test_interface_solvers PRIVATE mc_contact_checks)
set_tests_properties(test_interface_solvers PROPERTIES TIMEOUT 600)

# Assemblies: bodies 1..N and contact pairs (issue 32): patch tests of a stack and a corner,
# invariance under renumbering and splitting, conservation, bad input (tests/test_contact_pairs.c).
mc_add_check_test(test_contact_pairs test_contact_pairs.c host_assembly.c)

# The condensed interface operator stored by blocks (issue 32): a chain's condensed answer is the
# sparse path's, its storage grows linearly, friction on separate blocks (tests/test_interface_blocks.c).
mc_add_check_test(test_interface_blocks test_interface_blocks.c)

# Friction (issue 33): frictional patch tests (stick and slip, every method), mu = 0 against the
# frictionless solve, a floating body in full slip, load steps and history, bad input
# (tests/test_friction.c).
mc_add_check_test(test_friction test_friction.c host_assembly.c)
