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

# Two models in two threads at once.
find_package(Threads REQUIRED)
mc_add_check_test(test_model_threads test_model_threads.c)
target_link_libraries(test_model_threads PRIVATE hertz_scene Threads::Threads)
