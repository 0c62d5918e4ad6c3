#!/usr/bin/env bash
# The README's test command: installs what is missing, configures, builds with
# -j2 and runs every test, three times over:
#   1. the normal build (build/): kernel adjoints, generator golden and
#      diagnostic tests, runtime, examples, a consumer project built against
#      dpgen installed, as add_subdirectory and via FetchContent, and the
#      distributed runtime and examples (DPGEN_WITH_MPI, DPGEN_WITH_PETSC:
#      under mpirun with 1, 2 and 4 ranks, oversubscribed on 2 cores), and the
#      PyTorch ops (DPGEN_WITH_TORCH: gradcheck of every op, the generic
#      rollout and solve, the PyTorch solver-in-the-loop examples, and
#      torch.package: pip install into a fresh venv, dpgen_torch.load of a
#      kernel written on the fly, its cache and its errors) with Debian's own
#      Python (/usr/bin/python3);
#   2. the same suite built with AddressSanitizer and UBSan (build-asan/),
#      MPI tests included, with ASAN_OPTIONS=detect_leaks=0 for them only
#      (OpenMPI's run-time-loaded components leak; bounds and UB checks stay),
#      but without the PyTorch parts: Debian's libtorch and Python are not
#      built with ASan, and loading an ASan-instrumented library into them
#      does not work; and without the generator's own tests: it generates with
#      the dpgen of 1. (the generator runs under ASan and UBSan in 3.);
#   3. the generator under libFuzzer (build-fuzz/, clang, ASan, UBSan): every
#      kernel the build generates from once, and a fuzz run from the shipped
#      ones (180 s;
#      DPGEN_FUZZ_SECONDS changes the length).
# Ends with one line "tests: N passed, M failed" over all of them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DPGEN_BUILD_DIR:-$root/build}
"$root/scripts/setup.sh"

passed=0
failed=0
status=0
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
# Runs ctest in $1 and adds its counts to the totals.
run_ctest() {
  local dir=$1 name=$2
  echo "== $name: ctest in $dir"
  set +e
  ctest --test-dir "$dir" --output-on-failure -j2 2>&1 | tee "$logs/$name.log"
  local rc=${PIPESTATUS[0]}
  set -e
  local line total bad
  line=$(grep -E "tests passed, [0-9]+ tests failed out of [0-9]+" "$logs/$name.log" | tail -1 || true)
  total=$(sed -E 's/.*out of ([0-9]+).*/\1/' <<<"$line")
  bad=$(sed -E 's/.*passed, ([0-9]+) tests failed.*/\1/' <<<"$line")
  if [ -z "$line" ]; then total=0; bad=1; fi
  passed=$((passed + total - bad))
  failed=$((failed + bad))
  [ "$rc" -eq 0 ] || status=1
}

# 1. The normal build.
mpi=(-DDPGEN_WITH_MPI=ON -DDPGEN_WITH_PETSC=ON)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${mpi[@]}" \
  -DDPGEN_WITH_TORCH=ON -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build "$build" -j2
run_ctest "$build" release

# 2. Everything again under AddressSanitizer + UndefinedBehaviorSanitizer
#    (but the consumer.* tests: their projects build without the sanitizers,
#    exactly as in 1.).
#    It generates with the release stage's dpgen (DPGEN_GENERATOR): the
#    generator itself runs under ASan+UBSan in stage 3, over the kernels the
#    build generates from, the rejected adversarial ones and the diagnostic
#    tests' kernels (not over the command-line driver, lit's other inputs or
#    the issue-22 corpus). The C kernels are instrumented too.
#    -O1 -g1 (line tables): RelWithDebInfo's -O2 -g made this stage the
#    longest of the three.
san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S "$root" -B "$root/build-asan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${mpi[@]}" \
  -DCMAKE_CXX_FLAGS="$san" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_C_FLAGS="$san" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_EXE_LINKER_FLAGS="$san" -DDPGEN_TEST_CONSUMERS=OFF -DDPGEN_WITH_TORCH=OFF \
  -DDPGEN_INSTALL=OFF -DDPGEN_GENERATOR="$build/tool/dpgen"
cmake --build "$root/build-asan" -j2
run_ctest "$root/build-asan" sanitizers

# 3. The generator under libFuzzer (clang), ASan and UBSan (tests/fuzz/CMakeLists.txt).
cmake -S "$root" -B "$root/build-fuzz" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-19 -DCMAKE_CXX_COMPILER=clang++-19 -DDPGEN_BUILD_FUZZ=ON \
  -DDPGEN_BUILD_TESTS=OFF -DDPGEN_BUILD_EXAMPLES=OFF \
  -DDPGEN_FUZZ_SECONDS="${DPGEN_FUZZ_SECONDS:-180}" \
  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build "$root/build-fuzz" -j2 --target fuzz_generator
run_ctest "$root/build-fuzz" fuzz

echo "tests: $passed passed, $failed failed"
exit $status
