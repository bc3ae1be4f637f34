# Sanitizer and fuzzing builds (docs/RELIABILITY.md).
#
# COLORDECIMATION_SANITIZE: a comma-separated list handed to -fsanitize= for every target of
# this project (the module, the mesh generators, the tests and the tools), for example
# "address,undefined". VTK itself is not instrumented; it does not need to be, since every
# executable of this project is linked with the sanitizer runtime. UndefinedBehaviorSanitizer
# is made fatal (-fno-sanitize-recover=all) so that a finding fails the test that hit it.
#
# COLORDECIMATION_FUZZ (Clang only): instrument everything for libFuzzer's coverage
# (-fsanitize=fuzzer-no-link) and build the fuzz target in Testing/Fuzz, which links with
# -fsanitize=fuzzer. Combine it with COLORDECIMATION_SANITIZE=address,undefined.
set(COLORDECIMATION_SANITIZE "" CACHE STRING
  "Sanitizers for -fsanitize= (comma-separated, e.g. address,undefined); empty: none")
option(COLORDECIMATION_FUZZ "Build the libFuzzer target (Clang only)" OFF)

if (COLORDECIMATION_SANITIZE)
  if (NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "COLORDECIMATION_SANITIZE needs GCC or Clang")
  endif ()
  set(colordecimation_sanitize_flags
    "-fsanitize=${COLORDECIMATION_SANITIZE}"
    -fno-omit-frame-pointer
    -fno-sanitize-recover=all)
  # GCC's "undefined" leaves out float-cast-overflow (Clang's includes it): a NaN or huge
  # double converted to an integer is undefined behaviour that a filter parameter can reach.
  if (COLORDECIMATION_SANITIZE MATCHES "undefined" AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    list(APPEND colordecimation_sanitize_flags -fsanitize=float-cast-overflow)
  endif ()
  add_compile_options(${colordecimation_sanitize_flags} -g)
  add_link_options(${colordecimation_sanitize_flags})
  message(STATUS "ColorDecimation: sanitizers ${COLORDECIMATION_SANITIZE}")
endif ()

if (COLORDECIMATION_FUZZ)
  if (NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "COLORDECIMATION_FUZZ needs Clang (CC=clang CXX=clang++)")
  endif ()
  add_compile_options(-fsanitize=fuzzer-no-link)
  add_link_options(-fsanitize=fuzzer-no-link)
  message(STATUS "ColorDecimation: libFuzzer coverage instrumentation")
endif ()
