# SKEIN_FUZZ=ON: every library is built with libFuzzer's coverage and AddressSanitizer +
# UndefinedBehaviorSanitizer, so that a fuzz target sees into all of skein (fuzz/README.md).
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "SKEIN_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                    -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=address,undefined)
