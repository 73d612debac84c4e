# The fuzz tier (ctest -L fuzz): each libFuzzer target of tests/fuzz/ runs briefly on every test
# run, as CI runs them. The targets need clang and the sanitisers, so they are built apart, into
# build-fuzz/ by scripts/fuzz.sh (the FuzzBuild fixture, once per ctest run), whatever compiler
# built this tree. Seconds a target: INKWIRE_FUZZ_SECONDS (default 5; the long runs are
# scripts/fuzz.sh 600).
set(INKWIRE_FUZZ_SECONDS 5 CACHE STRING "seconds each fuzz target runs in the fuzz tier")
set(INKWIRE_FUZZ_TARGETS fuzz_frames fuzz_message fuzz_tween fuzz_landmarks fuzz_http fuzz_websocket fuzz_config fuzz_broker
    fuzz_voice fuzz_glb fuzz_video fuzz_calibration)
add_test(NAME FuzzBuild COMMAND ${PROJECT_SOURCE_DIR}/scripts/fuzz.sh --build-only)
# (A cold clang build of the instrumented decoders takes minutes on two cores.)
set_tests_properties(FuzzBuild PROPERTIES LABELS fuzz FIXTURES_SETUP fuzz_build TIMEOUT 1800)
foreach(target ${INKWIRE_FUZZ_TARGETS})
  add_test(NAME Fuzz_${target} COMMAND ${PROJECT_SOURCE_DIR}/scripts/fuzz.sh --no-build ${INKWIRE_FUZZ_SECONDS} ${target})
  # libFuzzer's own start and the corpus's first pass come on top of the seconds it fuzzes.
  math(EXPR timeout "${INKWIRE_FUZZ_SECONDS} * 3 + 120")
  set_tests_properties(Fuzz_${target} PROPERTIES LABELS fuzz FIXTURES_REQUIRED fuzz_build TIMEOUT ${timeout})
endforeach()
