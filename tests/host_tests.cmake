# Host bodies (issue 22): bodies given by the host's own stiffness, load vector and equation
# numbering, against the same scenes with mesh bodies; a layered orthotropic section; bad input
# (tests/test_host_body.c). The host's matrices come from tests/host_assembly.c, an assembler
# written independently of lib/.
mc_add_check_test(test_host_body test_host_body.c host_assembly.c)
target_link_libraries(test_host_body PRIVATE hertz_scene)
# Host bodies whose element matrices carry single-precision round-off (issue 31, trap 1): floating
# ones found free and solved, weak holds refused (tests/test_host_precision.c).
mc_add_check_test(test_host_precision test_host_precision.c host_assembly.c)
