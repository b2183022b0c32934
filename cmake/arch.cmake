# Vector instructions. feran is built from source on the machine that runs it
# (scripts/build.sh), so by default it uses AVX2 and FMA (the x86-64-v3 level) when
# that machine has them: the Krylov and dense kernels of Eigen then run about 20 %
# faster than with the baseline SSE2 (docs/performance.md). Not the full
# -march=native: GCC 12 reports false -Wmaybe-uninitialized warnings inside its
# AVX-512 headers, which the warnings-as-errors build rejects.
#   FERAN_ARCH=auto      x86-64-v3 when /proc/cpuinfo lists avx2, fma and bmi2 (default)
#   FERAN_ARCH=baseline  no -march flag (portable binaries)
#   FERAN_ARCH=<level>   -march=<level>, e.g. x86-64-v2
set(FERAN_ARCH "auto" CACHE STRING "Instruction set: auto, baseline, or a -march level")
include(CheckCXXCompilerFlag)
set(_feran_march "")
if(FERAN_ARCH STREQUAL "auto")
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64" AND EXISTS /proc/cpuinfo)
    file(STRINGS /proc/cpuinfo _feran_flags REGEX "^flags" LIMIT_COUNT 1)
    if(_feran_flags MATCHES " avx2( |$)" AND _feran_flags MATCHES " fma( |$)" AND _feran_flags MATCHES " bmi2( |$)")
      set(_feran_march "x86-64-v3")
    endif()
  endif()
elseif(NOT FERAN_ARCH STREQUAL "baseline")
  set(_feran_march "${FERAN_ARCH}")
endif()
if(_feran_march)
  string(MAKE_C_IDENTIFIER "FERAN_HAS_MARCH_${_feran_march}" _feran_check)
  check_cxx_compiler_flag("-march=${_feran_march}" ${_feran_check})
  if(${_feran_check})
    # On the library as a PUBLIC option (src/CMakeLists.txt), so that every program
    # built against it — in this tree or through find_package(feran) — uses the same
    # instruction set, and with it the same Eigen alignment (a program built without
    # it would pass misaligned Eigen objects to the library).
    set(FERAN_MARCH_FLAG "-march=${_feran_march}")
    message(STATUS "feran: -march=${_feran_march}")
  endif()
endif()
