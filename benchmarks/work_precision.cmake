# Work-precision of the integrator: wall time against error for the event-located RK4 at a range
# of steps_per_period and for the paper's fixed-step method, against a high-accuracy reference.
# A benchmark, never run by ctest. One command: benchmarks/run_work_precision.sh [--quick].
# See benchmarks/WORK_PRECISION.md.
add_executable(work_precision ${CMAKE_CURRENT_LIST_DIR}/work_precision.cpp)
target_link_libraries(work_precision PRIVATE rocksweep_physics CLI11::CLI11)
