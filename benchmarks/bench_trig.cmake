# Micro-benchmark of sin/cos variants for the RK4 kernel (see benchmarks/VECTORISATION.md).
# Needs SLEEF (Debian: libsleef-dev); skipped when it is missing.
find_path(SLEEF_INCLUDE_DIR sleef.h)
find_library(SLEEF_LIBRARY sleef)
if(SLEEF_INCLUDE_DIR AND SLEEF_LIBRARY)
  add_executable(bench_trig bench_trig.cpp)
  target_include_directories(bench_trig PRIVATE ${PROJECT_SOURCE_DIR}/include ${SLEEF_INCLUDE_DIR})
  target_link_libraries(bench_trig PRIVATE ${SLEEF_LIBRARY} m)
else()
  message(STATUS "bench_trig: SLEEF not found, not built")
endif()
