#!/usr/bin/env bash
# Set-up on a fresh Debian 12 machine (as root): install what is missing, build, then
#   demo : run the Hertz contact demo
#   test : run the whole test suite (ctest; each Check runner prints its summary)
# Usage: bash tools/bootstrap.sh demo|test
set -euo pipefail
mode=${1:-test}
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config libsuitesparse-dev libopenblas-dev liblapacke-dev check
          gfortran python3 python3-numpy python3-venv python3-setuptools python3-wheel abigail-tools
          nlohmann-json3-dev gmsh python3-matplotlib python3-meshio python3-scipy
          clang libclang-rt-14-dev valgrind)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq "${missing[@]}"
fi

build=${MC_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j"$(nproc)"

case "$mode" in
  demo)
    # The Hertz scene through the scene runner: Gmsh meshes the .geo, mortarcontact-run solves the
    # JSON scene (progress on stderr), then the pressure profile is plotted against Hertz.
    out="$build/hertz"
    mkdir -p "$out"
    gmsh -2 -format msh41 -v 2 examples/runner/hertz/hertz.geo -o "$out/hertz.msh"
    cp examples/runner/hertz/hertz.json "$out/"
    "$build/examples/runner/mortarcontact-run" "$out/hertz.json"
    /usr/bin/python3 examples/python/plot_hertz_pressure.py "$out/hertz_pressure.csv" "$out/hertz_pressure.png"
    echo
    echo "ParaView: open $out/hertz.pvd (displacement, stress, von Mises, contact pressure, gap, active)"
    echo "Plot:     $out/hertz_pressure.png (pressure profile against Hertz)"
    echo "CSV:      $out/hertz_pressure.csv" ;;
  test)
    ctest --test-dir "$build" --output-on-failure -V -j1
    # Bad input, fuzzing, sanitizers (docs/robustness.md). The C test programs are the tests
    # labelled memcheck (every Check program, and fuzz_corpus_replay); each step fails CI.
    # (a) AddressSanitizer + UndefinedBehaviorSanitizer (gcc), a lean build of just those programs.
    t0=$SECONDS
    asan=${MC_ASAN_DIR:-build-asan}
    cmake -S . -B "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMC_SANITIZE=ON -DMC_BUILD_BENCH=OFF >/dev/null
    mapfile -t targets < <(python3 tools/memcheck_tests.py targets "$asan")
    [ ${#targets[@]} -gt 0 ] || { echo "no memcheck tests in $asan" >&2; exit 1; }
    cmake --build "$asan" -j"$(nproc)" --target "${targets[@]}"
    CK_FORK=no ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ctest --test-dir "$asan" -L memcheck --output-on-failure -j1
    t_asan=$((SECONDS - t0))
    # (a') ThreadSanitizer (gcc): the thread tests (MC_OPTION_THREADS, models in host threads), a
    # lean build of just that program. OpenBLAS is not instrumented; tools/tsan.supp says why its
    # reports are suppressed, and nothing else is.
    t0=$SECONDS
    tsan=${MC_TSAN_DIR:-build-tsan}
    cmake -S . -B "$tsan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMC_SANITIZE_THREAD=ON -DMC_BUILD_BENCH=OFF >/dev/null
    cmake --build "$tsan" -j"$(nproc)" --target test_model_threads
    CK_FORK=no TSAN_OPTIONS="suppressions=$PWD/tools/tsan.supp halt_on_error=1 second_deadlock_stack=1" \
      ctest --test-dir "$tsan" -R '^test_model_threads$' --output-on-failure -j1
    t_tsan=$((SECONDS - t0))
    # (b) valgrind memcheck of the same programs from the normal build. Left out for time (they
    # run under ASan/UBSan above; under valgrind they took 3, 10 and 11 minutes): the convergence
    # study and the two long scene suites; test_interface_solvers (both interface solvers on every
    # scene, 45 s natively) and test_westergaard (39 s under valgrind); test_model_threads (280 s
    # under valgrind, which runs its threads one at a time: 2026-11-28, when .ci/run took 1714 s
    # of its 30 minutes) runs under ASan/UBSan and under TSan (step (a')). test_contact keeps the
    # contact paths, both interface solvers included, under valgrind.
    t0=$SECONDS
    CK_FORK=no OPENBLAS_NUM_THREADS=1 python3 tools/memcheck_tests.py run "$build" \
      --exclude test_contact_convergence,test_contact_scenes,test_contact_hard,test_interface_solvers,test_westergaard,test_model_threads -- \
      valgrind -q --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect --num-callers=30
    t_valgrind=$((SECONDS - t0))
    # (c) the libFuzzer target (clang), a bounded run from the checked-in seed corpus; new inputs
    # go to $fuzz/fuzz-work, a crash, leak, timeout or out-of-memory input to $fuzz/.
    t0=$SECONDS
    fuzz=${MC_FUZZ_DIR:-build-fuzz}
    cmake -S . -B "$fuzz" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DMC_BUILD_FUZZ=ON -DMC_BUILD_TESTS=OFF -DMC_BUILD_EXAMPLES=OFF -DMC_BUILD_BENCH=OFF >/dev/null
    cmake --build "$fuzz" -j"$(nproc)" --target fuzz_api fuzz_replay
    # First the corpus replayed with the fuzz build's own flags and static link (fuzz_replay): the
    # same scenes as the plain builds' fuzz_corpus_replay, host bodies included.
    "$fuzz/tests/fuzz/fuzz_replay" --min-solves 20 --min-contact-solves 12 --min-host-solves 6 --min-pair-solves 4 --min-friction-solves 4 tests/fuzz/corpus/*
    mkdir -p "$fuzz/fuzz-work"
    if ! "$fuzz/tests/fuzz/fuzz_api" -max_total_time="${MC_FUZZ_SECONDS:-60}" -timeout=10 -rss_limit_mb=2048 \
         -print_final_stats=1 -artifact_prefix="$fuzz/" "$fuzz/fuzz-work" tests/fuzz/corpus >"$fuzz/fuzz.log" 2>&1; then
      tail -n 80 "$fuzz/fuzz.log"
      echo "fuzz_api failed: see $fuzz/fuzz.log and the crash-*/leak-*/timeout-*/oom-* file in $fuzz/" >&2
      exit 1
    fi
    grep -E '^(INFO: .*corpus|stat::)|Done' "$fuzz/fuzz.log" || true
    t_fuzz=$((SECONDS - t0))
    echo "robustness steps: ASan/UBSan ${t_asan} s, TSan ${t_tsan} s, valgrind ${t_valgrind} s, fuzzing ${t_fuzz} s" ;;
  *)
    echo "usage: $0 demo|test" >&2; exit 2 ;;
esac
