#!/bin/sh
# The CPU libraries' unit tests as the page's build compiles them (tests/web/CMakeLists.txt), run
# in node: the desktop's test sources on Emscripten's libc++, the threads of parallel_for.h and
# the page's Embree. ./setup.sh web test builds them (target luz_node_tests) and runs this.
#   tests/web/run_node_tests.sh BUILD_WEB
set -eu
tests=$1/tests
status=0
started=$(date +%s)
for program in test_core test_image_compare test_scenes test_whitted test_path_tracer; do
  # Emscripten 3.1.6's output detects node's own fetch() and then misreads the .wasm file.
  if node --no-experimental-fetch "$tests/$program.js" --gtest_brief=1 >"$tests/$program.log" 2>&1; then
    echo "node tests: $program passed ($(grep -o '[0-9]* tests\? from [0-9]* test suites\? ran. ([0-9]* ms total)' "$tests/$program.log"))"
  else
    echo "node tests: $program FAILED ($tests/$program.log):"
    tail -20 "$tests/$program.log"
    status=1
  fi
done
echo "node tests: $(($(date +%s) - started)) s"
exit $status
