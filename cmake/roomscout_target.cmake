# Warnings and sanitizer flags for roomscout's own targets (never global flags).
function(roomscout_configure_target target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-deprecated-enum-enum-conversion)
  if(ROOMSCOUT_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  # Coverage instrumentation for libFuzzer (fuzz/); linking with the same flag brings the
  # coverage callbacks into executables that are not fuzzers (tests, the CLI).
  if(ROOMSCOUT_BUILD_FUZZERS)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    target_link_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
