# Compiler warnings for feran's own targets.
function(feran_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                         -Wno-sign-conversion)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    # g++ 12 reports a false use-after-free inside Eigen's aligned_free when sparse
    # products are inlined (GCC bug 104475 family); the code path is Eigen's own.
    target_compile_options(${target} PRIVATE -Wno-use-after-free)
    # ... and a false -Wrestrict in std::string's operator+ with a literal
    # (GCC bug 105329), and the same code's false -Warray-bounds and
    # -Wstringop-overflow, which appear when the tests' precompiled headers change
    # what gets inlined (GCC bugs 105651, 106199).
    target_compile_options(${target} PRIVATE -Wno-restrict -Wno-array-bounds -Wno-stringop-overflow)
  endif()
  if(FERAN_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
