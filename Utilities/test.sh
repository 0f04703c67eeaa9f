#!/usr/bin/env bash
# Sets up, builds, and runs the whole test suite under a virtual X display (the filter tests that do
# not render also under valgrind); meanwhile, at the lowest priority, builds the Core tests again
# with AddressSanitizer and UndefinedBehaviorSanitizer in a second tree (build-sanitize, or
# $KERF_SANITIZE_BUILD_DIR) and without CHOLMOD in a third (build-without-cholmod), and runs them
# there after the main suite. KERF_SANITIZE=OFF and KERF_WITHOUT_CHOLMOD=OFF skip the second and
# third trees. Arguments go to every ctest run.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${KERF_BUILD_DIR:-$source_dir/build}
# Each stage says how long it took, and the main suite names its slowest tests (ctest's cost
# data: the mean seconds of each test's runs), so that a suite growing past the budget shows where.
stage_start=$(date +%s)
stage() { echo "kerf test: $1 took $(($(date +%s) - stage_start)) s"; stage_start=$(date +%s); }
"$source_dir/Utilities/setup.sh"
stage "the set-up"
"$source_dir/Utilities/build.sh"
stage "the build"
status=0

# The Core tests are built twice more in trees of their own: by Clang with AddressSanitizer and
# UndefinedBehaviorSanitizer, and without CHOLMOD (below). Those builds start now, at the lowest
# priority, while the main suite runs: the scheduler gives them only what the suite leaves idle (its
# serial ParaView and GUI tests use one core of two), and their tests run after the suite.
# Sanitizer: the Core tests only (compiling the filters and the program with the sanitizers too
# would double the stage, Documentation/robustness.md, *Sanitizers*; the first stage runs the
# filter tests that do not render under valgrind and the readers' fuzzing in the ordinary build).
# Compiled by Clang (the first tree is GCC's, so both compilers build Core): on 2 cores its cold
# build takes half of GCC's CPU time and its tests 166 s against 293. -O1 with line tables: half
# the compile time of -O2 -g, and stacks still name the lines. Leaks are reported except those of
# the OpenGL driver, listed in the suppression file.
sanitize_tree=${KERF_SANITIZE_BUILD_DIR:-$source_dir/build-sanitize}
sanitize_arguments=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  -DKERF_SANITIZE=ON)
# The route without any GPL module (README, *Licence*): Core built without CHOLMOD factors with
# Eigen's SimplicialLDLT. With the first tree's flags: only the files that test KERF_HAVE_CHOLMOD
# compile differently (Source/Core/CMakeLists.txt), and the compiler cache hands over the others'
# objects.
without_cholmod_tree=${KERF_WITHOUT_CHOLMOD_BUILD_DIR:-$source_dir/build-without-cholmod}
without_cholmod_arguments=(-DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_CHOLMOD=ON)
second_trees=()
if [ "${KERF_SANITIZE:-ON}" != OFF ]; then second_trees+=(sanitize); fi
if [ "${KERF_WITHOUT_CHOLMOD:-ON}" != OFF ]; then second_trees+=(without_cholmod); fi

# Configures a second tree (its flags as arguments; again from scratch when they changed, since
# CMake keeps a tree's first compiler) and builds the Core tests there; the file kerf-built says it
# succeeded. Its output goes to the log kerf-second-tree-NAME.log in the first tree.
build_core_tests_in() {
  local tree=$1
  shift
  local arguments="$*"
  if [ -f "$tree/build.ninja" ] && [ "$(cat "$tree/kerf-configure-arguments" 2>/dev/null)" != "$arguments" ]; then
    rm -rf "$tree"
  fi
  rm -f "$tree/kerf-built"
  if [ ! -f "$tree/build.ninja" ]; then
    mkdir -p "$tree"
    cmake -S "$source_dir" -B "$tree" -G Ninja -DKERF_BUILD_BENCHMARKS=OFF -DPython3_EXECUTABLE=/usr/bin/python3 \
      "$@" "${compiler_cache[@]}" >"$tree/configure.log" 2>&1 || {
      cat "$tree/configure.log"
      return 1
    }
    echo "$arguments" >"$tree/kerf-configure-arguments"
  fi
  cmake --build "$tree" --target KerfCoreTests -- -j"$(nproc)" && touch "$tree/kerf-built"
}
second_log() { echo "$build_dir/kerf-second-tree-$1.log"; }
second_builds=
if [ ${#second_trees[@]} -gt 0 ]; then
  for name in "${second_trees[@]}"; do
    tree_name="${name}_tree"
    rm -f "${!tree_name}/kerf-built" "$(second_log "$name")"
  done
  # In a process group of its own (set -m), so that stopping this script stops the compilers too.
  set -m
  (
    renice -n 19 -p "$BASHPID" >/dev/null
    source "$source_dir/Utilities/compiler-cache.sh" "$source_dir"
    for name in "${second_trees[@]}"; do
      tree_name="${name}_tree" arguments_name="${name}_arguments[@]"
      build_core_tests_in "${!tree_name}" "${!arguments_name}" >"$(second_log "$name")" 2>&1 || true
    done
  ) </dev/null &
  second_builds=$!
  set +m
  trap '[ -n "$second_builds" ] && kill -- -"$second_builds" 2>/dev/null || true' EXIT
fi

# A 24-bit screen: on xvfb-run's default 8-bit one ParaView's render windows fail to open
# ("bad X server connection") now and then.
(cd "$build_dir" && xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure -j"$(nproc)" "$@") || status=$?
stage "the main suite"
if [ -f "$build_dir/Testing/Temporary/CTestCostData.txt" ]; then
  echo "kerf test: the slowest tests (mean seconds):"
  # sed reads the whole list (head would exit early and, under pipefail, sort's SIGPIPE would
  # fail the run).
  awk 'NF == 3 { printf "  %8.1f  %s\n", $3, $1 }' "$build_dir/Testing/Temporary/CTestCostData.txt" | sort -rn | sed -n 1,8p
fi
if [ -n "$second_builds" ]; then
  wait "$second_builds" || true
  second_builds=
  stage "the rest of the second trees' builds, after the main suite,"
fi

# Runs a second tree's Core tests, or prints its build's log when the build failed.
core_tests_in() {
  local name=$1 tree=$2
  shift 2
  if [ ! -f "$tree/kerf-built" ]; then
    echo "kerf test: the Core tests in $tree did not build:"
    cat "$(second_log "$name")" 2>/dev/null || true
    return 1
  fi
  (cd "$tree" && ctest --output-on-failure -j"$(nproc)" -R '^Core\.' "$@")
}
for name in "${second_trees[@]}"; do
  case $name in
  sanitize)
    (
      export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1"
      export LSAN_OPTIONS="suppressions=$source_dir/Testing/Sanitizers/lsan-suppressions.txt:print_suppressions=0"
      export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
      core_tests_in sanitize "$sanitize_tree" "$@"
    ) || status=$?
    stage "the sanitizer stage's tests"
    ;;
  without_cholmod)
    core_tests_in without_cholmod "$without_cholmod_tree" "$@" || status=$?
    stage "the tests without CHOLMOD"
    ;;
  esac
done
exit "$status"
