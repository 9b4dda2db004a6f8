# Bad input, fuzz corpus, sanitizers (included from tests/CMakeLists.txt).
#   test_input          bad input on every entry point (statuses, messages, model still usable)
#   fuzz_corpus_replay  the fuzz target tests/fuzz/fuzz_api.c run on the seed corpus without
#                       libFuzzer (plain build, ASan/UBSan build, valgrind); checks that the corpus
#                       still reaches successful solves, with and without contact, with a host
#                       body, with contact on two pairs (assemblies), with friction rows that stick
#                       or slip
# Label `memcheck`: the C programs that bootstrap.sh runs under ASan/UBSan (build-asan) and
# valgrind; mc_add_check_test gives it to every Check program.
mc_add_check_test(test_input test_input.c)

add_executable(fuzz_corpus_replay fuzz/fuzz_api.c fuzz/replay_main.c)
target_link_libraries(fuzz_corpus_replay PRIVATE mortarcontact m)
target_compile_options(fuzz_corpus_replay PRIVATE -Wall -Wextra)
file(GLOB MC_FUZZ_SEEDS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/*)
list(SORT MC_FUZZ_SEEDS)
add_test(NAME fuzz_corpus_replay COMMAND fuzz_corpus_replay --min-solves 20 --min-contact-solves 12 --min-host-solves 6 --min-pair-solves 4 --min-friction-solves 4 ${MC_FUZZ_SEEDS})
set_tests_properties(fuzz_corpus_replay PROPERTIES TIMEOUT 300 LABELS memcheck)
